"""SceneSpec: the source of truth for a scene, as frozen, versioned data.

Frame: MuJoCo's (metres, Z up, floor at z = 0). An object's ``position`` is where its asset's
local origin goes, which is the centre of its footprint at its bottom; its front faces +X at
``yaw_deg = 0`` and yaw turns counter-clockwise about +Z.
"""

from __future__ import annotations

import math
from typing import Annotated, Final, Literal

from pydantic import Field, field_validator, model_validator

from holomj.errors import SpecError
from holomj.spec.base import (
    FrozenModel,
    Identifier,
    PositiveFloat,
    Rgb,
    Vec2,
    Vec3,
    Vec4,
)
from holomj.spec.materials import BUILTIN_MATERIALS, Material
from holomj.spec.walls import Wall, derive_walls, find_wall_for_opening, room_polygon

SCHEMA_VERSION: Final = "1.0"

DOOR_WIDTHS = {"single": 1.0, "double": 2.0}
DOOR_KINDS = ("doorway", "doorframe", "open")
WINDOW_KINDS = ("fixed", "hung", "slider")


class Room(FrozenModel):
    """A room: a simple floor polygon (any shape, metres) and the materials of its surfaces."""

    id: Identifier
    type: str = Field(default="room", max_length=64)
    polygon: list[Vec2] = Field(min_length=3, max_length=256)
    floor_material: str = "floor_default"
    wall_material: str = "wall_default"
    ceiling_material: str = "ceiling_default"


class Door(FrozenModel):
    """A door in the wall between two rooms, or in an exterior wall when it names one room.

    ``doorway``: a frame with a hinged leaf; ``doorframe``: a frame, no leaf; ``open``: a
    full-height gap with no frame at all. ``position`` is the centre of the opening on the wall
    line, in world x/y.
    """

    id: Identifier
    kind: Literal["doorway", "doorframe", "open"] = "doorway"
    rooms: Annotated[list[Identifier], Field(min_length=1, max_length=2)]
    position: Vec2
    leaves: Literal["single", "double"] = "single"
    width: Annotated[float, Field(ge=0.4, le=4.0)] | None = None
    height: Annotated[float, Field(ge=1.5, le=4.0)] = 2.1
    hinge_side: Literal["left", "right"] = Field(
        default="left", description="Hinge side seen from the room the door opens into."
    )
    opens_into: Identifier | None = Field(
        default=None, description="Room the leaf swings into (default: the first room)."
    )
    material: str = "door_default"

    @property
    def effective_width(self) -> float:
        """The width in metres: the given one, else 1 m (single) or 2 m (double)."""
        return self.width if self.width is not None else DOOR_WIDTHS[self.leaves]


class Window(FrozenModel):
    """A window: a hole in a wall with a frame and a glass pane."""

    id: Identifier
    kind: Literal["fixed", "hung", "slider"] = "fixed"
    rooms: Annotated[list[Identifier], Field(min_length=1, max_length=2)]
    position: Vec2
    width: Annotated[float, Field(ge=0.2, le=6.0)] = 1.2
    height: Annotated[float, Field(ge=0.2, le=4.0)] = 1.2
    base_height: Annotated[float, Field(ge=0.0, le=4.0)] = 0.9


class SceneObject(FrozenModel):
    """An instance of a library asset placed in the scene."""

    id: Identifier
    asset: str = Field(min_length=1, max_length=256)
    position: Vec3
    yaw_deg: float = 0.0
    quat: Vec4 | None = Field(
        default=None, description="Full rotation (w, x, y, z); overrides yaw_deg when given."
    )
    scale: PositiveFloat | tuple[PositiveFloat, PositiveFloat, PositiveFloat] = 1.0
    static: bool = Field(default=False, description="Static objects get no joint.")
    support: Identifier | None = Field(
        default=None, description="Object this one rests on; None means the floor."
    )
    room: Identifier | None = None
    mass_kg: PositiveFloat | None = None
    proxy: bool | None = Field(
        default=None,
        description="True when the asset is a proxy (a stand-in for a category the library "
        "could not supply); left out otherwise.",
    )

    @field_validator("quat")
    @classmethod
    def _unit_quat(cls, quat: Vec4 | None) -> Vec4 | None:
        if quat is None:
            return None
        norm = math.sqrt(sum(q * q for q in quat))
        if norm < 1e-9:
            raise ValueError("quaternion has zero length")
        w, x, y, z = (q / norm for q in quat)
        return (w, x, y, z)

    @property
    def scale3(self) -> tuple[float, float, float]:
        """The scale as three factors."""
        if isinstance(self.scale, tuple):
            return self.scale
        return (self.scale, self.scale, self.scale)


