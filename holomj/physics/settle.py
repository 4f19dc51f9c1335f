"""Settle a scene, watch it for a while, and judge every object: the stability report.

The simulation starts from the model's initial pose on a fresh ``MjData`` (nothing is shared
with the caller) and steps with the scene's own options. It first *settles*: steps until every
free body has been at rest (linear speed under ``rest_linear_mps`` and angular speed under
``rest_angular_rps``) for ``rest_window_s``, or until ``settle_cap_s``. It then *monitors* a
window of ``monitor_s``, over which each object's drift, rotation, path length (jitter) and
deepest contact are measured; at the end, what it rests on. MuJoCo is deterministic on one
thread, so the same scene always gives the same numbers.

Objects are judged by the one rule of :data:`holomj.spec.report.STABILITY_RULE`: at rest over
the monitor window, close to the pose they were authored at, and without penetration at t = 0.
Positions are those of each object body's centre of mass (``xipos``), so the verdict does not
depend on where the body frame sits (a footed pole that topples ends 90° from its authored pose
with its centre of mass half its height lower, although its frame may not have moved).

Moving parts of articulated objects (the hinge and slide joints of bodies below an object's
body: doors, drawers, lids) count too: settling waits for them to be at rest as well (the same
speed thresholds, per radian or metre), and an object whose part ends more than
``part_rotation_deg`` (hinges) or ``part_travel_m`` (slides) from its authored joint value is
unstable, the reason naming the part ("door_0_hinge swung 35.2° from its authored angle").

MuJoCo 3.17's sleeping islands (``mjENBL_SLEEP``) are off by default: a sleeping body cannot
drift, so creep slower than ``sleep_tolerance`` would go unseen, and the scene's own options
are the ones its users simulate with. ``sleep=True`` turns them on for big scenes: 780 objects
at rest step in 0.7 ms instead of 28 ms.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass

import mujoco
import numpy as np

from holomj.physics.audit import AuditResult, GeomOwners, Rooms, audit, lowest_points
from holomj.physics.scene_io import LoadedScene
from holomj.physics.smoke import warning_counts
from holomj.spec.report import ObjectReport, StabilityReport, Thresholds

FLOOR = "floor"
FIXED = "fixed"
_CHECK_EVERY = 10  # steps between rest checks while settling


@dataclass(frozen=True)
class PartJoints:
    """The hinge and slide joints of the objects' moving parts (doors, drawers, lids)."""

    owner: np.ndarray  # object index per joint
    joint: np.ndarray  # joint id
    qpos: np.ndarray  # qpos address
    dof: np.ndarray  # dof address
    hinge: np.ndarray  # bool: hinge (radians) or slide (metres)

    @classmethod
    def of(cls, model: mujoco.MjModel, owners: GeomOwners) -> PartJoints:
        kinds = (int(mujoco.mjtJoint.mjJNT_HINGE), int(mujoco.mjtJoint.mjJNT_SLIDE))
        roots = set(owners.object_bodies.tolist())
        joints = [
            j
            for j in range(model.njnt)
            if int(model.jnt_type[j]) in kinds
            and owners.body_owner[model.jnt_bodyid[j]] >= 0
            and int(model.jnt_bodyid[j]) not in roots
        ]
        ids = np.array(joints, dtype=int)
        return cls(
            owner=owners.body_owner[model.jnt_bodyid[ids]] if ids.size else ids,
            joint=ids,
            qpos=model.jnt_qposadr[ids] if ids.size else ids,
            dof=model.jnt_dofadr[ids] if ids.size else ids,
            hinge=(model.jnt_type[ids] == int(mujoco.mjtJoint.mjJNT_HINGE))
            if ids.size
            else np.zeros(0, dtype=bool),
        )

    def __len__(self) -> int:
        return int(self.joint.size)

    def at_rest(self, data: mujoco.MjData, th: Thresholds) -> bool:
        """Every part slower than the rest thresholds (rad/s for hinges, m/s for slides)."""
        if not len(self):
            return True
        speed = np.abs(data.qvel[self.dof])
        limit = np.where(self.hinge, th.rest_angular_rps, th.rest_linear_mps)
        return bool(np.all(speed < limit))

    def departures(self, start: np.ndarray, end: np.ndarray) -> np.ndarray:
        """How far each joint ends from its start: degrees for hinges, metres for slides."""
        delta = np.abs(end[self.qpos] - start[self.qpos])
        return np.where(self.hinge, np.degrees(delta), delta)


