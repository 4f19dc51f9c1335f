"""``holomj tasks OUT [-n N]``: feasible robot tasks proposed for a scene folder, written to its
``tasks.json`` (the job: :mod:`holomj.jobs.tasks`; the format: ``holomj schema task``).

Exit codes: 0 when tasks were written, 2 for bad input (not a scene folder, no objects.json,
N below 1, a task in ``--prompt`` the scene cannot do, with the reason), 1 for a failure of ours.
"""

from __future__ import annotations

from typing import Annotated

import typer

from holomj.cli.options import FolderArg, JsonOption, QuietOption
from holomj.cli.output import emit_json, guard, out_console


def tasks_command(
    folder: FolderArg,
    count: Annotated[
        int, typer.Option("-n", "--count", help="Propose at most this many tasks.")
    ] = 10,
    prompt: Annotated[
        str | None,
        typer.Option(
            "--prompt",
            help='Tasks in words instead: "open the fridge, then put the mug in the sink".',
        ),
    ] = None,
    as_json: JsonOption = False,
    quiet: QuietOption = False,
) -> None:
    """Propose feasible tasks (open/close parts, pick-and-place, rearrange, navigate) for a
    scene folder, or read the ones --prompt names, and write its tasks.json. --json prints it."""
    from holomj.jobs.tasks import propose_folder_tasks

    tasks = guard(lambda: propose_folder_tasks(folder, count, prompt=prompt))
    if as_json:
        emit_json(tasks.model_dump(mode="json"))
        return
    if quiet:
        return
    out_console.print(f"[bold green]wrote[/] {len(tasks.tasks)} tasks to {folder}/tasks.json")
    for task in tasks.tasks:
        out_console.print(f"  {task.kind:10s} {task.id}: {task.description}", markup=False)
