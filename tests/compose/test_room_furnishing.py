"""Furnishing one room: retrieval per instance, layout against inset walls, wall objects."""

from __future__ import annotations

import pytest
from shapely import affinity
from shapely.geometry import Polygon, box

from holomj.compose.house_shell import build_shell
from holomj.compose.room_assets import retrieve_room
from holomj.compose.room_context import RoomContext
from holomj.compose.room_furnishing import furnish_room
from holomj.layout.furniture_rules import FIXED_CATEGORIES, object_id
from holomj.spec.scene import SceneSpec
from tests.layout.choosers import CategoryChooser
from tests.layout.plans import two_room_plan


@pytest.fixture(scope="module")
def furnished(default_library):
    plan = two_room_plan()
    shell = build_shell(plan, seed=3, pick_material=None)
    context = RoomContext(SceneSpec(rooms=shell.rooms).walls, shell.doors, shell.windows, 2.7, 0.1)
    chooser = CategoryChooser(default_library)
    rooms = {}
    for plan_room in plan.rooms:
        room = next(r for r in shell.rooms if r.id == plan_room.id)
        assets = retrieve_room(plan_room, default_library, chooser, 3)
        result = furnish_room(plan_room, room, context, assets, default_library, 3)
        rooms[room.id] = (room, result)
    return plan, shell, rooms


def _footprint(obj, library) -> Polygon:
    depth, width, _ = library.get(obj.asset).meta.size
    rect = box(-depth / 2, -width / 2, depth / 2, width / 2)
    return affinity.translate(affinity.rotate(rect, obj.yaw_deg), obj.position[0], obj.position[1])


def test_every_planned_instance_is_placed_or_reported(furnished, default_library) -> None:
    plan, _, rooms = furnished
    for plan_room in plan.rooms:
        _, result = rooms[plan_room.id]
        placed = {o.id for o in result.objects}
        reported = {u["object"] for u in result.unplaced}
        for obj in plan_room.objects:
            for instance in obj.instances():
                assert object_id(plan_room.id, instance) in placed or instance in reported
    _, living = rooms["living_room"]
    spaceship = [u for u in living.unplaced if u["object"] == "spaceship-0"]
    assert spaceship and spaceship[0]["stage"] == "retrieve"


def test_floor_objects_stay_clear_of_walls_and_each_other(furnished, default_library) -> None:
    _, _, rooms = furnished
    for room, result in rooms.values():
        inner = Polygon(room.polygon).buffer(-0.05 + 1e-6)  # half an interior wall
        floor = [o for o in result.objects if o.position[2] == 0.0]
        assert floor
        shapes = [_footprint(o, default_library) for o in floor]
        for obj, shape in zip(floor, shapes):
            assert inner.covers(shape), f"{obj.id} reaches into a wall"
        for i, a in enumerate(shapes):
            for b in shapes[i + 1 :]:
                assert a.intersection(b).area < 1e-9


def test_static_rules_and_wall_objects(furnished, default_library) -> None:
    _, _, rooms = furnished
    _, living = rooms["living_room"]
    paintings = [o for o in living.objects if "painting" in o.id]
    assert len(paintings) == 2
    assert all(o.static and o.position[2] > 0.8 for o in paintings)
    _, kitchen = rooms["kitchen"]
    for obj in kitchen.objects:
        category = default_library.get(obj.asset).meta.category
        if category in FIXED_CATEGORIES:
            assert obj.static
        if category == "dining_chair":
            assert not obj.static


def test_receptacles_are_the_placed_objects_with_small_objects(furnished) -> None:
    _, _, rooms = furnished
    _, living = rooms["living_room"]
    assert [rid for rid, _ in living.receptacles] == ["living_room.coffee_table_0"]
    _, kitchen = rooms["kitchen"]
    assert [p.name for _, p in kitchen.receptacles] == ["dining table"]
    assert kitchen.layout["placed"] >= 6 and kitchen.layout["hard_checks_ok"]