@dataclass
class ObjectTrack:
    """Index arrays of the objects' bodies and (for free bodies) their velocity dofs."""

    owners: GeomOwners
    dynamic: np.ndarray  # bool per object
    lin_dofs: np.ndarray  # (n_dynamic, 3)
    ang_dofs: np.ndarray  # (n_dynamic, 3)
    parts: PartJoints | None = None  # the moving parts' joints

    @classmethod
    def of(cls, model: mujoco.MjModel, objects: dict[str, int]) -> ObjectTrack:
        owners = GeomOwners(model, objects)
        free_dof = {}
        for joint in range(model.njnt):
            if model.jnt_type[joint] == mujoco.mjtJoint.mjJNT_FREE:
                free_dof[int(model.jnt_bodyid[joint])] = int(model.jnt_dofadr[joint])
        bodies = owners.object_bodies
        dynamic = np.array([int(b) in free_dof for b in bodies], dtype=bool)
        adr = np.array([free_dof[int(b)] for b in bodies[dynamic]], dtype=int)
        lin = adr[:, None] + np.arange(3) if adr.size else np.zeros((0, 3), dtype=int)
        ang = adr[:, None] + np.arange(3, 6) if adr.size else np.zeros((0, 3), dtype=int)
        return cls(owners, dynamic, lin, ang, PartJoints.of(model, owners))

    def speeds(self, data: mujoco.MjData) -> tuple[np.ndarray, np.ndarray]:
        """Linear (m/s) and angular (rad/s) speed of each free object."""
        qvel = data.qvel
        return (
            np.linalg.norm(qvel[self.lin_dofs], axis=1),
            np.linalg.norm(qvel[self.ang_dofs], axis=1),
        )

    def at_rest(self, data: mujoco.MjData, th: Thresholds) -> np.ndarray:
        """Per free object: slower than the rest thresholds."""
        lin, ang = self.speeds(data)
        return (lin < th.rest_linear_mps) & (ang < th.rest_angular_rps)


@dataclass
class SettleResult:
    """The raw outcome of settle + monitor, before judging."""

    data: mujoco.MjData
    start_pos: np.ndarray  # object centres of mass at t = 0 (the authored pose)
    start_quat: np.ndarray  # object body orientations at t = 0
    start_qpos: np.ndarray  # joint values at t = 0 (the moving parts' authored values)
    monitor_pos: np.ndarray  # centres of mass at the start of the monitor window
    monitor_quat: np.ndarray
    path: np.ndarray  # path length of the centre of mass over the monitor window
    penetration: np.ndarray  # deepest contact during the monitor window (>= 0)
    settle_time: float
    settled: bool
    sim_time: float
    wall_time: float
    warnings: dict[str, int]


def run_settle(
    model: mujoco.MjModel, track: ObjectTrack, th: Thresholds, sleep: bool = False
) -> SettleResult:
    """Settle from the initial pose, then monitor; see the module docstring.

    ``sleep`` turns on MuJoCo's sleeping islands for this run (``model`` is restored after):
    much faster on big scenes once they rest, but a body asleep cannot creep, so drift slower
    than MuJoCo's ``sleep_tolerance`` goes unseen.
    """
    flags = model.opt.enableflags
    if sleep:
        model.opt.enableflags = flags | mujoco.mjtEnableBit.mjENBL_SLEEP
    try:
        result = _run_settle(model, track, th)
    finally:
        model.opt.enableflags = flags
    # The final state, recomputed awake: contacts and forces of every body (sleeping bodies
    # have none), for supports and the deepest contact.
    final = mujoco.MjData(model)
    final.qpos[:] = result.data.qpos
    final.qvel[:] = result.data.qvel
    final.time = result.data.time
    mujoco.mj_forward(model, final)
    _deepest_contacts(final, track.owners.geom_owner, result.penetration)
    result.warnings = _merge(result.warnings, warning_counts(final))
    result.data = final
    return result


