"""An articulated MJCF file imported through ``holomj assets import``: its hinge and slide joints
kept (ranges, the file's damping), each body decomposed, and the parts pass the simulation tests;
what a part cannot be is refused with one line naming the body."""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

import mujoco
import pytest
from typer.testing import CliRunner

from holomj.cli.app import app
from holomj.library import AssetLibrary
from tests.asset_pipeline.articulated_helpers import (
    HINGE,
    compiled_object,
    part_joints,
    simulate,
    value,
    warnings_of,
)
from tests.asset_pipeline.urdf_helpers import DRAWER_TRAVEL_M, write_mjcf_cabinet


@pytest.fixture(scope="module")
def imported(tmp_path_factory: pytest.TempPathFactory) -> dict:
    root = tmp_path_factory.mktemp("mjcf")
    path = write_mjcf_cabinet(root / "model")
    library = root / "library"
    args = ["assets", "import", str(path), "--library", str(library), "--json"]
    args += ["--no-thumbnails", "--preset", "fast", "--category", "cabinet"]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 0, result.output
    lib = AssetLibrary.open(library)
    derivation = json.loads((lib.get("cabinet").root / "derivation.json").read_text())
    return {"library": lib, "derivation": derivation}


def test_joints_ranges_and_dynamics_are_kept(imported: dict) -> None:
    meta = imported["library"].get("cabinet").meta
    art = meta.articulation
    assert art is not None
    door, drawer = art.parts
    assert (door.name, door.joint.name, door.kind) == ("door", "door_hinge", "door")
    assert (drawer.name, drawer.joint.name, drawer.kind) == ("drawer", "drawer_slide", "drawer")
    assert door.joint.range == pytest.approx((0.0, math.radians(100.0)))  # angle="degree"
    assert drawer.joint.range == pytest.approx((0.0, DRAWER_TRAVEL_M))
    assert door.joint.damping == pytest.approx(3.0)  # the file's
    assert drawer.joint.damping == pytest.approx(60.0)  # not in the file: holomj's default
    assert door.joint.axis == pytest.approx((0.0, 0.0, -1.0))
    assert meta.size == pytest.approx((0.551, 0.8, 0.8), abs=0.002)  # metres, as written
    # Colours from the file: the carcass's material, the door's geom rgba.
    assert meta.visual[0].rgba == pytest.approx((0.6, 0.45, 0.3, 1.0))
    assert any(v.rgba == pytest.approx((0.8, 0.8, 0.8, 1.0)) for v in door.visual)
    assert door.handle is not None and door.handle.pos[2] == pytest.approx(0.4, abs=0.01)
    assert [s.part for s in art.interior] == [None, "drawer"]
    derivation = imported["derivation"]
    assert derivation["source"]["format"] == "mjcf"
    assert len(derivation["bodies"]) == 3
    assert any("free joint of body 'cabinet' dropped" in w for w in derivation["warnings"])


def test_the_imported_parts_stay_closed_open_and_close(imported: dict) -> None:
    model = compiled_object(imported["library"], "cabinet").model
    joints = part_joints(model)
    assert len(joints) == 2
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    simulate(model, data, 2.0)
    assert max(abs(value(model, data, j)) for j in joints) < 0.001
    for joint in joints:
        hinge = int(model.jnt_type[joint]) == HINGE
        data = mujoco.MjData(model)
        mujoco.mj_forward(model, data)
        simulate(model, data, 1.5, joint, +1.0)
        assert value(model, data, joint) >= (math.radians(20.0) if hinge else 0.10)
        assert simulate(model, data, 1.5, joint, -1.0) <= 0.001
        simulate(model, data, 0.3)
        assert abs(value(model, data, joint)) < (math.radians(1.0) if hinge else 0.002)
        assert not warnings_of(data)


BROKEN_MJCF = {
    "ball": (
        'type="slide" axis="1 0 0"',
        'type="ball"',
        r"body 'drawer': ball joint 'drawer_slide' \(ball\) is not supported",
    ),
    "two_joints": (
        '<geom type="mesh" mesh="door"',
        '<joint name="extra" type="slide"/><geom type="mesh" mesh="door"',
        r"body 'door' has 2 joints",
    ),
    "unlimited_slide": (
        ' range="0 0.35"',
        "",
        r"body 'drawer': slide joint 'drawer_slide' \(slide\) has no range",
    ),
    "missing_mesh": ('file="door.obj"', 'file="nope.obj"', r"MuJoCo cannot load it: .*nope.obj"),
}


@pytest.mark.parametrize("case", sorted(BROKEN_MJCF))
def test_a_malformed_mjcf_is_refused(tmp_path: Path, case: str) -> None:
    old, new, pattern = BROKEN_MJCF[case]
    path = write_mjcf_cabinet(tmp_path / "model")
    text = path.read_text()
    assert old in text
    path.write_text(text.replace(old, new, 1))
    library = tmp_path / "library"
    result = CliRunner().invoke(
        app, ["assets", "import", str(path), "--library", str(library), "--no-thumbnails"]
    )
    assert result.exit_code == 2, result.output
    lines = [line for line in result.output.splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith(f"error: {path}: "), result.output
    assert re.search(pattern, lines[0]), lines[0]
    assert not library.exists()


def test_parts_that_overlap_when_closed_are_reported(tmp_path: Path) -> None:
    from asset_pipeline.importer import ImportOptions, import_asset
    from tests.asset_pipeline.import_helpers import LOW

    path = write_mjcf_cabinet(tmp_path / "model")
    text = path.read_text().replace('<body name="drawer">', '<body name="drawer" pos="0 0 -0.1">')
    path.write_text(text)
    imported = import_asset(path, "overlap", ImportOptions(coacd=LOW))
    touching = [w for w in imported.report["warnings"] if "may touch" in w]
    assert touching and "'door'" in touching[0] and "'drawer'" in touching[0]
