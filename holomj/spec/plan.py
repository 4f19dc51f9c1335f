"""ScenePlan: what a planner (offline knowledge base or LLM) decided a request needs.

A plan is pure data, written to ``OUT/plan.json``. It names rooms with sizes and materials (as
descriptions: the retrieval stage turns them into materials), the objects of each room with
sizes in metres, quantities and same/varied variance, small objects to drop on receptacles, and
layout constraints in the layout language's text form over *instance names*: an object named
``dining chair`` with quantity 4 has the instances ``dining chair-0`` ... ``dining chair-3``.

Object sizes are (width, depth, height) in metres: width left-right, depth front-back (the
object's front faces +X in the asset frame), height up.
"""

from __future__ import annotations

from typing import Annotated, Any, Literal

from pydantic import Field, model_validator

from holomj.spec.base import FrozenModel, Identifier, PositiveFloat
from holomj.spec.relations import PlanRelationKind

PLAN_SCHEMA_VERSION: Literal["1.0"] = "1.0"

# Names of plan objects: Holodeck-like ("dining chair"), no '|' or ',' (they separate fields of
# the constraint text form) and no trailing "-<n>" (that is an instance suffix).
ObjectName = Annotated[
    str, Field(min_length=1, max_length=64, pattern=r"^[a-z0-9][a-z0-9 _.+]*[a-z0-9]$|^[a-z0-9]$")
]
Size3 = tuple[PositiveFloat, PositiveFloat, PositiveFloat]
Variance = Literal["same", "varied"]
RoomSide = Annotated[float, Field(ge=1.0, le=40.0)]
# The shapes of a kitchen's counter run (see holomj.layout.counter_runs).
CounterRunShape = Literal["one_wall", "galley", "L", "U"]
# Rows asked for a floor object's instances: how many, or "any" (rows, the count left open).
RowsAsked = Annotated[int, Field(ge=1, le=20)] | Literal["any"]


def instance_name(name: str, index: int) -> str:
    """The name of the ``index``-th instance of a plan object (``"sofa"``, 0 -> ``"sofa-0"``)."""
    return f"{name}-{index}"


class PlanSmallObject(FrozenModel):
    """Small objects to drop onto the receptacle that lists them."""

    name: ObjectName
    description: str = Field(default="", max_length=500)
    category: str | None = Field(
        default=None, max_length=64, description="Library category hint (the offline planner's)."
    )
    quantity: Annotated[int, Field(ge=1, le=30)] = 1
    variance: Variance = "varied"
    instances: Annotated[int, Field(ge=1, le=40)] | None = Field(
        default=None,
        description="On this many of the receptacle's instances (the first ones); all if null.",
    )


class PlanObject(FrozenModel):
    """A floor or wall object of a room, with how many and how alike they are."""

    name: ObjectName
    description: str = Field(default="", max_length=500)
    category: str | None = Field(
        default=None, max_length=64, description="Library category hint (the offline planner's)."
    )
    size: Size3 | None = Field(
        default=None, description="(width, depth, height) in metres; None: the asset's own."
    )
    quantity: Annotated[int, Field(ge=1, le=40)] = 1
    variance: Variance = "same"
    placement: Literal["floor", "wall", "ceiling"] = "floor"
    above: ObjectName | None = Field(
        default=None,
        description="Wall objects only: hang above this floor object (its first instance).",
    )
    faced_by: ObjectName | None = Field(
        default=None,
        description="Wall objects only: hang where this floor object looks (its first "
        "instance's front meets the wall): a mirror the salon chair faces.",
    )
    on_top: list[PlanSmallObject] = Field(default_factory=list, max_length=20)
    requested: bool = Field(default=False, description="Explicitly asked for in the request.")
    defining: bool = Field(
        default=False,
        description="Defining furniture of its room (a bed in a bedroom): laid out first, and "
        "the plan changes (a window moves) before it is dropped.",
    )
    rows: RowsAsked | None = Field(
        default=None,
        description="Floor objects only: the request asks for the instances in rows (desks in "
        "a classroom): how many rows, or 'any' when it does not say; null when it asks none.",
    )

    @model_validator(mode="after")
    def _check(self) -> PlanObject:
        if self.above is not None and self.placement == "floor":
            raise ValueError("'above' is for wall and ceiling objects")
        if self.faced_by is not None and self.placement != "wall":
            raise ValueError("'faced_by' is for wall objects")
        if self.rows is not None and self.placement != "floor":
            raise ValueError("'rows' is for floor objects")
        return self

    def instances(self) -> list[str]:
        """Instance names, ``name-0`` ... ``name-(quantity-1)``."""
        return [instance_name(self.name, k) for k in range(self.quantity)]


class PlanWindows(FrozenModel):
    """Windows of one room: how many, of which kind (None: the room type's defaults)."""

    count: Annotated[int, Field(ge=0, le=12)] | None = None
    kind: Literal["fixed", "hung", "slider"] | None = None


