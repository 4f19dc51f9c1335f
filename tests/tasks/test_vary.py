"""``holomj vary`` on the generated kitchen: three variants, each validated and written whole,
with other materials, lights, a replaced piece of furniture and small objects dropped again;
each keeps the tasks it still makes possible."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import numpy as np
import pytest

from asset_pipeline.default_library import ensure_default_library
from holomj.errors import InputError
from holomj.jobs.folder import open_library, read_scene
from holomj.jobs.tasks import propose_folder_tasks, read_objects, read_tasks
from holomj.jobs.vary import (
    VarySources,
    still_possible,
    task_objects,
    variant_operations,
    vary_folder,
)
from holomj.library.store import AssetLibrary
from holomj.retrieval.materials import MaterialLibrary


@pytest.fixture(scope="module")
def source(kitchen: Path, tmp_path_factory: pytest.TempPathFactory) -> Path:
    folder = tmp_path_factory.mktemp("vary") / "kitchen"
    shutil.copytree(kitchen, folder)
    propose_folder_tasks(folder, 10)
    return folder


@pytest.fixture(scope="module")
def varied(source: Path):
    return vary_folder(
        source, 3, source.parent / "variants", seed=0, library_path=ensure_default_library()
    )


def test_three_variants_validate_and_differ(source: Path, varied) -> None:
    assert varied.validated == 3
    scene = read_scene(source)
    floors = set()
    replaced = 0
    for variant in varied.variants:
        folder = Path(variant.path)
        assert folder.name == variant.name and (folder / "scene.xml").is_file()
        assert json.loads((folder / "report.json").read_text())["ok"]
        assert variant.refused == []
        kinds = [op["op"] for op in variant.operations]
        assert {"material", "light", "replace", "move"} <= set(kinds)
        report = json.loads((folder / "edit_report.json").read_text())
        for op in report["operations"]:
            if op["op"] == "replace":
                replaced += op["details"]["asset"] != op["details"]["from_asset"]
        edited = read_scene(folder)
        floors.add(edited.rooms[0].floor_material)
        assert {obj.id for obj in scene.objects} <= {obj.id for obj in edited.objects}
        print(f"{variant.name}: {variant.seconds:.1f} s, {variant.tries} draw(s)")
    assert replaced == 3
    assert len(floors) >= 2
    assert not list(Path(varied.out_dir).glob(".*"))  # no half-written folder left


def test_variants_keep_the_tasks_they_still_make_possible(source: Path, varied) -> None:
    tasks = read_tasks(source)
    for variant in varied.variants:
        kept = read_tasks(Path(variant.path))
        assert [task.id for task in kept.tasks] == variant.tasks_kept
        assert variant.tasks_kept  # tasks' objects are never replaced
        assert set(variant.tasks_kept) | set(variant.tasks_dropped) == {t.id for t in tasks.tasks}
    objects = read_objects(source)
    named = sorted(task_objects(tasks))
    gone = {**objects, "objects": [o for o in objects["objects"] if o["id"] != named[0]]}
    left = still_possible(tasks, gone)
    assert 0 < len(left.tasks) < len(tasks.tasks)
    assert all(named[0] not in task.model_dump_json() for task in left.tasks)


def test_operations_are_drawn_from_the_seed(source: Path) -> None:
    sources = VarySources(
        open_library(source), AssetLibrary.open(ensure_default_library()), MaterialLibrary.load()
    )
    scene = read_scene(source)
    first = variant_operations(scene, sources, np.random.default_rng([0, 1]))
    again = variant_operations(scene, sources, np.random.default_rng([0, 1]))
    other = variant_operations(scene, sources, np.random.default_rng([0, 2]))
    assert first == again and first != other
    assert [op for op in first if op["op"] == "move"] == [
        {"op": "move", "id": obj.id, "on": obj.support}
        for obj in scene.objects
        if obj.support is not None
    ]


def test_bad_requests_are_refused(source: Path) -> None:
    with pytest.raises(InputError):
        vary_folder(source, 0)
    with pytest.raises(InputError):
        vary_folder(source, 1, source)
