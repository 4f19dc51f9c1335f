"""AI2-THOR asset table, THOR types, true sizes and materials of real ProcTHOR house imports."""

from __future__ import annotations

import copy
import json
import re
from importlib import resources

import pytest

from holomj.importers import ImportResult, import_procthor
from holomj.importers.counter_shapes import counter_shape
from holomj.importers.ids import sanitise
from holomj.importers.materials import MaterialResolver, table_name
from holomj.importers.substitute import (
    MAX_ASPECT_CHANGE,
    MIN_EXTENT,
    SCALE_MAX,
    SCALE_MIN,
    choose_asset,
    fit_scale,
)
from holomj.importers.thor_assets import (
    thor_asset,
    thor_assets,
    thor_category,
    thor_type_table,
)
from holomj.library import AssetLibrary
from holomj.spec.materials import BUILTIN_MATERIALS

from .conftest import REAL_HOUSES, load_fixture, load_real_house, write_library

# Assets of the default library's categories (sizes as there: depth, width, height).
THOR_TEST_ASSETS = {
    "bed_000": ("bed", 2.1, 1.6, 1.0),
    "sofa_000": ("sofa", 0.9, 2.0, 0.85),
    "dining_chair_000": ("dining_chair", 0.45, 0.45, 0.9),
    "dining_table_000": ("dining_table", 0.9, 1.6, 0.75),
    "kitchen_counter_001": ("kitchen_counter", 0.62, 2.4, 0.92),
    "dresser_000": ("dresser", 0.5, 1.2, 0.85),
    "fridge_001": ("fridge", 0.75, 0.9, 1.8),
    "toilet_000": ("toilet", 0.68, 0.4, 0.8),
    "television_000": ("television", 0.24, 1.25, 0.8, ["object"]),
    "painting_000": ("painting", 0.03, 0.8, 0.6, ["wall"]),
    "pan_000": ("pan", 0.26, 0.48, 0.05, ["object"]),
    "bread_000": ("bread", 0.12, 0.3, 0.1, ["object"]),
    "mug_001": ("mug", 0.09, 0.12, 0.11, ["object"]),
    "book_000": ("book", 0.23, 0.16, 0.03, ["object"]),
}
SNAKE = re.compile(r"^[a-z][a-z0-9_]*$")
OLD_SCHEMA = REAL_HOUSES[:2]


@pytest.fixture(scope="module")
def thor_library(tmp_path_factory: pytest.TempPathFactory) -> AssetLibrary:
    return AssetLibrary.open(write_library(tmp_path_factory.mktemp("thorlib"), THOR_TEST_ASSETS))


@pytest.fixture(scope="module")
def imported(thor_library: AssetLibrary) -> dict[str, tuple[dict, ImportResult]]:
    houses = {}
    for name in REAL_HOUSES:
        house = load_real_house(name)
        houses[name] = (house, import_procthor(copy.deepcopy(house), thor_library, name))
    return houses


def _walk(objects: list[dict], parent: dict | None = None):
    """Source objects in import order (each followed by its children), with their parent."""
    for obj in objects:
        yield obj, parent
        yield from _walk(obj.get("children") or [], obj)


def _kept(house: dict, result: ImportResult):
    """:func:`_walk` without the objects merged into their parent's stand-in (a faucet)."""
    merged = {m["object"] for m in result.merged}
    return [(o, p) for o, p in _walk(house["objects"]) if o["id"] not in merged]


def _used_size(result: ImportResult, library: AssetLibrary, object_id: str) -> tuple:
    """The size of an imported object in its own frame (asset size x scale, turn undone)."""
    obj = next(o for o in result.scene.objects if o.id == object_id)
    size = [a * s for a, s in zip(library.get(obj.asset).meta.size, obj.scale3)]
    sub = next((s for s in result.substitutions if s.object_id == object_id), None)
    if sub is not None and sub.turn_deg:
        size = [size[1], size[0], size[2]]
    return tuple(size)


# -- the tables ------------------------------------------------------------------------------
def test_every_thor_type_maps_to_a_category() -> None:
    types = {asset.type for asset in thor_assets().values()}
    assert len(thor_assets()) == 1653
    assert len(types) == 109
    assert set(thor_type_table()) == types
    for thor_type in sorted(types):
        category = thor_category(thor_type)
        assert category and SNAKE.match(category), thor_type
        assert all(SNAKE.match(c) for c in thor_type_table()[thor_type][1:]), thor_type
    assert thor_category("ArmChair") == "armchair"
    assert thor_category("CounterTop") == "kitchen_counter"
    assert thor_category("Spatula") == "spatula"


