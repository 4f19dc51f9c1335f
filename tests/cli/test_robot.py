"""``holomj compile --robot/--profile`` and ``holomj add-robot`` through typer's runner."""

from __future__ import annotations

import json
from pathlib import Path

import mujoco
import pytest
from typer.testing import CliRunner

from holomj.cli import app
from tests.conftest import FIXTURES


@pytest.fixture
def runner() -> CliRunner:
    return CliRunner()


@pytest.fixture
def compiled_folder(runner: CliRunner, tmp_path: Path) -> Path:
    out = tmp_path / "house"
    fixture = str(FIXTURES / "two_room_scene.json")
    result = runner.invoke(app, ["compile", fixture, "-o", str(out), "-q", "--check-seconds", "0"])
    assert result.exit_code == 0, result.output
    return out


def test_compile_with_a_robot(runner: CliRunner, tmp_path: Path) -> None:
    out = tmp_path / "out"
    args = ["compile", str(FIXTURES / "two_room_scene.json"), "-o", str(out), "--json"]
    result = runner.invoke(app, [*args, "--robot", "jaco", "--seed", "2"])
    assert result.exit_code == 0, result.output
    report = json.loads(result.stdout)
    assert report["robot"]["name"] == "jaco" and report["sim_warnings"] == {}
    for name in ("robot.json", "objects.json", "navmap.json", "navmap.png", "scene.xml"):
        assert (out / name).is_file(), name
    model = mujoco.MjModel.from_xml_path(str(out / "scene.xml"))
    assert model.body("robot/base_mount").pos.tolist() == report["robot"]["position"]


def test_bad_robot_and_profile_are_input_errors(runner: CliRunner, tmp_path: Path) -> None:
    out = tmp_path / "out"
    args = ["compile", str(FIXTURES / "two_room_scene.json"), "-o", str(out)]
    result = runner.invoke(app, [*args, "--robot", "hal9000"])
    assert result.exit_code == 2
    assert "unknown robot 'hal9000'" in result.stderr and "jaco" in result.stderr
    result = runner.invoke(app, [*args, "--profile", "gpu"])
    assert result.exit_code == 2 and "use default or mjx" in result.stderr
    assert not out.exists()


def test_add_robot_keeps_the_other_files(runner: CliRunner, compiled_folder: Path) -> None:
    (compiled_folder / "notes.txt").write_text("mine")
    result = runner.invoke(app, ["add-robot", str(compiled_folder), "jaco", "--room", "kitchen"])
    assert result.exit_code == 0, result.output
    assert "added jaco" in result.stdout and "in kitchen" in result.stdout
    assert (compiled_folder / "notes.txt").read_text() == "mine"
    assert (compiled_folder / "import_report.json").is_file()
    record = json.loads((compiled_folder / "robot.json").read_text())
    assert record["room"] == "kitchen"
    objects = json.loads((compiled_folder / "objects.json").read_text())
    assert objects["robot"]["name"] == "jaco"
    navmap = json.loads((compiled_folder / "navmap.json").read_text())
    assert navmap["robot"]["position"] == record["position"]
    # A second robot needs --replace.
    again = runner.invoke(app, ["add-robot", str(compiled_folder), "jaco"])
    assert again.exit_code == 2 and "already has a robot" in again.stderr
    replaced = runner.invoke(
        app, ["add-robot", str(compiled_folder), "jaco", "--replace", "--room", "living", "--json"]
    )
    assert replaced.exit_code == 0, replaced.output
    assert json.loads(replaced.stdout)["room"] == "living"
    assert mujoco.MjModel.from_xml_path(str(compiled_folder / "scene.xml")).nbody > 20


def test_add_robot_input_errors(runner: CliRunner, compiled_folder: Path, tmp_path: Path) -> None:
    before = (compiled_folder / "scene.xml").read_text()
    result = runner.invoke(app, ["add-robot", str(compiled_folder), "nosuchbot"])
    assert result.exit_code == 2 and "unknown robot" in result.stderr
    result = runner.invoke(app, ["add-robot", str(tmp_path), "jaco"])
    assert result.exit_code == 2 and "not a holomj scene folder" in result.stderr
    result = runner.invoke(app, ["add-robot", str(compiled_folder), "jaco", "--clearance", "2"])
    assert result.exit_code == 2 and "no free floor spot" in result.stderr
    assert (compiled_folder / "scene.xml").read_text() == before
    assert not (compiled_folder / "robot.json").exists()


def test_compile_with_the_mjx_profile(runner: CliRunner, tmp_path: Path) -> None:
    out = tmp_path / "mjx"
    fixture = str(FIXTURES / "two_room_scene.json")
    result = runner.invoke(app, ["compile", fixture, "-o", str(out), "-q", "--profile", "mjx"])
    assert result.exit_code == 0, result.output
    model = mujoco.MjModel.from_xml_path(str(out / "scene.xml"))
    assert model.numeric("max_geom_pairs").data[0] > 0
