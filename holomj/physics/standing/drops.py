"""Children of receptacles put on the receptacle's surface, by spawn-and-drop.

An imported house says which object rests on which (ProcTHOR ``children``), but its coordinates
do not put the child on the surface of the asset that now stands in for its parent. Each child
is dropped, parents before their children, in a :class:`~holomj.physics.drop_world.DropWorld`
where the children wait parked:

1. the surface: the parent's surface under the child's x/y whose height is closest to where the
   child was authored above its parent (a bookshelf's shelf), else the nearest one;
2. the spot: the child's own x/y when its footprint (at its own yaw) fits on that surface, else
   the closest point where it fits, then spots around it on rings of growing radius and on a
   grid over the whole surface (the closest to the authored x/y first, then spots spread
   evenly over the rest of the surface), then the same on the
   parent's other surfaces; a footprint that fits
   nowhere is tried turned by 90°, and finally at the closest point on the surface;
3. each spot is rejected at once when the child would collide there (when it collides with its
   parent only, which rises above the surface there, it is tried again above the parent's
   top); otherwise it is dropped
   from :data:`DROP_HEIGHT_M` and accepted when it comes to rest on the parent, inside the
   surface, no lower than 1 cm under it, upright when its asset must stand, touching no child
   placed before it and without pushing one (the rule of :mod:`holomj.physics.spawn`).

At most :data:`MAX_DROPS` drops and :data:`MAX_SPOTS` spots per child. A static child (held
still in the scene, a ProcTHOR ``kinematic`` faucet) that no spot holds may stay at its own
x/y just above its parent's top, when it collides with nothing there. The outcome of every
child is recorded.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field

import mujoco
import numpy as np
from shapely.geometry import Point
from shapely.ops import nearest_points
from shapely.prepared import prep

from holomj.mjcf.geometry import yaw_quat
from holomj.physics.audit import GeomOwners, lowest_points
from holomj.physics.bounds import world_aabbs
from holomj.physics.drop_world import FULL, DropWorld, Outcome
from holomj.physics.spawn import (
    LIFT_CAP_M,
    landing_problem,
)
from holomj.physics.standing.prepass import DropSurface, receptacle_surfaces
from holomj.physics.surfaces_world import footprint, footprint_polygon, object_yaw
from holomj.spec.assets import AssetMeta
from holomj.spec.scene import SceneObject

DROP_HEIGHT_M = 0.01
SETTLE_S = 1.5
MAX_DROPS = 10
MAX_SPOTS = 80
RINGS_M = (0.03, 0.06, 0.1, 0.15, 0.2, 0.3, 0.45)
DIRECTIONS = 8
GRID_M = 0.05  # then a grid over the whole surface, at least this fine
MAX_GRID = 400  # ... and at most this many points
MIN_SPACING_M = 0.02  # spots closer than this to an earlier one are skipped
SPOTS_PER_SURFACE = 30
NEAREST_SPOTS = 18  # of which the nearest to the authored x/y; the others spread over the rest
HOLD_DAMPING = 1e6  # N·s/m on the joint of a static child held still in the drop world


@dataclass(frozen=True)
class Child:
    """One object to drop onto its parent."""

    obj: SceneObject  # at its imported pose, moved as its parent was (x/y and yaw are kept)
    parent: str
    height_above_parent: float  # authored: its z minus its parent's z
    static: bool = False  # held still in the scene: may stay where no drop holds it


@dataclass
class Dropped:
    """What happened to one child."""

    object_id: str
    onto: str
    accepted: bool
    reason: str
    attempts: int = 0
    surface_index: int | None = None
    position: tuple[float, float, float] | None = None
    quat: tuple[float, float, float, float] | None = None
    target: tuple[float, float] = (0.0, 0.0)
    rejections: dict[str, int] = field(default_factory=dict)
    static_hold: bool = False  # not dropped: held still above its parent (a static child)

    @property
    def offset_m(self) -> float:
        """How far from its authored x/y it came to rest."""
        if self.position is None:
            return 0.0
        return math.hypot(self.position[0] - self.target[0], self.position[1] - self.target[1])

    def to_dict(self) -> dict:
        """JSON-able form for the import report."""
        record: dict = {
            "object": self.object_id,
            "onto": self.onto,
            "surface": self.surface_index,
            "attempts": self.attempts,
            "from_xy": [round(v, 4) for v in self.target],
        }
        if self.position is not None:
            record["position"] = [round(v, 4) for v in self.position]
            record["offset_m"] = round(self.offset_m, 4)
        if self.rejections:
            record["rejections"] = dict(sorted(self.rejections.items()))
        if self.static_hold:
            record["held_still"] = True
        return record


def drop_children(
    world: DropWorld,
    children: list[Child],
    parents: dict[str, SceneObject],
    metas: dict[str, AssetMeta],
) -> dict[str, Dropped]:
    """Drop every child onto its parent (see the module docstring). ``parents`` holds every
    parent at its pose in the world; ``metas`` the asset of every object involved."""
    offsets = _bottom_offsets(world, [c.obj.id for c in children])
    nstep = max(1, round(SETTLE_S / world.model.opt.timestep))
    results: dict[str, Dropped] = {}
    placed: dict[str, list[str]] = {}
    jobs = {c.obj.id: c for c in children}
    for child in _parents_first(children, metas):
        parent = parents[child.parent]
        if child.parent in results:  # a child that is itself a parent: where it landed
            earlier = results[child.parent]
            if not earlier.accepted or earlier.position is None:
                results[child.obj.id] = Dropped(
                    child.obj.id, child.parent, False,
                    f"its receptacle {child.parent} could not be placed",
                    target=child.obj.position[:2],
                )  # fmt: skip
                continue
            parent = parents[child.parent].model_copy(
                update={"position": earlier.position, "quat": earlier.quat}
            )
            was = jobs[child.parent].obj.position
            child = _shifted(child, earlier.position[0] - was[0], earlier.position[1] - was[1])
        result = _drop_one(
            world, child, parent, metas, offsets[child.obj.id], placed.get(child.parent, []),
            nstep,
        )  # fmt: skip
        results[child.obj.id] = result
        if result.accepted and not result.static_hold:
            placed.setdefault(child.parent, []).append(child.obj.id)
    return {c.obj.id: results[c.obj.id] for c in children}


def _shifted(child: Child, dx: float, dy: float) -> Child:
    """``child`` with its x/y moved as its parent was."""
    x, y, z = child.obj.position
    obj = child.obj.model_copy(update={"position": (x + dx, y + dy, z)})
    return Child(obj, child.parent, child.height_above_parent, child.static)


def _parents_first(children: list[Child], metas: dict[str, AssetMeta]) -> list[Child]:
    """Children ordered so that a child that is also a parent comes before its own children;
    otherwise largest footprint first (plates find room before apples), then scene order."""
    ids = {c.obj.id for c in children}
    parent_of = {c.obj.id: c.parent for c in children}

    def depth(object_id: str) -> int:
        d = 0
        while parent_of.get(object_id) in ids and d < len(ids):
            object_id = parent_of[object_id]
            d += 1
        return d

    def area(child: Child) -> float:
        hx, hy = footprint(metas[child.obj.id], child.obj.scale3)
        return 4.0 * hx * hy

    return sorted(children, key=lambda c: (depth(c.obj.id), -area(c)))


def _bottom_offsets(world: DropWorld, ids: list[str]) -> dict[str, float]:
    """Per object: its lowest collider point minus its origin's z, in its parked pose (the
    orientation it is dropped in)."""
    owners = GeomOwners(world.model, {i: world.bodies[i].body for i in ids})
    lowest = lowest_points(world.model, world.data, owners)
    offsets = {}
    for index, object_id in enumerate(owners.names):
        z = float(world.data.xpos[world.bodies[object_id].body][2])
        offsets[object_id] = float(lowest[index]) - z if math.isfinite(lowest[index]) else 0.0
    return offsets


def _drop_one(
    world: DropWorld,
    child: Child,
    parent: SceneObject,
    metas: dict[str, AssetMeta],
    bottom: float,
    placed: list[str],
    nstep: int,
) -> Dropped:
    obj, meta = child.obj, metas[child.obj.id]
    target = (float(obj.position[0]), float(obj.position[1]))
    result = Dropped(obj.id, parent.id, False, "", target=target)
    height = meta.size[2] * obj.scale3[2]
    surfaces = [
        s
        for s in receptacle_surfaces(parent, metas[parent.id])
        if s.box_top or s.world.clearance > height + DROP_HEIGHT_M + 1e-3
    ]
    if not surfaces:
        result.reason = f"no surface of {parent.id} has room for it ({height:.2f} m tall)"
        return result
    half = footprint(meta, obj.scale3)
    yaw = object_yaw(obj)
    tilted = obj.quat is not None and abs(_tilt_deg(obj.quat)) > 1.0
    base_quat = np.array(obj.quat if tilted and obj.quat is not None else yaw_quat(yaw))
    wanted = parent.position[2] + child.height_above_parent
    rec_bodies = _subtree(world.model, world.bodies[parent.id].body)
    before = {oid: world.pose(oid)[0] for oid in placed}
    world.activate(obj.id)
    drops = 0
    for surface, x, y, turn in _spots(surfaces, target, wanted, half, yaw):
        if drops >= MAX_DROPS or result.attempts >= MAX_SPOTS:
            break
        result.attempts += 1
        quat = _turned(base_quat, turn)
        pos = np.array([x, y, surface.world.height + DROP_HEIGHT_M - bottom])
        state = world.candidate_state(obj.id, pos, quat)
        hit = world.spawn_collision(obj.id, state)
        if hit is not None and _owner_label(hit) == parent.id:
            # the parent rises above its surface here (a rim, a backsplash): drop from above it
            pos[2] = _top(world, parent.id) + DROP_HEIGHT_M - bottom
            state = world.candidate_state(obj.id, pos, quat)
            hit = world.spawn_collision(obj.id, state)
        if hit is not None:
            _count(result, f"collides with {_owner_label(hit)}")
            continue
        drops += 1
        upright = meta.upright and not tilted
        judge = functools.partial(_judge, world, surface, rec_bodies, upright, before)
        [(outcome, reason)] = world.drop(
            obj.id, [state], nstep, watch=[], judge=judge, floor_z=surface.world.height - 0.5
        )
        if outcome is None:
            continue
        if reason is not None:
            _count(result, reason)
            continue
        world.commit(obj.id, outcome.state)
        lift = min(world.penetration(obj.id), LIFT_CAP_M)
        q = outcome.quat / np.linalg.norm(outcome.quat)
        q = -q if q[0] < 0 else q
        px, py, pz = (float(v) for v in outcome.position)
        result.accepted = True
        result.reason = "placed"
        result.surface_index = surface.world.index
        result.position = (round(px, 6), round(py, 6), round(pz + lift, 6))
        result.quat = _quat4(q)
        return result
    if child.static and _hold_still(world, obj.id, target, base_quat, parent.id, bottom, result):
        return result
    world.park(obj.id)
    result.reason = _failure(result, parent.id)
    return result


def _hold_still(
    world: DropWorld,
    object_id: str,
    target: tuple[float, float],
    quat: np.ndarray,
    parent: str,
    bottom: float,
    result: Dropped,
) -> bool:
    """Last resort for a static child no spot holds: its own x/y, just above its parent's top,
    held still there (it is static in the scene), when it collides with nothing."""
    result.attempts += 1
    pos = np.array([target[0], target[1], _top(world, parent) + 0.001 - bottom])
    state = world.candidate_state(object_id, pos, quat)
    hit = world.spawn_collision(object_id, state)
    if hit is not None:
        _count(result, f"collides with {_owner_label(hit)}")
        return False
    # Static in the scene; in the drop world it is held by a damping that lets it sink a few
    # micrometres a second, so the children dropped after it land around it.
    dof = world.bodies[object_id].dof
    world.model.dof_damping[dof : dof + 6] = HOLD_DAMPING
    world.commit(object_id, state)
    result.accepted = True
    result.reason = "held still above its parent (static)"
    result.static_hold = True
    result.position = (round(float(pos[0]), 6), round(float(pos[1]), 6), round(float(pos[2]), 6))
    result.quat = _quat4(quat)
    return True


def _quat4(quat: np.ndarray) -> tuple[float, float, float, float]:
    w, x, y, z = (round(float(v), 8) for v in quat)
    return (w, x, y, z)


def _top(world: DropWorld, object_id: str) -> float:
    """The highest point of an object's colliders in the committed state."""
    data = mujoco.MjData(world.model)
    mujoco.mj_setState(world.model, data, world.state, FULL)
    mujoco.mj_kinematics(world.model, data)
    _, high = world_aabbs(world.model, data)
    geoms = world.bodies[object_id].geoms
    body = world.bodies[object_id].body
    return float(high[geoms, 2].max()) if geoms.size else float(data.xpos[body][2])


