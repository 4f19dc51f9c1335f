"""Walls derived from rooms: shared stretches once, exterior stretches once."""

from __future__ import annotations

import math
from types import SimpleNamespace

import pytest

from holomj.errors import SpecError
from holomj.spec.walls import derive_walls, find_wall_for_opening, room_polygon


def _rooms(*polygons):
    return [SimpleNamespace(id=f"r{i}", polygon=p) for i, p in enumerate(polygons)]


def _total(walls, exterior: bool) -> float:
    return sum(w.length for w in walls if w.exterior == exterior)


def test_single_room_has_four_exterior_walls() -> None:
    walls = derive_walls(_rooms([(0, 0), (4, 0), (4, 3), (0, 3)]))
    assert len(walls) == 4
    assert all(w.exterior for w in walls)
    assert _total(walls, True) == pytest.approx(14.0)


def test_exterior_walls_point_away_from_their_room() -> None:
    walls = derive_walls(_rooms([(0, 0), (4, 0), (4, 3), (0, 3)]))
    for wall in walls:
        mid = wall.point_at(wall.length / 2)
        probe = (mid[0] + wall.outward[0] * 0.1, mid[1] + wall.outward[1] * 0.1)
        assert not (0 < probe[0] < 4 and 0 < probe[1] < 3)


def test_partly_shared_edges_split_into_interior_and_exterior() -> None:
    kitchen = [(0, 0), (4, 0), (4, 3), (0, 3)]
    living = [(4, 0), (7, 0), (7, 5), (0, 5), (0, 3), (4, 3)]  # L-shape wrapping the kitchen
    walls = derive_walls(_rooms(kitchen, living))
    interior = [w for w in walls if not w.exterior]
    assert len(interior) == 2
    assert _total(walls, False) == pytest.approx(7.0)
    # Perimeter of the union (7 x 5 rectangle).
    assert _total(walls, True) == pytest.approx(24.0)


def test_three_rooms_in_a_row_with_unequal_edges() -> None:
    a = [(0, 0), (3, 0), (3, 4), (0, 4)]
    b = [(3, 0), (6, 0), (6, 2), (3, 2)]
    c = [(3, 2), (6, 2), (6, 4), (3, 4)]
    walls = derive_walls(_rooms(a, b, c))
    shared = {w.rooms: w.length for w in walls if not w.exterior}
    assert shared == {
        ("r0", "r1"): pytest.approx(2.0),
        ("r0", "r2"): pytest.approx(2.0),
        ("r1", "r2"): pytest.approx(3.0),
    }


def test_clockwise_input_gives_the_same_walls() -> None:
    ccw = derive_walls(_rooms([(0, 0), (4, 0), (4, 3), (0, 3)]))
    cw = derive_walls(_rooms([(0, 0), (0, 3), (4, 3), (4, 0)]))
    assert [(w.start, w.end) for w in ccw] == [(w.start, w.end) for w in cw]


def test_rotated_rooms() -> None:
    c, s = math.cos(0.5), math.sin(0.5)
    square = [(0, 0), (4, 0), (4, 4), (0, 4)]
    rot = [(x * c - y * s, x * s + y * c) for x, y in square]
    walls = derive_walls(_rooms(rot))
    assert len(walls) == 4 and _total(walls, True) == pytest.approx(16.0)


def test_find_wall_for_opening() -> None:
    walls = derive_walls(_rooms([(0, 0), (4, 0), (4, 3), (0, 3)], [(4, 0), (8, 0), (8, 3), (4, 3)]))
    wall, t = find_wall_for_opening(walls, ["r1", "r0"], (4.0, 1.0), 1.0)
    assert wall.rooms == ("r0", "r1")
    assert t == pytest.approx(1.0)
    with pytest.raises(SpecError, match="does not fit"):
        find_wall_for_opening(walls, ["r0", "r1"], (4.0, 0.3), 1.0)


@pytest.mark.parametrize(
    ("points", "message"),
    [
        ([(0, 0), (1, 1), (1, 0), (0, 1)], "intersects itself"),
        ([(0, 0), (0, 0), (1, 0), (0, 1)], "coincide"),
        ([(0, 1), (1, 0), (0, 0), (0, 1e-12 + 1)], "vertices 3 and 0 coincide"),
        ([(0, 0), (4, 0), (4, 4), (2, 1e-13), (0, 4)], "vertex 3 touches edge 0-1"),
        ([(0, 0), (4, 0), (4, 4), (1e-9, 1e-9), (0, 4)], "vertices 0 and 3 coincide"),
        ([(0, 0), (0.1, 0), (0, 0.1)], "area"),
        ([(0, 0), (1e5, 0), (0, 1)], "10 km"),
    ],
)
def test_bad_room_polygons(points, message) -> None:
    with pytest.raises(SpecError, match=message):
        room_polygon(points)


def test_a_ring_may_repeat_its_first_vertex_exactly() -> None:
    assert room_polygon([(0, 0), (2, 0), (2, 2), (0, 2), (0, 0)]).area == pytest.approx(4.0)
