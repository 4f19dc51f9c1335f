"""Hypothesis fuzz of the house importer: a house with fields removed or replaced by other JSON
values is either imported or refused with a located FormatError / SpecError, never a crash."""

from __future__ import annotations

import copy
from typing import Any

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from holomj.errors import FormatError, SpecError
from holomj.importers.procthor import import_procthor
from holomj.library import AssetLibrary

from .conftest import load_fixture

HOUSES = ("procthor_house_v1.json", "holodeck_house.json")
VALUES = st.none() | st.booleans() | st.integers(-5, 5) | st.floats(-1e3, 1e3) | st.text(max_size=6)
VALUES = (
    VALUES | st.lists(VALUES, max_size=3) | st.dictionaries(st.text(max_size=4), VALUES, max_size=3)
)


def _paths(value: Any, prefix: tuple = ()) -> list[tuple]:
    """Every path to a value inside ``value`` (dict keys and list indexes)."""
    found = [prefix] if prefix else []
    if isinstance(value, dict):
        for key, item in value.items():
            found += _paths(item, (*prefix, key))
    elif isinstance(value, list):
        for index, item in enumerate(value[:4]):
            found += _paths(item, (*prefix, index))
    return found


def _mutate(house: dict, path: tuple, new: Any, delete: bool) -> dict:
    house = copy.deepcopy(house)
    target = house
    for step in path[:-1]:
        target = target[step]
    if delete and isinstance(target, dict):
        del target[path[-1]]
    else:
        target[path[-1]] = new
    return house


@settings(
    max_examples=120, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)
@given(data=st.data())
def test_mutated_houses_import_or_refuse_cleanly(
    library: AssetLibrary, data: st.DataObject
) -> None:
    house = load_fixture(data.draw(st.sampled_from(HOUSES)))
    paths = _paths(house)
    for _ in range(data.draw(st.integers(1, 3))):
        path = data.draw(st.sampled_from(paths))
        house = _mutate(house, path, data.draw(VALUES), data.draw(st.booleans()))
        paths = _paths(house) or paths
        if not _paths(house):
            break
    try:
        import_procthor(house, library, "fuzz.json")
    except (FormatError, SpecError) as err:
        assert "fuzz.json" in err.one_line()
