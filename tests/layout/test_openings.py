"""Doors join every room to the entrance; windows use Holodeck's sizes on exterior walls only."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from shapely.affinity import rotate, translate
from shapely.geometry import Polygon, box

from holomj.errors import SpecError
from holomj.layout.door_window_placement import (
    WINDOW_BASE_HEIGHT_M,
    WINDOW_SIZES_CM,
    WindowRequest,
    door_kind,
    place_doors,
    place_windows,
    reachable,
    window_sizes_m,
)
from holomj.layout.floorplan import RoomRequest, plan_floor
from holomj.layout.wall_objects import WallObjectRequest, ceiling_lights, place_wall_objects
from holomj.mjcf import compile_scene, names
from holomj.physics.audit import audit
from holomj.physics.scene_io import LoadedScene
from holomj.physics.smoke import simulate
from holomj.spec.scene import Door, Room, SceneObject, SceneSpec
from holomj.spec.walls import derive_walls, find_wall_for_opening


def _rect(rid: str, rtype: str, x0: float, y0: float, x1: float, y1: float) -> Room:
    return Room(id=rid, type=rtype, polygon=[(x0, y0), (x1, y0), (x1, y1), (x0, y1)])


def _apartment() -> list[Room]:
    """Living (6 x 4) with a dining room east of it, a hallway, a bedroom and a bathroom."""
    return [
        _rect("living", "living_room", 0, 0, 6, 4),
        _rect("dining", "dining_room", 6, 0, 10, 4),
        _rect("hall", "hallway", 0, 4, 3, 6.5),
        _rect("bed", "bedroom", 3, 4, 7, 7.5),
        _rect("bath", "bathroom", 7, 4, 10, 6.5),
    ]


def test_holodeck_window_size_tables_exactly() -> None:
    assert WINDOW_SIZES_CM == {
        "fixed": ((92, 120), (150, 92), (150, 120), (150, 180), (240, 120), (240, 180)),
        "hung": ((87, 160), (96, 91), (120, 160), (130, 67), (130, 87), (130, 130)),
        "slider": ((91, 92), (120, 61), (120, 91), (120, 120), (150, 92), (150, 120)),
    }
    assert window_sizes_m("hung")[0] == (0.87, 1.6)


@pytest.mark.parametrize(
    ("a", "b", "kind"),
    [
        ("bedroom", "living_room", "doorway"),
        ("bathroom", "hallway", "doorway"),
        ("kitchen", "living_room", "open"),
        ("Living Room", "dining_room", "open"),
        ("hallway", "kitchen", "doorframe"),
        ("unknown_type", "living_room", "doorway"),
    ],
)
def test_door_kind_table(a: str, b: str, kind: str) -> None:
    assert door_kind(a, b) == kind


def test_door_kind_overrides_and_bad_kind() -> None:
    assert door_kind("bedroom", "hallway", {"bedroom": "doorframe"}) == "doorframe"
    with pytest.raises(SpecError, match="unknown door kind 'gate'"):
        door_kind("bedroom", "hallway", {"bedroom": "gate"})


def test_doors_of_an_apartment() -> None:
    rooms = _apartment()
    doors = place_doors(rooms, np.random.default_rng(0), entrance="hall")
    by_rooms = {tuple(sorted(d.rooms)): d for d in doors}
    exterior = by_rooms[("hall",)]
    assert exterior.kind == "doorway" and exterior.effective_width == 1.0
    assert len(doors) == len(rooms)  # a tree plus the front door
    assert reachable(rooms, doors, "hall") == {r.id for r in rooms}
    # Living and dining are big public rooms with a 4 m shared wall: a double open passage.
    living_dining = by_rooms[("dining", "living")]
    assert living_dining.kind == "open" and living_dining.leaves == "double"
    # The bathroom is a leaf of the tree behind a hinged door swinging into it.
    bath_doors = [d for d in doors if "bath" in d.rooms]
    assert len(bath_doors) == 1 and bath_doors[0].kind == "doorway"
    assert bath_doors[0].opens_into == "bath"
    SceneSpec(rooms=rooms, doors=doors)  # every door lies on its shared wall


def test_doors_keep_clear_of_wall_ends() -> None:
    rooms = _apartment()
    walls = derive_walls(rooms)
    for seed in range(20):
        for door in place_doors(rooms, np.random.default_rng(seed), extra_doors=2):
            wall, t = find_wall_for_opening(walls, door.rooms, door.position, door.effective_width)
            assert t - door.effective_width / 2 >= 0.3 - 1e-6
            assert t + door.effective_width / 2 <= wall.length - 0.3 + 1e-6


def test_extra_doors_only_between_public_rooms() -> None:
    rooms = _apartment()
    tree = place_doors(rooms, np.random.default_rng(1))
    more = place_doors(rooms, np.random.default_rng(1), extra_doors=3)
    added = {tuple(sorted(d.rooms)) for d in more} - {tuple(sorted(d.rooms)) for d in tree}
    for pair in added:
        assert not {"bed", "bath"} & set(pair)


def test_unreachable_room_is_an_error() -> None:
    rooms = [
        _rect("a", "living_room", 0, 0, 4, 4),
        _rect("b", "bedroom", 4, 3.5, 8, 7.5),  # shares 0.5 m with a
    ]
    with pytest.raises(SpecError, match="'b' cannot be reached from 'a'"):
        place_doors(rooms, np.random.default_rng(0))


def test_entrance_without_exterior_wall_is_an_error() -> None:
    rooms = [
        _rect("n", "bedroom", 0, 6, 9, 9),
        _rect("s", "bedroom", 0, 0, 9, 3),
        _rect("w", "bedroom", 0, 3, 3, 6),
        _rect("e", "bedroom", 6, 3, 9, 6),
        _rect("core", "hallway", 3, 3, 6, 6),
    ]
    with pytest.raises(SpecError, match="'core' has no exterior wall"):
        place_doors(rooms, np.random.default_rng(0), entrance="core")


def test_reachable_follows_doors_only() -> None:
    rooms = _apartment()
    doors = [Door(id="d", rooms=["hall", "living"], position=(1.5, 4.0))]
    assert reachable(rooms, doors, "hall") == {"hall", "living"}
    assert reachable(rooms, doors, "nowhere") == set()


def test_default_windows() -> None:
    rooms = _apartment()
    rng = np.random.default_rng(4)
    doors = place_doors(rooms, rng, entrance="hall")
    windows = place_windows(rooms, doors, rng)
    SceneSpec(rooms=rooms, doors=doors, windows=windows)
    per_room = {r.id: [w for w in windows if w.rooms == [r.id]] for r in rooms}
    assert per_room["hall"] == []  # no windows in hallways
    assert per_room["living"] and per_room["bed"]
    for window in windows:
        assert (round(window.width * 100), round(window.height * 100)) in WINDOW_SIZES_CM[
            window.kind
        ]
        assert window.base_height == WINDOW_BASE_HEIGHT_M[window.kind]


def test_window_requests_direction_kind_and_base_height() -> None:
    rooms = _apartment()
    doors = place_doors(rooms, np.random.default_rng(0), entrance="hall")
    walls = derive_walls(rooms)
    windows = place_windows(
        rooms,
        doors,
        np.random.default_rng(0),
        per_room={
            "living": WindowRequest(count=2, direction="south"),
            "dining": {"count": 1, "direction": "east", "kind": "hung"},
            "bed": 1,
        },
        kind="slider",
        base_height=1.0,
    )
    assert sorted(w.rooms[0] for w in windows) == ["bed", "dining", "living", "living"]
    for window in windows:
        wall, _ = find_wall_for_opening(walls, window.rooms, window.position, window.width)
        assert wall.exterior
        assert window.base_height == 1.0
        if window.rooms == ["living"]:
            assert window.kind == "slider" and wall.outward == pytest.approx((0.0, -1.0))
        if window.rooms == ["dining"]:
            assert window.kind == "hung" and wall.outward == pytest.approx((1.0, 0.0))


def test_too_many_windows_are_reported_not_forced() -> None:
    rooms = [_rect("bath", "bathroom", 0, 0, 2.5, 2.5)]
    report: list[str] = []
    windows = place_windows(
        rooms, [], np.random.default_rng(0), per_room={"bath": 20}, kind="fixed", report=report
    )
    assert 0 < len(windows) < 20
    assert report and "does not fit" in report[0]
    SceneSpec(rooms=rooms, windows=windows)


def test_window_too_tall_for_the_wall_is_an_error() -> None:
    rooms = [_rect("a", "bedroom", 0, 0, 4, 4)]
    with pytest.raises(SpecError, match="no hung window fits"):
        place_windows(rooms, [], np.random.default_rng(0), kind="hung", base_height=2.2)
    with pytest.raises(SpecError, match="unknown room 'b'"):
        place_windows(rooms, [], np.random.default_rng(0), per_room={"b": 1})


def test_windows_fit_a_low_wall() -> None:
    rooms = [_rect("a", "living_room", 0, 0, 6, 5)]
    windows = place_windows(rooms, [], np.random.default_rng(0), wall_height=2.2)
    assert windows
    for window in windows:
        assert window.base_height + window.height <= 2.2 - 0.15 + 1e-9


@settings(max_examples=40, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), n=st.integers(2, 6))
def test_openings_never_overlap(seed: int, n: int) -> None:
    rng = np.random.default_rng(seed)
    types = ["living_room", "kitchen", "bedroom", "bathroom", "dining_room", "office"]
    reqs = [RoomRequest(id=f"r{i}", type=types[i % len(types)]) for i in range(n)]
    plan = plan_floor(reqs, rng)
    doors = place_doors(plan.rooms, rng, entrance=plan.entrance, extra_doors=1)
    per_room = {r.id: WindowRequest(count=4) for r in plan.rooms}
    windows = place_windows(plan.rooms, doors, rng, per_room=per_room)
    scene = SceneSpec(rooms=plan.rooms, doors=doors, windows=windows)
    walls = scene.walls
    spans: dict[str, list[tuple[float, float]]] = {}
    for opening in [*doors, *windows]:
        width = opening.effective_width if isinstance(opening, Door) else opening.width
        wall, t = find_wall_for_opening(walls, opening.rooms, opening.position, width)
        spans.setdefault(wall.id, []).append((t - width / 2, t + width / 2))
    for items in spans.values():
        items.sort()
        for (_, a1), (b0, _) in zip(items, items[1:]):
            assert b0 >= a1 + 0.3 - 1e-6


def _stand_against_a_wall(scene: SceneSpec, room_id: str) -> tuple[SceneObject, Polygon]:
    """A 1.2 x 0.4 x 0.5 m static box 2 cm off a wall face, in the widest stretch between
    the openings of the room's walls."""
    walls = scene.walls
    spans: dict[str, list[tuple[float, float]]] = {}
    for item in [*scene.doors, *scene.windows]:
        width = item.effective_width if isinstance(item, Door) else item.width
        wall, t = find_wall_for_opening(walls, item.rooms, item.position, width)
        spans.setdefault(wall.id, []).append((t - width / 2 - 0.1, t + width / 2 + 0.1))
    best = None
    for wall in walls:
        if room_id not in wall.rooms:
            continue
        cursor = 0.2
        for a, b in sorted(spans.get(wall.id, [])) + [(wall.length - 0.2, wall.length)]:
            if best is None or a - cursor > best[0]:
                best = (a - cursor, wall, (a + cursor) / 2)
            cursor = max(cursor, b)
    assert best is not None and best[0] >= 1.3
    _, wall, t = best
    if wall.exterior:
        inward, face = (-wall.outward[0], -wall.outward[1]), 0.0
    else:
        n = wall.normal
        inward = n if wall.left_room == room_id else (-n[0], -n[1])
        face = scene.wall_thickness / 2
    mx, my = wall.point_at(t)
    off = face + 0.02 + 0.2
    centre = (mx + inward[0] * off, my + inward[1] * off)
    yaw = math.degrees(math.atan2(inward[1], inward[0]))
    stand = SceneObject(
        id="stand",
        asset="builtin:box",
        position=(centre[0], centre[1], 0.0),
        yaw_deg=yaw,
        scale=(0.4, 1.2, 0.5),
        static=True,
        room=room_id,
    )
    footprint = rotate(box(-0.2, -0.6, 0.2, 0.6), yaw, origin=(0, 0))
    return stand, translate(footprint, *centre)


