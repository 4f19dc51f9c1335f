"""Success of a task as a predicate on MuJoCo state (:mod:`holomj.spec.tasks`).

A condition reads only ``mujoco.MjModel`` / ``mujoco.MjData`` and the scene's ``objects.json``
record; :class:`SuccessCheck` adds the time it must hold (``hold_s``, measured on
``data.time``), so any policy in any framework can be judged by stepping it beside the rollout::

    check = success_check(task, model, objects_record)
    for step in rollout:
        ...
        if check.update(data):
            break  # success

Conditions (each also gives a distance to success, 0 when it holds, for shaped rewards):

- open/close: ``(q - closed) / (open limit - closed)`` at least (open) or at most (close)
  ``fraction``, the open limit being the end of the joint's range farther from its closed value;
- pick-and-place: a contact between the object and the receptacle at the surface's height
  (within ``height_tol_m``), the object's centre inside the surface's footprint, the object's
  speed below ``max_speed_m_s``; surfaces are moved with their body from the model's initial
  pose (``qpos0``, where ``objects.json`` recorded them) to the current one;
- navigate: the base's centre within ``radius_m`` of the object's centre and its x axis within
  ``facing_deg`` of the direction to it, or the base inside the room's polygon.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import mujoco
import numpy as np

from holomj.errors import InputError
from holomj.spec.tasks import (
    ArticulationTask,
    NavigateTask,
    PickPlaceTask,
    PlaceGoal,
    RearrangeTask,
    Task,
)
from holomj.tasks.scene_objects import (
    SceneObjects,
    body_id,
    polygon_distance,
    subtree,
)


@dataclass(frozen=True)
class Status:
    """Whether a task's condition holds now, and how far the state is from it."""

    holds: bool
    distance: float


class Condition:
    """A task's instantaneous condition on the state."""

    def status(self, data: mujoco.MjData) -> Status:
        """The condition on ``data`` (positions, contacts and velocities as last computed)."""
        raise NotImplementedError


class JointFraction(Condition):
    """An articulated part past (open) or within (close) a fraction of its range."""

    def __init__(self, task: ArticulationTask, model: mujoco.MjModel, scene: SceneObjects):
        record = scene.joint(task.object, task.joint)
        joint = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, record["name"])
        if joint < 0:
            raise _mismatch(f"joint {record['name']!r}")
        self.qpos_adr = int(model.jnt_qposadr[joint])
        self.closed = float(record["closed"])
        low, high = (float(v) for v in record["range"])
        self.open = high if abs(high - self.closed) >= abs(low - self.closed) else low
        self.opening = task.kind == "open"
        self.fraction = task.fraction

    def openness(self, data: mujoco.MjData) -> float:
        """How open the part is: 0 closed, 1 at the open end of its range."""
        span = self.open - self.closed
        if abs(span) < 1e-9:
            return 0.0
        return (float(data.qpos[self.qpos_adr]) - self.closed) / span

    def status(self, data: mujoco.MjData) -> Status:
        value = self.openness(data)
        gap = self.fraction - value if self.opening else value - self.fraction
        return Status(holds=gap <= 0.0, distance=max(0.0, gap))


@dataclass(frozen=True)
class TaskSurface:
    """A receptacle surface fixed to a body (it moves with it)."""

    body: int
    local: np.ndarray  # polygon vertices (n, 3) in the body's frame at qpos0


class RestingOn(Condition):
    """An object resting on one of a receptacle's surfaces, inside its footprint, slow."""

    def __init__(
        self,
        goal: PlaceGoal,
        model: mujoco.MjModel,
        scene: SceneObjects,
        height_tol_m: float,
        max_speed_m_s: float,
    ):
        item = scene.object(goal.object)
        receptacle = scene.object(goal.receptacle)
        self.object = body_id(model, item["body"])
        self.object_bodies = subtree(model, self.object)
        self.receptacle_bodies = subtree(model, body_id(model, receptacle["body"]))
        self.surfaces = _surfaces(model, receptacle, goal)
        self.height_tol = height_tol_m
        self.max_speed = max_speed_m_s
        self._model = model
        self._velocity = np.zeros(6)
        self._is_object = np.zeros(model.nbody, dtype=bool)
        self._is_object[list(self.object_bodies)] = True
        self._is_receptacle = np.zeros(model.nbody, dtype=bool)
        self._is_receptacle[list(self.receptacle_bodies)] = True

    def status(self, data: mujoco.MjData) -> Status:
        centre = data.xpos[self.object]
        contacts = self._contact_heights(data)
        best = math.inf
        for surface in self.surfaces:
            world = world_polygon(data, surface)
            height = float(world[:, 2].mean())
            outside = polygon_distance(float(centre[0]), float(centre[1]), world[:, :2].tolist())
            touching = [z for z in contacts if abs(z - height) <= self.height_tol]
            if not outside and touching and self._slow(data):
                return Status(True, 0.0)
            best = min(best, math.hypot(outside, max(0.0, abs(float(centre[2]) - height))))
        return Status(False, best)

    def _contact_heights(self, data: mujoco.MjData) -> list[float]:
        count = int(data.ncon)
        if count == 0:
            return []
        contacts = data.contact
        bodies = self._model.geom_bodyid[contacts.geom[:count]]  # (count, 2)
        item, receptacle = self._is_object[bodies], self._is_receptacle[bodies]
        between = (item[:, 0] & receptacle[:, 1]) | (item[:, 1] & receptacle[:, 0])
        return [float(z) for z in contacts.pos[:count][between, 2]]

    def _slow(self, data: mujoco.MjData) -> bool:
        mujoco.mj_objectVelocity(
            self._model, data, mujoco.mjtObj.mjOBJ_BODY, self.object, self._velocity, 0
        )
        return float(np.linalg.norm(self._velocity[3:])) <= self.max_speed


