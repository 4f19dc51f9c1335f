"""``holomj layout solve``: floor-object layout for one room (pure geometry, no MuJoCo; the job:
:mod:`holomj.jobs.layout_solve`).

Exit codes: 0 when a layout was written (even with unplaced objects: they are listed in the
output with the reason), 2 for bad input, 1 for a failure of ours.
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from holomj.cli.options import JsonOption, QuietOption, SeedOption
from holomj.cli.output import emit_json, err_console, guard, out_console

layout_app = typer.Typer(
    help="Furniture layout for one room under Holodeck-style constraints.",
    no_args_is_help=True,
    pretty_exceptions_enable=False,
    add_completion=False,
)


@layout_app.command("solve")
def solve_command(
    input_path: Annotated[
        Path,
        typer.Argument(
            metavar="INPUT",
            help="Layout problem JSON: room polygon (m), doors, windows, objects with sizes "
            "(size_unit 'cm' or 'm') and constraints (Holodeck text or typed JSON).",
        ),
    ],
    out: Annotated[Path, typer.Option("--out", "-o", help="Result JSON file to write.")],
    solver: Annotated[
        str, typer.Option("--solver", help="cpsat (CP-SAT, greedy warm start) or greedy.")
    ] = "cpsat",
    time_limit: Annotated[
        float,
        typer.Option("--time-limit", min=0.05, max=600.0, help="Time budget in seconds."),
    ] = 1.0,
    seed: SeedOption = 0,
    as_json: JsonOption = False,
    quiet: QuietOption = False,
) -> None:
    """Place the objects of one room; write placements, constraint report and unplaced objects.

    --json also prints the result.
    """
    from holomj.jobs.layout_solve import solve_layout_file

    solved = guard(
        lambda: solve_layout_file(
            input_path, out, solver=solver, time_limit_s=time_limit, seed=seed
        )
    )
    if as_json:
        emit_json(solved.to_dict())
        return
    if quiet:
        return
    result = solved.result
    out_console.print(
        f"[bold green]placed[/] {len(result.placements)}/{len(solved.problem.objects)} objects, "
        f"{result.satisfied}/{result.total} constraints satisfied in {result.solve_time_s:.2f} s "
        f"({result.solver_used}) -> {out}"
    )
    for item in result.unplaced:
        out_console.print(f"  [yellow]unplaced[/] {item.id}: {item.reason}", markup=True)
    for warning in result.warnings:
        err_console.print(f"warning: {warning}", markup=False)
