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

from asset_pipeline.import_plan import asset_id_for, plan_jobs
from asset_pipeline.importer import ImportOptions
from asset_pipeline.manage import coacd_params, run_imports
from holomj.cli import app
from holomj.errors import InputError
from holomj.library import AssetLibrary
from tests.asset_pipeline.import_helpers import box_obj

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
    # The nearest meaningful path component: scanner and dataset folders are skipped.
    assert asset_id_for(Path("ycb/002_master_chef_can/google_16k/textured.obj")) == (
        "002_master_chef_can"
    )
    assert asset_id_for(Path("ycb/002_master_chef_can/tsdf/textured.obj")) == (
        "002_master_chef_can"
    )
    assert asset_id_for(Path("ycb/024_bowl/poisson/textured.obj")) == "024_bowl"
    assert asset_id_for(Path("gso/Blue_Mug/meshes/model.obj")) == "Blue_Mug"
    assert asset_id_for(Path("shapenet/03001627/1a6f615e/models/model_normalized.obj")) == (
        "1a6f615e"
    )
    assert asset_id_for(Path("kitchen/toaster/source/untitled.glb")) == "toaster"
    assert asset_id_for(Path("/textured.obj")) == "textured"  # nothing better on the path


def _ycb_layout(root: Path, shared: Path) -> list[Path]:
    """Copies of the shared YCB meshes in YCB's own layout: <item>/google_16k/textured.obj."""
    found = []
    for folder in sorted((shared / "objects").glob("ycb_*")):
        target = root / "ycb" / folder.name.removeprefix("ycb_") / "google_16k"
        target.mkdir(parents=True)
        for name in ("textured.obj", "textured.mtl", "texture_map.png"):
            if (folder / name).is_file():
                shutil.copy(folder / name, target / name)
        found.append(target / "textured.obj")
    return found


def test_ycb_layout_gives_one_meaningful_id_per_item(tmp_path: Path, shared_assets: Path) -> None:
    files = _ycb_layout(tmp_path, shared_assets)
    assert len(files) >= 5
    jobs = plan_jobs([tmp_path / "ycb"])
    ids = [j.asset_id for j in jobs]
    assert len(set(ids)) == len(ids) == len(files)
    assert "google_16k" not in ids and "textured" not in ids
    assert "005_tomato_soup_can" in ids and "024_bowl" in ids
    assert all(j.id_note is None for j in jobs)
    # Two items whose folders carry the same name still never share an id.
    again = tmp_path / "more" / "005_tomato_soup_can" / "google_16k"
    again.mkdir(parents=True)
    shutil.copy(files[0], again / "textured.obj")
    clash = plan_jobs([tmp_path / "ycb", tmp_path / "more"])
    by_path = {j.path: j for j in clash}
    extra = by_path[again / "textured.obj"]
    assert extra.asset_id == "005_tomato_soup_can-2"
    assert "taken by another file of this import" in extra.id_note


def test_ids_never_silently_replace_another_files_asset(
    tmp_path: Path, shared_assets: Path
) -> None:
    from asset_pipeline.import_plan import existing_assets
    from asset_pipeline.library_writer import write_library

    library = write_library(tmp_path / "lib", "lib", [])
    first = tmp_path / "shop_a" / "d6_dice" / "google_16k" / "model.glb"
    first.parent.mkdir(parents=True)
    shutil.copy(shared_assets / "objects/bm_d6_dice/d6_dice.glb", first)
    other = tmp_path / "shop_b" / "d6_dice" / "meshes" / "textured.obj"
    other.parent.mkdir(parents=True)
    other.write_text(box_obj(0.02, 0.02, 0.02))
    planned = plan_jobs([first], None, existing_assets(library))
    summary = run_imports(planned, library, FAST, thumbnails=False)
    assert [o.asset_id for o in summary.outcomes] == ["d6_dice"]
    # Another file with the same name: a suffix, and a note saying which and why.
    jobs = plan_jobs([other], None, existing_assets(library))
    assert jobs[0].asset_id == "d6_dice-2"
    assert "'d6_dice' is taken in the library (from " in jobs[0].id_note
    assert str(first) in jobs[0].id_note
    summary = run_imports(jobs, library, FAST, thumbnails=False)
    assert summary.outcomes[0].ok and summary.outcomes[0].id_note == jobs[0].id_note
    assert AssetLibrary.open(library).ids() == ["builtin:box", "d6_dice", "d6_dice-2"]
    # The same file again (same bytes, here at another path) updates its own asset.
    copy = tmp_path / "elsewhere" / "d6_dice.glb"
    copy.parent.mkdir()
    shutil.copy(first, copy)
    same = plan_jobs([copy], None, existing_assets(library))
    assert same[0].asset_id == "d6_dice" and "same file" in same[0].id_note
    again = plan_jobs([other], None, existing_assets(library))
    assert again[0].asset_id == "d6_dice-2"
    # An explicit id held by another file's asset fails, naming the asset and the fix.
    with pytest.raises(InputError, match="already in the library") as info:
        plan_jobs([other], "d6_dice", existing_assets(library))
    assert "holomj assets remove d6_dice" in str(info.value)
    assert plan_jobs([first], "d6_dice", existing_assets(library))[0].asset_id == "d6_dice"


def test_cli_import_reports_a_renamed_id(tmp_path: Path) -> None:
    library = tmp_path / "lib"
    for shop in ("a", "b"):
        mesh = tmp_path / shop / "crate" / "google_16k" / "textured.obj"
        mesh.parent.mkdir(parents=True)
        mesh.write_text(box_obj(0.2 if shop == "a" else 0.3, 0.1, 0.1))
    runner = CliRunner()
    args = ["assets", "import", "--library", str(library), "--no-thumbnails", "--preset", "fast"]
    first = runner.invoke(app, [*args, str(tmp_path / "a")])
    assert first.exit_code == 0, first.output
    second = runner.invoke(app, [*args, "--json", str(tmp_path / "b")])
    assert second.exit_code == 0, second.output
    outcome = json.loads(second.output)["outcomes"][0]
    assert outcome["asset_id"] == "crate-2" and "imported as 'crate-2'" in outcome["id_note"]
    third = runner.invoke(app, [*args, "--id", "crate", str(tmp_path / "b")])
    assert third.exit_code == 2 and "already in the library" in third.output
    assert AssetLibrary.open(library).ids() == ["builtin:box", "crate", "crate-2"]


def test_plan_skips_collision_meshes_and_dedups_ids(small_meshes: Path) -> None:
    jobs = plan_jobs([small_meshes])
    assert [j.path.name for j in jobs] == ["apple.glb", "coffee_cup.glb", "d6_dice.glb"]
    twice = plan_jobs([small_meshes / "apple.glb", small_meshes / "apple.glb"])
    assert [j.asset_id for j in twice] == ["apple", "apple-2"]
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
