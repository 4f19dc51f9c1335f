"""The Gymnasium environment on a generated kitchen: Gymnasium's checker passes, reset restores
the validated scene without recompiling, the reward is the success predicate, and neither doing
nothing nor random actions are ever judged successful."""

from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env

from holomj import envs
from holomj.errors import InputError
from holomj.jobs.tasks import propose_folder_tasks
from holomj.spec.tasks import ArticulationTask


@pytest.fixture(scope="module")
def tasks(kitchen: Path):
    return propose_folder_tasks(kitchen, limit=40, write=False).tasks


def _drawer_task(tasks, kind: str = "open") -> ArticulationTask:
    return next(
        t
        for t in tasks
        if isinstance(t, ArticulationTask) and t.kind == kind and "drawer" in t.joint
    )


def test_the_environment_passes_gymnasiums_checker(kitchen: Path, tasks) -> None:
    for task in (_drawer_task(tasks), next(t for t in tasks if t.kind == "pick_place")):
        env = envs.make(kitchen, task, robot="jaco")
        check_env(env, skip_render_check=True)
        env.close()


def test_reset_restores_the_scene_and_a_close_task_starts_open(kitchen: Path, tasks) -> None:
    task = _drawer_task(tasks, "close")
    env = envs.make(kitchen, task.model_dump(), shaping=1.0)
    model = env.model
    first, _ = env.reset(seed=0)
    opened = env.condition.openness(env.data)  # type: ignore[attr-defined]
    assert opened == pytest.approx(task.start)
    rng = np.random.default_rng(0)
    for _ in range(20):
        env.step(rng.uniform(-1.0, 1.0, env.action_space.shape))
    assert not np.allclose(env.data.qpos, model.qpos0)
    again, _ = env.reset(seed=1)
    assert env.model is model  # the compiled model is kept
    for key in first:
        np.testing.assert_allclose(again[key], first[key])
    _, reward, *_ = env.step(np.zeros(env.action_space.shape))
    assert reward < 0.0  # shaped: minus the distance to success


def test_the_reward_is_the_predicate(kitchen: Path, tasks) -> None:
    task = _drawer_task(tasks)
    env = envs.make(kitchen, task, max_episode_steps=200)
    env.reset(seed=0)
    adr = env.condition.qpos_adr  # type: ignore[attr-defined]
    env.data.qpos[adr] = env.condition.open  # type: ignore[attr-defined]  # pulled fully out
    total, terminated = 0.0, False
    for _ in range(200):
        _, reward, terminated, truncated, info = env.step(np.zeros(env.action_space.shape))
        total += reward
        if terminated or truncated:
            break
    assert terminated and info["success"] and total == 1.0


def test_doing_nothing_and_random_actions_never_succeed(kitchen: Path, tasks) -> None:
    chosen = [_drawer_task(tasks), _drawer_task(tasks, "close")]
    chosen += [t for t in tasks if t.kind in ("pick_place", "rearrange")][:2]
    rng = np.random.default_rng(0)
    for task in chosen:
        env = envs.make(kitchen, task, max_episode_steps=60)
        for episode in range(2):
            env.reset(seed=episode)
            random = episode == 1
            truncated = False
            while not truncated:
                action = (
                    rng.uniform(-1, 1, env.action_space.shape)
                    if random
                    else np.zeros(env.action_space.shape)
                )
                _, reward, terminated, truncated, info = env.step(action)
                assert not terminated and not info["success"] and reward == 0.0, task.id


def test_bad_input_is_refused_with_the_reason(kitchen: Path, tmp_path: Path) -> None:
    with pytest.raises(InputError, match="not 'panda'"):
        envs.make(kitchen, {"kind": "navigate", "id": "n", "room": "kitchen"}, robot="panda")
    with pytest.raises(InputError, match="run 'holomj tasks"):
        envs.make(kitchen, "nope")
    folder = tmp_path / "kitchen"
    shutil.copytree(kitchen, folder)
    tasks = propose_folder_tasks(folder, limit=4)
    with pytest.raises(InputError, match="no task 'nope'"):
        envs.make(folder, "nope")
    assert envs.make(folder, tasks.tasks[0].id).task == tasks.tasks[0]
    with pytest.raises(InputError, match="not a holomj scene folder"):
        envs.make(tmp_path, {"kind": "navigate", "id": "n", "room": "kitchen"})


def test_a_reset_can_move_the_small_objects_from_its_seed(kitchen: Path, tasks) -> None:
    task = next(t for t in tasks if t.kind == "pick_place")
    env = envs.make(kitchen, task, redrop_m=0.05)
    assert env.droppable, "the kitchen has small objects standing in the open"
    adr = [d.qpos_adr for d in env.droppable]

    def poses(seed: int) -> np.ndarray:
        env.reset(seed=seed)
        return np.array([env.data.qpos[a : a + 7] for a in adr])

    first, again, other = poses(3), poses(3), poses(4)
    np.testing.assert_allclose(first, again)
    assert not np.allclose(first, other)
    home = np.array([env.model.qpos0[a : a + 7] for a in adr])
    assert np.abs(first[:, :2] - home[:, :2]).max() <= 0.05 + 1e-9
    for _ in range(50):  # they drop back and stay: nothing is judged placed by moving them
        _, reward, terminated, _, _ = env.step(np.zeros(env.action_space.shape))
        assert not terminated and reward == 0.0
    model = env.model
    dofs = [int(model.jnt_dofadr[list(model.jnt_qposadr).index(a)]) for a in adr]
    speeds = [float(np.abs(env.data.qvel[d : d + 3]).max()) for d in dofs]
    assert max(speeds) < 0.05, speeds
