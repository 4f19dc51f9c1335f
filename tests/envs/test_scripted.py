"""The scripted policy (the project's IK onto the handle, a grip, a Cartesian pull) opens every
drawer of the generated kitchen and its fridge's lower door, and the task's predicate says so."""

from __future__ import annotations

from pathlib import Path

import pytest

from holomj import envs
from holomj.envs.scripted import open_part
from holomj.errors import InputError
from holomj.jobs.tasks import propose_folder_tasks


def test_the_scripted_policy_opens_the_drawers_and_the_fridge(kitchen: Path) -> None:
    tasks = propose_folder_tasks(kitchen, limit=100, write=False).tasks
    chosen = [t for t in tasks if t.kind == "open" and "drawer" in getattr(t, "joint", "")]
    assert chosen, [t.id for t in tasks]
    chosen += [t for t in tasks if t.kind == "open" and t.id.endswith("fridge_0-door_0_hinge")]
    results = {}
    for task in chosen:
        env = envs.make(kitchen, task, max_episode_steps=600)
        results[task.id] = open_part(env)
        opened = env.condition.openness(env.data)  # type: ignore[attr-defined]
        assert results[task.id].success == (opened >= task.fraction), task.id
    assert all(r.success for r in results.values()), results


def test_it_scripts_open_tasks_of_parts_with_handles(kitchen: Path) -> None:
    tasks = propose_folder_tasks(kitchen, limit=100, write=False).tasks
    place = next(t for t in tasks if t.kind == "pick_place")
    with pytest.raises(InputError, match="not an open task"):
        open_part(envs.make(kitchen, place))
