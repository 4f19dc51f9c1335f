"""Preparing robot MJCF: home pose as qpos0 (joint meaning kept), fixed base, holding still."""

from __future__ import annotations

import math
from pathlib import Path

import mujoco
import numpy as np
import pytest

from holomj.errors import InputError
from holomj.robots import shapes
from holomj.robots.prepare import PreparedRobot, prepare_robot
from holomj.robots.registry import RobotSource, resolve_robot

ARM_JOINTS = [f"joint_{i}" for i in range(1, 7)]


def _set(model: mujoco.MjModel, data: mujoco.MjData, values: dict[str, float]) -> None:
    for name, value in values.items():
        data.qpos[model.joint(name).qposadr[0]] = value
    mujoco.mj_kinematics(model, data)


def test_jaco_starts_in_its_home_pose(jaco: PreparedRobot) -> None:
    model = jaco.spec.compile()
    source = resolve_robot("jaco")
    for name, value in source.home.items():
        assert model.qpos0[model.joint(name).qposadr[0]] == pytest.approx(value, abs=1e-9)
    # Fingers start at 0, below their range [0.15, 1.35]: moved 1 % inside it.
    finger = model.joint("hand/finger_1")
    assert model.qpos0[finger.qposadr[0]] == pytest.approx(0.15 + 0.012)
    assert jaco.home["joint_2"] == pytest.approx(2.9248)


@pytest.mark.parametrize("offset", [0.0, 0.3, -0.5])
def test_joint_values_keep_their_meaning(jaco: PreparedRobot, offset: float) -> None:
    """The wrist sits where the original model puts it for the same joint values."""
    original = mujoco.MjModel.from_xml_path(str(resolve_robot("jaco").xml))
    prepared = jaco.spec.compile()
    values = {name: value + offset for name, value in resolve_robot("jaco").home.items()}
    data_o, data_p = mujoco.MjData(original), mujoco.MjData(prepared)
    _set(original, data_o, values)
    _set(prepared, data_p, values)
    np.testing.assert_allclose(
        data_p.site("wristsite").xpos, data_o.site("wristsite").xpos, atol=1e-9
    )
    np.testing.assert_allclose(
        data_p.site("wristsite").xmat, data_o.site("wristsite").xmat, atol=1e-9
    )


def test_jaco_holds_still_without_a_controller(jaco: PreparedRobot) -> None:
    model = jaco.spec.compile()
    data = mujoco.MjData(model)
    for _ in range(1000):  # 2 s
        mujoco.mj_step(model, data)
    assert np.max(np.abs(data.qpos - model.qpos0)) < 1e-6
    assert all(w.number == 0 for w in data.warning)
    assert np.all(model.body_gravcomp[1:] == 1.0)
    assert model.njnt == 9 and mujoco.mjtJoint.mjJNT_FREE not in set(model.jnt_type)


def test_files_are_embedded_under_robot(jaco: PreparedRobot) -> None:
    assert jaco.files and all(key.startswith("robot/") for key in jaco.files)
    assert "robot/base.stl" in jaco.files and "robot/hand/finger_distal.stl" in jaco.files
    xml = jaco.to_xml()
    assert 'file="robot/base.stl"' in xml and "<frame" not in xml
    reloaded = mujoco.MjSpec.from_string(xml, assets=jaco.files).compile()
    assert reloaded.nbody == jaco.spec.compile().nbody


def test_footprint_holds_every_collider(jaco: PreparedRobot) -> None:
    fp = jaco.footprint
    assert 0.15 < fp.radius_m < 1.0 and 0.3 < fp.height_m < 1.3
    model = jaco.spec.compile()
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    points = np.vstack([shapes.world_points(model, data, g) for g in shapes.collider_ids(model)])
    assert np.max(np.hypot(points[:, 0], points[:, 1])) <= fp.radius_m + 1e-3
    assert points[:, 2].min() > -0.01  # nothing below the base


def test_panda_is_fixed_up(panda: PreparedRobot) -> None:
    model = panda.spec.compile()
    assert model.qpos0[model.joint("panda_joint4").qposadr[0]] == pytest.approx(-3 * math.pi / 4)
    assert any("negative damping" in note for note in panda.notes)
    assert np.all(model.dof_damping >= 0)
    assert model.nu == 1  # the hand's actuator
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    assert all(c.dist >= -0.001 for c in data.contact[: data.ncon])
    for _ in range(1000):
        mujoco.mj_step(model, data)
    assert np.max(np.abs(data.qpos - model.qpos0)) < 1e-5