class AllOf(Condition):
    """Every condition at once (rearrange); the distance is their sum."""

    def __init__(self, parts: list[Condition]):
        self.parts = parts

    def status(self, data: mujoco.MjData) -> Status:
        statuses = [p.status(data) for p in self.parts]
        return Status(all(s.holds for s in statuses), sum(s.distance for s in statuses))


class BaseAt(Condition):
    """The robot's base near an object and facing it, or inside a room."""

    def __init__(self, task: NavigateTask, model: mujoco.MjModel, scene: SceneObjects):
        self.base = body_id(model, scene.robot_base())
        self.target = -1
        self.polygon: list[list[float]] = []
        if task.object is not None:
            self.target = body_id(model, scene.object(task.object)["body"])
        elif task.room is not None:
            self.polygon = scene.room(task.room)["polygon"]
        self.radius = task.radius_m
        self.facing = math.radians(task.facing_deg)

    def status(self, data: mujoco.MjData) -> Status:
        x, y = float(data.xpos[self.base][0]), float(data.xpos[self.base][1])
        if self.target < 0:
            gap = polygon_distance(x, y, self.polygon)
            return Status(gap <= 0.0, gap)
        to = data.xpos[self.target][:2] - data.xpos[self.base][:2]
        far = max(0.0, float(np.linalg.norm(to)) - self.radius)
        heading = data.xmat[self.base].reshape(3, 3)[:2, 0]
        turn = abs(math.atan2(heading[0] * to[1] - heading[1] * to[0], float(heading @ to)))
        off = max(0.0, turn - self.facing)
        return Status(far <= 0.0 and off <= 0.0, far + 0.1 * off)


class SuccessCheck:
    """A task's condition that must hold for ``hold_s`` of simulated time in a row."""

    def __init__(self, condition: Condition, hold_s: float):
        self.condition = condition
        self.hold_s = hold_s
        self.since: float | None = None
        self.last = Status(False, math.inf)

    def reset(self) -> None:
        """Forget how long the condition has held (a new episode)."""
        self.since = None
        self.last = Status(False, math.inf)

    def update(self, data: mujoco.MjData) -> bool:
        """Read the condition on ``data``; whether it has now held for ``hold_s``."""
        self.last = self.condition.status(data)
        if not self.last.holds:
            self.since = None
            return False
        if self.since is None:
            self.since = float(data.time)
        return float(data.time) - self.since >= self.hold_s - 1e-9


def condition_for(task: Task, model: mujoco.MjModel, record: dict[str, Any]) -> Condition:
    """The instantaneous condition of ``task`` on ``model``'s state (``record``: the
    scene's ``objects.json``); an unknown object, joint or room is an InputError."""
    scene = SceneObjects(record)
    if isinstance(task, ArticulationTask):
        return JointFraction(task, model, scene)
    if isinstance(task, PickPlaceTask):
        return RestingOn(task.goal, model, scene, task.height_tol_m, task.max_speed_m_s)
    if isinstance(task, RearrangeTask):
        return AllOf(
            [RestingOn(g, model, scene, task.height_tol_m, task.max_speed_m_s) for g in task.goals]
        )
    return BaseAt(task, model, scene)


def success_check(task: Task, model: mujoco.MjModel, record: dict[str, Any]) -> SuccessCheck:
    """:func:`condition_for` with the task's hold time."""
    return SuccessCheck(condition_for(task, model, record), task.hold_s)


def _surfaces(
    model: mujoco.MjModel, receptacle: dict[str, Any], goal: PlaceGoal
) -> list[TaskSurface]:
    """The goal's candidate surfaces, in their body's frame at the model's initial pose."""
    key = "interior_surfaces" if goal.interior else "surfaces"
    records = receptacle.get(key, [])
    if goal.surface is not None:
        records = [s for s in records if s["index"] == goal.surface]
    if not records:
        raise InputError(
            f"object {receptacle['id']!r} has no {key.replace('_', ' ')}"
            + (f" with index {goal.surface}" if goal.surface is not None else ""),
            fix="pick a receptacle and surface index listed in objects.json",
        )
    initial = mujoco.MjData(model)
    mujoco.mj_kinematics(model, initial)
    surfaces = []
    for record in records:
        body = body_id(model, record.get("body") or receptacle["body"])
        world = np.array([[x, y, record["height"]] for x, y in record["polygon"]], dtype=float)
        rot = initial.xmat[body].reshape(3, 3)
        surfaces.append(TaskSurface(body, (world - initial.xpos[body]) @ rot))
    return surfaces


def world_polygon(data: mujoco.MjData, surface: TaskSurface) -> np.ndarray:
    """A surface's polygon vertices (n, 3) in the world at ``data``'s pose."""
    rot = data.xmat[surface.body].reshape(3, 3)
    return np.asarray(surface.local @ rot.T + data.xpos[surface.body])


def _mismatch(what: str) -> Exception:
    return InputError(f"the model has no {what}", fix="check that objects.json is the scene's own")
