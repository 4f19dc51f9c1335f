"""Duplicate ids (issue 12): an id used twice is an input error naming both places, in every
format, while ids that only clash once sanitised are renamed with a warning.

The CLI cases run ``holomj compile`` through typer's runner against the small test library:
exit code 2, exactly one line on stderr, and no output folder.
"""

from __future__ import annotations

import copy
import json
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from holomj.cli import app
from holomj.errors import SpecError
from holomj.importers import import_procthor, import_scenedef
from holomj.importers.ids import IdMap, check_unique_ids, listed_ids
from holomj.library import AssetLibrary

from .conftest import load_fixture

HOUSE = load_fixture("procthor_house_v1.json")
HOLODECK = load_fixture("holodeck_house.json")
SCENEDEF = load_fixture("scenedef_scene.json")
SCENE = load_fixture("two_room_scene.json")

Edit = Callable[[dict[str, Any]], None]


def _set_id(*path: str | int, to: tuple[str | int, ...]) -> Edit:
    """An edit giving the entry at ``path`` the id of the entry at ``to``."""

    def entry(doc: dict[str, Any], where: tuple[str | int, ...]) -> dict[str, Any]:
        node: Any = doc
        for part in where:
            node = node[part]
        return node

    def edit(doc: dict[str, Any]) -> None:
        entry(doc, path)["id"] = entry(doc, to)["id"]

    return edit


def _two_scenedef_rooms(doc: dict[str, Any]) -> None:
    """Turn the SceneDef's single room into two side by side with the same id."""
    room = doc.pop("room")
    other = copy.deepcopy(room)
    other["bbox"] = [[5, 0, 0], [9, 4, 2.8]]
    doc["rooms"] = [room, other]


CASES = {
    "procthor-objects": (
        HOUSE,
        _set_id("objects", 3, to=("objects", 1)),
        "objects[3].id: duplicate id 'Chair|1|1' (also objects[1].id)",
    ),
    "procthor-child-after-object": (
        HOUSE,
        _set_id("objects", 4, "children", 0, to=("objects", 1)),
        "objects[4].children[0].id: duplicate id 'Chair|1|1' (also objects[1].id)",
    ),
    "procthor-object-after-child": (
        HOUSE,
        _set_id("objects", 5, to=("objects", 0, "children", 0)),
        "objects[5].id: duplicate id 'Mug|1|0|0' (also objects[0].children[0].id)",
    ),
    "procthor-two-children": (
        HOUSE,
        _set_id("objects", 11, "children", 0, to=("objects", 0, "children", 2)),
        "objects[11].children[0].id: duplicate id 'Bowl|1|0|2' (also objects[0].children[2].id)",
    ),
    "procthor-rooms": (
        HOUSE,
        _set_id("rooms", 2, to=("rooms", 0)),
        "rooms[2].id: duplicate id 'room|1' (also rooms[0].id)",
    ),
    "procthor-doors": (
        HOUSE,
        _set_id("doors", 3, to=("doors", 1)),
        "doors[3].id: duplicate id 'door|1|3' (also doors[1].id)",
    ),
    "procthor-windows": (
        HOUSE,
        _set_id("windows", 1, to=("windows", 0)),
        "windows[1].id: duplicate id 'window|1|0' (also windows[0].id)",
    ),
    "procthor-window-and-door": (
        HOUSE,
        _set_id("windows", 0, to=("doors", 4)),
        "windows[0].id: duplicate id 'door|2|exterior' (also doors[4].id)",
    ),
    "holodeck-objects": (
        HOLODECK,
        _set_id("objects", 4, to=("objects", 0)),
        "objects[4].id: duplicate id 'sofa-0 (living room)' (also objects[0].id)",
    ),
    "holodeck-rooms": (
        HOLODECK,
        _set_id("rooms", 2, to=("rooms", 0)),
        "rooms[2].id: duplicate id 'living room' (also rooms[0].id)",
    ),
    "scenedef-objects": (
        SCENEDEF,
        _set_id("objects", 3, to=("objects", 0)),
        "objects[3].id: duplicate id 'bed' (also objects[0].id)",
    ),
    "scenedef-multi-placement-objects": (
        SCENEDEF,
        _set_id("objects", 4, to=("objects", 1)),
        "objects[4].id: duplicate id 'nightstand' (also objects[1].id)",
    ),
    "scenedef-window-and-door": (
        SCENEDEF,
        _set_id("windows", 0, to=("doors", 0)),
        "windows[0].id: duplicate id 'door_main' (also doors[0].id)",
    ),
    "scenedef-rooms": (
        SCENEDEF,
        _two_scenedef_rooms,
        "rooms[1].id: duplicate id 'bedroom' (also rooms[0].id)",
    ),
    "holomj-objects": (
        SCENE,
        _set_id("objects", 2, to=("objects", 0)),
        "objects[2].id: duplicate id 'crate' (also objects[0].id)",
    ),
    "holomj-window-and-door": (
        SCENE,
        _set_id("windows", 1, to=("doors", 0)),
        "windows[1].id: duplicate id 'kitchen_door' (also doors[0].id)",
    ),
    "holomj-rooms": (
        SCENE,
        _set_id("rooms", 1, to=("rooms", 0)),
        "rooms[1].id: duplicate id 'kitchen' (also rooms[0].id)",
    ),
}


