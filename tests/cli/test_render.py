"""``holomj render``: success output, --json, --no-report, and one-line errors with exit 2."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from holomj.cli import app

runner = CliRunner()


def test_render_writes_renders_and_the_page(two_room_folder: Path) -> None:
    args = ["render", str(two_room_folder), "--width", "64", "--height", "48", "--no-shadows"]
    result = runner.invoke(app, args)
    assert result.exit_code == 0, result.output
    assert "rendered 4 images" in result.output  # top, plan, two rooms
    assert (two_room_folder / "report.html").is_file()
    assert (two_room_folder / "renders" / "rooms" / "kitchen.png").is_file()


def test_render_json_without_the_page(two_room_folder: Path) -> None:
    args = ["render", str(two_room_folder), "--views", "objects", "--width", "48"]
    args += ["--height", "32", "--depth", "--segmentation", "--no-report", "--json"]
    result = runner.invoke(app, args)
    assert result.exit_code == 0, result.output
    summary = json.loads(result.stdout)
    assert summary["report_html"] is None
    assert [v["subject"] for v in summary["views"]] == ["table"]
    assert summary["views"][0]["depth"] == "renders/objects/table_depth.png"
    assert summary["legend"] == "renders/segmentation.json"
    assert not (two_room_folder / "report.html").exists()


def test_quiet_prints_nothing(two_room_folder: Path) -> None:
    args = ["render", str(two_room_folder), "--views", "top", "--width", "32", "--height", "24"]
    result = runner.invoke(app, [*args, "--quiet", "--no-shadows"])
    assert result.exit_code == 0 and result.stdout == ""


@pytest.mark.parametrize(
    ("extra", "message"),
    [
        (["--views", "top,sideways"], "--views: unknown view 'sideways'"),
        (["--width", "100000"], "--width: image size 100000 px is out of range"),
        (["--height", "2"], "--height: image size 2 px is out of range"),
    ],
)
def test_bad_options_are_one_line_exit_2(two_room_folder: Path, extra, message) -> None:
    result = runner.invoke(app, ["render", str(two_room_folder), *extra])
    assert result.exit_code == 2
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and message in lines[0]
    assert not (two_room_folder / "renders").exists()


def test_not_a_holomj_folder_is_exit_2(tmp_path: Path) -> None:
    for target in (tmp_path / "missing", tmp_path):
        result = runner.invoke(app, ["render", str(target)])
        assert result.exit_code == 2
        assert len(result.stderr.strip().splitlines()) == 1
