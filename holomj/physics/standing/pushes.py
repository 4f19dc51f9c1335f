"""How an overlapping object is pushed clear when a house is made to stand.

The default of :func:`holomj.physics.repair.separate` moves an object along the contact normal.
Two cases need better than that (:class:`StandPushes` is the ``push_rule``):

* **Walls** (and window panes): boxes of the world body whose thinnest horizontal axis is thin.
  An object is pushed along that axis, towards its own room, until its collider clears the
  wall's face on that side, plus :data:`WALL_GAP_M`. The contact normal of a deep overlap may
  point through a thin interior wall into the next room; this never does.
* **Floor objects** (furniture standing on the floor) only move horizontally: by the minimum
  translation that separates the two colliders' footprints (the separating-axis test on their
  convex hulls seen from above), so a chair that overlaps a table is slid out, never lifted
  onto it.

Collider shapes are read from the compiled model: mesh vertices, box corners, and for round
primitives points on circumscribing polygons (so the footprint is never underestimated).
"""

from __future__ import annotations

import math

import mujoco
import numpy as np
import shapely
from shapely.geometry import MultiPoint, Point, Polygon

from holomj.physics.audit import GeomOwners, Overlap

WALL_GAP_M = 0.001  # clearance left between an object and the wall it was pushed out of
GAP_M = 0.0005  # clearance left between two objects separated horizontally
SLAB_MAX_THICKNESS_M = 0.6  # a world box thinner than this (horizontally) counts as a wall
_RING = 16  # points on a circumscribing polygon of a round collider
_RING_SCALE = 1.0 / math.cos(math.pi / _RING)


def geom_points(model: mujoco.MjModel, data: mujoco.MjData, geom: int) -> np.ndarray:
    """World points (k, 3) whose convex hull contains the collider ``geom`` (exact for meshes
    and boxes; circumscribing polygons for round primitives)."""
    kind = model.geom_type[geom]
    size = model.geom_size[geom]
    if kind == mujoco.mjtGeom.mjGEOM_MESH:
        mesh = model.geom_dataid[geom]
        start, count = model.mesh_vertadr[mesh], model.mesh_vertnum[mesh]
        local = np.asarray(model.mesh_vert[start : start + count], dtype=float)
    elif kind == mujoco.mjtGeom.mjGEOM_BOX:
        signs = np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)])
        local = signs * size[:3]
    else:
        local = _round_points(int(kind), size)
    xmat = data.geom_xmat[geom].reshape(3, 3)
    return data.geom_xpos[geom] + local @ xmat.T


def _round_points(kind: int, size: np.ndarray) -> np.ndarray:
    angles = np.arange(_RING) * 2.0 * math.pi / _RING
    ring = np.stack([np.cos(angles), np.sin(angles), np.zeros(_RING)], axis=1) * _RING_SCALE
    if kind == mujoco.mjtGeom.mjGEOM_SPHERE:
        r = size[0]
        return np.concatenate([ring * r, [[0, 0, r], [0, 0, -r]]])
    if kind == mujoco.mjtGeom.mjGEOM_CYLINDER:
        r, h = size[0], size[1]
        return np.concatenate([ring * r + [0, 0, h], ring * r - [0, 0, h]])
    if kind == mujoco.mjtGeom.mjGEOM_CAPSULE:
        r, h = size[0], size[1]
        return np.concatenate([ring * r + [0, 0, h], ring * r - [0, 0, h], [[0, 0, h + r]],
                               [[0, 0, -h - r]]])  # fmt: skip
    if kind == mujoco.mjtGeom.mjGEOM_ELLIPSOID:
        signs = np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)])
        return signs * size[:3]
    return np.zeros((1, 3))


def footprint_hull(points: np.ndarray) -> np.ndarray:
    """The convex hull (counter-clockwise vertices, (k, 2)) of points seen from above."""
    hull = MultiPoint([tuple(p) for p in points[:, :2]]).convex_hull
    if isinstance(hull, Polygon):
        return np.asarray(hull.exterior.coords[:-1], dtype=float)
    return np.asarray(hull.coords if not isinstance(hull, Point) else [hull.coords[0]], float)


def min_translation_2d(mover: np.ndarray, other: np.ndarray) -> np.ndarray | None:
    """The shortest translation (2,) of convex polygon ``mover`` that separates it from convex
    polygon ``other`` (separating-axis test), or None when they do not overlap."""
    best: tuple[float, np.ndarray] | None = None
    for axis in _edge_normals(mover) + _edge_normals(other):
        pa, pb = mover @ axis, other @ axis
        forward = pb.max() - pa.min()  # move along +axis until mover's low side clears
        backward = pa.max() - pb.min()  # move along -axis until mover's high side clears
        if forward <= 0.0 or backward <= 0.0:
            return None
        amount, direction = (forward, axis) if forward <= backward else (backward, -axis)
        if best is None or amount < best[0]:
            best = (float(amount), direction)
    if best is None:
        return None
    return best[1] * best[0]


