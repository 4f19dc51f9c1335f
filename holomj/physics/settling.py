"""Settling a compiled scene: step it from its initial pose until every free body (and every
moving part of an articulated object) has been at rest for a while, or a time cap, then monitor
a window and measure each object's drift, rotation, path and deepest contact, and what it rests
on at the end. :mod:`holomj.physics.settle` judges the numbers.
"""

from __future__ import annotations

import time
from dataclasses import dataclass

import mujoco
import numpy as np

from holomj.physics.audit import GeomOwners
from holomj.physics.smoke import warning_counts
from holomj.spec.report import Thresholds

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
