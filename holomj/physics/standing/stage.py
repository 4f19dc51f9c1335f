"""Make an imported house stand: every object on the floor or on its receptacle, clear of the
walls and of each other, settled, and judged by the validation rule.

1. **Audit** the scene as imported (the numbers ``before``).
2. **First pass** (:mod:`~holomj.physics.standing.prepass`): objects whose footprint lies on a
   receptacle rest on it; everything else free stands on the floor (its lowest collider point
   at z = 0); objects outside their room are pulled in.
3. **Separate** (:func:`holomj.physics.repair.separate`, its push rule
   :class:`~holomj.physics.standing.pushes.StandPushes`): every object that is not a child
   (children wait parked) is pushed out of the walls along their normal, towards its room,
   and out of its neighbours by the shortest move (floor objects horizontally), up to
   ``max_move_m``; deeper overlaps are left and their objects unsaved.
4. **Drop** the children (``support`` set) onto their parents' surfaces
   (:mod:`~holomj.physics.standing.drops`).
5. **Settle** the scene with furniture free (:func:`holomj.physics.settle.run_validation`);
   stable objects get their settled pose (:func:`holomj.physics.repair.bake`), unstable ones
   keep theirs and are unsaved. Objects already lost (too deep to separate, children no spot
   held, and what rests on them) are held still out of the way meanwhile, so they cannot
   throw their neighbours about, and keep their imported pose.
6. **Write back** (the caller's ``recompile``, ``as-is``) with a keyframe ``settled``
   (:func:`holomj.physics.repair.add_settled_key`) and **validate** that scene as
   ``holomj validate`` does (furniture free): what it says is the verdict (``report``).

Nothing is deleted: an object that cannot be saved stays in the scene at its imported pose and
is listed in ``unsaved`` with the reason. Every pose change is listed in ``moved`` with the
reasons in order (``lowered 12 mm to stand on the floor; moved 31 mm clear of wall_004, then
settled``) except moves under 1 mm by settling alone (counted in ``settled``), every drop in
``dropped``, every separation in ``separated``.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import mujoco

from holomj.library.store import AssetLibrary
from holomj.mjcf.compiler import CompiledScene, compile_scene
from holomj.mjcf.geometry import yaw_quat
from holomj.mjcf.objects import Furniture, is_furniture
from holomj.physics.audit import Rooms, audit
from holomj.physics.drop_world import DropWorld
from holomj.physics.repair import add_settled_key, bake, moves, separate
from holomj.physics.scene_io import LoadedScene, loaded_from_compiled
from holomj.physics.settle import Validation, run_validation
from holomj.physics.spawn import PARK_HEIGHT_M
from holomj.physics.standing.drops import Child, Dropped, drop_children
from holomj.physics.standing.prepass import prepare
from holomj.physics.standing.pushes import StandPushes
from holomj.physics.standing.records import (
    move_reasons,
    penetrations,
    reassigned,
    separations,
    validation_summary,
)
from holomj.spec.assets import AssetMeta
from holomj.spec.report import RepairAction, StabilityReport, Thresholds, Unsaved
from holomj.spec.scene import SceneObject, SceneSpec

MAX_MOVE_M = 0.5  # overlaps needing a longer move are not separated: their objects are unsaved
PARK_SPACING_M = 3.0
SLIGHT_MOVE_M = 0.001  # settling moves below this (and SLIGHT_TURN_DEG) are only counted
SLIGHT_TURN_DEG = 0.5
TILT_DEG = 1.0  # a dropped object tilted less than this is written with a yaw only

Recompile = Callable[[SceneSpec, Furniture], CompiledScene]


@dataclass(frozen=True)
class StandOptions:
    """Limits of the stage. ``sleep`` lets the settle run of step 5 use MuJoCo's sleeping
    islands (faster; the final validation never does)."""

    thresholds: Thresholds = field(default_factory=Thresholds)
    max_move_m: float = MAX_MOVE_M
    sleep: bool = True


@dataclass
class StandOutcome:
    """The scene made to stand, and every change made to it."""

    compiled: CompiledScene  # the written scene (``as-is``) with its ``settled`` keyframe
    report: StabilityReport | None  # the final validation (None when it was skipped)
    moved: list[RepairAction] = field(default_factory=list)
    dropped: list[Dropped] = field(default_factory=list)
    separated: list[dict[str, Any]] = field(default_factory=list)
    reassigned: list[dict[str, str]] = field(default_factory=list)
    settled: dict[str, Any] = field(default_factory=dict)  # moved only by settling, slightly
    unsaved: list[Unsaved] = field(default_factory=list)
    before: dict[str, Any] = field(default_factory=dict)
    after: dict[str, Any] = field(default_factory=dict)
    seconds: dict[str, float] = field(default_factory=dict)

    @property
    def scene(self) -> SceneSpec:
        """The scene as written."""
        return self.compiled.scene

    @property
    def valid(self) -> bool:
        """Every object saved and the final validation ok."""
        return not self.unsaved and self.report is not None and self.report.ok

    def to_report(self) -> dict[str, Any]:
        """The fields this stage adds to ``import_report.json``:

        ``valid`` (every object saved and the final validation ok); ``moved`` (object,
        ``moved_m``, ``translation``, ``rotation_deg``, ``why``: every pose change but slight
        settling); ``settled_only`` (how many objects settling alone moved, under 1 mm, and
        the most); ``dropped`` (object, ``onto``, ``surface`` index (-1: the top of its
        bounding box, null: held still), ``attempts``, ``from_xy``, ``position``,
        ``offset_m``); ``separated`` (object, ``from`` (an object or a wall), ``moved_m``,
        ``translation``); ``reassigned`` (object, ``field`` support or room, ``value``,
        ``why``); ``unsaved`` (object, ``why``); ``penetrations_before`` /
        ``penetrations_after`` (``count``, deepest ``max_m`` at t = 0); ``validation`` (the
        final verdict in numbers); ``stand_seconds`` per step."""
        report = self.report
        return {
            "valid": self.valid,
            "moved": [
                {"object": a.name, **a.model_dump(mode="json", exclude={"name"})}
                for a in self.moved
            ],
            "settled_only": self.settled,
            "dropped": [d.to_dict() for d in self.dropped if d.accepted],
            "separated": self.separated,
            "reassigned": self.reassigned,
            "unsaved": [{"object": u.name, "why": u.why} for u in self.unsaved],
            "penetrations_before": self.before,
            "penetrations_after": self.after,
            "validation": None if report is None else validation_summary(report),
            "stand_seconds": {k: round(v, 3) for k, v in self.seconds.items()},
        }


def make_stand(
    scene: SceneSpec,
    library: AssetLibrary,
    recompile: Recompile,
    options: StandOptions | None = None,
    *,
    validate_unsaved: bool = True,
    source: Path | str = "scene",
) -> StandOutcome:
    """Make ``scene`` stand (see the module docstring). ``recompile(scene, furniture)`` builds
    the scene to write (``as-is``) and to validate (``free``), e.g. with a robot attached.
    ``validate_unsaved=False`` skips the final validation when an object is already unsaved
    (the caller refuses such a scene anyway)."""
    opts = options or StandOptions()
    th = opts.thresholds
    clock = _Clock()
    metas = {o.id: library.get(o.asset).meta for o in scene.objects}
    rooms = Rooms(scene, 0.0).polygons

    # 1. every object gets a free joint where it can (children are dropped with one)
    work = _rebuilt(scene, [o.model_copy(update={"static": False}) for o in scene.objects])
    compiled = compile_scene(work, library, furniture="free")
    loaded = loaded_from_compiled(compiled, library, Path(source))
    before = audit(loaded, tolerance=th.tolerance_m, room_margin=th.room_margin_m)
    clock.lap("audit")

    # 2. first pass
    prepared = prepare(work.objects, compiled.model, loaded.objects, metas, rooms)
    free = _free_objects(compiled.model, loaded.objects)
    children = [o for o in prepared.objects if o.support is not None and o.id in free]
    child_ids = {o.id for o in children}
    parked = _parked(prepared.objects, child_ids, scene)
    first = _rebuilt(work, parked)
    _pose_model(compiled.model, first.objects, loaded.objects)
    clock.lap("first_pass")

    # 3. separate what is not a child
    pushes = StandPushes(
        rooms,
        {o.id: o.room for o in first.objects},
        {o.id for o in first.objects if o.support is None and o.id in free},
    )
    at_first = LoadedScene(loaded.source, compiled.model, loaded.objects, first, library)
    second, why_separated, unsaved_separated = separate(
        at_first, th, max_move_m=opts.max_move_m, push_rule=pushes, fixed=child_ids
    )
    _pose_model(compiled.model, second.objects, loaded.objects)
    separated = separations(first, second, why_separated, pushes.walls)
    clock.lap("separate")

    # 4. drop the children
    jobs = _child_jobs(scene, second, children, child_ids)
    drops = _drop(compiled, jobs, second, metas)
    clock.lap("drops")

    # 5. settle, holding still (parked) what is already lost and what rests on it
    placed_scene = _after_drops(scene, second, drops, prepared.objects)
    lost = {u.name: u.why for u in unsaved_separated}
    lost.update({oid: d.reason for oid, d in drops.items() if not d.accepted})
    lost.update(_resting_on(placed_scene.objects, set(lost)))
    settle_compiled, settling = _settle(placed_scene, scene, lost, library, metas, opts, source)
    baked, unstable = bake(placed_scene, settling, keep=set(lost))
    unsaved = [Unsaved(name=k, why=v) for k, v in lost.items()]
    unsaved += [
        Unsaved(name=o.name, why="; ".join(o.reasons))
        for o in settling.report.objects
        if o.name in unstable and o.name not in lost
    ]
    clock.lap("settle")

    # 6. write back with the settled keyframe, and validate
    final = recompile(baked, "as-is")
    add_settled_key(
        final, settle_compiled.model, settling.result.data, skip={u.name for u in unsaved}
    )
    report, after = _final_check(
        final, baked, recompile, library, (th, Path(source)), unsaved,
        validate_unsaved or not unsaved,
    )  # fmt: skip
    clock.lap("validate")

    moved = moves(scene, baked, move_reasons(prepared.reasons, separated, drops))
    settled_only = [a for a in moved if a.why == "settled" and _slight(a)]
    return StandOutcome(
        compiled=final,
        report=report,
        moved=[a for a in moved if a not in settled_only],
        settled=_settled_summary(settled_only),
        dropped=[drops[o.id] for o in children],
        separated=separated,
        reassigned=reassigned(scene, baked, prepared.reasons),
        unsaved=sorted(unsaved, key=lambda u: u.name),
        before=penetrations(before.penetrations, before),
        after=after,
        seconds=clock.laps,
    )


def _drop(
    compiled: CompiledScene, jobs: list[Child], second: SceneSpec, metas: dict[str, AssetMeta]
) -> dict[str, Dropped]:
    """Every child dropped onto its parent, in a drop world of the compiled scene."""
    world = DropWorld(compiled, sorted(j.obj.id for j in jobs), nthread=1)
    try:
        return drop_children(world, jobs, {o.id: o for o in second.objects}, metas)
    finally:
        world.close()


def _settle(
    placed: SceneSpec,
    scene: SceneSpec,
    lost: dict[str, str],
    library: AssetLibrary,
    metas: dict[str, AssetMeta],
    opts: StandOptions,
    source: Path | str,
) -> tuple[CompiledScene, Validation]:
    """Settle the placed scene with furniture free, holding still (parked) what is lost and
    static props; the compiled scene and the validation run."""
    objects = [
        o.model_copy(
            update={"static": o.id in lost or (o.static and not is_furniture(o, metas[o.id]))}
        )
        for o in _parked(placed.objects, set(lost), scene)
    ]
    compiled = compile_scene(_rebuilt(placed, objects), library, furniture="as-is")
    loaded = loaded_from_compiled(compiled, library, Path(source))
    return compiled, run_validation(loaded, opts.thresholds, "free", opts.sleep)


def _settled_summary(settled_only: list[RepairAction]) -> dict[str, Any]:
    """How many objects settling alone moved slightly, and the most."""
    return {
        "objects": len(settled_only),
        "max_m": round(max((a.moved_m for a in settled_only), default=0.0), 6),
    }


def _child_jobs(
    scene: SceneSpec, second: SceneSpec, children: list[SceneObject], child_ids: set[str]
) -> list[Child]:
    """One drop per child: at its imported pose moved as its parent was (a child of a child
    moves with its parent when that one lands), at its authored height above its parent."""
    imported = {o.id: o for o in scene.objects}
    now = {o.id: o.position for o in second.objects}
    jobs = []
    for obj in children:
        parent = imported[str(obj.support)]
        dx, dy = (now[parent.id][k] - parent.position[k] for k in (0, 1))
        if parent.id in child_ids:
            dx = dy = 0.0
        x, y, z = imported[obj.id].position
        update = {"support": obj.support, "position": (x + dx, y + dy, z)}
        jobs.append(
            Child(
                imported[obj.id].model_copy(update=update),
                parent.id,
                z - parent.position[2],
                static=imported[obj.id].static,
            )
        )
    return jobs


def _final_check(
    final: CompiledScene,
    baked: SceneSpec,
    recompile: Recompile,
    library: AssetLibrary,
    context: tuple[Thresholds, Path],
    unsaved: list[Unsaved],
    validate: bool,
) -> tuple[StabilityReport | None, dict[str, Any]]:
    """Validate the written scene as ``holomj validate`` does (furniture free), adding to
    ``unsaved`` what does not stand once settled; without ``validate``, only audit it. The
    report (None when not validated) and the penetrations after."""
    th, source = context
    if not validate:
        found = audit(
            loaded_from_compiled(final, library, source),
            tolerance=th.tolerance_m,
            room_margin=th.room_margin_m,
        )
        return None, penetrations(found.penetrations)
    checked = recompile(baked, "free")
    report = run_validation(
        loaded_from_compiled(checked, library, source), th, "free", False
    ).report
    known = {u.name for u in unsaved}
    unsaved += [
        Unsaved(name=o.name, why="once settled: " + "; ".join(o.reasons))
        for o in report.objects
        if not o.stable and o.name not in known
    ]
    return report, penetrations(report.penetrations)


def _slight(action: RepairAction) -> bool:
    """A move too small to list one by one (settling into contact)."""
    return action.moved_m < SLIGHT_MOVE_M and action.rotation_deg < SLIGHT_TURN_DEG


class _Clock:
    def __init__(self) -> None:
        self.laps: dict[str, float] = {}
        self._last = time.perf_counter()

    def lap(self, name: str) -> None:
        now = time.perf_counter()
        self.laps[name] = now - self._last
        self._last = now


def _rebuilt(scene: SceneSpec, objects: list[SceneObject]) -> SceneSpec:
    return SceneSpec.model_validate({**scene.model_dump(), "objects": objects})


def _free_objects(model: mujoco.MjModel, bodies: dict[str, int]) -> set[str]:
    free = {
        int(model.jnt_bodyid[j])
        for j in range(model.njnt)
        if model.jnt_type[j] == mujoco.mjtJoint.mjJNT_FREE
    }
    return {name for name, body in bodies.items() if body in free}


def _parked(objects: list[SceneObject], ids: set[str], scene: SceneSpec) -> list[SceneObject]:
    """``objects`` with those in ``ids`` parked high above the house, apart from each other."""
    xs = [p[0] for room in scene.rooms for p in room.polygon]
    ys = [p[1] for room in scene.rooms for p in room.polygon]
    x0, y0 = min(xs), min(ys)
    result, k = [], 0
    for obj in objects:
        if obj.id in ids:
            obj = obj.model_copy(update={"position": (x0 + PARK_SPACING_M * k, y0, PARK_HEIGHT_M)})
            k += 1
        result.append(obj)
    return result


def _pose_model(model: mujoco.MjModel, objects: list[SceneObject], bodies: dict[str, int]) -> None:
    """Put every object of ``model`` at its pose in ``objects`` (initial qpos of free bodies,
    body frames of the others)."""
    free_adr = {
        int(model.jnt_bodyid[j]): int(model.jnt_qposadr[j])
        for j in range(model.njnt)
        if model.jnt_type[j] == mujoco.mjtJoint.mjJNT_FREE
    }
    for obj in objects:
        body = bodies[obj.id]
        quat = obj.quat if obj.quat is not None else yaw_quat(math.radians(obj.yaw_deg))
        if body in free_adr:
            adr = free_adr[body]
            model.qpos0[adr : adr + 3] = obj.position
            model.qpos0[adr + 3 : adr + 7] = quat
        else:
            model.body_pos[body] = obj.position
            model.body_quat[body] = quat


def _after_drops(
    scene: SceneSpec,
    separated: SceneSpec,
    drops: dict[str, Dropped],
    prepared: list[SceneObject],
) -> SceneSpec:
    """The scene with the separated poses, the dropped children where they landed, unplaced
    children where they were imported, new supports and rooms, and the original static flags."""
    imported = {o.id: o for o in scene.objects}
    supports = {o.id: o for o in prepared}
    objects = []
    for obj in separated.objects:
        original = imported[obj.id]
        update: dict[str, Any] = {"static": original.static}
        drop = drops.get(obj.id)
        if drop is not None:
            update["support"] = supports[obj.id].support
            if drop.accepted and drop.position is not None and drop.quat is not None:
                update.update(_pose_fields(drop.position, drop.quat))
                update["room"] = original.room or supports[str(drop.onto)].room
            else:
                update.update(
                    {
                        "position": original.position,
                        "quat": original.quat,
                        "yaw_deg": original.yaw_deg,
                    }
                )
        objects.append(obj.model_copy(update=update))
    return _rebuilt(scene, objects)


def _pose_fields(
    position: tuple[float, float, float], quat: tuple[float, float, float, float]
) -> dict[str, Any]:
    w, x, y, z = quat
    yaw = math.degrees(math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z)))
    tilt = math.degrees(math.acos(max(-1.0, min(1.0, 1.0 - 2.0 * (x * x + y * y)))))
    return {
        "position": position,
        "yaw_deg": round(yaw, 4),
        "quat": quat if tilt > TILT_DEG else None,
    }


def _resting_on(objects: list[SceneObject], lost: set[str]) -> dict[str, str]:
    """Objects resting (directly or not) on a lost one, and why they are lost too."""
    result: dict[str, str] = {}
    changed = True
    while changed:
        changed = False
        for obj in objects:
            gone = lost | set(result)
            if obj.id not in gone and obj.support in gone:
                result[obj.id] = f"rests on {obj.support}, which could not be saved"
                changed = True
    return result
