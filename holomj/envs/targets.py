"""What an environment shows of its task: a target point and a goal point, world frame.

- open/close: the handle's position, and (openness, fraction, 0);
- pick-and-place and rearrange: the (first unplaced) object's position, and the centre of its
  goal surface;
- navigate: the object's position or the room's centroid, and the base's position.
"""

from __future__ import annotations

from typing import Any

import mujoco
import numpy as np

from holomj.spec.tasks import ArticulationTask, NavigateTask, Task
from holomj.tasks.predicates import AllOf, Condition, JointFraction, RestingOn, world_polygon
from holomj.tasks.scene_objects import SceneObjects, body_id


class TaskTargets:
    """The target and goal points of one task on one model."""

    def __init__(
        self, task: Task, model: mujoco.MjModel, record: dict[str, Any], condition: Condition
    ):
        self.condition = condition
        scene = SceneObjects(record)
        self.site = -1
        self.body = -1
        self.fixed = np.zeros(3)
        if isinstance(task, ArticulationTask):
            handle = scene.joint(task.object, task.joint).get("handle")
            if handle is not None:
                self.site = model.site(handle["site"]).id
            else:
                self.body = body_id(model, scene.joint(task.object, task.joint)["body"])
        elif isinstance(task, NavigateTask):
            self.base = body_id(model, scene.robot_base())
            if task.object is not None:
                self.body = body_id(model, scene.object(task.object)["body"])
            elif task.room is not None:
                polygon = np.asarray(scene.room(task.room)["polygon"], dtype=float)
                self.fixed = np.array([*polygon.mean(axis=0), 0.0])

    def points(self, data: mujoco.MjData) -> tuple[np.ndarray, np.ndarray]:
        """The (target, goal) points on ``data``."""
        condition = self.condition
        if isinstance(condition, JointFraction):
            where = data.site_xpos[self.site] if self.site >= 0 else data.xpos[self.body]
            goal = np.array([condition.openness(data), condition.fraction, 0.0])
            return where.copy(), goal
        if isinstance(condition, AllOf):
            parts = [p for p in condition.parts if isinstance(p, RestingOn)]
            open_parts = [p for p in parts if not p.status(data).holds]
            condition = (open_parts or parts)[0]
        if isinstance(condition, RestingOn):
            polygon = world_polygon(data, condition.surfaces[0])
            return data.xpos[condition.object].copy(), polygon.mean(axis=0)
        target = data.xpos[self.body].copy() if self.body >= 0 else self.fixed.copy()
        return target, data.xpos[self.base].copy()