def _subtree(model: mujoco.MjModel, body: int) -> frozenset[int]:
    """``body`` and the bodies under it (an articulated receptacle's lid, doors, drawers)."""
    root = int(model.body_rootid[body])
    return frozenset(
        b for b in range(model.nbody) if int(model.body_rootid[b]) == root and b >= body
    )


def _owner_label(geom_name: str) -> str:
    """``Bed|4|0/collision_3`` -> ``Bed|4|0``; ``structure/wall_004/0/room`` -> ``wall_004``."""
    parts = geom_name.split("/")
    if parts[0] == "structure" and len(parts) > 1:
        return parts[1]
    return geom_name.rsplit("/", 1)[0] if "/" in geom_name else geom_name


def _count(result: Dropped, reason: str) -> None:
    result.rejections[reason] = result.rejections.get(reason, 0) + 1


def _failure(result: Dropped, parent: str) -> str:
    if not result.rejections:
        return f"no spot on {parent} fits its footprint"
    tried = ", ".join(f"{n} {r}" for r, n in sorted(result.rejections.items()))
    return f"no spot on {parent} holds it ({result.attempts} tried: {tried})"


def _spots(
    surfaces: list[DropSurface],
    target: tuple[float, float],
    wanted: float,
    half: tuple[float, float],
    yaw: float,
):
    """Candidate (surface, x, y, turn) in the order of the module docstring."""
    point = Point(*target)
    ordered = sorted(
        surfaces,
        key=lambda s: (
            not s.world.polygon.contains(point),
            abs(s.world.height - wanted),
            s.world.polygon.distance(point),
        ),
    )
    fallbacks = []
    any_fit = False
    for surface in ordered:
        spots = _fitting_spots(surface, target, half, yaw)
        for x, y in spots:
            any_fit = True
            yield surface, x, y, 0.0
        fallbacks.append(surface)
    if not any_fit:
        for surface in ordered:
            for x, y in _fitting_spots(surface, target, half, yaw + math.pi / 2):
                yield surface, x, y, math.pi / 2
    for surface in fallbacks:
        inner = surface.world.polygon.buffer(-min(half), join_style="mitre")
        region = inner if not inner.is_empty else surface.world.polygon
        near = nearest_points(region, point)[0]
        yield surface, float(near.x), float(near.y), 0.0


