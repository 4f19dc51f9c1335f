"""Spawn-and-drop: put small objects on a receptacle's support surfaces, physically.

Like AI2-THOR's random spawn, but every pose is tested by the simulator. For each requested
object, in turn (largest footprint first, so plates and books find room before apples):

1. sample a candidate pose: a support surface of the receptacle (weighted by area, every shelf
   of a bookshelf; surfaces with too little headroom are skipped), a random yaw, a
   footprint-bottom-centre point such that the turned footprint rectangle lies inside the
   surface, at ``surface height + drop_height``;
2. reject it at once if its colliders are within 0.5 mm of any collider of the scene (objects
   placed so far included; objects still to be placed are parked and take no contact slots);
3. drop the surviving candidates, up to ``batch`` (at most one per worker thread) at a time in
   parallel, until the object falls asleep (MuJoCo's island sleeping: at rest), falls off, or
   ``settle_s`` seconds pass;
4. accept the first candidate in sampling order that is at rest, touches the receptacle and no
   other placed object, has its centre inside the surface and no lower than 1 cm below it, is
   upright within :data:`UPRIGHT_TOL_DEG` when its asset must stand, and has not pushed an
   object placed before it by more than :data:`DISTURB_TOL_M`.

At most ``max_attempts`` candidate poses are tried per object (spawn rejections included);
every object's outcome, accepted or not, is reported with the reasons of its rejected
candidates. Accepted objects are written into the scene at their settled pose (``quat`` and
``yaw_deg``; ``support`` = the receptacle; its room), lifted by the fraction of a millimetre
they sink into their support so the scene starts contact-free. The receptacle keeps its pose
in the scene; how far it drifted during the drops (when it is not static) is reported.

**Inside** (``inside`` requests): the same, on the receptacle's interior surfaces (an
articulated asset's shelves behind its doors, drawer bottoms, a fridge's glass shelves: its
``articulation.interior``) with its doors and drawers closed: the candidate is spawned in the
free space of the closed compartment, must fit under the surface's ``clearance_m``, and must
come to rest on the body that surface belongs to (the carcass, or the drawer it moves with).

Deterministic for a given generator: each object draws from its own child generator, every
drop starts from the committed state in a fresh MjData, and the first accepted candidate in
sampling order wins, so neither ``batch`` nor the number of threads changes the result.
"""

from __future__ import annotations

import functools
import math
import os
import re
import time
from collections import Counter
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from shapely.geometry import Point, Polygon

from holomj.errors import InputError
from holomj.library.store import AssetLibrary, LibraryAsset
from holomj.mjcf import names
from holomj.mjcf.compiler import CompiledScene, compile_scene
from holomj.mjcf.geometry import yaw_quat
from holomj.physics.drop_world import DropWorld, Outcome
from holomj.physics.spawn_requests import find_object, resolve_request
from holomj.physics.surfaces_world import (
    SurfaceSampler,
    WorldSurface,
    footprint,
    object_yaw,
    world_interior_surfaces,
    world_surfaces,
)
from holomj.spec.scene import SceneObject, SceneSpec

UPRIGHT_TOL_DEG = 10.0
REST_SPEED = 0.02  # m/s
REST_SPIN = 0.3  # rad/s
FALL_TOL_M = 0.01  # the object may not end lower than this below its surface
DISTURB_TOL_M = 0.01  # objects placed before may not be pushed further than this
PARK_HEIGHT_M = 100.0  # parked objects wait this high above the floor, 2 m apart
LIFT_CAP_M = 0.003  # settled poses are lifted by their penetration, at most this much

Request = tuple[str, int]


@dataclass(frozen=True)
class SpawnPlacement:
    """What happened to one requested object."""

    object_id: str
    asset: str
    surface_index: int | None  # index into the receptacle asset's ``surfaces`` (inside:
    #                            into its ``articulation.interior``)
    attempts: int  # candidate poses tried (spawn rejections included)
    accepted: bool
    reason: str  # "placed" or why it failed
    final_pose: dict[str, Any] | None  # {"position": [x, y, z], "quat": [w, x, y, z], ...}
    seconds: float
    rejections: dict[str, int] = field(default_factory=dict)  # reason -> count
    inside: bool = False  # asked inside the receptacle (its interior surfaces)

    def to_dict(self) -> dict[str, Any]:
        """JSON-able form (``inside`` only for an object asked inside)."""
        record = dict(self.__dict__)
        if not self.inside:
            del record["inside"]
        return record


