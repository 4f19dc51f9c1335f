"""Holodeck house import: ids with spaces, centimetre footprints, small objects, open walls."""

from __future__ import annotations

import pytest

from holomj.importers import ImportResult, import_procthor
from holomj.importers.ids import IdMap, sanitise
from holomj.library import AssetLibrary

from .conftest import load_fixture


@pytest.fixture(scope="module")
def result(library: AssetLibrary) -> ImportResult:
    return import_procthor(load_fixture("holodeck_house.json"), library, "holodeck_house.json")


def test_sanitise_is_deterministic_and_valid() -> None:
    assert sanitise("living room") == "living_room"
    assert sanitise("sofa-0 (living room)") == "sofa-0_living_room"
    assert sanitise("  (( ") == "id"
    ids = IdMap("room")
    assert [ids.new("a b"), ids.new("a  b"), ids.new("a_b")] == ["a_b", "a_b_2", "a_b_3"]
    assert ids.lookup("a b") == "a_b"


def test_format_rooms_and_height(result: ImportResult) -> None:
    scene = result.scene
    assert result.format == "holodeck"
    assert [r.id for r in scene.rooms] == ["living_room", "kitchen", "bedroom"]
    assert scene.room("living_room").type == "living room"
    assert scene.wall_height == pytest.approx(2.8)
    assert scene.room("bedroom").wall_material == "pink_paint"


def test_openings(result: ImportResult) -> None:
    scene = result.scene
    doors = {d.id: d for d in scene.doors}
    inner = doors["door|1|bedroom|living_room"]
    assert sorted(inner.rooms) == ["bedroom", "living_room"]
    assert inner.position == pytest.approx((3.5, 4.0))
    outer = doors["door|0|exterior|living_room"]
    assert outer.rooms == ["living_room"]
    # wall0 is the reversed exterior wall: x runs from (0, 0)
    assert outer.position == pytest.approx((2.0, 0.0))
    (open_door,) = [d for d in scene.doors if d.kind == "open"]
    assert sorted(open_door.rooms) == ["kitchen", "living_room"]
    assert open_door.width == pytest.approx(3.9)
    kinds = sorted(w.kind for w in scene.windows)
    assert kinds == ["fixed", "slider"]


def test_objects(result: ImportResult) -> None:
    objects = {o.id: o for o in result.scene.objects}
    sofa = objects["sofa-0_living_room"]
    assert sofa.asset == "sofa_modern"
    assert sofa.room == "living_room"
    assert sofa.static  # kinematic: true
    assert sofa.yaw_deg == pytest.approx(-90.0)  # rotation.y = 180 faces unity -z = holomj -Y
    # coffee table: box sized from the footprint (cm) and twice its centre height
    table = objects["coffee_table-0_living_room"]
    assert table.asset == "builtin:box"
    assert table.scale == pytest.approx((0.6, 1.1, 0.45))
    assert table.position == pytest.approx((2.5, 2.0, 0.0))
    # small object "mug-0|dining table-0 (kitchen)" rests on the dining table
    mug = objects["mug-0|dining_table-0_kitchen"]
    assert mug.support == "dining_table-0_kitchen"
    assert mug.asset == "Mug_1"
    assert mug.position[2] == pytest.approx(0.75)
    # a wall object keeps its height
    painting = objects["painting-0_living_room"]
    assert painting.position[2] == pytest.approx(1.3)
    subs = {s.object_id: s for s in result.substitutions}
    # "dining table" is matched to the library's category of that name
    assert subs["dining_table-0_kitchen"].category == "dining_table"
    assert subs["dining_table-0_kitchen"].used_asset == "dining_table_oak"
