"""Importing many files: ids, the content-addressed cache, atomic commits, resume after kill -9."""

from __future__ import annotations

import json
import os
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
from typer.testing import CliRunner

from asset_pipeline.importer import ImportOptions
from asset_pipeline.manage import asset_id_for, coacd_params, plan_jobs, run_imports
from holomj.cli import app
from holomj.errors import InputError
from holomj.library import AssetLibrary

FAST = ImportOptions(coacd=coacd_params("fast"))
SMALL = ["objects/bm_apple", "objects/bm_d6_dice", "objects/bm_coffee_cup"]


@pytest.fixture
def small_meshes(tmp_path: Path, shared_assets: Path) -> Path:
    """A folder of three small real GLB files (and a V-HACD file that must be skipped)."""
    folder = tmp_path / "meshes"
    folder.mkdir()
    for name in SMALL:
        glb = next((shared_assets / name).glob("*.glb"))
        shutil.copy(glb, folder / glb.name)
    (folder / "apple_vhacd.obj").write_text("v 0 0 0\n")
    return folder


def test_asset_ids_from_file_names(tmp_path: Path) -> None:
    assert asset_id_for(Path("x/coffee_cup.glb")) == "coffee_cup"
    assert asset_id_for(Path("ycb_005_tomato_soup_can/textured.obj")) == "ycb_005_tomato_soup_can"
    assert asset_id_for(Path("sofa_03_1k.gltf")) == "sofa_03"
    assert asset_id_for(Path("my chair (v2).glb")) == "my_chair_v2"


def test_plan_skips_collision_meshes_and_dedups_ids(small_meshes: Path) -> None:
    jobs = plan_jobs([small_meshes])
    assert [j.path.name for j in jobs] == ["apple.glb", "coffee_cup.glb", "d6_dice.glb"]
    twice = plan_jobs([small_meshes / "apple.glb", small_meshes / "apple.glb"])
    assert [j.asset_id for j in twice] == ["apple", "apple_2"]
    with pytest.raises(InputError, match="file not found"):
        plan_jobs([small_meshes / "nope.glb"])
    with pytest.raises(InputError, match="no mesh files"):
        plan_jobs(
            [small_meshes.parent / "empty"]
            if (small_meshes.parent / "empty").mkdir() is None
            else []
        )


def test_cache_makes_reimport_instant_and_options_reprocess(
    small_meshes: Path, tmp_path: Path
) -> None:
    library = tmp_path / "lib"
    jobs = plan_jobs([small_meshes / "apple.glb"])
    from asset_pipeline.library_writer import write_library

    write_library(library, "lib", [])
    first = run_imports(jobs, library, FAST, thumbnails=False)
    assert [o.ok for o in first.outcomes] == [True] and not first.outcomes[0].cached
    again = run_imports(jobs, library, FAST, thumbnails=False)
    assert again.outcomes[0].cached
    assert again.outcomes[0].seconds < max(0.5, first.outcomes[0].seconds / 3)
    changed = ImportOptions(coacd=coacd_params("fast", threshold=0.25))
    third = run_imports(jobs, library, changed, thumbnails=False)
    assert not third.outcomes[0].cached
    asset = AssetLibrary.open(library).get("apple")
    derivation = json.loads((asset.root / "derivation.json").read_text())
    assert derivation["cache_key"] == third.outcomes[0].cache_key


def test_bad_file_fails_alone(small_meshes: Path, tmp_path: Path) -> None:
    (small_meshes / "broken.glb").write_bytes(b"glTF\x02\x00\x00\x00garbage")
    from asset_pipeline.library_writer import write_library

    library = write_library(tmp_path / "lib", "lib", [])
    jobs = plan_jobs([small_meshes / "broken.glb", small_meshes / "d6_dice.glb"])
    summary = run_imports(jobs, library, FAST, thumbnails=False)
    by_id = {o.asset_id: o for o in summary.outcomes}
    assert by_id["d6_dice"].ok
    assert not by_id["broken"].ok and "broken.glb" in by_id["broken"].error
    assert AssetLibrary.open(library).ids() == ["builtin:box", "d6_dice"]


@pytest.mark.slow
def test_killed_import_leaves_a_valid_library_and_resumes(
    small_meshes: Path, tmp_path: Path
) -> None:
    library = tmp_path / "lib"
    command = [
        sys.executable,
        "-m",
        "holomj",
        "assets",
        "import",
        str(small_meshes),
        "--library",
        str(library),
        "--preset",
        "fast",
        "--no-thumbnails",
    ]
    proc = subprocess.Popen(
        command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True
    )
    deadline = time.monotonic() + 120
    index = library / "library.json"
    while time.monotonic() < deadline:
        if index.is_file() and json.loads(index.read_text())["assets"]:
            break
        time.sleep(0.05)
    os.killpg(proc.pid, signal.SIGKILL)
    proc.wait()
    committed = AssetLibrary.open(library)  # never half an asset in the index
    assert 1 <= len(committed.ids()) - 1 <= 3
    for asset_id in committed.ids():
        assert committed.get(asset_id).meta.visual
    result = subprocess.run([*command, "--json"], capture_output=True, text=True, check=False)
    assert result.returncode == 0, result.stderr
    summary = json.loads(result.stdout)
    assert summary["succeeded"] == 3 and summary["cached"] >= 1
    assert sorted(AssetLibrary.open(library).ids()) == [
        "apple",
        "builtin:box",
        "coffee_cup",
        "d6_dice",
    ]


def test_cli_import_list_show_remove(small_meshes: Path, tmp_path: Path) -> None:
    runner = CliRunner()
    library = tmp_path / "lib"
    result = runner.invoke(
        app,
        [
            "assets",
            "import",
            str(small_meshes / "coffee_cup.glb"),
            "--library",
            str(library),
            "--preset",
            "fast",
            "--category",
            "mug",
            "--id",
            "mug_real",
            "--json",
        ],
    )
    assert result.exit_code == 0, result.output
    listed = runner.invoke(app, ["assets", "list", "--library", str(library), "--json"])
    rows = {r["id"]: r for r in json.loads(listed.stdout)}
    assert rows["mug_real"]["category"] == "mug" and 0.1 < rows["mug_real"]["mass_kg"] < 0.8
    shown = json.loads(
        runner.invoke(app, ["assets", "show", "mug_real", "--library", str(library)]).stdout
    )
    assert shown["meta"]["thumbnails"] and shown["derivation"]["decomposition"]["method"]
    assert (
        runner.invoke(app, ["assets", "remove", "mug_real", "--library", str(library)]).exit_code
        == 0
    )
    missing = runner.invoke(app, ["assets", "show", "mug_real", "--library", str(library)])
    assert missing.exit_code == 2 and "mug_real" in missing.stderr
    bad = runner.invoke(
        app, ["assets", "import", str(tmp_path / "nothing.glb"), "--library", str(library)]
    )
    assert bad.exit_code == 2 and "file not found" in bad.stderr
    preset = runner.invoke(
        app, ["assets", "import", str(small_meshes), "--library", str(library), "--preset", "ultra"]
    )
    assert preset.exit_code == 2 and "--preset" in preset.stderr
