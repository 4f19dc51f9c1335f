"""``holomj layout``: floor-object layout for one room (pure geometry, no MuJoCo).

Exit codes: 0 when a layout was written (even with unplaced objects: they are listed in the
output with the reason), 2 for bad input, 1 for a failure of ours.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Annotated

import typer

from holomj.cli_common import emit_json, err_console, guard, out_console
from holomj.errors import InputError

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
    seed: Annotated[int, typer.Option("--seed", min=0, help="Random seed.")] = 0,
    as_json: Annotated[bool, typer.Option("--json", help="Also print the result as JSON.")] = False,
    quiet: Annotated[bool, typer.Option("--quiet", "-q", help="Print nothing on success.")] = False,
) -> None:
    """Place the objects of one room; write placements, constraint report and unplaced objects."""
    from holomj.layout.room_problem import load_problem
    from holomj.layout.solve import SOLVERS, solve_room
    from holomj.seeds import seed_rng

    if solver not in SOLVERS:
        guard(
            lambda: _raise(
                InputError(
                    f"unknown solver {solver!r}",
                    where="--solver",
                    fix=f"use one of: {', '.join(SOLVERS)}",
                )
            )
        )
    problem = guard(lambda: load_problem(input_path))
    result = guard(
        lambda: solve_room(
            problem, solver=solver, time_limit_s=time_limit, rng=seed_rng(seed)
        )
    )
    data = result.to_dict()
    guard(lambda: _write_json_atomic(out, data))
    if as_json:
        emit_json(data)
        return
    if quiet:
        return
    out_console.print(
        f"[bold green]placed[/] {len(result.placements)}/{len(problem.objects)} objects, "
        f"{result.satisfied}/{result.total} constraints satisfied in {result.solve_time_s:.2f} s "
        f"({result.solver_used}) -> {out}"
    )
    for item in result.unplaced:
        out_console.print(f"  [yellow]unplaced[/] {item.id}: {item.reason}", markup=True)
    for warning in result.warnings:
        err_console.print(f"warning: {warning}", markup=False)


def _raise(err: Exception) -> None:
    raise err


def _write_json_atomic(path: Path, data: dict) -> None:
    """Write JSON beside the target and rename it into place."""
    from holomj.atomic import write_file

    path = Path(path)
    parent = path.parent if str(path.parent) else Path(".")
    if not parent.is_dir():
        raise InputError("output folder does not exist", where=str(parent))
    try:
        write_file(path, json.dumps(data, indent=2, sort_keys=True) + "\n")
    except OSError as err:
        raise InputError(f"cannot write: {err.strerror or err}", where=str(path)) from None
