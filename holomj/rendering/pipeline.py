"""Render a scene in memory: its views, the annotated plan, the segmentation legend, timings.

:func:`render_scene` takes a compiled model and its scene (and optionally the joint positions to
pose it in) and returns a :class:`Rendering`: PNG images by name (``top.png`` and ``plan.png``
for view ``top``, ``rooms/<room>.png`` for ``rooms``, ``objects/<receptacle>.png`` for
``objects``: receptacles with what rests on them; ``*_depth.png`` and ``*_seg.png`` on
request), the views and their cameras, the legend and how long each step took. Nothing is
read from or written to disk; the render job (:mod:`holomj.jobs.render`) saves a rendering
into an output folder.

The rendering runs in this process with its OpenGL backend; when that backend cannot make a
context it raises :class:`holomj.rendering.gl.GLUnavailable` (the job then falls back to a child
process with another backend).
"""

from __future__ import annotations

import io
import time
from collections.abc import Sequence
from dataclasses import asdict, dataclass, field
from typing import Any

import mujoco
import numpy as np
from PIL import Image

from holomj.errors import InputError
from holomj.rendering import gl
from holomj.rendering.cameras import top_camera
from holomj.rendering.labels import segmentation_labels
from holomj.rendering.plan_view import draw_plan
from holomj.rendering.source import prepare_scene
from holomj.rendering.view_plan import (
    TOP_CAMERA,
    house_bounds,
    plan_objects,
    view_jobs,
    view_subjects,
)
from holomj.rendering.views import ViewJob, render_views
from holomj.spec.scene import SceneSpec

VIEW_NAMES = ("top", "rooms", "objects")
PLAN_IMAGE = "plan.png"
MIN_PIXELS, MAX_PIXELS = 16, 4096


@dataclass(frozen=True)
class RenderOptions:
    """What to render and how."""

    views: tuple[str, ...] = ("top", "rooms")
    width: int = 640
    height: int = 480
    depth: bool = False
    segmentation: bool = False
    shadows: bool = True

    def to_dict(self) -> dict[str, Any]:
        """JSON-able form."""
        return asdict(self)

    @classmethod
    def from_dict(cls, data: dict[str, Any]) -> RenderOptions:
        """The options from their JSON form (:func:`dataclasses.asdict`)."""
        return cls(**{**data, "views": tuple(data["views"])})


@dataclass
class Rendering:
    """What one render made: PNG images by name (``top.png``, ``rooms/kitchen.png``, ...), the
    views (their ``image``, ``depth`` and ``segmentation`` are names in ``images``), the top
    camera and the plan image's name (view ``top``), the segmentation legend, timings."""

    options: RenderOptions
    backend: str
    gl_renderer: str
    images: dict[str, bytes]
    views: list[dict[str, Any]]
    top: dict[str, Any] | None = None
    plan: str | None = None
    legend: dict[str, Any] | None = None
    timings_s: dict[str, float] = field(default_factory=dict)


def parse_views(views: str | Sequence[str]) -> tuple[str, ...]:
    """Views from ``"top,rooms"`` or a sequence, checked, in canonical order."""
    items = views.split(",") if isinstance(views, str) else list(views)
    chosen = {v.strip() for v in items if v.strip()}
    unknown = sorted(chosen - set(VIEW_NAMES))
    if unknown:
        raise InputError(
            f"unknown view {unknown[0]!r}",
            where="--views",
            fix=f"choose from {', '.join(VIEW_NAMES)}",
        )
    if not chosen:
        raise InputError("no view chosen", where="--views", fix=f"use {','.join(VIEW_NAMES)}")
    return tuple(v for v in VIEW_NAMES if v in chosen)


def check_size(width: int, height: int) -> None:
    """Reject image sizes outside [MIN_PIXELS, MAX_PIXELS]."""
    for name, value in (("--width", width), ("--height", height)):
        if not MIN_PIXELS <= value <= MAX_PIXELS:
            raise InputError(
                f"image size {value} px is out of range",
                where=name,
                fix=f"use {MIN_PIXELS} to {MAX_PIXELS} pixels",
            )


def render_scene(
    model: mujoco.MjModel,
    scene: SceneSpec,
    options: RenderOptions,
    *,
    qpos: np.ndarray | None = None,
) -> Rendering:
    """Render ``scene`` from its compiled ``model`` (not modified), posed by ``qpos`` (default:
    the initial pose), in this process; see the module docstring."""
    clock = time.perf_counter()
    timings: dict[str, float] = {}
    subjects = view_subjects(scene, options.views)
    rs = prepare_scene(model, scene, options.width, options.height, qpos=qpos)
    timings["load"] = time.perf_counter() - clock
    start = time.perf_counter()
    top = top_camera(house_bounds(scene), options.width, options.height, scene.wall_height)
    jobs = view_jobs(rs, subjects, top)
    if "top" in options.views and options.shadows:  # the plan is drawn on a shadowless view
        jobs.append(ViewJob("plan", None, "plan", top.pose(TOP_CAMERA), save=False, shadows=False))
    timings["cameras"] = time.perf_counter() - start
    labels = segmentation_labels(rs.model, scene) if options.segmentation else None
    run = render_views(
        rs,
        jobs,
        options.width,
        options.height,
        depth=options.depth,
        labels=labels,
        shadows=options.shadows,
    )
    timings["context"] = run.context_s
    for view in run.views:
        for kind, seconds in view.seconds.items():
            timings[f"render_{kind}"] = timings.get(f"render_{kind}", 0.0) + seconds
    rendering = Rendering(
        options=options,
        backend=gl.current_backend(),
        gl_renderer=run.gl_renderer,
        images=run.images,
        views=[view.to_dict() for view in run.views if view.job.save],
    )
    if "top" in options.views:
        start = time.perf_counter()
        # the shadowless plan view when there is one, else the (shadowless) top view itself
        bases = {v.job.kind: v.pixels for v in run.views if v.pixels is not None}
        base = bases.get("plan", bases.get("top"))
        if base is None:
            raise AssertionError("the top view was not rendered")
        plan = draw_plan(Image.fromarray(base), top, scene, plan_objects(rs))
        buffer = io.BytesIO()
        plan.save(buffer, format="PNG")
        rendering.images[PLAN_IMAGE] = buffer.getvalue()
        rendering.top = top.to_dict()
        rendering.plan = PLAN_IMAGE
        timings["plan"] = time.perf_counter() - start
    if labels is not None:
        rendering.legend = labels.to_dict()
    timings["total"] = time.perf_counter() - clock
    rendering.timings_s = {k: round(v, 4) for k, v in timings.items()}
    return rendering
