"""The layout-solve job (``holomj layout solve``): one room's floor objects placed from a layout
problem file, the result written as JSON (pure geometry, no MuJoCo).

A layout is written even when objects stay unplaced: they are listed in the result with the
reason.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any, Literal, cast

from holomj.errors import InputError

if TYPE_CHECKING:
    from holomj.layout.room_problem import RoomProblem
    from holomj.layout.solve import LayoutResult

Solver = Literal["cpsat", "greedy"]  # holomj.layout.solve.SOLVERS


@dataclass(frozen=True)
class LayoutSolveResult:
    """What the job did: the problem read, the layout found and the file written."""

    problem: RoomProblem
    result: LayoutResult
    output: Path

    def to_dict(self) -> dict[str, Any]:
        """The result as written to :attr:`output`."""
        return self.result.to_dict()


def solve_layout_file(
    input_path: Path,
    out: Path,
    *,
    solver: str = "cpsat",
    time_limit_s: float = 1.0,
    seed: int = 0,
) -> LayoutSolveResult:
    """Solve the layout problem in ``input_path`` and write the result to ``out`` atomically.

    Raises :class:`~holomj.errors.InputError` for an unknown ``solver``, a bad problem file
    (naming the file and field) or an ``out`` whose folder does not exist.
    """
    from holomj.layout.room_problem import load_problem
    from holomj.layout.solve import SOLVERS, solve_room
    from holomj.seeds import seed_rng

    if solver not in SOLVERS:
        raise InputError(
            f"unknown solver {solver!r}", where="--solver", fix=f"use one of: {', '.join(SOLVERS)}"
        )
    problem = load_problem(input_path)
    result = solve_room(
        problem,
        solver=cast(Solver, solver),  # checked against SOLVERS above
        time_limit_s=time_limit_s,
        rng=seed_rng(seed),
    )
    _write_json_atomic(Path(out), result.to_dict())
    return LayoutSolveResult(problem, result, Path(out))


def _write_json_atomic(path: Path, data: dict[str, Any]) -> None:
    """Write JSON beside the target and rename it into place."""
    from holomj.atomic import write_file

    parent = path.parent if str(path.parent) else Path(".")
    if not parent.is_dir():
        raise InputError("output folder does not exist", where=str(parent))
    try:
        write_file(path, json.dumps(data, indent=2, sort_keys=True) + "\n")
    except OSError as err:
        raise InputError(f"cannot write: {err.strerror or err}", where=str(path)) from None
