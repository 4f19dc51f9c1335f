"""Procedural articulated assets, in real simulation: every category stays closed, opens under a
30 N pull on its handle, closes again without penetration, and keeps what is put inside."""

from __future__ import annotations

import math
from pathlib import Path

import mujoco
import numpy as np
import pytest

from asset_pipeline.procedural import CATEGORIES, DEFAULT_LIBRARY_VERSION
from asset_pipeline.procedural.articulated import (
    ARTICULATED,
    ARTICULATED_VERSION,
    KEPT_RIGID,
    LIBRARY_ARTICULATED,
    articulated_variants,
    generate_articulated,
)
from asset_pipeline.procedural.attributes import attributes_from_text
from holomj.errors import InputError
from holomj.library import AssetLibrary
from holomj.mjcf import compile_scene
from tests.asset_pipeline.articulated_helpers import (
    HINGE,
    apply_pull,
    articulated_library,
    clearance_to_parent,
    compiled_object,
    one_object_scene,
    part_joints,
    simulate,
    value,
    warnings_of,
)

CATEGORY_NAMES = sorted(ARTICULATED)
# Every asset of the library (each category's size variants; the default library ships them).
ASSET_IDS = sorted(v[0] for v in articulated_variants())
OPEN_DOOR_RAD = math.radians(20.0)
OPEN_DRAWER_M = 0.10
DEEPEST_M = 0.001


@pytest.fixture(scope="module")
def library(tmp_path_factory: pytest.TempPathFactory) -> AssetLibrary:
    """Every articulated asset of the library variant (all sizes of every category)."""
    root = tmp_path_factory.mktemp("articulated") / "library"
    return articulated_library(root)


def _asset(category: str) -> str:
    return f"{category}_art_000"


# --- the assets -------------------------------------------------------------------------------
def test_the_catalogue_covers_the_issue() -> None:
    wanted = {
        "base_cabinet", "kitchen_cabinet", "wall_cabinet", "drawer_unit", "wardrobe", "dresser",
        "nightstand", "sideboard", "fridge", "oven", "stove", "dishwasher", "microwave",
        "washing_machine", "toilet", "laptop", "trunk", "toy_box", "kitchen_counter",
        "sink_counter",
    }  # fmt: skip
    assert wanted <= set(ARTICULATED)
    # Categories the rigid library has keep their kind and placement (a one-line swap later).
    for name, info in ARTICULATED.items():
        if name in CATEGORIES and name != "laptop":  # the rigid laptop stands open
            rigid = CATEGORIES[name]
            assert info.placement == rigid.placement and info.kind == rigid.kind, name
            assert info.check_size(rigid.default_size) == rigid.default_size, name
            # the same valid sizes: synthesis clamps a planned size alike either way
            assert (info.size_min, info.size_max) == (rigid.size_min, rigid.size_max), name
            assert info.variants == rigid.variants, name


@pytest.mark.parametrize("category", CATEGORY_NAMES)
def test_metadata_records_parts_joints_handles_and_interiors(category: str) -> None:
    bundle = generate_articulated(category, f"{category}_x", None, 0)
    meta = bundle.meta
    art = meta.articulation
    assert art is not None and art.parts
    size = np.asarray(meta.size)
    for part in art.parts:
        joint = part.joint
        assert joint.closed == 0.0 and joint.range[0] == 0.0
        assert joint.damping > 0 and joint.frictionloss > 0
        if joint.type == "hinge":
            assert math.radians(60) <= joint.range[1] <= math.radians(135), part.name
        else:  # drawers and racks open to 0.9 of their depth
            assert 0.2 <= joint.range[1] <= 0.9 * size[0], part.name
        assert part.handle is not None, part.name
        assert np.all(np.abs(part.handle.pos) <= size / 2 + [0, 0, size[2]]), part.name
        assert abs(np.linalg.norm(part.handle.pull) - 1.0) < 1e-6
        assert part.mass_kg > 0
        for name in [v.mesh for v in part.visual] + [c.mesh for c in part.collision if c.mesh]:
            assert name in bundle.files
    assert art.mass_kg < meta.mass
    for surface in art.interior:
        assert surface.behind and surface.clearance_m is not None and surface.clearance_m >= 0.05
    if category not in ("toilet", "laptop"):
        assert art.interior, "things can be put inside"
    drawers = [p for p in art.parts if p.kind == "drawer"]
    for drawer in drawers:  # each drawer bottom is an interior surface moving with it
        assert any(s.part == drawer.name for s in art.interior)


