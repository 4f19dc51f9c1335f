"""``holomj generate --robot`` (validated with the robot) and ``--profile mjx``."""

from __future__ import annotations

import json
from pathlib import Path

import mujoco
import pytest
from typer.testing import CliRunner

from holomj.cli import app

runner = CliRunner()


def test_bad_robot_fails_before_any_work(tmp_path: Path, default_library) -> None:
    out = tmp_path / "out"
    args = ["generate", "a small kitchen", "-o", str(out), "--library", str(default_library.root)]
    result = runner.invoke(app, [*args, "--robot", "c3po"])
    assert result.exit_code == 2 and "unknown robot 'c3po'" in result.stderr
    result = runner.invoke(app, [*args, "--profile", "warp"])
    assert result.exit_code == 2 and "--profile" in result.stderr
    assert not out.exists()


@pytest.mark.slow
def test_generate_with_a_robot(tmp_path: Path, default_library) -> None:
    out = tmp_path / "kitchen"
    result = runner.invoke(
        app,
        [
            "generate",
            "a small kitchen",
            "-o",
            str(out),
            "--library",
            str(default_library.root),
            "--no-render",
            "--seed",
            "1",
            "--robot",
            "jaco",
            "--json",
        ],
    )
    assert result.exit_code == 0, result.output
    summary = json.loads(result.stdout)
    assert summary["ok"] and summary["penetrations"] == 0
    record = json.loads((out / "robot.json").read_text())
    assert record["name"] == "jaco" and record["room"] == "kitchen"
    assert "] robot: done" in (out / "generate.log").read_text()
    report = json.loads((out / "report.json").read_text())
    assert report["ok"] and report["warnings"] == {}
    model = mujoco.MjModel.from_xml_path(str(out / "scene.xml"))
    assert model.body("robot/base_mount").pos[:2].tolist() == record["position"][:2]
    objects = json.loads((out / "objects.json").read_text())
    assert (
        objects["robot"]["name"] == "jaco"
        and len(objects["objects"]) == summary["objects"]["objects"]
    )
    navmap = json.loads((out / "navmap.json").read_text())
    assert all(room["reachable"] for room in navmap["rooms"].values())
