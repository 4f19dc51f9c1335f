"""``holomj compile``, ``info`` and ``schema``, and how ``main()`` reports bad input: through
typer's runner and through a real subprocess."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import mujoco
import pytest
from typer.testing import CliRunner

from holomj.cli import app
from tests.conftest import FIXTURES, copy_fixture

EXAMPLE = Path(__file__).parents[2] / "examples" / "procthor_house.json"


@pytest.fixture
def runner() -> CliRunner:
    return CliRunner()


@pytest.mark.parametrize(
    ("fixture", "fmt"),
    [
        ("two_room_scene.json", "holomj"),
        ("procthor_house_v1.json", "procthor"),
        ("procthor_house_legacy.json", "procthor"),
        ("holodeck_house.json", "holodeck"),
        ("scenedef_scene.json", "scenedef"),
    ],
)
def test_compile_every_format(runner: CliRunner, tmp_path: Path, fixture: str, fmt: str) -> None:
    out = tmp_path / "out"
    result = runner.invoke(app, ["compile", str(FIXTURES / fixture), "-o", str(out), "--json"])
    assert result.exit_code == 0, result.output
    report = json.loads(result.stdout)
    assert report["format"] == fmt
    assert report["sim_warnings"] == {}
    model = mujoco.MjModel.from_xml_path(str(out / "scene.xml"))
    assert model.nbody == report["model"]["bodies"]
    assert json.loads((out / "import_report.json").read_text())["format"] == fmt


def test_compile_then_info(runner: CliRunner, tmp_path: Path) -> None:
    out = tmp_path / "house"
    assert runner.invoke(app, ["compile", str(EXAMPLE), "-o", str(out), "-q"]).exit_code == 0
    result = runner.invoke(app, ["info", str(out), "--json"])
    assert result.exit_code == 0, result.output
    info = json.loads(result.stdout)
    assert len(info["rooms"]) == 4
    assert info["objects"] == 20
    assert info["model"]["hinges"] >= 1
    assert info["model"]["total_mass_kg"] > 100
    text = runner.invoke(app, ["info", str(out)])
    assert text.exit_code == 0 and "LivingRoom" in text.stdout
    nlight = mujoco.MjModel.from_xml_path(str(out / "scene.xml")).nlight
    assert info["lights"] == info["model"]["lights"] == nlight == 6
    assert "lights 6" in text.stdout


def test_info_counts_the_lights_the_compiler_adds(runner: CliRunner, tmp_path: Path) -> None:
    """A scene that lists no lights gets a sun and a ceiling light per room: info counts them."""
    data = json.loads((FIXTURES / "two_room_scene.json").read_text())
    data["lights"] = []
    scene = tmp_path / "unlit.json"
    scene.write_text(json.dumps(data))
    out = tmp_path / "out"
    assert runner.invoke(app, ["compile", str(scene), "-o", str(out), "-q"]).exit_code == 0
    nlight = mujoco.MjModel.from_xml_path(str(out / "scene.xml")).nlight
    assert nlight == 1 + len(data["rooms"])
    info = json.loads(runner.invoke(app, ["info", str(out), "--json"]).stdout)
    assert info["lights"] == nlight
    text = runner.invoke(app, ["info", str(out)])
    assert f"lights {nlight}" in text.stdout


def test_bad_input_is_one_line_exit_2_and_writes_nothing(runner: CliRunner, tmp_path: Path) -> None:
    data = json.loads((FIXTURES / "two_room_scene.json").read_text())
    data["rooms"][0]["polygon"][1] = ["east", 0]
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps(data))
    out = tmp_path / "out"
    result = runner.invoke(app, ["compile", str(bad), "-o", str(out)])
    assert result.exit_code == 2
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1, result.stderr
    assert str(bad) in lines[0] and "rooms[0].polygon[1]" in lines[0]
    assert not out.exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bad.json"]


@pytest.mark.parametrize(
    ("polygon", "message"),
    [
        # the ring's last vertex 1e-12 m from its first: used to crash the floor's triangulation
        ([[0, 0], [4, 0], [4, 3], [0, 3], [1e-12, 0]], "vertices 4 and 0 coincide"),
        # the outline touches itself: vertex 4 lies 1e-13 m from the edge 0-1
        ([[0, 0], [4, 0], [4, 3], [0, 3], [2, 1e-13]], "vertex 4 touches edge 0-1"),
    ],
)
def test_degenerate_room_polygon_is_one_line_exit_2(
    runner: CliRunner, tmp_path: Path, polygon: list, message: str
) -> None:
    data = json.loads((FIXTURES / "two_room_scene.json").read_text())
    data["rooms"][0]["polygon"] = polygon
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps(data))
    result = runner.invoke(app, ["compile", str(bad), "-o", str(tmp_path / "out")])
    assert result.exit_code == 2, result.output
    assert f"rooms[0].polygon (kitchen): {message}" in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize(
    ("content", "needle"),
    [
        ("{not json", "invalid JSON"),
        ('{"hello": 1}', "not a format holomj knows"),
        ("[1, 2, 3]", ""),
    ],
)
def test_unreadable_inputs(runner: CliRunner, tmp_path: Path, content: str, needle: str) -> None:
    bad = tmp_path / "bad.json"
    bad.write_text(content)
    result = runner.invoke(app, ["compile", str(bad), "-o", str(tmp_path / "out")])
    assert result.exit_code == 2, result.output
    assert needle.lower() in result.stderr.lower()
    assert len(result.stderr.strip().splitlines()) == 1


def test_missing_file_and_unknown_format(runner: CliRunner, tmp_path: Path) -> None:
    result = runner.invoke(app, ["compile", str(tmp_path / "nope.json"), "-o", str(tmp_path / "o")])
    assert result.exit_code == 2 and "file not found" in result.stderr
    result = runner.invoke(
        app,
        [
            "compile",
            str(FIXTURES / "two_room_scene.json"),
            "-o",
            str(tmp_path / "o"),
            "--format",
            "usd",
        ],
    )
    assert result.exit_code == 2 and "--format" in result.stderr and "procthor" in result.stderr


def test_forced_format_mismatch_is_a_clean_error(runner: CliRunner, tmp_path: Path) -> None:
    result = runner.invoke(
        app,
        [
            "compile",
            str(FIXTURES / "two_room_scene.json"),
            "-o",
            str(tmp_path / "o"),
            "--format",
            "procthor",
        ],
    )
    assert result.exit_code == 2
    assert len(result.stderr.strip().splitlines()) == 1


def test_existing_output_is_left_untouched_without_overwrite(
    runner: CliRunner, tmp_path: Path
) -> None:
    source = copy_fixture("two_room_scene.json", tmp_path / "in")
    out = tmp_path / "out"
    out.mkdir()
    (out / "keep.txt").write_text("mine")
    result = runner.invoke(app, ["compile", str(source), "-o", str(out)])
    assert result.exit_code == 2 and "--overwrite" in result.stderr
    assert [p.name for p in out.iterdir()] == ["keep.txt"]
    result = runner.invoke(app, ["compile", str(source), "-o", str(out), "--overwrite", "-q"])
    assert result.exit_code == 0, result.output
    assert not (out / "keep.txt").exists() and (out / "scene.xml").is_file()


def test_missing_asset_names_file_and_object(runner: CliRunner, tmp_path: Path) -> None:
    data = json.loads((FIXTURES / "two_room_scene.json").read_text())
    data["objects"][0]["asset"] = "unicorn_statue"
    src = tmp_path / "scene.json"
    src.write_text(json.dumps(data))
    result = runner.invoke(app, ["compile", str(src), "-o", str(tmp_path / "o")])
    assert result.exit_code == 2
    assert "objects[0].asset" in result.stderr and "unicorn_statue" in result.stderr


def test_info_on_a_non_scene_folder(runner: CliRunner, tmp_path: Path) -> None:
    result = runner.invoke(app, ["info", str(tmp_path)])
    assert result.exit_code == 2 and "scene.json" in result.stderr


def test_schema_command(runner: CliRunner, tmp_path: Path) -> None:
    result = runner.invoke(app, ["schema"])
    assert result.exit_code == 0
    assert "rooms" in json.loads(result.stdout)["properties"]
    target = tmp_path / "asset.schema.json"
    assert runner.invoke(app, ["schema", "asset", "-o", str(target)]).exit_code == 0
    assert "collision" in json.loads(target.read_text())["properties"]
    assert runner.invoke(app, ["schema", "nope"]).exit_code == 2


def test_real_subprocess_compile_is_byte_identical_across_runs(tmp_path: Path) -> None:
    outputs = []
    for name in ("a", "b"):
        out = tmp_path / name
        result = subprocess.run(
            [sys.executable, "-m", "holomj", "compile", str(EXAMPLE), "-o", str(out)],
            capture_output=True,
            text=True,
            check=False,
            cwd=tmp_path,
        )
        assert result.returncode == 0, result.stderr
        assert "compiled" in result.stdout
        outputs.append((out / "scene.xml").read_bytes())
    assert outputs[0] == outputs[1]


def test_real_subprocess_bad_input_exit_code(tmp_path: Path) -> None:
    bad = tmp_path / "bad.json"
    bad.write_text('{"rooms": []}')
    result = subprocess.run(
        [sys.executable, "-m", "holomj", "compile", str(bad), "-o", str(tmp_path / "out")],
        capture_output=True,
        text=True,
        check=False,
    )
    assert result.returncode == 2
    assert result.stderr.count("\n") == 1 and "Traceback" not in result.stderr
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize(
    ("args", "needle"),
    [
        (["populate", "SCENE", "--on", "table", "--objects", "mug", "--seed", "-1"], "--seed"),
        (["generate", "a kitchen", "-o", "OUT", "--seed", "-1"], "--seed"),
        (["validate", "SCENE", "--tolerance-mm", "-3"], "--tolerance-mm"),
        (["compile", "--no-such-option"], "--no-such-option"),
        (["validate"], "SCENE"),
    ],
)
def test_real_subprocess_bad_options_are_one_line(
    tmp_path: Path, args: list[str], needle: str
) -> None:
    """Option errors caught by the command-line parser, too, are one line with exit code 2."""
    args = [str(tmp_path / a) if a in ("SCENE", "OUT") else a for a in args]
    result = subprocess.run(
        [sys.executable, "-m", "holomj", *args], capture_output=True, text=True, check=False
    )
    assert result.returncode == 2, result.stderr
    assert result.stderr.count("\n") == 1 and "Traceback" not in result.stderr, result.stderr
    assert result.stderr.startswith("error: holomj") and needle in result.stderr
    assert not (tmp_path / "OUT").exists()
