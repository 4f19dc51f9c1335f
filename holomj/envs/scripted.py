"""A scripted policy that opens a drawer or a door with the project's inverse kinematics.

:func:`open_part` takes an environment whose task opens a part with a handle: it moves the robot's
base (a static body: no recompiling) to the free spot in front of the handle that
:func:`holomj.robots.reach_handle.reach_handle` finds, drives the arm to joint targets solved by
the same inverse kinematics (in front of the handle, then onto it), closes the fingers, and pulls
along the handle's path (straight out for a drawer, on its circle about the hinge for a door) in
small Cartesian steps (damped least squares on the site's Jacobian from the current joints, so
the arm never jumps to another solution), until the task's predicate reports success.

:func:`close_part` does the reverse for a close task (the part starts open, at the task's
``start``): the base faces the handle between its closed and its start place, the hand grips the
handle where it is now and pushes it back along the same path until the part is closed.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import mujoco
import numpy as np

from holomj.envs.arm_env import HAND, SceneArmEnv
from holomj.errors import InputError
from holomj.robots.reach_handle import HandleReach, reach_handle
from holomj.spec.tasks import ArticulationTask
from holomj.tasks.scene_objects import SceneObjects, body_id

APPROACH_M = 0.10  # the pre-grasp point, this far out along the pull direction
PULL_M = 0.40  # how far the hand pulls at most
CLOSE_OVERSHOOT_M = 0.08  # a drawer is pushed toward this far past closed (a firmer push)
CLOSE_BASE_BLEND = 0.7  # the base faces the handle this far from its closed toward its start place
PULL_STEP_M = 0.004  # per environment step
FINGERS_CLOSED = 1.35  # rad, Jaco-like three-finger hands (clipped to each finger's range)
SETTLE_STEPS = 40  # environment steps per waypoint
DAMPING = 0.05


@dataclass(frozen=True)
class ScriptResult:
    """What a scripted episode did: success, environment steps, the base spot it used."""

    success: bool
    steps: int
    base: tuple[float, float, float]
    reached: bool


def open_part(env: SceneArmEnv, seed: int = 0) -> ScriptResult:
    """Run one scripted episode of ``env``'s open task: a drawer (slide joint) or a door or
    lid (hinge joint) with a handle."""
    record, handle = _handle_record(env, "open")
    pull = np.asarray(handle["pull"], dtype=float)
    spot = _place_base(env, handle["position"], handle["pull"], seed)
    grip = _grip(env, np.asarray(handle["position"], dtype=float), pull, seed)
    if grip.over:
        return ScriptResult(grip.success, grip.steps, spot.base, spot.reached)
    site = _site(env, spot.site)
    start = env.data.site_xpos[site].copy()
    span = PULL_M if record["type"] == "slide" else _range_span(record)
    path = _handle_path(record, start, pull, span)
    return _finish(env, site, path, grip.steps, spot)


def close_part(env: SceneArmEnv, seed: int = 0) -> ScriptResult:
    """Run one scripted episode of ``env``'s close task: the part starts open (the task's
    ``start``); the hand grips the handle where it is now and pushes it back along its path
    (straight in for a drawer, on its circle about the hinge for a door) until the task's
    predicate reports success."""
    record, handle = _handle_record(env, "close")
    env.reset(seed=seed)
    position, pull = _handle_now(env, record, handle)
    middle = CLOSE_BASE_BLEND * position + (1.0 - CLOSE_BASE_BLEND) * np.asarray(
        handle["position"], dtype=float
    )
    facing = pull + np.asarray(handle["pull"], dtype=float)
    spot = _place_base(env, middle.tolist(), (facing / np.linalg.norm(facing)).tolist(), seed)
    grip = _grip(env, position, pull, seed)
    if grip.over:
        return ScriptResult(grip.success, grip.steps, spot.base, spot.reached)
    site = _site(env, spot.site)
    start = env.data.site_xpos[site].copy()
    joint = env.model.joint(record["name"])
    opened = abs(float(env.data.qpos[joint.qposadr[0]]) - float(record["closed"]))
    overshoot = CLOSE_OVERSHOOT_M if record["type"] == "slide" else 0.0
    path = _handle_path(record, start, -pull, opened + overshoot)
    return _finish(env, site, path, grip.steps, spot)


def _handle_record(env: SceneArmEnv, kind: str) -> tuple[dict[str, Any], dict[str, Any]]:
    """The ``objects.json`` record of the task's joint and of its handle (a ``kind`` task)."""
    task = env.task
    if not isinstance(task, ArticulationTask) or task.kind != kind:
        article = "an" if kind == "open" else "a"
        raise InputError(
            f"task {task.id!r} is not {article} {kind} task",
            fix=f"pass {article} {kind} task's env",
        )
    record = SceneObjects(env.record).joint(task.object, task.joint)
    handle = record.get("handle")
    if handle is None:
        raise InputError(f"joint {task.joint!r} has no handle", fix="script a part with a handle")
    return record, handle