class Light(FrozenModel):
    """A light source. ``energy`` scales the colour (1 = full diffuse)."""

    id: Identifier
    kind: Literal["point", "spot", "directional"] = "point"
    position: Vec3 = (0.0, 0.0, 2.5)
    direction: Vec3 = (0.0, 0.0, -1.0)
    energy: Annotated[float, Field(ge=0.0, le=100.0)] = 1.0
    color: Rgb = (1.0, 1.0, 1.0)
    cast_shadow: bool = False
    cutoff_deg: Annotated[float, Field(gt=0.0, le=90.0)] = 45.0

    @field_validator("direction")
    @classmethod
    def _nonzero_direction(cls, direction: Vec3) -> Vec3:
        if math.sqrt(sum(d * d for d in direction)) < 1e-9:
            raise ValueError("direction has zero length")
        return direction


class Camera(FrozenModel):
    """A fixed camera looking from ``position`` at ``target``."""

    id: Identifier
    position: Vec3
    target: Vec3
    fovy_deg: Annotated[float, Field(gt=0.0, lt=180.0)] = 60.0
    orthographic: bool = False

    @model_validator(mode="after")
    def _distinct_points(self) -> Camera:
        if math.dist(self.position, self.target) < 1e-6:
            raise ValueError("camera position and target coincide")
        return self


class SceneSpec(FrozenModel):
    """A whole scene. Walls are not stored: they are derived from the rooms (see ``walls``)."""

    schema_version: Literal["1.0"] = SCHEMA_VERSION
    name: str = Field(default="scene", max_length=128)
    wall_height: Annotated[float, Field(ge=1.5, le=20.0)] = 2.7
    wall_thickness: Annotated[float, Field(ge=0.02, le=0.5)] = Field(
        default=0.1, description="Interior walls, centred on the shared room edge."
    )
    exterior_wall_thickness: Annotated[float, Field(ge=0.05, le=1.0)] = Field(
        default=0.2, description="Exterior walls, grown outwards from the room edge."
    )
    ceilings: bool = False
    rooms: list[Room] = Field(min_length=1, max_length=256)
    doors: list[Door] = Field(default_factory=list, max_length=1024)
    windows: list[Window] = Field(default_factory=list, max_length=1024)
    objects: list[SceneObject] = Field(default_factory=list, max_length=20000)
    lights: list[Light] = Field(default_factory=list, max_length=256)
    cameras: list[Camera] = Field(default_factory=list, max_length=256)
    materials: dict[Identifier, Material] = Field(default_factory=dict)
    source: str | None = Field(default=None, description="Where this scene came from.")

    @model_validator(mode="after")
    def _check_consistency(self) -> SceneSpec:
        _check_unique(("rooms", [r.id for r in self.rooms]))
        _check_unique(("objects", [o.id for o in self.objects]))
        _check_unique(
            ("doors", [d.id for d in self.doors]), ("windows", [w.id for w in self.windows])
        )
        _check_unique(("lights", [li.id for li in self.lights]))
        _check_unique(("cameras", [c.id for c in self.cameras]))
        _check_materials(self)
        _check_rooms(self.rooms)
        _check_openings(self)
        _check_objects(self)
        return self

    @property
    def walls(self) -> list[Wall]:
        """The walls derived from the rooms: shared edges once, exterior edges once."""
        return derive_walls(self.rooms)

    @property
    def openings(self) -> list[Door | Window]:
        """The doors, then the windows."""
        return [*self.doors, *self.windows]

    def room(self, room_id: str) -> Room:
        """The room with this id."""
        for room in self.rooms:
            if room.id == room_id:
                return room
        raise SpecError(f"no room with id {room_id!r}", where="rooms")


