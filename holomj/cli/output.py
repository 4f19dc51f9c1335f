"""What every command shares for output: consoles, JSON, spinners, and errors as exit codes."""

from __future__ import annotations

import contextlib
import json
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any, TypeVar

import typer
from rich.console import Console

from holomj.errors import HolomjError

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


def spinner(message: str, show: bool = True) -> contextlib.AbstractContextManager[Any]:
    """A spinner with ``message`` on stderr while the block runs (nothing when not ``show``)."""
    return err_console.status(message, spinner="dots") if show else contextlib.nullcontext()


def library_root(path: Path | None) -> Path:
    """The ``--library`` a command uses (:func:`holomj.jobs.library.resolve_library`), with a
    spinner while the default library is built on first use; errors exit as :func:`guard`'s."""
    from holomj.jobs.library import resolve_library

    with spinner("building the default asset library (first use)", show=path is None):
        return guard(lambda: resolve_library(path))
