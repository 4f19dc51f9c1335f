"""What laying out a room gives: each object's placement, each constraint's report, the objects
left out with the reason, the post-check's findings (:class:`HardChecks`) and the whole
:class:`LayoutResult`.
"""

from __future__ import annotations

from pydantic import BaseModel, Field


class Placement(BaseModel):
    """Where an object goes: centre of its footprint (metres) and yaw (degrees, CCW)."""

    x: float
    y: float
    yaw_deg: float
    width: float = Field(description="Left-right size in metres.")
    depth: float = Field(description="Front-back size in metres.")


class ConstraintReport(BaseModel):
    """One constraint and whether the final layout satisfies it."""

    text: str
    object: str
    kind: str
    target: str | None
    weight: float
    satisfied: bool
    detail: str
    source: str | None = None


class UnplacedObject(BaseModel):
    """An object the layout does not contain, and why."""

    id: str
    reason: str


class HardChecks(BaseModel):
    """The post-check of the hard rules on the final layout (lists name offending objects)."""

    overlaps: list[str] = Field(default_factory=list)
    clearance: list[str] = Field(default_factory=list)
    outside_room: list[str] = Field(default_factory=list)
    door_zones: list[str] = Field(default_factory=list)
    windows: list[str] = Field(default_factory=list)
    facing_wall: list[str] = Field(default_factory=list)
    walkable: bool | None = Field(
        default=None, description="None when not applicable (fewer than two doors)."
    )
    walkable_detail: str = ""

    @property
    def ok(self) -> bool:
        """True when no hard rule is broken."""
        return not (
            self.overlaps
            or self.clearance
            or self.outside_room
            or self.door_zones
            or self.windows
            or self.facing_wall
            or self.walkable is False
        )

    def problems(self, blocking: str) -> list[str]:
        """The broken rules in words, in rule order; ``blocking`` is said when the way between
        the doors is blocked ("the run blocks the way between the doors")."""
        out = [
            *self.overlaps,
            *self.clearance,
            *(f"{i} outside the room" for i in self.outside_room),
            *self.door_zones,
            *self.windows,
            *(f"{i} faces a wall" for i in self.facing_wall),
        ]
        if self.walkable is False:
            out.append(blocking)
        return out


class LayoutResult(BaseModel):
    """The answer for one room."""

    room_id: str
    placements: dict[str, Placement]
    constraints: list[ConstraintReport]
    satisfied: int
    total: int
    unplaced: list[UnplacedObject]
    solve_time_s: float
    solver_used: str
    solver_status: str
    hard_checks: HardChecks
    warnings: list[str]
    # the share of the free floor a robot reaches from the doors (holomj.layout.open_pockets)
    reachable_share: float | None = None

    def to_dict(self) -> dict:
        """JSON-ready data."""
        return self.model_dump(mode="json")
