"""3D-Generalist SceneDef import."""

from __future__ import annotations

import copy

import pytest

from holomj.errors import FormatError
from holomj.importers import ImportResult, import_scenedef
from holomj.library import AssetLibrary

from .conftest import load_fixture


@pytest.fixture(scope="module")
def data() -> dict:
    return load_fixture("scenedef_scene.json")


@pytest.fixture(scope="module")
def result(data: dict, library: AssetLibrary) -> ImportResult:
    return import_scenedef(data, library, "scenedef_scene.json")


def test_room_and_materials(result: ImportResult) -> None:
    scene = result.scene
    assert result.format == "scenedef"
    assert scene.name == "cozy bedroom"
    (room,) = scene.rooms
    assert room.polygon == [(0.0, 0.0), (5.0, 0.0), (5.0, 4.0), (0.0, 4.0)]
    assert room.wall_material == "sage"
    assert scene.materials["sage"].rgba == pytest.approx((0.62, 0.7, 0.6, 1.0))
    assert scene.wall_height == pytest.approx(2.8)


def test_openings(result: ImportResult) -> None:
    (door,) = result.scene.doors
    assert door.rooms == ["bedroom"]
    assert door.width == pytest.approx(0.9)
    (window,) = result.scene.windows
    assert window.kind == "hung"
    assert window.base_height == pytest.approx(0.9)


def test_objects(result: ImportResult) -> None:
    objects = {o.id: o for o in result.scene.objects}
    assert set(objects) == {"bed", "nightstand_0", "nightstand_1", "mug", "chair", "couch"}
    # position is the bbox centre: bottom = z - height / 2
    assert objects["bed"].position == pytest.approx((1.25, 2.0, 0.0))
    assert objects["mug"].position[2] == pytest.approx(0.55)
    assert objects["mug"].support == "nightstand_0"
    assert objects["chair"].yaw_deg == pytest.approx(90.0)  # same convention as holomj
    assert objects["couch"].asset == "sofa_small"  # given asset in the library
    assert objects["nightstand_0"].asset == "builtin:box"
    assert objects["nightstand_0"].scale == pytest.approx((0.4, 0.5, 0.55))
    assert any("material" in w for w in result.warnings)


def test_tilted_placement_gets_a_quaternion(data: dict, library: AssetLibrary) -> None:
    tilted = copy.deepcopy(data)
    tilted["objects"][3]["placements"][0]["rotation"] = [90, 0, 0]
    chair = next(
        o for o in import_scenedef(tilted, library, "s.json").scene.objects if o.id == "chair"
    )
    assert chair.quat == pytest.approx((2**-0.5, 2**-0.5, 0.0, 0.0))


def test_lights(result: ImportResult) -> None:
    lights = {light.id: light for light in result.scene.lights}
    assert lights["ceiling"].color == pytest.approx((1.0, 0.95, 0.85))
    assert lights["sun"].kind == "directional"


def test_rooms_list_and_floor_polygon(library: AssetLibrary) -> None:
    data = {
        "rooms": [
            {"id": "a", "floor": [[0, 0], [3, 0], [3, 3], [0, 3]]},
            {"id": "b", "floor": [[3, 0], [6, 0], [6, 3], [3, 3]]},
        ],
        "doors": [{"position": [3.0, 1.5], "width": 0.9}],
        "objects": [],
    }
    scene = import_scenedef(data, library, "two.json").scene
    assert sorted(scene.doors[0].rooms) == ["a", "b"]


def test_unknown_support_names_path(data: dict, library: AssetLibrary) -> None:
    bad = copy.deepcopy(data)
    bad["objects"][2]["placements"][0]["on"] = "wardrobe"
    with pytest.raises(FormatError, match=r"s\.json: objects\[2\]\.placements\[0\]\.on"):
        import_scenedef(bad, library, "s.json")
