"""Category names are compared one way, and the category facts read in the asset axes."""

from __future__ import annotations

import pytest

from holomj.spec.categories import (
    asset_axes,
    category_aliases,
    category_size,
    normalise_category,
    plan_axes,
)


@pytest.mark.parametrize("name", ["Dining Table", "dining-table", "DiningTable", "dining_table"])
def test_one_normalisation(name: str) -> None:
    assert normalise_category(name) == "diningtable"


def test_sizes_are_in_the_asset_axes() -> None:
    # category_facts.json: a sofa is 2.0 m wide (side to side) and 0.9 m deep (front to back);
    # an asset's x is its depth.
    assert category_size("Sofa") == (0.9, 2.0, 0.85)
    assert category_size("sofa") == category_size("SOFA")
    assert category_size("no such thing") is None
    assert plan_axes(asset_axes((2.0, 0.9, 0.85))) == (2.0, 0.9, 0.85)
    assert asset_axes((2.0, 0.9, 0.85)) == (0.9, 2.0, 0.85)


def test_stand_ins_by_normalised_name() -> None:
    aliases = category_aliases()
    assert aliases["couch"] == ["sofa"]
    assert all(k == normalise_category(k) for k in aliases)