def _edge_normals(polygon: np.ndarray) -> list[np.ndarray]:
    if len(polygon) < 2:
        return []
    edges = np.roll(polygon, -1, axis=0) - polygon
    normals = []
    for ex, ey in edges:
        length = math.hypot(ex, ey)
        if length > 1e-9:
            normals.append(np.array([ey / length, -ex / length]))
    return normals


class StandPushes:
    """The ``push_rule`` of :func:`holomj.physics.repair.separate` for houses (module doc).

    ``rooms`` maps room ids to polygons; ``room_of`` object ids to their room; ``floor``
    names the objects that only move horizontally.
    """

    def __init__(
        self,
        rooms: dict[str, Polygon],
        room_of: dict[str, str | None],
        floor: set[str],
    ) -> None:
        self.rooms = rooms
        self.room_of = room_of
        self.floor = floor
        self.walls: dict[str, str] = {}  # object id -> the wall it was last pushed out of

    def __call__(
        self,
        model: mujoco.MjModel,
        data: mujoco.MjData,
        owners: GeomOwners,
        overlap: Overlap,
        mover: int,
        push: np.ndarray,
    ) -> np.ndarray | None:
        own, other = overlap.geom1, overlap.geom2
        if owners.geom_owner[own] != mover:
            own, other = other, own
        name = owners.names[mover]
        if owners.geom_owner[other] < 0 and is_slab(model, other):
            wall_push = self.out_of_slab(model, data, own, other, name)
            if wall_push is not None:
                self.walls[name] = wall_label(model, other)
                return wall_push
        if name in self.floor and model.geom_type[other] != mujoco.mjtGeom.mjGEOM_PLANE:
            mine = footprint_hull(geom_points(model, data, own))
            theirs = footprint_hull(geom_points(model, data, other))
            move = min_translation_2d(mine, theirs)
            if move is None:  # the footprints only touch: slide along the normal's level part
                level = np.array([push[0], push[1], 0.0])
                norm = float(np.linalg.norm(level))
                return level / norm * float(np.linalg.norm(push)) if norm > 1e-9 else None
            length = float(np.linalg.norm(move))
            return np.array([*(move / length * (length + GAP_M)), 0.0])
        return None

    def out_of_slab(
        self, model: mujoco.MjModel, data: mujoco.MjData, own: int, slab: int, name: str
    ) -> np.ndarray | None:
        """The push of collider ``own`` (of object ``name``) out of wall box ``slab``, towards
        the object's room; None when it does not reach into the slab along its normal."""
        axis, half = slab_axis(model, data, slab)
        centre = data.geom_xpos[slab]
        normal = self._into_room(centre, axis, half, name, data, own)
        face = float(normal @ centre) + half
        reach = float(np.min(geom_points(model, data, own) @ normal))
        depth = face - reach
        if depth <= 0.0:
            return None
        return normal * (depth + WALL_GAP_M)

    def _into_room(
        self,
        centre: np.ndarray,
        axis: np.ndarray,
        half: float,
        name: str,
        data: mujoco.MjData,
        own: int,
    ) -> np.ndarray:
        """The sign of the wall normal that points into the object's room."""
        room = self.rooms.get(self.room_of.get(name) or "")
        if room is not None:
            ahead = [
                room.distance(shapely.Point(*(centre + sign * axis * (half + 0.05))[:2]))
                for sign in (1.0, -1.0)
            ]
            if abs(ahead[0] - ahead[1]) > 1e-6:
                return axis if ahead[0] < ahead[1] else -axis
        toward = float((data.geom_xpos[own] - centre) @ axis)
        return axis if toward >= 0.0 else -axis


def wall_label(model: mujoco.MjModel, geom: int) -> str:
    """``wall_004`` for a piece of that wall (``structure/wall_004/0/room``), else the geom's
    name."""
    name = model.geom(geom).name or f"geom_{geom}"
    parts = name.split("/")
    return parts[1] if len(parts) > 2 and parts[0] == "structure" else name


def is_slab(model: mujoco.MjModel, geom: int) -> bool:
    """A box of the world body, thin in one horizontal direction: a wall piece or a pane."""
    if model.geom_type[geom] != mujoco.mjtGeom.mjGEOM_BOX or model.geom_bodyid[geom] != 0:
        return False
    return float(min(model.geom_size[geom][:2])) * 2.0 < SLAB_MAX_THICKNESS_M


def slab_axis(model: mujoco.MjModel, data: mujoco.MjData, slab: int) -> tuple[np.ndarray, float]:
    """The horizontal unit normal of a wall box (its thinner local x/y axis) and its half
    thickness."""
    size = model.geom_size[slab]
    k = 0 if size[0] <= size[1] else 1
    axis = data.geom_xmat[slab].reshape(3, 3)[:, k].copy()
    axis[2] = 0.0
    return axis / max(float(np.linalg.norm(axis)), 1e-12), float(size[k])
