"""The scripted policy (the project's IK onto the handle, a grip, a Cartesian pull) opens every
drawer of the generated kitchen, and the task's predicate says so."""

from __future__ import annotations

from pathlib import Path

import pytest

from holomj import envs
from holomj.envs.scripted import open_drawer
from holomj.errors import InputError
from holomj.jobs.tasks import propose_folder_tasks


def test_the_scripted_policy_opens_the_drawers(kitchen: Path) -> None:
    tasks = propose_folder_tasks(kitchen, limit=100, write=False).tasks
    drawers = [t for t in tasks if t.kind == "open" and "drawer" in getattr(t, "joint", "")]
    assert drawers, [t.id for t in tasks]
    results = {}
    for task in drawers:
        env = envs.make(kitchen, task, max_episode_steps=600)
        results[task.id] = open_drawer(env)
        opened = env.condition.openness(env.data)  # type: ignore[attr-defined]
        assert results[task.id].success == (opened >= task.fraction), task.id
    assert all(r.success for r in results.values()), results


def test_it_scripts_drawers_only(kitchen: Path) -> None:
    tasks = propose_folder_tasks(kitchen, limit=100, write=False).tasks
    door = next(t for t in tasks if t.kind == "open" and "hinge" in getattr(t, "joint", ""))
    with pytest.raises(InputError, match="not a drawer"):
        open_drawer(envs.make(kitchen, door))
    place = next(t for t in tasks if t.kind == "pick_place")
    with pytest.raises(InputError, match="not an open task"):
        open_drawer(envs.make(kitchen, place))
