"""What a Holodeck house says about its objects: names matched to library categories through
the knowledge base, planned sizes, wall objects, small objects' extents."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from holomj.importers.holodeck_hints import (
    HolodeckHints,
    base_name,
    category_for_name,
    scaled_to_extent,
)

CATEGORIES = [
    "floor_lamp",
    "tv_stand",
    "book",
    "box",
    "cardboard_box",
    "sofa",
    "desk",
    "vase",
    "potted_plant",
    "wall_cabinet",
    "curtains",
    "dining_chair",
]


@pytest.mark.parametrize(
    ("name", "category"),
    [
        ("floor lamp", "floor_lamp"),  # a library category named outright
        ("standing lamp", "floor_lamp"),  # a knowledge-base alias
        ("media unit", "tv_stand"),
        ("books", "book"),  # plural
        ("classic literature books", "book"),  # leading words dropped
        ("small decorative box", "box"),
        ("floor-to-ceiling curtains", "curtains"),
        ("wooden writing desk", "desk"),
        ("conference chair", "dining_chair"),
        ("vase with flowers", "vase"),  # the head before "with"
    ],
)
def test_names_find_the_category_of_their_kind(name: str, category: str) -> None:
    kind = category_for_name(name, CATEGORIES)
    assert kind is not None and kind.category == category


def test_a_kind_the_library_lacks_is_not_matched() -> None:
    assert category_for_name("blu-ray player", CATEGORIES) is None
    assert category_for_name("gaming console", CATEGORIES) is None  # game_console not here
    assert category_for_name("gaming console", [*CATEGORIES, "game_console"]) is not None


def test_base_names() -> None:
    assert base_name("sofa-0 (living room)") == "sofa"
    assert base_name("books-1|coffee table-0 (living room)") == "books"
    assert base_name("Floor Lamp-12") == "floor lamp"


HOUSE = {
    "object_selection_plan": {
        "living room": {
            "wall shelf": {"location": "wall", "size": [80, 25, 3]},
            "sofa": {"location": "floor", "size": [300, 200, 75]},
            "broken": {"size": [1, "x", 3]},
        }
    },
    "wall_objects": [{"id": "painting-0 (living room)", "roomId": "living room"}],
    "receptacle2small_objects": {
        "coffee table-0 (living room)": [["books-0", "abc", 0.25], ["bad", "x"]],
    },
}


def test_hints_read_plan_sizes_wall_objects_and_extents() -> None:
    hints = HolodeckHints.read(HOUSE)
    # [width, depth, height] cm -> (depth, width, height) m
    assert hints.plan_size("living room", "sofa") == pytest.approx((2.0, 3.0, 0.75))
    assert hints.plan_size(None, "wall shelf") == pytest.approx((0.25, 0.8, 0.03))
    assert hints.plan_size("living room", "broken") is None
    assert hints.on_wall("living room", "wall shelf") and hints.on_wall("living room", "painting")
    assert not hints.on_wall("living room", "sofa")
    assert hints.small_extent("books-0|coffee table-0 (living room)") == pytest.approx(0.25)
    assert hints.small_extent("books-0") is None


def test_scaled_to_extent_keeps_proportions() -> None:
    assert scaled_to_extent((0.2, 0.4, 0.1), 0.2) == pytest.approx((0.1, 0.2, 0.05))


JSON = st.recursive(
    st.none() | st.booleans() | st.floats(allow_nan=False) | st.integers() | st.text(max_size=8),
    lambda children: (
        st.lists(children, max_size=4) | st.dictionaries(st.text(max_size=8), children, max_size=4)
    ),
    max_leaves=20,
)
KEYS = st.sampled_from(
    ["object_selection_plan", "wall_objects", "receptacle2small_objects", "selected_objects"]
)


@settings(max_examples=150, deadline=None)
@given(st.dictionaries(KEYS, JSON, max_size=4))
def test_hints_never_fail_on_malformed_houses(data: dict) -> None:
    hints = HolodeckHints.read(data)
    for size in hints.plan_sizes.values():
        assert all(v > 0 for v in size)
    for extent in hints.extents.values():
        assert 0 < extent <= 3.0


@settings(max_examples=200, deadline=None)
@given(st.text(max_size=40))
def test_any_name_gives_a_library_category_or_none(name: str) -> None:
    kind = category_for_name(name, CATEGORIES)
    assert kind is None or kind.category in CATEGORIES