@dataclass(frozen=True)
class SpawnResult:
    """The populated scene and every placement outcome."""

    scene: SceneSpec
    placements: list[SpawnPlacement]
    receptacle_drift_m: float = 0.0  # how far the receptacle moved during the drops
    seconds: float = 0.0

    @property
    def all_placed(self) -> bool:
        """True when every requested object was placed."""
        return all(p.accepted for p in self.placements)

    def to_dict(self) -> dict[str, Any]:
        """JSON-able report (without the scene)."""
        placed = sum(p.accepted for p in self.placements)
        return {
            "requested": len(self.placements),
            "placed": placed,
            "receptacle_drift_m": round(self.receptacle_drift_m, 6),
            "seconds": round(self.seconds, 4),
            "placements": [p.to_dict() for p in self.placements],
        }


@dataclass
class _Job:
    """One object to place."""

    object_id: str
    asset: LibraryAsset
    seed: int
    order: int
    inside: bool = False


def populate(
    scene: SceneSpec,
    library: AssetLibrary,
    receptacle_id: str,
    requests: list[Request],
    rng: np.random.Generator,
    *,
    max_attempts: int = 20,
    drop_height: float = 0.02,
    settle_s: float = 1.5,
    batch: int = 8,
    nthread: int | None = None,
    attach: Callable[[CompiledScene], CompiledScene] | None = None,
    inside: list[Request] | None = None,
) -> SpawnResult:
    """Drop the requested small objects onto ``receptacle_id`` (see the module docstring);
    those of ``inside`` go into it (onto its interior surfaces).

    ``nthread`` worker threads drop candidates in parallel (default :func:`default_threads`);
    the result does not depend on it. ``attach`` adds what the scene carries besides its
    objects (a folder's robot, see :func:`holomj.jobs.folder.attach_folder_robot`) to the
    compiled world, so candidates are spawned clear of it and dropped against it.

    ``library`` must hold the scene's assets and the requested ones (see
    :func:`merge_libraries`). ``requests`` are
    (category or asset id, count). Raises :class:`InputError` for an unknown receptacle, a
    receptacle without support surfaces (without interior surfaces, for ``inside``), an
    unknown request or bad numbers.
    """
    start = time.perf_counter()
    _check_numbers(max_attempts, drop_height, settle_s, batch)
    receptacle, surfaces, interior = _receptacle_surfaces(
        scene, library, receptacle_id, bool(requests), bool(inside)
    )
    jobs = _make_jobs(scene, library, requests, rng)
    if inside:
        jobs += _make_jobs(scene, library, inside, rng, inside=True, first=jobs)
    if not jobs:
        return SpawnResult(scene, [], 0.0, time.perf_counter() - start)

    parked = _parked_scene(scene, receptacle, jobs)
    compiled = compile_scene(parked, library, furniture="as-is")
    if attach is not None:
        compiled = attach(compiled)
    threads = nthread or default_threads(batch)
    world = DropWorld(compiled, [j.object_id for j in jobs], nthread=threads)
    rec_start, _ = world.pose(receptacle_id)
    nstep = max(1, round(settle_s / world.model.opt.timestep))
    bodies = _surface_bodies(world, receptacle_id, interior)

    placed: list[str] = []
    outcomes: dict[str, SpawnPlacement] = {}
    order = sorted(jobs, key=lambda j: (-_footprint_area(j.asset, 1.0), j.order))
    try:
        for job in order:
            outcome = _place_one(
                world, job, interior if job.inside else surfaces, placed, bodies,
                max_attempts=max_attempts, drop_height=drop_height, nstep=nstep, batch=batch,
            )  # fmt: skip
            outcomes[job.object_id] = outcome
            if outcome.accepted:
                placed.append(job.object_id)
    finally:
        world.close()
    rec_end, _ = world.pose(receptacle_id)
    placements = [outcomes[j.object_id] for j in jobs]
    new_objects = [
        _scene_object(job, p, receptacle)
        for job, p in zip(jobs, placements)
        if p.accepted and p.final_pose is not None
    ]
    populated = scene.model_copy(update={"objects": [*scene.objects, *new_objects]})
    return SpawnResult(
        scene=SceneSpec.model_validate(populated.model_dump()),
        placements=placements,
        receptacle_drift_m=float(np.linalg.norm(rec_end - rec_start)),
        seconds=time.perf_counter() - start,
    )