def test_end_to_end_plan_compiles_and_simulates(empty_library) -> None:
    rng = np.random.default_rng(11)
    reqs = [
        RoomRequest(id="living", type="living_room", area_m2=22),
        RoomRequest(id="kitchen", type="kitchen", area_m2=11, adjacent_to=["living"]),
        RoomRequest(id="bedroom", type="bedroom", area_m2=13),
        RoomRequest(id="bathroom", type="bathroom", area_m2=6.5, adjacent_to=["bedroom"]),
    ]
    plan = plan_floor(reqs, rng)
    doors = place_doors(plan.rooms, rng, entrance=plan.entrance)
    windows = place_windows(plan.rooms, doors, rng)
    lights = ceiling_lights(plan.rooms, 2.7)
    scene = SceneSpec(name="planned", rooms=plan.rooms, doors=doors, windows=windows, lights=lights)
    assert windows and len(doors) == 4
    compiled = compile_scene(SceneSpec.model_validate(scene.model_dump()), empty_library)
    assert simulate(compiled.model, 1.0).ok

    # Wall objects over a stand, as static boxes: no collider may touch another at t = 0.
    stand, footprint = _stand_against_a_wall(scene, "living")
    wall_reqs = [
        WallObjectRequest(id="tv", size=(1.0, 0.08, 0.6), kind="television", above="stand"),
        WallObjectRequest(id="painting", size=(0.9, 0.04, 0.6), kind="painting"),
        WallObjectRequest(id="clock", size=(0.3, 0.05, 0.3), kind="clock"),
        WallObjectRequest(id="cabinet", size=(0.8, 0.35, 0.6), kind="wall_cabinet"),
    ]
    placed, unplaced = place_wall_objects(
        scene.room("living"),
        scene.walls,
        doors,
        windows,
        [("stand", footprint, 0.5)],
        wall_reqs,
        rng,
        wall_height=scene.wall_height,
        wall_thickness=scene.wall_thickness,
    )
    assert unplaced == [] and placed[0].id == "tv"
    sizes = {r.id: r.size for r in wall_reqs}
    objects = [stand] + [
        p.scene_object("builtin:box", scale=(sizes[p.id][1], sizes[p.id][0], sizes[p.id][2]))
        for p in placed
    ]
    full = SceneSpec.model_validate({**scene.model_dump(), "objects": objects})
    compiled = compile_scene(full, empty_library)
    assert simulate(compiled.model, 1.0).ok
    loaded = LoadedScene(
        source=Path("planned"),
        model=compiled.model,
        objects={o.id: compiled.model.body(names.object_body(o.id)).id for o in objects},
        scene=full,
    )
    result = audit(loaded)
    assert result.ok, (result.penetrations, result.outside_rooms, result.below_floor)
