"""Scene edits as data: the operations ``holomj edit`` applies, and the report it writes.

An operations file is a JSON list (or ``{"operations": [...]}``) of at most
:data:`MAX_OPERATIONS` objects, each naming its ``op``:

==========  ===============================================================================
op          what it does
==========  ===============================================================================
add         a described object ("a green armchair") in a room, with optional attributes,
            size and relations (near / against the wall / facing / by the window / in the
            corner ...), or at a given position
add_on      small objects ("a red mug") dropped on or in a receptacle of the scene
remove      an object (and what rests on it)
move        an object to a position and/or yaw, to where relations hold, or (a small
            object) onto another receptacle
replace     an object by a newly described one in the same place
material    a room's floor, walls or ceiling (a material name or a description)
light       add a light fixture to a room, or change one (a fixture object or a light)
==========  ===============================================================================

The format is strict (unknown fields are errors, numbers must be finite): a file that does not
parse is refused as a whole. What the scene decides (an unknown id, a size over 10 m, a position
outside every room, a material nothing matches) refuses only that operation, with the reason, in
the :class:`EditReport`. Nothing in an operations file is ever executed.
"""

from __future__ import annotations

from typing import Annotated, Any, Final, Literal

from pydantic import BaseModel, Field, RootModel, model_validator

from holomj.errors import SpecError
from holomj.spec.base import (
    FrozenModel,
    Identifier,
    PositiveFloat,
    Rgb,
    Vec2,
    Vec3,
    validate_model,
)
from holomj.spec.relations import EDIT_OBJECT_KINDS, EDIT_PLACE_KINDS, EditRelationKind

EDIT_SCHEMA_VERSION: Final = "1.0"
MAX_OPERATIONS = 50  # per file (and per refine round)
MAX_RELATIONS = 8
MAX_ADD_ON = 10

Description = Annotated[str, Field(min_length=1, max_length=300)]
Category = Annotated[
    str, Field(min_length=1, max_length=64, pattern=r"^[A-Za-z0-9][A-Za-z0-9_ \-]*$")
]
Attribute = Annotated[
    str, Field(min_length=1, max_length=40, pattern=r"^[A-Za-z0-9][A-Za-z0-9 \-]*$")
]
Size = tuple[PositiveFloat, PositiveFloat, PositiveFloat]
Yaw = Annotated[float, Field(ge=-3600.0, le=3600.0)]

# Relations an edit may ask of a floor object (:mod:`holomj.spec.relations`): places (no target)
# and relations to another object of the room (its id). ``above`` is for wall and ceiling objects.
PLACE_RELATIONS = EDIT_PLACE_KINDS
OBJECT_RELATIONS = EDIT_OBJECT_KINDS


class EditRelation(FrozenModel):
    """Where an object should be: a place of its room (``corner``, ``wall`` (against a wall),
    ``middle``, ``under_window``, ``by_window``, ``by_door``, ``facing_window``,
    ``facing_door``: no target) or a relation to another object of the room (``target``, its
    id: ``adjacent_to`` (next to), ``near``, ``in_front_of``, ``behind``, ``facing``,
    ``across_from``, ``around`` (at a table), ``above`` (wall and ceiling objects))."""

    kind: EditRelationKind
    target: Identifier | None = None

    @model_validator(mode="after")
    def _check_target(self) -> EditRelation:
        if self.kind in PLACE_RELATIONS and self.target is not None:
            raise ValueError(f"'{self.kind}' takes no target")
        if self.kind in OBJECT_RELATIONS and self.target is None:
            raise ValueError(f"'{self.kind}' needs a target object id")
        return self


class _Operation(FrozenModel):
    comment: str = Field(
        default="", max_length=500, description="Why (for people and logs); not interpreted."
    )


