"""Tasks as data: what the schema accepts and refuses, and ``holomj schema task``."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest
from pydantic import ValidationError

from holomj.spec.schema import json_schema
from holomj.spec.tasks import NavigateTask, PlaceGoal, RearrangeTask, TaskSet


def test_a_task_set_round_trips_through_json() -> None:
    data = {
        "scene": "kitchen",
        "tasks": [
            {"kind": "open", "id": "a", "object": "fridge", "joint": "fridge/door_0_hinge"},
            {"kind": "pick_place", "id": "b", "goal": {"object": "mug", "receptacle": "sink"}},
            {"kind": "navigate", "id": "c", "room": "kitchen"},
        ],
    }
    tasks = TaskSet.model_validate(data)
    assert [t.kind for t in tasks.tasks] == ["open", "pick_place", "navigate"]
    assert tasks.tasks[0].fraction == 0.5 and tasks.tasks[0].hold_s == 1.0
    assert TaskSet.model_validate_json(tasks.model_dump_json()) == tasks


def test_bad_tasks_are_refused() -> None:
    with pytest.raises(ValidationError, match="exactly one"):
        NavigateTask(id="n", room="kitchen", object="fridge")
    with pytest.raises(ValidationError, match="exactly one"):
        NavigateTask(id="n")
    goal = PlaceGoal(object="mug", receptacle="sink")
    with pytest.raises(ValidationError, match="each object once"):
        RearrangeTask(id="r", goals=[goal, goal])
    with pytest.raises(ValidationError):
        RearrangeTask(id="r", goals=[goal])  # one goal is a pick-and-place
    nav = {"kind": "navigate", "id": "same", "room": "kitchen"}
    with pytest.raises(ValidationError, match="unique"):
        TaskSet.model_validate({"scene": "s", "tasks": [nav, nav]})
    with pytest.raises(ValidationError):
        TaskSet.model_validate({"scene": "s", "tasks": [{**nav, "kind": "fly"}]})
    with pytest.raises(ValidationError):
        TaskSet.model_validate(
            {
                "scene": "s",
                "tasks": [
                    {"kind": "open", "id": "o", "object": "f", "joint": "j", "fraction": 1.5}
                ],
            }
        )


def test_schema_command_prints_the_task_schema() -> None:
    schema = json_schema("task")
    assert schema["$comment"] == "holomj task format, schema_version 1.0"
    assert {"NavigateTask", "ArticulationTask", "PickPlaceTask", "RearrangeTask"} <= set(
        schema["$defs"]
    )
    run = subprocess.run(
        [sys.executable, "-m", "holomj", "schema", "task"], capture_output=True, text=True
    )
    assert run.returncode == 0, run.stderr
    assert json.loads(run.stdout)["$comment"] == schema["$comment"]
