"""render_folder: bad input, atomic writes, the settled keyframe, the manifest."""

from __future__ import annotations

import json
from pathlib import Path

import mujoco
import numpy as np
import pytest
from PIL import Image

import holomj.render.folder as folder_module
from holomj.errors import FormatError, HolomjError, InputError
from holomj.render import render_folder
from holomj.render.cameras import TopCamera
from holomj.render.folder import parse_views


def test_parse_views_checks_names_and_orders_them() -> None:
    assert parse_views("rooms, top") == ("top", "rooms")
    assert parse_views(["objects", "top", "top"]) == ("top", "objects")
    with pytest.raises(InputError, match=r"unknown view 'plan'.*top, rooms, objects"):
        parse_views("top,plan")
    with pytest.raises(InputError, match="no view"):
        parse_views(" , ")


@pytest.mark.parametrize(("width", "height"), [(0, 480), (640, 100_000), (8, 8), (-5, 10)])
def test_absurd_sizes_are_bad_input(two_room_folder: Path, width: int, height: int) -> None:
    with pytest.raises(InputError, match="out of range") as info:
        render_folder(two_room_folder, width=width, height=height)
    assert info.value.exit_code == 2
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


def test_a_failed_render_leaves_the_previous_renders(two_room_folder: Path, monkeypatch) -> None:
    first = render_folder(two_room_folder, views="top", width=32, height=24, shadows=False)
    before = {f: (two_room_folder / f).read_bytes() for f in first.files}

    def broken(rs, jobs, target, *args, **kwargs):
        (target / "half.png").write_bytes(b"not finished")
        raise HolomjError("renderer crashed")

    monkeypatch.setattr(folder_module, "render_views", broken)
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
    model = spec.compile()
    qpos = model.qpos0.copy()
    address = model.jnt_qposadr[model.joint("crate/freejoint").id]
    qpos[address : address + 2] = (6.3, 4.3)  # the crate, moved into the far corner
    spec.add_key(name="settled", qpos=qpos.tolist())
    xml.write_text(spec.to_xml())
    summary = render_folder(two_room_folder, views="top", width=160, height=120, segmentation=True)
    legend = json.loads((two_room_folder / "renders" / "segmentation.json").read_text())
    crate = next(e["label"] for e in legend["labels"] if e["name"] == "crate")
    top = summary.top
    assert top is not None
    camera = TopCamera(tuple(top["centre"]), top["height_m"], 160, 120, 0.0)
    labels = np.asarray(Image.open(two_room_folder / "renders" / "top_seg.png"))
    u, v = (round(c) for c in camera.to_pixel(6.3, 4.3))
    assert labels[v, u] == crate
    u, v = (round(c) for c in camera.to_pixel(5.5, 2.5))  # where scene.json puts it
    assert labels[v, u] != crate


def test_summary_lists_files_relative_to_out(two_room_folder: Path) -> None:
    summary = render_folder(two_room_folder, views="top", width=48, height=32, depth=True)
    assert summary.out == str(two_room_folder)
    assert summary.files == sorted(summary.files[:-1]) + ["renders/manifest.json"]
    assert set(summary.files) >= {
        "renders/top.png",
        "renders/top_depth.png",
        "renders/plan.png",
        "renders/manifest.json",
    }
    assert summary.plan == "renders/plan.png"
    assert summary.timings_s["total"] > 0 and summary.backend in ("egl", "osmesa", "glfw")
    width, height = Image.open(two_room_folder / "renders" / "plan.png").size
    assert width == 48 and height > 32  # the legend strip goes below the view


def test_close_ups_need_something_resting_on_a_receptacle(two_room_folder: Path) -> None:
    scene_path = two_room_folder / "scene.json"
    scene = json.loads(scene_path.read_text())
    for obj in scene["objects"]:
        obj.pop("support", None)
    scene_path.write_text(json.dumps(scene))
    summary = render_folder(two_room_folder, views="objects", width=32, height=24)
    assert summary.views == [] and summary.files == ["renders/manifest.json"]
