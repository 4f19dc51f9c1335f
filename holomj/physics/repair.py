"""``holomj validate --repair``: resolve small initial penetrations, settle, bake the result back.

1. **Separate.** For every pair of colliders interpenetrating deeper than the tolerance and at
   most ``repair_max_m``, one object is moved along the contact normal by the depth (plus half
   a tolerance): the dynamic one of the pair, else the one resting on the other, else the one
   listed later in the scene; structure and the floor never move. Repeat until no pair is
   deeper than the tolerance. Deeper pairs are left alone and reported as unsaved.
2. **Settle** the separated scene (furniture free, as validation does).
3. **Bake**: every free object that ends stable (``STABILITY_RULE``: at rest, and close to
   the pose it had after separation) gets its settled pose in ``scene.json`` (``yaw_deg``, or
   ``quat`` when it tilts more than 1°); unstable ones and those too deep to separate keep
   their pose and are reported as unsaved. No object is ever deleted, and no pose that fails
   the rule (a toppled lamp, a box that slid away) is ever written as settled.
4. **Recompile** the new scene with a keyframe ``settled`` holding the joint positions the
   simulation settled to, except those of the unsaved objects, which keep their authored pose
   there too. Writing it back into its folder is the jobs layer's (``holomj.jobs.validate``).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

import mujoco
import numpy as np

from holomj.errors import InputError
from holomj.mjcf.compiler import CompiledScene, compile_spec
from holomj.mjcf.objects import Furniture
from holomj.physics.audit import GeomOwners, Overlap, find_overlaps
from holomj.physics.scene_io import LoadedScene
from holomj.physics.settle import Validation, run_validation
from holomj.physics.settling import ObjectTrack
from holomj.spec.report import RepairAction, Thresholds, Unsaved
from holomj.spec.scene import SceneObject, SceneSpec

SETTLED_KEY = "settled"
MAX_ROUNDS = 100
TILT_DEG = 1.0  # below this tilt a settled pose is baked as a yaw


@dataclass
class RepairOutcome:
    """What ``--repair`` made of a scene: the recompiled scene (with its ``settled`` keyframe),
    every object it moved and every object it could not save."""

    compiled: CompiledScene
    repaired: list[RepairAction] = field(default_factory=list)
    unsaved: list[Unsaved] = field(default_factory=list)

    @property
    def scene(self) -> SceneSpec:
        """The repaired scene."""
        return self.compiled.scene


Recompile = Callable[[SceneSpec, Furniture], CompiledScene]


def repair_scene(
    loaded: LoadedScene,
    recompile: Recompile,
    thresholds: Thresholds | None = None,
    furniture: Furniture = "free",
    sleep: bool = False,
) -> RepairOutcome:
    """Repair the holomj scene of ``loaded`` (see the module docstring). ``recompile(scene,
    furniture)`` compiles a scene the way ``loaded`` was (its library, its robot)."""
    th = thresholds or Thresholds()
    if loaded.scene is None or loaded.library is None:
        raise InputError(
            "--repair needs a holomj scene (scene.json and assets/)",
            where=str(loaded.source),
            fix="validate without --repair, or compile the scene with 'holomj compile'",
        )
    original = loaded.scene
    separated, why, unsaved = separate(loaded, th)
    compiled = recompile(separated, furniture)
    objects = {o.id: compiled.model.body(f"{o.id}/body").id for o in separated.objects}
    settled_scene = LoadedScene(
        loaded.source, compiled.model, objects, separated, loaded.library, compiled, loaded.folder
    )
    validation = run_validation(settled_scene, th, furniture, sleep)
    baked, unstable = bake(separated, validation, keep={u.name for u in unsaved})
    unsaved += [
        Unsaved(name=o.name, why="; ".join(o.reasons))
        for o in validation.report.objects
        if o.name in unstable and o.name not in {u.name for u in unsaved}
    ]
    final = recompile(baked, "as-is")
    unsaved_names = {u.name for u in unsaved}
    add_settled_key(final, compiled.model, validation.result.data, skip=unsaved_names)
    repaired = moves(original, baked, why)
    return RepairOutcome(final, repaired, sorted(unsaved, key=lambda u: u.name))


PushRule = Callable[
    [mujoco.MjModel, mujoco.MjData, GeomOwners, Overlap, int, np.ndarray], np.ndarray | None
]
"""``rule(model, data, owners, overlap, mover, push)``: the push (world frame) to give object
``mover`` (an index into ``owners.names``) to resolve ``overlap``, where ``push`` is the default
one (along the contact normal, as deep as the pair); None keeps the default."""


def separate(
    loaded: LoadedScene,
    th: Thresholds,
    *,
    max_move_m: float | None = None,
    push_rule: PushRule | None = None,
    fixed: frozenset[str] | set[str] = frozenset(),
) -> tuple[SceneSpec, dict[str, str], list]:
    """Push interpenetrating objects apart; returns the new scene, why each object moved, and
    the objects that could not be saved.

    ``max_move_m`` (default ``th.repair_max_m``): a pair whose push is longer is left alone
    and its mover reported unsaved. ``push_rule`` may replace the default push (along the
    contact normal) of a pair, e.g. to keep floor objects on the floor; objects in ``fixed``
    never move (like structure). An object pushed back the way it was pushed the round before
    is squeezed: from then on the other party of its overlaps moves."""
    model = loaded.model
    scene = loaded.scene
    if scene is None:
        raise InputError("only holomj scenes can be repaired", where=str(loaded.source))
    data = mujoco.MjData(model)
    owners = GeomOwners(model, loaded.objects)
    fixed_ids = {owners.names.index(name) for name in fixed if name in owners.names}
    rounds = _Rounds(
        owners,
        ObjectTrack.of(model, loaded.objects),
        {o.id: i for i, o in enumerate(scene.objects)},
        {o.id: o.support for o in scene.objects},
        fixed_ids,
        th.tolerance_m,
        th.repair_max_m if max_move_m is None else max_move_m,
        push_rule,
    )
    body_pos = model.body_pos.copy()  # restored below: the model is not ours to keep
    free_adr = _free_joint_addresses(model)
    try:
        for _ in range(MAX_ROUNDS):
            mujoco.mj_kinematics(model, data)
            pushes = rounds.pushes(model, data)
            if not pushes:
                break
            for mover, push in pushes.items():
                body = int(owners.object_bodies[mover])
                if body in free_adr:
                    data.qpos[free_adr[body] : free_adr[body] + 3] += push
                else:
                    model.body_pos[body] += push
        else:
            mujoco.mj_kinematics(model, data)
            for overlap in find_overlaps(model, data, owners, th.tolerance_m):
                for geom in (overlap.geom1, overlap.geom2):
                    if owners.geom_owner[geom] >= 0:
                        name = owners.names[owners.geom_owner[geom]]
                        rounds.unsaved.setdefault(name, "still interpenetrating after repair")
        mujoco.mj_kinematics(model, data)
        positions = data.xpos[owners.object_bodies].copy()
    finally:
        model.body_pos[:] = body_pos
    objects = []
    for obj in scene.objects:
        i = owners.names.index(obj.id)
        if obj.id in rounds.why:
            obj = obj.model_copy(update={"position": _clean_vec(positions[i])})
        objects.append(obj)
    unsaved_list = [Unsaved(name=k, why=v) for k, v in sorted(rounds.unsaved.items())]
    return _rebuilt(scene, objects), rounds.why, unsaved_list


def _free_joint_addresses(model: mujoco.MjModel) -> dict[int, int]:
    """Body id -> qpos address of its free joint, for every body with one."""
    return {
        int(model.jnt_bodyid[joint]): int(model.jnt_qposadr[joint])
        for joint in range(model.njnt)
        if model.jnt_type[joint] == mujoco.mjtJoint.mjJNT_FREE
    }


@dataclass
class _Rounds:
    """The pushes of each round of :func:`separate`, and what it found: why each object moved,
    the objects it could not save, the pairs it gave up on and the squeezed movers."""

    owners: GeomOwners
    track: ObjectTrack
    index: dict[str, int]
    supports: dict[str, str | None]
    fixed_ids: set[int]
    tolerance_m: float
    limit_m: float
    push_rule: PushRule | None
    why: dict[str, str] = field(default_factory=dict)
    unsaved: dict[str, str] = field(default_factory=dict)
    skipped: set[tuple[int, int]] = field(default_factory=set)
    stuck: set[int] = field(default_factory=set)
    last: dict[int, np.ndarray] = field(default_factory=dict)

    def pushes(self, model: mujoco.MjModel, data: mujoco.MjData) -> dict[int, np.ndarray]:
        """This round's push of each mover (object index), deepest overlap first; empty when
        nothing is left to push."""
        owners = self.owners
        overlaps = [
            o
            for o in find_overlaps(model, data, owners, self.tolerance_m)
            if (o.geom1, o.geom2) not in self.skipped
        ]
        pushes: dict[int, np.ndarray] = {}
        for overlap in overlaps:  # deepest first
            mover, push = _mover(
                owners, self.track, overlap, self.index, self.supports, self.fixed_ids, self.stuck
            )
            if mover is None or mover in pushes:
                continue
            name = owners.names[mover]
            other = owners.label(
                overlap.geom1 if owners.geom_owner[overlap.geom2] == mover else overlap.geom2
            )
            push = push * (1.0 + 0.5 * self.tolerance_m / overlap.depth)
            if self.push_rule is not None:
                ruled = self.push_rule(model, data, owners, overlap, mover, push)
                push = push if ruled is None else np.asarray(ruled, dtype=float)
            limit = self.limit_m
            if overlap.depth > limit or float(np.linalg.norm(push)) > limit + self.tolerance_m:
                self.skipped.add((overlap.geom1, overlap.geom2))
                needs = float(np.linalg.norm(push))
                extra = f", needs a move of {needs * 1000:.0f} mm" if self.push_rule else ""
                self.unsaved.setdefault(
                    name,
                    f"penetrates {other} by {overlap.depth * 1000:.1f} mm{extra} "
                    f"(repairs up to {limit * 1000:.0f} mm)",
                )
                continue
            pushes[mover] = push
            self.why.setdefault(name, f"separated from {other}")
        for mover, push in pushes.items():
            # pushed back the way it came last round: squeezed (between a wall and a
            # neighbour, say); from now on the other party of its overlaps moves instead
            if mover in self.last and float(np.dot(push, self.last[mover])) < 0.0:
                self.stuck.add(mover)
        if pushes:
            self.last = pushes
        return pushes


def _mover(
    owners: GeomOwners,
    track: ObjectTrack,
    overlap: Overlap,
    index: dict[str, int],
    supports: dict[str, str | None],
    fixed: set[int] | frozenset[int] = frozenset(),
    stuck: set[int] | frozenset[int] = frozenset(),
) -> tuple[int | None, np.ndarray]:
    """Which object of an overlapping pair moves, and its push (world frame); objects in
    ``fixed`` (indices) count as structure, objects ``stuck`` give way to the other party."""
    o1, o2 = int(owners.geom_owner[overlap.geom1]), int(owners.geom_owner[overlap.geom2])
    o1, o2 = (-1 if o1 in fixed else o1), (-1 if o2 in fixed else o2)
    if o1 < 0 and o2 < 0:
        return None, overlap.push2
    if o1 < 0:
        return o2, overlap.push2
    if o2 < 0:
        return o1, -overlap.push2
    if (o1 in stuck) != (o2 in stuck):
        return (o2, overlap.push2) if o1 in stuck else (o1, -overlap.push2)
    n1, n2 = owners.names[o1], owners.names[o2]
    d1, d2 = bool(track.dynamic[o1]), bool(track.dynamic[o2])
    if d1 != d2:
        return (o1, -overlap.push2) if d1 else (o2, overlap.push2)
    if supports.get(n1) == n2:
        return o1, -overlap.push2
    if supports.get(n2) == n1:
        return o2, overlap.push2
    later_is_2 = index.get(n2, 0) >= index.get(n1, 0)
    return (o2, overlap.push2) if later_is_2 else (o1, -overlap.push2)


def bake(
    scene: SceneSpec, validation: Validation, keep: set[str] | frozenset[str] = frozenset()
) -> tuple[SceneSpec, set[str]]:
    """The scene with the settled pose of every stable free object (except those in ``keep``,
    which keep their pose); and the names of the unstable ones."""
    data = validation.result.data
    owners = validation.track.owners
    reports = {o.name: o for o in validation.report.objects}
    unstable = {name for name, o in reports.items() if not o.stable}
    objects = []
    for obj in scene.objects:
        i = owners.names.index(obj.id)
        report = reports[obj.id]
        if report.dynamic and report.stable and obj.id not in keep:
            body = int(owners.object_bodies[i])
            obj = obj.model_copy(update=_pose_fields(data.xpos[body], data.xquat[body]))
        objects.append(obj)
    return _rebuilt(scene, objects), unstable


def _pose_fields(pos: np.ndarray, quat: np.ndarray) -> dict:
    """``position`` and ``yaw_deg`` (or ``quat`` when tilted) of a settled body."""
    quat = np.asarray(quat, dtype=float) / np.linalg.norm(quat)
    flat = np.zeros(9)
    mujoco.mju_quat2Mat(flat, quat)
    rot = flat.reshape(3, 3)
    tilt = math.degrees(math.acos(min(1.0, max(-1.0, rot[2, 2]))))
    yaw = math.degrees(math.atan2(rot[1, 0], rot[0, 0]))
    fields: dict = {"position": _clean_vec(pos), "yaw_deg": round(yaw, 4)}
    if tilt > TILT_DEG:
        if quat[0] < 0:
            quat = -quat
        fields["quat"] = tuple(round(float(q), 8) for q in quat)
    else:
        fields["quat"] = None
    return fields


def _clean_vec(values: np.ndarray) -> tuple[float, float, float]:
    x, y, z = (round(float(v), 6) + 0.0 for v in values)
    return (x, y, z)


def _rebuilt(scene: SceneSpec, objects: list[SceneObject]) -> SceneSpec:
    return SceneSpec.model_validate({**scene.model_dump(), "objects": objects})


def add_settled_key(
    compiled: CompiledScene,
    settled: mujoco.MjModel,
    data: mujoco.MjData,
    skip: set[str] | frozenset[str] = frozenset(),
) -> None:
    """Add the keyframe ``settled`` to ``compiled`` (joints matched by name) and recompile.

    The joints of the objects in ``skip`` (unsaved objects) keep their authored position."""
    model = compiled.model
    qpos = model.qpos0.copy()
    skipped_prefixes = tuple(f"{name}/" for name in skip)
    for joint in range(model.njnt):
        name = model.joint(joint).name
        if skipped_prefixes and name.startswith(skipped_prefixes):
            continue
        try:
            source = settled.joint(name)
        except KeyError:
            continue
        width = _qpos_width(model.jnt_type[joint])
        if _qpos_width(settled.jnt_type[source.id]) != width:
            continue
        start, src = model.jnt_qposadr[joint], settled.jnt_qposadr[source.id]
        qpos[start : start + width] = data.qpos[src : src + width]
    compiled.spec.add_key(name=SETTLED_KEY, qpos=[float(q) for q in qpos], time=0.0)
    compiled.model = compile_spec(compiled.spec, compiled.files)


def _qpos_width(kind: int) -> int:
    return {
        mujoco.mjtJoint.mjJNT_FREE: 7,
        mujoco.mjtJoint.mjJNT_BALL: 4,
    }.get(mujoco.mjtJoint(kind), 1)


def moves(before: SceneSpec, after: SceneSpec, why: dict[str, str]) -> list[RepairAction]:
    """Every object whose pose changed between the two scenes, and by how much."""
    actions = []
    for old, new in zip(before.objects, after.objects):
        delta = np.array(new.position) - np.array(old.position)
        angle = _angle_deg(_quat_of(old), _quat_of(new))
        if np.linalg.norm(delta) < 1e-6 and angle < 1e-3:
            continue
        reason = why.get(old.id)
        reason = f"{reason}, then settled" if reason else "settled"
        actions.append(
            RepairAction(
                name=old.id,
                moved_m=round(float(np.linalg.norm(delta)), 6),
                translation=_clean_vec(delta),
                rotation_deg=round(angle, 4),
                why=reason,
            )
        )
    return actions


def _quat_of(obj: SceneObject) -> np.ndarray:
    if obj.quat is not None:
        return np.array(obj.quat)
    half = math.radians(obj.yaw_deg) / 2
    return np.array([math.cos(half), 0.0, 0.0, math.sin(half)])


def _angle_deg(q1: np.ndarray, q2: np.ndarray) -> float:
    dot = min(1.0, abs(float(np.dot(q1, q2))))
    return math.degrees(2.0 * math.acos(dot))
