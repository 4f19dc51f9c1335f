"""The GLB export read back: a valid glTF 2.0 binary, Y-up, one node per object named by its id
at its pose in ``objects.json`` and with its bounds, walls, floors, openings and lights, shared
meshes and materials, and articulated parts nested under their object."""

from __future__ import annotations

import json
from pathlib import Path

import mujoco
import numpy as np
import pytest
import trimesh

from holomj.formats.glb import Z_UP_TO_Y_UP, scene_glb
from holomj.jobs.folder import read_scene
from tests.formats.conftest import Articulated
from tests.formats.gltf_reader import Glb, read_glb


def _folder_glb(out: Path, colliders: bool = True) -> tuple[Glb, dict]:
    model = mujoco.MjModel.from_xml_path(str(out / "scene.xml"))
    data = scene_glb(model, read_scene(out), colliders=colliders)
    return read_glb(data), json.loads((out / "objects.json").read_text())


def check_objects_match(glb: Glb, record: dict, bounds_tolerance: float) -> None:
    """Node count, poses and bounds of the GLB's objects against ``objects.json``."""
    nodes = glb.by_kind("object")
    assert sorted(nodes) == sorted(o["id"] for o in record["objects"])
    for obj in record["objects"]:
        index = nodes[obj["id"]]
        assert glb.nodes[index]["name"] == obj["id"]
        world = glb.world_z_up(index)
        assert np.allclose(world[:3, 3], obj["position"], atol=2e-6), obj["id"]
        rotation = np.zeros(9)
        mujoco.mju_quat2Mat(rotation, np.asarray(obj["quat"], dtype=float))
        assert np.allclose(world[:3, :3], rotation.reshape(3, 3), atol=2e-6), obj["id"]
        points = glb.points(index)
        low, high = points.min(axis=0), points.max(axis=0)
        # objects.json bounds each geom by a hull-containing cloud (boxes around spheres and
        # capsules), the GLB by its triangles: the GLB lies inside, and close
        assert np.all(low >= np.asarray(obj["aabb"]["min"]) - 1e-4), obj["id"]
        assert np.all(high <= np.asarray(obj["aabb"]["max"]) + 1e-4), obj["id"]
        assert np.allclose(low, obj["aabb"]["min"], atol=bounds_tolerance), obj["id"]
        assert np.allclose(high, obj["aabb"]["max"], atol=bounds_tolerance), obj["id"]


def test_two_room_glb_matches_objects_json(two_room_out: Path) -> None:
    glb, record = _folder_glb(two_room_out)
    check_objects_match(glb, record, bounds_tolerance=1e-4)  # boxes only: exact


def test_glb_is_y_up_metres_with_rooms_structure_openings_and_lights(two_room_out: Path) -> None:
    glb, _ = _folder_glb(two_room_out, colliders=False)
    gltf = glb.gltf
    root = gltf["scenes"][gltf["scene"]]["nodes"]
    assert len(root) == 1 and glb.nodes[root[0]]["rotation"] == list(Z_UP_TO_Y_UP)
    scene = read_scene(two_room_out)
    assert sorted(glb.by_kind("room")) == sorted(r.id for r in scene.rooms)
    assert sorted(glb.by_kind("floor")) == sorted(r.id for r in scene.rooms)
    assert sorted(glb.by_kind("walls")) == sorted(r.id for r in scene.rooms)
    assert set(glb.by_kind("door")) == {d.id for d in scene.doors}
    assert set(glb.by_kind("window")) == {w.id for w in scene.windows}
    assert glb.by_kind("colliders") == {}  # only on request
    # every object hangs under its room
    for obj in scene.objects:
        assert glb.parents[glb.by_kind("object")[obj.id]] == glb.by_kind("room")[obj.room]
    # door leaves under their door, turned about their hinges
    leaves = glb.by_kind("leaf")
    assert {glb.parents[i] for i in leaves.values()} == {
        glb.by_kind("door")[d] for d in ("front_door", "kitchen_door")
    }
    # Y is up: the floors at y = 0, the walls up to the wall height
    y_up = np.vstack([glb.points(i, z_up=False) for i in glb.by_kind("walls").values()])
    assert y_up[:, 1].min() == pytest.approx(0.0, abs=1e-6)
    assert y_up[:, 1].max() == pytest.approx(scene.wall_height, abs=1e-3)
    lights = gltf["extensions"]["KHR_lights_punctual"]["lights"]
    assert gltf["extensionsUsed"] == ["KHR_lights_punctual"]
    assert sorted(light["type"] for light in lights) == ["directional", "point"]
    direction = -glb.world_z_up(glb.by_kind("light")["light/sun"])[:3, 2]  # they shine along -Z
    expected = np.array([0.2, 0.1, -1.0]) / np.linalg.norm([0.2, 0.1, -1.0])
    assert np.allclose(direction, expected, atol=1e-5)


