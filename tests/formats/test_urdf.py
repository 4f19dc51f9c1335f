"""URDF per articulated asset, read back two ways: parsed as XML (links, joints, ranges, meshes
present) and loaded by MuJoCo's own URDF importer (same joints, ranges, masses and hinge
anchors as the scene's model). ``holomj assets import`` takes meshes only (no URDF) today."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

import mujoco
import numpy as np
import pytest

from holomj.formats.urdf import UrdfFile, articulated_urdfs
from holomj.jobs.folder import read_scene
from holomj.spec.export_details import UrdfDetails
from tests.formats.conftest import Articulated


def _write(urdf: UrdfFile, root: Path) -> Path:
    folder = root / urdf.asset_id
    folder.mkdir(parents=True)
    path = folder / f"{urdf.asset_id}.urdf"
    path.write_text(urdf.urdf)
    for relative, data in urdf.meshes.items():
        (folder / relative).parent.mkdir(parents=True, exist_ok=True)
        (folder / relative).write_bytes(data)
    return path


def _parsed_joints(text: str) -> dict[str, dict]:
    robot = ET.fromstring(text)
    out = {}
    for joint in robot.findall("joint"):
        limit = joint.find("limit")
        out[joint.get("name")] = {
            "type": joint.get("type"),
            "parent": joint.find("parent").get("link"),
            "child": joint.find("child").get("link"),
            "axis": [float(v) for v in joint.find("axis").get("xyz").split()]
            if joint.find("axis") is not None
            else None,
            "range": (float(limit.get("lower")), float(limit.get("upper")))
            if limit is not None
            else None,
        }
    return out


def check_urdf_against_model(
    urdf: UrdfFile,
    model: mujoco.MjModel,
    tmp_path: Path,
    root_pos: np.ndarray,
    root_rot: np.ndarray,
) -> None:
    """The URDF's joints (by XML and through MuJoCo's importer) against the scene's model;
    ``root_pos``, ``root_rot``: where the URDF's root link is in the scene."""
    robot = ET.fromstring(urdf.urdf)
    links = {link.get("name") for link in robot.findall("link")}
    for mesh in robot.iter("mesh"):
        assert mesh.get("filename") in urdf.meshes
    joints = _parsed_joints(urdf.urdf)
    moving = {n: j for n, j in joints.items() if j["type"] != "fixed"}
    assert moving and all(j["parent"] in links and j["child"] in links for j in joints.values())
    source = {model.joint(j).name.replace("/", "_"): j for j in range(model.njnt)}
    for name, joint in moving.items():
        index = source[name]
        kind = model.jnt_type[index]
        assert joint["type"] == ("revolute" if kind == mujoco.mjtJoint.mjJNT_HINGE else "prismatic")
        reference = model.qpos0[model.jnt_qposadr[index]]  # the URDF's zero
        assert joint["range"] == pytest.approx(tuple(model.jnt_range[index] - reference), abs=1e-9)
    # MuJoCo's URDF importer gives the same joints, ranges, dynamics, axes, anchors and masses
    loaded = mujoco.MjModel.from_xml_path(str(_write(urdf, tmp_path)))
    assert {loaded.joint(j).name for j in range(loaded.njnt)} == set(moving)
    data = mujoco.MjData(loaded)
    mujoco.mj_kinematics(loaded, data)
    source_data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, source_data)
    for j in range(loaded.njnt):
        index = source[loaded.joint(j).name]
        assert loaded.jnt_type[j] == model.jnt_type[index]
        reference = model.qpos0[model.jnt_qposadr[index]]
        assert np.allclose(loaded.jnt_range[j], model.jnt_range[index] - reference, atol=1e-9)
        assert loaded.dof_damping[loaded.jnt_dofadr[j]] == pytest.approx(
            model.dof_damping[model.jnt_dofadr[index]]
        )
        axis = root_rot.T @ source_data.xaxis[index]
        anchor = root_rot.T @ (source_data.xanchor[index] - root_pos)
        assert np.allclose(data.xaxis[j], axis, atol=1e-6)
        assert np.allclose(data.xanchor[j], anchor, atol=1e-6)
        child = loaded.jnt_bodyid[j]
        assert loaded.body_subtreemass[child] == pytest.approx(
            model.body_subtreemass[model.jnt_bodyid[index]], rel=1e-5
        )