def _merge(a: dict[str, int], b: dict[str, int]) -> dict[str, int]:
    return {k: a.get(k, 0) + b.get(k, 0) for k in sorted(set(a) | set(b))}


def _deepest_contacts(data: mujoco.MjData, geom_owner: np.ndarray, deepest: np.ndarray) -> None:
    """Raise ``deepest`` (per object) to the depth of the contacts in ``data``."""
    ncon = data.ncon
    if not ncon:
        return
    depth = -data.contact.dist[:ncon]
    pairs = data.contact.geom[:ncon]
    for column in (0, 1):
        owner = geom_owner[pairs[:, column]]
        mine = owner >= 0
        np.maximum.at(deepest, owner[mine], depth[mine])


def _run_settle(model: mujoco.MjModel, track: ObjectTrack, th: Thresholds) -> SettleResult:
    started = time.perf_counter()
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    bodies = track.owners.object_bodies
    start_pos = data.xipos[bodies].copy()
    start_quat = data.xquat[bodies].copy()
    start_qpos = data.qpos.copy()
    parts = track.parts
    dt = model.opt.timestep
    cap_steps = round(th.settle_cap_s / dt)
    window_steps = max(1, round(th.rest_window_s / dt))
    quiet_since = 0 if not track.dynamic.any() and not parts else None
    steps = 0
    while steps < cap_steps:
        if quiet_since is not None and steps - quiet_since >= window_steps:
            break
        for _ in range(min(_CHECK_EVERY, cap_steps - steps)):
            mujoco.mj_step(model, data)
        steps += min(_CHECK_EVERY, cap_steps - steps)
        if track.at_rest(data, th).all() and (parts is None or parts.at_rest(data, th)):
            quiet_since = steps if quiet_since is None else quiet_since
        else:
            quiet_since = None
    settled = quiet_since is not None and steps - quiet_since >= window_steps
    settle_time = steps * dt

    geom_owner = track.owners.geom_owner
    n = len(bodies)
    monitor_pos = data.xipos[bodies].copy()
    monitor_quat = data.xquat[bodies].copy()
    previous = monitor_pos.copy()
    path = np.zeros(n)
    deepest = np.zeros(n)
    for _ in range(round(th.monitor_s / dt)):
        mujoco.mj_step(model, data)
        current = data.xipos[bodies]
        path += np.linalg.norm(current - previous, axis=1)
        previous = current.copy()
        _deepest_contacts(data, geom_owner, deepest)
    return SettleResult(
        data=data,
        start_pos=start_pos,
        start_quat=start_quat,
        start_qpos=start_qpos,
        monitor_pos=monitor_pos,
        monitor_quat=monitor_quat,
        path=path,
        penetration=deepest,
        settle_time=settle_time,
        settled=settled,
        sim_time=data.time,
        wall_time=time.perf_counter() - started,
        warnings=warning_counts(data),
    )


