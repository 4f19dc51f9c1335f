"""``holomj materials ...``: import a folder of textures as materials, list the materials (the
jobs: :mod:`holomj.jobs.materials`)."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer
from rich.table import Table

from holomj.cli.options import JsonOption, MaterialsOption
from holomj.cli.output import emit_json, guard, out_console

materials_app = typer.Typer(
    help="Manage surface materials (colours and textures).", no_args_is_help=True
)


@materials_app.command("import")
def import_command(
    folder: Annotated[
        Path, typer.Argument(metavar="DIR", help="A folder of PNG/JPG tiling textures.")
    ],
    surface: Annotated[
        str | None,
        typer.Option(help="floor, wall, ceiling or any (default: guessed from each name)."),
    ] = None,
    texture_size: Annotated[
        float, typer.Option("--texture-size", help="World size of one tile, metres.")
    ] = 1.0,
    materials: MaterialsOption = None,
    as_json: JsonOption = False,
) -> None:
    """Add every colour texture of DIR as a material (normal/roughness maps are skipped)."""
    from holomj.jobs.materials import import_materials

    result = guard(
        lambda: import_materials(
            folder, root=materials, surface=surface, texture_size_m=texture_size
        )
    )
    if as_json:
        emit_json(result.to_dict())
        return
    table = Table(title=f"imported into {result.root}")
    for column in ("material", "surfaces", "description"):
        table.add_column(column)
    for entry in result.added:
        table.add_row(entry.name, ",".join(entry.surfaces), entry.description)
    out_console.print(table)
    out_console.print(
        f"{len(result.added)} added ({len(result.replaced)} replaced), "
        f"{len(result.skipped)} skipped"
    )


@materials_app.command("list")
def list_command(materials: MaterialsOption = None, as_json: JsonOption = False) -> None:
    """List the built-in and user materials with their surfaces."""
    from holomj.jobs.materials import list_materials

    listing = guard(lambda: list_materials(materials))
    rows = listing.rows
    if as_json:
        emit_json(rows)
        return
    table = Table(title=f"materials: {len(rows)} ({listing.root})")
    for column in ("name", "kind", "surfaces", "description"):
        table.add_column(column)
    for row in rows:
        kind = "built-in" if row["builtin"] else "texture" if row["texture"] else "user"
        table.add_row(row["name"], kind, ",".join(row["surfaces"]) or "-", row["description"])
    out_console.print(table)
