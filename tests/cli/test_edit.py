"""``holomj edit`` and ``holomj schema edit`` through typer's runner: exit codes, the written
folder and report, and a malformed operations file leaving the folder untouched."""

from __future__ import annotations

import hashlib
import json
import shutil
from pathlib import Path

import pytest
from typer.testing import CliRunner

import holomj
from holomj.cli import app
from holomj.library.store import AssetLibrary


@pytest.fixture(scope="module")
def living_room(tmp_path_factory: pytest.TempPathFactory, default_library: AssetLibrary) -> Path:
    """A generated living room (tests that edit in place work on a copy)."""
    out = tmp_path_factory.mktemp("cli_edit") / "living_room"
    holomj.generate(
        "a living room with a sofa and a coffee table",
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


def invoke(library: AssetLibrary, *args: str):
    return CliRunner().invoke(app, ["edit", *args, "--library", str(library.root)])


def write_ops(path: Path, ops) -> Path:
    path.write_text(json.dumps(ops) if not isinstance(ops, str) else ops)
    return path


def test_schema_edit_prints_the_operations_format():
    result = CliRunner().invoke(app, ["schema", "edit"])
    assert result.exit_code == 0, result.output
    schema = json.loads(result.stdout)
    assert schema["type"] == "array"
    assert {"AddOp", "AddOnOp", "RemoveOp", "MoveOp", "ReplaceOp", "MaterialOp", "LightOp"} <= set(
        schema["$defs"]
    )
    unknown = CliRunner().invoke(app, ["schema", "nope"])
    assert unknown.exit_code == 2 and "edit" in unknown.stderr


@pytest.mark.parametrize(
    ("text", "words"),
    [
        ("not json", "invalid JSON"),
        ('{"op": "remove", "id": "x"}', "expected a JSON list"),
        ('[{"op": "teleport", "id": "x"}]', "does not match any of the expected tags"),
        ('[{"op": "remove", "id": "x", "exec": "rm -rf /"}]', "unknown field"),
        ('[{"op": "add", "description": "x", "size": [NaN, 1, 1]}]', "non-finite"),
        ('[{"op": "move", "id": "x"}]', "give position"),
    ],
)
def test_a_malformed_file_exits_2_and_leaves_the_folder_untouched(
    living_room, tmp_path, default_library, text, words
):
    before = folder_hash(living_room)
    ops = write_ops(tmp_path / "ops.json", text)
    result = invoke(default_library, str(living_room), str(ops))
    assert result.exit_code == 2, result.output
    line = result.stderr.strip()
    assert line.count("\n") == 0 and str(ops) in line and words in line, line
    assert folder_hash(living_room) == before


def test_edit_into_a_new_folder_with_a_json_report(living_room, tmp_path, default_library):
    before = folder_hash(living_room)
    ops = write_ops(
        tmp_path / "ops.json",
        [
            {
                "op": "material",
                "room": "living_room",
                "surface": "walls",
                "material": "white paint",
            },
            {"op": "remove", "id": "living_room.coffee_table_0"},
        ],
    )
    new, report_path = tmp_path / "new", tmp_path / "r" / "edit.json"
    result = invoke(
        default_library, str(living_room), str(ops), "-o", str(new), "--json", str(report_path)
    )
    assert result.exit_code == 0, result.output
    assert "2/2 operation(s) applied" in result.stdout and "validation ok" in result.stdout
    report = json.loads(report_path.read_text())
    assert report == json.loads((new / "edit_report.json").read_text())
    assert report["applied"] == 2 and report["refused"] == 0 and report["validation"]["ok"]
    assert "living_room.coffee_table_0" in report["removed"]
    assert json.loads((new / "report.json").read_text())["ok"]
    assert (new / "plan.json").is_file()  # the folder's other files come along
    assert folder_hash(living_room) == before  # the source is not touched
    again = invoke(default_library, str(living_room), str(ops), "-o", str(new))
    assert again.exit_code == 2 and "exists" in again.stderr


def test_edit_in_place_with_a_refused_operation_exits_1(living_room, tmp_path, default_library):
    copy = tmp_path / "copy"
    shutil.copytree(living_room, copy)
    ops = write_ops(
        tmp_path / "ops.json",
        [
            {"op": "add", "description": "a floor lamp", "relations": [{"kind": "corner"}]},
            {"op": "remove", "id": "living_room.no_such_thing"},
        ],
    )
    result = invoke(default_library, str(copy), str(ops), "--json", "-")
    assert result.exit_code == 1, result.output
    report = json.loads(result.stdout)  # --json -: the report alone on stdout
    assert [o["status"] for o in report["operations"]] == ["applied", "refused"]
    assert "unknown object id" in report["operations"][1]["reason"]
    scene = json.loads((copy / "scene.json").read_text())
    assert report["added"][0] in {o["id"] for o in scene["objects"]}
    assert report["validation"]["ok"] and (copy / "edit_report.json").is_file()


def test_edit_needs_a_scene_folder(tmp_path, default_library):
    ops = write_ops(tmp_path / "ops.json", [{"op": "remove", "id": "x"}])
    result = invoke(default_library, str(tmp_path), str(ops))
    assert result.exit_code == 2 and "not a holomj scene folder" in result.stderr
