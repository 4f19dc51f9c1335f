"""The stability report of ``holomj validate``: pure, frozen, versioned data.

Units: metres, degrees, seconds. Every object of the scene appears in ``objects`` with its
numbers, stable or not; ``reasons`` says in words why an object is not stable.
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field

from holomj.spec.base import FrozenModel, Vec3

REPORT_SCHEMA_VERSION = "1.0"

NonNegative = Annotated[float, Field(ge=0.0)]


class Thresholds(FrozenModel):
    """Every limit the validation uses, so a report says what it was judged against."""

    tolerance_m: NonNegative = Field(
        default=0.001, description="Penetration at t = 0 deeper than this is a defect."
    )
    drift_m: NonNegative = Field(default=0.01, description="Stable: moves less over monitor.")
    rotation_deg: NonNegative = Field(default=5.0, description="Stable: turns less over monitor.")
    fall_m: NonNegative = Field(default=0.05, description="Fell: ends this much below t = 0.")
    below_floor_m: NonNegative = Field(
        default=0.01, description="Fell through: lowest collider point below -this at the end."
    )
    room_margin_m: NonNegative = Field(
        default=0.05, description="An object within this distance of its room counts as inside."
    )
    rest_linear_mps: NonNegative = Field(default=0.005, description="At rest: slower than this.")
    rest_angular_rps: NonNegative = Field(default=0.05, description="At rest: turns slower.")
    rest_window_s: NonNegative = Field(
        default=0.25, description="Settled: every free body at rest for this long."
    )
    settle_cap_s: NonNegative = Field(default=5.0, description="Most time spent settling.")
    monitor_s: NonNegative = Field(default=3.0, description="Window the numbers are taken over.")
    repair_max_m: NonNegative = Field(
        default=0.05, description="--repair resolves penetrations up to this depth."
    )


class ObjectReport(FrozenModel):
    """One object: how it behaved over the monitor window and why it is not stable."""

    name: str
    stable: bool
    dynamic: bool = Field(description="Has a free joint in the validated model.")
    drift_m: NonNegative = Field(description="Distance moved over the monitor window.")
    rotation_deg: NonNegative = Field(description="Rotation over the monitor window.")
    path_m: NonNegative = Field(description="Path length over the monitor window (jitter).")
    drop_m: float = Field(description="Height lost from t = 0 to the end (negative: rose).")
    fell: bool
    left_room: bool
    support: str | None = Field(
        description="What it rests on at the end: an object id, 'floor' (ground and structure), "
        "'fixed' for a static object, None when nothing holds it up."
    )
    expected_support: str | None = Field(
        description="The scene's support ('floor' when none); None: anything will do."
    )
    penetration_m: NonNegative = Field(description="Deepest contact during the monitor window.")
    at_rest: bool
    reasons: list[str] = Field(default_factory=list)


class PenetrationPair(FrozenModel):
    """Two things that overlap at t = 0 more than the tolerance (the deepest geom pair)."""

    a: str
    b: str
    geom_a: str
    geom_b: str
    depth_m: NonNegative


class ObjectDefect(FrozenModel):
    """An object in a wrong place at t = 0 (below the floor, outside every room)."""

    name: str
    value_m: float = Field(
        description="Below floor: lowest collider z; outside: distance to the nearest room."
    )


class RepairAction(FrozenModel):
    """An object ``--repair`` moved, and by how much."""

    name: str
    moved_m: NonNegative
    translation: Vec3
    rotation_deg: NonNegative = 0.0
    why: str


class Unsaved(FrozenModel):
    """An object ``--repair`` could not fix; it stays in the scene."""

    name: str
    why: str


class StabilityReport(FrozenModel):
    """Everything ``holomj validate`` found about a scene."""

    schema_version: Literal["1.0"] = REPORT_SCHEMA_VERSION
    ok: bool = Field(
        description="Every object stable, no penetration, object below the floor or outside "
        "the rooms at t = 0, and no MuJoCo warning."
    )
    source: str
    furniture: str = "free"
    objects: list[ObjectReport]
    penetrations: list[PenetrationPair] = Field(default_factory=list)
    below_floor: list[ObjectDefect] = Field(default_factory=list)
    outside_rooms: list[ObjectDefect] = Field(default_factory=list)
    max_penetration_m: NonNegative = Field(
        default=0.0, description="Deepest contact of any object during the monitor window."
    )
    warnings: dict[str, int] = Field(default_factory=dict)
    counts: dict[str, int] = Field(default_factory=dict)
    sim_time_s: NonNegative = 0.0
    wall_time_s: NonNegative = 0.0
    realtime_factor: NonNegative = 0.0
    settle_time_s: NonNegative = Field(default=0.0, description="Sim time until at rest.")
    settled: bool = Field(default=True, description="At rest before the settle cap.")
    monitor_s: NonNegative = 0.0
    thresholds: Thresholds = Field(default_factory=Thresholds)
    repaired: list[RepairAction] = Field(default_factory=list)
    unsaved: list[Unsaved] = Field(default_factory=list)

    def unstable(self) -> list[ObjectReport]:
        """The objects that are not stable."""
        return [o for o in self.objects if not o.stable]
