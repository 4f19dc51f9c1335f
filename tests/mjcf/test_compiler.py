"""The compiler: structure, openings, objects, determinism, golden XML, physics smoke runs."""

from __future__ import annotations

import difflib
import math
import os
from pathlib import Path

import mujoco
import numpy as np
import pytest
from shapely.geometry import Point, Polygon

from holomj.errors import AssetNotFoundError
from holomj.library import AssetLibrary
from holomj.mjcf import compile_scene
from holomj.mjcf.textures import PATTERNS, pattern_mean, pattern_png
from holomj.physics.smoke import simulate
from holomj.spec.materials import BUILTIN_MATERIALS
from holomj.spec.scene import SceneSpec
from tests.conftest import TESTS, two_room_data

GOLDEN = TESTS / "golden" / "two_room_scene.xml"


def _geom(model: mujoco.MjModel, name: str):
    return model.geom(name)


def test_golden_xml(two_room_scene: SceneSpec, empty_library: AssetLibrary) -> None:
    xml = compile_scene(two_room_scene, empty_library).to_xml()
    if os.environ.get("HOLOMJ_UPDATE_GOLDEN") == "1":
        GOLDEN.write_text(xml)
    expected = GOLDEN.read_text()
    if xml != expected:
        diff = "".join(
            difflib.unified_diff(
                expected.splitlines(True), xml.splitlines(True), "golden", "actual", n=1
            )
        )
        pytest.fail(
            f"XML differs from {GOLDEN} (set HOLOMJ_UPDATE_GOLDEN=1 to accept):\n{diff[:4000]}"
        )


def test_same_input_gives_identical_xml(
    two_room_scene: SceneSpec, empty_library: AssetLibrary
) -> None:
    first = compile_scene(two_room_scene, empty_library).to_xml()
    again = compile_scene(SceneSpec.model_validate(two_room_data()), empty_library).to_xml()
    assert first == again


def test_one_second_without_warnings(
    two_room_scene: SceneSpec, empty_library: AssetLibrary
) -> None:
    model = compile_scene(two_room_scene, empty_library).model
    result = simulate(model, 1.0)
    assert result.warnings == {}
    assert result.steps == 500


def test_class_conventions(two_room_scene: SceneSpec, empty_library: AssetLibrary) -> None:
    model = compile_scene(two_room_scene, empty_library).model
    for i in range(model.ngeom):
        name = model.geom(i).name
        if "/visual_" in name or "/frame_" in name or "/handle_" in name or "/floor/" in name:
            assert model.geom_group[i] == 2, name
            assert model.geom_contype[i] == 0 and model.geom_conaffinity[i] == 0, name
        if "/collision_" in name:
            assert model.geom_group[i] == 3, name
    # Visual geoms add no mass: the crate's mass is exactly its collider's.
    crate = model.body("crate/body")
    assert crate.mass[0] == pytest.approx(0.6 * 0.4 * 0.5 * 200.0)


def test_walls_have_real_holes(two_room_scene: SceneSpec, empty_library: AssetLibrary) -> None:
    model = compile_scene(two_room_scene, empty_library).model
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    walls = [i for i in range(model.ngeom) if model.geom(i).name.startswith("structure/wall_")]

    def blocked(point) -> bool:
        for i in walls:
            local = data.geom_xmat[i].reshape(3, 3).T @ (np.array(point) - data.geom_xpos[i])
            if np.all(np.abs(local) <= model.geom_size[i] + 1e-9):
                return True
        return False

    assert not blocked((2.0, 3.0, 1.0)), "kitchen door opening is blocked"
    assert blocked((2.0, 3.0, 2.4)), "wall above the kitchen door is missing"
    assert not blocked((0.0, 1.5, 1.5)), "kitchen window is blocked"
    assert blocked((-0.1, 1.5, 0.5)), "wall below the kitchen window is missing"
    assert not blocked((7.1, 2.0, 1.0)), "front door opening is blocked"
    assert blocked((1.0, 3.0, 1.0)), "solid interior wall missing"
    # The exterior corner is closed.
    assert blocked((7.1, -0.1, 1.0))


