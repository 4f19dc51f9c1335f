"""Render an output folder: ``OUT/renders/`` with the views, the plan, a legend and a manifest.

``OUT/renders/`` holds ``top.png`` and ``plan.png`` (view ``top``), ``rooms/<room>.png`` (view
``rooms``), ``objects/<receptacle>.png`` (view ``objects``: receptacles with what rests on
them), ``*_depth.png`` and ``*_seg.png`` on request, ``segmentation.json`` (the label legend)
and ``manifest.json`` (this :class:`RenderSummary`). The folder is built beside OUT/renders
and renamed into place, so a failure leaves the previous renders untouched.

The rendering runs in this process with its OpenGL backend; when that backend cannot make a
context, the job re-runs in a child process with each fallback backend in turn
(:mod:`holomj.render.gl`).
"""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
import time
from collections.abc import Sequence
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

from PIL import Image

from holomj.atomic import replace_folder
from holomj.errors import ExportError, HolomjError, InputError
from holomj.render import gl
from holomj.render.cameras import top_camera
from holomj.render.jobs import TOP_CAMERA, house_bounds, plan_objects, view_jobs, view_subjects
from holomj.render.labels import segmentation_labels
from holomj.render.plan_view import draw_plan
from holomj.render.source import load_render_scene, read_scene
from holomj.render.views import ViewJob, render_views

RENDERS_DIR = "renders"
MANIFEST = "manifest.json"
LEGEND = "segmentation.json"
VIEW_NAMES = ("top", "rooms", "objects")
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


@dataclass
class RenderSummary:
    """What :func:`render_folder` wrote (paths relative to OUT) and how long it took."""

    out: str
    backend: str
    gl_renderer: str
    options: dict[str, Any]
    files: list[str]
    views: list[dict[str, Any]]
    top: dict[str, Any] | None = None
    plan: str | None = None
    legend: str | None = None
    timings_s: dict[str, float] = field(default_factory=dict)

    def to_dict(self) -> dict[str, Any]:
        """JSON-able form (also written as ``renders/manifest.json``)."""
        return asdict(self)

    @classmethod
    def from_dict(cls, data: dict[str, Any]) -> RenderSummary:
        """The summary from its JSON form."""
        return cls(**data)


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


def render_folder(
    out: Path,
    *,
    views: str | Sequence[str] = ("top", "rooms"),
    width: int = 640,
    height: int = 480,
    depth: bool = False,
    segmentation: bool = False,
    shadows: bool = True,
) -> RenderSummary:
    """Render the holomj output folder ``out`` into ``out/renders/`` (see module docstring)."""
    out = Path(out)
    options = RenderOptions(parse_views(views), width, height, depth, segmentation, shadows)
    check_size(width, height)
    read_scene(out)  # bad input fails here, before any work
    result: dict[str, RenderSummary] = {}

    def fill(tmp: Path) -> None:
        result["summary"] = _render_with_fallback(out, tmp, options)

    try:
        replace_folder(out / RENDERS_DIR, fill)
    except OSError as err:
        raise ExportError(f"writing the renders failed: {err}", where=str(out)) from None
    summary = result["summary"]
    summary.out = str(out)
    return summary


def _render_with_fallback(out: Path, target: Path, options: RenderOptions) -> RenderSummary:
    try:
        return render_into(out, target, options)
    except gl.GLUnavailable as err:
        failures = {gl.current_backend(): err.what}
    for backend in gl.fallback_backends():
        _empty(target)
        summary, why = _render_in_child(backend, out, target, options)
        if summary is not None:
            return summary
        failures[backend] = why
    raise gl.no_backend_error(failures)


def _empty(folder: Path) -> None:
    for child in folder.iterdir():
        if child.is_dir():
            shutil.rmtree(child)
        else:
            child.unlink()


def _render_in_child(
    backend: str, out: Path, target: Path, options: RenderOptions
) -> tuple[RenderSummary | None, str]:
    """Run :func:`render_into` in a child process using ``backend``; (summary, why not)."""
    request = {"out": str(out), "target": str(target), "options": asdict(options)}
    proc = subprocess.run(
        [sys.executable, "-m", "holomj.render.worker"],
        input=json.dumps(request),
        capture_output=True,
        text=True,
        env=gl.child_environment(backend),
        check=False,
    )
    lines = proc.stdout.strip().splitlines()
    try:
        reply = json.loads(lines[-1]) if lines else None
    except json.JSONDecodeError:
        reply = None
    if not isinstance(reply, dict):
        tail = " ".join(proc.stderr.split()[-30:]) or f"exit code {proc.returncode}"
        return None, f"the renderer process failed: {tail}"
    if reply.get("ok"):
        return RenderSummary.from_dict(reply["summary"]), ""
    if reply.get("gl"):
        return None, str(reply.get("error"))
    error_class = InputError if reply.get("exit_code") == 2 else HolomjError
    raise error_class(str(reply.get("error")))


def render_into(out: Path, target: Path, options: RenderOptions) -> RenderSummary:
    """Render ``out`` into the empty folder ``target`` in this process (no fallback)."""
    clock = time.perf_counter()
    timings: dict[str, float] = {}
    scene = read_scene(out)
    subjects = view_subjects(scene, options.views)
    cameras = [s.camera for s in subjects]
    rs = load_render_scene(out, scene, cameras, options.width, options.height)
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
        target,
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
    summary = RenderSummary(
        out=str(out),
        backend=gl.current_backend(),
        gl_renderer=run.gl_renderer,
        options=asdict(options),
        files=[],
        views=[_relative(view.to_dict()) for view in run.views if view.job.save],
    )
    if "top" in options.views:
        start = time.perf_counter()
        plan_base = [v.pixels for v in run.views if v.pixels is not None]
        base = Image.fromarray(plan_base[0]) if plan_base else Image.open(target / "top.png")
        plan = draw_plan(base, top, scene, plan_objects(rs))
        plan.save(target / "plan.png", format="PNG")
        summary.top = top.to_dict()
        summary.plan = f"{RENDERS_DIR}/plan.png"
        timings["plan"] = time.perf_counter() - start
    if labels is not None:
        (target / LEGEND).write_text(json.dumps(labels.to_dict(), indent=2) + "\n")
        summary.legend = f"{RENDERS_DIR}/{LEGEND}"
    timings["total"] = time.perf_counter() - clock
    summary.timings_s = {k: round(v, 4) for k, v in timings.items()}
    files = sorted(p.relative_to(target).as_posix() for p in target.rglob("*") if p.is_file())
    summary.files = [f"{RENDERS_DIR}/{f}" for f in [*files, MANIFEST]]
    (target / MANIFEST).write_text(json.dumps(summary.to_dict(), indent=2) + "\n")
    return summary


def _relative(view: dict[str, Any]) -> dict[str, Any]:
    """Paths of a view's files relative to OUT (they are written relative to renders/)."""
    for key in ("image", "depth", "segmentation"):
        if view[key] is not None:
            view[key] = f"{RENDERS_DIR}/{view[key]}"
    return view
