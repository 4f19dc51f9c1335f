"""Audit a scene at t = 0: interpenetrating colliders, objects below the floor or outside rooms.

Colliders are the geoms that take part in contacts (``contype`` or ``conaffinity`` set) and the
geoms of the collision group 3 even when their contact bits are off; visual geoms never count.
Every pair of colliders is considered, including pairs MuJoCo itself would never test (two
static objects, bits that do not match), except pairs in one body, a body and its parent (as
MuJoCo filters them), pairs an ``<exclude>`` names, and pairs of structure with structure (walls
may meet floors and each other). A broad phase on world-aligned boxes (numpy, sweep along x)
keeps it fast for scenes with hundreds of objects; ``mujoco.mj_geomDistance`` measures the
candidates.
"""

from __future__ import annotations

from dataclasses import dataclass

import mujoco
import numpy as np
import shapely
from shapely.geometry import Polygon

from holomj.physics.bounds import world_aabbs
from holomj.physics.scene_io import LoadedScene
from holomj.spec.report import ObjectDefect, PenetrationPair
from holomj.spec.scene import SceneSpec

COLLISION_GROUP = 3
FLOOR = "floor"
STRUCTURE = "structure"


@dataclass(frozen=True)
class Overlap:
    """One pair of colliders that interpenetrate: geom ids, depth, and the push on ``geom2``
    (world frame, length ``depth``) that separates them."""

    geom1: int
    geom2: int
    depth: float
    push2: np.ndarray


class GeomOwners:
    """Which object (index into ``names``) each geom and body of a model belongs to."""

    def __init__(self, model: mujoco.MjModel, objects: dict[str, int]) -> None:
        self.model = model
        self.names = list(objects)
        self.object_bodies = np.array([objects[n] for n in self.names], dtype=int)
        body_owner = np.full(model.nbody, -1, dtype=int)
        body_owner[self.object_bodies] = np.arange(len(self.names))
        for body in range(1, model.nbody):  # parents come before children
            if body_owner[body] < 0:
                body_owner[body] = body_owner[model.body_parentid[body]]
        self.body_owner = body_owner
        self.geom_owner = body_owner[model.geom_bodyid]
        contacts = (model.geom_contype != 0) | (model.geom_conaffinity != 0)
        self.collider = contacts | (model.geom_group == COLLISION_GROUP)

    def label(self, geom: int) -> str:
        """The object id of a geom, ``floor`` for a plane of the world, else ``structure``."""
        owner = self.geom_owner[geom]
        if owner >= 0:
            return self.names[owner]
        if self.model.geom_type[geom] == mujoco.mjtGeom.mjGEOM_PLANE:
            return FLOOR
        return STRUCTURE

    def geom_name(self, geom: int) -> str:
        """The geom's name, or ``geom_<id>`` for an unnamed one."""
        return self.model.geom(geom).name or f"geom_{geom}"


def candidate_pairs(
    owners: GeomOwners, low: np.ndarray, high: np.ndarray, margin: float = 0.0
) -> np.ndarray:
    """Pairs (i < j) of colliders whose boxes overlap, minus the pairs the audit skips."""
    model = owners.model
    geoms = np.flatnonzero(owners.collider)
    if geoms.size < 2:
        return np.zeros((0, 2), dtype=int)
    lo = low[geoms] - margin
    hi = high[geoms] + margin
    order = np.argsort(lo[:, 0], kind="stable")
    geoms, lo, hi = geoms[order], lo[order], hi[order]
    # Sweep along x: for each box, the later boxes that start before it ends.
    ends = np.searchsorted(lo[:, 0], hi[:, 0], side="right")
    counts = np.maximum(ends - np.arange(len(geoms)) - 1, 0)
    first = np.repeat(np.arange(len(geoms)), counts)
    offsets = np.arange(counts.sum()) - np.repeat(np.cumsum(counts) - counts, counts)
    second = first + 1 + offsets
    keep = np.all(lo[first, 1:] <= hi[second, 1:], axis=1) & np.all(
        lo[second, 1:] <= hi[first, 1:], axis=1
    )
    g1, g2 = geoms[first[keep]], geoms[second[keep]]
    g1, g2 = np.minimum(g1, g2), np.maximum(g1, g2)
    b1, b2 = model.geom_bodyid[g1], model.geom_bodyid[g2]
    keep = b1 != b2
    keep &= (owners.geom_owner[g1] >= 0) | (owners.geom_owner[g2] >= 0)
    if not model.opt.disableflags & mujoco.mjtDisableBit.mjDSBL_FILTERPARENT:
        p1, p2 = model.body_parentid[b1], model.body_parentid[b2]
        parent = ((p1 == b2) & (b2 != 0)) | ((p2 == b1) & (b1 != 0))
        keep &= ~parent
    if model.nexclude:
        signatures = set(int(s) for s in model.exclude_signature)
        lo_b, hi_b = np.minimum(b1, b2), np.maximum(b1, b2)
        excluded = np.array(
            [((int(x) + 1) << 16) + int(y) + 1 in signatures for x, y in zip(lo_b, hi_b)],
            dtype=bool,
        )
        keep &= ~excluded
    pairs = np.stack([g1[keep], g2[keep]], axis=1)
    return pairs[np.lexsort((pairs[:, 1], pairs[:, 0]))] if len(pairs) else pairs