def test_door_hinge_swings_and_stops_at_its_limit(
    two_room_scene: SceneSpec, empty_library: AssetLibrary
) -> None:
    model = compile_scene(two_room_scene, empty_library).model
    data = mujoco.MjData(model)
    joint = model.joint("kitchen_door/hinge_0")
    low, high = joint.range
    assert math.isclose(high - low, math.pi / 2, rel_tol=1e-6)
    direction = 1.0 if high > 0 else -1.0
    dof = joint.dofadr[0]
    for _ in range(1500):
        data.qfrc_applied[dof] = direction * 30.0
        mujoco.mj_step(model, data)
    angle = data.qpos[joint.qposadr[0]]
    assert abs(angle) > math.radians(80), "door did not swing open"
    assert low - 0.05 <= angle <= high + 0.05, "door passed its limit"
    # It swings into the kitchen (y < 3): the leaf's free end moved to the kitchen side.
    mujoco.mj_forward(model, data)
    panel = model.geom("kitchen_door/panel_0").id
    assert data.geom_xpos[panel][1] < 2.9


def test_double_door_has_two_leaves_opening_into_the_room(
    two_room_scene: SceneSpec, empty_library: AssetLibrary
) -> None:
    model = compile_scene(two_room_scene, empty_library).model
    data = mujoco.MjData(model)
    for index in (0, 1):
        joint = model.joint(f"front_door/hinge_{index}")
        low, high = joint.range
        data.qpos[joint.qposadr[0]] = high if high > 0 else low
    mujoco.mj_forward(model, data)
    for index in (0, 1):
        # Fully open leaves stand inside the living room (x < 7).
        assert data.geom_xpos[model.geom(f"front_door/panel_{index}").id][0] < 6.7


def test_static_and_dynamic_objects(two_room_scene: SceneSpec, empty_library: AssetLibrary) -> None:
    model = compile_scene(two_room_scene, empty_library).model
    assert model.body("crate/body").jntnum[0] == 1
    assert model.body("table/body").jntnum[0] == 0
    assert model.joint("crate/freejoint").type[0] == mujoco.mjtJoint.mjJNT_FREE


def test_objects_rest_where_placed(two_room_scene: SceneSpec, empty_library: AssetLibrary) -> None:
    model = compile_scene(two_room_scene, empty_library).model
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    start = {name: data.body(name).xpos.copy() for name in ("crate/body", "cube/body")}
    for _ in range(1000):
        mujoco.mj_step(model, data)
    for name, pos in start.items():
        assert np.linalg.norm(data.body(name).xpos - pos) < 0.005, name


def test_cameras_and_lights(two_room_scene: SceneSpec, empty_library: AssetLibrary) -> None:
    model = compile_scene(two_room_scene, empty_library).model
    cams = {model.camera(i).name for i in range(model.ncam)}
    assert {
        "camera/overview",
        "camera/room/kitchen",
        "camera/room/living",
        "camera/doorway_view",
    } <= cams
    assert (
        model.cam_projection[model.camera("camera/overview").id]
        == mujoco.mjtProjection.mjPROJ_ORTHOGRAPHIC
    )
    assert model.nlight == 2
    assert model.light("light/sun").type[0] == mujoco.mjtLightType.mjLIGHT_DIRECTIONAL


def test_default_lights_when_scene_has_none(empty_library: AssetLibrary) -> None:
    data = two_room_data()
    data["lights"] = []
    model = compile_scene(SceneSpec.model_validate(data), empty_library).model
    assert model.nlight == 3  # a sun and one light per room


def test_ceilings_are_optional_and_hideable(empty_library: AssetLibrary) -> None:
    data = two_room_data()
    data["ceilings"] = True
    model = compile_scene(SceneSpec.model_validate(data), empty_library).model
    ceiling = model.geom("structure/ceiling/living")
    assert ceiling.group[0] == 1 and ceiling.contype[0] == 0


def test_non_rectangular_floor_is_triangulated(
    two_room_scene: SceneSpec, empty_library: AssetLibrary
) -> None:
    model = compile_scene(two_room_scene, empty_library).model
    mesh = model.mesh("structure/floor/living")
    verts = model.mesh_vert[mesh.vertadr[0] : mesh.vertadr[0] + mesh.vertnum[0]]
    # The L-shaped living room keeps its notch: no floor vertex inside the kitchen's square.
    assert not any(0.01 < x < 3.99 and 0.01 < y < 2.99 for x, y, _ in verts)


def test_missing_asset_names_the_object(empty_library: AssetLibrary) -> None:
    data = two_room_data()
    data["objects"][1]["asset"] = "builtin:boks"
    with pytest.raises(
        AssetNotFoundError, match=r"objects\[1\]\.asset \(table\).*did you mean: builtin:box"
    ):
        compile_scene(SceneSpec.model_validate(data), empty_library)


