"""ProcTHOR house import: schema 1.0.0 and the older one."""

from __future__ import annotations

import copy

import pytest

from holomj.importers import ImportResult, import_procthor
from holomj.importers.procthor import IMPORT_WALL_THICKNESS
from holomj.library import AssetLibrary
from holomj.spec.scene import SceneSpec

from .conftest import load_fixture

SOURCE = "procthor_house_v1.json"


@pytest.fixture(scope="module")
def house() -> dict:
    return load_fixture(SOURCE)


@pytest.fixture(scope="module")
def result(house: dict, library: AssetLibrary) -> ImportResult:
    return import_procthor(house, library, SOURCE)


def _obj(scene: SceneSpec, object_id: str):
    return next(o for o in scene.objects if o.id == object_id)


def _room(house: dict, objects: list[dict]) -> dict:
    data = copy.deepcopy(house)
    data["objects"] = objects
    return data


def test_rooms_openings_and_frame(result: ImportResult) -> None:
    scene = result.scene
    assert result.format == "procthor"
    assert [r.id for r in scene.rooms] == ["room|1", "room|2", "room|3", "room|4"]
    living = scene.room("room|2")
    assert len(living.polygon) == 6  # the L-shaped room
    # floorPolygon {x, y, z} -> (x, z)
    assert living.polygon[0] == (4.0, 0.0)
    assert scene.wall_height == pytest.approx(2.6)
    assert scene.wall_thickness == IMPORT_WALL_THICKNESS
    # Exterior walls grow outwards, so they keep the default thickness that stops tunnelling.
    assert (
        scene.exterior_wall_thickness == SceneSpec.model_fields["exterior_wall_thickness"].default
    )
    assert scene.source == SOURCE


def test_doors(result: ImportResult) -> None:
    doors = {d.id: d for d in result.scene.doors}
    assert len(doors) == 6  # five doors of the file + the open connection of the empty walls
    assert doors["door|1|2"].kind == "doorframe"
    assert doors["door|1|3"].kind == "doorway"
    assert doors["door|2|3"].leaves == "double"
    assert doors["door|2|3"].width == pytest.approx(1.6)
    assert doors["door|2|4"].leaves == "single"
    exterior = doors["door|2|exterior"]
    assert exterior.rooms == ["room|2"]
    # hole x 2.0..3.0 from the first vertex (10, 0) of wall0 towards (4, 0)
    assert exterior.position == pytest.approx((7.5, 0.0))
    # door|1|2: hole 1.0..2.0 along wall0 from (4, 4) towards (4, 0)
    assert doors["door|1|2"].position == pytest.approx((4.0, 2.5))
    assert doors["door|1|2"].height == pytest.approx(2.1)
    open_doors = [d for d in result.scene.doors if d.kind == "open"]
    assert len(open_doors) == 1
    assert sorted(open_doors[0].rooms) == ["room|2", "room|4"]
    assert open_doors[0].position == pytest.approx((8.5, 4.0))


def test_windows(result: ImportResult) -> None:
    windows = {w.id: w for w in result.scene.windows}
    assert len(windows) == 4
    assert [windows[k].kind for k in sorted(windows)] == ["fixed", "slider", "hung", "fixed"]
    kitchen = windows["window|1|0"]
    assert kitchen.rooms == ["room|1"]
    assert kitchen.position == pytest.approx((0.0, 1.6))
    assert (kitchen.width, kitchen.height, kitchen.base_height) == pytest.approx((1.2, 1.2, 0.9))


def test_materials(result: ImportResult) -> None:
    scene = result.scene
    rooms = {r.id: r for r in scene.rooms}
    assert rooms["room|1"].floor_material == "marble"  # BrownMarbleFake1 (table)
    assert rooms["room|2"].floor_material == "oak_floor"  # WoodFloorsCross (table)
    assert rooms["room|3"].floor_material == "carpet_grey"
    # a colour given with the material becomes a scene material of that colour
    tiles = rooms["room|4"].floor_material
    assert scene.materials[tiles].rgba == pytest.approx((0.9, 0.9, 0.95, 1.0))
    # most common wall material of the room (one wall of the living room is BlueDrywall)
    assert rooms["room|2"].wall_material == "beige_paint"
    assert rooms["room|1"].wall_material == "white_paint"
    assert rooms["room|4"].wall_material == "grey_paint"
    # unknown name: deterministic colour, registered, with a warning
    odd = rooms["room|3"].wall_material
    assert odd in scene.materials
    assert any("Xyzzy9" in w for w in result.warnings)
    assert all(r.ceiling_material == "white_paint" for r in scene.rooms)


def test_objects_positions_and_yaw(result: ImportResult) -> None:
    scene = result.scene
    # Chair|1|1: rotation.y = 90 faces unity +x = holomj +X -> yaw 0; centre y 0.45, on the floor
    chair = _obj(scene, "Chair|1|1")
    assert chair.yaw_deg == pytest.approx(0.0)
    assert chair.position == pytest.approx((1.2, 2.0, 0.0))
    assert _obj(scene, "Chair|1|2").yaw_deg == pytest.approx(180.0)
    # Mug_1 is in the library (0.1 m tall): bbox centre 0.80 -> bottom 0.75, on the table
    mug = _obj(scene, "Mug|1|0|0")
    assert mug.asset == "Mug_1"
    assert mug.position[2] == pytest.approx(0.75)
    assert mug.support == "DiningTable|1|0"
    assert mug.room == "room|1"
    assert mug.yaw_deg == pytest.approx(45.0)
    assert _obj(scene, "Television|2|3|0").support == "TVStand|2|3"
    assert _obj(scene, "Fridge|1|3").static
    assert not _obj(scene, "Sofa|2|0").static
    # rooms found from the object's x/y
    assert _obj(scene, "Sofa|2|0").room == "room|2"
    assert _obj(scene, "Bed|3|0").room == "room|3"
    # non-zero rotation.x/z -> a full quaternion
    book = _obj(scene, "Book|3|1|0")
    assert book.quat is not None
    assert _obj(scene, "Bed|3|0").quat is None


