"""``holomj batch`` through the command line: bad input is one line, exit code 2, nothing written.

The engines, resuming and the summary are tested in ``tests/batch``.
"""

from __future__ import annotations

from pathlib import Path

from typer.testing import CliRunner

from holomj.cli import app


def test_bad_input_is_one_line_and_exit_2(tmp_path: Path, empty_library) -> None:
    runner = CliRunner()
    jobs = tmp_path / "jobs.txt"
    jobs.write_text("a small kitchen\n")
    cases = [
        (["batch", str(tmp_path / "missing.txt"), "-o", str(tmp_path / "o")], "not found"),
        (["batch", str(jobs), "-o", str(tmp_path / "o"), "--seeds", "3:1"], "--seeds"),
        (["batch", str(jobs), "-o", str(tmp_path / "o"), "--planner", "magic"], "--planner"),
        (["batch", str(jobs), "-o", str(tmp_path / "o"), "--workers", "0"], "--workers"),
    ]
    for args, message in cases:
        result = runner.invoke(app, args)
        assert result.exit_code == 2, (args, result.output)
        assert message in result.output
    assert not (tmp_path / "o").exists()
    blocked = tmp_path / "file"
    blocked.write_text("x")
    lib = ["--library", str(empty_library.root)]
    result = runner.invoke(app, ["batch", str(jobs), "-o", str(blocked), *lib])
    assert result.exit_code == 2 and "not a folder" in result.output
    result = runner.invoke(app, ["batch", str(jobs), "-o", str(tmp_path / "o"), "--library", "."])
    assert result.exit_code == 2 and "not an asset library" in result.output
    result = runner.invoke(
        app, ["batch", str(jobs), "-o", str(tmp_path / "o"), *lib, "--text-model", "nope"]
    )
    assert result.exit_code == 2 and "--text-model" in result.output
    assert not (tmp_path / "o").exists()
