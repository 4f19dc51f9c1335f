"""Malformed inputs: one-line errors naming the file and the JSON path, never a traceback.

The fuzz tests feed arbitrary JSON-like values and mutated fixtures to every importer and
accept only HolomjError subclasses.
"""

from __future__ import annotations

import copy
import math
from typing import Any

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from holomj.errors import FormatError, HolomjError, SpecError
from holomj.importers import import_procthor, import_scenedef
from holomj.importers.detect import detect_format
from holomj.library import AssetLibrary

from .conftest import load_fixture

HOUSE = load_fixture("procthor_house_v1.json")
HOLODECK = load_fixture("holodeck_house.json")
SCENEDEF = load_fixture("scenedef_scene.json")


def _house() -> dict:
    return copy.deepcopy(HOUSE)


def test_missing_rooms(library: AssetLibrary) -> None:
    data = _house()
    del data["rooms"]
    with pytest.raises(FormatError) as info:
        import_procthor(data, library, "house.json")
    assert str(info.value) == "house.json: missing required field 'rooms'"


def test_empty_rooms(library: AssetLibrary) -> None:
    data = _house()
    data["rooms"] = []
    with pytest.raises(FormatError, match=r"house\.json: rooms: a house needs at least one room"):
        import_procthor(data, library, "house.json")


def test_bad_number(library: AssetLibrary) -> None:
    data = _house()
    data["rooms"][1]["floorPolygon"][2]["x"] = "four"
    with pytest.raises(FormatError) as info:
        import_procthor(data, library, "house.json")
    assert str(info.value) == (
        "house.json: rooms[1].floorPolygon[2].x: expected a number, got a string"
    )


@pytest.mark.parametrize("value", [math.nan, math.inf, 1e300, True])
def test_non_finite_or_huge_numbers(library: AssetLibrary, value: Any) -> None:
    data = _house()
    data["objects"][3]["position"]["y"] = value
    with pytest.raises(FormatError, match=r"house\.json: objects\[3\]\.position\.y"):
        import_procthor(data, library, "house.json")


def test_door_off_its_wall(library: AssetLibrary) -> None:
    data = _house()
    data["doors"][0]["holePolygon"][0]["x"] = 5.0  # beyond the 4 m wall
    data["doors"][0]["holePolygon"][1]["x"] = 6.0
    with pytest.raises(SpecError) as info:
        import_procthor(data, library, "house.json")
    message = str(info.value)
    assert message.startswith("house.json: doors[0]: ")
    assert "\n" not in message


def test_window_on_unknown_wall(library: AssetLibrary) -> None:
    data = _house()
    data["windows"][2]["wall0"] = "wall|9|0.00|0.00|1.00|0.00"
    with pytest.raises(FormatError, match=r"house\.json: windows\[2\]\.wall0: unknown wall"):
        import_procthor(data, library, "house.json")


def test_door_too_narrow(library: AssetLibrary) -> None:
    data = _house()
    data["doors"][1]["holePolygon"][1]["x"] = 0.7  # 0.2 m wide
    with pytest.raises(SpecError, match=r"house\.json: doors\[1\]\.width"):
        import_procthor(data, library, "house.json")


def test_overlapping_rooms(library: AssetLibrary) -> None:
    data = _house()
    data["rooms"][0]["floorPolygon"][2]["x"] = 5.0  # kitchen grows into the living room
    data["rooms"][0]["floorPolygon"][3]["x"] = 5.0
    with pytest.raises(SpecError, match=r"^house\.json: "):
        import_procthor(data, library, "house.json")


def test_unknown_light_type(library: AssetLibrary) -> None:
    data = _house()
    data["proceduralParameters"]["lights"][1]["type"] = "laser"
    with pytest.raises(
        FormatError, match=r"proceduralParameters\.lights\[1\]\.type: unknown light type"
    ):
        import_procthor(data, library, "house.json")


def test_child_missing_position(library: AssetLibrary) -> None:
    data = _house()
    del data["objects"][0]["children"][1]["position"]
    with pytest.raises(
        FormatError, match=r"objects\[0\]\.children\[1\]: missing required field 'position'"
    ):
        import_procthor(data, library, "house.json")


def test_extra_fields_are_ignored(library: AssetLibrary) -> None:
    data = _house()
    data["somethingNew"] = {"a": 1}
    data["rooms"][0]["sparkles"] = True
    data["objects"][0]["futureField"] = [1, 2]
    assert len(import_procthor(data, library, "house.json").scene.rooms) == 4