def _check_unique(*lists: tuple[str, list[str]]) -> None:
    """Reject an id used twice across ``lists`` (``(field, ids)`` pairs sharing one namespace),
    naming both places: ``windows[0].id: duplicate id 'x' (also doors[2].id)``."""
    first: dict[str, str] = {}
    for field, ids in lists:
        for index, item in enumerate(ids):
            where = f"{field}[{index}].id"
            if item in first:
                raise SpecError(f"duplicate id {item!r} (also {first[item]})", where=where)
            first[item] = where


def _check_materials(scene: SceneSpec) -> None:
    known = set(BUILTIN_MATERIALS) | set(scene.materials)
    refs = [
        (f"rooms[{i}].{field}", getattr(room, field))
        for i, room in enumerate(scene.rooms)
        for field in ("floor_material", "wall_material", "ceiling_material")
    ] + [(f"doors[{i}].material", door.material) for i, door in enumerate(scene.doors)]
    for where, name in refs:
        if name not in known:
            raise SpecError(
                f"unknown material {name!r}",
                where=where,
                fix="define it under 'materials' or use a built-in one such as 'floor_default'",
            )


def _check_rooms(rooms: list[Room]) -> None:
    polygons = []
    for index, room in enumerate(rooms):
        try:
            polygons.append(room_polygon(room.polygon))
        except SpecError as err:
            raise err.located(f"rooms[{index}].polygon ({room.id})") from None
    for i in range(len(polygons)):
        for j in range(i + 1, len(polygons)):
            if not polygons[i].intersects(polygons[j]):
                continue
            overlap = polygons[i].intersection(polygons[j]).area
            if overlap > 1e-4:
                raise SpecError(
                    f"room {rooms[i].id!r} overlaps room {rooms[j].id!r} by {overlap:.3f} m²",
                    where=f"rooms[{j}].polygon",
                    fix="rooms may share edges but not area",
                )


def _check_openings(scene: SceneSpec) -> None:
    room_ids = {r.id for r in scene.rooms}
    walls = scene.walls
    spans: dict[str, list[tuple[float, float, str, float, float]]] = {}
    openings = [("doors", i, d) for i, d in enumerate(scene.doors)] + [
        ("windows", i, w) for i, w in enumerate(scene.windows)
    ]
    for kind, index, opening in openings:
        where = f"{kind}[{index}]"
        for room in opening.rooms:
            if room not in room_ids:
                raise SpecError(f"unknown room {room!r}", where=f"{where}.rooms")
        if len(opening.rooms) == 2 and opening.rooms[0] == opening.rooms[1]:
            raise SpecError("an opening joins two different rooms", where=f"{where}.rooms")
        if isinstance(opening, Door):
            width, bottom, top = opening.effective_width, 0.0, opening.height
            if opening.opens_into is not None and opening.opens_into not in opening.rooms:
                raise SpecError(
                    f"room {opening.opens_into!r} is not one of the door's rooms",
                    where=f"{where}.opens_into",
                )
        else:
            width, bottom = opening.width, opening.base_height
            top = opening.base_height + opening.height
        if top > scene.wall_height - 0.05:
            raise SpecError(
                f"opening top at {top:.2f} m reaches the wall top ({scene.wall_height:.2f} m)",
                where=where,
                fix="lower it or raise wall_height",
            )
        try:
            wall, t = find_wall_for_opening(walls, opening.rooms, opening.position, width)
        except SpecError as err:
            raise err.located(where) from None
        spans.setdefault(wall.id, []).append((t - width / 2, t + width / 2, where, bottom, top))
    for items in spans.values():
        items.sort()
        for (_, a1, a_where, a_bot, a_top), (b0, _, b_where, b_bot, b_top) in zip(items, items[1:]):
            if b0 < a1 - 1e-6 and a_bot < b_top and b_bot < a_top:
                raise SpecError(f"overlaps {a_where} on the same wall", where=b_where)


def _check_objects(scene: SceneSpec) -> None:
    room_ids = {r.id for r in scene.rooms}
    object_ids = {o.id for o in scene.objects}
    for index, obj in enumerate(scene.objects):
        where = f"objects[{index}]"
        if obj.room is not None and obj.room not in room_ids:
            raise SpecError(f"unknown room {obj.room!r}", where=f"{where}.room")
        if obj.support is not None:
            if obj.support not in object_ids:
                raise SpecError(f"unknown support object {obj.support!r}", where=f"{where}.support")
            if obj.support == obj.id:
                raise SpecError("an object cannot rest on itself", where=f"{where}.support")