def _receptacle_surfaces(
    scene: SceneSpec, library: AssetLibrary, receptacle_id: str, requests: bool, inside: bool
) -> tuple[SceneObject, list[WorldSurface], list[WorldSurface]]:
    """The receptacle, its support surfaces and its interior ones (world frame); an InputError
    when it has none of the kind the requests (on it) or ``inside`` requests (in it) need."""
    receptacle = find_object(scene, receptacle_id)
    rec_asset = library.get(receptacle.asset)
    surfaces = world_surfaces(receptacle, rec_asset.meta)
    interior = world_interior_surfaces(receptacle, rec_asset.meta)
    if (requests or not inside) and not surfaces:
        raise InputError(
            f"object {receptacle_id!r} (asset {rec_asset.meta.id!r}) has no support surfaces",
            where="--on",
            fix="choose a table, desk, shelf or other receptacle",
        )
    if inside and not interior:
        raise InputError(
            f"object {receptacle_id!r} (asset {rec_asset.meta.id!r}) has nothing to put things "
            "inside (no interior surfaces)",
            where="--on",
            fix="choose an articulated cabinet, drawer unit, fridge or other storage",
        )
    return receptacle, surfaces, interior


def default_threads(batch: int) -> int:
    """Worker threads for parallel drops: one core is left to the rest of the process (on a
    busy 2-core machine a second drop thread was measured not to pay off)."""
    return max(1, min(batch, (os.cpu_count() or 1) - 1))


def _check_numbers(max_attempts: int, drop_height: float, settle_s: float, batch: int) -> None:
    checks = [
        (max_attempts >= 1, "max_attempts must be at least 1"),
        (0.0 <= drop_height <= 0.5, "drop_height must lie in [0, 0.5] m"),
        (0.01 <= settle_s <= 30.0, "settle_s must lie in [0.01, 30] s"),
        (batch >= 1, "batch must be at least 1"),
    ]
    for ok, message in checks:
        if not ok:
            raise InputError(message)


def _surface_bodies(
    world: DropWorld, receptacle_id: str, interior: list[WorldSurface]
) -> dict[str | None, int]:
    """The body ids a dropped object may rest on, by the part a surface lies on (None: the
    receptacle's carcass)."""
    bodies: dict[str | None, int] = {None: world.bodies[receptacle_id].body}
    for surface in interior:
        if surface.part is not None:
            body = names.object_part_body(receptacle_id, surface.part)
            bodies[surface.part] = world.model.body(body).id
    return bodies


def _make_jobs(
    scene: SceneSpec,
    library: AssetLibrary,
    requests: list[Request],
    rng: np.random.Generator,
    *,
    inside: bool = False,
    first: list[_Job] | None = None,
) -> list[_Job]:
    """Jobs for ``requests`` (after the jobs ``first``, whose ids they do not reuse)."""
    before = first or []
    taken = {o.id for o in scene.objects} | {j.object_id for j in before}
    counters: Counter[str] = Counter()
    jobs: list[_Job] = []
    for name, count in requests:
        if count < 0 or count > 1000:
            raise InputError(f"count {count} for {name!r} must lie in [0, 1000]", where="objects")
        for _ in range(count):
            asset = resolve_request(library, name, rng)
            stem = _id_stem(asset.meta.category)
            while True:
                object_id = f"{stem}_{counters[stem]:02d}"
                counters[stem] += 1
                if object_id not in taken:
                    break
            taken.add(object_id)
            seed = int(rng.integers(2**63 - 1))
            jobs.append(_Job(object_id, asset, seed, len(before) + len(jobs), inside))
    return jobs


def _id_stem(category: str) -> str:
    """``Toy Block`` -> ``toy_block``: a plain prefix for object ids."""
    return re.sub(r"[^a-z0-9]+", "_", category.lower()).strip("_") or "object"


def _parked_scene(scene: SceneSpec, receptacle: SceneObject, jobs: list[_Job]) -> SceneSpec:
    """The scene with every object to place added far below the floor, spaced apart."""
    x0, y0, _ = receptacle.position
    parked = [
        SceneObject(
            id=job.object_id,
            asset=job.asset.meta.id,
            position=(x0 + 2.0 * k, y0, PARK_HEIGHT_M),
            support=receptacle.id,
            room=receptacle.room,
        )
        for k, job in enumerate(jobs)
    ]
    return scene.model_copy(update={"objects": [*scene.objects, *parked]})