def find_overlaps(
    model: mujoco.MjModel, data: mujoco.MjData, owners: GeomOwners, tolerance: float
) -> list[Overlap]:
    """Every collider pair interpenetrating deeper than ``tolerance`` at the pose in ``data``
    (whose kinematics must be current), deepest first."""
    low, high = world_aabbs(model, data)
    fromto = np.zeros(6)
    overlaps = []
    for g1, g2 in candidate_pairs(owners, low, high):
        dist = mujoco.mj_geomDistance(model, data, int(g1), int(g2), 0.0, fromto)
        if dist < -tolerance:
            push = fromto[:3] - fromto[3:]
            length = float(np.linalg.norm(push))
            # Coincident witness points: push straight up.
            push = push * (-dist / length) if length > 1e-12 else np.array([0.0, 0.0, -dist])
            overlaps.append(Overlap(int(g1), int(g2), float(-dist), push))
    overlaps.sort(key=lambda o: (-o.depth, o.geom1, o.geom2))
    return overlaps


def penetration_pairs(owners: GeomOwners, overlaps: list[Overlap]) -> list[PenetrationPair]:
    """One entry per pair of things (objects, floor, structure), with its deepest geom pair."""
    seen: dict[tuple[str, str], PenetrationPair] = {}
    for overlap in overlaps:  # deepest first
        a, b = owners.label(overlap.geom1), owners.label(overlap.geom2)
        ga, gb = owners.geom_name(overlap.geom1), owners.geom_name(overlap.geom2)
        if owners.geom_owner[overlap.geom1] < 0 or (
            owners.geom_owner[overlap.geom2] >= 0 and b < a
        ):
            a, b, ga, gb = b, a, gb, ga  # objects first, then alphabetical
        if (a, b) not in seen:
            seen[(a, b)] = PenetrationPair(
                a=a, b=b, geom_a=ga, geom_b=gb, depth_m=round(overlap.depth, 6)
            )
    return sorted(seen.values(), key=lambda p: (-p.depth_m, p.a, p.b))


def lowest_points(model: mujoco.MjModel, data: mujoco.MjData, owners: GeomOwners) -> np.ndarray:
    """The lowest z of each object's colliders (``inf`` for an object without any)."""
    lowest = np.full(len(owners.names), np.inf)
    geoms = np.flatnonzero(owners.collider & (owners.geom_owner >= 0))
    low, _ = world_aabbs(model, data)
    for geom in geoms:
        z = _geom_lowest_z(model, data, int(geom), low[geom, 2])
        owner = owners.geom_owner[geom]
        lowest[owner] = min(lowest[owner], z)
    return lowest


