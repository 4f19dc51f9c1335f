"""``holomj export`` and ``holomj.export()``: default targets under OUT/export/, every format,
JSON output, atomic replacement, and one-line errors with exit code 2 for bad input."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest
from typer.testing import CliRunner

import holomj
from holomj.cli import app
from holomj.errors import InputError
from holomj.jobs.export import default_target, export_folder
from tests.formats.gltf_reader import read_glb

runner = CliRunner()


@pytest.fixture
def folder(two_room_out: Path, tmp_path: Path) -> Path:
    """A private copy of the two-room folder (exports write into it)."""
    return Path(shutil.copytree(two_room_out, tmp_path / "two_room"))


def test_cli_exports_glb_to_the_default_target(folder: Path) -> None:
    result = runner.invoke(app, ["export", str(folder), "--format", "glb"])
    assert result.exit_code == 0, result.output
    target = folder / "export" / "scene.glb"
    assert f"exported glb: {target}" in result.stdout
    glb = read_glb(target.read_bytes())
    assert set(glb.by_kind("object")) == {"crate", "table", "cube"}
    # object facts from objects.json ride along in the extras
    extras = glb.nodes[glb.by_kind("object")["crate"]]["extras"]["holomj"]
    assert extras["category"] == "box" and extras["mass_kg"] > 0 and extras["room"] == "living"


def test_cli_json_for_every_format(folder: Path, tmp_path: Path) -> None:
    pytest.importorskip("pxr", reason="usd-core is not installed (the export extra)")
    outputs = {
        "glb": tmp_path / "a" / "b.glb",
        "usd": tmp_path / "usd" / "scene.usda",
        "urdf": tmp_path / "urdf",
    }
    for fmt, target in outputs.items():
        result = runner.invoke(app, ["export", str(folder), "-f", fmt, "-o", str(target), "--json"])
        assert result.exit_code == 0, result.output
        record = json.loads(result.stdout)
        assert record["format"] == fmt and record["target"] == str(target)
        assert record["bytes"] > 0 and record["timings_s"]["total"] > 0
    assert (tmp_path / "usd" / "scene.usda").read_text().startswith("#usda")
    urdf = json.loads(
        runner.invoke(
            app, ["export", str(folder), "-f", "urdf", "-o", str(tmp_path / "u2"), "--json"]
        ).stdout
    )
    assert sorted(a["id"] for a in urdf["details"]["assets"]) == ["front_door", "kitchen_door"]
    for relative in urdf["files"]:
        assert (tmp_path / "u2" / relative).is_file()


def test_api_export(folder: Path) -> None:
    result = holomj.export(folder, "glb", colliders=True)
    assert Path(result.target) == default_target(folder, "glb")
    assert read_glb(Path(result.target).read_bytes()).by_kind("colliders")


def test_a_new_export_replaces_the_old_atomically(folder: Path) -> None:
    export_folder(folder, "urdf")
    stale = folder / "export" / "urdf" / "stale.txt"
    stale.write_text("old")
    export_folder(folder, "urdf")
    assert not stale.exists()  # the folder was replaced as a whole
    target = default_target(folder, "glb")
    export_folder(folder, "glb")
    first = target.read_bytes()
    export_folder(folder, "glb")
    assert target.read_bytes() == first
    leftovers = [p.name for p in target.parent.iterdir() if p.name.startswith(".")]
    assert leftovers == []


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--format", "obj"], "--format: unknown export format 'obj' (choose glb, usd or urdf)"),
        (["--format", "glb", "-o", "x.gltf"], "a GLB export must be a file ending in .glb"),
        (["--format", "usd", "-o", "x.fbx"], "a USD export must be a file ending in .usdz"),
        (["--format", "usd", "--colliders"], "--colliders applies to --format glb only"),
    ],
)
def test_bad_input_is_one_line_exit_2(folder: Path, args: list[str], message: str) -> None:
    result = runner.invoke(app, ["export", str(folder), *args])
    assert result.exit_code == 2
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and message in lines[0]
    assert not (folder / "export").exists()


def test_not_a_scene_folder_is_exit_2(tmp_path: Path) -> None:
    result = runner.invoke(app, ["export", str(tmp_path), "--format", "glb"])
    assert result.exit_code == 2
    assert "not a holomj scene folder" in result.stderr
    with pytest.raises(InputError, match="not a holomj scene folder"):
        holomj.export(tmp_path / "missing")


def test_urdf_target_that_is_a_file_is_bad_input(folder: Path, tmp_path: Path) -> None:
    target = tmp_path / "file.txt"
    target.write_text("keep me")
    with pytest.raises(InputError, match="a URDF export is a folder"):
        export_folder(folder, "urdf", target)
    assert target.read_text() == "keep me"


def test_missing_usd_core_names_the_extra(folder: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    import builtins

    real_import = builtins.__import__

    def no_pxr(name, *args, **kwargs):
        if name == "pxr" or name.startswith("pxr."):
            raise ImportError("No module named 'pxr'")
        return real_import(name, *args, **kwargs)

    monkeypatch.setattr(builtins, "__import__", no_pxr)
    with pytest.raises(InputError, match=r"holomj\[export\]"):
        export_folder(folder, "usd")
    assert not (folder / "export").exists()
