"""``holomj eval`` on the command line: the table, ``--json``, ``--spec``, ``--prompt`` and exit
codes (0 when measured, whatever was found; 2 for bad input, with nothing written)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from holomj.cli import app
from tests.evaluation.scenes import GOOD, box, compile_scene, variant


@pytest.fixture
def runner() -> CliRunner:
    return CliRunner()


@pytest.fixture(scope="module")
def good(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return compile_scene(GOOD, tmp_path_factory.mktemp("good"))


@pytest.fixture(scope="module")
def bad(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The good scene with a crate in the doorway and another inside the sofa."""
    scene = variant(
        GOOD,
        box("crate_0", "living_room", (2.0, 0.5), (0.8, 0.6, 0.8)),
        box("crate_1", "living_room", (0.6, 1.5), (0.4, 0.4, 0.4)),
    )
    return compile_scene(scene, tmp_path_factory.mktemp("bad"))


def test_table_and_json_report(runner: CliRunner, good: Path, tmp_path: Path) -> None:
    report = tmp_path / "reports" / "eval.json"
    result = runner.invoke(app, ["eval", str(good), "--json", str(report)])
    assert result.exit_code == 0, result.output
    for word in ("navigability", "front_access", "windows_clear", "stability", "overall"):
        assert word in result.stdout
    assert "no report.json" in result.stdout
    data = json.loads(report.read_text())
    assert data["schema_version"] == "1.0" and data["folder"] == str(good)
    assert data["scores"]["doors_clear"] == {
        "score": 1.0,
        "ok": True,
        "held": 1,
        "total": 1,
        "summary": "1/1 doors clear",
    }
    result = runner.invoke(app, ["eval", str(good), "--json", "-"])
    assert result.exit_code == 0
    assert json.loads(result.stdout)["scores"].keys() == data["scores"].keys()


def test_failures_are_measured_not_judged(runner: CliRunner, bad: Path) -> None:
    result = runner.invoke(app, ["eval", str(bad)])
    assert result.exit_code == 0, result.output
    assert "collisions: living_room.crate_1 / living_room.sofa_0" in result.stdout
    assert "doors: front: living_room.crate_0" in result.stdout


def test_spec_file_and_prompt(runner: CliRunner, good: Path, tmp_path: Path) -> None:
    lines = [
        {"id": "a", "prompt": "p", "objects": [{"name": "sofa", "count": {"eq": 1}}]},
        {"id": "b", "prompt": "p", "objects": [{"name": "sofa", "count": {"eq": 2}}]},
    ]
    spec = tmp_path / "specs.jsonl"
    spec.write_text("\n".join(json.dumps(line) for line in lines) + "\n")
    out = tmp_path / "r.json"
    result = runner.invoke(app, ["eval", str(good), "--spec", str(spec), "--id", "b"])
    assert result.exit_code == 0, result.output
    assert "0/1 counts met" in result.stdout and "1 found" in result.stdout
    result = runner.invoke(app, ["eval", str(good), "--spec", str(spec), "--json", str(out)])
    assert result.exit_code == 2 and "pick one with --id" in result.stderr
    assert not out.exists()  # bad input: nothing written

    result = runner.invoke(
        app, ["eval", str(good), "--prompt", "a living room with a sofa", "--json", str(out)]
    )
    assert result.exit_code == 0, result.output
    data = json.loads(out.read_text())
    assert data["against"]["source"] == "prompt" and data["against"]["planner"] == "offline"
    sofa = next(r for r in data["details"]["counts"] if r.get("name") == "sofa")
    assert sofa["held"] and sofa["found"] == 1


def test_bad_input_exits_with_2(runner: CliRunner, good: Path, tmp_path: Path) -> None:
    out = tmp_path / "r.json"
    result = runner.invoke(app, ["eval", str(tmp_path), "--json", str(out)])
    assert result.exit_code == 2 and "not a holomj scene folder" in result.stderr
    result = runner.invoke(app, ["eval", str(good), "--prompt", "x", "--spec", "s.json"])
    assert result.exit_code == 2 and "not both" in result.stderr
    broken = tmp_path / "broken.json"
    broken.write_text('{"objects": [{"name": "sofa", "count": {"eq": -1}}]}')
    result = runner.invoke(app, ["eval", str(good), "--spec", str(broken), "--json", str(out)])
    assert result.exit_code == 2 and "objects[0].count" in result.stderr
    broken.write_text("{not json")
    result = runner.invoke(app, ["eval", str(good), "--spec", str(broken)])
    assert result.exit_code == 2 and "not JSON" in result.stderr
    result = runner.invoke(app, ["eval", str(good), "--spec", str(tmp_path / "missing.json")])
    assert result.exit_code == 2 and "no such file" in result.stderr
    assert not out.exists()
