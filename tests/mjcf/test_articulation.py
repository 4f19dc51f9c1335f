"""Articulated objects in the compiled scene: part bodies on named joints, closed by default,
exported to scene.xml and objects.json, loaded by MuJoCo and dm_control, accepted by MJX."""

from __future__ import annotations

import math
from pathlib import Path

import mujoco
import numpy as np
import pytest

from holomj.jobs.folder import write_scene_folder
from holomj.jobs.robot_learning import objects_json
from holomj.library import AssetLibrary
from holomj.mjcf import compile_scene
from holomj.spec.scene import SceneSpec
from tests.asset_pipeline.articulated_helpers import (
    ROOM,
    articulated_library,
    part_joints,
    simulate,
    warnings_of,
)

KITCHEN = ["base_cabinet", "fridge", "dishwasher", "stove", "washing_machine", "microwave"]


@pytest.fixture(scope="module")
def library(tmp_path_factory: pytest.TempPathFactory) -> AssetLibrary:
    root = tmp_path_factory.mktemp("articulated") / "library"
    return articulated_library(root, [*KITCHEN, "dresser", "trunk"])


def _scene(objects: list[dict]) -> SceneSpec:
    return SceneSpec.model_validate({"name": "kitchen", "rooms": [ROOM], "objects": objects})


def _kitchen() -> SceneSpec:
    """A row of articulated appliances and cabinets along a wall, a microwave on the cabinet,
    a dresser turned to face +Y, a trunk scaled up."""
    objects: list[dict] = []
    y = 0.5
    for category in KITCHEN[:-1]:
        objects.append(
            {
                "id": category,
                "asset": f"{category}_art_000",
                "position": [0.45, y, 0.0],
                "room": "room",
            }
        )
        y += 0.9
    objects.append(
        {
            "id": "microwave",
            "asset": "microwave_art_000",
            "position": [0.4, 0.5, 0.88 + 0.001],
            "room": "room",
            "support": "base_cabinet",
        }
    )
    objects.append(
        {
            "id": "dresser",
            "asset": "dresser_art_000",
            "position": [3.5, 0.4, 0.0],
            "yaw_deg": 90.0,
            "room": "room",
        }
    )
    objects.append(
        {
            "id": "trunk",
            "asset": "trunk_art_000",
            "position": [3.5, 3.5, 0.0],
            "scale": [1.1, 1.2, 1.0],
            "room": "room",
        }
    )
    return _scene(objects)


def test_parts_compile_to_bodies_on_named_joints(library: AssetLibrary) -> None:
    compiled = compile_scene(_kitchen(), library, furniture="free")
    model = compiled.model
    meta = library.get("base_cabinet_art_000").meta
    art = meta.articulation
    assert art is not None
    for part in art.parts:
        body = model.body(f"base_cabinet/{part.name}")
        joint = model.joint(f"base_cabinet/{part.joint.name}")
        assert model.body_parentid[body.id] == model.body("base_cabinet/body").id
        assert joint.bodyid[0] == body.id
        kind = (
            mujoco.mjtJoint.mjJNT_HINGE
            if part.joint.type == "hinge"
            else mujoco.mjtJoint.mjJNT_SLIDE
        )
        assert joint.type[0] == kind
        np.testing.assert_allclose(joint.range, part.joint.range, atol=1e-9)
        assert joint.limited[0] and joint.damping[0] == pytest.approx(part.joint.damping)
        assert model.site(f"base_cabinet/{part.name}/handle").bodyid[0] == body.id
        # Contacts with the carcass are excluded (the joint range stops the part).
        assert model.nexclude >= len(art.parts)
    # The default pose is closed; the object weighs what its asset says (parts included).
    assert np.all(model.qpos0[[model.jnt_qposadr[j] for j in part_joints(model, "")]] == 0.0)
    carcass = model.body("base_cabinet/body").id
    assert model.body_subtreemass[carcass] == pytest.approx(meta.mass, rel=1e-6)
    # A scaled object: slides travel further with the axis they run along, pivots move.
    trunk = library.get("trunk_art_000").meta.articulation
    assert trunk is not None
    lid = model.joint("trunk/lid_hinge")
    anchor = np.array(trunk.parts[0].joint.anchor) * [1.1, 1.2, 1.0]
    np.testing.assert_allclose(lid.pos, anchor, atol=1e-9)
    text = compiled.to_xml()
    assert 'name="dishwasher/rack_0_slide"' in text and "<exclude" in text


