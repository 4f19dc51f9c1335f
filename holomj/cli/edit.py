"""``holomj edit OUT OPS.json [-o NEW] [--json REPORT]``: apply edit operations to a scene (the
job: :mod:`holomj.jobs.edit`; the format: ``holomj schema edit``).

OPS.json is a JSON list of operations (add, add_on, remove, move, replace, material, light).
Each is applied or refused with a reason; only what an operation touches changes, new small
objects are dropped with the simulator, and the edited scene is validated and written
atomically: back into OUT, or into the new folder NEW (``-o``). ``edit_report.json`` in the
written folder lists every operation's outcome, what moved, and the validation summary.

Exit codes: 0 when every operation was applied and the scene validates, 1 when an operation
was refused or the edited scene does not validate (it is written all the same), 2 for bad
input (an unreadable or malformed operations file leaves OUT untouched).
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from holomj.cli.options import FolderArg, LibraryOption, OverwriteOption, QuietOption, SeedOption
from holomj.cli.output import err_console, guard, library_root, out_console, spinner


def edit_command(
    scene: FolderArg,
    ops: Annotated[
        Path,
        typer.Argument(
            metavar="OPS.json", help="The operations: a JSON list (see 'holomj schema edit')."
        ),
    ],
    out: Annotated[
        Path | None,
        typer.Option(
            "--out", "-o", metavar="NEW", help="Write the edited scene here (default: into OUT)."
        ),
    ] = None,
    json_out: Annotated[
        Path | None,
        typer.Option(
            "--json", metavar="REPORT", help="Also write the edit report here ('-': stdout)."
        ),
    ] = None,
    overwrite: OverwriteOption = False,
    seed: SeedOption = 0,
    library: LibraryOption = None,
    quiet: QuietOption = False,
) -> None:
    """Apply edit operations (add, add_on, remove, move, replace, material, light) to a scene."""
    from holomj.jobs.edit import EDIT_REPORT, apply_edits, read_operations
    from holomj.jobs.folder import require_scene_folder, write_json_file

    guard(lambda: require_scene_folder(scene, "holomj generate' or 'holomj compile"))
    operations = guard(lambda: read_operations(ops))
    library_path = library_root(library)
    show = not quiet and json_out is None and err_console.is_terminal
    with spinner(f"editing {scene} ({len(operations)} operation(s))", show=show):
        report = guard(
            lambda: apply_edits(
                scene, operations, out, seed=seed, library_path=library_path, overwrite=overwrite
            )
        )
    if json_out is not None:
        guard(lambda: write_json_file(json_out, report.model_dump(mode="json")))
    if not quiet and str(json_out) != "-":
        colour = "green" if report.ok else "yellow"
        out_console.print(
            f"[bold {colour}]{report.applied}/{len(report.operations)} operation(s) applied[/] "
            f"-> {report.output} (see {EDIT_REPORT})"
        )
        for result in report.operations:
            if result.status == "refused":
                out_console.print(
                    f"  refused: [{result.index}] {result.op}: {result.reason}", markup=False
                )
        if report.moved:
            out_console.print("  moved: " + ", ".join(m.id for m in report.moved), markup=False)
        if report.validation is not None:
            counts = report.validation["counts"]
            verdict = "[green]ok[/]" if report.validation["ok"] else "[red]NOT ok[/]"
            out_console.print(
                f"  validation {verdict}: {counts['stable']}/{counts['objects']} stable"
            )
        if report.stale_files:
            out_console.print(
                f"  {' and '.join(report.stale_files)} show the scene before the edit: "
                f"'holomj render {report.output}' refreshes them",
                markup=False,
            )
    if not report.ok:
        raise typer.Exit(code=1)
