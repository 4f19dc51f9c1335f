"""The Panda attached by ``holomj add-robot`` reaches the handles ``objects.json`` lists in a
kitchen of articulated cabinets (a kinematic reach check: damped least squares IK on the
compiled scene, from a free base spot in front of each handle)."""

from __future__ import annotations

import json
import math
from pathlib import Path

import mujoco
import numpy as np
import pytest
from typer.testing import CliRunner

from asset_pipeline.procedural.articulated import build_articulated_library
from holomj.cli.app import app
from holomj.errors import InputError
from holomj.robots.reach_handle import TOLERANCE_M, reach_handle, reach_objects_json
from holomj.robots.registry import installed_robots

CATEGORIES = ["base_cabinet", "drawer_unit", "dishwasher", "kitchen_cabinet"]
# Base cabinets, a drawer unit and a dishwasher against the wall y = 0, facing +y; a wall
# cabinet above them (its handles at 1.55 m: out of a floor-mounted Panda's reach).
KITCHEN = {
    "schema_version": "1.0",
    "name": "articulated kitchen",
    "wall_height": 2.6,
    "rooms": [{"id": "kitchen", "type": "kitchen",
               "polygon": [[0, 0], [4, 0], [4, 3.5], [0, 3.5]]}],
    "doors": [{"id": "front_door", "rooms": ["kitchen"], "position": [4, 2.5]}],
    "objects": [
        {"id": "cabinet", "asset": "base_cabinet_art_000", "position": [0.6, 0.295, 0]},
        {"id": "drawers", "asset": "drawer_unit_art_000", "position": [1.16, 0.295, 0]},
        {"id": "dishwasher", "asset": "dishwasher_art_000", "position": [1.72, 0.305, 0]},
        {"id": "wall_cabinet", "asset": "kitchen_cabinet_art_000", "position": [0.9, 0.18, 1.45]},
    ],
}  # fmt: skip
pytestmark = pytest.mark.slow  # about 25 s: compile, add-robot and a dozen IK runs
REACHABLE = [
    "cabinet/door_0_hinge",
    "drawers/drawer_0_slide",  # the lowest drawer, 0.19 m up
    "drawers/drawer_3_slide",
    "dishwasher/door_0_hinge",
]


@pytest.fixture(scope="module")
def kitchen(tmp_path_factory: pytest.TempPathFactory) -> dict:
    """The kitchen compiled and given a Panda with the CLI; its model and objects.json."""
    if "panda" not in installed_robots():
        pytest.skip("dm-robotics-panda is not installed (pip install dm-robotics-panda --no-deps)")
    root = tmp_path_factory.mktemp("kitchen")
    library = build_articulated_library(root / "library", CATEGORIES)
    scene = json.loads(json.dumps(KITCHEN))
    for obj in scene["objects"]:
        obj.update(yaw_deg=90, static=True, room="kitchen")
    (root / "scene.json").write_text(json.dumps(scene))
    out = root / "out"
    runner = CliRunner()
    compiled = runner.invoke(
        app, ["compile", str(root / "scene.json"), "-o", str(out), "--library", str(library)]
    )
    assert compiled.exit_code == 0, compiled.output
    added = runner.invoke(app, ["add-robot", str(out), "panda"])
    assert added.exit_code == 0, added.output
    return {
        "model": mujoco.MjModel.from_xml_path(str(out / "scene.xml")),
        "objects": json.loads((out / "objects.json").read_text()),
    }


def _handles(objects: dict) -> dict[str, dict]:
    return {
        joint["name"]: joint["handle"]
        for obj in objects["objects"]
        for joint in obj["joints"]
        if joint["handle"] is not None
    }


def test_the_panda_reaches_the_base_cabinet_handles(kitchen: dict) -> None:
    model, handles = kitchen["model"], _handles(kitchen["objects"])
    assert kitchen["objects"]["robot"]["name"] == "panda"
    report = []
    for name in REACHABLE:
        handle = handles[name]
        result = reach_handle(model, handle["position"], handle["pull"], label=name)
        report.append(result.to_dict())
        assert result.reached and result.residual_m <= TOLERANCE_M, result.to_dict()
        assert result.arm_penetration_m <= 0.005 and result.site == "robot/hand/TCP"
        # Check it on the scene's own model: the base where the result stands it, its joint
        # values, and the handle's site (named in objects.json).
        check = _posed(model, result)
        tcp = check[0].site("robot/hand/TCP").id
        site = check[0].site(handle["site"]).id
        gap = float(np.linalg.norm(check[1].site_xpos[tcp] - check[1].site_xpos[site]))
        assert gap <= TOLERANCE_M, (name, gap)
    print(json.dumps(report, indent=1))  # the residuals, for the record (pytest -s)


def test_a_wall_cabinet_handle_is_out_of_reach_from_the_floor(kitchen: dict) -> None:
    handle = _handles(kitchen["objects"])["wall_cabinet/door_0_hinge"]
    assert handle["position"][2] > 1.5
    result = reach_handle(kitchen["model"], handle["position"], handle["pull"])
    assert not result.reached and result.residual_m > 0.2  # a floor-mounted Panda: ~1.2 m


def test_from_the_add_robot_spot_alone_and_by_objects_json(kitchen: dict) -> None:
    model = kitchen["model"]
    handle = _handles(kitchen["objects"])["cabinet/door_0_hinge"]
    fixed = reach_handle(model, handle["position"], handle["pull"], move_base=False)
    robot = kitchen["objects"]["robot"]
    assert not fixed.moved_base and fixed.spots_tried == 1
    assert fixed.base[:2] == pytest.approx(robot["position"][:2], abs=1e-6)
    assert math.isfinite(fixed.residual_m)
    low = reach_objects_json(model, kitchen["objects"], max_height=0.3)
    assert [r.label for r in low] == ["drawers/drawer_0_slide", "dishwasher/rack_0_slide"]
    assert all(r.reached for r in low)


def test_a_model_without_a_robot_is_refused() -> None:
    model = mujoco.MjModel.from_xml_string(
        "<mujoco><worldbody><site name='s'/></worldbody></mujoco>"
    )
    with pytest.raises(InputError, match="no robot"):
        reach_handle(model, (0, 0, 0), (1, 0, 0))


def _posed(model: mujoco.MjModel, result) -> tuple[mujoco.MjModel, mujoco.MjData]:
    import copy

    posed = copy.copy(model)
    mount = posed.body("robot/base_mount").id
    posed.body_pos[mount][:2] = result.base[:2]
    yaw = math.radians(result.base[2])
    posed.body_quat[mount] = [math.cos(yaw / 2), 0.0, 0.0, math.sin(yaw / 2)]
    data = mujoco.MjData(posed)
    for name, value in result.qpos.items():
        data.qpos[posed.jnt_qposadr[posed.joint(name).id]] = value
    mujoco.mj_kinematics(posed, data)
    return posed, data


def test_result_is_json_able(kitchen: dict, tmp_path: Path) -> None:
    handle = _handles(kitchen["objects"])["drawers/drawer_3_slide"]
    result = reach_handle(kitchen["model"], handle["position"], handle["pull"], label="d")
    path = tmp_path / "reach.json"
    path.write_text(json.dumps(result.to_dict()))
    assert json.loads(path.read_text())["label"] == "d"
