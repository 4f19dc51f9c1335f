"""A Gymnasium environment on a scene folder: the attached fixed-base arm and one task.

- **Observations** (a ``Dict``): ``joints`` and ``velocities`` of the robot's joints (arm and
  hand), ``target`` and ``goal`` points of the task (:mod:`holomj.envs.targets`).
- **Actions**: one value in [-1, 1] per robot joint: a change of its position target of at most
  ``max_delta_rad`` per step (``action_mode="delta"``), or the target itself mapped onto the
  joint's range (``"position"``). The joints are driven by :class:`~holomj.envs.servo.JointServo`
  (the hand's stiffer, so that its fingers grip) for ``frame_skip`` physics steps per action.
- **Reward**: 1 on success (the task's predicate, held for its ``hold_s``: the episode then
  terminates), minus ``shaping`` times the predicate's distance to success when ``shaping`` > 0.
- **Reset**: ``mj_resetData`` restores the validated scene (``qpos0``: the poses ``objects.json``
  records) on the model compiled once at construction; with ``redrop_m`` > 0 the small objects
  standing in the open are moved by up to that much and turned, from the reset's seed
  (:mod:`holomj.envs.redrop`); then the task's start state (a close task's part opened to its
  ``start``). Episodes are truncated after ``max_episode_steps``.
"""

from __future__ import annotations

from typing import Any

import gymnasium as gym
import mujoco
import numpy as np
from gymnasium import spaces

from holomj.envs.redrop import droppable_objects, redrop
from holomj.envs.servo import DEFAULT_BANDWIDTH, JointServo
from holomj.envs.targets import TaskTargets
from holomj.spec.tasks import ArticulationTask, Task
from holomj.tasks.predicates import JointFraction, SuccessCheck, condition_for

FRAME_SKIP = 10
MAX_DELTA_RAD = 0.05
MAX_EPISODE_STEPS = 500
_BIG = 1e3
HAND = "/hand/"  # the joints of a hand mounted on the arm (holomj.robots.registry)
HAND_BANDWIDTH = 90.0  # rad/s: a stiffer servo for the fingers, so that they grip


