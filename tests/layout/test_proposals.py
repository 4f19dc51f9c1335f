"""Small-object proposals: capacity by surface area (at most 15), categories by weight."""

from __future__ import annotations

import numpy as np
import pytest

from asset_pipeline.procedural import CATEGORIES
from holomj.errors import SpecError
from holomj.layout.proposals import (
    AREA_PER_OBJECT_M2,
    capacity,
    default_catalogue,
    propose_small_objects,
)
from holomj.spec.assets import AssetMeta


def _meta(category: str, *areas: float) -> AssetMeta:
    surfaces = [
        {
            "height": 0.75,
            "polygon": [(-0.5, -0.5), (0.5, -0.5), (0.5, 0.5), (-0.5, 0.5)],
            "area_m2": a,
        }
        for a in areas
    ]
    return AssetMeta(
        id=f"{category}_asset",
        category=category,
        size=(1.0, 1.0, 0.75),
        visual=[{"mesh": "visual.obj"}],
        collision=[{"kind": "box", "size": (0.5, 0.5, 0.375), "volume_m3": 0.75}],
        surfaces=surfaces,
    )


def test_default_catalogue_uses_library_categories() -> None:
    catalogue = default_catalogue()
    plain = {key for key in catalogue if ":" not in key}
    assert plain == {
        "dining_table",
        "desk",
        "bookshelf",
        "coffee_table",
        "kitchen_counter",
        "nightstand",
        "dresser",
        "tv_stand",
        "side_table",
        "shelving_unit",
    }
    for key, items in catalogue.items():
        receptacle = key.partition(":")[2] or key
        assert receptacle in CATEGORIES
        assert items
        for category, weight in items:
            assert category in CATEGORIES, (receptacle, category)
            assert weight > 0
    assert {c for c, _ in catalogue["dining_table"]} == {
        "plate",
        "bowl",
        "cup",
        "mug",
        "bottle",
        "apple",
        "vase",
        "candle",
    }


def test_capacity_grows_with_area_up_to_fifteen() -> None:
    assert capacity(_meta("nightstand", 0.18)) == 3
    assert capacity(_meta("desk", 0.3, 0.3)) == 10
    assert capacity(_meta("dining_table", 1.44)) == 15
    assert capacity(_meta("dining_table", 1.44), 4) == 4
    assert capacity(_meta("dining_table", AREA_PER_OBJECT_M2 * 0.9)) == 0
    areas = [0.06 * k for k in range(1, 16)]
    assert [capacity(_meta("desk", a)) for a in areas] == list(range(1, 16))


def test_proposals_fill_capacity_and_are_deterministic() -> None:
    receptacles = [
        ("table", _meta("dining_table", 1.5), "dining_room"),
        ("stand", _meta("nightstand", 0.2), "bedroom"),
        ("shelf", _meta("bookshelf", 0.3, 0.3, 0.3), "living_room"),
        ("sofa", _meta("sofa", 1.0), "living_room"),  # not a receptacle in the catalogue
        ("bare", _meta("desk"), "office"),  # no surfaces
    ]
    a = propose_small_objects(receptacles, None, np.random.default_rng(7))
    b = propose_small_objects(receptacles, None, np.random.default_rng(7))
    assert a == b
    totals: dict[str, int] = {}
    for p in a:
        assert p.count > 0
        totals[p.receptacle_id] = totals.get(p.receptacle_id, 0) + p.count
    assert totals == {"table": 15, "stand": 3, "shelf": 15}
    allowed = {c for c, _ in default_catalogue()["nightstand"]}
    assert {p.category for p in a if p.receptacle_id == "stand"} <= allowed
    c = propose_small_objects(receptacles, None, np.random.default_rng(8))
    assert c != a or len(a) == 0


def test_weights_steer_the_categories() -> None:
    catalogue = {"desk": [("book", 1.0), ("laptop", 0.0)]}
    props = propose_small_objects(
        [("d", _meta("desk", 0.6), "office")], catalogue, np.random.default_rng(0)
    )
    assert props == [props[0]] and props[0].category == "book" and props[0].count == 10


def test_room_type_key_overrides() -> None:
    catalogue = {"desk": [["book", 1]], "kids_room:desk": [["toy_block", 1]]}
    rec = [("d1", _meta("desk", 0.12), "Kids Room"), ("d2", _meta("desk", 0.12), "office")]
    props = propose_small_objects(rec, catalogue, np.random.default_rng(0))
    assert [(p.receptacle_id, p.category, p.count) for p in props] == [
        ("d1", "toy_block", 2),
        ("d2", "book", 2),
    ]


def test_proposals_scale_with_area() -> None:
    small = propose_small_objects(
        [("t", _meta("coffee_table", 0.25), "living_room")], None, np.random.default_rng(0)
    )
    big = propose_small_objects(
        [("t", _meta("coffee_table", 0.5), "living_room")], None, np.random.default_rng(0)
    )
    assert sum(p.count for p in small) == 4
    assert sum(p.count for p in big) == 8


@pytest.mark.parametrize(
    "catalogue",
    [{"desk": "book"}, {"desk": [["book"]]}, {"desk": [["book", -1]]}, {"desk": [[3, 1]]}],
)
def test_bad_catalogue_is_an_error(catalogue: dict) -> None:
    with pytest.raises(SpecError, match="desk"):
        propose_small_objects(
            [("d", _meta("desk", 0.6), "office")], catalogue, np.random.default_rng(0)
        )
