"""The annotated plan: rooms, objects, doors and windows drawn where they are."""

from __future__ import annotations

import numpy as np
import pytest
from PIL import Image
from shapely.geometry import Point, Polygon, box

from holomj.rendering.cameras import top_camera
from holomj.rendering.plan_view import (
    DOOR_COLOR,
    FURNITURE_COLOR,
    ROOM_COLOR,
    SMALL_COLOR,
    WINDOW_COLOR,
    PlanViewObject,
    _label_spot,
    _scale_bar_metres,
    draw_plan,
    openings,
)


def _near(pixels: np.ndarray, at: tuple[float, float], color: tuple[int, ...], r: int = 2) -> bool:
    u, v = round(at[0]), round(at[1])
    patch = pixels[max(v - r, 0) : v + r + 1, max(u - r, 0) : u + r + 1].reshape(-1, 3)
    return bool((np.abs(patch.astype(int) - np.array(color[:3])).max(axis=1) <= 10).any())


@pytest.fixture
def plan(two_room_scene):
    camera = top_camera((-0.2, -0.2, 7.2, 5.2), 640, 480, two_room_scene.wall_height)
    objects = [
        PlanViewObject("table", box(1.4, 0.8, 2.6, 1.6), small=False),
        PlanViewObject("cube", box(1.95, 1.15, 2.05, 1.25), small=True),
    ]
    white = Image.new("RGB", (640, 480), "white")
    image = draw_plan(white, camera, two_room_scene, objects)
    return np.asarray(image), camera


def test_openings_lie_on_their_walls(two_room_scene) -> None:
    found = {o.id: o for o in openings(two_room_scene)}
    assert found["kitchen_door"].kind == "door"
    assert found["kitchen_door"].start == pytest.approx((1.5, 3.0))
    assert found["kitchen_door"].end == pytest.approx((2.5, 3.0))
    front = found["front_door"]  # 1.8 m double door on the x = 7 wall
    assert sorted([front.start[1], front.end[1]]) == pytest.approx([1.1, 2.9])
    assert found["living_window"].kind == "window"


def test_doors_windows_and_objects_are_drawn_in_place(plan) -> None:
    pixels, camera = plan
    assert _near(pixels, camera.to_pixel(2.0, 3.0), DOOR_COLOR)
    assert _near(pixels, camera.to_pixel(7.0, 2.0), DOOR_COLOR)
    assert _near(pixels, camera.to_pixel(0.0, 1.5), WINDOW_COLOR)
    assert _near(pixels, camera.to_pixel(3.0, 5.0), WINDOW_COLOR)
    assert _near(pixels, camera.to_pixel(2.6, 1.2), FURNITURE_COLOR)  # table's right edge
    assert _near(pixels, camera.to_pixel(2.05, 1.2), SMALL_COLOR)  # the cube on it
    assert _near(pixels, camera.to_pixel(5.5, 0.0), ROOM_COLOR)  # a room outline
    assert not _near(pixels, camera.to_pixel(5.5, 4.0), FURNITURE_COLOR, r=1)


def test_room_names_are_written_away_from_the_furniture(plan, two_room_scene) -> None:
    pixels, camera = plan
    taken = box(1.4, 0.8, 2.6, 1.6).buffer(0.15)
    for room in two_room_scene.rooms:
        x, y = _label_spot(Polygon(room.polygon), taken)
        assert Polygon(room.polygon).contains(Point(x, y)) and not taken.contains(Point(x, y))
        u, v = (round(c) for c in camera.to_pixel(x, y))
        patch = pixels[v - 12 : v + 12, u - 40 : u + 40]
        assert (patch.max(axis=2) < 90).sum() > 30, f"no name written for {room.id}"


def test_legend_strip_goes_below_the_view(plan) -> None:
    pixels, _ = plan
    assert pixels.shape[1] == 640 and 480 + 10 < pixels.shape[0] < 480 + 60
    strip = pixels[480:]
    for color in (FURNITURE_COLOR, SMALL_COLOR, DOOR_COLOR, WINDOW_COLOR):
        assert (np.abs(strip.astype(int) - np.array(color[:3])).max(axis=2) <= 10).sum() > 20


@pytest.mark.parametrize(("width", "bar"), [(8.0, 1.0), (30.0, 5.0), (120.0, 20.0), (3.0, 0.5)])
def test_scale_bar_lengths_are_round(width: float, bar: float) -> None:
    assert _scale_bar_metres(width) == pytest.approx(bar)