class SceneArmEnv(gym.Env[dict[str, Any], np.ndarray]):
    """One task on a compiled scene with its attached robot (see the module docstring)."""

    metadata = {"render_modes": ["rgb_array"], "render_fps": 50}  # noqa: RUF012  # as gymnasium.Env

    def __init__(
        self,
        model: mujoco.MjModel,
        record: dict[str, Any],
        task: Task,
        *,
        frame_skip: int = FRAME_SKIP,
        max_delta_rad: float = MAX_DELTA_RAD,
        action_mode: str = "delta",
        shaping: float = 0.0,
        max_episode_steps: int = MAX_EPISODE_STEPS,
        redrop_m: float = 0.0,
        render_mode: str | None = None,
    ) -> None:
        if action_mode not in ("delta", "position"):
            raise ValueError(f"action_mode must be 'delta' or 'position', not {action_mode!r}")
        self.model = model
        self.data = mujoco.MjData(model)
        self.task = task
        self.record = record
        self.condition = condition_for(task, model, record)
        self.check = SuccessCheck(self.condition, task.hold_s)
        self.targets = TaskTargets(task, model, record, self.condition)
        joints = [j["name"] for j in (record.get("robot") or {}).get("joints", [])]
        hand = np.array([HAND in name for name in joints], dtype=bool)
        bandwidth = np.where(hand, HAND_BANDWIDTH, DEFAULT_BANDWIDTH)
        self.servo = JointServo.for_joints(model, joints, bandwidth)
        self.frame_skip = frame_skip
        self.max_delta = max_delta_rad
        self.action_mode = action_mode
        self.shaping = shaping
        self.max_episode_steps = max_episode_steps
        self.redrop_m = redrop_m
        self.droppable = droppable_objects(model, record) if redrop_m > 0.0 else []
        self.render_mode = render_mode
        self._renderer: mujoco.Renderer | None = None
        self._target = self.servo.home.copy()
        self._steps = 0
        n = len(joints)
        self.action_space = spaces.Box(-1.0, 1.0, shape=(n,), dtype=np.float32)
        self._joint_space = spaces.Box(
            self.servo.low.astype(np.float32) - 0.1,
            self.servo.high.astype(np.float32) + 0.1,
            dtype=np.float32,
        )
        self.observation_space = spaces.Dict(
            {
                "joints": self._joint_space,
                "velocities": spaces.Box(-_BIG, _BIG, shape=(n,), dtype=np.float32),
                "target": spaces.Box(-_BIG, _BIG, shape=(3,), dtype=np.float32),
                "goal": spaces.Box(-_BIG, _BIG, shape=(3,), dtype=np.float32),
            }
        )

    def reset(
        self, *, seed: int | None = None, options: dict[str, Any] | None = None
    ) -> tuple[dict[str, np.ndarray], dict[str, Any]]:
        """Restore the validated scene and the task's start state (no recompiling)."""
        super().reset(seed=seed)
        mujoco.mj_resetData(self.model, self.data)
        if self.droppable:
            redrop(self.data, self.droppable, self.redrop_m, self.np_random)
        self._start_state()
        mujoco.mj_forward(self.model, self.data)
        self.check.reset()
        self._target = self.servo.clip(self.data.qpos[self.servo.qpos_adr].copy())
        self._steps = 0
        return self._observation(), self._info(False)

    def step(
        self, action: np.ndarray
    ) -> tuple[dict[str, np.ndarray], float, bool, bool, dict[str, Any]]:
        """Move the joint targets by ``action``, simulate ``frame_skip`` steps, judge the task."""
        act = np.clip(np.asarray(action, dtype=float), -1.0, 1.0)
        if self.action_mode == "delta":
            self._target = self.servo.clip(self._target + act * self.max_delta)
        else:
            low, high = self.servo.low, self.servo.high
            self._target = low + (act + 1.0) * 0.5 * (high - low)
        for _ in range(self.frame_skip):
            self.servo.apply(self.data, self._target)
            mujoco.mj_step(self.model, self.data)
        success = self.check.update(self.data)  # once per action: hold times count in steps
        self._steps += 1
        reward = float(success)
        if self.shaping > 0.0:
            reward -= self.shaping * float(self.check.last.distance)
        truncated = not success and self._steps >= self.max_episode_steps
        return self._observation(), reward, success, truncated, self._info(success)

    @property
    def target(self) -> np.ndarray:
        """The robot's joint position targets now."""
        return self._target

    def set_joint_targets(self, target: np.ndarray) -> None:
        """Set the robot's joint position targets directly (for scripted policies)."""
        self._target = self.servo.clip(np.asarray(target, dtype=float))

    def render(self) -> np.ndarray | None:
        """An RGB image of the scene from its free camera (``render_mode="rgb_array"``)."""
        if self.render_mode != "rgb_array":
            return None
        if self._renderer is None:
            self._renderer = mujoco.Renderer(self.model, 240, 320)
        self._renderer.update_scene(self.data)
        return self._renderer.render()

    def close(self) -> None:
        """Free the renderer, when one was made."""
        if self._renderer is not None:
            self._renderer.close()
            self._renderer = None

    def _start_state(self) -> None:
        task, condition = self.task, self.condition
        if isinstance(task, ArticulationTask) and task.start is not None:
            assert isinstance(condition, JointFraction)
            value = condition.closed + task.start * (condition.open - condition.closed)
            self.data.qpos[condition.qpos_adr] = value

    def _observation(self) -> dict[str, np.ndarray]:
        target, goal = self.targets.points(self.data)
        space = self._joint_space
        joints = np.clip(self.data.qpos[self.servo.qpos_adr], space.low, space.high)
        return {
            "joints": joints.astype(np.float32),
            "velocities": np.clip(self.data.qvel[self.servo.dof_adr], -_BIG, _BIG).astype(
                np.float32
            ),
            "target": np.clip(target, -_BIG, _BIG).astype(np.float32),
            "goal": np.clip(goal, -_BIG, _BIG).astype(np.float32),
        }

    def _info(self, success: bool) -> dict[str, Any]:
        return {
            "success": success,
            "distance": float(self.check.last.distance),
            "task": self.task.id,
        }
