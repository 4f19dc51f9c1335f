"""Real Holodeck outputs (``../shared/procthor/houses``) import as their author saw them: each
Objaverse-uid object stands in with a model of its own kind at its authored size, wall objects
keep their height, small objects rest on the receptacle their id names. Import only (fast);
``scripts/bench_house_import.py`` compiles and validates every house."""

from __future__ import annotations

import pytest

from holomj.importers.procthor import import_procthor
from holomj.library.store import BUILTIN_BOX, AssetLibrary

from .conftest import load_real_house

LIVING_ROOM = "holodeck_lmgyuan_a_living_room_20231209234735.json"
CONFERENCE_ROOM = "holodeck_lmgyuan_a_small_conference_room_20231209223858.json"


@pytest.fixture(scope="module")
def living_room(default_library: AssetLibrary):
    return import_procthor(load_real_house(LIVING_ROOM), default_library, LIVING_ROOM)


def test_objects_get_models_of_their_own_kind(living_room, default_library) -> None:
    objects = {o.id: o for o in living_room.scene.objects}
    category = {k: default_library.get(o.asset).meta.category for k, o in objects.items()}
    assert category["floor_lamp-0_living_room"] == "floor_lamp"  # not a box
    assert category["media_unit-0_living_room"] == "tv_stand"  # "media unit" is a TV stand
    assert category["wall_shelf-0_living_room"] == "wall_cabinet"
    assert category["books-0|coffee_table-0_living_room"] == "book"
    floor = [o for o in living_room.scene.objects if o.support is None]
    boxes = [o.id for o in floor if o.asset == BUILTIN_BOX]
    assert not boxes, f"floor objects left as boxes: {boxes}"


def test_authored_sizes_and_heights(living_room, default_library) -> None:
    subs = {s.object_id: s for s in living_room.substitutions}
    lamp = subs["floor_lamp-0_living_room"]
    assert lamp.size_source == "footprint"
    # planned 40 x 40 x 160 cm; the footprint from the vertices, the height from the plan
    assert lamp.source_size[2] == pytest.approx(1.6)
    objects = {o.id: o for o in living_room.scene.objects}
    shelf = objects["wall_shelf-0_living_room"]
    assert shelf.position[2] > 1.0  # a wall shelf stays on the wall, not on the floor
    books = subs["books-0|coffee_table-0_living_room"]
    assert books.size_source == "extent"  # the house lists its largest side
    assert max(books.source_size) == pytest.approx(0.3, abs=0.1)
    assert objects["books-0|coffee_table-0_living_room"].support == "coffee_table-0_living_room"


def test_every_object_of_a_big_holodeck_room_is_kept_by_the_importer(default_library) -> None:
    house = load_real_house(CONFERENCE_ROOM)
    result = import_procthor(house, default_library, CONFERENCE_ROOM)
    assert len(result.scene.objects) == len(house["objects"])
    assert not [w for w in result.warnings if "assuming a 0.5 m cube" in w]
