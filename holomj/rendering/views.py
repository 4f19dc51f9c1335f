"""Colour, depth and segmentation images of a list of views, as PNG bytes in memory.

* colour: 8-bit RGB PNG;
* depth: 16-bit grey PNG in millimetres along the camera axis, 0 where nothing was hit (the
  far plane), saturating at 65535 mm;
* segmentation: 16-bit grey PNG of labels (see :mod:`holomj.rendering.labels`).

Ceilings (geom group 1) are hidden in the top view; colliders (group 3) are always hidden.
"""

from __future__ import annotations

import io
import time
from dataclasses import dataclass, field

import mujoco
import numpy as np
from PIL import Image

from holomj.rendering import gl
from holomj.rendering.cameras import CameraPose
from holomj.rendering.labels import Labels
from holomj.rendering.source import RenderScene

DEPTH_MAX_MM = 65535


@dataclass(frozen=True)
class ViewJob:
    """One view to render: ``stem`` names its images (``<stem>.png``, ``<stem>_depth.png``...)."""

    kind: str  # "top", "room" or "object"
    subject: str | None  # the room or object it shows
    stem: str
    pose: CameraPose
    save: bool = True  # False: keep the colour pixels in memory only (no depth, no labels)
    shadows: bool | None = None  # None: the run's setting


@dataclass
class RenderedView:
    """The image names of one view and how long it took; ``pixels``: the colour image, kept
    for views not saved and for the top view (the plan is drawn on it)."""

    job: ViewJob
    image: str
    depth: str | None = None
    segmentation: str | None = None
    seconds: dict[str, float] = field(default_factory=dict)
    pixels: np.ndarray | None = None

    def to_dict(self) -> dict[str, object]:
        """JSON-able form."""
        return {
            "kind": self.job.kind,
            "subject": self.job.subject,
            "image": self.image,
            "depth": self.depth,
            "segmentation": self.segmentation,
            "camera": self.job.pose.to_dict(),
            "seconds": {k: round(v, 4) for k, v in self.seconds.items()},
        }


def scene_option(show_ceilings: bool) -> mujoco.MjvOption:
    """Visible geom groups: structure (0), visual (2), and ceilings (1) when asked."""
    option = mujoco.MjvOption()
    option.geomgroup[:] = np.array([1, int(show_ceilings), 1, 0, 0, 0], dtype=np.uint8)
    return option


def depth_to_mm(depth: np.ndarray, far_m: float) -> np.ndarray:
    """Metres (float) to millimetres (uint16); 0 where the ray reached the far plane."""
    mm = np.clip(np.rint(depth.astype(np.float64) * 1000.0), 0, DEPTH_MAX_MM)
    mm[depth >= far_m * 0.999] = 0
    return mm.astype(np.uint16)


@dataclass
class RenderRun:
    """The views rendered, their PNG images by name, and the OpenGL renderer that drew them."""

    views: list[RenderedView]
    gl_renderer: str
    context_s: float = 0.0  # creating the OpenGL context and uploading the model
    images: dict[str, bytes] = field(default_factory=dict)


def render_views(
    rs: RenderScene,
    jobs: list[ViewJob],
    width: int,
    height: int,
    *,
    depth: bool = False,
    labels: Labels | None = None,
    shadows: bool = True,
) -> RenderRun:
    """Render every job: PNG images ``<stem>.png``, ``<stem>_depth.png``, ``<stem>_seg.png``."""
    if not jobs:  # nothing to draw (e.g. only close-ups asked, and nothing rests on anything)
        return RenderRun([], "none")
    far_m = float(rs.model.vis.map.zfar * rs.model.stat.extent)
    results = []
    images: dict[str, bytes] = {}
    start = time.perf_counter()
    with gl.open_renderer(rs.model, width, height) as renderer:
        name = gl.renderer_name()
        context_s = time.perf_counter() - start
        for job in jobs:
            camera = rs.aim(job.pose)
            option = scene_option(show_ceilings=job.kind != "top")
            view = RenderedView(job, f"{job.stem}.png")
            start = time.perf_counter()
            renderer.update_scene(rs.data, camera=camera, scene_option=option)
            job_shadows = shadows if job.shadows is None else job.shadows
            renderer.scene.flags[mujoco.mjtRndFlag.mjRND_SHADOW] = job_shadows
            pixels = renderer.render()
            view.seconds["color"] = time.perf_counter() - start
            if not job.save or job.kind == "top":
                view.pixels = pixels
            if not job.save:
                results.append(view)
                continue
            images[view.image] = png_bytes(pixels)
            if depth:
                start = time.perf_counter()
                renderer.enable_depth_rendering()
                renderer.update_scene(rs.data, camera=camera, scene_option=option)
                view.depth = f"{job.stem}_depth.png"
                images[view.depth] = png_bytes(depth_to_mm(renderer.render(), far_m))
                renderer.disable_depth_rendering()
                view.seconds["depth"] = time.perf_counter() - start
            if labels is not None:
                start = time.perf_counter()
                renderer.enable_segmentation_rendering()
                renderer.update_scene(rs.data, camera=camera, scene_option=option)
                view.segmentation = f"{job.stem}_seg.png"
                images[view.segmentation] = png_bytes(labels.image(renderer.render()))
                renderer.disable_segmentation_rendering()
                view.seconds["segmentation"] = time.perf_counter() - start
            results.append(view)
    return RenderRun(results, name, context_s, images)


def png_bytes(pixels: np.ndarray) -> bytes:
    """An image (RGB, or 16-bit grey) as PNG file contents."""
    buffer = io.BytesIO()
    Image.fromarray(np.ascontiguousarray(pixels)).save(buffer, format="PNG")
    return buffer.getvalue()