def test_position_z_uses_height_of_asset(library: AssetLibrary, house: dict) -> None:
    # A mug floating at bbox centre 1.30 m: the library mug is 0.10 m tall -> z = 1.25.
    data = _room(
        house,
        [
            {
                "id": "Mug|1|9",
                "assetId": "Mug_1",
                "position": {"x": 1.0, "y": 1.30, "z": 1.0},
                "rotation": {"x": 0, "y": 90, "z": 0},
            }
        ],
    )
    mug = import_procthor(data, library, "mug.json").scene.objects[0]
    assert mug.position == pytest.approx((1.0, 1.0, 1.25))
    assert mug.yaw_deg == pytest.approx(0.0)


def test_substitution_report(result: ImportResult) -> None:
    subs = {s.object_id: s for s in result.substitutions}
    # Sofa_1 is no AI2-THOR asset: the THOR type comes from the id, the size from the
    # category's typical size, and the closest sofa stands in unscaled.
    sofa = subs["Sofa|2|0"]
    assert (sofa.requested_asset, sofa.category, sofa.used_asset) == (
        "Sofa_1",
        "sofa",
        "sofa_modern",
    )
    assert sofa.reason == "not in library; same category, closest size"
    assert (sofa.scale, sofa.size_source) == (1.0, "category")
    fridge = subs["Fridge|1|3"]
    assert fridge.used_asset == "builtin:box"
    assert "no asset of category 'fridge'" in fridge.reason
    # Fridge_1 is in the AI2-THOR table (x 1.013 wide, y 1.9668 high, z 0.7242 deep): the box
    # gets that true size (depth, width, height)
    assert _obj(result.scene, "Fridge|1|3").scale == pytest.approx((0.7242, 1.013, 1.9668))
    assert fridge.source_size == pytest.approx((0.7242, 1.013, 1.9668))
    assert fridge.size_source == "thor"
    # unknown category: a 0.5 m cube with a warning
    assert _obj(result.scene, "Zorblax|2|4").scale == pytest.approx((0.5, 0.5, 0.5))
    assert any("Zorblax" in w and "0.5 m cube" in w for w in result.warnings)
    assert "Mug|1|0|0" not in subs  # in the library: no substitution
    report = result.to_report()
    assert report["objects"] == len(result.scene.objects) == 21
    assert report["substitutions"][0].keys() == {
        "object_id",
        "requested_asset",
        "category",
        "used_asset",
        "reason",
        "scale",
        "source_size",
        "size_source",
        "turn_deg",
    }


def test_closest_size_picks_the_smaller_sofa(library: AssetLibrary, house: dict) -> None:
    data = _room(
        house,
        [
            {
                "id": "Sofa|2|0",
                "assetId": "Sofa_9",
                "object_name": "sofa-0",
                "position": {"x": 8.0, "y": 0.4, "z": 2.0},
                "rotation": {"x": 0, "y": 0, "z": 0},
                "vertices": [[725, 155], [725, 245], [875, 245], [875, 155]],
            }
        ],
    )
    result = import_procthor(data, library, "sofa.json")
    assert result.scene.objects[0].asset == "sofa_small"  # 1.5 m wide, like the footprint


def test_lights(result: ImportResult) -> None:
    lights = {light.id: light for light in result.scene.lights}
    sun = lights["DirectionalLight"]
    assert sun.kind == "directional"
    assert sun.direction[2] < -0.5
    assert sun.energy == pytest.approx(0.35)
    point = lights["light_1"]
    assert point.kind == "point"
    assert point.position == pytest.approx((2.0, 2.0, 2.4))
    assert point.color == pytest.approx((1.0, 0.855, 0.722))
    spot = lights["light_spot_bed"]
    assert spot.direction == pytest.approx((0.0, 0.0, -1.0), abs=1e-9)
    assert spot.cutoff_deg == pytest.approx(30.0)


def test_energy_is_clamped(library: AssetLibrary, house: dict) -> None:
    data = copy.deepcopy(house)
    data["proceduralParameters"]["lights"] = [
        {"id": "blinding", "type": "point", "position": {"x": 1, "y": 2, "z": 1}, "intensity": 1e5}
    ]
    light = import_procthor(data, library, "x.json").scene.lights[0]
    assert light.energy == 100.0


def test_legacy_schema(library: AssetLibrary) -> None:
    result = import_procthor(load_fixture("procthor_house_legacy.json"), library, "legacy.json")
    scene = result.scene
    assert len(scene.rooms) == 2
    assert scene.room("room|2").floor_material == "oak_floor"
    assert scene.room("room|1").floor_material == "grey_tile"
    assert scene.room("room|2").wall_material == "blue_paint"
    door = scene.doors[0]
    assert door.kind == "doorway"
    assert door.position == pytest.approx((4.0, 1.7))  # boundingBox x 0.8..1.8 from (4, 3)
    window = scene.windows[0]
    assert window.kind == "hung"
    assert window.rooms == ["room|2"]
    assert scene.wall_height == pytest.approx(2.5)
    assert {o.asset for o in scene.objects} == {"sofa_modern", "chair_wood"}


def test_import_is_deterministic(house: dict, library: AssetLibrary) -> None:
    first = import_procthor(copy.deepcopy(house), library, SOURCE)
    second = import_procthor(copy.deepcopy(house), library, SOURCE)
    assert first.scene.model_dump_json() == second.scene.model_dump_json()
    assert first.to_report() == second.to_report()
