"""Can the attached robot reach a handle? A kinematic reach check on the compiled scene.

For a handle (its world position and pull direction, as ``objects.json`` lists them), the arm's
end-effector site is brought onto the handle by damped least squares inverse kinematics on the
MuJoCo model (``mj_jacSite``; joint ranges respected), first from where the robot stands and,
when that is out of reach, from base spots in front of the handle: at :data:`STANDOFFS_M` from it
along its horizontal pull direction, also :data:`LATERAL_M` to either side, facing the handle. A
spot where the robot (at its home pose) interpenetrates the scene is skipped. As a secondary goal
(in the null space of the position task) the gripper approaches against the pull direction.

The robot's base is moved in a copy of the model (its static ``robot/base_mount`` body), the
scene is left as it is: this answers "is there a free spot from which the arm reaches the
handle", not "can it be grasped without a collision" (the hand may touch the handle's part).
The result says where the base stood, the residual distance, the approach angle, whether any arm
link (the hand excluded) interpenetrates the scene at the solution, and the joint values.
"""

from __future__ import annotations

import copy
import math
from collections.abc import Sequence
from dataclasses import dataclass, field, replace

import mujoco
import numpy as np

from holomj.errors import InputError
from holomj.physics.bounds import world_aabbs
from holomj.spec.robot import ROBOT_PREFIX

TOLERANCE_M = 0.02
STANDOFFS_M = (0.55, 0.45, 0.65, 0.75)
LATERAL_M = (0.0, 0.2, -0.2)
PENETRATION_M = 0.005  # deeper arm contact at a solution makes the spot a poor one
MAX_STEPS = 300
POLISH_STEPS = 100
DAMPING = 0.05
MAX_STEP_RAD = 0.2
RESTARTS = 4
END_EFFECTOR_NAMES = ("tcp", "pinch", "grip_site", "gripper", "end_effector", "eef", "ee_site")
HAND_PREFIX = "hand/"


@dataclass(frozen=True)
class HandleReach:
    """The outcome of a reach check for one handle (lengths in metres, angles in degrees)."""

    target: tuple[float, float, float]
    site: str
    reached: bool
    residual_m: float
    approach_error_deg: float
    base: tuple[float, float, float]  # x, y, yaw_deg of the robot's base
    moved_base: bool
    arm_penetration_m: float
    qpos: dict[str, float] = field(default_factory=dict)
    spots_tried: int = 0
    label: str = ""

    def to_dict(self) -> dict:
        """JSON-able form."""
        return {
            "label": self.label,
            "target": list(self.target),
            "site": self.site,
            "reached": self.reached,
            "residual_m": round(self.residual_m, 5),
            "approach_error_deg": round(self.approach_error_deg, 2),
            "base": [round(v, 4) for v in self.base],
            "moved_base": self.moved_base,
            "arm_penetration_m": round(self.arm_penetration_m, 5),
            "spots_tried": self.spots_tried,
            "qpos": {k: round(v, 6) for k, v in self.qpos.items()},
        }


def reach_handle(
    model: mujoco.MjModel,
    position: Sequence[float],
    pull: Sequence[float],
    *,
    prefix: str = ROBOT_PREFIX,
    site: str | None = None,
    tolerance: float = TOLERANCE_M,
    move_base: bool = True,
    seed: int = 0,
    label: str = "",
) -> HandleReach:
    """Reach check of the robot under ``prefix`` for the handle at ``position`` with pull
    direction ``pull`` (world frame); see the module docstring. ``model`` is not changed.

    Raises :class:`~holomj.errors.InputError` when the model has no robot under ``prefix``.
    """
    model = copy.copy(model)
    arm = _Arm(model, prefix, site)
    target = np.asarray(position, dtype=float)
    toward = np.asarray(pull, dtype=float)
    rng = np.random.default_rng(seed)
    home_pos = model.body_pos[arm.mount].copy()
    home_quat = model.body_quat[arm.mount].copy()
    spots = [(home_pos, home_quat, False)]
    if move_base:
        spots += [(p, q, True) for p, q in _spots_facing(target, toward, home_pos, arm)]
    best: HandleReach | None = None
    tried = 0
    for pos, quat, moved in spots:
        model.body_pos[arm.mount] = pos
        model.body_quat[arm.mount] = quat
        if moved and arm.penetration(arm.home) > 0.001:
            continue  # the base (at home) would stand in furniture
        tried += 1
        result = arm.solve(target, -toward, tolerance, rng)
        yaw = math.degrees(2 * math.atan2(quat[3], quat[0]))
        reach = HandleReach(
            target=(float(target[0]), float(target[1]), float(target[2])),
            site=model.site(arm.site).name,
            reached=result.residual <= tolerance and result.penetration <= PENETRATION_M,
            residual_m=result.residual,
            approach_error_deg=result.approach_deg,
            base=(float(pos[0]), float(pos[1]), (yaw + 180.0) % 360.0 - 180.0),
            moved_base=moved,
            arm_penetration_m=result.penetration,
            qpos=arm.named(result.q),
            spots_tried=tried,
            label=label,
        )
        if best is None or _better(reach, best):
            best = reach
        if reach.reached:
            break
    assert best is not None
    return replace(best, spots_tried=tried)


