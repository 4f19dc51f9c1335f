"""``holomj.envs.make(folder, task, robot=...)``: a Gymnasium environment on a scene folder."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import mujoco

from holomj.envs.arm_env import SceneArmEnv
from holomj.errors import FormatError, InputError
from holomj.file_names import SCENE_XML, TASKS_JSON
from holomj.formats.package import load_package
from holomj.jobs.folder import require_scene_folder
from holomj.jobs.tasks import read_objects, read_tasks
from holomj.spec.base import validate_model
from holomj.spec.tasks import Task, TaskSet


def make(
    folder: Path | str,
    task: Task | str | dict[str, Any],
    robot: str | None = None,
    package: Path | str | None = None,
    **options: Any,
) -> SceneArmEnv:
    """The environment of ``task`` on the scene in ``folder`` with its attached robot.

    ``task``: a task, its JSON form, or the id of a task in the folder's ``tasks.json``
    (``holomj tasks OUT``). ``robot``: the robot the folder must have attached (its name or
    spec as ``robot.json`` records it; None: whichever it has). ``package``: load the model from
    this single-file package of the folder (``holomj pack``: ``.mjb`` loads fastest, or ``.zip``)
    instead of compiling ``scene.xml``. ``options`` go to
    :class:`~holomj.envs.arm_env.SceneArmEnv` (frame_skip, max_delta_rad, action_mode, shaping,
    max_episode_steps, render_mode). Bad input is an InputError with the reason.
    """
    root = require_scene_folder(Path(folder))
    record = read_objects(root)
    attached = record.get("robot")
    if attached is None:
        raise InputError(
            "the scene has no robot",
            where=str(root),
            fix=f"attach one with 'holomj add-robot {root} {robot or 'jaco'}'",
        )
    if robot is not None and robot not in (attached.get("name"), attached.get("spec")):
        raise InputError(
            f"the scene has robot {attached.get('name')!r} attached, not {robot!r}",
            where=str(root),
            fix=f"run 'holomj add-robot {root} {robot} --replace' first",
        )
    chosen = _task(root, task)
    if package is not None:
        return SceneArmEnv(load_package(package), record, chosen, **options)
    try:
        model = mujoco.MjModel.from_xml_path(str(root / SCENE_XML))
    except ValueError as err:
        raise FormatError(f"cannot load: {err}", where=str(root / SCENE_XML)) from None
    return SceneArmEnv(model, record, chosen, **options)


def _task(root: Path, task: Task | str | dict[str, Any]) -> Task:
    if isinstance(task, dict):
        wrapped = validate_model(TaskSet, {"scene": "", "tasks": [task]}, "task")
        return wrapped.tasks[0]
    if not isinstance(task, str):
        return task
    if not (root / TASKS_JSON).is_file():
        raise InputError(
            f"no {TASKS_JSON} to find task {task!r} in",
            where=str(root),
            fix=f"run 'holomj tasks {root}' first, or pass the task itself",
        )
    tasks = {t.id: t for t in read_tasks(root / TASKS_JSON).tasks}
    if task not in tasks:
        raise InputError(
            f"no task {task!r} in {TASKS_JSON}",
            where=str(root),
            fix=f"use one of: {', '.join(sorted(tasks)) or '(none: run holomj tasks first)'}",
        )
    return tasks[task]