def test_scene_xml_loads_and_runs_without_warnings(library: AssetLibrary, tmp_path: Path) -> None:
    folder = write_scene_folder(
        compile_scene(_kitchen(), library, furniture="free"), tmp_path / "k"
    )
    model = mujoco.MjModel.from_xml_path(str(folder / "scene.xml"))
    data = mujoco.MjData(model)
    simulate(model, data, 1.0)
    assert not warnings_of(data)
    for joint in part_joints(model, ""):
        if model.joint(joint).name.startswith(("structure", "front")):
            continue
        q = data.qpos[model.jnt_qposadr[joint]]
        tol = math.radians(0.5) if model.jnt_type[joint] == mujoco.mjtJoint.mjJNT_HINGE else 1e-3
        assert abs(q) < tol, model.joint(joint).name


def test_objects_json_lists_joints_handles_and_interior_surfaces(library: AssetLibrary) -> None:
    compiled = compile_scene(_kitchen(), library)
    record = {o["id"]: o for o in objects_json(compiled)["objects"]}
    dresser = record["dresser"]
    assert dresser["joints"] and dresser["interior_surfaces"]
    first = dresser["joints"][0]
    assert first["name"] == "dresser/drawer_0_slide" and first["type"] == "slide"
    assert first["body"] == "dresser/drawer_0" and first["value"] == 0.0 == first["closed"]
    # The dresser faces +Y (yaw 90°): its drawers pull out along +Y, handles on that side.
    np.testing.assert_allclose(first["axis"], [0.0, 1.0, 0.0], atol=1e-6)
    handle = first["handle"]
    np.testing.assert_allclose(handle["pull"], [0.0, 1.0, 0.0], atol=1e-6)
    assert handle["position"][1] > dresser["position"][1] + 0.2
    assert handle["site"] == "dresser/drawer_0/handle"
    bottoms = [s for s in dresser["interior_surfaces"] if s["part"] == "drawer_0"]
    assert bottoms and bottoms[0]["body"] == "dresser/drawer_0"
    assert bottoms[0]["behind"] == ["dresser/drawer_0_slide"]
    inside = bottoms[0]["polygon"]
    low, high = dresser["aabb"]["min"], dresser["aabb"]["max"]
    assert all(low[0] <= x <= high[0] and low[1] <= y <= high[1] for x, y in inside)
    fridge = record["fridge"]
    hinge = fridge["joints"][0]
    assert hinge["type"] == "hinge" and hinge["range"][1] == pytest.approx(math.radians(110))
    assert fridge["interior_surfaces"] and all(
        s["part"] is None and s["behind"] for s in fridge["interior_surfaces"]
    )
    # The box around an articulated object holds its doors and handles too.
    assert fridge["aabb"]["max"][0] == pytest.approx(0.45 + 0.35, abs=1e-3)
    # Rigid objects list none.
    rigid = compile_scene(
        _scene([{"id": "b", "asset": "builtin:box", "position": [1, 1, 0], "room": "room"}]),
        library,
    )
    (box,) = objects_json(rigid)["objects"]
    assert box["joints"] == [] and box["interior_surfaces"] == []


def test_dm_control_loads_the_scene_and_exposes_the_joints(
    library: AssetLibrary, tmp_path: Path
) -> None:
    from holomj.jobs.arena import HolomjArena

    folder = write_scene_folder(compile_scene(_kitchen(), library), tmp_path / "k")
    arena = HolomjArena(folder)
    joints = arena.articulations()
    names = {j["name"] for j in joints}
    assert "fridge/door_0_hinge" in names and "dishwasher/rack_1_slide" in names
    door = next(j for j in joints if j["name"] == "fridge/door_0_hinge")
    assert door["joint_element"] is not None and door["handle_element"] is not None
    from dm_control import mjcf

    physics = mjcf.Physics.from_mjcf_model(arena.mjcf_model)
    physics.bind(door["joint_element"]).qpos = 0.5
    physics.step()
    assert physics.bind(door["joint_element"]).qpos[0] == pytest.approx(0.5, abs=0.02)


def test_mjx_profile_accepts_articulated_objects(library: AssetLibrary) -> None:
    mjx = pytest.importorskip(
        "mujoco.mjx", reason="needs the mjx extra (pip install 'holomj[mjx]')"
    )
    compiled = compile_scene(_kitchen(), library, profile="mjx")
    door = compiled.model.geom("washing_machine/door_0/collision_0")
    assert door.type[0] == mujoco.mjtGeom.mjGEOM_MESH  # the round door, as a convex prism
    mjx.put_model(compiled.model)