def test_asset_table_sizes_in_holomj_frame() -> None:
    bed = thor_asset("Bed_9")  # THOR [x 2.0712 wide, y 1.3546 high, z 2.4115 deep]
    assert bed is not None and bed.type == "Bed"
    assert bed.size == pytest.approx((2.4115, 2.0712, 1.3546))  # depth, width, height
    assert bed.receptacle and not bed.can_open
    fridge = thor_asset("fridge_1")  # case-insensitive
    assert fridge is not None and fridge.can_open and fridge.type == "Fridge"
    assert thor_asset("Zorblax_1") is None


def test_table_carries_attribution_and_licence() -> None:
    data = resources.files("holomj.data")
    source = json.loads(data.joinpath("thor_assets.json").read_text("utf-8"))["_source"]
    assert source["commit"] == "53d5bd4c8c96a699e6a615dc390abb670cc9d353"
    assert "Apache-2.0" in source["license"]
    licence = data.joinpath("LICENSE-procthor-Apache-2.0.txt").read_text("utf-8")
    assert "Apache License" in licence and "Allen Institute for AI" in licence


# -- fitting a stand-in ----------------------------------------------------------------------
def test_fit_scale_limits() -> None:
    assert fit_scale((1.0, 1.0, 1.0), (1.5, 0.8, 1.2)) == pytest.approx((1.5, 0.8, 1.2))
    assert fit_scale((1.0, 1.0, 1.0), (SCALE_MAX + 0.1, 1.0, 1.0)) is None
    assert fit_scale((1.0, 1.0, 1.0), (SCALE_MIN - 0.1, 0.5, 0.5)) is None
    # each axis within limits, but the proportions change too much
    assert fit_scale((1.0, 1.0, 1.0), (1.9, 1.9 / (MAX_ASPECT_CHANGE + 0.1), 1.0)) is None


def test_stand_in_scaled_turned_or_boxed(thor_library: AssetLibrary) -> None:
    # a sofa 2.4 m wide: the sofa scaled to it
    choice, warning = choose_asset(
        thor_library,
        object_id="s",
        requested="Sofa_X",
        category="sofa",
        size=(1.0, 2.4, 0.9),
        fit=True,
        size_source="thor",
    )
    assert warning is None and choice.asset == "sofa_000" and choice.turn_deg == 0
    assert choice.scale == pytest.approx((1.0 / 0.9, 1.2, 0.9 / 0.85), abs=1e-4)
    assert choice.height == pytest.approx(0.9, abs=1e-4)
    sub = choice.substitution
    assert sub is not None and sub.source_size == pytest.approx((1.0, 2.4, 0.9))
    assert sub.scale == choice.scale and sub.size_source == "thor"
    # a pan with its handle along its depth: the library pan (handle along y) turns
    choice, _ = choose_asset(
        thor_library,
        object_id="p",
        requested="Pan_X",
        category="pan",
        size=(0.43, 0.28, 0.05),
        fit=True,
    )
    assert choice.asset == "pan_000" and choice.turn_deg == 90.0
    assert choice.scale == pytest.approx((0.28 / 0.26, 0.43 / 0.48, 1.0), abs=1e-4)
    # furniture never turns: an L-shaped counter's 3 m deep box is beyond the limits -> a box
    choice, _ = choose_asset(
        thor_library,
        object_id="c",
        requested="Countertop_L_8x10",
        category="kitchen_counter",
        size=(3.048, 2.4392, 0.9384),
        fit=True,
    )
    assert choice.asset == "builtin:box"
    assert choice.scale == pytest.approx((3.048, 2.4392, 0.9384))
    assert "kitchen_counter_001" in choice.substitution.reason


# -- real houses -----------------------------------------------------------------------------
@pytest.mark.parametrize("name", OLD_SCHEMA)
def test_old_schema_objects_get_thor_categories(imported, name: str) -> None:
    house, result = imported[name]
    subs = {s.object_id: s for s in result.substitutions}
    for obj, _ in _kept(house, result):
        sub = subs[sanitise(obj["id"])]
        expected = thor_category(thor_asset(obj["assetId"]).type)
        assert sub.category == expected, obj["id"]
        assert not sub.category.isdigit() and sub.category != "small"


@pytest.mark.parametrize("name", REAL_HOUSES)
def test_objects_keep_their_true_size(imported, thor_library: AssetLibrary, name: str) -> None:
    house, result = imported[name]
    runs = [o for o in result.scene.objects if o.id.endswith(("_side_left", "_side_right"))]
    assert len(result.scene.objects) == len(_kept(house, result)) + len(runs)
    for obj, _ in _kept(house, result):
        if counter_shape(obj["assetId"]):  # built as counter runs (test_counter_shapes)
            continue
        true = [max(v, MIN_EXTENT) for v in thor_asset(obj["assetId"]).size]
        used = _used_size(result, thor_library, sanitise(obj["id"]))
        for axis in range(3):
            assert 0.5 <= used[axis] / true[axis] <= 2.0, (obj["id"], used, true)
            # fitted or boxed, the object has its true size to rounding
            assert used[axis] == pytest.approx(true[axis], rel=1e-3), (obj["id"], used, true)


