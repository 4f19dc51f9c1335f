"""The render job: ``OUT/renders/`` and ``OUT/report.html`` of an output folder.

``OUT/renders/`` holds ``top.png`` and ``plan.png`` (view ``top``), ``rooms/<room>.png`` (view
``rooms``), ``objects/<receptacle>.png`` (view ``objects``: receptacles with what rests on
them), ``*_depth.png`` and ``*_seg.png`` on request, ``segmentation.json`` (the label legend)
and ``manifest.json`` (this :class:`RenderSummary`). The folder is built beside OUT/renders
and renamed into place, so a failure leaves the previous renders untouched. ``OUT/report.html``
(:func:`write_report_html`) is replaced atomically.

The images are made in memory by :mod:`holomj.rendering` from the model of the folder's
``scene.xml`` (in its ``settled`` keyframe when it has one) or, when the caller already holds it,
from the compiled scene itself. The rendering runs in this process with its OpenGL backend;
when that backend cannot make a context, the job re-runs on the folder in a child process
(``python -m holomj.jobs.render``) with each fallback backend in turn (:mod:`holomj.rendering.gl`).
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

import mujoco

from holomj.atomic import replace_folder, write_file
from holomj.errors import ExportError, FormatError, HolomjError, InputError
from holomj.file_names import (
    ASSETS_DIR,
    IMPORT_REPORT,
    PLAN_JSON,
    RENDERS_DIR,
    REPORT_HTML,
    REPORT_JSON,
    SCENE_JSON,
    SCENE_XML,
)
from holomj.jobs.folder import open_library, read_json_report, read_scene
from holomj.mjcf.compiler import CompiledScene
from holomj.rendering import gl
from holomj.rendering.pipeline import (
    VIEW_NAMES,
    Rendering,
    RenderOptions,
    check_size,
    parse_views,
    render_scene,
)
from holomj.rendering.report_html import manifest_images, render_page
from holomj.rendering.source import settled_qpos
from holomj.spec.base import validate_model
from holomj.spec.plan import ScenePlan
from holomj.spec.report import StabilityReport
from holomj.spec.scene import SceneSpec

MANIFEST = "manifest.json"
LEGEND = "segmentation.json"

__all__ = [
    "LEGEND",
    "MANIFEST",
    "VIEW_NAMES",
    "RenderSummary",
    "check_folder",
    "load_scene_model",
    "render_folder",
    "render_into",
    "write_report_html",
]


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


def _folder_scene(out: Path) -> SceneSpec:
    """The scene of a holomj output folder (checked to be one)."""
    check_folder(out)
    return read_scene(out)


def load_scene_model(out: Path) -> mujoco.MjModel:
    """The model of ``out``'s exported ``scene.xml`` (what users load)."""
    xml = Path(out) / SCENE_XML
    try:
        return mujoco.MjModel.from_xml_path(str(xml))
    except ValueError as err:
        raise FormatError(
            f"MuJoCo cannot load it: {' '.join(str(err).split())}",
            where=str(xml),
            fix=f"check that {ASSETS_DIR}/ beside it is complete",
        ) from None


def render_folder(
    out: Path,
    *,
    views: str | Sequence[str] = ("top", "rooms"),
    width: int = 640,
    height: int = 480,
    depth: bool = False,
    segmentation: bool = False,
    shadows: bool = True,
    compiled: CompiledScene | None = None,
    recorded_out: Path | None = None,
) -> RenderSummary:
    """Render the holomj output folder ``out`` into ``out/renders/`` (see module docstring).

    ``compiled``: the folder's scene, compiled, when the caller holds it (``holomj generate``):
    its model and scene are rendered instead of loading ``scene.xml`` again (in its ``settled``
    keyframe when the model has one); a fallback to a child process still reads the folder.
    ``recorded_out``: the folder's final path, when ``out`` is a temporary folder renamed into
    place afterwards (what the summary and its manifest name).
    """
    out = Path(out)
    options = RenderOptions(parse_views(views), width, height, depth, segmentation, shadows)
    check_size(width, height)
    # bad input fails here, before any work
    scene = _folder_scene(out) if compiled is None else None
    if compiled is not None:
        check_folder(out)
    result: dict[str, RenderSummary] = {}

    def fill(tmp: Path) -> None:
        result["summary"] = _render_with_fallback(out, tmp, options, compiled, scene)
        if recorded_out is not None:
            result["summary"].out = str(recorded_out)
            (tmp / MANIFEST).write_text(json.dumps(result["summary"].to_dict(), indent=2) + "\n")

    try:
        replace_folder(out / RENDERS_DIR, fill)
    except OSError as err:
        raise ExportError(f"writing the renders failed: {err}", where=str(out)) from None
    summary = result["summary"]
    summary.out = str(recorded_out or out)
    return summary