@pytest.fixture
def runner() -> CliRunner:
    return CliRunner()


def _write(tmp_path: Path, document: dict[str, Any], name: str = "house.json") -> Path:
    folder = tmp_path / "in"
    folder.mkdir()
    path = folder / name
    path.write_text(json.dumps(document))
    return path


@pytest.mark.parametrize("case", sorted(CASES))
def test_compile_rejects_duplicate_ids(
    runner: CliRunner, tmp_path: Path, library: AssetLibrary, case: str
) -> None:
    base, edit, expected = CASES[case]
    document = copy.deepcopy(base)
    edit(document)
    source = _write(tmp_path, document)
    out = tmp_path / "out"
    result = runner.invoke(
        app, ["compile", str(source), "-o", str(out), "--library", str(library.root)]
    )
    assert result.exit_code == 2, result.output
    assert result.stderr.strip().splitlines() == [f"error: {source}: {expected}"]
    assert result.stdout == ""
    assert not out.exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["in"]


def test_real_subprocess_duplicate_id(tmp_path: Path, library: AssetLibrary) -> None:
    """The same through a real process: exit status 2, one line, no traceback, no folder."""
    import subprocess
    import sys

    document = copy.deepcopy(HOUSE)
    document["objects"][3]["id"] = document["objects"][1]["id"]
    source = _write(tmp_path, document)
    out = tmp_path / "out"
    command = [sys.executable, "-m", "holomj", "compile", str(source), "-o", str(out)]
    result = subprocess.run(
        [*command, "--library", str(library.root)], capture_output=True, text=True, check=False
    )
    assert result.returncode == 2, result.stderr
    assert result.stderr == (
        f"error: {source}: objects[3].id: duplicate id 'Chair|1|1' (also objects[1].id)\n"
    )
    assert not out.exists()


def test_ids_clashing_only_once_sanitised_compile_with_a_warning(
    runner: CliRunner, tmp_path: Path, library: AssetLibrary
) -> None:
    """``"sofa-0 (living room)"`` and ``"sofa-0 living room"`` are different ids that holomj
    spells the same: not a duplicate; the second gets a suffix and import_report.json says so."""
    document = copy.deepcopy(HOLODECK)
    document["objects"][1]["id"] = "sofa-0 living room"
    source = _write(tmp_path, document)
    out = tmp_path / "out"
    result = runner.invoke(
        app,
        [
            "compile",
            str(source),
            "-o",
            str(out),
            "--library",
            str(library.root),
            "--check-seconds",
            "0",
            "--json",
        ],
    )
    assert result.exit_code == 0, result.output
    warning = (
        "objects[1].id: id 'sofa-0 living room' renamed to 'sofa-0_living_room_2' "
        "(its holomj form 'sofa-0_living_room' was already taken)"
    )
    assert warning in json.loads(result.stdout)["warnings"]
    report = json.loads((out / "import_report.json").read_text())
    assert warning in report["warnings"]
    scene = json.loads((out / "scene.json").read_text())
    ids = [o["id"] for o in scene["objects"]]
    assert ids[:2] == ["sofa-0_living_room", "sofa-0_living_room_2"]


def test_id_clashing_with_a_made_up_one_is_renamed(library: AssetLibrary) -> None:
    """A SceneDef object called like another one's second placement (``nightstand_1``) keeps
    the import going; the placement's made-up id keeps its name and the ``on`` references."""
    document = copy.deepcopy(SCENEDEF)
    document["objects"][3]["id"] = "nightstand_1"
    result = import_scenedef(document, library, "s.json")
    ids = [o.id for o in result.scene.objects]
    assert ids == ["bed", "nightstand_0", "nightstand_1", "mug", "nightstand_1_2", "couch"]
    assert (
        "objects[3].id: id 'nightstand_1' renamed to 'nightstand_1_2' "
        "(its holomj form 'nightstand_1' was already taken)"
    ) in result.warnings
    assert result.scene.objects[3].support == "nightstand_0"


def test_objects_without_ids_are_not_duplicates(library: AssetLibrary) -> None:
    """SceneDef objects without an id are named after their category: two chairs are fine."""
    document = copy.deepcopy(SCENEDEF)
    chair = document["objects"][3]
    del chair["id"]
    second = copy.deepcopy(chair)
    second["placements"][0]["position"] = [4.2, 2.4, 0.45]
    document["objects"].append(second)
    result = import_scenedef(document, library, "s.json")
    ids = [o.id for o in result.scene.objects]
    assert ids == ["bed", "nightstand_0", "nightstand_1", "mug", "chair", "couch", "chair_2"]
    assert not any("renamed" in w for w in result.warnings)