@pytest.mark.parametrize("name", REAL_HOUSES)
def test_no_guessed_cubes_or_unknown_materials(imported, name: str) -> None:
    _, result = imported[name]
    assert not [w for w in result.warnings if "0.5 m cube" in w]
    assert not [w for w in result.warnings if "unknown material" in w]
    assert all(s.size_source == "thor" for s in result.substitutions)


@pytest.mark.parametrize("name", REAL_HOUSES)
def test_resting_objects_stay_on_their_support(
    imported, thor_library: AssetLibrary, name: str
) -> None:
    house, result = imported[name]
    objects = {o.id: o for o in result.scene.objects}
    on_floor = on_parent = 0
    for obj, parent in _kept(house, result):
        me = objects[sanitise(obj["id"])]
        bottom = obj["position"]["y"] - thor_asset(obj["assetId"]).size[2] / 2
        if parent is None:
            assert me.support is None
            if abs(bottom) < 0.01:
                assert me.position[2] == 0.0, obj["id"]
                on_floor += 1
            continue
        parent_top = parent["position"]["y"] + thor_asset(parent["assetId"]).size[2] / 2
        if counter_shape(parent["assetId"]):  # on the counter run under it
            assert str(me.support).startswith(sanitise(parent["id"])), obj["id"]
        else:
            assert me.support == sanitise(parent["id"])
        if abs(bottom - parent_top) < 0.01:
            base = objects[me.support]
            base_height = thor_library.get(base.asset).meta.size[2] * base.scale3[2]
            assert me.position[2] == pytest.approx(base.position[2] + base_height), obj["id"]
            on_parent += 1
    assert on_floor >= 10 and on_parent >= 5


def test_bed_headboard_against_its_wall(imported) -> None:
    # Bed_9 (2.41 m long) in room|4 of train_4, rotation.y 180: its back is at unity
    # z = 5.06 + 2.41 / 2 = 6.27, against the wall z = 6.293.
    _, result = imported["procthor_ai2thor_train_4.json"]
    bed = next(o for o in result.scene.objects if o.id == "Bed|4|0|0")
    assert bed.yaw_deg == pytest.approx(-90.0)  # front towards -Y: the back towards +Y
    depth = 2.4115
    assert bed.position[1] + depth / 2 == pytest.approx(6.293, abs=0.05)


def test_a_sinks_faucet_is_part_of_its_stand_in(imported) -> None:
    for name in REAL_HOUSES:
        house, result = imported[name]
        faucets = [o for o, _ in _walk(house["objects"]) if "Faucet" in o["assetId"]]
        merged = {m["object"]: m for m in result.merged}
        assert faucets and all(f["id"] in merged for f in faucets)
        for f in faucets:
            assert merged[f["id"]]["category"] == "faucet"
            sink = next(o for o in result.scene.objects if o.id == merged[f["id"]]["into"])
            assert sink.id in {s.object_id for s in result.substitutions}
        assert result.to_report()["merged"] == result.merged


def test_wall_colour_of_the_old_schema(imported) -> None:
    # 143: PureWhite walls painted (r 0.078, g 0.490, b 0.529) by their own 'color'
    _, result = imported["procthor_ai2thor_143.json"]
    walls = {r.id: r.wall_material for r in result.scene.rooms}
    material = result.scene.materials[walls["room|5"]]
    assert material.rgba[:3] == pytest.approx((0.0784, 0.4902, 0.5294), abs=1e-3)


# -- kinds of objects not in the THOR table --------------------------------------------------
def test_type_fallbacks_never_use_old_schema_id_prefixes(library: AssetLibrary) -> None:
    house = load_fixture("procthor_house_v1.json")
    house["objects"] = [
        {"id": "4|2|9", "assetId": "Coffee_Table_99", "position": {"x": 7, "y": 0.2, "z": 2}},
        {"id": "small|4|1", "assetId": "Zorblax_1", "position": {"x": 7, "y": 0.2, "z": 3}},
        {"id": "4|7", "assetId": "", "position": {"x": 7, "y": 0.2, "z": 1}},
        {"id": "Mug|4|3", "assetId": "Blorp_2", "position": {"x": 6, "y": 0.2, "z": 1}},
    ]
    result = import_procthor(house, library, "fallbacks.json")
    categories = {s.object_id: s.category for s in result.substitutions}
    assert categories == {
        "4|2|9": "coffee_table",  # THOR type spelled by the assetId
        "small|4|1": "Zorblax",  # the assetId's first word, not 'small'
        "4|7": "object",  # nothing to go by
        "Mug|4|3": "mug",  # THOR type from the id
    }


