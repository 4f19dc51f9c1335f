"""The scripted close policy (the project's IK onto the opened part's handle, a grip, a
Cartesian push back along its path) closes every drawer of the generated kitchen, and the task's
predicate says so; a do-nothing rollout of the same tasks is never judged successful."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from holomj import envs
from holomj.envs.scripted import close_part
from holomj.errors import InputError
from holomj.jobs.tasks import propose_folder_tasks
from holomj.spec.tasks import Task


def _drawer_closings(kitchen: Path) -> list[Task]:
    tasks = propose_folder_tasks(kitchen, limit=100, write=False).tasks
    chosen = [t for t in tasks if t.kind == "close" and "drawer" in getattr(t, "joint", "")]
    assert chosen, [t.id for t in tasks]
    return chosen


def test_the_scripted_policy_closes_the_drawers(kitchen: Path) -> None:
    results = {}
    for task in _drawer_closings(kitchen):
        env = envs.make(kitchen, task, max_episode_steps=600)
        results[task.id] = close_part(env)
        closed = env.condition.openness(env.data)  # type: ignore[attr-defined]
        assert results[task.id].success == (closed <= task.fraction), task.id  # type: ignore[attr-defined]
    assert all(r.success for r in results.values()), results


def test_doing_nothing_leaves_the_drawers_open(kitchen: Path) -> None:
    for task in _drawer_closings(kitchen):
        env = envs.make(kitchen, task, max_episode_steps=300)
        env.reset(seed=0)
        assert env.condition.openness(env.data) > task.fraction  # type: ignore[attr-defined]
        still = np.zeros(env.action_space.shape, dtype=np.float32)
        for _ in range(300):
            _, _, terminated, truncated, info = env.step(still)
            assert not terminated and not info["success"], task.id
            if truncated:
                break


def test_it_scripts_close_tasks_only(kitchen: Path) -> None:
    tasks = propose_folder_tasks(kitchen, limit=100, write=False).tasks
    opening = next(t for t in tasks if t.kind == "open")
    with pytest.raises(InputError, match="not a close task"):
        close_part(envs.make(kitchen, opening))
