"""objects.json: objects with poses, boxes, masses, surfaces and supports; doors; the robot."""

from __future__ import annotations

import json
import math
from pathlib import Path

import mujoco
import numpy as np
import pytest

from holomj.jobs.folder import write_scene_folder
from holomj.jobs.robot_learning import objects_json
from holomj.library import AssetLibrary
from holomj.mjcf import compile_scene
from holomj.robots.attach import add_robot
from holomj.spec.scene import SceneSpec


@pytest.fixture
def compiled(two_room_scene: SceneSpec, empty_library: AssetLibrary):
    return compile_scene(two_room_scene, empty_library)


def test_objects(compiled) -> None:
    record = objects_json(compiled)
    assert record["schema_version"] == "1.0" and record["scene"] == "two rooms"
    assert [r["id"] for r in record["rooms"]] == ["kitchen", "living"]
    assert record["rooms"][1]["area_m2"] == pytest.approx(23.0)
    objects = {o["id"]: o for o in record["objects"]}
    assert list(objects) == ["crate", "table", "cube"]  # the scene's order
    table, cube, crate = objects["table"], objects["cube"], objects["crate"]
    assert table["category"] == "box" and table["asset"] == "builtin:box"
    assert table["static"] and table["joint"] is None and table["room"] == "kitchen"
    assert table["aabb"] == {"min": [1.4, 0.8, 0.0], "max": [2.6, 1.6, 0.75]}
    assert cube["support"] == "table" and not cube["static"]
    assert cube["joint"] == "cube/freejoint" and cube["body"] == "cube/body"
    # The table top is a receptacle surface at its height, in world coordinates.
    (top,) = table["surfaces"]
    assert top["height"] == pytest.approx(0.75)
    xs = [p[0] for p in top["polygon"]]
    assert 1.4 <= min(xs) < max(xs) <= 2.6 and top["area_m2"] > 0.8
    model = compiled.model
    assert crate["mass_kg"] == pytest.approx(float(model.body("crate/body").mass[0]), abs=1e-6)
    assert crate["yaw_deg"] == pytest.approx(30.0)
    w, _, _, z = crate["quat"]
    assert math.degrees(2 * math.atan2(z, w)) == pytest.approx(30.0, abs=1e-4)
    # A 0.6 x 0.4 box turned 30°: its box is wider than it is.
    half_x = 0.3 * math.cos(math.radians(30)) + 0.2 * math.sin(math.radians(30))
    assert crate["aabb"]["max"][0] - 5.5 == pytest.approx(half_x, abs=1e-5)


def test_doors(compiled) -> None:
    doors = {d["id"]: d for d in objects_json(compiled)["doors"]}
    kitchen, front = doors["kitchen_door"], doors["front_door"]
    assert kitchen["rooms"] == ["kitchen", "living"] and kitchen["width"] == 1.0
    (leaf,) = kitchen["leaves"]
    assert leaf["joint"] == "kitchen_door/hinge_0" and leaf["body"] == "kitchen_door/leaf_0"
    assert leaf["range_rad"] == pytest.approx([-math.pi / 2, 0.0], abs=1e-6)
    assert leaf["axis"] == [0.0, 0.0, 1.0] and leaf["hinge"][1] == pytest.approx(2.95)
    assert len(front["leaves"]) == 2 and front["width"] == 1.8
    model = compiled.model
    joint = model.joint("front_door/hinge_1")
    assert front["leaves"][1]["range_rad"] == pytest.approx(list(joint.range), abs=1e-6)


def test_robot_and_export(compiled, tmp_path: Path) -> None:
    assert objects_json(compiled)["robot"] is None
    with_robot = add_robot(compiled, "jaco", np.random.default_rng(0))
    out = write_scene_folder(with_robot, tmp_path / "out")
    record = json.loads((out / "objects.json").read_text())
    robot = record["robot"]
    assert robot["name"] == "jaco" and robot["base_body"] == "robot/base_mount"
    assert len(robot["joints"]) == 9 and robot["joints"][1]["name"] == "robot/joint_2"
    assert robot["joints"][1]["home"] == pytest.approx(2.9248)
    assert robot["joints"][1]["range"] == pytest.approx([0.820305, 5.462881])
    reloaded = mujoco.MjModel.from_xml_path(str(out / "scene.xml"))
    for obj in record["objects"]:
        assert reloaded.body(obj["body"]).id > 0
    assert (out / "objects.json").read_text() == (
        json.dumps(record, indent=2, sort_keys=True, ensure_ascii=False) + "\n"
    )
