"""What rendering works on: a scene and its model in memory, in its resting state.

The model is the scene's compiled MuJoCo model (for an output folder, its exported
``scene.xml``), posed by the ``settled`` keyframe's joint positions when it has one (``holomj
validate --repair`` writes it; :func:`settled_qpos`), else in its initial pose. Views are drawn
with a free camera aimed at each :class:`~holomj.rendering.cameras.CameraPose`
(:meth:`RenderScene.aim`), so the model needs no cameras of its own. Reading a folder happens in
the jobs layer (:mod:`holomj.jobs.render`).
"""

from __future__ import annotations

import copy
import math
from dataclasses import dataclass
from functools import cached_property

import mujoco
import numpy as np
from shapely.geometry import MultiPoint, Polygon

from holomj.mjcf import names
from holomj.rendering.cameras import CameraPose, Mass
from holomj.spec.scene import SceneSpec

SETTLED_KEY = "settled"
VISIBLE_GROUPS = (0, 2)  # structure and visual geoms; 1 is ceilings, 3 colliders
VERTICAL = 0.999  # |cos| of a view direction this close to vertical: +Y up in the image


def settled_qpos(model: mujoco.MjModel) -> np.ndarray | None:
    """The joint positions of ``model``'s ``settled`` keyframe (None when it has none)."""
    key = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_KEY, SETTLED_KEY)
    return model.key_qpos[key].copy() if key >= 0 else None


@dataclass
class RenderScene:
    """A scene and a private copy of its model, posed; the views are drawn from it."""

    scene: SceneSpec
    model: mujoco.MjModel
    data: mujoco.MjData

    def body(self, object_id: str) -> int:
        """The body id of a scene object (-1 when the model lacks it)."""
        return mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_BODY, names.object_body(object_id))

    def aim(self, pose: CameraPose) -> mujoco.MjvCamera:
        """A free camera at ``pose`` (looking at its target; orthographic ones straight down,
        +Y up in the image), with the model's field of view set to the pose's."""
        position = np.asarray(pose.position, dtype=float)
        target = np.asarray(pose.target, dtype=float)
        offset = target - position
        distance = float(np.linalg.norm(offset))
        camera = mujoco.MjvCamera()
        camera.type = mujoco.mjtCamera.mjCAMERA_FREE
        camera.lookat[:] = target
        camera.distance = distance
        if pose.orthographic:
            camera.azimuth, camera.elevation = 90.0, -90.0
        else:
            forward = offset / distance
            # like look_at_quat: looking (nearly) straight down or up, +Y is up in the image
            vertical = abs(float(forward[2])) > VERTICAL
            camera.azimuth = 90.0 if vertical else math.degrees(math.atan2(forward[1], forward[0]))
            camera.elevation = math.degrees(math.asin(float(np.clip(forward[2], -1.0, 1.0))))
        camera.orthographic = int(pose.orthographic)
        # a free camera takes its field of view and projection from the model's visual options
        self.model.vis.global_.fovy = pose.fovy
        self.model.vis.global_.orthographic = int(pose.orthographic)
        return camera

    @cached_property
    def _geoms_by_body(self) -> dict[int, list[int]]:
        table: dict[int, list[int]] = {}
        for geom, body in enumerate(self.model.geom_bodyid):
            table.setdefault(int(body), []).append(geom)
        return table

    def object_points(self, object_id: str) -> np.ndarray:
        """World corners (n x 3) of the bounding boxes of an object's visible geoms."""
        body = self.body(object_id)
        if body < 0:
            return np.zeros((0, 3))
        geoms = self._geoms_by_body.get(body, [])
        shown = [g for g in geoms if self.model.geom_group[g] in VISIBLE_GROUPS] or geoms
        corners = []
        signs = np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)])
        for g in shown:
            centre, half = self.model.geom_aabb[g, :3], self.model.geom_aabb[g, 3:]
            local = centre + signs * half
            rotation = self.data.geom_xmat[g].reshape(3, 3)
            corners.append(local @ rotation.T + self.data.geom_xpos[g])
        return np.concatenate(corners) if corners else np.zeros((0, 3))

    def footprint(self, object_id: str) -> Polygon | None:
        """The smallest rotated rectangle around an object on the floor plan."""
        points = self.object_points(object_id)
        if len(points) == 0:
            return None
        shape = MultiPoint([tuple(p) for p in points[:, :2]]).minimum_rotated_rectangle
        return shape if isinstance(shape, Polygon) else shape.buffer(0.01)

    def mass(self, object_id: str) -> Mass | None:
        """Centre of mass and mass of an object."""
        body = self.body(object_id)
        if body < 0:
            return None
        position = tuple(float(v) for v in self.data.xipos[body])
        return Mass((position[0], position[1], position[2]), float(self.model.body_mass[body]))

    def yaw_deg(self, object_id: str) -> float:
        """The direction an object's front (+X) faces, degrees about +Z."""
        body = self.body(object_id)
        if body < 0:
            return 0.0
        x_axis = self.data.xmat[body].reshape(3, 3)[:, 0]
        return float(np.degrees(np.arctan2(x_axis[1], x_axis[0])))


def prepare_scene(
    model: mujoco.MjModel,
    scene: SceneSpec,
    width: int,
    height: int,
    *,
    qpos: np.ndarray | None = None,
) -> RenderScene:
    """``scene`` with a copy of ``model`` (left untouched) in the pose ``qpos`` (default: the
    model's initial pose), ready to render images of ``width`` x ``height`` pixels."""
    model = copy.deepcopy(model)
    model.vis.global_.offwidth = max(int(model.vis.global_.offwidth), width)
    model.vis.global_.offheight = max(int(model.vis.global_.offheight), height)
    data = mujoco.MjData(model)
    if qpos is not None:
        data.qpos[:] = qpos
    mujoco.mj_forward(model, data)
    return RenderScene(scene, model, data)
