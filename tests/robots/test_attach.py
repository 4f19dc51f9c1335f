"""Attaching a robot to a compiled scene, exporting it, and putting it back on recompile."""

from __future__ import annotations

import json
from pathlib import Path

import mujoco
import numpy as np
import pytest

from holomj.errors import HolomjError, InputError
from holomj.jobs.folder import attach_folder_robot, read_robot, write_scene_folder
from holomj.library import AssetLibrary
from holomj.mjcf import compile_scene
from holomj.mjcf.compiler import CompiledScene
from holomj.physics.scene_io import loaded_from_compiled
from holomj.physics.settle import run_validation
from holomj.robots.attach import (
    MOUNT_BODY,
    add_robot,
    attach_prepared,
    place_robot,
    reattach_robot,
)
from holomj.robots.placement import Spot
from holomj.spec.report import Thresholds
from holomj.spec.scene import SceneSpec
from holomj.spec.scene_file import read_scene_file
from tests.conftest import two_room_data


@pytest.fixture
def with_jaco(two_room_compiled: CompiledScene, jaco) -> CompiledScene:
    return add_robot(two_room_compiled, "jaco", np.random.default_rng(0))


def _robot_joints(model: mujoco.MjModel) -> list[int]:
    return [j for j in range(model.njnt) if model.joint(j).name.startswith("robot/")]


def test_robot_stands_at_its_spot(with_jaco: CompiledScene) -> None:
    record = with_jaco.robot
    assert record is not None and record.name == "jaco" and record.room in ("kitchen", "living")
    model = with_jaco.model
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    np.testing.assert_allclose(data.body(MOUNT_BODY).xpos, record.position, atol=1e-9)
    assert len(_robot_joints(model)) == 9
    for name, value in record.home.items():
        assert model.qpos0[model.joint(name).qposadr[0]] == pytest.approx(value, abs=1e-9)
    assert record.package == "dm-control" and record.source.startswith("dm-control:dm_control/")


def test_robot_touches_nothing_and_holds_still(with_jaco: CompiledScene) -> None:
    model = with_jaco.model
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    robot_bodies = {b for b in range(model.nbody) if model.body(b).name.startswith("robot/")}
    for contact in data.contact[: data.ncon]:
        bodies = {int(model.geom_bodyid[contact.geom1]), int(model.geom_bodyid[contact.geom2])}
        if bodies & robot_bodies:
            assert contact.dist > -0.001
    for _ in range(1000):  # 2 s
        mujoco.mj_step(model, data)
    assert all(w.number == 0 for w in data.warning)
    adr = [model.jnt_qposadr[j] for j in _robot_joints(model)]
    assert np.max(np.abs(data.qpos[adr] - model.qpos0[adr])) < 1e-5


def test_scene_with_robot_validates(with_jaco: CompiledScene, empty_library: AssetLibrary) -> None:
    loaded = loaded_from_compiled(with_jaco, empty_library, Path("two_room"))
    fast = Thresholds(settle_cap_s=2.0, monitor_s=1.0)
    report = run_validation(loaded, fast, "as-is").report
    assert report.ok, report.model_dump()
    assert report.penetrations == [] and report.warnings == {}


def test_same_seed_same_xml(two_room_compiled: CompiledScene, jaco) -> None:
    a = add_robot(two_room_compiled, "jaco", np.random.default_rng(3))
    b = add_robot(two_room_compiled, "jaco", np.random.default_rng(3))
    assert a.to_xml() == b.to_xml()
    assert two_room_compiled.robot is None and "robot/" not in two_room_compiled.to_xml()


def test_one_robot_per_scene(with_jaco: CompiledScene) -> None:
    with pytest.raises(InputError, match="already has a robot"):
        add_robot(with_jaco, "jaco", np.random.default_rng(0))


def test_export_and_reattach(with_jaco: CompiledScene, tmp_path: Path) -> None:
    out = write_scene_folder(with_jaco, tmp_path / "out")
    record = read_robot(out)
    assert record == with_jaco.robot
    assert json.loads((out / "robot.json").read_text())["xml"] == "assets/robot.xml"
    assert (out / "assets" / "robot.xml").is_file()
    assert (out / "assets" / "robot" / "base.stl").is_file()
    xml = (out / "scene.xml").read_text()
    assert "<frame" not in xml and str(tmp_path) not in xml
    reloaded = mujoco.MjModel.from_xml_path(str(out / "scene.xml"))
    assert (reloaded.nbody, reloaded.ngeom, reloaded.nq) == (
        with_jaco.model.nbody,
        with_jaco.model.ngeom,
        with_jaco.model.nq,
    )
    np.testing.assert_allclose(reloaded.qpos0, with_jaco.model.qpos0, atol=1e-6)
    # Recompiling the folder from scene.json puts the robot back where it was.
    library = AssetLibrary.open(out / "assets")
    bare = compile_scene(read_scene_file(out / "scene.json"), library)
    again = attach_folder_robot(bare, out)
    assert again.robot == record
    np.testing.assert_allclose(again.model.body_pos, with_jaco.model.body_pos, atol=1e-9)
    np.testing.assert_allclose(again.model.qpos0, with_jaco.model.qpos0, atol=1e-9)
    assert attach_folder_robot(bare, tmp_path) is bare  # no robot.json: unchanged


