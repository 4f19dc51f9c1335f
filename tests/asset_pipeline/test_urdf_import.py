"""A PartNet-Mobility-style URDF imported through ``holomj assets import``: one articulated
asset whose door and drawer pass the same real-simulation tests as the procedural ones."""

from __future__ import annotations

import json
import math
from pathlib import Path

import mujoco
import numpy as np
import pytest
from typer.testing import CliRunner

from holomj.cli.app import app
from holomj.library import AssetLibrary
from holomj.mjcf import compile_scene
from tests.asset_pipeline.articulated_helpers import (
    HINGE,
    clearance_to_parent,
    compiled_object,
    one_object_scene,
    part_joints,
    simulate,
    value,
    warnings_of,
)
from tests.asset_pipeline.urdf_helpers import (
    DRAWER_TRAVEL_M,
    KNOB_CENTRE,
    write_partnet_cabinet,
)

OPEN_DOOR_RAD = math.radians(20.0)
OPEN_DRAWER_M = 0.10
DEEPEST_M = 0.001
ASSET = "storagefurniture_7120"
# The cabinet's footprint runs from x = -0.25 (back) to 0.301 (drawer pull): asset x = design x
# minus the centre of that span.
X_SHIFT = (0.301 - 0.25) / 2


@pytest.fixture(scope="module")
def imported(tmp_path_factory: pytest.TempPathFactory, shared_assets: Path) -> dict:
    """The cabinet's folder imported with the CLI (a tomato soup can from ../shared/assets as
    the door's knob); the library, the JSON summary and the asset's derivation."""
    root = tmp_path_factory.mktemp("urdf")
    folder = root / "partnet" / "7120"
    knob = shared_assets / "objects/ycb_005_tomato_soup_can/textured.obj"
    write_partnet_cabinet(folder, knob)
    library = root / "library"
    args = ["assets", "import", str(root / "partnet"), "--library", str(library), "--json"]
    args += ["--no-thumbnails", "--preset", "fast", "--size", "2", "2", "0.8"]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 0, result.output
    lib = AssetLibrary.open(library)
    derivation = json.loads((lib.get(ASSET).root / "derivation.json").read_text())
    return {"library": lib, "summary": json.loads(result.stdout), "derivation": derivation}


def test_the_model_folder_is_one_articulated_asset(imported: dict) -> None:
    summary = imported["summary"]
    assert summary["succeeded"] == 1 and summary["failed"] == 0  # the OBJs are its links
    meta = imported["library"].get(ASSET).meta
    assert meta.category == "cabinet"  # meta.json's StorageFurniture
    # PartNet-Mobility's normalised units scaled to 0.8 m tall; Y-up meshes and its -X front
    # turned to holomj's Z up and +X front.
    assert meta.size == pytest.approx((0.551, 0.8, 0.8), abs=0.002)
    art = meta.articulation
    assert art is not None and [p.name for p in art.parts] == ["link_0", "link_1"]
    door, drawer = art.parts
    assert (door.kind, drawer.kind) == ("door", "drawer")  # semantics.txt
    assert door.joint.type == "hinge" and drawer.joint.type == "slide"
    # The door's [-1.9, 0] rad (opening negative) became [0, 1.9] about the flipped axis.
    assert door.joint.range == pytest.approx((0.0, 1.9))
    assert door.joint.axis == pytest.approx((0.0, 0.0, -1.0), abs=1e-6)
    assert drawer.joint.range == pytest.approx((0.0, DRAWER_TRAVEL_M), abs=1e-3)
    assert drawer.joint.axis == pytest.approx((1.0, 0.0, 0.0), abs=1e-6)
    assert door.joint.closed == drawer.joint.closed == 0.0
    # The knob (a textured mesh of its own) is part of the door; the grasp is on it.
    assert any(v.texture for v in door.visual)
    knob = np.array(KNOB_CENTRE) - [X_SHIFT, 0.0, 0.0]
    assert door.handle is not None and drawer.handle is not None
    assert np.linalg.norm(np.array(door.handle.pos[1:]) - knob[1:]) < 0.01
    assert door.handle.pos[0] > 0.26  # on the front of the knob
    assert np.dot(door.handle.pull, (1.0, 0.0, 0.0)) > 0.99
    assert drawer.handle.pos == pytest.approx((0.301 - X_SHIFT, 0.0, 0.6675), abs=0.005)
    assert drawer.handle.pull == pytest.approx((1.0, 0.0, 0.0))
    # Inside: the bottom shelf behind the door, the drawer bottom moving with the drawer.
    shelf = [s for s in art.interior if s.part is None]
    bottom = [s for s in art.interior if s.part == "link_1"]
    assert len(shelf) == 1 and shelf[0].behind == ["joint_0"] and shelf[0].height < 0.03
    assert len(bottom) == 1 and bottom[0].behind == ["joint_1"]
    assert [s.height for s in meta.surfaces] == pytest.approx([0.8], abs=0.002)  # the top
    assert art.mass_kg < meta.mass and 10.0 <= meta.mass <= 120.0


def test_the_derivation_records_the_format_and_coacd_per_link(imported: dict) -> None:
    derivation = imported["derivation"]
    assert derivation["source"]["format"] == "urdf"
    assert derivation["source"]["partnet_mobility"] is True
    bodies = {b["body"]: b for b in derivation["bodies"]}
    assert len(bodies) == 3  # the carcass and two parts, each decomposed on its own
    door = next(b for b in derivation["bodies"] if b["links"] == ["link_0"])
    methods = [a["method"] for a in door["decomposition"]["attempts"]]
    assert "coacd" in methods  # the knob mesh is not convex: CoACD ran for that link
    assert door["joint"]["axis_flipped"] is True
    assert door["joint"]["kind_source"].startswith("semantics.txt")
    assert derivation["normalisation"]["front"] == "-x"  # found from the opening motion