def final_supports(model: mujoco.MjModel, data: mujoco.MjData, owners: GeomOwners) -> list[str]:
    """What each object rests on: the thing below it pushing up hardest, from the contacts of
    ``data`` (after ``mj_forward``). ``floor`` for the ground and structure, ``""`` when
    nothing holds it up."""
    push: dict[tuple[int, str], float] = {}
    force = np.zeros(6)
    for k in range(data.ncon):
        contact = data.contact[k]
        if contact.efc_address < 0:
            continue
        mujoco.mj_contactForce(model, data, k, force)
        normal_z = contact.frame[2]  # the normal points from geom1 to geom2
        g1, g2 = int(contact.geom[0]), int(contact.geom[1])
        for me, other, sign in ((g1, g2, -1.0), (g2, g1, 1.0)):
            owner = int(owners.geom_owner[me])
            if owner < 0 or owners.geom_owner[other] == owner:
                continue
            up = force[0] * normal_z * sign
            if up <= 0.0:
                continue
            label = owners.names[o] if (o := int(owners.geom_owner[other])) >= 0 else FLOOR
            push[(owner, label)] = push.get((owner, label), 0.0) + up
    best: dict[int, tuple[float, str]] = {}
    for (owner, label), value in sorted(push.items()):
        if owner not in best or value > best[owner][0]:
            best[owner] = (value, label)
    return [best[i][1] if i in best else "" for i in range(len(owners.names))]


def quat_angle_deg(q1: np.ndarray, q2: np.ndarray) -> np.ndarray:
    """Rotation angle between unit quaternions, row by row, in degrees."""
    dot = np.clip(np.abs(np.sum(q1 * q2, axis=1)), 0.0, 1.0)
    return np.degrees(2.0 * np.arccos(dot))


def displacement_from_authored(
    start: np.ndarray, end: np.ndarray, settle_drop: float
) -> np.ndarray:
    """Distance of each final centre of mass from its authored one, after the allowed settle:
    up to ``settle_drop`` of sinking is forgiven (a dropped object falling onto its support)."""
    delta = end - start
    sink = np.minimum(delta[:, 2], 0.0)
    delta[:, 2] = np.where(delta[:, 2] < 0.0, np.minimum(sink + settle_drop, 0.0), delta[:, 2])
    return np.linalg.norm(delta, axis=1)


def object_penetrations(owners: GeomOwners, found: AuditResult) -> np.ndarray:
    """Each object's own deepest interpenetrating pair at t = 0 (0 when it has none)."""
    deepest = np.zeros(len(owners.names))
    for overlap in found.overlaps:
        for geom in (overlap.geom1, overlap.geom2):
            owner = int(owners.geom_owner[geom])
            if owner >= 0:
                deepest[owner] = max(deepest[owner], overlap.depth)
    return deepest


def _penetration_partners(owners: GeomOwners, found: AuditResult) -> dict[str, tuple[str, float]]:
    """Per object name: the other party of its deepest pair at t = 0, and the depth."""
    partners: dict[str, tuple[str, float]] = {}
    for pair in found.penetrations:  # deepest first
        for me, other in ((pair.a, pair.b), (pair.b, pair.a)):
            if me in owners.names and me not in partners:
                partners[me] = (other, pair.depth_m)
    return partners


