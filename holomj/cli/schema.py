"""``holomj schema [KIND]``: the JSON Schema of a holomj data format (the job:
:mod:`holomj.jobs.schema`)."""

from __future__ import annotations

from typing import Annotated

import typer

from holomj.cli.options import OutFileOption
from holomj.cli.output import guard


def schema_command(
    kind: Annotated[str, typer.Argument(help="scene, asset, library, report or plan.")] = "scene",
    out: OutFileOption = None,
) -> None:
    """Print the JSON Schema of a holomj data format."""
    from holomj.jobs.schema import write_schema

    guard(lambda: write_schema(kind, "-" if out is None else out))
