"""``holomj populate`` through typer's runner: exit codes, the rewritten folder, the report."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from holomj.cli import app
from holomj.errors import InputError
from holomj.jobs.folder import load_for_physics
from holomj.jobs.populate import parse_objects, populate_folder
from holomj.jobs.receptacle_priors import MAX_SAME, prior_requests, receptacle_weights
from holomj.library import AssetLibrary
from holomj.physics.smoke import simulate
from holomj.seeds import stage_rng
from tests.physics.spawn_helpers import receptacle_scene


@pytest.fixture
def folder(tmp_path: Path, default_library: AssetLibrary) -> Path:
    """An exported one-room scene with a static dining table ``rec``."""
    scene_json = tmp_path / "scene_in.json"
    scene = receptacle_scene("dining_table_000")
    scene_json.write_text(scene.model_dump_json(exclude_none=True))
    out = tmp_path / "out"
    result = CliRunner().invoke(
        app,
        ["compile", str(scene_json), "-o", str(out), "-q", "--library", str(default_library.root)],
    )
    assert result.exit_code == 0, result.output
    assert (out / "import_report.json").is_file()
    return out


def invoke(folder: Path, library: AssetLibrary, *args: str):
    return CliRunner().invoke(app, ["populate", str(folder), "--library", str(library.root), *args])


def test_populate_writes_back_a_loadable_scene(folder: Path, default_library: AssetLibrary):
    result = invoke(folder, default_library, "--on", "rec", "--objects", "mug:2,book,apple:2")
    assert result.exit_code == 0, result.output
    assert "placed 5/5" in result.stdout
    report = json.loads((folder / "populate_report.json").read_text())
    assert report["placed"] == 5 and report["requested"] == 5 and len(report["runs"]) == 1
    assert all(p["accepted"] for p in report["placements"])
    assert (folder / "import_report.json").is_file()  # other reports are kept
    assert not (folder / "report.json").exists()  # none to rewrite: none is made
    loaded = load_for_physics(folder, furniture="as-is")
    assert len(loaded.scene.objects) == 6
    assert simulate(loaded.model, 1.0).warnings == {}
    # a second run adds to the scene and to the report's history
    again = invoke(folder, default_library, "--on", "rec", "--objects", "cup", "--seed", "3")
    assert again.exit_code == 0, again.output
    report = json.loads((folder / "populate_report.json").read_text())
    assert len(report["runs"]) == 2
    assert len(load_for_physics(folder).scene.objects) == 7


def test_populate_json_and_partial_failure(folder: Path, default_library: AssetLibrary):
    result = invoke(
        folder, default_library, "--on", "rec", "--objects", "bottle:60", "--max-attempts", "2",
        "--json",
    )  # fmt: skip
    assert result.exit_code == 1, result.output
    report = json.loads(result.stdout)
    assert 0 < report["placed"] < 60
    failed = [p for p in report["placements"] if not p["accepted"]]
    assert failed and all(p["attempts"] <= 2 and p["reason"] for p in failed)
    loaded = load_for_physics(folder, furniture="as-is")
    assert len(loaded.scene.objects) == 1 + report["placed"]
    assert simulate(loaded.model, 1.0).warnings == {}


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--on", "tabel", "--objects", "mug"], "objects: rec"),
        (["--on", "recc", "--objects", "mug"], "did you mean: rec"),
        (["--on", "rec", "--objects", "mug:2,,:3"], "--objects"),
        (["--on", "rec", "--objects", "unicorn:2"], "unicorn"),
        (["--on", "rec", "--objects", "mug:0"], "--objects"),
    ],
)
def test_bad_input_exits_2(folder: Path, default_library: AssetLibrary, args, message) -> None:
    before = (folder / "scene.json").read_text()
    result = invoke(folder, default_library, *args)
    assert result.exit_code == 2, result.output
    assert message in result.output
    assert (folder / "scene.json").read_text() == before
    assert not (folder / "populate_report.json").exists()


@pytest.mark.parametrize("seed", ["-1", "4294967296"])
def test_a_seed_out_of_range_exits_2(folder: Path, default_library: AssetLibrary, seed: str):
    before = (folder / "scene.json").read_text()
    result = invoke(folder, default_library, "--on", "rec", "--objects", "mug", "--seed", seed)
    assert result.exit_code == 2, result.output
    assert isinstance(result.exception, SystemExit) and "Traceback" not in result.output
    errors = [line for line in result.output.splitlines() if "--seed" in line]
    assert len(errors) == 1 and "Invalid value for '--seed'" in errors[0]
    assert (folder / "scene.json").read_text() == before
    with pytest.raises(InputError, match="--seed"):
        populate_folder(folder, "rec", [("mug", 1)], seed=int(seed))


def test_not_a_scene_folder_exits_2(tmp_path: Path, default_library: AssetLibrary) -> None:
    result = invoke(tmp_path, default_library, "--on", "rec", "--objects", "mug")
    assert result.exit_code == 2
    assert "not a holomj scene folder" in result.output


def test_parse_objects() -> None:
    assert parse_objects("mug:2, book ,apple:3") == [("mug", 2), ("book", 1), ("apple", 3)]
    assert parse_objects("builtin:box") == [("builtin:box", 1)]
    for bad in ("", " , ", "mug:0", ":3", "mug:2000"):
        with pytest.raises(InputError):
            parse_objects(bad)


def test_without_objects_it_draws_what_sits_on_such_a_receptacle(
    folder: Path, default_library: AssetLibrary
) -> None:
    result = invoke(folder, default_library, "--on", "rec", "--count", "4", "--seed", "2")
    assert result.exit_code == 0, result.output
    assert "drawn from the ai2thor statistics" in result.stdout
    report = json.loads((folder / "populate_report.json").read_text())
    assert report["drawn_from"] == "ai2thor" and report["requested"] == 4
    weights, _ = receptacle_weights("dining_table")
    assert all(r["name"] in weights and r["count"] <= MAX_SAME for r in report["requests"])
    # the same seed draws the same objects
    rng = stage_rng(2, "populate", "priors")
    again, source = prior_requests("dining_table", default_library, rng, 4)
    assert source == "ai2thor"
    assert again == [(r["name"], r["count"]) for r in report["requests"]]


def test_the_priors_pool_thors_receptacle_types_and_fall_back_to_holomjs() -> None:
    counter, source = receptacle_weights("kitchen_counter")
    assert source == "ai2thor" and {"bowl", "mug", "plate"} <= set(counter)
    _, source = receptacle_weights("kitchen_island")  # no THOR receptacle maps to it
    assert source == "holomj"
    with pytest.raises(InputError, match="--on"):
        prior_requests("no_such_furniture", AssetLibrary.open(None), stage_rng(0, "x"), 2)