def judge(
    loaded: LoadedScene,
    track: ObjectTrack,
    result: SettleResult,
    th: Thresholds,
    found: AuditResult,
) -> list[ObjectReport]:
    """Turn the raw numbers into one :class:`ObjectReport` per object (``STABILITY_RULE``)."""
    model, data = loaded.model, result.data
    owners = track.owners
    bodies = owners.object_bodies
    end_pos = data.xipos[bodies]
    end_quat = data.xquat[bodies]
    drift = np.linalg.norm(end_pos - result.monitor_pos, axis=1)
    rotation = quat_angle_deg(end_quat, result.monitor_quat)
    displacement = displacement_from_authored(result.start_pos, end_pos, th.settle_drop_m)
    turned = quat_angle_deg(end_quat, result.start_quat)
    drop = result.start_pos[:, 2] - end_pos[:, 2]
    penetration = object_penetrations(owners, found)
    partners = _penetration_partners(owners, found)
    below_floor_at_start = {d.name for d in found.below_floor}
    outside_at_start = {d.name for d in found.outside_rooms}
    lowest = lowest_points(model, data, owners)
    supports = final_supports(model, data, owners)
    at_rest = np.ones(len(bodies), dtype=bool)
    at_rest[track.dynamic] = track.at_rest(data, th)
    scene_objects = {o.id: o for o in loaded.scene.objects} if loaded.scene else {}
    rooms = Rooms(loaded.scene, th.room_margin_m) if loaded.scene else None
    inside = {}
    if rooms is not None:
        for i, name in enumerate(owners.names):
            room = scene_objects[name].room if name in scene_objects else None
            inside[name] = bool(rooms.inside(end_pos[i : i + 1, :2], room)[0])
    motion = _part_motion(model, track.parts, result.start_qpos, data.qpos, len(bodies))
    reports = []
    for i, name in enumerate(owners.names):
        dynamic = bool(track.dynamic[i])
        spec = scene_objects.get(name)
        expected = (spec.support or FLOOR) if spec is not None else None
        support = (supports[i] or None) if dynamic else FIXED
        fell = bool(drop[i] > th.fall_m or lowest[i] < -th.below_floor_m)
        left_room = bool(rooms is not None and not inside[name])
        reasons = []
        # (a) at rest over the monitor window
        if drift[i] >= th.drift_m:
            reasons.append(f"drifted {drift[i] * 1000:.1f} mm during the monitor window")
        if rotation[i] >= th.rotation_deg:
            reasons.append(f"turned {rotation[i]:.1f}° during the monitor window")
        # (b) close to the authored pose
        if displacement[i] >= th.displacement_m:
            reasons.append(f"ended {displacement[i] * 1000:.1f} mm from its authored position")
        if turned[i] >= th.rotation_from_authored_deg:
            reasons.append(f"ended {turned[i]:.1f}° from its authored orientation")
        if fell:
            reasons.append(
                f"fell {drop[i]:.3f} m" if drop[i] > th.fall_m else "fell through the floor"
            )
        # (c) no penetration at t = 0, in its place, on its support
        if penetration[i] > th.tolerance_m:
            other, depth = partners.get(name, ("something", float(penetration[i])))
            reasons.append(f"penetrates {other} by {depth * 1000:.1f} mm at t = 0")
        if name in below_floor_at_start:
            reasons.append("below the floor at t = 0")
        if name in outside_at_start:
            reasons.append("outside every room at t = 0")
        if left_room:
            room = spec.room if spec is not None and spec.room else None
            reasons.append(f"left room {room}" if room else "ended outside every room")
        if dynamic and expected is not None and support != expected:
            reasons.append(f"rests on {support or 'nothing'}, expected {expected}")
        if dynamic and result.warnings:
            reasons.append("MuJoCo warnings: " + ", ".join(sorted(result.warnings)))
        # (d) moving parts where they were authored
        for joint, (value, hinge) in motion[i].items():
            if hinge and value >= th.part_rotation_deg:
                reasons.append(f"{joint} swung {value:.1f}° from its authored angle by itself")
            elif not hinge and value >= th.part_travel_m:
                reasons.append(
                    f"{joint} slid {value * 1000:.1f} mm from its authored position by itself"
                )
        reports.append(
            ObjectReport(
                name=name,
                stable=not reasons,
                dynamic=dynamic,
                displacement_m=_r(displacement[i]),
                rotation_from_authored_deg=_r(turned[i], 4),
                drift_m=_r(drift[i]),
                rotation_deg=_r(rotation[i], 4),
                path_m=_r(result.path[i]),
                drop_m=_r(drop[i]),
                fell=fell,
                left_room=left_room,
                support=support,
                expected_support=expected,
                penetration_m=_r(penetration[i]),
                contact_depth_m=_r(result.penetration[i]),
                at_rest=bool(at_rest[i]),
                part_motion={j: _r(v, 4 if h else 6) for j, (v, h) in motion[i].items()},
                reasons=reasons,
            )
        )
    return reports


def _part_motion(
    model: mujoco.MjModel,
    parts: PartJoints | None,
    start: np.ndarray,
    end: np.ndarray,
    count: int,
) -> list[dict[str, tuple[float, bool]]]:
    """Per object: joint name (without the object's prefix) -> (departure from the authored
    value in degrees or metres, hinge?)."""
    motion: list[dict[str, tuple[float, bool]]] = [{} for _ in range(count)]
    if parts is None or not len(parts):
        return motion
    for owner, joint, value, hinge in zip(
        parts.owner, parts.joint, parts.departures(start, end), parts.hinge, strict=True
    ):
        name = model.joint(int(joint)).name
        name = name.split("/", 1)[1] if "/" in name else name
        motion[int(owner)][name] = (float(value), bool(hinge))
    return motion


