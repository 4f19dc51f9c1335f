"""``holomj tasks OUT``: feasible tasks proposed for a generated kitchen, written to tasks.json,
each one checkable on the scene; bad input gives one line and exit 2."""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

import mujoco

from holomj.jobs.tasks import propose_folder_tasks, read_tasks
from holomj.tasks.predicates import success_check
from holomj.tasks.propose import graspable


def _holomj(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "holomj", *args], capture_output=True, text=True, timeout=300
    )


def test_the_kitchen_gets_feasible_tasks_of_every_kind(kitchen: Path, tmp_path: Path) -> None:
    folder = tmp_path / "kitchen"
    shutil.copytree(kitchen, folder)
    tasks = propose_folder_tasks(folder, limit=40)
    assert len(tasks.tasks) >= 5
    kinds = {t.kind for t in tasks.tasks}
    assert {"open", "close", "pick_place", "navigate"} <= kinds, kinds
    assert read_tasks(folder) == tasks
    record = json.loads((folder / "objects.json").read_text())
    objects = {o["id"]: o for o in record["objects"]}
    model = mujoco.MjModel.from_xml_path(str(folder / "scene.xml"))
    for task in tasks.tasks:
        success_check(task, model, record)  # every id it names is in the scene
        if task.kind == "pick_place":
            assert graspable(objects[task.goal.object])
            assert task.goal.receptacle != objects[task.goal.object]["support"]
    assert len(propose_folder_tasks(folder, limit=3, write=False).tasks) == 3
    assert len({t.kind for t in propose_folder_tasks(folder, limit=3, write=False).tasks}) == 3


def test_the_command_writes_tasks_json_and_refuses_bad_input(kitchen: Path, tmp_path: Path) -> None:
    folder = tmp_path / "kitchen"
    shutil.copytree(kitchen, folder)
    run = _holomj("tasks", str(folder), "-n", "6", "--json")
    assert run.returncode == 0, run.stderr
    assert len(json.loads(run.stdout)["tasks"]) == 6
    assert read_tasks(folder / "tasks.json").model_dump(mode="json") == json.loads(run.stdout)
    for args in ((str(tmp_path / "missing"),), (str(folder), "-n", "0")):
        bad = _holomj("tasks", *args)
        assert bad.returncode == 2, bad
        assert bad.stderr.startswith("error: ") and bad.stderr.count("\n") == 1, bad.stderr
    (folder / "objects.json").unlink()
    bad = _holomj("tasks", str(folder))
    assert bad.returncode == 2 and "objects.json" in bad.stderr, bad.stderr