def _place_base(
    env: SceneArmEnv, position: Sequence[float], pull: Sequence[float], seed: int
) -> HandleReach:
    """Move the robot's mount to the free spot in front of a handle at ``position`` (pulled
    along ``pull``) and reset ``env``."""
    task = env.task
    label = task.joint if isinstance(task, ArticulationTask) else ""
    spot = reach_handle(env.model, position, pull, seed=seed, label=label)
    _move_base(env, spot.base)
    env.reset(seed=seed)
    return spot


def _handle_now(
    env: SceneArmEnv, record: dict[str, Any], handle: dict[str, Any]
) -> tuple[np.ndarray, np.ndarray]:
    """The handle's position and pull direction in the current state: the recorded ones (at
    the model's initial pose) carried along with the part's joint."""
    site = _site(env, handle["site"])
    initial = mujoco.MjData(env.model)
    mujoco.mj_kinematics(env.model, initial)
    turn = env.data.site_xmat[site].reshape(3, 3) @ initial.site_xmat[site].reshape(3, 3).T
    pull = turn @ np.asarray(handle["pull"], dtype=float)
    return env.data.site_xpos[site].copy(), pull / np.linalg.norm(pull)


def _grip(env: SceneArmEnv, position: np.ndarray, pull: np.ndarray, seed: int) -> _Held:
    """Drive the arm in front of the handle at ``position``, onto it, and close the fingers."""
    steps = 0
    for point, closed in (
        (position + APPROACH_M * pull, False),
        (position, False),
        (position, True),
    ):
        solution = reach_handle(
            env.model, point.tolist(), pull.tolist(), move_base=False, seed=seed
        )
        env.set_joint_targets(_targets(env, solution.qpos, closed))
        done = _hold(env, SETTLE_STEPS)
        steps += done.steps
        if done.over:
            return _Held(steps, done.success, True)
    return _Held(steps, False, False)


def _finish(
    env: SceneArmEnv, site: int, path: list[np.ndarray], steps: int, spot: HandleReach
) -> ScriptResult:
    """Move ``site`` along ``path`` a step at a time, then keep it at the path's end while the
    task's condition must hold; the episode's result."""
    hold = max(SETTLE_STEPS, _hold_steps(env))
    for goal in path + path[-1:] * hold:
        env.set_joint_targets(_toward(env, site, goal))
        done = _hold(env, 1)
        steps += done.steps
        if done.over:
            return ScriptResult(done.success, steps, spot.base, spot.reached)
    done = _hold(env, 0 if path else hold)
    return ScriptResult(done.success, steps + done.steps, spot.base, spot.reached)


def _hold_steps(env: SceneArmEnv) -> int:
    """Environment steps covering the task's ``hold_s`` (and a half second more)."""
    hold_s = env.task.hold_s if isinstance(env.task, ArticulationTask) else 0.0
    return math.ceil((hold_s + 0.5) / (env.model.opt.timestep * env.frame_skip))


def _site(env: SceneArmEnv, name: str) -> int:
    return mujoco.mj_name2id(env.model, mujoco.mjtObj.mjOBJ_SITE, name)


def _range_span(record: dict[str, Any]) -> float:
    """How far the joint turns from closed to the far end of its range."""
    low, high = (float(v) for v in record["range"])
    return max(abs(high - record["closed"]), abs(low - record["closed"]))