def reach_objects_json(
    model: mujoco.MjModel, objects: dict, *, max_height: float | None = None, **options
) -> list[HandleReach]:
    """:func:`reach_handle` for every handle an ``objects.json`` record lists (those below
    ``max_height`` when given), labelled ``<joint name>``."""
    results = []
    for obj in objects.get("objects", []):
        for joint in obj.get("joints", []):
            handle = joint.get("handle")
            if handle is None:
                continue
            if max_height is not None and handle["position"][2] > max_height:
                continue
            results.append(
                reach_handle(
                    model, handle["position"], handle["pull"], label=joint["name"], **options
                )
            )
    return results


def _better(a: HandleReach, b: HandleReach) -> bool:
    """Whether ``a`` is a better outcome than ``b`` (reached, then smaller residual)."""
    return (a.reached, -a.residual_m) > (b.reached, -b.residual_m)


def _spots_facing(
    target: np.ndarray, pull: np.ndarray, home: np.ndarray, arm: _Arm
) -> list[tuple[np.ndarray, np.ndarray]]:
    """Base poses in front of the handle, facing it (nearest standoff first)."""
    flat = np.array([pull[0], pull[1], 0.0])
    if np.linalg.norm(flat) < 0.2:  # a handle pulled up: come from where the robot stands
        flat = np.array([home[0] - target[0], home[1] - target[1], 0.0])
    if np.linalg.norm(flat) < 1e-9:
        flat = np.array([1.0, 0.0, 0.0])
    flat /= np.linalg.norm(flat)
    side = np.array([-flat[1], flat[0], 0.0])
    spots = []
    for standoff in STANDOFFS_M:
        for lateral in LATERAL_M:
            xy = target[:2] + standoff * flat[:2] + lateral * side[:2]
            facing = math.atan2(target[1] - xy[1], target[0] - xy[0]) - arm.front
            quat = np.array([math.cos(facing / 2), 0.0, 0.0, math.sin(facing / 2)])
            spots.append((np.array([xy[0], xy[1], home[2]]), quat))
    return spots


@dataclass(frozen=True)
class _Solution:
    q: np.ndarray
    residual: float
    approach_deg: float
    penetration: float


