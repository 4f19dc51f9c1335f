"""``holomj refine`` through typer's runner: the offline reading corner on a generated living
room (exit 0, refine.json, the source untouched), ``--json``, and bad input (exit 2, nothing
written)."""

from __future__ import annotations

import hashlib
import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

import holomj
from holomj.cli import app
from holomj.library.store import AssetLibrary

INSTRUCTION = "add a reading corner with an armchair and a floor lamp by the window"


@pytest.fixture(scope="module")
def living_room(tmp_path_factory: pytest.TempPathFactory, default_library: AssetLibrary) -> Path:
    """A generated living room (refine writes to other folders)."""
    out = tmp_path_factory.mktemp("cli_refine") / "living_room"
    holomj.generate(
        "a living room with a sofa, a coffee table and a tv",
        out,
        seed=0,
        render=False,
        library=default_library,
    )
    return out


def folder_hash(folder: Path) -> str:
    digest = hashlib.sha256()
    for path in sorted(p for p in folder.rglob("*") if p.is_file()):
        digest.update(str(path.relative_to(folder)).encode())
        digest.update(path.read_bytes())
    return digest.hexdigest()


@pytest.mark.slow
def test_refine_offline_reading_corner(
    living_room: Path, tmp_path: Path, default_library: AssetLibrary
) -> None:
    before = folder_hash(living_room)
    out = tmp_path / "refined"
    args = ["refine", str(living_room), "--instruction", INSTRUCTION, "-o", str(out)]
    result = CliRunner().invoke(app, [*args, "--library", str(default_library.root), "--json"])
    assert result.exit_code == 0, result.output
    record = json.loads(result.stdout)
    assert record["ok"] and record["kept"] >= 1
    assert json.loads((out / "refine.json").read_text())["rounds"] == record["rounds"]
    checks = record["after"]["checks"]
    assert {c["what"] for c in checks if c["check"] == "relation"} == {
        "armchair next to window",
        "floor lamp next to window",
        "floor lamp next to armchair",
    }
    assert all(c["held"] for c in checks)
    ids = {o["id"] for o in json.loads((out / "scene.json").read_text())["objects"]}
    assert {"living_room.refine.armchair_0", "living_room.refine.floor_lamp_0"} <= ids
    assert folder_hash(living_room) == before
    evaluated = CliRunner().invoke(app, ["eval", str(out), "--json", str(tmp_path / "e.json")])
    assert evaluated.exit_code in (0, 1), evaluated.output
    scores = json.loads((tmp_path / "e.json").read_text())["scores"]
    assert scores["collisions"]["ok"] and scores["stability"]["ok"]


@pytest.mark.slow
def test_bad_input_exits_2_and_writes_nothing(
    living_room: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    for name in ("HOLOMJ_LLM_BASE_URL", "OPENAI_BASE_URL", "HOLOMJ_LLM_MODEL"):
        monkeypatch.delenv(name, raising=False)
    before = folder_hash(living_room)
    out = tmp_path / "new"
    base = ["refine", str(living_room), "-o", str(out)]
    for extra in (
        ["--instruction", "   "],
        ["--instruction", INSTRUCTION, "--rounds", "0"],
        ["--instruction", INSTRUCTION, "--planner", "oracle"],
        ["--instruction", INSTRUCTION, "--planner", "llm"],
        [],
    ):
        result = CliRunner().invoke(app, [*base, *extra])
        assert result.exit_code == 2, (extra, result.output)
    missing = CliRunner().invoke(app, ["refine", str(tmp_path / "nope"), "-i", INSTRUCTION])
    assert missing.exit_code == 2
    assert not out.exists()
    assert folder_hash(living_room) == before
