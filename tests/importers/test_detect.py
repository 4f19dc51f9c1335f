"""Format detection and loading any supported input file."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from holomj.errors import AssetNotFoundError, FormatError, InputError, SpecError
from holomj.importers import detect_format, load_scene_input
from holomj.library import AssetLibrary

from .conftest import FIXTURES, load_fixture


@pytest.mark.parametrize(
    ("name", "expected"),
    [
        ("procthor_house_v1.json", "procthor"),
        ("procthor_house_legacy.json", "procthor"),
        ("holodeck_house.json", "procthor"),
        ("scenedef_scene.json", "scenedef"),
        ("two_room_scene.json", "holomj"),
    ],
)
def test_detect_format(name: str, expected: str) -> None:
    assert detect_format(load_fixture(name)) == expected


@pytest.mark.parametrize("data", [[], {"rooms": []}, {"hello": 1}, "text", None])
def test_unknown_format_is_explained(data: object) -> None:
    with pytest.raises(FormatError, match="floorPolygon"):
        detect_format(data, "odd.json")


@pytest.mark.parametrize(
    ("name", "fmt"),
    [
        ("procthor_house_v1.json", "procthor"),
        ("holodeck_house.json", "holodeck"),
        ("scenedef_scene.json", "scenedef"),
    ],
)
def test_load_foreign_files(name: str, fmt: str, library: AssetLibrary) -> None:
    detected = load_scene_input(FIXTURES / name, library)
    forced = load_scene_input(FIXTURES / name, library, fmt=fmt)
    assert detected.scene == forced.scene
    assert detected.scene.source == str(FIXTURES / name)
    assert all(o.asset in library for o in detected.scene.objects)


def test_load_holomj_scene_resolves_textures(tmp_path: Path, library: AssetLibrary) -> None:
    data = load_fixture("two_room_scene.json")
    data["materials"] = {"tiles": {"rgba": [1, 1, 1, 1], "texture": "textures/tiles.png"}}
    data["rooms"][0]["floor_material"] = "tiles"
    (tmp_path / "textures").mkdir()
    (tmp_path / "textures" / "tiles.png").write_bytes(b"\x89PNG")
    path = tmp_path / "scene.json"
    path.write_text(json.dumps(data))
    result = load_scene_input(path, library)
    assert result.format == "holomj"
    texture = Path(result.scene.materials["tiles"].texture)
    assert texture.is_absolute()
    assert texture == (tmp_path / "textures" / "tiles.png").resolve()
    assert result.substitutions == []


def test_holomj_missing_texture(tmp_path: Path, library: AssetLibrary) -> None:
    data = load_fixture("two_room_scene.json")
    data["materials"] = {"tiles": {"texture": "nope.png"}}
    path = tmp_path / "scene.json"
    path.write_text(json.dumps(data))
    with pytest.raises(SpecError, match=r"materials\.tiles\.texture"):
        load_scene_input(path, library)


def test_holomj_missing_asset(tmp_path: Path, library: AssetLibrary) -> None:
    data = load_fixture("two_room_scene.json")
    data["objects"][1]["asset"] = "chair_wod"
    path = tmp_path / "scene.json"
    path.write_text(json.dumps(data))
    with pytest.raises(AssetNotFoundError) as info:
        load_scene_input(path, library)
    message = str(info.value)
    assert f"{path}: objects[1].asset" in message
    assert "chair_wood" in message  # did you mean


def test_unknown_format_option(library: AssetLibrary) -> None:
    with pytest.raises(InputError, match="holomj, procthor, holodeck, scenedef"):
        load_scene_input(FIXTURES / "scenedef_scene.json", library, fmt="usd")


def test_missing_file(tmp_path: Path, library: AssetLibrary) -> None:
    with pytest.raises(FormatError, match="file not found"):
        load_scene_input(tmp_path / "nope.json", library)


def test_forced_wrong_format_gives_located_error(tmp_path: Path, library: AssetLibrary) -> None:
    path = tmp_path / "house.json"
    shutil.copy(FIXTURES / "scenedef_scene.json", path)
    with pytest.raises(FormatError, match=r"house\.json: missing required field 'rooms'"):
        load_scene_input(path, library, fmt="procthor")