class _Arm:
    """The robot's joints, end-effector site and colliders in ``model``."""

    def __init__(self, model: mujoco.MjModel, prefix: str, site: str | None) -> None:
        self.model = model
        self.data = mujoco.MjData(model)
        mount = f"{prefix}base_mount"
        body = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, mount)
        if body < 0:
            raise InputError(f"the model has no robot (no body {mount!r})", where="reach check")
        self.mount = body
        inside = np.zeros(model.nbody, dtype=bool)
        inside[body] = True
        for b in range(body + 1, model.nbody):  # parents come before children
            inside[b] = inside[model.body_parentid[b]]
        self.bodies = inside
        self.site = self._site(prefix, site)
        kinds = (int(mujoco.mjtJoint.mjJNT_HINGE), int(mujoco.mjtJoint.mjJNT_SLIDE))
        joints = [
            j
            for j in range(model.njnt)
            if inside[model.jnt_bodyid[j]]
            and int(model.jnt_type[j]) in kinds
            and not model.joint(j).name.startswith(f"{prefix}{HAND_PREFIX}")
        ]
        self.joints = joints
        self.qadr = np.array([model.jnt_qposadr[j] for j in joints], dtype=int)
        self.dofs = np.array([model.jnt_dofadr[j] for j in joints], dtype=int)
        ranges = np.array([model.jnt_range[j] for j in joints], dtype=float).reshape(-1, 2)
        limited = np.array([bool(model.jnt_limited[j]) for j in joints])
        self.low = np.where(limited, ranges[:, 0], -math.pi)
        self.high = np.where(limited, ranges[:, 1], math.pi)
        self.home = model.qpos0[self.qadr].copy()
        hand = np.array(
            [model.body(b).name.startswith(f"{prefix}{HAND_PREFIX}") for b in range(model.nbody)]
        )
        colliding = (model.geom_contype != 0) | (model.geom_conaffinity != 0)
        on_robot = inside[model.geom_bodyid]
        self.arm_geoms = np.flatnonzero(colliding & on_robot & ~hand[model.geom_bodyid])
        not_plane = model.geom_type != mujoco.mjtGeom.mjGEOM_PLANE
        self.scene_geoms = np.flatnonzero(colliding & ~on_robot & not_plane)
        self.front = self._front()

    def _site(self, prefix: str, name: str | None) -> int:
        model = self.model
        if name is not None:
            site = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_SITE, name)
            if site < 0:
                raise InputError(f"no site {name!r} in the model", where="reach check")
            return site
        ours = [s for s in range(model.nsite) if self.bodies[model.site_bodyid[s]]]
        if not ours:
            raise InputError("the robot has no site to use as its end effector", where=prefix)
        for key in END_EFFECTOR_NAMES:
            for s in ours:
                if model.site(s).name.lower().rsplit("/", 1)[-1].startswith(key):
                    return s
        return max(ours, key=lambda s: (_depth(model, int(model.site_bodyid[s])), s))

    def _front(self) -> float:
        """The direction (radians, base frame) the arm reaches at home: towards its site."""
        self.set(self.home)
        rot = self.data.xmat[self.mount].reshape(3, 3)
        local = rot.T @ (self.data.site_xpos[self.site] - self.data.xpos[self.mount])
        return math.atan2(local[1], local[0]) if np.hypot(local[0], local[1]) > 0.05 else 0.0

    def set(self, q: np.ndarray) -> None:
        self.data.qpos[:] = self.model.qpos0
        self.data.qpos[self.qadr] = q
        mujoco.mj_kinematics(self.model, self.data)
        mujoco.mj_comPos(self.model, self.data)

    def named(self, q: np.ndarray) -> dict[str, float]:
        return {self.model.joint(j).name: float(v) for j, v in zip(self.joints, q, strict=True)}

    def solve(
        self, target: np.ndarray, approach: np.ndarray, tolerance: float, rng: np.random.Generator
    ) -> _Solution:
        """The best of a few damped-least-squares runs (from home, then random starts)."""
        best: _Solution | None = None
        for attempt in range(RESTARTS):
            start = self.home if attempt == 0 else rng.uniform(self.low, self.high)
            q = self._descend(start, target, approach)
            self.set(q)
            residual = float(np.linalg.norm(target - self.data.site_xpos[self.site]))
            solution = _Solution(q, residual, self._approach_deg(approach), self.penetration(q))
            if best is None or (
                (
                    solution.residual <= tolerance,
                    solution.penetration <= PENETRATION_M,
                    -solution.residual,
                )
                > (best.residual <= tolerance, best.penetration <= PENETRATION_M, -best.residual)
            ):
                best = solution
            if best.residual <= tolerance and best.penetration <= PENETRATION_M:
                break
        assert best is not None
        return best

    def _descend(self, start: np.ndarray, target: np.ndarray, approach: np.ndarray) -> np.ndarray:
        """Damped least squares from ``start``: the position with the approach as a secondary
        goal, then a polish of the position alone."""
        q = self._steps(start, target, approach, MAX_STEPS)
        return self._steps(q, target, None, POLISH_STEPS)

    def _steps(
        self, start: np.ndarray, target: np.ndarray, approach: np.ndarray | None, count: int
    ) -> np.ndarray:
        model, data = self.model, self.data
        q = np.clip(np.asarray(start, dtype=float), self.low, self.high)
        jacp = np.zeros((3, model.nv))
        jacr = np.zeros((3, model.nv))
        for _ in range(count):
            self.set(q)
            error = target - data.site_xpos[self.site]
            if np.linalg.norm(error) < 1e-4:
                break
            mujoco.mj_jacSite(model, data, jacp, jacr, self.site)
            jp, jr = jacp[:, self.dofs], jacr[:, self.dofs]
            inverse = jp.T @ np.linalg.inv(jp @ jp.T + DAMPING**2 * np.eye(3))
            step = inverse @ error
            if approach is not None:  # turn the site's z axis towards ``approach``, in the
                # null space of the position task
                z = data.site_xmat[self.site].reshape(3, 3)[:, 2]
                turn = np.cross(z, approach / max(float(np.linalg.norm(approach)), 1e-12))
                null = np.eye(len(q)) - inverse @ jp
                step += null @ (0.5 * jr.T @ np.linalg.solve(jr @ jr.T + 0.1 * np.eye(3), turn))
            largest = float(np.max(np.abs(step)))
            if largest > MAX_STEP_RAD:
                step *= MAX_STEP_RAD / largest
            q = np.clip(q + step, self.low, self.high)
        return q

    def _approach_deg(self, approach: np.ndarray) -> float:
        z = self.data.site_xmat[self.site].reshape(3, 3)[:, 2]
        unit = approach / max(float(np.linalg.norm(approach)), 1e-12)
        return math.degrees(math.acos(float(np.clip(z @ unit, -1.0, 1.0))))

    def penetration(self, q: np.ndarray) -> float:
        """The deepest interpenetration of an arm collider (hand excluded) with the scene."""
        model, data = self.model, self.data
        self.set(q)
        low, high = world_aabbs(model, data)
        deepest = 0.0
        fromto = np.zeros(6)
        others = self.scene_geoms
        for g in self.arm_geoms:
            near = others[
                np.all(low[others] <= high[g] + 0.01, axis=1)
                & np.all(low[g] <= high[others] + 0.01, axis=1)
            ]
            for other in near:
                distance = mujoco.mj_geomDistance(model, data, int(g), int(other), 0.01, fromto)
                deepest = max(deepest, -distance)
        return deepest


def _depth(model: mujoco.MjModel, body: int) -> int:
    depth = 0
    while body > 0:
        body = int(model.body_parentid[body])
        depth += 1
    return depth