def test_texture_material(tmp_path: Path, empty_library: AssetLibrary, shared_assets: Path) -> None:
    data = two_room_data()
    texture = shared_assets / "textures" / "libero_seamless_wood_planks_floor.png"
    data["materials"] = {"planks": {"texture": str(texture), "texture_size_m": 1.5}}
    data["rooms"][1]["floor_material"] = "planks"
    compiled = compile_scene(SceneSpec.model_validate(data), empty_library)
    # The user's texture, and the procedural tiles of the other room's grey_tile floor.
    assert compiled.model.ntex == 2
    assert compiled.files["textures/planks.png"] == texture.read_bytes()
    assert compiled.files["textures/grey_tile.png"] == pattern_png("tile")
    # The slab's coordinates count tiles of 1.5 m: used as they are, not garbled by texuniform.
    floor = compiled.model.material("material/planks/uv")
    assert tuple(floor.texrepeat) == (1.0, 1.0) and not floor.texuniform
    assert simulate(compiled.model, 0.2).ok


def test_room_materials_wear_procedural_textures(empty_library: AssetLibrary) -> None:
    """A built-in wood, tile, brick or carpet room material gets its pattern at the pattern's
    physical tile size, tinted to keep its colour; paints stay plain."""
    data = two_room_data()
    data["rooms"][0]["floor_material"] = "carpet_grey"
    data["rooms"][1]["floor_material"] = "oak_floor"
    data["rooms"][1]["wall_material"] = "brick"
    compiled = compile_scene(SceneSpec.model_validate(data), empty_library)
    model = compiled.model
    assert compiled.files["textures/carpet_grey.png"] == pattern_png("carpet")
    assert compiled.files["textures/oak_floor.png"] == pattern_png("planks")
    assert compiled.files["textures/brick.png"] == pattern_png("brick")
    assert model.ntex == 3
    # Average colour kept: tint x mean luminance == the built-in colour.
    oak = model.material("material/oak_floor/uv")
    expected = BUILTIN_MATERIALS["oak_floor"].rgba
    np.testing.assert_allclose(
        np.asarray(oak.rgba[:3]) * pattern_mean("planks"), expected[:3], atol=2e-3
    )
    assert model.material("material/wall_default").texid[mujoco.mjtTextureRole.mjTEXROLE_RGB] == -1
    # The floor slab's texture coordinates count tiles (7 x 5 m of living room), used as they are.
    assert tuple(oak.texrepeat) == (1.0, 1.0) and not oak.texuniform
    slab = model.mesh("structure/floor/living").id
    start, count = model.mesh_texcoordadr[slab], model.mesh_texcoordnum[slab]
    uv = model.mesh_texcoord[start : start + count]
    span = uv.max(axis=0) - uv.min(axis=0)
    np.testing.assert_allclose(span, np.array([7.0, 5.0]) / PATTERNS["planks"].tile_m, atol=1e-4)
    # Every brick wall piece repeats the bricks once per tile along its length and height.
    tile = PATTERNS["brick"].tile_m
    pieces = [
        i
        for i in range(model.ngeom)
        if model.geom(i).name.startswith("structure/wall_")
        and model.material(model.geom_matid[i]).name.startswith("material/brick/")
    ]
    assert pieces
    for i in pieces:
        material = model.material(model.geom_matid[i])
        length, _, height = 2.0 * model.geom_size[i]
        np.testing.assert_allclose(material.texrepeat, [length / tile, height / tile], atol=1e-3)
        assert not material.texuniform
    assert simulate(model, 0.2).ok


def test_light_fixtures_carry_their_rooms_light(default_library: AssetLibrary) -> None:
    """A room with a ceiling fixture is lit from under it; a room without one from its centre."""
    data = two_room_data()
    data["lights"] = []
    pendant = default_library.by_category("pendant_light")[0].meta
    height = data.get("wall_height", 2.7)
    z = round(height - pendant.size[2], 4)
    data["objects"] = [
        {"id": "lamp", "asset": pendant.id, "position": [1.0, 1.0, z], "static": True}
    ]
    scene = SceneSpec.model_validate(data)
    model = compile_scene(scene, default_library).model
    lights = {model.light(i).name: model.light_pos[i] for i in range(model.nlight)}
    room = next(r.id for r in scene.rooms if Polygon(r.polygon).contains(Point(1.0, 1.0)))
    fixture = lights[f"light/room/{room}/fixture0"]
    assert fixture[0] == pytest.approx(1.0) and fixture[1] == pytest.approx(1.0)
    assert fixture[2] < z  # under the fixture's lowest point
    assert f"light/room/{room}" not in lights
    others = [r.id for r in scene.rooms if r.id != room]
    assert all(f"light/room/{r}" in lights for r in others)