class AddOp(_Operation):
    """Add a described object. Its kind, size and placement (floor, wall or ceiling) come from
    the planner's knowledge base (unknown nouns are planned like their nearest kinds), its
    asset from retrieval. Relations in the description ("by the window", "next to the sofa")
    count like ``relations``. Without ``position`` a floor object goes to the free floor pose
    (no overlap, clear of doors and windows, reachable) that satisfies most relations; only
    the new object is laid out, everything else stays where it is."""

    op: Literal["add"]
    description: Description
    room: Identifier | None = Field(
        default=None,
        description="Room id (default: the room of the first relation target, or "
        "of the position, or the scene's only room).",
    )
    id: Identifier | None = Field(default=None, description="Id for the new object.")
    category: Category | None = Field(default=None, description="Library category hint.")
    attributes: list[Attribute] = Field(
        default_factory=list, max_length=10, description="Words for retrieval: 'green', 'oak'."
    )
    size: Size | None = Field(
        default=None, description="(width, depth, height) in metres; each at most 10 m."
    )
    relations: list[EditRelation] = Field(default_factory=list, max_length=MAX_RELATIONS)
    position: Vec2 | Vec3 | None = Field(
        default=None, description="Floor (x, y) of the object's footprint centre; z ignored."
    )
    yaw_deg: Yaw | None = None
    placement: Literal["floor", "wall", "ceiling"] | None = Field(
        default=None, description="Default: the kind's placement."
    )


class AddOnOp(_Operation):
    """Drop small objects on or in a receptacle (spawn-and-drop: accepted only where they come
    to rest on it)."""

    op: Literal["add_on"]
    description: Description
    on: Identifier = Field(description="Id of the receptacle object.")
    count: Annotated[int, Field(ge=1, le=MAX_ADD_ON)] = 1
    category: Category | None = None
    attributes: list[Attribute] = Field(default_factory=list, max_length=10)


class RemoveOp(_Operation):
    """Remove an object; the small objects resting on it go with it."""

    op: Literal["remove"]
    id: Identifier


class MoveOp(_Operation):
    """Move an object: to ``position`` / ``yaw_deg`` (checked, never adjusted), to the best free
    pose where ``relations`` hold, or (a small object) onto the receptacle ``on``. Small objects
    on a moved receptacle move along with it."""

    op: Literal["move"]
    id: Identifier
    position: Vec2 | Vec3 | None = None
    yaw_deg: Yaw | None = None
    relations: list[EditRelation] = Field(default_factory=list, max_length=MAX_RELATIONS)
    on: Identifier | None = None

    @model_validator(mode="after")
    def _check(self) -> MoveOp:
        given = [self.position is not None or self.yaw_deg is not None, bool(self.relations)]
        if self.on is not None and any(given):
            raise ValueError("'on' moves a small object onto a receptacle: give it alone")
        if self.on is None and not any(given):
            raise ValueError("give position, yaw_deg, relations or on")
        if self.position is not None and self.relations:
            raise ValueError("give a position or relations, not both")
        return self


class ReplaceOp(_Operation):
    """Replace an object by a newly described one (a new asset) in the same place; its
    footprint is checked, and the nearest free pose taken when it does not fit there."""

    op: Literal["replace"]
    id: Identifier
    description: Description
    category: Category | None = None
    attributes: list[Attribute] = Field(default_factory=list, max_length=10)
    size: Size | None = None


class MaterialOp(_Operation):
    """Give a room's floor, walls or ceiling a material: a material's name or a description
    ("light oak parquet") matched against the material library."""

    op: Literal["material"]
    room: Identifier | None = Field(default=None, description="Default: every room.")
    surface: Literal["floor", "wall", "walls", "ceiling"]
    material: Description


class LightOp(_Operation):
    """Add a light fixture (a ceiling object: "a pendant light"; by default "a ceiling light")
    to a room, at ``position``, above the object ``above`` or at the room's centre; or, with
    ``id``, change a fixture object (move it, or a new ``description``) or one of the scene's
    lights (position, energy, colour, kind). A room with fixtures is lit by a light under each
    of them."""

    op: Literal["light"]
    id: Identifier | None = None
    room: Identifier | None = None
    description: Description | None = None
    position: Vec2 | Vec3 | None = None
    above: Identifier | None = None
    energy: Annotated[float, Field(ge=0.0, le=100.0)] | None = None
    color: Rgb | None = None
    kind: Literal["point", "spot", "directional"] | None = None

    @model_validator(mode="after")
    def _check(self) -> LightOp:
        if self.position is not None and self.above is not None:
            raise ValueError("give a position or above, not both")
        return self