def _render_with_fallback(
    out: Path,
    target: Path,
    options: RenderOptions,
    compiled: CompiledScene | None,
    scene: SceneSpec | None,
) -> RenderSummary:
    try:
        return render_into(out, target, options, compiled=compiled, scene=scene)
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
    """Run :func:`render_into` on the folder in a child process using ``backend``;
    (summary, why not)."""
    request = {"out": str(out), "target": str(target), "options": options.to_dict()}
    proc = subprocess.run(
        [sys.executable, "-m", "holomj.jobs.render"],
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


def render_into(
    out: Path,
    target: Path,
    options: RenderOptions,
    *,
    compiled: CompiledScene | None = None,
    scene: SceneSpec | None = None,
) -> RenderSummary:
    """Render ``out`` (or ``compiled``; ``scene``: ``out``'s scene when already read) into the
    empty folder ``target`` in this process (no fallback: raises
    :class:`holomj.rendering.gl.GLUnavailable`)."""
    clock = time.perf_counter()
    if compiled is not None:
        model, scene = compiled.model, compiled.scene
    else:
        scene = scene if scene is not None else _folder_scene(out)
        model = load_scene_model(out)
    read_s = time.perf_counter() - clock
    rendering = render_scene(model, scene, options, qpos=settled_qpos(model))
    return _save_rendering(rendering, out, target, read_s)


def _save_rendering(rendering: Rendering, out: Path, target: Path, read_s: float) -> RenderSummary:
    """Write ``rendering``'s images, legend and manifest into ``target`` (``OUT/renders``)."""
    start = time.perf_counter()
    for name, data in rendering.images.items():
        path = target / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_bytes(data)
    names = list(rendering.images)
    if rendering.legend is not None:
        (target / LEGEND).write_text(json.dumps(rendering.legend, indent=2) + "\n")
        names.append(LEGEND)
    write_s = time.perf_counter() - start
    timings = dict(rendering.timings_s)
    total = timings.pop("total", 0.0) + read_s + write_s
    timings["load"] = timings.get("load", 0.0) + read_s
    timings["write"] = write_s
    timings["total"] = total
    summary = RenderSummary(
        out=str(out),
        backend=rendering.backend,
        gl_renderer=rendering.gl_renderer,
        options=rendering.options.to_dict(),
        files=[f"{RENDERS_DIR}/{f}" for f in [*sorted(names), MANIFEST]],
        views=[_relative(view) for view in rendering.views],
        top=rendering.top,
        plan=f"{RENDERS_DIR}/{rendering.plan}" if rendering.plan else None,
        legend=f"{RENDERS_DIR}/{LEGEND}" if rendering.legend is not None else None,
        timings_s={k: round(v, 4) for k, v in timings.items()},
    )
    (target / MANIFEST).write_text(json.dumps(summary.to_dict(), indent=2) + "\n")
    return summary


def _relative(view: dict[str, Any]) -> dict[str, Any]:
    """Paths of a view's files relative to OUT (the rendering names them within renders/)."""
    view = dict(view)
    for key in ("image", "depth", "segmentation"):
        if view[key] is not None:
            view[key] = f"{RENDERS_DIR}/{view[key]}"
    return view


def write_report_html(
    out: Path,
    *,
    embed: bool = True,
    interactive: bool = True,
    compiled: CompiledScene | None = None,
) -> Path:
    """Write ``OUT/report.html`` from the folder's scene, assets, reports and renders.

    ``embed``: images as ``data:`` URIs (a page that stands alone); else linked relatively.
    ``interactive``: with the 3D view (the scene's GLB, colliders included, in its ``settled``
    keyframe when it has one, like the images). ``compiled``: the folder's scene, compiled, when
    the caller holds it (its model is used instead of loading ``scene.xml`` again).
    """
    out = Path(out)
    scene = _folder_scene(out)
    glb = None
    if interactive:
        from holomj.formats.glb import scene_glb

        model = compiled.model if compiled is not None else load_scene_model(out)
        glb = scene_glb(model, scene, qpos=settled_qpos(model), colliders=True)
    manifest = read_json_report(out, f"{RENDERS_DIR}/{MANIFEST}")
    manifest = manifest if isinstance(manifest, dict) else None
    images: dict[str, bytes | str] = {}
    for relative in manifest_images(manifest):
        path = out / relative
        if path.is_file():
            images[relative] = path.read_bytes() if embed else relative
    page = render_page(
        scene,
        open_library(out),
        report=_read_report(out, REPORT_JSON, StabilityReport),
        plan=_read_report(out, PLAN_JSON, ScenePlan),
        imported=read_json_report(out, IMPORT_REPORT),
        manifest=manifest,
        images=images,
        glb=glb,
    )
    target = out / REPORT_HTML
    try:
        write_file(target, page)
    except OSError as err:
        raise ExportError(f"cannot write the report page: {err}", where=str(target)) from None
    return target


def _read_report(out: Path, name: str, model: type[Any]) -> Any:
    """A JSON report of ``out`` validated as ``model`` (None when absent)."""
    data = read_json_report(out, name)
    return None if data is None else validate_model(model, data, str(out / name))


def _child_main() -> int:
    """The child process of the GL fallback: render one folder with this process's backend.

    Reads ``{"out", "target", "options"}`` as JSON on stdin and prints one JSON line on stdout:
    ``{"ok": true, "summary": ...}``, or ``{"ok": false, "gl": true, "error": ...}`` when this
    backend cannot render, or ``{"ok": false, "gl": false, "error": ..., "exit_code": ...}``
    for any other holomj error. The parent sets ``MUJOCO_GL``.
    """
    request = json.loads(sys.stdin.read())
    options = RenderOptions.from_dict(request["options"])
    try:
        summary = render_into(Path(request["out"]), Path(request["target"]), options)
    except gl.GLUnavailable as err:
        reply = {"ok": False, "gl": True, "error": err.what}
    except HolomjError as err:
        reply = {"ok": False, "gl": False, "error": err.one_line(), "exit_code": err.exit_code}
    else:
        reply = {"ok": True, "summary": summary.to_dict()}
    sys.stdout.write(json.dumps(reply) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(_child_main())