def _geom_lowest_z(model: mujoco.MjModel, data: mujoco.MjData, geom: int, aabb_z: float) -> float:
    kind = model.geom_type[geom]
    z = data.geom_xpos[geom, 2]
    up = data.geom_xmat[geom].reshape(3, 3)[2]  # world z of the geom's axes
    size = model.geom_size[geom]
    if kind == mujoco.mjtGeom.mjGEOM_SPHERE:
        return z - size[0]
    if kind == mujoco.mjtGeom.mjGEOM_CAPSULE:
        return z - size[0] - abs(up[2]) * size[1]
    if kind == mujoco.mjtGeom.mjGEOM_CYLINDER:
        return z - abs(up[2]) * size[1] - size[0] * np.sqrt(max(0.0, 1.0 - up[2] ** 2))
    if kind == mujoco.mjtGeom.mjGEOM_BOX:
        return z - float(np.abs(up) @ size)
    if kind == mujoco.mjtGeom.mjGEOM_ELLIPSOID:
        return z - float(np.sqrt(np.sum((up * size) ** 2)))
    if kind == mujoco.mjtGeom.mjGEOM_MESH:
        mesh = model.geom_dataid[geom]
        start, count = model.mesh_vertadr[mesh], model.mesh_vertnum[mesh]
        verts = model.mesh_vert[start : start + count]
        return z + float(np.min(verts @ up))
    return float(aabb_z)


def below_floor(
    lowest: np.ndarray, owners: GeomOwners, tolerance: float, floor_z: float = 0.0
) -> list[ObjectDefect]:
    """Objects whose lowest collider point lies deeper than ``tolerance`` under the floor."""
    return [
        ObjectDefect(name=owners.names[i], value_m=float(lowest[i]))
        for i in np.flatnonzero(lowest < floor_z - tolerance)
    ]


class Rooms:
    """Room polygons of a holomj scene, for inside/outside checks with a margin."""

    def __init__(self, scene: SceneSpec, margin: float) -> None:
        self.polygons = {room.id: Polygon(room.polygon) for room in scene.rooms}
        self.margin = margin
        self._grown = {k: p.buffer(margin) for k, p in self.polygons.items()}
        self._all = shapely.union_all(list(self._grown.values()))
        for geometry in (*self._grown.values(), self._all):
            shapely.prepare(geometry)

    def inside(self, xy: np.ndarray, room: str | None = None) -> np.ndarray:
        """Whether each point is in ``room`` (or in any room when None), within the margin."""
        area = self._all if room is None or room not in self._grown else self._grown[room]
        return shapely.contains_xy(area, xy[:, 0], xy[:, 1])

    def distance(self, x: float, y: float) -> float:
        """Distance from a point to the nearest room (0 inside one)."""
        point = shapely.Point(x, y)
        return float(min(p.distance(point) for p in self.polygons.values()))


def outside_rooms(
    scene: SceneSpec, positions: np.ndarray, names: list[str], margin: float
) -> list[ObjectDefect]:
    """Objects whose x/y lies outside every room (by more than ``margin``)."""
    rooms = Rooms(scene, margin)
    outside = ~rooms.inside(positions[:, :2])
    return [
        ObjectDefect(name=names[i], value_m=rooms.distance(*positions[i, :2]))
        for i in np.flatnonzero(outside)
    ]


@dataclass
class AuditResult:
    """What the audit at t = 0 found."""

    overlaps: list[Overlap]
    penetrations: list[PenetrationPair]
    below_floor: list[ObjectDefect]
    outside_rooms: list[ObjectDefect]

    @property
    def ok(self) -> bool:
        """No defect at all."""
        return not (self.penetrations or self.below_floor or self.outside_rooms)


def audit(
    loaded: LoadedScene,
    *,
    tolerance: float = 0.001,
    room_margin: float = 0.05,
    data: mujoco.MjData | None = None,
) -> AuditResult:
    """Audit ``loaded`` at its initial pose (or at the pose in ``data``, left untouched)."""
    model = loaded.model
    work = mujoco.MjData(model)
    if data is not None:
        work.qpos[:] = data.qpos
        work.mocap_pos[:] = data.mocap_pos
        work.mocap_quat[:] = data.mocap_quat
    mujoco.mj_kinematics(model, work)
    owners = GeomOwners(model, loaded.objects)
    overlaps = find_overlaps(model, work, owners, tolerance)
    lowest = lowest_points(model, work, owners)
    outside: list[ObjectDefect] = []
    if loaded.scene is not None and owners.names:
        positions = work.xpos[owners.object_bodies]
        outside = outside_rooms(loaded.scene, positions, owners.names, room_margin)
    return AuditResult(
        overlaps=overlaps,
        penetrations=penetration_pairs(owners, overlaps),
        below_floor=below_floor(lowest, owners, tolerance),
        outside_rooms=outside,
    )
