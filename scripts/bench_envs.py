"""Benchmark: the Gymnasium environment on a scene folder (no rendering).

For a scene folder with a robot (``holomj generate ... --robot jaco``) it proposes tasks
(``holomj tasks``' proposer, nothing written) and, for one task of each kind it finds, measures:
the time to make the environment (load ``scene.xml``, compile, build the task's predicate), the
median reset time over ``--resets`` resets, and environment steps per second with random actions
over ``--steps`` steps (each step ``frame_skip`` physics steps plus the predicate), beside the
raw ``mj_step`` rate of the same model; then ``--episodes`` episodes of ``--episode-steps``
steps per task kind, half doing nothing and half random, counting false successes. With
``--script`` it also runs the scripted policies on every open and every close task (drawers and
doors: tries, successes, steps). Writes JSON::

    python scripts/bench_envs.py OUT --out bench_results/envs.json [--steps 2000] [--script]
"""

from __future__ import annotations

import argparse
import json
import platform
import statistics
import sys
import time
from pathlib import Path

import mujoco
import numpy as np

from holomj import envs
from holomj.envs.scripted import close_part, open_part
from holomj.jobs.tasks import propose_folder_tasks
from holomj.spec.tasks import ArticulationTask, Task


def bench_task(folder: Path, task: Task, steps: int, resets: int) -> dict:
    """Make, reset and step timings of one task's environment."""
    start = time.perf_counter()
    env = envs.make(folder, task)
    made = time.perf_counter() - start
    times = []
    for seed in range(resets):
        start = time.perf_counter()
        env.reset(seed=seed)
        times.append(time.perf_counter() - start)
    rng = np.random.default_rng(0)
    env.reset(seed=0)
    successes = 0
    start = time.perf_counter()
    for _ in range(steps):
        _, _, terminated, truncated, _ = env.step(rng.uniform(-1, 1, env.action_space.shape))
        successes += int(terminated)
        if terminated or truncated:
            env.reset()
    elapsed = time.perf_counter() - start
    return {
        "task": task.id,
        "kind": task.kind,
        "make_s": round(made, 4),
        "reset_ms_median": round(1000 * statistics.median(times), 4),
        "steps_per_s": round(steps / elapsed, 1),
        "physics_steps_per_s": round(steps * env.frame_skip / elapsed, 1),
        "random_successes": successes,
    }


def false_successes(folder: Path, task: Task, episodes: int, steps: int) -> dict:
    """Episodes judged successful with no action (the first half) or random actions."""
    env = envs.make(folder, task, max_episode_steps=steps)
    rng = np.random.default_rng(0)
    judged = {"nothing": 0, "random": 0}
    for episode in range(episodes):
        policy = "nothing" if episode < episodes // 2 else "random"
        env.reset(seed=episode)
        for _ in range(steps):
            action = np.zeros(env.action_space.shape)
            if policy == "random":
                action = rng.uniform(-1, 1, env.action_space.shape)
            _, _, terminated, truncated, _ = env.step(action)
            if terminated or truncated:
                judged[policy] += int(terminated)
                break
    return {"task": task.id, "episodes": episodes, "steps": steps, "successes": judged}


def raw_physics_rate(folder: Path, steps: int) -> float:
    """``mj_step`` per second on the folder's model, nothing else."""
    model = mujoco.MjModel.from_xml_path(str(folder / "scene.xml"))
    data = mujoco.MjData(model)
    start = time.perf_counter()
    for _ in range(steps):
        mujoco.mj_step(model, data)
    return steps / (time.perf_counter() - start)


def scripted(folder: Path, tasks: list[Task], kind: str = "open") -> dict:
    """The scripted policy on every ``kind`` (open or close) task (drawers and doors)."""
    policy = open_part if kind == "open" else close_part
    results = []
    for task in tasks:
        if not (isinstance(task, ArticulationTask) and task.kind == kind):
            continue
        start = time.perf_counter()
        result = policy(envs.make(folder, task, max_episode_steps=600))
        results.append(
            {
                "task": task.id,
                "success": result.success,
                "steps": result.steps,
                "wall_s": round(time.perf_counter() - start, 2),
            }
        )
    return {
        "tries": len(results),
        "successes": sum(r["success"] for r in results),
        "episodes": results,
    }


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folder", type=Path)
    parser.add_argument("--out", type=Path, default=None, help="JSON file (default: stdout)")
    parser.add_argument("--steps", type=int, default=2000)
    parser.add_argument("--resets", type=int, default=50)
    parser.add_argument("--episodes", type=int, default=100, help="per kind, for false successes")
    parser.add_argument("--episode-steps", type=int, default=100)
    parser.add_argument(
        "--script", action="store_true", help="run the scripted open and close policies"
    )
    args = parser.parse_args()
    tasks = list(propose_folder_tasks(args.folder, limit=1000, write=False).tasks)
    first: dict[str, Task] = {}
    for task in tasks:
        first.setdefault(task.kind, task)
    result: dict = {
        "folder": str(args.folder),
        "machine": {"python": platform.python_version(), "mujoco": mujoco.__version__},
        "tasks_proposed": len(tasks),
        "raw_mj_step_per_s": round(raw_physics_rate(args.folder, args.steps), 1),
        "environments": [
            bench_task(args.folder, t, args.steps, args.resets) for t in first.values()
        ],
        "false_successes": {
            kind: false_successes(args.folder, t, args.episodes, args.episode_steps)
            for kind, t in first.items()
        },
    }
    if args.script:
        result["scripted_open"] = scripted(args.folder, tasks, "open")
        result["scripted_close"] = scripted(args.folder, tasks, "close")
    text = json.dumps(result, indent=2) + "\n"
    if args.out is None:
        sys.stdout.write(text)
    else:
        args.out.parent.mkdir(parents=True, exist_ok=True)
        args.out.write_text(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
