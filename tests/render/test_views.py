"""Rendered images of the two-room scene: not blank, every room seen, depth and labels right."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from PIL import Image
from shapely.geometry import Point, Polygon
from shapely.ops import polylabel, unary_union

from holomj.render import RenderSummary
from holomj.render.cameras import TopCamera
from holomj.spec.scene_file import read_scene_file
from tests.render.conftest import SMALL


def _image(out: Path, relative: str) -> np.ndarray:
    return np.asarray(Image.open(out / relative))


def _top(summary: RenderSummary) -> TopCamera:
    top = summary.top
    assert top is not None
    return TopCamera(tuple(top["centre"]), top["height_m"], top["width_px"], top["height_px"], 0)


def test_every_view_is_written_and_not_blank(rendered_two_room) -> None:
    out, summary = rendered_two_room
    kinds = [(v["kind"], v["subject"]) for v in summary.views]
    assert kinds == [("top", None), ("room", "kitchen"), ("room", "living"), ("object", "table")]
    for view in summary.views:
        pixels = _image(out, view["image"])
        assert pixels.shape == (SMALL[1], SMALL[0], 3)
        assert pixels.std() > 10, f"{view['image']} is blank"
        assert len(np.unique(pixels.reshape(-1, 3), axis=0)) > 20, f"{view['image']} is flat"
    for name in summary.files:
        assert (out / name).is_file(), name
    manifest = json.loads((out / "renders" / "manifest.json").read_text())
    assert manifest["views"] == summary.views and manifest["files"] == summary.files


def test_top_view_shows_every_room_floor(rendered_two_room) -> None:
    out, summary = rendered_two_room
    scene = read_scene_file(out / "scene.json")
    labels = _image(out, "renders/top_seg.png")
    legend = json.loads((out / "renders" / "segmentation.json").read_text())["labels"]
    floor = next(e["label"] for e in legend if e["name"] == "floor" and e["kind"] == "structure")
    top = _top(summary)
    colours = []
    furniture = unary_union([Point(o.position[:2]).buffer(0.9) for o in scene.objects])
    for room in scene.rooms:
        spot = polylabel(Polygon(room.polygon).difference(furniture), tolerance=0.05)
        u, v = (round(c) for c in top.to_pixel(spot.x, spot.y))
        assert labels[v, u] == floor, f"room {room.id} is not visible at pixel {(u, v)}"
        colours.append(tuple(_image(out, "renders/top.png")[v, u]))
    assert colours[0] != colours[1]  # grey tile and oak floor


def test_top_view_depth_is_in_millimetres(rendered_two_room) -> None:
    out, summary = rendered_two_room
    depth = _image(out, "renders/top_depth.png")
    assert depth.dtype == np.uint16
    top = _top(summary)
    camera_z = summary.views[0]["camera"]["position"][2]
    u, v = (round(c) for c in top.to_pixel(1.7, 1.0))  # the 0.75 m high table (not its cube)
    assert depth[v, u] == pytest.approx((camera_z - 0.75) * 1000, abs=15)
    u, v = (round(c) for c in top.to_pixel(6.5, 4.5))  # bare living-room floor
    assert depth[v, u] == pytest.approx(camera_z * 1000, abs=15)
    assert depth[0, 0] == 0  # nothing beyond the house: the far plane reads 0


def test_segmentation_labels_name_the_objects(rendered_two_room) -> None:
    out, summary = rendered_two_room
    legend = json.loads((out / "renders" / "segmentation.json").read_text())["labels"]
    by_name = {e["name"]: e["label"] for e in legend if e["kind"] != "structure"}
    assert {"crate", "table", "cube", "kitchen_door", "living_window"} <= set(by_name)
    labels = _image(out, "renders/top_seg.png")
    top = _top(summary)
    for name, (x, y) in {"table": (1.6, 1.0), "crate": (5.5, 2.5), "cube": (2.0, 1.2)}.items():
        u, v = (round(c) for c in top.to_pixel(x, y))
        assert labels[v, u] == by_name[name], name
    close = _image(out, "renders/objects/table_seg.png")
    assert by_name["table"] in close and by_name["cube"] in close


def test_room_views_look_at_their_room(rendered_two_room) -> None:
    out, summary = rendered_two_room
    legend = json.loads((out / "renders" / "segmentation.json").read_text())["labels"]
    by_name = {e["name"]: e["label"] for e in legend if e["kind"] != "structure"}
    kitchen = _image(out, "renders/rooms/kitchen_seg.png")
    living = _image(out, "renders/rooms/living_seg.png")
    assert (kitchen == by_name["table"]).mean() > 0.02  # the furniture is in view
    assert (living == by_name["crate"]).sum() >= 20  # a small box far off at 160 x 120
    for view in summary.views[1:3]:
        assert view["camera"]["position"][2] == pytest.approx(1.6)


def test_no_depth_or_segmentation_unless_asked(two_room_folder) -> None:
    from holomj.render import render_folder

    summary = render_folder(two_room_folder, views="rooms", width=64, height=48, shadows=False)
    assert all(v["depth"] is None and v["segmentation"] is None for v in summary.views)
    assert summary.plan is None and summary.legend is None
    written = sorted(p.name for p in (two_room_folder / "renders").rglob("*.png"))
    assert written == ["kitchen.png", "living.png"]
