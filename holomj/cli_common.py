"""What every CLI command shares: consoles, JSON output and turning errors into exit codes."""

from __future__ import annotations

import json
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Annotated, Any, TypeVar

import typer
from rich.console import Console

from holomj.errors import HolomjError

LibraryOption = Annotated[
    Path | None,
    typer.Option(
        "--library",
        help="Asset library folder (default: $HOLOMJ_HOME/library, built on first use).",
    ),
]

out_console = Console(soft_wrap=True)
err_console = Console(stderr=True, highlight=False, soft_wrap=True)

T = TypeVar("T")


def guard(job: Callable[[], T]) -> T:
    """Run ``job``; a HolomjError becomes one line on stderr and its exit code."""
    try:
        return job()
    except HolomjError as err:
        err_console.print(f"error: {err.one_line()}", markup=False)
        raise typer.Exit(code=err.exit_code) from None


def emit_json(data: Any) -> None:
    """Print ``data`` as JSON on stdout."""
    sys.stdout.write(json.dumps(data, indent=2, sort_keys=True) + "\n")


def write_text(path: Path, text: str) -> None:
    """Write ``text`` to ``path``; an OS error becomes a one-line InputError naming the file."""
    from holomj.errors import InputError

    try:
        Path(path).write_text(text, encoding="utf-8")
    except OSError as err:
        raise InputError(f"cannot write: {err.strerror or err}", where=str(path)) from None
