"""Geometry shared by the wall-object placers: the faces of a room's walls and what hangs on them.

A wall object hangs on the interior face of one of its room's walls: interior walls are centred
on the room edge, so their face is ``wall_thickness / 2`` into the room; exterior walls grow
outwards, so their face is the room edge itself. Along a face, ``t`` is the distance from the
wall's start; ``out`` is the distance from the face into the room.

Used by :mod:`holomj.layout.wall_objects` (paintings, shelves, TVs, ...) and
:mod:`holomj.layout.window_dressing` (curtains and blinds at windows).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from shapely.geometry import Polygon

from holomj.spec.scene import Door, Room, SceneObject, Window
from holomj.spec.walls import Wall

OPENING_MARGIN_M = 0.05  # frames stick out of the opening's span by about this
END_MARGIN_M = 0.1  # from the ends of a wall segment (a crossing interior wall's half thickness)
CEILING_GAP_M = 0.05  # a wall object's top stays this far below the wall top
OBJECT_GAP_M = 0.02  # between two wall objects


@dataclass(frozen=True)
class FloorItem:
    """A floor object as wall placement sees it: its footprint and its height."""

    id: str
    footprint: Polygon
    height: float
    front: tuple[float, float] | None = None  # the unit direction it faces, if known


@dataclass(frozen=True)
class WallPlacement:
    """Where a wall object goes: position of its bottom centre, yaw, and the wall it hangs on.

    ``scale`` is the factor (asset x = depth, y = width, z = height) the asset is stretched by
    to fit where it hangs (curtains sized to their window); None leaves it as it is.
    """

    id: str
    x: float
    y: float
    z: float
    yaw_deg: float
    wall_id: str
    room: str
    note: str | None = None  # how it was placed when not as asked (a TV off its stand's wall)
    scale: tuple[float, float, float] | None = None

    def scene_object(
        self, asset: str, scale: float | tuple[float, float, float] | None = None
    ) -> SceneObject:
        """A static SceneObject for this placement (at the placement's own scale unless one is
        given)."""
        if scale is None:
            scale = self.scale if self.scale is not None else 1.0
        return SceneObject(
            id=self.id,
            asset=asset,
            position=(self.x, self.y, self.z),
            yaw_deg=self.yaw_deg,
            scale=scale,
            static=True,
            room=self.room,
        )


@dataclass(frozen=True)
class Unplaced:
    """A wall object that found no place, and why."""

    id: str
    reason: str


@dataclass(frozen=True)
class WallFace:
    """The room-side face of one wall: ``offset`` from the wall line along ``inward``."""

    wall: Wall
    offset: float  # distance of the face from the wall line, into the room
    inward: tuple[float, float]


@dataclass(frozen=True)
class PlacedBox:
    """A wall object already hung: its footprint, its height range, and its span on its wall."""

    footprint: Polygon
    z0: float
    z1: float
    wall_id: str
    t0: float
    t1: float


@dataclass(frozen=True)
class WallSite:
    """A room's wall faces and what stands at them: the scene's walls, doors and windows (other
    rooms' among them), the floor furniture, the wall objects hung so far (hanging one more
    appends it) and the wall height."""

    faces: Sequence[WallFace]
    walls: Sequence[Wall]
    doors: Sequence[Door]
    windows: Sequence[Window]
    floor: Sequence[FloorItem]
    placed: list[PlacedBox]
    wall_height: float


def room_faces(room: Room, walls: Sequence[Wall], wall_thickness: float) -> list[WallFace]:
    """The faces of the walls of ``room`` (``walls`` are the scene's, from ``derive_walls``)."""
    faces = []
    for wall in walls:
        if room.id not in wall.rooms:
            continue
        nx, ny = wall.normal
        if wall.exterior:
            inward = (-wall.outward[0], -wall.outward[1])
            offset = 0.0
        else:
            inward = (nx, ny) if wall.left_room == room.id else (-nx, -ny)
            offset = wall_thickness / 2
        faces.append(WallFace(wall, offset, inward))
    return faces


def face_point(face: WallFace, t: float, out: float) -> tuple[float, float]:
    """World x/y of the point ``t`` along the face, ``out`` in front of it."""
    x, y = face.wall.point_at(t)
    ix, iy = face.inward
    d = face.offset + out
    return (x + ix * d, y + iy * d)


def face_band(face: WallFace, reach: float) -> Polygon:
    """The strip of floor in front of the face, ``reach`` deep."""
    wall = face.wall
    ix, iy = face.inward
    a = face_point(face, 0.0, 0.0)
    b = face_point(face, wall.length, 0.0)
    return Polygon(
        [a, b, (b[0] + ix * reach, b[1] + iy * reach), (a[0] + ix * reach, a[1] + iy * reach)]
    )


def face_rect(
    face: WallFace, t: float, width: float, depth: float, standoff: float = 0.0
) -> Polygon:
    """The footprint of an object ``width`` wide centred ``t`` along the face, ``depth`` deep,
    its back ``standoff`` in front of the face."""
    return Polygon(
        [
            face_point(face, t - width / 2, standoff),
            face_point(face, t + width / 2, standoff),
            face_point(face, t + width / 2, standoff + depth),
            face_point(face, t - width / 2, standoff + depth),
        ]
    )


def fits_on(face: WallFace, t: float, width: float) -> bool:
    """Whether an object ``width`` wide centred ``t`` along the face keeps clear of its ends."""
    return (
        t - width / 2 >= END_MARGIN_M - 1e-9
        and t + width / 2 <= face.wall.length - END_MARGIN_M + 1e-9
    )


def hits_placed(foot: Polygon, z0: float, z1: float, placed: Sequence[PlacedBox]) -> bool:
    """Whether a box (footprint, z0..z1) comes within ``OBJECT_GAP_M`` of a placed one."""
    for other in placed:
        overlap_z = z0 < other.z1 + OBJECT_GAP_M and other.z0 < z1 + OBJECT_GAP_M
        if overlap_z and foot.distance(other.footprint) < OBJECT_GAP_M:
            return True
    return False