def test_designs_are_deterministic_and_checked() -> None:
    first = generate_articulated("dresser", "d", None, 3)
    second = generate_articulated("dresser", "d", None, 3)
    assert first.meta == second.meta and first.files == second.files
    with pytest.raises(InputError, match="outside the valid range"):
        generate_articulated("dresser", "d", (5.0, 1.0, 1.0), 0)
    with pytest.raises(InputError, match=r"no articulated generator.*did you mean"):
        generate_articulated("dreser", "d")
    assert ARTICULATED_VERSION.startswith("art-") and DEFAULT_LIBRARY_VERSION
    ids = [v[0] for v in articulated_variants()]
    assert len(ids) == len(set(ids)) and "base_cabinet_art_000" in ids


def test_attributes_recolour_articulated_parts() -> None:
    wanted = attributes_from_text("a white cabinet with brass handles", "base_cabinet")
    bundle = generate_articulated("base_cabinet", "c", None, 0, wanted)
    assert bundle.meta.attributes.get("handles.material") == "brass"
    door = bundle.meta.articulation.part("door_0")  # type: ignore[union-attr]
    brass = [v for v in door.visual if "brass" in v.mesh]
    assert brass, [v.mesh for v in door.visual]


def test_rigid_assets_are_unchanged() -> None:
    rigid = CATEGORIES["base_cabinet"]
    assert rigid.builder.__module__ == "asset_pipeline.procedural.storage"
    from asset_pipeline.procedural import generate_asset

    meta = generate_asset("base_cabinet", "b").meta
    assert meta.articulation is None and "articulation" not in meta.model_dump(mode="json")


# --- simulation -------------------------------------------------------------------------------
def _open_parent_first(model: mujoco.MjModel, data: mujoco.MjData, joint: int) -> None:
    """A rack behind a closed door: open the door (its sibling hinge) first."""
    name = model.joint(joint).name
    if not name.endswith("_slide") or "rack" not in name:
        return
    door = model.joint(name.split("/")[0] + "/door_0_hinge").id
    data.qpos[model.jnt_qposadr[door]] = model.jnt_range[door][1]
    mujoco.mj_forward(model, data)
    simulate(model, data, 0.3)


@pytest.mark.parametrize("asset", ASSET_IDS)
def test_stays_closed_opens_under_a_pull_and_closes_without_penetration(
    library: AssetLibrary, asset: str
) -> None:
    model = compiled_object(library, asset).model
    joints = part_joints(model)
    assert joints
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    simulate(model, data, 2.0)  # left alone: stays closed
    for joint in joints:
        moved = abs(value(model, data, joint))
        limit = math.radians(0.5) if int(model.jnt_type[joint]) == HINGE else 0.001
        assert moved < limit, f"{model.joint(joint).name} moved {moved} in 2 s alone"
    assert not warnings_of(data)
    for joint in joints:
        name = model.joint(joint).name
        hinge = int(model.jnt_type[joint]) == HINGE
        data = mujoco.MjData(model)
        mujoco.mj_forward(model, data)
        _open_parent_first(model, data, joint)
        simulate(model, data, 1.5, joint, +1.0)
        opened = value(model, data, joint)
        assert opened >= (OPEN_DOOR_RAD if hinge else OPEN_DRAWER_M), f"{name} opened {opened}"
        deepest = simulate(model, data, 1.5, joint, -1.0)
        assert deepest <= DEEPEST_M, f"{name} closed with a contact {deepest * 1000:.2f} mm deep"
        simulate(model, data, 0.3)
        closed = value(model, data, joint)
        assert abs(closed) < (math.radians(1.0) if hinge else 0.002), f"{name} ended at {closed}"
        assert clearance_to_parent(model, data, joint) > -DEEPEST_M, name
        assert not warnings_of(data), name


def test_a_free_standing_dresser_stays_put_and_opens(library: AssetLibrary) -> None:
    compiled = compiled_object(library, _asset("dresser"), static=False)
    model = compiled.model
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    carcass = model.body("obj/body").id
    start = data.xipos[carcass].copy()
    simulate(model, data, 2.0)
    joints = part_joints(model)
    assert max(abs(value(model, data, j)) for j in joints) < 0.001
    assert np.linalg.norm(data.xipos[carcass] - start) < 0.005
    top = max(joints, key=lambda j: model.jnt_pos[j][2])  # the top drawer
    simulate(model, data, 1.5, top, +1.0)
    assert value(model, data, top) >= OPEN_DRAWER_M
    assert not warnings_of(data)