def _footprint_area(asset: LibraryAsset, scale: float) -> float:
    hx, hy = footprint(asset.meta, (scale, scale, scale))
    return 4.0 * hx * hy


def _place_one(
    world: DropWorld,
    job: _Job,
    surfaces: list[WorldSurface],
    placed: list[str],
    bodies: dict[str | None, int],
    *,
    max_attempts: int,
    drop_height: float,
    nstep: int,
    batch: int,
) -> SpawnPlacement:
    start = time.perf_counter()
    meta = job.asset.meta
    rng = np.random.default_rng(job.seed)
    half = footprint(meta, (1.0, 1.0, 1.0))
    height = meta.size[2]
    samplers = [
        SurfaceSampler(s, half) for s in surfaces if s.clearance > height + drop_height + 1e-3
    ]
    samplers = [s for s in samplers if s.feasible]
    if not samplers:
        return _placement(job, 0, "no surface is large or high enough for it", Counter(), start)
    weights = np.array([s.surface.area for s in samplers])
    weights = weights / weights.sum()
    before = {oid: world.pose(oid)[0] for oid in placed}
    world.activate(job.object_id)
    tried: list[tuple[int, str]] = []  # (attempt number, why it was rejected)
    attempts = 0
    rounds = 0
    while attempts < max_attempts:
        pending: list[tuple[int, SurfaceSampler, np.ndarray]] = []
        # Most objects land at the first try: the first round drops one candidate; later
        # rounds drop as many as there are worker threads (same wall time as one).
        width = 1 if rounds == 0 else min(batch, world.nthread)
        rounds += 1
        while attempts < max_attempts and len(pending) < width:
            attempts += 1
            candidate = _candidate(world, job.object_id, samplers, weights, rng, drop_height)
            if isinstance(candidate, str):
                tried.append((attempts, candidate))
            else:
                pending.append((attempts, *candidate))
        if not pending:
            continue
        verdicts = world.drop(
            job.object_id,
            [state for _, _, state in pending],
            nstep,
            watch=[],
            judge=functools.partial(
                _judge_candidate,
                world,
                [p[1].surface for p in pending],
                bodies,
                meta.upright,
                before,
            ),
            floor_z=min(s.surface.height for s in samplers) - 0.1,
        )
        for (number, sampler, _), (outcome, reason) in zip(pending, verdicts):
            if outcome is None:
                break  # never needed: an earlier candidate was accepted
            if reason is not None:
                tried.append((number, reason))
                continue
            # Candidates sampled after the accepted one were never needed: forget them, so
            # the outcome does not depend on the round width (the number of threads).
            rejections = Counter(r for n, r in tried if n < number)
            world.commit(job.object_id, outcome.state)
            lift = min(world.penetration(job.object_id), LIFT_CAP_M)
            final_pose = _final_pose(outcome, lift, sampler.surface.height)
            return _placement(
                job, number, "placed", rejections, start, (sampler.surface.index, final_pose)
            )
    world.park(job.object_id)
    rejections = Counter(r for _, r in tried)
    return _placement(job, attempts, _failure_reason(rejections), rejections, start)


def _candidate(
    world: DropWorld,
    object_id: str,
    samplers: list[SurfaceSampler],
    weights: np.ndarray,
    rng: np.random.Generator,
    drop_height: float,
) -> tuple[SurfaceSampler, np.ndarray] | str:
    """A spawn state for ``object_id`` on a surface drawn by area (with its sampler), or why
    the draw was rejected before dropping."""
    sampler = samplers[int(rng.choice(len(samplers), p=weights))]
    pose = sampler.sample(rng)
    if pose is None:
        return "no free footprint on the surface"
    x, y, yaw = pose
    pos = np.array([x, y, sampler.surface.height + drop_height])
    state = world.candidate_state(object_id, pos, np.array(yaw_quat(yaw)))
    if world.spawn_collision(object_id, state) is not None:
        return "collides at spawn"
    return sampler, state


def _judge_candidate(
    world: DropWorld,
    surfaces: list[WorldSurface],
    bodies: dict[str | None, int],
    upright: bool,
    before: dict[str, np.ndarray],
    k: int,
    outcome: Outcome,
) -> str | None:
    surface = surfaces[k]
    return landing_problem(
        world,
        outcome,
        surface.polygon,
        surface.height,
        frozenset({bodies[surface.part]}),
        upright,
        before,
    )