def test_duplicate_light_ids_are_renamed_with_a_warning(library: AssetLibrary) -> None:
    """Lights take no space, so a repeated light id is renamed rather than rejected."""
    document = copy.deepcopy(HOUSE)
    lights = document["proceduralParameters"]["lights"]
    lights[2]["id"] = lights[1]["id"]
    result = import_procthor(document, library, "house.json")
    assert [li.id for li in result.scene.lights][1:3] == ["light_1", "light_1_2"]
    assert (
        "proceduralParameters.lights[2].id: id 'light_1' renamed to 'light_1_2' "
        "(the same id appears earlier)"
    ) in result.warnings


def test_unique_ids_leave_no_warnings(library: AssetLibrary) -> None:
    for document, run in ((HOUSE, import_procthor), (HOLODECK, import_procthor)):
        result = run(copy.deepcopy(document), library, "house.json")
        assert not any("renamed" in w for w in result.warnings)
    result = import_scenedef(copy.deepcopy(SCENEDEF), library, "s.json")
    assert not any("renamed" in w for w in result.warnings)


# -- the helpers ---------------------------------------------------------------------------


def test_listed_ids_walks_children_in_document_order() -> None:
    objects = [
        {"id": "a", "children": [{"id": "a1"}, {"id": "", "children": [{"id": "a2x"}]}]},
        "not an object",
        {"id": 7},
        {"id": "b", "children": "not a list"},
    ]
    assert list(listed_ids(objects, "objects", children="children")) == [
        ("a", "objects[0].id"),
        ("a1", "objects[0].children[0].id"),
        ("a2x", "objects[0].children[1].children[0].id"),
        ("b", "objects[3].id"),
    ]
    assert list(listed_ids({"id": "x"}, "rooms")) == []


def test_check_unique_ids_names_both_places() -> None:
    check_unique_ids([("a", "rooms[0].id"), ("b", "rooms[1].id")], "f.json")
    with pytest.raises(SpecError) as info:
        check_unique_ids([("a", "doors[0].id"), ("b", "doors[1].id"), ("a", "windows[0].id")], "f")
    assert str(info.value) == "f: windows[0].id: duplicate id 'a' (also doors[0].id)"
    assert info.value.exit_code == 2


def test_id_map_prefers_the_inputs_own_id_for_lookups() -> None:
    ids = IdMap("room")
    assert ids.new("room_0") == "room_0"  # made up for a room without an id
    assert ids.new("room_0", "rooms[1].id") == "room_0_2"
    assert ids.lookup("room_0") == "room_0_2"
    assert ids.renamed == [
        "rooms[1].id: id 'room_0' renamed to 'room_0_2' "
        "(its holomj form 'room_0' was already taken)"
    ]
    assert ids.new("room_0") == "room_0_3"
    assert ids.lookup("room_0") == "room_0_2"


# -- fuzzing -------------------------------------------------------------------------------

NAMESPACES = {"rooms": ("rooms",), "openings": ("doors", "windows"), "objects": ("objects",)}


def _entries(document: dict[str, Any], namespace: str, nested: bool) -> list[tuple[str, dict]]:
    """``(JSON path, entry)`` of one namespace in document order (children right after their
    parent when ``nested``)."""
    out: list[tuple[str, dict]] = []

    def walk(items: list[dict], path: str) -> None:
        for index, item in enumerate(items):
            out.append((f"{path}[{index}]", item))
            if nested and "children" in item:
                walk(item["children"], f"{path}[{index}].children")

    for key in NAMESPACES[namespace]:
        walk(document.get(key, []), key)
    return out


FORMATS = {
    "procthor": (HOUSE, import_procthor, True),
    "holodeck": (HOLODECK, import_procthor, True),
    "scenedef": (SCENEDEF, import_scenedef, False),
}


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data())
def test_fuzz_duplicated_ids_name_both_places(library: AssetLibrary, data: st.DataObject) -> None:
    """Any two entries of one namespace given the same id, whatever its text, are rejected
    at the later one, naming the earlier one."""
    fmt = data.draw(st.sampled_from(sorted(FORMATS)))
    base, run, nested = FORMATS[fmt]
    document = copy.deepcopy(base)
    namespace = data.draw(st.sampled_from(sorted(NAMESPACES)))
    entries = _entries(document, namespace, nested)
    assume(len(entries) >= 2)
    later = data.draw(st.integers(min_value=1, max_value=len(entries) - 1))
    earlier = data.draw(st.integers(min_value=0, max_value=later - 1))
    raw = data.draw(st.one_of(st.just(entries[earlier][1].get("id")), st.text(min_size=1)))
    others = {e.get("id") for k, (_, e) in enumerate(entries) if k not in (earlier, later)}
    assume(isinstance(raw, str) and raw and raw not in others)
    entries[earlier][1]["id"] = raw
    entries[later][1]["id"] = raw
    with pytest.raises(SpecError) as info:
        run(document, library, "fuzz.json")
    expected = (
        f"fuzz.json: {entries[later][0]}.id: duplicate id {raw!r} (also {entries[earlier][0]}.id)"
    )
    assert str(info.value) == " ".join(expected.split())