USER_ROBOT = """
<mujoco model="toy">
  <compiler angle="degree"/>
  <worldbody>
    <body name="base">
      <freejoint name="float"/>
      <geom type="box" size="0.1 0.1 0.05" pos="0 0 0.05"/>
      <body name="link" pos="0 0 0.1">
        <joint name="lift" type="hinge" axis="0 1 0" range="10 80"/>
        <geom type="capsule" fromto="0 0 0 0 0 0.3" size="0.03"/>
        <body name="tip" pos="0 0 0.3">
          <joint name="bend" type="hinge" axis="0 1 0" range="-45 45"/>
          <geom type="capsule" fromto="0 0 0 0 0 0.2" size="0.02"/>
          <site name="end" pos="0 0 0.2"/>
        </body>
      </body>
    </body>
  </worldbody>
  {keyframe}
</mujoco>
"""


def _user_robot(tmp_path: Path, keyframe: str = "") -> RobotSource:
    xml = tmp_path / "toy.xml"
    xml.write_text(USER_ROBOT.replace("{keyframe}", keyframe))
    return resolve_robot(str(xml))


def test_user_mjcf_in_degrees_with_a_free_base(tmp_path: Path) -> None:
    robot = prepare_robot(_user_robot(tmp_path))
    model = robot.spec.compile()
    assert model.nq == 2  # free joint removed
    assert any("free joint 'float' removed" in note for note in robot.notes)
    lift = model.joint("lift")
    # 0 deg is outside [10, 80] deg: 1 % of the range inside it, in radians.
    assert model.qpos0[lift.qposadr[0]] == pytest.approx(math.radians(10 + 0.7))
    assert model.qpos0[model.joint("bend").qposadr[0]] == pytest.approx(0.0)
    original = mujoco.MjModel.from_xml_path(str(tmp_path / "toy.xml"))
    data_o, data_p = mujoco.MjData(original), mujoco.MjData(model)
    values = {"lift": math.radians(50), "bend": math.radians(-20)}
    _set(original, data_o, values)
    _set(model, data_p, values)
    # The original floats 7 qpos in; compare the tip relative to the base body.
    rel_o = data_o.site("end").xpos - data_o.body("base").xpos
    rel_p = data_p.site("end").xpos - data_p.body("base").xpos
    np.testing.assert_allclose(rel_p, rel_o, atol=1e-9)


def test_user_keyframe_home_is_used(tmp_path: Path) -> None:
    key = '<keyframe><key name="home" qpos="0 0 0 1 0 0 0 0.5 0.25"/></keyframe>'
    robot = prepare_robot(_user_robot(tmp_path, key))
    model = robot.spec.compile()
    assert model.nkey == 0 and any("keyframe 'home' dropped" in n for n in robot.notes)
    assert model.qpos0[model.joint("lift").qposadr[0]] == pytest.approx(0.5)
    assert model.qpos0[model.joint("bend").qposadr[0]] == pytest.approx(0.25)


def test_home_outside_the_range_is_rejected(tmp_path: Path) -> None:
    source = _user_robot(tmp_path)
    bad = RobotSource(name="toy", xml=source.xml, description="", home={"bend": 2.0})
    with pytest.raises(InputError, match="home value 2 of joint 'bend' is outside its range"):
        prepare_robot(bad)
    unknown = RobotSource(name="toy", xml=source.xml, description="", home={"elbow": 0.1})
    with pytest.raises(InputError, match="unknown joints: elbow"):
        prepare_robot(unknown)


def test_broken_mjcf_is_an_input_error(tmp_path: Path) -> None:
    xml = tmp_path / "broken.xml"
    xml.write_text("<mujoco><worldbody><body><geom type='mesh' mesh='nope'/></body></worldbody>")
    with pytest.raises(InputError, match="MuJoCo cannot load the robot MJCF") as info:
        prepare_robot(resolve_robot(str(xml)))
    assert str(xml) in info.value.one_line()