# -- materials -------------------------------------------------------------------------------
def test_material_names_as_written_in_houses() -> None:
    assert table_name("BrownMarbleFake 1") == "BrownMarbleFake1"
    assert table_name("YellowDrywall 2") == "YellowDrywall"
    resolver = MaterialResolver()
    assert resolver.resolve("bathroomTilesGrey 2", None, "x", "w") == "grey_tile"
    assert resolver.resolve("WoodFineDarkFloorsRedNRM1", None, "x", "w") == "cherry_floor"
    robin = resolver.resolve("RobinEgg", None, "x", "w")
    assert robin == "procthor_robin_egg"
    assert resolver.scene_materials[robin].rgba == pytest.approx((0.59, 0.84, 0.82, 1.0))
    assert resolver.warnings == []


def test_every_material_of_the_real_houses_is_known() -> None:
    names = set()
    for name in REAL_HOUSES:
        house = load_real_house(name)
        for room in house["rooms"]:
            names.add(_name(room.get("floorMaterial")))
        for wall in house["walls"]:
            names.add(_name(wall.get("material")))
        names.add(_name(house["proceduralParameters"].get("ceilingMaterial")))
    names.discard(None)
    assert len(names) >= 15
    for material in sorted(names):
        entry = table_name(material)
        assert entry is not None, material
    assert all(v in BUILTIN_MATERIALS for v in _table_targets())


def _name(material) -> str | None:
    return material.get("name") if isinstance(material, dict) else material


def _table_targets() -> list[str]:
    text = resources.files("holomj.data").joinpath("procthor_materials.json").read_text("utf-8")
    table = json.loads(text)
    return [
        v if isinstance(v, str) else v["like"] for k, v in table.items() if not k.startswith("_")
    ]


def test_turned_stand_in_keeps_tilted_orientation_consistent() -> None:
    from holomj.importers.frames import quat_from_euler_xyz, quat_from_unity
    from holomj.importers.house_objects import turn_quat as _turn_quat

    # a pure yaw: turning the quaternion by 90° is the yaw plus 90°
    turned = _turn_quat(quat_from_unity(0.0, 30.0, 0.0), 90.0)
    assert turned == pytest.approx(quat_from_euler_xyz(0.0, 0.0, 90.0 - 30.0 + 90.0), abs=1e-9)
    assert _turn_quat((1.0, 0.0, 0.0, 0.0), 0.0) == (1.0, 0.0, 0.0, 0.0)


# -- objects that open -----------------------------------------------------------------------
def test_objects_that_open_prefer_articulated_stand_ins(default_library: AssetLibrary) -> None:
    box = thor_asset("Box_10")
    assert box is not None and box.can_open

    def choose(prefer: bool):
        choice, _ = choose_asset(
            default_library,
            object_id="b",
            requested="Box_10",
            category=thor_category("Box"),
            size=box.size,
            fit=True,
            stand_ins=(*thor_type_table()["Box"][1:], "Box"),
            size_source="thor",
            prefer_articulated=prefer,
        )
        return choice, default_library.get(choice.asset).meta

    choice, meta = choose(True)  # a box with a lid that lifts, scaled to the THOR box
    assert meta.articulated and meta.category in ("toy_box", "trunk"), meta.id
    assert "(the original opens)" in choice.substitution.reason  # type: ignore[union-attr]  # a stand-in was chosen
    choice, meta = choose(False)  # without the preference: the rigid cardboard box
    assert meta.category == "cardboard_box" and not meta.articulated


@pytest.mark.parametrize("name", REAL_HOUSES)
def test_real_houses_get_articulated_stand_ins_for_what_opens(
    default_library: AssetLibrary, name: str
) -> None:
    house = load_real_house(name)
    result = import_procthor(copy.deepcopy(house), default_library, name)
    used = {o.id: o.asset for o in result.scene.objects}
    opening = [
        o
        for o, _ in _kept(house, result)
        if thor_asset(o["assetId"]).can_open
        and thor_asset(o["assetId"]).type in ("Box", "Fridge", "Toilet", "WashingMachine")
    ]
    assert opening
    for obj in opening:
        asset = used[sanitise(obj["id"])]
        meta = default_library.get(asset).meta
        assert meta.articulated, (obj["id"], asset)
