"""What refine shows its planners: a folder's scene summary and small renders, in memory.

- :func:`scene_summary`: rooms, windows, doors, lights and objects (ids, categories, rooms,
  positions, bounding-box sizes, what they rest on) from the folder's ``scene.json`` and
  ``objects.json``.
- :func:`render_views`: the top view and eye-height views of chosen rooms, as PNG bytes (small:
  320 x 240 by default, no shadows). Rendering runs in this process; when it has no OpenGL
  context it says why and refine goes on without images.
- :func:`render_receptacle`: a camera straight above a receptacle looking down at its support
  surfaces, the image and the camera's intrinsics and extrinsics as MuJoCo drew it (position,
  forward and up vectors of the GL camera, vertical field of view, image size), for pointing.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from holomj.file_names import OBJECTS_JSON
from holomj.jobs.folder import read_json_report, read_scene
from holomj.refinement.pointing import PinholeCamera
from holomj.refinement.summary import ObjectInfo, PlannerSceneSummary, RoomInfo

FLOOR_Z_M = 0.05
POINTING_FOVY_DEG = 45.0
POINTING_MARGIN = 1.15


def scene_summary(folder: Path) -> PlannerSceneSummary:
    """The summary of the scene in ``folder`` (see the module docstring)."""
    scene = read_scene(folder)
    record = read_json_report(folder, OBJECTS_JSON) or {}
    listed = {str(o.get("id")): o for o in record.get("objects", []) if isinstance(o, dict)}
    rooms = [
        RoomInfo(
            id=r.id,
            type=r.type,
            polygon=tuple((float(x), float(y)) for x, y in r.polygon),
            windows=tuple(w.id for w in scene.windows if r.id in w.rooms),
            doors=tuple(d.id for d in scene.doors if r.id in d.rooms),
        )
        for r in scene.rooms
    ]
    objects = []
    for obj in scene.objects:
        row = listed.get(obj.id, {})
        aabb = row.get("aabb") or {}
        lo = aabb.get("min") or [*obj.position[:2], obj.position[2]]
        hi = aabb.get("max") or lo
        size = tuple(round(float(h) - float(v), 4) for v, h in zip(lo, hi))
        if obj.support is not None:
            placement = "object"
        elif float(lo[2]) < FLOOR_Z_M:
            placement = "floor"
        elif float(hi[2]) >= scene.wall_height - 0.15:
            placement = "ceiling"
        else:
            placement = "wall"
        objects.append(
            ObjectInfo(
                id=obj.id,
                category=str(row.get("category") or obj.asset),
                room=obj.room or row.get("room"),
                position=_vec3(obj.position),
                yaw_deg=float(row.get("yaw_deg", obj.yaw_deg) or 0.0),
                size=_vec3(size) if len(size) == 3 else (0.0, 0.0, 0.0),
                support=obj.support,
                placement=placement,
                static=bool(row.get("static", obj.static)),
            )
        )
    windows = [
        {
            "id": w.id,
            "rooms": list(w.rooms),
            "position": [round(v, 3) for v in w.position],
            "width_m": w.width,
            "sill_m": w.base_height,
        }
        for w in scene.windows
    ]
    doors = [
        {"id": d.id, "rooms": list(d.rooms), "position": [round(v, 3) for v in d.position]}
        for d in scene.doors
    ]
    return PlannerSceneSummary(
        rooms=rooms,
        objects=objects,
        windows=windows,
        doors=doors,
        lights=[light.id for light in scene.lights],
        wall_height=scene.wall_height,
    )


@dataclass
class Views:
    """Rendered views: PNG bytes by name (``top.png``, ``rooms/<room>.png``), captions, the
    seconds it took, and why there are none (``error``) when rendering failed."""

    images: dict[str, bytes]
    captions: dict[str, str]
    seconds: float
    error: str | None = None


def render_views(
    folder: Path,
    rooms: list[str] | None = None,
    *,
    width: int = 320,
    height: int = 240,
    max_rooms: int = 3,
) -> Views:
    """The top view and the eye-height views of ``rooms`` (default: every room, at most
    ``max_rooms``) of ``folder``'s scene, in memory."""
    import time

    start = time.perf_counter()
    try:
        from holomj.jobs.render import load_scene_model
        from holomj.rendering.cameras import top_camera
        from holomj.rendering.source import prepare_scene, settled_qpos
        from holomj.rendering.view_plan import Subject, house_bounds, view_jobs
        from holomj.rendering.views import render_views as draw

        scene = read_scene(folder)
        model = load_scene_model(folder)
        known = [r.id for r in scene.rooms]
        chosen = [r for r in (rooms or known) if r in known][:max_rooms]
        subjects = [Subject("top", None, "render/top")]
        subjects += [Subject("room", r, f"render/room/{r}") for r in chosen]
        rs = prepare_scene(model, scene, width, height, qpos=settled_qpos(model))
        top = top_camera(house_bounds(scene), width, height, scene.wall_height)
        run = draw(rs, view_jobs(rs, subjects, top), width, height, shadows=False)
    except Exception as err:  # no GL context, a model MuJoCo cannot load: refine goes on blind
        why = f"{type(err).__name__}: {' '.join(str(err).split())[:200]}"
        return Views({}, {}, round(time.perf_counter() - start, 3), error=why)
    captions = {}
    for view in run.views:
        if view.job.kind == "top":
            captions[view.image] = (
                "top view of the whole scene, looking straight down (x to the right, y up)"
            )
        else:
            captions[view.image] = f"view of room {view.job.subject} from a corner, at eye height"
    return Views(dict(run.images), captions, round(time.perf_counter() - start, 3))