def test_an_object_in_a_drawer_stays_inside_when_it_is_pulled(
    library: AssetLibrary, tmp_path: Path
) -> None:
    asset = library.get(_asset("nightstand"))
    art = asset.meta.articulation
    assert art is not None
    drawer = art.parts[-1]  # the top drawer
    (bottom,) = [s for s in art.interior if s.part == drawer.name]
    xs, ys = zip(*bottom.polygon)
    spot = [3.0 + float(np.mean(xs)), 3.0 + float(np.mean(ys)), bottom.height + 0.01]
    cube = {"id": "cube", "asset": "builtin:box", "position": spot, "scale": [0.05, 0.05, 0.05],
            "room": "room", "mass_kg": 0.2}  # fmt: skip
    scene = one_object_scene(asset.meta.id, objects=[cube])
    model = compile_scene(scene, library).model
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    simulate(model, data, 0.5)  # dropped 1 cm onto the drawer bottom
    joint = model.joint(f"obj/{drawer.joint.name}").id
    body = model.body(f"obj/{drawer.name}").id
    box = model.body("cube/body").id
    simulate(model, data, 1.5, joint, +1.0)
    assert value(model, data, joint) >= OPEN_DRAWER_M
    simulate(model, data, 0.5)
    # The cube is still on the drawer bottom, inside its walls, in the drawer's frame.
    rel = data.xmat[body].reshape(3, 3).T @ (data.xipos[box] - data.xpos[body])
    low, high = np.array([min(xs), min(ys)]), np.array([max(xs), max(ys)])
    margin = 0.021  # the surface is eroded 2 cm from the drawer walls
    assert np.all(rel[:2] >= low - margin) and np.all(rel[:2] <= high + margin), rel
    assert abs(rel[2] - (bottom.height + 0.025)) < 0.005, rel
    apply_pull(model, data, joint, 0.0)
    assert not warnings_of(data)


# --- the library switch -----------------------------------------------------------------------
def test_the_default_library_is_articulated_by_default() -> None:
    from asset_pipeline import default_library

    assert default_library.ARTICULATED_BY_DEFAULT is True
    # synthesis on demand follows: the library's articulated categories, not the laptop
    assert default_library.articulated_synthesis("kitchen_counter")
    assert not default_library.articulated_synthesis("laptop")
    assert not default_library.articulated_synthesis("sofa")
    assert sorted(KEPT_RIGID) == ["laptop"]
    assert sorted(LIBRARY_ARTICULATED) == sorted(set(ARTICULATED) - KEPT_RIGID)


@pytest.mark.slow
def test_the_switch_builds_the_default_library_articulated(tmp_path: Path) -> None:
    from asset_pipeline.default_library import VERSION_FILE, ensure_default_library

    root = ensure_default_library(tmp_path / "library", articulated=True)
    library = AssetLibrary.open(root)
    for category in LIBRARY_ARTICULATED:
        found = library.by_category(category)
        assert found and all(a.meta.articulation is not None for a in found), category
    assert library.by_category("sofa")  # the rest of the default library is there
    laptops = library.by_category("laptop")  # kept rigid: open on desks, as planned
    assert laptops and all(a.meta.articulation is None for a in laptops)
    assert (root / VERSION_FILE).read_text().strip() == ARTICULATED_VERSION
    ensure_default_library(root, articulated=False)  # and back: the rigid ones return
    rigid = AssetLibrary.open(root).by_category("base_cabinet")
    assert rigid and all(a.meta.articulation is None for a in rigid)


# --- the metadata schema ----------------------------------------------------------------------
def test_the_articulation_record_is_checked() -> None:
    from holomj.errors import SpecError
    from holomj.spec.assets import AssetMeta
    from holomj.spec.base import validate_model

    good = generate_articulated("nightstand", "n", None, 1).meta.model_dump(mode="json")
    assert validate_model(AssetMeta, good, "n").articulation is not None

    def broken(change) -> str:
        data = generate_articulated("nightstand", "n", None, 1).meta.model_dump(mode="json")
        change(data)
        with pytest.raises(SpecError) as err:
            validate_model(AssetMeta, data, "n")
        return str(err.value)

    part = ("articulation", "parts", 0)

    def at(data, path):
        for key in path:
            data = data[key]
        return data

    assert "low < high" in broken(lambda d: at(d, part)["joint"].update(range=[0.3, 0.1]))
    assert "outside the range" in broken(lambda d: at(d, part)["joint"].update(closed=1.0))
    assert "must come before" in broken(lambda d: at(d, part).update(parent="drawer_9"))
    assert "two parts" in broken(lambda d: d["articulation"]["parts"].append(at(d, part)))
    assert "needs mass_kg" in broken(lambda d: d.update(mass_kg=None))
    assert "not less than" in broken(lambda d: d.update(mass_kg=0.5))
    assert "unknown part" in broken(lambda d: d["articulation"]["interior"][0].update(part="x"))