def landing_problem(
    world: DropWorld,
    outcome: Outcome,
    polygon: Polygon,
    surface_z: float | None,
    rec_bodies: frozenset[int],
    upright: bool,
    before: dict[str, np.ndarray],
    receptacle: str = "the receptacle",
) -> str | None:
    """Why a dropped object's outcome is rejected (the rule of spawn-and-drop), or None when it
    is accepted: it must stay finite, not end more than ``FALL_TOL_M`` below ``surface_z``
    (None: no such check), be at rest, stand over ``polygon``, touch one of ``rec_bodies`` (the
    receptacle's bodies) and no
    object placed before, be upright when ``upright``, and leave those objects (``before``:
    their positions) where they were. ``receptacle`` names the receptacle in the reasons."""
    if not outcome.finite:
        return "simulation diverged"
    if surface_z is not None and outcome.position[2] < surface_z - FALL_TOL_M:
        return "fell off"
    if outcome.speed > REST_SPEED or outcome.spin > REST_SPIN:
        return "still moving"
    if not polygon.contains(Point(float(outcome.position[0]), float(outcome.position[1]))):
        return "off the surface"
    if not rec_bodies & outcome.touches:
        return f"not resting on {receptacle}"
    if outcome.touches & {world.bodies[object_id].body for object_id in before}:
        return "leans on another object"
    if upright and outcome.tilt_deg > UPRIGHT_TOL_DEG:
        return "not upright"
    for object_id, pos in before.items():
        moved, _ = world.pose(object_id, outcome.state)
        if np.linalg.norm(moved - pos) > DISTURB_TOL_M:
            return "disturbed a placed object"
    return None


SPAWN_REASONS = ("collides at spawn", "no free footprint on the surface")


def _failure_reason(rejections: Counter[str]) -> str:
    """``no free space`` when most candidates could not even be spawned, else the most
    common reason the dropped ones were rejected for."""
    if not rejections:
        return "no candidate tried"
    spawn = sum(rejections[r] for r in SPAWN_REASONS)
    dropped = Counter({r: n for r, n in rejections.items() if r not in SPAWN_REASONS})
    if spawn * 2 >= sum(rejections.values()) or not dropped:
        return "no free space"
    return dropped.most_common(1)[0][0]


def _placement(
    job: _Job,
    attempts: int,
    reason: str,
    rejections: Counter[str],
    start: float,
    accepted: tuple[int, dict[str, Any]] | None = None,
) -> SpawnPlacement:
    """The outcome of placing ``job``; ``accepted``: the surface index and final pose of the
    candidate that came to rest (None: none did, for ``reason``)."""
    return SpawnPlacement(
        object_id=job.object_id,
        asset=job.asset.meta.id,
        surface_index=accepted[0] if accepted else None,
        attempts=attempts,
        accepted=accepted is not None,
        reason=reason,
        final_pose=accepted[1] if accepted else None,
        seconds=round(time.perf_counter() - start, 4),
        rejections=dict(sorted(rejections.items())),
        inside=job.inside,
    )


def _final_pose(outcome: Outcome, lift: float, surface_height: float) -> dict[str, Any]:
    quat = outcome.quat / np.linalg.norm(outcome.quat)
    if quat[0] < 0:
        quat = -quat
    x, y, z = (float(v) for v in outcome.position)
    return {
        "position": [round(x, 6), round(y, 6), round(z + lift, 6)],
        "quat": [round(float(q), 7) for q in quat],
        "tilt_deg": round(outcome.tilt_deg, 3),
        "height_above_surface_m": round(z + lift - surface_height, 6),
        "lift_m": round(lift, 6),
    }


def _scene_object(job: _Job, placement: SpawnPlacement, receptacle: SceneObject) -> SceneObject:
    pose = placement.final_pose or {}
    quat = tuple(pose["quat"])
    w, x, y, z = quat
    yaw = math.degrees(math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z)))
    return SceneObject(
        id=job.object_id,
        asset=job.asset.meta.id,
        position=tuple(pose["position"]),
        yaw_deg=round(yaw, 4),
        quat=quat,
        support=receptacle.id,
        room=receptacle.room,
    )


__all__ = [
    "SpawnPlacement",
    "SpawnResult",
    "object_yaw",
    "populate",
    "resolve_request",
]