def test_scenedef_errors(library: AssetLibrary) -> None:
    data = copy.deepcopy(SCENEDEF)
    data["objects"][0]["placements"][0]["position"] = [1, 2]
    with pytest.raises(
        FormatError, match=r"s\.json: objects\[0\]\.placements\[0\]\.position: expected 3 numbers"
    ):
        import_scenedef(data, library, "s.json")
    data = copy.deepcopy(SCENEDEF)
    data["windows"][0]["position"] = [2.0, 2.0]  # the middle of the room
    with pytest.raises(FormatError, match=r"s\.json: windows\[0\]\.position: .* not on any wall"):
        import_scenedef(data, library, "s.json")


# -- fuzzing ---------------------------------------------------------------------------------

json_scalars = st.one_of(
    st.none(),
    st.booleans(),
    st.integers(min_value=-(10**20), max_value=10**20),
    st.floats(allow_nan=True, allow_infinity=True),
    st.text(max_size=12),
)
json_values = st.recursive(
    json_scalars,
    lambda children: st.one_of(
        st.lists(children, max_size=4),
        st.dictionaries(st.text(max_size=10), children, max_size=4),
    ),
    max_leaves=20,
)
# Keys the importers look for, so random documents reach deeper code.
known_keys = st.sampled_from(
    [
        "rooms",
        "floorPolygon",
        "walls",
        "doors",
        "windows",
        "objects",
        "children",
        "id",
        "assetId",
        "position",
        "rotation",
        "x",
        "y",
        "z",
        "polygon",
        "wall0",
        "room0",
        "holePolygon",
        "proceduralParameters",
        "lights",
        "placements",
        "bbox",
        "room",
        "category",
        "bbox_size",
        "vertices",
        "wall_height",
    ]
)
structured = st.recursive(
    json_scalars,
    lambda children: st.one_of(
        st.lists(children, max_size=4),
        st.dictionaries(known_keys, children, max_size=5),
    ),
    max_leaves=30,
)


def _only_holomj_errors(run: Any) -> None:
    try:
        run()
    except HolomjError as err:
        assert "\n" not in str(err)


def _paths(value: Any, prefix: tuple = ()) -> list[tuple]:
    out = [prefix]
    if isinstance(value, dict):
        for key, child in value.items():
            out += _paths(child, (*prefix, key))
    elif isinstance(value, list):
        for index, child in enumerate(value):
            out += _paths(child, (*prefix, index))
    return out


def _mutate(document: dict, data: st.DataObject) -> dict:
    doc = copy.deepcopy(document)
    paths = _paths(doc)[1:]
    for _ in range(data.draw(st.integers(min_value=1, max_value=4))):
        path = data.draw(st.sampled_from(paths))
        parent = doc
        try:
            for part in path[:-1]:
                parent = parent[part]
            action = data.draw(st.sampled_from(["delete", "replace", "number"]))
            if action == "delete" and isinstance(parent, dict):
                del parent[path[-1]]
            elif action == "number":
                parent[path[-1]] = data.draw(
                    st.sampled_from([math.nan, math.inf, -1e308, 1e9, -5.0, 0, 0.0001, 361.0])
                )
            else:
                parent[path[-1]] = data.draw(json_values)
        except (KeyError, IndexError, TypeError):
            continue  # the path vanished through an earlier mutation
    return doc


FUZZ = settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])


@FUZZ
@given(document=st.one_of(json_values, structured))
def test_fuzz_arbitrary_documents(library: AssetLibrary, document: Any) -> None:
    _only_holomj_errors(lambda: import_procthor(document, library, "fuzz.json"))
    _only_holomj_errors(lambda: import_scenedef(document, library, "fuzz.json"))
    _only_holomj_errors(lambda: detect_format(document, "fuzz.json"))


@FUZZ
@given(data=st.data())
def test_fuzz_mutated_procthor(library: AssetLibrary, data: st.DataObject) -> None:
    document = _mutate(HOUSE, data)
    _only_holomj_errors(lambda: import_procthor(document, library, "fuzz.json"))


@FUZZ
@given(data=st.data())
def test_fuzz_mutated_holodeck(library: AssetLibrary, data: st.DataObject) -> None:
    document = _mutate(HOLODECK, data)
    _only_holomj_errors(lambda: import_procthor(document, library, "fuzz.json"))


@FUZZ
@given(data=st.data())
def test_fuzz_mutated_scenedef(library: AssetLibrary, data: st.DataObject) -> None:
    document = _mutate(SCENEDEF, data)
    _only_holomj_errors(lambda: import_scenedef(document, library, "fuzz.json"))
