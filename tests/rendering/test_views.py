"""Rendered images of the two-room scene: not blank, every room seen, depth and labels right."""

from __future__ import annotations

import io

import numpy as np
import pytest
from PIL import Image
from shapely.geometry import Point, Polygon
from shapely.ops import polylabel, unary_union

from holomj.mjcf.compiler import CompiledScene
from holomj.rendering import Rendering, RenderOptions, render_scene
from holomj.rendering.cameras import TopCamera
from tests.rendering.conftest import SMALL


def _image(rendering: Rendering, name: str) -> np.ndarray:
    return np.asarray(Image.open(io.BytesIO(rendering.images[name])))


def _top(rendering: Rendering) -> TopCamera:
    top = rendering.top
    assert top is not None
    return TopCamera(tuple(top["centre"]), top["height_m"], top["width_px"], top["height_px"], 0)


def _legend(rendering: Rendering) -> list[dict]:
    assert rendering.legend is not None
    return rendering.legend["labels"]


def test_every_view_is_made_and_not_blank(rendered_two_room: Rendering) -> None:
    rendering = rendered_two_room
    kinds = [(v["kind"], v["subject"]) for v in rendering.views]
    assert kinds == [("top", None), ("room", "kitchen"), ("room", "living"), ("object", "table")]
    for view in rendering.views:
        pixels = _image(rendering, view["image"])
        assert pixels.shape == (SMALL[1], SMALL[0], 3)
        assert pixels.std() > 10, f"{view['image']} is blank"
        assert len(np.unique(pixels.reshape(-1, 3), axis=0)) > 20, f"{view['image']} is flat"
        for key in ("depth", "segmentation"):
            assert view[key] in rendering.images
    assert rendering.plan == "plan.png" and "plan.png" in rendering.images
    named = {v[k] for v in rendering.views for k in ("image", "depth", "segmentation")}
    assert set(rendering.images) == named | {"plan.png"}


def test_top_view_shows_every_room_floor(
    rendered_two_room: Rendering, two_room_compiled: CompiledScene
) -> None:
    rendering, scene = rendered_two_room, two_room_compiled.scene
    labels = _image(rendering, "top_seg.png")
    legend = _legend(rendering)
    floor = next(e["label"] for e in legend if e["name"] == "floor" and e["kind"] == "structure")
    top = _top(rendering)
    colours = []
    furniture = unary_union([Point(o.position[:2]).buffer(0.9) for o in scene.objects])
    for room in scene.rooms:
        spot = polylabel(Polygon(room.polygon).difference(furniture), tolerance=0.05)
        u, v = (round(c) for c in top.to_pixel(spot.x, spot.y))
        assert labels[v, u] == floor, f"room {room.id} is not visible at pixel {(u, v)}"
        colours.append(tuple(_image(rendering, "top.png")[v, u]))
    assert colours[0] != colours[1]  # grey tile and oak floor


def test_top_view_depth_is_in_millimetres(rendered_two_room: Rendering) -> None:
    rendering = rendered_two_room
    depth = _image(rendering, "top_depth.png")
    assert depth.dtype == np.uint16
    top = _top(rendering)
    camera_z = rendering.views[0]["camera"]["position"][2]
    u, v = (round(c) for c in top.to_pixel(1.7, 1.0))  # the 0.75 m high table (not its cube)
    assert depth[v, u] == pytest.approx((camera_z - 0.75) * 1000, abs=15)
    u, v = (round(c) for c in top.to_pixel(6.5, 4.5))  # bare living-room floor
    assert depth[v, u] == pytest.approx(camera_z * 1000, abs=15)
    assert depth[0, 0] == 0  # nothing beyond the house: the far plane reads 0


def test_segmentation_labels_name_the_objects(rendered_two_room: Rendering) -> None:
    rendering = rendered_two_room
    legend = _legend(rendering)
    by_name = {e["name"]: e["label"] for e in legend if e["kind"] != "structure"}
    assert {"crate", "table", "cube", "kitchen_door", "living_window"} <= set(by_name)
    labels = _image(rendering, "top_seg.png")
    top = _top(rendering)
    for name, (x, y) in {"table": (1.6, 1.0), "crate": (5.5, 2.5), "cube": (2.0, 1.2)}.items():
        u, v = (round(c) for c in top.to_pixel(x, y))
        assert labels[v, u] == by_name[name], name
    close = _image(rendering, "objects/table_seg.png")
    assert by_name["table"] in close and by_name["cube"] in close


def test_room_views_look_at_their_room(rendered_two_room: Rendering) -> None:
    rendering = rendered_two_room
    by_name = {e["name"]: e["label"] for e in _legend(rendering) if e["kind"] != "structure"}
    kitchen = _image(rendering, "rooms/kitchen_seg.png")
    living = _image(rendering, "rooms/living_seg.png")
    assert (kitchen == by_name["table"]).mean() > 0.02  # the furniture is in view
    assert (living == by_name["crate"]).sum() >= 20  # a small box far off at 160 x 120
    for view in rendering.views[1:3]:
        assert view["camera"]["position"][2] == pytest.approx(1.6)


def test_no_depth_or_segmentation_unless_asked(two_room_compiled: CompiledScene) -> None:
    options = RenderOptions(views=("rooms",), width=64, height=48, shadows=False)
    rendering = render_scene(two_room_compiled.model, two_room_compiled.scene, options)
    assert all(v["depth"] is None and v["segmentation"] is None for v in rendering.views)
    assert rendering.plan is None and rendering.legend is None and rendering.top is None
    assert sorted(rendering.images) == ["rooms/kitchen.png", "rooms/living.png"]