def _fitting_spots(
    surface: DropSurface, target: tuple[float, float], half: tuple[float, float], yaw: float
) -> list[tuple[float, float]]:
    """Spots on ``surface`` where the footprint at ``yaw`` fits, closest to ``target`` first."""
    polygon = surface.world.polygon
    prepared = prep(polygon)

    def fits(x: float, y: float) -> bool:
        return prepared.contains(footprint_polygon(half, x, y, yaw))

    point = Point(*target)
    if fits(*target):
        centre = target
    else:
        region = polygon.buffer(-math.hypot(*half), join_style="mitre")
        if region.is_empty:
            region = polygon.buffer(-min(half), join_style="mitre")
        if region.is_empty:
            return []
        near = nearest_points(region, point)[0]
        centre = (float(near.x), float(near.y))
    candidates = [centre]
    for radius in RINGS_M:
        for k in range(DIRECTIONS):
            angle = 2.0 * math.pi * k / DIRECTIONS
            candidates.append(
                (centre[0] + radius * math.cos(angle), centre[1] + radius * math.sin(angle))
            )
    x0, y0, x1, y1 = polygon.bounds
    step = max(GRID_M, math.sqrt((x1 - x0) * (y1 - y0) / MAX_GRID))
    for gx in np.arange(x0 + step / 2, x1, step):
        for gy in np.arange(y0 + step / 2, y1, step):
            candidates.append((float(gx), float(gy)))
    fitting = [c for c in candidates if fits(*c)]
    fitting.sort(key=lambda c: math.hypot(c[0] - target[0], c[1] - target[1]))
    spots = _spread(fitting)
    if len(spots) <= SPOTS_PER_SURFACE:
        return spots
    # the nearest spots first, then spots spread over the rest of the surface (a crowded
    # corner must not hide the free end of a long dresser)
    near, far = spots[:NEAREST_SPOTS], spots[NEAREST_SPOTS:]
    step = len(far) / (SPOTS_PER_SURFACE - NEAREST_SPOTS)
    return near + [far[int(k * step)] for k in range(SPOTS_PER_SURFACE - NEAREST_SPOTS)]


