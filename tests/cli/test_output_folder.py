"""Every job that writes a folder checks it before any work: OUT under a regular file, under
/proc, in a read-only folder, or existing without --overwrite exits 2 with one line naming what
and where, and nothing is written."""

from __future__ import annotations

import json
import os
from collections.abc import Callable
from pathlib import Path

import pytest
from typer.testing import CliRunner

from holomj.cli import app
from holomj.library.store import AssetLibrary
from tests.conftest import FIXTURES

runner = CliRunner()
INSTRUCTION = "add a floor lamp by the window"


@pytest.fixture(scope="module")
def scene_folder(tmp_path_factory: pytest.TempPathFactory, default_library: AssetLibrary) -> Path:
    """A compiled two-room scene, the input of edit and refine."""
    out = tmp_path_factory.mktemp("output_folder") / "scene"
    result = runner.invoke(app, ["compile", str(FIXTURES / "two_room_scene.json"), "-o", str(out)])
    assert result.exit_code == 0, result.output
    return out


def _bad_outputs(root: Path) -> dict[str, tuple[Path, str]]:
    """Case -> (OUT, what the one-line error must name)."""
    a_file = root / "a_file"
    a_file.write_text("not a folder")
    existing = root / "existing"
    existing.mkdir()
    (existing / "keep.txt").write_text("mine")
    cases = {
        "under a regular file": (a_file / "out", str(a_file)),
        "under /proc": (Path("/proc/holomj-test-out"), "/proc"),
        "exists without --overwrite": (existing, str(existing)),
    }
    if os.geteuid() != 0:  # root writes into read-only folders: the case cannot happen then
        read_only = root / "read_only"
        read_only.mkdir()
        read_only.chmod(0o555)
        cases["in a read-only folder"] = (read_only / "out", str(read_only))
    return cases


def _listing(root: Path) -> list[str]:
    return sorted(str(p.relative_to(root)) for p in root.rglob("*"))


def _commands(scene: Path, library: AssetLibrary, ops: Path) -> dict[str, Callable[[Path], list]]:
    lib = ["--library", str(library.root)]
    return {
        "generate": lambda out: ["generate", "a small kitchen", "-o", str(out), *lib],
        "compile": lambda out: ["compile", str(FIXTURES / "two_room_scene.json"), "-o", str(out)],
        "edit": lambda out: ["edit", str(scene), str(ops), "-o", str(out), *lib],
        "refine": lambda out: ["refine", str(scene), "-i", INSTRUCTION, "-o", str(out), *lib],
    }


@pytest.mark.parametrize("job", ["generate", "compile", "edit", "refine"])
def test_a_bad_output_folder_exits_2_before_any_work(
    tmp_path: Path, scene_folder: Path, default_library: AssetLibrary, job: str
) -> None:
    ops = tmp_path / "ops.json"
    ops.write_text(json.dumps([{"op": "remove", "id": "living.sofa"}]))
    command = _commands(scene_folder, default_library, ops)[job]
    for case, (out, where) in _bad_outputs(tmp_path).items():
        before = _listing(tmp_path)
        result = runner.invoke(app, command(out))
        assert result.exit_code == 2, (job, case, result.output)
        errors = [line for line in result.output.splitlines() if line.startswith("error:")]
        assert len(errors) == 1 and where in errors[0], (job, case, result.output)
        assert "Traceback" not in result.output
        assert _listing(tmp_path) == before, (job, case)
        assert not Path("/proc/holomj-test-out").exists()
