"""``holomj schema [KIND]``: the JSON Schema of a holomj data format (the job:
:mod:`holomj.jobs.schema`; ``edit``, the operations of ``holomj edit``:
:func:`holomj.spec.edit.operations_schema`)."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from holomj.cli.options import OutFileOption
from holomj.cli.output import guard


def schema_command(
    kind: Annotated[
        str, typer.Argument(help="scene, asset, library, report, plan, task or edit.")
    ] = "scene",
    out: OutFileOption = None,
) -> None:
    """Print the JSON Schema of a holomj data format."""
    from holomj.errors import InputError
    from holomj.jobs.schema import write_schema
    from holomj.spec.schema import SCHEMAS

    target = Path("-") if out is None else out
    if kind == "edit":
        from holomj.jobs.folder import write_json_file
        from holomj.spec.edit import operations_schema

        guard(lambda: write_json_file(target, operations_schema()))
        return
    if kind not in SCHEMAS:
        known = ", ".join([*SCHEMAS, "edit"])
        guard(lambda: _refuse(InputError(f"unknown schema {kind!r}", fix=f"use one of: {known}")))

    guard(lambda: write_schema(kind, target))


def _refuse(err: Exception) -> None:
    raise err
