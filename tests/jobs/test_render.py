"""The render job: OUT/renders/ (bad input, atomic writes, the settled keyframe, the manifest,
the compiled scene in memory, the OpenGL fallback) and OUT/report.html."""

from __future__ import annotations

import base64
import dataclasses
import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import mujoco
import numpy as np
import pytest
from PIL import Image

import holomj.jobs.render as render_job
from holomj.errors import FormatError, HolomjError, InputError, SpecError
from holomj.jobs.render import RenderSummary, render_folder, write_report_html
from holomj.library import AssetLibrary
from holomj.mjcf.compiler import CompiledScene
from holomj.rendering import gl
from holomj.rendering.cameras import TopCamera
from holomj.spec.report import StabilityReport
from tests.rendering.conftest import empty_library_at, two_room_compiled_in, two_room_folder_in
from tests.rendering.html_page import Page, parse_page


@pytest.fixture(scope="module")
def compiled_two_room(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The two-room fixture scene compiled into an output folder (do not modify it)."""
    return two_room_folder_in(tmp_path_factory.mktemp("render"))


@pytest.fixture
def two_room_folder(compiled_two_room: Path, tmp_path: Path) -> Path:
    """A private copy of the compiled two-room folder, free to modify."""
    return Path(shutil.copytree(compiled_two_room, tmp_path / "two_room"))


@pytest.fixture(scope="module")
def two_room_compiled(tmp_path_factory: pytest.TempPathFactory) -> CompiledScene:
    """The two-room fixture scene compiled in memory (do not modify it)."""
    library = AssetLibrary.open(empty_library_at(tmp_path_factory.mktemp("library")))
    return two_room_compiled_in(library)


def _moved_crate_qpos(model: mujoco.MjModel) -> np.ndarray:
    qpos = model.qpos0.copy()
    address = model.jnt_qposadr[model.joint("crate/freejoint").id]
    qpos[address : address + 2] = (6.3, 4.3)  # the crate, moved into the far corner
    return qpos


def _crate_seen_at_far_corner(out: Path, summary: RenderSummary) -> bool:
    """Whether the crate's label is at (6.3, 4.3) in the top view (and not at (5.5, 2.5))."""
    legend = json.loads((out / "renders" / "segmentation.json").read_text())
    crate = next(e["label"] for e in legend["labels"] if e["name"] == "crate")
    top = summary.top
    assert top is not None
    camera = TopCamera(tuple(top["centre"]), top["height_m"], 160, 120, 0.0)
    labels = np.asarray(Image.open(out / "renders" / "top_seg.png"))
    u, v = (round(c) for c in camera.to_pixel(6.3, 4.3))
    far = labels[v, u] == crate
    u, v = (round(c) for c in camera.to_pixel(5.5, 2.5))  # where scene.json puts it
    return bool(far and labels[v, u] != crate)


@pytest.mark.parametrize(("width", "height"), [(0, 480), (640, 100_000), (8, 8), (-5, 10)])
def test_absurd_sizes_are_bad_input(two_room_folder: Path, width: int, height: int) -> None:
    with pytest.raises(InputError, match="out of range") as info:
        render_folder(two_room_folder, width=width, height=height)
    assert info.value.exit_code == 2
    assert not (two_room_folder / "renders").exists()


def test_unknown_views_are_bad_input(two_room_folder: Path) -> None:
    with pytest.raises(InputError, match="unknown view 'plan'"):
        render_folder(two_room_folder, views="top,plan")
    assert not (two_room_folder / "renders").exists()


def test_missing_or_foreign_folders_are_bad_input(tmp_path: Path) -> None:
    with pytest.raises(FormatError, match="not found"):
        render_folder(tmp_path / "nope")
    (tmp_path / "plain").mkdir()
    with pytest.raises(FormatError, match="not a holomj output folder") as info:
        render_folder(tmp_path / "plain")
    assert info.value.exit_code == 2 and "\n" not in str(info.value)
    (tmp_path / "file.txt").write_text("x")
    with pytest.raises(FormatError, match="not a folder"):
        render_folder(tmp_path / "file.txt")


def test_a_broken_scene_xml_is_one_line(two_room_folder: Path) -> None:
    (two_room_folder / "scene.xml").write_text("<mujoco><worldbody><geom/></mujoco>")
    with pytest.raises(FormatError, match="MuJoCo cannot load it") as info:
        render_folder(two_room_folder, views="top", width=32, height=24)
    assert "scene.xml" in str(info.value) and "\n" not in str(info.value)
    assert not (two_room_folder / "renders").exists()


def test_a_failed_render_leaves_the_previous_renders(two_room_folder: Path, monkeypatch) -> None:
    first = render_folder(two_room_folder, views="top", width=32, height=24, shadows=False)
    before = {f: (two_room_folder / f).read_bytes() for f in first.files}

    def broken(rendering, out, target, read_s):
        (target / "half.png").write_bytes(b"not finished")
        raise HolomjError("renderer crashed")

    monkeypatch.setattr(render_job, "_save_rendering", broken)
    with pytest.raises(HolomjError, match="renderer crashed"):
        render_folder(two_room_folder, views="top,rooms", width=32, height=24)
    after = {f: (two_room_folder / f).read_bytes() for f in first.files}
    assert after == before
    assert not (two_room_folder / "renders" / "half.png").exists()
    leftovers = [p.name for p in two_room_folder.iterdir() if p.name.startswith(".renders")]
    assert leftovers == []


def test_renders_use_the_settled_keyframe(two_room_folder: Path) -> None:
    xml = two_room_folder / "scene.xml"
    spec = mujoco.MjSpec.from_file(str(xml))
    spec.add_key(name="settled", qpos=_moved_crate_qpos(spec.compile()).tolist())
    xml.write_text(spec.to_xml())
    summary = render_folder(two_room_folder, views="top", width=160, height=120, segmentation=True)
    assert _crate_seen_at_far_corner(two_room_folder, summary)


def test_summary_lists_files_relative_to_out(two_room_folder: Path) -> None:
    summary = render_folder(two_room_folder, views="top", width=48, height=32, depth=True)
    assert summary.out == str(two_room_folder)
    assert summary.files == sorted(summary.files[:-1]) + ["renders/manifest.json"]
    assert set(summary.files) == {
        "renders/top.png",
        "renders/top_depth.png",
        "renders/plan.png",
        "renders/manifest.json",
    }
    assert summary.plan == "renders/plan.png" and summary.legend is None
    assert summary.views[0]["image"] == "renders/top.png"
    assert summary.views[0]["depth"] == "renders/top_depth.png"
    assert summary.timings_s["total"] > 0 and summary.backend in ("egl", "osmesa", "glfw")
    width, height = Image.open(two_room_folder / "renders" / "plan.png").size
    assert width == 48 and height > 32  # the legend strip goes below the view
    manifest = json.loads((two_room_folder / "renders" / "manifest.json").read_text())
    assert manifest == json.loads(json.dumps(summary.to_dict()))
    written = sorted(
        p.relative_to(two_room_folder).as_posix()
        for p in (two_room_folder / "renders").rglob("*")
        if p.is_file()
    )
    assert written == sorted(summary.files)


def test_every_view_depth_and_segmentation_is_written(two_room_folder: Path) -> None:
    summary = render_folder(
        two_room_folder,
        views="top,rooms,objects",
        width=64,
        height=48,
        depth=True,
        segmentation=True,
        shadows=False,
    )
    kinds = [(v["kind"], v["subject"]) for v in summary.views]
    assert kinds == [("top", None), ("room", "kitchen"), ("room", "living"), ("object", "table")]
    assert summary.legend == "renders/segmentation.json"
    for name in summary.files:
        assert (two_room_folder / name).is_file(), name
    for view in summary.views:
        for key in ("image", "depth", "segmentation"):
            assert view[key] in summary.files


def test_close_ups_need_something_resting_on_a_receptacle(two_room_folder: Path) -> None:
    scene_path = two_room_folder / "scene.json"
    scene = json.loads(scene_path.read_text())
    for obj in scene["objects"]:
        obj.pop("support", None)
    scene_path.write_text(json.dumps(scene))
    summary = render_folder(two_room_folder, views="objects", width=32, height=24)
    assert summary.views == [] and summary.files == ["renders/manifest.json"]


def test_the_compiled_scene_is_rendered_without_reading_scene_xml(
    two_room_folder: Path, two_room_compiled: CompiledScene
) -> None:
    expected = render_folder(two_room_folder, views="top,rooms", width=64, height=48)
    images = {f: (two_room_folder / f).read_bytes() for f in expected.files if f.endswith(".png")}
    (two_room_folder / "scene.xml").write_text("<mujoco><broken")
    summary = render_folder(
        two_room_folder, views="top,rooms", width=64, height=48, compiled=two_room_compiled
    )
    assert summary.files == expected.files

    def cameras(views: list[dict]) -> list[dict]:
        return [{k: v for k, v in view.items() if k != "seconds"} for view in views]

    assert cameras(summary.views) == cameras(expected.views)
    for name, data in images.items():
        assert (two_room_folder / name).read_bytes() == data, name


def test_the_compiled_scene_uses_its_settled_keyframe(
    two_room_folder: Path, two_room_compiled: CompiledScene
) -> None:
    spec = two_room_compiled.spec.copy()
    spec.add_key(name="settled", qpos=_moved_crate_qpos(two_room_compiled.model).tolist())
    compiled = dataclasses.replace(two_room_compiled, spec=spec, model=spec.compile())
    summary = render_folder(
        two_room_folder, views="top", width=160, height=120, segmentation=True, compiled=compiled
    )
    assert _crate_seen_at_far_corner(two_room_folder, summary)


def test_the_compiled_scene_still_needs_an_output_folder(
    tmp_path: Path, two_room_compiled: CompiledScene
) -> None:
    with pytest.raises(FormatError, match="not found"):
        render_folder(tmp_path / "nope", compiled=two_room_compiled)


def test_no_working_backend_is_one_line_naming_mujoco_gl(
    two_room_folder: Path, two_room_compiled: CompiledScene, monkeypatch
) -> None:
    monkeypatch.setattr(gl, "_failures", {})
    monkeypatch.setattr(gl, "current_backend", lambda: "egl")

    def no_context(*args, **kwargs):
        raise gl.GLUnavailable("EGL: no display", where="MUJOCO_GL=egl")

    tried = []

    def child(backend, *args):
        tried.append(backend)
        return None, "libOSMesa.so.8: cannot open shared object file"

    monkeypatch.setattr(gl, "open_renderer", no_context)
    monkeypatch.setattr(render_job, "_render_in_child", child)
    for compiled in (None, two_room_compiled):
        tried.clear()
        with pytest.raises(HolomjError) as info:
            render_folder(two_room_folder, views="top", width=32, height=24, compiled=compiled)
        message = str(info.value)
        assert tried == ["osmesa"]
        assert info.value.exit_code == 1 and "\n" not in message
        assert "MUJOCO_GL=egl: EGL: no display" in message
        assert "MUJOCO_GL=osmesa: libOSMesa.so.8" in message
        assert "set MUJOCO_GL" in message and "libosmesa6" in message
        assert not (two_room_folder / "renders").exists()


def test_the_child_process_renders_the_folder(two_room_folder: Path, monkeypatch) -> None:
    """Without a context here, a child process with a fallback backend renders the folder."""
    monkeypatch.setattr(gl, "current_backend", lambda: "broken")  # children: egl, osmesa

    def no_context(*args, **kwargs):
        raise gl.GLUnavailable("no context", where="MUJOCO_GL=broken")

    monkeypatch.setattr(gl, "open_renderer", no_context)
    summary = render_folder(two_room_folder, views="top", width=32, height=24, shadows=False)
    assert summary.backend in gl.BACKENDS and summary.out == str(two_room_folder)
    assert (two_room_folder / "renders" / "top.png").is_file()
    manifest = json.loads((two_room_folder / "renders" / "manifest.json").read_text())
    assert manifest["files"] == summary.files


@pytest.mark.slow
def test_broken_egl_falls_back_to_osmesa_in_a_child_process(two_room_folder: Path) -> None:
    """MUJOCO_EGL_DEVICE_ID beyond the devices makes EGL fail the way a missing driver does."""
    env = {**os.environ, "MUJOCO_GL": "egl", "MUJOCO_EGL_DEVICE_ID": "99"}
    env.pop("PYOPENGL_PLATFORM", None)
    args = ["render", str(two_room_folder), "--views", "top", "--width", "32", "--height", "24"]
    proc = subprocess.run(
        [sys.executable, "-m", "holomj", *args, "--no-report", "--no-shadows", "--json"],
        capture_output=True,
        text=True,
        env=env,
        check=False,
        timeout=120,
    )
    assert proc.returncode == 0, proc.stderr
    summary = json.loads(proc.stdout)
    assert summary["backend"] == "osmesa"
    assert (two_room_folder / "renders" / "top.png").is_file()
    manifest = json.loads((two_room_folder / "renders" / "manifest.json").read_text())
    assert manifest["backend"] == "osmesa"


def _parse(path: Path) -> Page:
    return parse_page(path.read_text(encoding="utf-8"))


def test_page_of_a_folder_without_reports_or_renders(two_room_folder: Path) -> None:
    path = write_report_html(two_room_folder)
    assert path == two_room_folder / "report.html"
    page = _parse(path)
    text = " ".join(page.text)
    assert "Not validated" in text and "holomj render OUT" in text  # no renders yet
    rows = {row[0]: row for row in page.rows if row}
    assert set(rows) == {"crate", "table", "cube"}
    assert rows["table"][2] == "box" and rows["table"][4] == "1.20 × 0.80 × 0.75"
    assert "format: holomj" in text  # import_report.json
    assert page.images == []


def test_page_reads_the_reports_and_embeds_the_renders(two_room_folder: Path) -> None:
    render_folder(two_room_folder, views="top,rooms,objects", width=64, height=48, shadows=False)
    report = StabilityReport(ok=True, source="two_room", objects=[], counts={"objects": 0})
    (two_room_folder / "report.json").write_text(report.model_dump_json())
    plan = {
        "prompt": "a kitchen & a living room",
        "planner": "offline",
        "seed": 7,
        "scene_type": "apartment",
        "rooms": [{"id": "kitchen", "type": "kitchen"}, {"id": "living", "type": "living_room"}],
        "notes": ["no sofa asset: used a box"],
    }
    (two_room_folder / "plan.json").write_text(json.dumps(plan))
    page = _parse(write_report_html(two_room_folder))
    text = " ".join(page.text)
    assert "Physically valid" in text and "no sofa asset: used a box" in text
    assert "rendered at 64×48" in text
    # plan, two rooms and the table close-up, embedded: the bytes of the files
    assert len(page.images) == 4
    plan_png = (two_room_folder / "renders" / "plan.png").read_bytes()
    assert base64.b64decode(page.images[0].split(",", 1)[1]) == plan_png


def test_linked_images_are_relative_and_exist(two_room_folder: Path) -> None:
    render_folder(two_room_folder, views="top,rooms", width=32, height=24, shadows=False)
    (two_room_folder / "renders" / "rooms" / "living.png").unlink()  # left out of the page
    page = _parse(write_report_html(two_room_folder, embed=False))
    assert page.images == ["renders/plan.png", "renders/rooms/kitchen.png"]
    for src in page.images:
        assert (two_room_folder / src).is_file()


def test_a_broken_report_json_is_bad_input(two_room_folder: Path) -> None:
    (two_room_folder / "report.json").write_text(json.dumps({"ok": "maybe"}))
    with pytest.raises(SpecError, match=r"report\.json") as info:
        write_report_html(two_room_folder)
    assert info.value.exit_code == 2
    assert not (two_room_folder / "report.html").exists()


def test_the_page_is_written_atomically(two_room_folder: Path) -> None:
    write_report_html(two_room_folder)
    leftovers = [p for p in two_room_folder.iterdir() if re.match(r"\.report\.html\.", p.name)]
    assert leftovers == []


def test_the_page_needs_an_output_folder(tmp_path: Path) -> None:
    with pytest.raises(FormatError, match="not found"):
        write_report_html(tmp_path / "nope")


def test_the_report_page_uses_the_compiled_scene_without_reading_scene_xml(
    two_room_folder: Path, two_room_compiled: CompiledScene
) -> None:
    expected = _parse(write_report_html(two_room_folder))
    (two_room_folder / "scene.xml").write_text("<mujoco><broken")
    page = _parse(write_report_html(two_room_folder, compiled=two_room_compiled))

    # the same page; the 3D view's floats may differ in their last digits (scene.xml rounds)
    def words(parsed: Page) -> list[str]:
        return [t for t in parsed.text if len(t) < 1000]  # the GLB is one long base64 text

    assert page.rows == expected.rows and words(page) == words(expected)
    assert 'id="layer-' in (two_room_folder / "report.html").read_text(encoding="utf-8")
    with pytest.raises(FormatError, match="MuJoCo cannot load it"):
        write_report_html(two_room_folder)


def test_renders_made_in_a_temporary_folder_name_the_final_one(
    two_room_folder: Path, two_room_compiled: CompiledScene, tmp_path: Path
) -> None:
    final = tmp_path / "final"
    summary = render_folder(
        two_room_folder,
        views="top",
        width=32,
        height=24,
        compiled=two_room_compiled,
        recorded_out=final,
    )
    manifest = json.loads((two_room_folder / "renders" / "manifest.json").read_text())
    assert summary.out == manifest["out"] == str(final)
