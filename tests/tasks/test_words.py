"""Tasks named in words, read against the generated kitchen: each clause one task, checkable on
the scene; infeasible or unknown asks refused with the clause and the reason."""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

import mujoco
import pytest

from holomj.errors import InputError
from holomj.jobs.tasks import read_tasks
from holomj.tasks.predicates import success_check
from holomj.tasks.words import tasks_from_words


@pytest.fixture(scope="module")
def objects(kitchen: Path) -> dict:
    return json.loads((kitchen / "objects.json").read_text())


def test_each_clause_is_one_task_on_the_scene(kitchen: Path, objects: dict) -> None:
    text = (
        "open the fridge, then put the mug in the sink; close the drawer unit and go to the stove"
    )
    tasks = tasks_from_words(text, objects).tasks
    assert [t.kind for t in tasks] == ["open", "pick_place", "close", "navigate"]
    categories = {o["id"]: o["category"] for o in objects["objects"]}
    assert categories[tasks[0].object] == "fridge"
    assert categories[tasks[1].goal.object] == "mug"
    assert categories[tasks[1].goal.receptacle] == "sink_counter"
    assert categories[tasks[2].object] == "drawer_unit" and tasks[2].start is not None
    assert categories[tasks[3].object] == "stove"
    model = mujoco.MjModel.from_xml_path(str(kitchen / "scene.xml"))
    for task in tasks:
        success_check(task, model, objects)
    room = objects["rooms"][0]
    assert tasks_from_words(f"go to the {room['type']}", objects).tasks[0].room == room["id"]


@pytest.mark.parametrize(
    ("text", "reason"),
    [
        ("put the fridge on the counter", "too big, too heavy or fixed"),
        ("put the mug on the apple", "no surface"),
        ("open the mug", "no door, drawer or lid"),
        ("open the piano", "no piano.*name one of"),
        ("dance", "not a task"),
        (" , ", "no task"),
    ],
)
def test_infeasible_asks_are_refused_with_the_reason(objects: dict, text: str, reason: str) -> None:
    with pytest.raises(InputError, match=reason):
        tasks_from_words(text, objects)


def test_the_command_reads_prompts(kitchen: Path, tmp_path: Path) -> None:
    folder = tmp_path / "kitchen"
    shutil.copytree(kitchen, folder)
    command = [sys.executable, "-m", "holomj", "tasks", str(folder), "--prompt"]
    run = subprocess.run([*command, "open the fridge"], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    assert [t.kind for t in read_tasks(folder).tasks] == ["open"]
    bad = subprocess.run([*command, "open the piano"], capture_output=True, text=True)
    assert bad.returncode == 2 and bad.stderr.count("\n") == 1 and "piano" in bad.stderr