def _handle_path(
    record: dict[str, Any], start: np.ndarray, direction: np.ndarray, span: float
) -> list[np.ndarray]:
    """Where the hand goes, step by step, to move the part: straight along ``direction`` for a
    slide, ``span`` metres; on the handle's circle about the hinge's axis for a hinge, the
    way that starts along ``direction``, turning ``span`` radians."""
    if record["type"] == "slide":
        count = max(1, round(span / PULL_STEP_M))
        return [start + (k + 1) * PULL_STEP_M * direction for k in range(count)]
    axis = np.asarray(record["axis"], dtype=float)
    anchor = np.asarray(record["anchor"], dtype=float)
    arm = start - anchor
    radial = arm - axis * float(axis @ arm)
    radius = float(np.linalg.norm(radial))
    if radius < 0.05:
        return []
    sign = 1.0 if float(np.cross(axis, radial) @ direction) >= 0.0 else -1.0
    steps = max(1, round(span * radius / PULL_STEP_M))
    return [
        anchor + axis * float(axis @ arm) + _rotate(radial, axis, sign * span * (k + 1) / steps)
        for k in range(steps)
    ]


def _rotate(vector: np.ndarray, axis: np.ndarray, angle: float) -> np.ndarray:
    """``vector`` (perpendicular to the unit ``axis``) turned by ``angle`` about it."""
    return vector * math.cos(angle) + np.cross(axis, vector) * math.sin(angle)


@dataclass(frozen=True)
class _Held:
    steps: int
    success: bool
    over: bool


def _hold(env: SceneArmEnv, steps: int) -> _Held:
    """Step ``env`` with the targets as they are; stop when the episode ends."""
    for step in range(1, steps + 1):
        _, _, terminated, truncated, _ = env.step(np.zeros(len(env.servo.qpos_adr)))
        if terminated or truncated:
            return _Held(step, terminated, True)
    return _Held(steps, False, False)


def _toward(env: SceneArmEnv, site: int, goal: np.ndarray) -> np.ndarray:
    """Joint targets moving ``site`` toward ``goal``: one damped least-squares step on the
    arm's joints (the hand's stay as they are)."""
    model, data = env.model, env.data
    jac = np.zeros((3, model.nv))
    mujoco.mj_jacSite(model, data, jac, None, site)
    arm = np.array([not _is_hand(model, adr) for adr in env.servo.qpos_adr])
    columns = jac[:, env.servo.dof_adr[arm]]
    error = goal - data.site_xpos[site]
    step = columns.T @ np.linalg.solve(columns @ columns.T + DAMPING**2 * np.eye(3), error)
    target = env.servo.clip(env.target.copy())
    target[arm] = data.qpos[env.servo.qpos_adr[arm]] + step
    return target


def _is_hand(model: mujoco.MjModel, qpos_adr: int) -> bool:
    joint = int(np.flatnonzero(model.jnt_qposadr == qpos_adr)[0])
    return HAND in model.joint(joint).name


def _move_base(env: SceneArmEnv, base: tuple[float, float, float]) -> None:
    """Put the robot's static mount at (x, y, yaw in degrees) in the environment's model."""
    mount = body_id(env.model, SceneObjects(env.record).robot_base())
    x, y, yaw = base
    env.model.body_pos[mount][:2] = (x, y)
    half = math.radians(yaw) / 2.0
    env.model.body_quat[mount] = (math.cos(half), 0.0, 0.0, math.sin(half))
    mujoco.mj_setConst(env.model, env.data)


def _targets(env: SceneArmEnv, arm: dict[str, float], closed: bool) -> np.ndarray:
    """Joint targets for every servoed joint: the arm's solution, the fingers open or closed."""
    model = env.model
    target = env.servo.home.copy()
    for index, adr in enumerate(env.servo.qpos_adr):
        joint = int(np.flatnonzero(model.jnt_qposadr == adr)[0])
        name = model.joint(joint).name
        if name in arm:
            target[index] = arm[name]
        elif closed:
            target[index] = FINGERS_CLOSED
    return target
