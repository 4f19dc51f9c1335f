"""Scene objects as floor placement sees them: their size and yaw, their footprint rectangle,
the room they are in, and :class:`Thing`, an object of the room with its outline and heights."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import shapely
from shapely.geometry import Point, Polygon

from holomj.library.store import AssetLibrary
from holomj.spec.scene import SceneObject, SceneSpec

FLOOR_Z_M = 0.05  # an object whose base is lower than this stands on the floor


@dataclass(frozen=True)
class Thing:
    """An object of the room as placement sees it."""

    id: str
    polygon: Polygon
    bottom: float
    top: float
    x: float
    y: float
    yaw_deg: float
    width: float
    depth: float
    on_floor: bool


def object_size(obj: SceneObject, library: AssetLibrary) -> tuple[float, float, float]:
    """(x extent, y extent, height) of an object, scale applied."""
    sx, sy, sz = obj.scale3
    if obj.asset not in library:
        return (sx, sy, sz)
    size = library.get(obj.asset).meta.size
    return (size[0] * sx, size[1] * sy, size[2] * sz)


def object_yaw(obj: SceneObject) -> float:
    """The yaw of an object in degrees (from its quaternion when it has one)."""
    if obj.quat is None:
        return obj.yaw_deg
    w, x, y, z = obj.quat
    return math.degrees(math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z)))


def footprint(x: float, y: float, yaw_deg: float, width: float, depth: float) -> Polygon:
    """The footprint rectangle (``depth`` along the object's front, ``width`` across)."""
    return shapely.polygons(corners(np.array([x]), np.array([y]), yaw_deg, width, depth))[0]


def corners(xs: np.ndarray, ys: np.ndarray, yaw_deg: float, width: float, depth: float):
    c, s = math.cos(math.radians(yaw_deg)), math.sin(math.radians(yaw_deg))
    local = np.array(
        [[depth / 2, width / 2], [-depth / 2, width / 2], [-depth / 2, -width / 2],
         [depth / 2, -width / 2]]
    )  # fmt: skip
    rx = local[:, 0] * c - local[:, 1] * s
    ry = local[:, 0] * s + local[:, 1] * c
    coords = np.empty((len(xs), 4, 2))
    coords[:, :, 0] = xs[:, None] + rx[None, :]
    coords[:, :, 1] = ys[:, None] + ry[None, :]
    return np.round(coords, 9)


def in_room(scene: SceneSpec, obj: SceneObject, room_id: str) -> bool:
    """Whether ``obj`` belongs to room ``room_id`` (its ``room``, else where it stands)."""
    if obj.room is not None:
        return obj.room == room_id
    return Polygon(scene.room(room_id).polygon).covers(Point(obj.position[0], obj.position[1]))


def room_at(scene: SceneSpec, x: float, y: float) -> str | None:
    """The room whose floor holds ``(x, y)``, or None."""
    for room in scene.rooms:
        if Polygon(room.polygon).buffer(1e-6).covers(Point(x, y)):
            return room.id
    return None