def test_the_imported_cabinet_stays_closed_opens_and_closes(imported: dict) -> None:
    model = compiled_object(imported["library"], ASSET).model
    joints = part_joints(model)
    assert len(joints) == 2
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


def test_an_object_in_the_imported_drawer_stays_inside(imported: dict) -> None:
    library = imported["library"]
    art = library.get(ASSET).meta.articulation
    (bottom,) = [s for s in art.interior if s.part == "link_1"]
    xs, ys = zip(*bottom.polygon)
    spot = [3.0 + float(np.mean(xs)), 3.0 + float(np.mean(ys)), bottom.height + 0.01]
    cube = {"id": "cube", "asset": "builtin:box", "position": spot, "scale": [0.05, 0.05, 0.05],
            "room": "room", "mass_kg": 0.2}  # fmt: skip
    model = compile_scene(one_object_scene(ASSET, objects=[cube]), library).model
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    simulate(model, data, 0.5)  # dropped 1 cm onto the drawer bottom
    joint = model.joint("obj/joint_1").id
    body = model.body("obj/link_1").id
    box = model.body("cube/body").id
    simulate(model, data, 1.5, joint, +1.0)
    assert value(model, data, joint) >= OPEN_DRAWER_M
    simulate(model, data, 0.5)
    rel = data.xmat[body].reshape(3, 3).T @ (data.xipos[box] - data.xpos[body])
    low, high = np.array([min(xs), min(ys)]), np.array([max(xs), max(ys)])
    margin = 0.021  # the surface is eroded 2 cm from the drawer walls
    assert np.all(rel[:2] >= low - margin) and np.all(rel[:2] <= high + margin), rel
    assert abs(rel[2] - (bottom.height + 0.025)) < 0.005, rel
    assert not warnings_of(data)


def test_a_reimport_comes_from_the_cache(imported: dict, tmp_path: Path) -> None:
    library = imported["library"].root
    source = Path(imported["derivation"]["source"]["file"])
    args = ["assets", "import", str(source), "--library", str(library), "--json"]
    args += ["--no-thumbnails", "--preset", "fast", "--size", "2", "2", "0.8"]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 0, result.output
    outcome = json.loads(result.stdout)["outcomes"][0]
    assert outcome["cached"] and outcome["asset_id"] == ASSET


SCREW_CAP = """<robot name="bottle">
  <link name="base"/>
  <link name="body"><visual><geometry><mesh filename="body.obj"/></geometry></visual></link>
  <joint name="fix" type="fixed"><parent link="base"/><child link="body"/></joint>
  <link name="cap_helper"/>
  <joint name="lift" type="prismatic">
    <origin xyz="0 0 0.3"/><axis xyz="0 0 1"/>
    <parent link="body"/><child link="cap_helper"/><limit lower="0.01" upper="0.03"/>
  </joint>
  <link name="cap">
    <visual><origin xyz="0 0 0.006"/><geometry><box size="0.04 0.04 0.01"/></geometry>
      <material name="red"><color rgba="0.8 0.1 0.1 1"/></material></visual>
  </link>
  <joint name="twist" type="continuous">
    <axis xyz="0 0 1"/><parent link="cap_helper"/><child link="cap"/>
  </joint>
</robot>
"""


def test_a_screw_joint_keeps_its_slide_and_a_pose_outside_the_range_is_closed(
    tmp_path: Path,
) -> None:
    from asset_pipeline.importer import ImportOptions, import_asset
    from tests.asset_pipeline.import_helpers import LOW, box_obj

    (tmp_path / "body.obj").write_text(box_obj(0.1, 0.1, 0.3))
    path = tmp_path / "bottle.urdf"
    path.write_text(SCREW_CAP)
    imported = import_asset(path, "bottle", ImportOptions(coacd=LOW))
    art = imported.bundle.meta.articulation
    assert art is not None and len(art.parts) == 1
    (cap,) = art.parts
    # The helper link took the cap's geometry and name; the continuous joint was dropped.
    assert (cap.name, cap.joint.name, cap.joint.type, cap.kind) == ("cap", "lift", "slide", "lid")
    assert cap.joint.range == pytest.approx((0.0, 0.02))
    assert cap.visual[0].rgba == pytest.approx((0.8, 0.1, 0.1, 1.0))  # the URDF's colour
    # The file's pose (lift = 0) is below the range: the cap was moved 1 cm up, to 0.01.
    assert imported.bundle.meta.size[2] == pytest.approx(0.321, abs=1e-4)
    warnings = " ".join(imported.report["warnings"])
    assert "joint 'twist' dropped" in warnings and "outside its range" in warnings


def test_a_urdf_without_moving_joints_is_a_rigid_asset(tmp_path: Path) -> None:
    from asset_pipeline.importer import ImportOptions, import_asset
    from tests.asset_pipeline.import_helpers import LOW, box_obj

    (tmp_path / "body.obj").write_text(box_obj(0.1, 0.1, 0.3))
    path = tmp_path / "block.urdf"
    path.write_text(SCREW_CAP.split('  <link name="cap_helper"/>')[0] + "</robot>\n")
    imported = import_asset(path, "block", ImportOptions(coacd=LOW))
    assert imported.bundle.meta.articulation is None
    assert "no moving joint" in " ".join(imported.report["warnings"])
