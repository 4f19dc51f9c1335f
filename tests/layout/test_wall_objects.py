"""Wall objects hang on the wall face, clear of openings, furniture and each other; lights."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from shapely.geometry import Polygon, box

from holomj.layout.wall_objects import (
    FloorItem,
    WallObjectRequest,
    WallPlacement,
    ceiling_lights,
    default_bottom,
    place_wall_objects,
)
from holomj.spec.scene import Door, Room, SceneSpec, Window
from holomj.spec.walls import Wall, derive_walls, find_wall_for_opening

THICK = 0.1


def _rect(rid: str, rtype: str, x0: float, y0: float, x1: float, y1: float) -> Room:
    return Room(id=rid, type=rtype, polygon=[(x0, y0), (x1, y0), (x1, y1), (x0, y1)])


ROOMS = [_rect("living", "living_room", 0, 0, 5, 4), _rect("bed", "bedroom", 5, 0, 8, 4)]
DOORS = [
    Door(id="front", rooms=["living"], position=(2.0, 0.0)),
    Door(id="inner", rooms=["bed", "living"], position=(5.0, 2.0)),
]
WINDOWS = [Window(id="win", rooms=["living"], position=(0.0, 2.0), width=1.2, height=1.2)]


def _wall_of(walls: list[Wall], wall_id: str) -> Wall:
    return next(w for w in walls if w.id == wall_id)


def _inward(wall: Wall, room: str) -> tuple[float, float]:
    if wall.exterior:
        return (-wall.outward[0], -wall.outward[1])
    nx, ny = wall.normal
    return (nx, ny) if wall.left_room == room else (-nx, -ny)


def _wall_rect(p: WallPlacement, size, walls) -> tuple[Wall, float, float, float, float]:
    wall = _wall_of(walls, p.wall_id)
    t, _ = wall.locate((p.x, p.y))
    return wall, t - size[0] / 2, t + size[0] / 2, p.z, p.z + size[2]


def _check_on_face(p: WallPlacement, size, walls, room: str = "living") -> None:
    wall = _wall_of(walls, p.wall_id)
    _, off = wall.locate((p.x, p.y))
    face = 0.0 if wall.exterior else THICK / 2
    inward = _inward(wall, room)
    # Distance from the wall line, measured into the room: face offset plus half the depth.
    sign = 1.0 if inward == pytest.approx(wall.normal) else -1.0
    assert sign * off == pytest.approx(face + size[1] / 2, abs=1e-3)
    yaw = math.radians(p.yaw_deg)
    assert (math.cos(yaw), math.sin(yaw)) == pytest.approx(inward, abs=1e-6)


def test_default_heights_by_kind() -> None:
    assert default_bottom("painting", 0.6) == pytest.approx(1.2)
    assert default_bottom("clock", 0.3) == pytest.approx(1.65)
    assert default_bottom("wall_cabinet", 0.7) == pytest.approx(1.45)
    assert default_bottom("mirror", 0.8) == pytest.approx(1.0)


def test_painting_sits_on_the_face_facing_the_room() -> None:
    walls = derive_walls(ROOMS)
    size = (0.8, 0.04, 0.6)
    req = WallObjectRequest(id="art", size=size, kind="painting")
    placed, unplaced = place_wall_objects(
        ROOMS[0], walls, DOORS, WINDOWS, [], [req], np.random.default_rng(0)
    )
    assert unplaced == []
    (p,) = placed
    assert p.z == pytest.approx(1.5 - 0.3)
    _check_on_face(p, size, walls)
    obj = p.scene_object("builtin:box", scale=size)
    assert obj.static and obj.room == "living"


def test_interior_wall_face_is_half_the_thickness_in() -> None:
    walls = derive_walls(ROOMS)
    # Only the shared wall is free: fill the exterior ones with tall furniture.
    furniture = [
        ("w_s", box(0.1, 0.1, 4.9, 0.6), 2.4),
        ("w_n", box(0.1, 3.4, 4.9, 3.9), 2.4),
        ("w_w", box(0.1, 0.1, 0.6, 3.9), 2.4),
    ]
    req = WallObjectRequest(id="mirror", size=(0.5, 0.03, 0.6), kind="mirror")
    placed, unplaced = place_wall_objects(
        ROOMS[0], walls, DOORS, [], furniture, [req], np.random.default_rng(0)
    )
    assert unplaced == []
    (p,) = placed
    wall = _wall_of(walls, p.wall_id)
    assert not wall.exterior
    assert p.x == pytest.approx(5.0 - THICK / 2 - 0.015)
    assert p.yaw_deg == pytest.approx(180.0)
    _check_on_face(p, (0.5, 0.03, 0.6), walls)
    # Not over the door between the rooms (y 1.5 .. 2.5 plus frame).
    assert not (p.y + 0.25 > 1.45 and p.y - 0.25 < 2.55)


def test_tv_centred_above_its_stand() -> None:
    walls = derive_walls(ROOMS)
    stand = ("stand", box(2.6, 3.5, 4.0, 3.95), 0.5)
    size = (1.2, 0.08, 0.7)
    req = WallObjectRequest(id="tv", size=size, kind="television", above="stand")
    placed, unplaced = place_wall_objects(
        ROOMS[0], walls, DOORS, WINDOWS, [stand], [req], np.random.default_rng(0)
    )
    assert unplaced == []
    (p,) = placed
    assert p.x == pytest.approx(3.3)
    assert p.y == pytest.approx(4.0 - 0.04)
    assert p.z == pytest.approx(0.5 + 0.1)
    assert p.yaw_deg == pytest.approx(-90.0)
    _check_on_face(p, size, walls)


def test_painting_above_a_sofa_keeps_its_default_height() -> None:
    walls = derive_walls(ROOMS)
    sofa = FloorItem("sofa", box(1.0, 3.1, 3.2, 4.0), 0.85)
    req = WallObjectRequest(id="art", size=(1.0, 0.04, 0.5), above="sofa")
    placed, _ = place_wall_objects(ROOMS[0], walls, [], [], [sofa], [req], np.random.default_rng(0))
    assert placed[0].x == pytest.approx(2.1)
    assert placed[0].z == pytest.approx(1.25)


def test_above_a_door_or_missing_object_is_reported() -> None:
    walls = derive_walls(ROOMS)
    cabinet = ("low", box(1.5, 0.05, 2.5, 0.5), 0.3)  # in front of the front door
    reqs = [
        WallObjectRequest(
            id="clock", size=(0.4, 0.05, 0.4), kind="clock", above="low", height_m=1.0
        ),
        WallObjectRequest(id="ghost", size=(0.4, 0.05, 0.4), above="nothing"),
    ]
    placed, unplaced = place_wall_objects(
        ROOMS[0], walls, DOORS, WINDOWS, [cabinet], reqs, np.random.default_rng(0)
    )
    assert placed == []
    reasons = {u.id: u.reason for u in unplaced}
    assert "door front" in reasons["clock"]
    assert "unknown floor object 'nothing'" in reasons["ghost"]


def test_tall_furniture_blocks_the_wall_behind_it() -> None:
    room = _rect("r", "bedroom", 0, 0, 3, 3)
    walls = derive_walls([room])
    wardrobes = [
        ("ward_s", box(0, 0, 3, 0.6), 2.2),
        ("ward_w", box(0, 0, 0.6, 3), 2.2),
        ("ward_e", box(2.4, 0, 3, 3), 2.2),
    ]
    req = WallObjectRequest(id="art", size=(0.6, 0.03, 0.5))
    placed, unplaced = place_wall_objects(
        room, walls, [], [], wardrobes, [req], np.random.default_rng(0)
    )
    assert unplaced == []
    assert placed[0].y == pytest.approx(3.0 - 0.015)  # the only free wall: north
    # A wall cabinet above the wardrobes' height still fits on their walls.
    high = WallObjectRequest(id="shelf", size=(0.6, 0.2, 0.3), height_m=2.3)
    placed, unplaced = place_wall_objects(
        room, walls, [], [], wardrobes, [high], np.random.default_rng(0)
    )
    assert unplaced == [] and placed


def test_reaching_the_ceiling_is_reported() -> None:
    room = _rect("r", "bedroom", 0, 0, 3, 3)
    req = WallObjectRequest(id="tall", size=(0.6, 0.03, 1.5), height_m=1.5)
    placed, unplaced = place_wall_objects(
        room, derive_walls([room]), [], [], [], [req], np.random.default_rng(0)
    )
    assert placed == [] and "wall top" in unplaced[0].reason


@settings(max_examples=60, deadline=None)
@given(
    seed=st.integers(0, 2**32 - 1),
    sizes=st.lists(
        st.tuples(st.floats(0.2, 1.6), st.floats(0.02, 0.4), st.floats(0.2, 0.9)),
        min_size=1,
        max_size=14,
    ),
    kinds=st.lists(
        st.sampled_from(["painting", "mirror", "clock", "wall_cabinet", "shelf"]),
        min_size=14,
        max_size=14,
    ),
)
def test_wall_objects_never_overlap_openings_or_each_other(seed, sizes, kinds) -> None:
    walls = derive_walls(ROOMS)
    reqs = [WallObjectRequest(id=f"o{i}", size=size, kind=kinds[i]) for i, size in enumerate(sizes)]
    placed, unplaced = place_wall_objects(
        ROOMS[0], walls, DOORS, WINDOWS, [], reqs, np.random.default_rng(seed)
    )
    assert len(placed) + len(unplaced) == len(reqs)
    assert all(u.reason for u in unplaced)
    size_of = {r.id: r.size for r in reqs}
    openings = []
    for opening in [*DOORS, *WINDOWS]:
        width = opening.effective_width if isinstance(opening, Door) else opening.width
        wall, t = find_wall_for_opening(walls, opening.rooms, opening.position, width)
        if isinstance(opening, Door):
            z0, z1 = 0.0, opening.height + 0.05
        else:
            z0, z1 = opening.base_height - 0.05, opening.base_height + opening.height + 0.05
        openings.append((wall.id, t - width / 2 - 0.05, t + width / 2 + 0.05, z0, z1))
    boxes = []
    for p in placed:
        size = size_of[p.id]
        _check_on_face(p, size, walls)
        wall, t0, t1, z0, z1 = _wall_rect(p, size, walls)
        assert t0 >= 0.1 - 1e-6 and t1 <= wall.length - 0.1 + 1e-6
        assert z1 <= 2.7 - 0.05 + 1e-9
        for wid, a0, a1, b0, b1 in openings:
            if wid == wall.id:
                assert not (t0 < a1 - 1e-9 and a0 < t1 - 1e-9 and z0 < b1 - 1e-9 and b0 < z1 - 1e-9)
        yaw = math.radians(p.yaw_deg)
        c, s = math.cos(yaw), math.sin(yaw)
        hx, hy = size[1] / 2, size[0] / 2
        corners = [
            (p.x + c * dx - s * dy, p.y + s * dx + c * dy)
            for dx, dy in [(-hx, -hy), (hx, -hy), (hx, hy), (-hx, hy)]
        ]
        foot = Polygon(corners)
        assert ROOMS[0].polygon and Polygon(ROOMS[0].polygon).buffer(1e-3).contains(foot)
        boxes.append((foot, z0, z1))
    for i in range(len(boxes)):
        for j in range(i + 1, len(boxes)):
            a, b = boxes[i], boxes[j]
            if a[1] < b[2] - 1e-9 and b[1] < a[2] - 1e-9:
                assert a[0].intersection(b[0]).area < 1e-6


def test_same_seed_same_placements() -> None:
    walls = derive_walls(ROOMS)
    reqs = [WallObjectRequest(id=f"p{i}", size=(0.5, 0.03, 0.4)) for i in range(5)]
    a = place_wall_objects(ROOMS[0], walls, DOORS, WINDOWS, [], reqs, np.random.default_rng(9))
    b = place_wall_objects(ROOMS[0], walls, DOORS, WINDOWS, [], reqs, np.random.default_rng(9))
    assert a == b


def test_ceiling_lights() -> None:
    rooms = [
        _rect("small", "bedroom", 0, 0, 4, 3),
        _rect("big", "living_room", 4, 0, 10, 6),
        Room(id="ell", polygon=[(0, 3), (4, 3), (4, 9), (-4, 9), (-4, 7), (0, 7)]),
    ]
    lights = ceiling_lights(rooms, 2.8)
    by_room: dict[str, list] = {}
    for light in lights:
        by_room.setdefault(light.id.split("_")[1], []).append(light)
    assert len(by_room["small"]) == 1 and len(by_room["big"]) == 4
    assert by_room["small"][0].position == pytest.approx((2.0, 1.5, 2.5))
    assert sum(li.energy for li in by_room["big"]) > by_room["small"][0].energy
    for room in rooms:
        poly = Polygon(room.polygon)
        for light in by_room[room.id]:
            assert poly.contains(
                Polygon(
                    [
                        *[
                            (light.position[0] + dx, light.position[1] + dy)
                            for dx, dy in [(0, 0), (1e-3, 0), (0, 1e-3)]
                        ]
                    ]
                )
            )
            assert light.kind == "point"
    SceneSpec(rooms=rooms[:2], lights=[li for li in lights if "ell" not in li.id])


def test_faced_wall_object_hangs_on_the_line_of_sight() -> None:
    walls = derive_walls(ROOMS)
    chair = FloorItem("chair", box(2.75, 1.5, 3.25, 2.0), 0.9, front=(0.0, 1.0))  # looks north
    req = WallObjectRequest(id="mirror", size=(0.6, 0.05, 0.9), kind="mirror", faced_by="chair")
    placed, unplaced = place_wall_objects(
        ROOMS[0], walls, DOORS, WINDOWS, [chair], [req], np.random.default_rng(0)
    )
    assert unplaced == []
    (p,) = placed
    assert p.x == pytest.approx(3.0, abs=0.05) and p.y > 3.8  # on the north wall, ahead of it


def test_a_deep_wall_object_keeps_clear_beside_a_door_and_a_flat_one_need_not() -> None:
    room = _rect("r", "kitchen", 0, 0, 4.0, 3.0)
    walls = derive_walls([room])
    door = Door(id="d", rooms=["r"], position=(1.0, 0.0), width=0.9)
    face_of_door = next(w for w in walls if w.locate((1.0, 0.0))[1] == pytest.approx(0.0, abs=0.06))
    # the wall left: the door's, right of the door; tall wardrobes take the others
    tall = [
        ("w1", box(0.05, 2.3, 3.95, 2.95), 2.2),
        ("w2", box(0.05, 0.05, 0.7, 2.95), 2.2),
        ("w3", box(3.3, 0.05, 3.95, 2.95), 2.2),
    ]
    cabinet = WallObjectRequest(id="cab", size=(0.8, 0.35, 0.7), kind="wall_cabinet")
    painting = WallObjectRequest(id="pic", size=(0.8, 0.03, 0.6), kind="painting", height_m=1.45)
    rng = np.random.default_rng(0)
    for request, clear in ((cabinet, 0.6), (painting, 0.0)):
        placed, _ = place_wall_objects(room, walls, [door], [], tall, [request], rng)
        assert len(placed) == 1 and placed[0].wall_id == face_of_door.id
        t, _ = face_of_door.locate((placed[0].x, placed[0].y))
        t_door, _ = face_of_door.locate(door.position)
        gap = abs(t - t_door) - request.size[0] / 2 - door.width / 2
        assert gap >= clear - 1e-6


def _hang_in(
    room: Room, floor: list, request: WallObjectRequest, windows: tuple = (), seed: int = 0
) -> tuple[list, list]:
    """Place one wall object in a room of its own (no doors)."""
    walls = derive_walls([room])
    rng = np.random.default_rng(seed)
    return place_wall_objects(room, walls, [], list(windows), floor, [request], rng)


def test_a_wall_cabinet_hangs_over_the_counter_run_not_over_the_floor() -> None:
    room = _rect("r", "kitchen", 0, 0, 4.0, 3.0)
    counters = [
        ("counter", box(0.05, 0.6, 0.65, 2.4), 0.9),
        ("table", box(1.8, 1.0, 2.6, 2.0), 0.75),
    ]
    cabinet = WallObjectRequest(id="cab", size=(0.8, 0.35, 0.7), kind="wall_cabinet")
    for seed in range(5):
        placed, _ = _hang_in(room, counters, cabinet, seed=seed)
        assert len(placed) == 1
        p = placed[0]
        assert p.x < 0.4 and 0.6 + 0.4 - 1e-6 <= p.y <= 2.4 - 0.4 + 1e-6, p  # over the counter


def test_an_optional_wall_cabinet_that_would_narrow_the_way_is_left_out() -> None:
    room = _rect("r", "kitchen", 0, 0, 4.0, 3.0)
    # furniture 0.5 m in front of every wall: no counter to hang over, no wall with room before it
    ring = [
        ("s", box(0.6, 0.6, 3.4, 0.9), 0.75),
        ("n", box(0.6, 2.1, 3.4, 2.4), 0.75),
        ("w", box(0.6, 0.9, 0.9, 2.1), 0.75),
        ("e", box(3.1, 0.9, 3.4, 2.1), 0.75),
    ]
    size = (0.8, 0.35, 0.7)
    optional = WallObjectRequest(id="cab", size=size, kind="wall_cabinet", optional=True)
    placed, unplaced = _hang_in(room, ring, optional)
    assert placed == [] and "narrow the way" in unplaced[0].reason
    asked = WallObjectRequest(id="cab", size=size, kind="wall_cabinet")
    placed, _ = _hang_in(room, ring, asked)
    assert len(placed) == 1  # asked for: it still hangs
    painting = WallObjectRequest(id="pic", size=(0.8, 0.03, 0.6), kind="painting", optional=True)
    placed, _ = _hang_in(room, ring, painting)
    assert len(placed) == 1  # flat: it narrows nothing


def test_a_wall_cabinet_over_open_floor_does_not_cut_off_the_corner_beside_it() -> None:
    """Only the west wall is free (a fridge in its south corner, a counter under a window along
    the north wall, wardrobes on the others): a cabinet in its middle would end 0.2 m short of
    the counter and cut off the corner behind it, so the cabinet, not asked for, is left out;
    one asked for still hangs."""
    room = _rect("r", "kitchen", 0, 0, 4.0, 3.2)
    floor = [
        ("counter", box(0.75, 2.55, 4.0, 3.15), 0.9),
        ("fridge", box(0.05, 0.05, 0.75, 0.75), 1.8),
        ("table", box(2.4, 0.9, 3.2, 1.9), 0.75),
        ("wardrobes_s", box(0.8, 0.05, 4.0, 0.65), 2.0),
        ("wardrobes_e", box(3.4, 0.65, 4.0, 2.5), 2.0),
    ]
    window = Window(id="w", rooms=["r"], position=(2.4, 3.2), width=3.0, height=1.2)
    size = (0.8, 0.35, 0.7)
    for optional in (True, False):
        request = WallObjectRequest(id="cab", size=size, kind="wall_cabinet", optional=optional)
        placed, unplaced = _hang_in(room, floor, request, windows=(window,))
        if optional:
            assert placed == [] and "cut off a corner" in unplaced[0].reason
        else:
            assert len(placed) == 1 and placed[0].x < 0.4  # on the west wall all the same