def test_glb_materials_shared_and_colliders_on_request(two_room_out: Path) -> None:
    plain, _ = _folder_glb(two_room_out, colliders=False)
    with_colliders, _ = _folder_glb(two_room_out, colliders=True)
    assert set(with_colliders.by_kind("colliders")) == {"crate", "table", "cube"}
    names = [m["name"] for m in plain.gltf["materials"]]
    assert len(names) == len(set(names))
    colliders = with_colliders.by_kind("colliders")
    material = {
        with_colliders.gltf["meshes"][with_colliders.nodes[i]["mesh"]]["primitives"][0]["material"]
        for i in colliders.values()
    }
    assert len(material) == 1  # one translucent collider material
    assert with_colliders.gltf["materials"][material.pop()]["alphaMode"] == "BLEND"


def test_glb_is_deterministic_and_reloads_in_trimesh(two_room_out: Path, tmp_path: Path) -> None:
    model = mujoco.MjModel.from_xml_path(str(two_room_out / "scene.xml"))
    scene = read_scene(two_room_out)
    first = scene_glb(model, scene)
    assert scene_glb(model, scene) == first
    path = tmp_path / "scene.glb"
    path.write_bytes(first)
    loaded = trimesh.load(path)
    assert isinstance(loaded, trimesh.Scene) and len(loaded.geometry) > 0
    low, high = loaded.bounds
    assert low[1] == pytest.approx(0.0, abs=0.05)  # Y up: the floor
    assert high[1] == pytest.approx(scene.wall_height, abs=0.05)


def test_ceilings_are_their_own_nodes(two_room_library) -> None:
    from holomj.mjcf.compiler import compile_scene
    from holomj.spec.scene import SceneSpec
    from tests.conftest import two_room_data

    scene = SceneSpec.model_validate({**two_room_data(), "ceilings": True})
    compiled = compile_scene(scene, two_room_library)
    glb = read_glb(scene_glb(compiled.model, scene))
    ceilings = glb.by_kind("ceiling")
    assert sorted(ceilings) == sorted(r.id for r in scene.rooms)
    for room, index in ceilings.items():
        assert glb.parents[index] == glb.by_kind("room")[room]
        heights = glb.points(index)[:, 2]
        assert heights.min() >= scene.wall_height - 0.3 and heights.max() <= scene.wall_height + 0.3


def test_articulated_parts_nest_under_their_object(articulated: Articulated) -> None:
    glb = read_glb(scene_glb(articulated.model, articulated.scene, colliders=True))
    crate = glb.by_kind("object")["crate"]
    parts = glb.by_kind("part")
    assert set(parts) == {"crate/lid", "crate/drawer", "crate/handle"}  # a node per body
    assert glb.parents[parts["crate/lid"]] == crate
    assert glb.parents[parts["crate/drawer"]] == parts["crate/lid"]
    assert glb.parents[parts["crate/handle"]] == parts["crate/drawer"]
    data = mujoco.MjData(articulated.model)
    mujoco.mj_kinematics(articulated.model, data)
    for name, index in parts.items():
        body = articulated.model.body(name).id
        assert np.allclose(glb.world_z_up(index)[:3, 3], data.xpos[body], atol=2e-6)
    handle_points = glb.points(parts["crate/handle"], recursive=False)
    handle = articulated.model.geom("crate/handle_cyl").id
    offset = np.abs(handle_points - data.geom_xpos[handle])
    on_handle = (offset[:, :2].max(axis=1) <= 0.0101) & (offset[:, 2] <= 0.0501)
    assert on_handle.all() and len(handle_points) >= 24


def check_quickstart_glb(apartment: Path) -> None:
    """The quick start's apartment (:mod:`tests.formats.test_quickstart`)."""
    glb, record = _folder_glb(apartment)
    # meshes bound by their triangles, cylinders by objects.json's 16-gons: within 5 mm
    check_objects_match(glb, record, bounds_tolerance=0.005)
    assert len(glb.gltf.get("textures", [])) > 0
    textured = [
        p
        for mesh in glb.gltf["meshes"]
        for p in mesh["primitives"]
        if "baseColorTexture" in glb.gltf["materials"][p["material"]]["pbrMetallicRoughness"]
    ]
    assert textured and all("TEXCOORD_0" in p["attributes"] for p in textured)
    # identical objects share their meshes: about one per object, and one per moving part
    parts = sum(len(o.get("joints") or []) for o in record["objects"])
    assert len(glb.gltf["meshes"]) < len(record["objects"]) + parts + 60
