"""holomj validate on the command line: report file, summary, exit codes, --repair."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest
from typer.testing import CliRunner

from holomj.cli import app
from holomj.library import AssetLibrary
from holomj.spec.report import StabilityReport
from tests.physics.scenes import box, export, make_scene

FAST = ["--monitor-s", "1", "--settle-s", "2"]


@pytest.fixture
def runner() -> CliRunner:
    return CliRunner()


@pytest.fixture
def stable_folder(empty_library: AssetLibrary, tmp_path: Path) -> Path:
    scene = make_scene([box("crate", (3, 3, 0), (0.5, 0.4, 0.3))])
    return export(scene, empty_library, tmp_path / "stable")


@pytest.fixture
def falling_folder(empty_library: AssetLibrary, tmp_path: Path) -> Path:
    scene = make_scene([box("floater", (3, 3, 0.3), (0.2, 0.2, 0.2))])
    return export(scene, empty_library, tmp_path / "falling")


def test_report_file_and_exit_codes(
    runner: CliRunner, stable_folder: Path, falling_folder: Path, tmp_path: Path
) -> None:
    report_path = tmp_path / "reports" / "stable.json"
    result = runner.invoke(
        app, ["validate", str(stable_folder), "--json", str(report_path), "--strict", *FAST]
    )
    assert result.exit_code == 0, result.output
    report = StabilityReport.model_validate_json(report_path.read_text())
    assert report.ok and report.objects[0].name == "crate"
    assert report.monitor_s == 1.0

    result = runner.invoke(app, ["validate", str(falling_folder), *FAST])
    assert result.exit_code == 0, result.output  # a report was made: not ok is not an error
    assert "floater" in result.stdout and "not ok" in result.stdout
    result = runner.invoke(app, ["validate", str(falling_folder), "--strict", "-q", *FAST])
    assert result.exit_code == 1 and result.stdout == ""


def test_bad_input_exits_with_2(runner: CliRunner, tmp_path: Path, stable_folder: Path) -> None:
    result = runner.invoke(app, ["validate", str(tmp_path / "missing")])
    assert result.exit_code == 2 and "not found" in result.stderr
    result = runner.invoke(app, ["validate", str(tmp_path)])
    assert result.exit_code == 2 and "not a holomj scene folder" in result.stderr
    result = runner.invoke(app, ["validate", str(stable_folder), "--furniture", "wobbly"])
    assert result.exit_code == 2 and "free, static or as-is" in result.stderr
    broken = tmp_path / "broken.xml"
    broken.write_text("<mujoco><worldbody><geom type='sphere'/></worldbody>")
    result = runner.invoke(app, ["validate", str(broken)])
    assert result.exit_code == 2 and "MuJoCo cannot load it" in result.stderr


def test_repair_through_the_cli(
    runner: CliRunner, empty_library: AssetLibrary, tmp_path: Path
) -> None:
    scene = make_scene([box("sunk", (3, 3, -0.005), (0.3, 0.3, 0.3))])
    folder = export(scene, empty_library, tmp_path / "sunk")
    result = runner.invoke(
        app, ["validate", str(folder), "--repair", "--strict", "--json", "-", *FAST]
    )
    assert result.exit_code == 0, result.output
    report = json.loads(result.stdout)
    assert report["ok"] and report["penetrations"] == [] and report["below_floor"] == []
    assert [a["name"] for a in report["repaired"]] == ["sunk"]
    assert report["repaired"][0]["moved_m"] == pytest.approx(0.005, abs=0.0015)
    assert "settled" in (folder / "scene.xml").read_text()


def test_real_subprocess(falling_folder: Path, tmp_path: Path) -> None:
    report_path = tmp_path / "report.json"
    result = subprocess.run(
        [
            sys.executable,
            "-m",
            "holomj",
            "validate",
            str(falling_folder),
            "--json",
            str(report_path),
            "--strict",
            *FAST,
        ],
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
    )
    assert result.returncode == 1, result.stderr
    assert "NOT ok" in result.stderr
    report = json.loads(report_path.read_text())
    assert report["counts"]["fell"] == 1 and not report["ok"]


def test_repair_never_bakes_a_toppled_pose(
    runner: CliRunner, empty_library: AssetLibrary, tmp_path: Path
) -> None:
    """A footed pole that topples is unsaved: its authored pose stays in scene.json and in the
    'settled' keyframe, the crate beside it is baked, and --repair exits 1."""
    import math

    import mujoco

    tilt = math.radians(10) / 2
    scene = make_scene(
        [
            box("crate", (1.5, 1.5, 0), (0.4, 0.4, 0.4)),
            box(
                "pole",
                (3, 3, 0.02 * math.sin(2 * tilt)),
                (0.04, 0.04, 1.0),
                quat=[math.cos(tilt), 0.0, math.sin(tilt), 0.0],
            ),
        ]
    )
    folder = export(scene, empty_library, tmp_path / "pole")
    authored = json.loads((folder / "scene.json").read_text())["objects"][1]
    result = runner.invoke(app, ["validate", str(folder), "--repair", "--json", "-", *FAST])
    assert result.exit_code == 1, result.output
    report = json.loads(result.stdout)
    assert [u["name"] for u in report["unsaved"]] == ["pole"]
    assert "from its authored orientation" in report["unsaved"][0]["why"]
    kept = json.loads((folder / "scene.json").read_text())["objects"][1]
    assert kept["position"] == authored["position"] and kept["quat"] == authored["quat"]
    model = mujoco.MjModel.from_xml_path(str(folder / "scene.xml"))
    key = model.key("settled")
    joint = model.joint("pole/freejoint")
    adr = joint.qposadr[0]
    assert key.qpos[adr : adr + 7] == pytest.approx(model.qpos0[adr : adr + 7])
    row = {o["name"]: o for o in report["objects"]}["pole"]
    assert not row["stable"] and row["rotation_from_authored_deg"] > 45