Operation = Annotated[
    AddOp | AddOnOp | RemoveOp | MoveOp | ReplaceOp | MaterialOp | LightOp,
    Field(discriminator="op"),
]
OP_NAMES = ("add", "add_on", "remove", "move", "replace", "material", "light")


class EditOperations(RootModel[list[Operation]]):
    """An operations file: a list of operations, applied in order."""

    root: list[Operation] = Field(max_length=MAX_OPERATIONS)


def parse_operations(data: Any, source: str = "operations") -> list[Any]:
    """Validate parsed JSON (a list, or ``{"operations": [...]}``) as operations; a
    :class:`~holomj.errors.SpecError` naming ``source`` and the field otherwise."""
    if isinstance(data, dict) and set(data) <= {"operations", "schema_version"}:
        if data.get("schema_version", EDIT_SCHEMA_VERSION) != EDIT_SCHEMA_VERSION:
            raise SpecError(
                f"unknown schema_version {data['schema_version']!r}",
                where=f"{source}: schema_version",
                fix=f"use {EDIT_SCHEMA_VERSION!r}",
            )
        data = data.get("operations")
    if not isinstance(data, list):
        raise SpecError(
            "expected a JSON list of operations",
            where=source,
            fix='e.g. [{"op": "remove", "id": "living_room.armchair_0"}]; see holomj schema edit',
        )
    return list(validate_model(EditOperations, data, source).root)


def operations_schema() -> dict[str, Any]:
    """The JSON Schema of an operations file (``holomj schema edit``)."""
    schema = EditOperations.model_json_schema()
    schema["$comment"] = (
        f"holomj edit operations, format {EDIT_SCHEMA_VERSION}: a JSON list of operations "
        f'(or {{"operations": [...]}}), at most {MAX_OPERATIONS}'
    )
    return schema


# --------------------------------------------------------------------------- report


class MovedObject(BaseModel):
    """An object that changed pose, from where to where, and why."""

    id: str
    from_position: Vec3
    to_position: Vec3
    from_yaw_deg: float
    to_yaw_deg: float
    why: str


class OperationResult(BaseModel):
    """One operation: applied or refused (with the reason), and what it changed."""

    index: int
    op: str
    status: Literal["applied", "refused"]
    reason: str = ""
    added: list[str] = Field(default_factory=list)
    removed: list[str] = Field(default_factory=list)
    moved: list[str] = Field(default_factory=list)
    changed: list[str] = Field(default_factory=list)
    notes: list[str] = Field(default_factory=list)
    details: dict[str, Any] = Field(default_factory=dict)
    seconds: float = 0.0


class EditReport(BaseModel):
    """``edit_report.json``: every operation's outcome, what moved, the new validation."""

    schema_version: Literal["1.0"] = EDIT_SCHEMA_VERSION
    source: str
    output: str
    seed: int = 0
    operations: list[OperationResult] = Field(default_factory=list)
    applied: int = 0
    refused: int = 0
    added: list[str] = Field(default_factory=list)
    removed: list[str] = Field(default_factory=list)
    moved: list[MovedObject] = Field(default_factory=list)
    validation: dict[str, Any] | None = Field(
        default=None, description="ok, counts, max penetration and the unstable objects."
    )
    written: bool = False
    stale_files: list[str] = Field(default_factory=list)
    seconds: float = 0.0

    @property
    def ok(self) -> bool:
        """Every operation applied and the edited scene validated (or was not validated)."""
        valid = self.validation is None or bool(self.validation.get("ok"))
        return self.refused == 0 and valid