def test_a_robot_inside_furniture_is_refused(two_room_compiled: CompiledScene, jaco) -> None:
    record = place_robot(jaco, Spot(x=2.0, y=1.2, yaw_deg=0.0, room="kitchen", clearance_m=0.0))
    with pytest.raises(HolomjError, match=r"robot geom .* interpenetrates table/collision_0"):
        attach_prepared(two_room_compiled, jaco.spec, jaco.files, record, jaco.to_xml())


def test_an_object_named_robot_is_refused(empty_library: AssetLibrary, jaco) -> None:
    data = two_room_data()
    data["objects"][0]["id"] = "robot"
    compiled = compile_scene(SceneSpec.model_validate(data), empty_library)
    with pytest.raises(InputError, match=r"objects: robot: the id 'robot' is the robot's name"):
        add_robot(compiled, "jaco", np.random.default_rng(0))


def test_robot_from_a_file_keeps_its_path(two_room_compiled: CompiledScene, tmp_path: Path) -> None:
    xml = tmp_path / "pole.xml"
    xml.write_text(
        "<mujoco><worldbody><body name='pole'><joint name='spin' axis='0 0 1'/>"
        "<geom type='capsule' fromto='0 0 0.1 0 0 1' size='0.05'/></body></worldbody></mujoco>"
    )
    compiled = add_robot(two_room_compiled, str(xml), np.random.default_rng(0))
    assert compiled.robot is not None
    assert compiled.robot.spec == str(xml) and compiled.robot.name == "pole"
    assert compiled.robot.source == str(xml.resolve()) and compiled.robot.package is None
    assert compiled.model.joint("robot/spin").id >= 0


def test_attaching_leaves_the_prepared_robot_usable(two_room_compiled: CompiledScene, jaco) -> None:
    before = jaco.to_xml()
    for x in (5.0, 6.0):
        record = place_robot(jaco, Spot(x=x, y=4.0, yaw_deg=0.0, room="living", clearance_m=0.0))
        compiled = attach_prepared(two_room_compiled, jaco.spec, jaco.files, record, before)
        assert 'file="robot/base.stl"' in compiled.to_xml()
    assert jaco.to_xml() == before


def test_validate_and_repair_keep_the_robot(with_jaco: CompiledScene, tmp_path: Path) -> None:
    from holomj.jobs.validate import repair_folder, validate

    out = write_scene_folder(with_jaco, tmp_path / "out")
    (out / "notes.txt").write_text("kept")
    stale = json.loads((out / "objects.json").read_text())
    report = validate(out, furniture="as-is")
    assert report.ok
    outcome = repair_folder(out, furniture="as-is")
    assert not outcome.unsaved
    model = mujoco.MjModel.from_xml_path(str(out / "scene.xml"))
    assert model.nbody == with_jaco.model.nbody  # the robot is still there
    assert read_robot(out) == with_jaco.robot
    assert (out / "assets" / "robot.xml").is_file()
    assert (out / "notes.txt").read_text() == "kept"
    # objects.json is written afresh from the repaired scene, not copied from before
    fresh = json.loads((out / "objects.json").read_text())
    assert fresh.keys() == stale.keys()
    scene = json.loads((out / "scene.json").read_text())
    poses = {o["id"]: o["position"] for o in scene["objects"]}
    for obj in fresh["objects"]:
        np.testing.assert_allclose(obj["position"], poses[obj["id"]], atol=1e-6)


def test_reattach_puts_the_same_robot_on_another_compile_of_the_scene(
    with_jaco: CompiledScene, two_room_scene: SceneSpec, empty_library: AssetLibrary
) -> None:
    """The robot moves, in memory, onto the scene compiled with static furniture."""
    held = compile_scene(two_room_scene, empty_library, furniture="static")
    again = reattach_robot(held, with_jaco)
    assert again.robot == with_jaco.robot
    mount_a = mujoco.MjData(with_jaco.model)
    mount_b = mujoco.MjData(again.model)
    mujoco.mj_kinematics(with_jaco.model, mount_a)
    mujoco.mj_kinematics(again.model, mount_b)
    body = MOUNT_BODY
    assert mount_b.body(body).xpos == pytest.approx(mount_a.body(body).xpos)
    assert again.model.nbody == with_jaco.model.nbody
    assert reattach_robot(held, held) is held  # nothing to carry over