def _spread(spots: list[tuple[float, float]]) -> list[tuple[float, float]]:
    """Spots in order, skipping those within :data:`MIN_SPACING_M` of one kept before."""
    kept: list[tuple[float, float]] = []
    for spot in spots:
        if all(math.hypot(spot[0] - k[0], spot[1] - k[1]) >= MIN_SPACING_M for k in kept):
            kept.append(spot)
    return kept


def _turned(quat: np.ndarray, turn: float) -> np.ndarray:
    if turn == 0.0:
        return quat
    w, z = math.cos(turn / 2), math.sin(turn / 2)
    qw, qx, qy, qz = quat
    # (w, 0, 0, z) * quat: a turn about the world's +Z
    return np.array([w * qw - z * qz, w * qx - z * qy, w * qy + z * qx, w * qz + z * qw])


def _tilt_deg(quat: tuple[float, float, float, float]) -> float:
    _, x, y, _ = quat
    zz = 1.0 - 2.0 * (x * x + y * y)
    return math.degrees(math.acos(max(-1.0, min(1.0, zz))))


def _judge(
    world: DropWorld,
    surface: DropSurface,
    rec_bodies: frozenset[int],
    upright: bool,
    before: dict[str, np.ndarray],
    _candidate: int,
    outcome: Outcome,
) -> str | None:
    """Why a drop is rejected, or None when it is accepted (the rule of spawn-and-drop,
    :func:`~holomj.physics.spawn.landing_problem`; on the top of a bounding box it may land lower,
    on the receptacle all the same)."""
    surface_z = None if surface.box_top else surface.world.height
    return landing_problem(
        world,
        outcome,
        surface.world.polygon,
        surface_z,
        rec_bodies,
        upright,
        before,
        receptacle="its receptacle",
    )
