"""What rendering reads from an output folder: the scene, and the model of its ``scene.xml``
with one placeholder camera per view (posed after the model is in its resting state).

The model is the exported ``scene.xml`` (what users load), in its ``settled`` keyframe when the
folder has one (``holomj validate --repair`` writes it), else in its initial pose.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property
from pathlib import Path

import mujoco
import numpy as np
from shapely.geometry import MultiPoint, Polygon

from holomj.errors import FormatError
from holomj.jobs.folder import ASSETS_DIR, SCENE_JSON, SCENE_XML
from holomj.mjcf import names
from holomj.mjcf.geometry import look_at_quat
from holomj.render.cameras import CameraPose, Mass
from holomj.spec.scene import SceneSpec
from holomj.spec.scene_file import read_scene_file

SETTLED_KEY = "settled"
VISIBLE_GROUPS = (0, 2)  # structure and visual geoms; 1 is ceilings, 3 colliders


def check_folder(out: Path) -> None:
    """Raise a one-line FormatError unless ``out`` is a folder written by holomj."""
    out = Path(out)
    if not out.exists():
        raise FormatError("not found", where=str(out), fix="pass a folder written by holomj")
    if not out.is_dir():
        raise FormatError("not a folder", where=str(out), fix="pass a folder written by holomj")
    missing = [n for n in (SCENE_XML, SCENE_JSON) if not (out / n).is_file()]
    if missing:
        raise FormatError(
            f"not a holomj output folder (no {' or '.join(missing)})",
            where=str(out),
            fix="pass a folder written by 'holomj compile' or 'holomj generate'",
        )


@dataclass
class RenderScene:
    """A folder's scene and model, with the ids of the placeholder cameras."""

    folder: Path
    scene: SceneSpec
    model: mujoco.MjModel
    data: mujoco.MjData
    cameras: dict[str, int]

    def body(self, object_id: str) -> int:
        """The body id of a scene object (-1 when the model lacks it)."""
        return mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_BODY, names.object_body(object_id))

    def place(self, pose: CameraPose) -> None:
        """Move the placeholder camera named ``pose.name`` to ``pose``."""
        cam = self.cameras[pose.name]
        self.model.cam_pos[cam] = pose.position
        if pose.orthographic:
            self.model.cam_quat[cam] = (1.0, 0.0, 0.0, 0.0)  # straight down, +Y up in the image
        else:
            self.model.cam_quat[cam] = look_at_quat(pose.position, pose.target)
        self.model.cam_fovy[cam] = pose.fovy
        self.model.cam_projection[cam] = (
            mujoco.mjtProjection.mjPROJ_ORTHOGRAPHIC
            if pose.orthographic
            else mujoco.mjtProjection.mjPROJ_PERSPECTIVE
        )
        mujoco.mj_camlight(self.model, self.data)

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


def read_scene(out: Path) -> SceneSpec:
    """The scene of a holomj output folder (checked to be one)."""
    check_folder(out)
    return read_scene_file(Path(out) / SCENE_JSON)


def load_render_scene(
    out: Path, scene: SceneSpec, camera_names: list[str], width: int, height: int
) -> RenderScene:
    """Load ``out``'s model for rendering, with a placeholder camera per ``camera_names``."""
    out = Path(out)
    xml = out / SCENE_XML
    try:
        spec = mujoco.MjSpec.from_file(str(xml))
        for name in camera_names:
            spec.worldbody.add_camera(name=name, pos=[0.0, 0.0, 1.0])
        model = spec.compile()
    except ValueError as err:
        raise FormatError(
            f"MuJoCo cannot load it: {' '.join(str(err).split())}",
            where=str(xml),
            fix=f"check that {ASSETS_DIR}/ beside it is complete",
        ) from None
    model.vis.global_.offwidth = max(int(model.vis.global_.offwidth), width)
    model.vis.global_.offheight = max(int(model.vis.global_.offheight), height)
    data = mujoco.MjData(model)
    key = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_KEY, SETTLED_KEY)
    if key >= 0:
        mujoco.mj_resetDataKeyframe(model, data, key)
    mujoco.mj_forward(model, data)
    cameras = {name: model.camera(name).id for name in camera_names}
    return RenderScene(out, scene, model, data, cameras)