@dataclass
class ReceptacleView:
    """A render looking down at a receptacle, and the camera that made it."""

    png: bytes
    camera: PinholeCamera
    seconds: float
    depth: Any = None  # metres along the camera axis (H x W), when asked for


def render_receptacle(
    folder: Path,
    receptacle_id: str,
    surfaces: list[Any],
    *,
    width: int = 400,
    height: int = 300,
    compiled: Any = None,
    depth: bool = False,
) -> ReceptacleView:
    """A camera above the receptacle's support ``surfaces`` (world polygons and heights)
    looking straight down, framing them with a margin; the image and the camera as MuJoCo drew
    it. ``compiled``: render this compiled scene instead of the folder's ``scene.xml``;
    ``depth``: also the depth image (metres along the camera axis)."""
    import time

    import mujoco
    import numpy as np

    from holomj.rendering import gl
    from holomj.rendering.cameras import CameraPose
    from holomj.rendering.source import prepare_scene, settled_qpos
    from holomj.rendering.views import png_bytes, scene_option

    start = time.perf_counter()
    if compiled is not None:
        model, scene, qpos = compiled.model, compiled.scene, None
    else:
        from holomj.jobs.render import load_scene_model

        scene = read_scene(folder)
        model = load_scene_model(folder)
        qpos = settled_qpos(model)
    xs = [x for s in surfaces for x, _ in s.polygon.exterior.coords]
    ys = [y for s in surfaces for _, y in s.polygon.exterior.coords]
    top = max(s.height for s in surfaces)
    centre = ((min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2)
    half_y = (max(ys) - min(ys)) / 2
    half_x = (max(xs) - min(xs)) / 2
    tan_v = math.tan(math.radians(POINTING_FOVY_DEG / 2))
    aspect = width / height
    reach = max(half_y, half_x / aspect, 0.15) * POINTING_MARGIN
    distance = reach / tan_v + 0.05
    pose = CameraPose(
        f"pointing/{receptacle_id}",
        (centre[0], centre[1], top + distance),
        (centre[0], centre[1], top),
        POINTING_FOVY_DEG,
    )
    rs = prepare_scene(model, scene, width, height, qpos=qpos)
    with gl.open_renderer(rs.model, width, height) as renderer:
        camera = rs.aim(pose)
        renderer.update_scene(rs.data, camera=camera, scene_option=scene_option(False))
        renderer.scene.flags[mujoco.mjtRndFlag.mjRND_SHADOW] = False
        pixels = renderer.render()
        gl_camera = renderer.scene.camera[0]
        pinhole = PinholeCamera(
            position=_vec3(np.asarray(gl_camera.pos)),
            forward=_vec3(np.asarray(gl_camera.forward)),
            up=_vec3(np.asarray(gl_camera.up)),
            fovy_deg=float(rs.model.vis.global_.fovy),
            width=width,
            height=height,
        )
        distances = None
        if depth:
            renderer.enable_depth_rendering()
            renderer.update_scene(rs.data, camera=camera, scene_option=scene_option(False))
            distances = np.asarray(renderer.render(), dtype=float)
            renderer.disable_depth_rendering()
    seconds = round(time.perf_counter() - start, 3)
    return ReceptacleView(png_bytes(pixels), pinhole, seconds, distances)


def _vec3(values: Iterable[float]) -> tuple[float, float, float]:
    """Three numbers as a tuple of floats."""
    x, y, z = (float(v) for v in values)
    return (x, y, z)
