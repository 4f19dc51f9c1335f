"""``holomj layout solve`` through typer's runner."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from holomj.cli import app
from tests.conftest import FIXTURES, copy_fixture


@pytest.fixture
def runner() -> CliRunner:
    return CliRunner()


def write(tmp_path: Path, data: dict) -> Path:
    path = tmp_path / "problem.json"
    path.write_text(json.dumps(data))
    return path


def test_solve_writes_placements(runner: CliRunner, tmp_path: Path) -> None:
    problem = copy_fixture("layout_living_room.json", tmp_path)
    out = tmp_path / "layout.json"
    result = runner.invoke(
        app, ["layout", "solve", str(problem), "-o", str(out), "--time-limit", "3", "--seed", "3"]
    )
    assert result.exit_code == 0, result.output
    assert "10/10 objects" in result.stdout
    data = json.loads(out.read_text())
    assert set(data["placements"]) == {o["id"] for o in json.loads(problem.read_text())["objects"]}
    for placement in data["placements"].values():
        assert set(placement) >= {"x", "y", "yaw_deg"}
    assert data["total"] == 36 and data["satisfied"] >= 34
    assert all({"text", "satisfied", "detail"} <= set(c) for c in data["constraints"])
    assert data["unplaced"] == []
    assert data["solve_time_s"] > 0 and data["solver_used"] == "cpsat"
    assert not list(tmp_path.glob(".layout.json.*"))  # no temporary file left behind


def test_greedy_and_json_output(runner: CliRunner, tmp_path: Path) -> None:
    problem = copy_fixture("layout_living_room.json", tmp_path)
    out = tmp_path / "layout.json"
    result = runner.invoke(
        app, ["layout", "solve", str(problem), "-o", str(out), "--solver", "greedy", "--json"]
    )
    assert result.exit_code == 0, result.output
    assert json.loads(result.stdout)["solver_used"] == "greedy"


@pytest.mark.parametrize(
    ("change", "needle"),
    [
        (lambda d: d.__setitem__("polygon", [[0, 0], [1, 0]]), "polygon"),
        (lambda d: d["objects"][0].__setitem__("width", -3), "objects[0].width"),
        (lambda d: d["doors"][0].__setitem__("position", [3, 3]), "doors[0].position"),
        (lambda d: d.__setitem__("size_unit", "inch"), "size_unit"),
        (lambda d: d["objects"][1].__setitem__("colour", "red"), "objects[1].colour"),
    ],
)
def test_bad_input_exits_2_with_one_line(
    runner: CliRunner, tmp_path: Path, change, needle: str
) -> None:
    data = json.loads((FIXTURES / "layout_living_room.json").read_text())
    change(data)
    out = tmp_path / "layout.json"
    result = runner.invoke(app, ["layout", "solve", str(write(tmp_path, data)), "-o", str(out)])
    assert result.exit_code == 2, result.output
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1, result.stderr
    assert needle in lines[0]
    assert not out.exists()


def test_bad_solver_and_missing_file(runner: CliRunner, tmp_path: Path) -> None:
    problem = copy_fixture("layout_living_room.json", tmp_path)
    result = runner.invoke(
        app, ["layout", "solve", str(problem), "-o", str(tmp_path / "o.json"), "--solver", "milp"]
    )
    assert result.exit_code == 2 and "--solver" in result.stderr
    result = runner.invoke(
        app, ["layout", "solve", str(tmp_path / "nope.json"), "-o", str(tmp_path / "o.json")]
    )
    assert result.exit_code == 2 and "file not found" in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1


def test_unplaceable_object_still_exits_0(runner: CliRunner, tmp_path: Path) -> None:
    data = json.loads((FIXTURES / "layout_living_room.json").read_text())
    data["objects"].append({"id": "pool_table-0", "width": 400, "depth": 800, "height": 90})
    out = tmp_path / "layout.json"
    result = runner.invoke(app, ["layout", "solve", str(write(tmp_path, data)), "-o", str(out)])
    assert result.exit_code == 0, result.output
    assert "unplaced pool_table-0" in result.stdout
    written = json.loads(out.read_text())
    assert [u["id"] for u in written["unplaced"]] == ["pool_table-0"]
    assert "does not fit" in written["unplaced"][0]["reason"]
    assert len(written["placements"]) == 10


def test_text_warnings_are_printed(runner: CliRunner, tmp_path: Path) -> None:
    data = json.loads((FIXTURES / "layout_living_room.json").read_text())
    data["constraints_text"] += "plant-0 | hovering, sofa-0\n"
    out = tmp_path / "layout.json"
    result = runner.invoke(app, ["layout", "solve", str(write(tmp_path, data)), "-o", str(out)])
    assert result.exit_code == 0, result.output
    assert "unknown constraint 'hovering'" in result.stderr
    assert any("hovering" in w for w in json.loads(out.read_text())["warnings"])
