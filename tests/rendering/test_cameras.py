"""Automatic camera placement: pure geometry, no rendering."""

from __future__ import annotations

import math

import pytest
from shapely.geometry import LineString, Point, Polygon

from holomj.rendering.cameras import (
    CORNER_INSET_M,
    EYE_HEIGHT_M,
    MIN_VIEW_DISTANCE_M,
    TOP_MARGIN_M,
    Mass,
    closeup_camera,
    furniture_centre,
    room_camera,
    top_camera,
)

SQUARE = [(0.0, 0.0), (4.0, 0.0), (4.0, 3.0), (0.0, 3.0)]
L_SHAPE = [(4.0, 0.0), (7.0, 0.0), (7.0, 5.0), (0.0, 5.0), (0.0, 3.0), (4.0, 3.0)]


def test_top_camera_maps_bounds_inside_the_image_with_a_margin() -> None:
    cam = top_camera((0.0, 0.0, 7.0, 5.0), 640, 480, wall_height=2.7)
    u0, v0 = cam.to_pixel(0.0, 0.0)
    u1, v1 = cam.to_pixel(7.0, 5.0)
    assert u0 < u1 and v0 > v1  # +X right, +Y up
    margin_px = TOP_MARGIN_M / cam.metres_per_pixel
    assert min(u0, 640 - u1, v1, 480 - v0) >= margin_px - 1e-6
    assert cam.to_pixel(3.5, 2.5) == pytest.approx((320.0, 240.0))
    assert cam.pose().orthographic and cam.pose().fovy == pytest.approx(cam.height_m)
    assert cam.pose().position[2] > 2.7  # above the walls


def test_top_camera_fits_a_long_house_by_its_width() -> None:
    cam = top_camera((0.0, 0.0, 30.0, 2.0), 400, 400, wall_height=3.0)
    assert cam.to_pixel(0.0, 1.0)[0] >= 0 and cam.to_pixel(30.0, 1.0)[0] <= 400
    assert cam.height_m == pytest.approx(30.0 + 2 * TOP_MARGIN_M)


def test_furniture_centre_is_mass_weighted_and_ignores_other_rooms() -> None:
    shape = Polygon(SQUARE)
    masses = [Mass((1.0, 1.0, 0.4), 30.0), Mass((3.0, 1.0, 0.4), 10.0), Mass((9, 9, 0), 500)]
    x, y, z = furniture_centre(shape, masses)
    assert (x, y, z) == pytest.approx((1.5, 1.0, 0.4))
    assert furniture_centre(shape, [Mass((9.0, 9.0, 0.0), 1.0)]) is None


def test_room_camera_stands_in_a_corner_at_eye_height_looking_at_the_furniture() -> None:
    masses = [Mass((3.0, 1.0, 0.5), 20.0)]
    pose = room_camera("render/room/a", SQUARE, masses, wall_height=2.7)
    x, y, z = pose.position
    assert z == pytest.approx(EYE_HEIGHT_M)
    walls = Polygon(SQUARE).exterior
    assert walls.distance(Point(x, y)) == pytest.approx(CORNER_INSET_M, abs=1e-6)
    corner = min(SQUARE, key=lambda p: math.dist(p, (x, y)))
    assert math.dist(corner, (x, y)) == pytest.approx(CORNER_INSET_M * math.sqrt(2))
    assert pose.target[:2] == pytest.approx((3.0, 1.0))
    assert math.dist((x, y), pose.target[:2]) >= MIN_VIEW_DISTANCE_M  # not the corner at (4, 0)


def test_room_camera_in_an_l_shaped_room_sees_its_target() -> None:
    masses = [Mass((5.5, 2.5, 0.3), 20.0)]
    pose = room_camera("render/room/l", L_SHAPE, masses, wall_height=2.7)
    shape = Polygon(L_SHAPE)
    assert shape.contains(Point(pose.position[:2]))
    assert LineString([pose.position[:2], pose.target[:2]]).within(shape.buffer(1e-6))
    reflex = (4.0, 3.0)
    assert math.dist(pose.position[:2], reflex) > 1.0
    # the corner in the crate's own wing sees more floor than the far end of the other wing
    assert pose.position[0] > 4.0


def test_room_camera_without_furniture_looks_at_the_room_centre() -> None:
    pose = room_camera("render/room/a", SQUARE, [], wall_height=2.4)
    assert pose.target[:2] == pytest.approx((2.0, 1.5))
    assert pose.position[2] == pytest.approx(min(EYE_HEIGHT_M, 2.4 - 0.2))


def test_closeup_camera_frames_the_object_and_stays_in_the_room() -> None:
    room = Polygon(SQUARE)
    centre = (0.5, 1.5, 0.8)
    pose = closeup_camera("render/object/shelf", centre, 0.4, front_deg=180.0, room=room)
    assert room.contains(Point(pose.position[:2]))  # the front (-X) is outside: it turned
    assert pose.target == centre
    assert math.dist(pose.position, centre) >= 0.4 / math.sin(math.radians(22.5))
    assert pose.position[2] > centre[2]


def test_closeup_camera_prefers_the_front() -> None:
    room = Polygon([(-5, -5), (5, -5), (5, 5), (-5, 5)])
    pose = closeup_camera("c", (0.0, 0.0, 0.5), 0.3, front_deg=90.0, room=room)
    assert pose.position[1] > 0.5 and abs(pose.position[0]) < 1e-9