def _r(value: float, digits: int = 6) -> float:
    """Rounded for the report (micrometres): stable JSON, no float noise."""
    value = float(value)
    return 0.0 if math.isclose(value, 0.0, abs_tol=10 ** -(digits + 1)) else round(value, digits)


@dataclass
class Validation:
    """A report and the simulation behind it (for baking settled poses back)."""

    report: StabilityReport
    track: ObjectTrack
    result: SettleResult


def validate_loaded(
    loaded: LoadedScene,
    thresholds: Thresholds | None = None,
    furniture: str = "free",
    sleep: bool = False,
) -> StabilityReport:
    """Audit at t = 0, settle, monitor and judge ``loaded``."""
    return run_validation(loaded, thresholds, furniture, sleep).report


def run_validation(
    loaded: LoadedScene,
    thresholds: Thresholds | None = None,
    furniture: str = "free",
    sleep: bool = False,
) -> Validation:
    """:func:`validate_loaded`, keeping the settled simulation state."""
    th = thresholds or Thresholds()
    started = time.perf_counter()
    found = audit(loaded, tolerance=th.tolerance_m, room_margin=th.room_margin_m)
    track = ObjectTrack.of(loaded.model, loaded.objects)
    result = run_settle(loaded.model, track, th, sleep)
    objects = judge(loaded, track, result, th, found)
    wall = time.perf_counter() - started
    return Validation(assemble(loaded, found, result, objects, th, furniture, wall), track, result)


def assemble(
    loaded: LoadedScene,
    found: AuditResult,
    result: SettleResult,
    objects: list[ObjectReport],
    th: Thresholds,
    furniture: str,
    wall: float,
) -> StabilityReport:
    """The scene-level report around the per-object ones."""
    unstable = [o for o in objects if not o.stable]
    counts = {
        "objects": len(objects),
        "dynamic": sum(o.dynamic for o in objects),
        "stable": len(objects) - len(unstable),
        "unstable": len(unstable),
        "static": sum(not o.dynamic for o in objects),
        "moved_from_authored": sum(
            o.displacement_m >= th.displacement_m
            or o.rotation_from_authored_deg >= th.rotation_from_authored_deg
            for o in objects
        ),
        "fell": sum(o.fell for o in objects),
        "left_room": sum(o.left_room for o in objects),
        "wrong_support": sum(
            o.dynamic and o.expected_support is not None and o.support != o.expected_support
            for o in objects
        ),
        "penetrations": len(found.penetrations),
        "below_floor": len(found.below_floor),
        "outside_rooms": len(found.outside_rooms),
    }
    ok = not unstable and found.ok and not result.warnings
    return StabilityReport(
        ok=ok,
        source=str(loaded.source),
        furniture=furniture,
        objects=objects,
        static_objects=[o.name for o in objects if not o.dynamic],
        penetrations=found.penetrations,
        below_floor=found.below_floor,
        outside_rooms=found.outside_rooms,
        max_penetration_m=_r(
            max([o.penetration_m for o in objects] + [p.depth_m for p in found.penetrations])
            if objects or found.penetrations
            else 0.0
        ),
        max_contact_depth_m=_r(max((o.contact_depth_m for o in objects), default=0.0)),
        warnings=result.warnings,
        counts=counts,
        sim_time_s=_r(result.sim_time, 4),
        wall_time_s=round(wall, 3),
        realtime_factor=round(result.sim_time / wall, 2) if wall > 0 else 0.0,
        settle_time_s=_r(result.settle_time, 4),
        settled=result.settled,
        monitor_s=th.monitor_s,
        thresholds=th,
    )