def test_doors_export_as_urdf(two_room_out: Path, tmp_path: Path) -> None:
    model = mujoco.MjModel.from_xml_path(str(two_room_out / "scene.xml"))
    scene = read_scene(two_room_out)
    urdfs = articulated_urdfs(model, scene)
    assert [u.asset_id for u in urdfs] == [d.id for d in scene.doors]  # every door has leaves
    front = next(u for u in urdfs if u.asset_id == "front_door")
    assert [j[0] for j in front.joints] == ["front_door_hinge_0", "front_door_hinge_1"]
    for urdf in urdfs:
        door = next(d for d in scene.doors if d.id == urdf.asset_id)
        base = np.array([door.position[0], door.position[1], 0.0])
        check_urdf_against_model(urdf, model, tmp_path / "loaded", base, np.eye(3))
    # the frame link stands where the door is; the leaves hang at their hinges
    robot = ET.fromstring(front.urdf)
    hinge = robot.find("joint[@name='front_door_hinge_0']/origin")
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    door = next(d for d in scene.doors if d.id == "front_door")
    anchor = data.xanchor[model.joint("front_door/hinge_0").id]
    xyz = np.array([float(v) for v in hinge.get("xyz").split()])
    assert np.allclose(xyz + [door.position[0], door.position[1], 0.0], anchor, atol=1e-6)


def test_articulated_furniture_exports_as_urdf(articulated: Articulated, tmp_path: Path) -> None:
    urdfs = articulated_urdfs(articulated.model, articulated.scene)
    crate = next(u for u in urdfs if u.asset_id == "crate")
    assert [(j[0], j[1]) for j in crate.joints] == [
        ("crate_lid_hinge", "revolute"),
        ("crate_drawer_slide", "prismatic"),
    ]
    data = mujoco.MjData(articulated.model)
    mujoco.mj_kinematics(articulated.model, data)
    body = articulated.model.body("crate/body").id
    root = (data.xpos[body], data.xmat[body].reshape(3, 3))
    check_urdf_against_model(crate, articulated.model, tmp_path, *root)
    # the lid's link frame is its hinge's anchor: MuJoCo puts the joint at the body origin
    loaded = mujoco.MjModel.from_xml_path(str(tmp_path / "crate" / "crate.urdf"))
    hinge = loaded.joint("crate_lid_hinge").id
    assert np.allclose(loaded.jnt_pos[hinge], 0.0)
    # the whole asset weighs what the crate's subtree does (MuJoCo fixes the root link to its
    # world and drops its mass, so read the URDF's own numbers)
    masses = [float(m.get("value")) for m in ET.fromstring(crate.urdf).iter("mass")]
    assert sum(masses) == pytest.approx(articulated.model.body_subtreemass[body], rel=1e-6)


def check_quickstart_urdf(apartment: Path, tmp_path: Path) -> None:
    """The quick start's apartment (:mod:`tests.formats.test_quickstart`)."""
    from holomj.jobs.export import export_folder

    result = export_folder(apartment, "urdf", tmp_path / "urdf")
    model = mujoco.MjModel.from_xml_path(str(apartment / "scene.xml"))
    moving = [j for j in range(model.njnt) if model.jnt_type[j] != mujoco.mjtJoint.mjJNT_FREE]
    assert isinstance(result.details, UrdfDetails)
    exported = [j for asset in result.details.assets for j in asset["joints"]]
    assert len(exported) == len(moving) > 0
    for asset in result.details.assets:
        path = tmp_path / "urdf" / asset["urdf"]
        loaded = mujoco.MjModel.from_xml_path(str(path))
        assert loaded.njnt == len(asset["joints"])
        for joint in asset["joints"]:
            index = loaded.joint(joint["name"]).id
            assert np.allclose(loaded.jnt_range[index], (joint["lower"], joint["upper"]))