class PlanRelation(FrozenModel):
    """Where the request puts an object: ``subject`` (a plan object, all its instances) in
    relation ``kind`` to ``target`` (another plan object of the room) or to a place (no target:
    corner, wall, middle, under / by a window, by a door, hanging from the ceiling).

    Layout relations become weighted layout constraints per instance; ``on`` (small objects on
    a receptacle), ``above`` (a wall object over a floor object) and ``ceiling`` are kept by the
    plan's structure. ``generate.json`` reports whether each one holds.
    """

    subject: ObjectName
    kind: PlanRelationKind
    target: ObjectName | None = None
    phrase: str = Field(default="", max_length=300, description="The request's words for it.")


class PlanRoom(FrozenModel):
    """One room of the plan."""

    id: Identifier
    type: str = Field(min_length=1, max_length=64)
    size: tuple[RoomSide, RoomSide] | None = Field(
        default=None, description="Exact (width, depth) in metres, or None to use area_m2."
    )
    area_m2: Annotated[float, Field(ge=1.0, le=1600.0)] | None = None
    adjacent_to: list[Identifier] = Field(default_factory=list, max_length=16)
    floor_material: str = Field(default="wood floor", max_length=200)
    wall_material: str = Field(default="white paint", max_length=200)
    ceiling_material: str = Field(default="white ceiling", max_length=200)
    windows: PlanWindows = Field(default_factory=PlanWindows)
    objects: list[PlanObject] = Field(default_factory=list, max_length=80)
    constraints: list[str] = Field(
        default_factory=list,
        max_length=2000,
        description="Layout constraints, text form over instance names: "
        "'coffee table-0 | near, sofa-0'.",
    )
    relations: list[PlanRelation] = Field(
        default_factory=list,
        max_length=200,
        description="Where the request puts the room's objects (weighted above the defaults).",
    )
    counter_run_shape: CounterRunShape | None = Field(
        default=None,
        description="The shape the request or the room's words ask for the kitchen's counter "
        "run ('a galley kitchen', 'U-shaped counters'); null: the layout chooses.",
    )

    @model_validator(mode="after")
    def _check(self) -> PlanRoom:
        if self.size is not None and self.area_m2 is not None:
            raise ValueError("give size or area_m2, not both")
        names = [o.name for o in self.objects]
        dupes = sorted({n for n in names if names.count(n) > 1})
        if dupes:
            raise ValueError(f"object names repeat: {', '.join(dupes)}")
        floor = {o.name for o in self.objects if o.placement == "floor"}
        for obj in self.objects:
            if obj.above is not None and obj.above not in floor:
                raise ValueError(f"{obj.name!r} hangs above {obj.above!r}, not a floor object here")
            if obj.faced_by is not None and obj.faced_by not in floor:
                raise ValueError(
                    f"{obj.name!r} is faced by {obj.faced_by!r}, not a floor object here"
                )
        if self.id in self.adjacent_to:
            raise ValueError("a room cannot be adjacent to itself")
        small = {s.name for o in self.objects for s in o.on_top}
        for rel in self.relations:
            known = set(names) | (small if rel.kind == "on" else set())
            for name in (rel.subject, rel.target):
                if name is not None and name not in known:
                    raise ValueError(f"relation {rel.kind!r} names {name!r}, not an object here")
        return self

    @property
    def area(self) -> float | None:
        """The requested floor area, if any (size wins over area_m2)."""
        if self.size is not None:
            return self.size[0] * self.size[1]
        return self.area_m2


class ScenePlan(FrozenModel):
    """Everything the later stages need to know about a request."""

    schema_version: Literal["1.0"] = PLAN_SCHEMA_VERSION
    prompt: str = Field(max_length=20_000)
    planner: Literal["offline", "llm"]
    seed: Annotated[int, Field(ge=0)]
    scene_type: str = Field(min_length=1, max_length=64)
    scene_type_match: str = Field(
        default="", max_length=500, description="How the scene type was chosen, for people."
    )
    style: list[str] = Field(default_factory=list, max_length=20)
    wall_height: Annotated[float, Field(ge=2.2, le=6.0)] = 2.7
    entrance_room: Identifier | None = None
    rooms: list[PlanRoom] = Field(min_length=1, max_length=30)
    notes: list[str] = Field(
        default_factory=list,
        max_length=200,
        description="What the planner could not do as asked, assumptions, fallbacks.",
    )
    usage: dict[str, Any] = Field(
        default_factory=dict, description="LLM accounting: calls, tokens, seconds (LLM plans)."
    )

    @model_validator(mode="after")
    def _check(self) -> ScenePlan:
        ids = [r.id for r in self.rooms]
        dupes = sorted({i for i in ids if ids.count(i) > 1})
        if dupes:
            raise ValueError(f"room ids repeat: {', '.join(dupes)}")
        for room in self.rooms:
            unknown = [n for n in room.adjacent_to if n not in ids]
            if unknown:
                raise ValueError(f"room {room.id!r} is adjacent to unknown {unknown[0]!r}")
        if self.entrance_room is not None and self.entrance_room not in ids:
            raise ValueError(f"entrance room {self.entrance_room!r} is not a room of the plan")
        return self

    def room(self, room_id: str) -> PlanRoom:
        """The room with this id (KeyError when absent)."""
        for room in self.rooms:
            if room.id == room_id:
                return room
        raise KeyError(room_id)
