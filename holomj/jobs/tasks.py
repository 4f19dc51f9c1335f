"""The tasks job (``holomj tasks OUT``): feasible robot tasks proposed for a scene folder and
written to its ``tasks.json`` (:mod:`holomj.tasks.propose`, :mod:`holomj.spec.tasks`)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from holomj.errors import FormatError, InputError
from holomj.file_names import NAVMAP_JSON, OBJECTS_JSON, TASKS_JSON
from holomj.jobs.folder import read_json_report, require_scene_folder, write_report
from holomj.spec.base import read_json, validate_model
from holomj.spec.tasks import TaskSet
from holomj.tasks.propose import propose_tasks
from holomj.tasks.words import tasks_from_words


def read_objects(folder: Path) -> dict[str, Any]:
    """The folder's ``objects.json``; a one-line error when it has none."""
    record = read_json_report(folder, OBJECTS_JSON)
    if not isinstance(record, dict):
        raise FormatError(
            f"no {OBJECTS_JSON} (or not a JSON object)",
            where=str(Path(folder) / OBJECTS_JSON),
        )
    return record


def propose_folder_tasks(
    folder: Path, limit: int = 10, *, write: bool = True, prompt: str | None = None
) -> TaskSet:
    """At most ``limit`` feasible tasks for the scene in ``folder`` (with ``prompt``: the tasks
    it names in words, :mod:`holomj.tasks.words`), written to its ``tasks.json`` unless not
    ``write``. Bad input (not a scene folder, no objects.json, a limit below 1, a task in words
    the scene cannot do) is an InputError with the reason."""
    folder = require_scene_folder(Path(folder))
    if limit < 1:
        raise InputError(f"cannot propose {limit} tasks", fix="pass -n 1 or more")
    objects = read_objects(folder)
    if prompt is not None:
        tasks = tasks_from_words(prompt, objects)
    else:
        navmap = read_json_report(folder, NAVMAP_JSON)
        tasks = propose_tasks(objects, navmap if isinstance(navmap, dict) else None, limit)
    if write:
        write_report(folder, TASKS_JSON, tasks.model_dump(mode="json"))
    return tasks


def read_tasks(path: Path) -> TaskSet:
    """A ``tasks.json`` file (or a folder's), validated."""
    path = Path(path)
    if path.is_dir():
        path = path / TASKS_JSON
    return validate_model(TaskSet, read_json(path), str(path))
