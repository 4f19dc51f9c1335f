"""``holomj vary OUT -n N [-o DIR] [--seed S]``: N validated variants of one scene's layout (the
job: :mod:`holomj.jobs.vary`): other floor and wall materials, jittered lights, other assets of
the same category at the same place, small objects dropped again; each written as
``DIR/variant_000`` ... with its tasks.json re-checked. Exit codes: 0 when every variant
validated, 1 when some did not (they are reported), 2 for bad input.
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from holomj.cli.options import (
    FolderArg,
    JsonOption,
    LibraryOption,
    MaterialsOption,
    QuietOption,
    SeedOption,
)
from holomj.cli.output import emit_json, err_console, guard, library_root, out_console


def vary_command(
    folder: FolderArg,
    count: Annotated[int, typer.Option("-n", "--count", min=1, help="How many variants.")] = 10,
    out_dir: Annotated[
        Path | None,
        typer.Option("--out", "-o", metavar="DIR", help="Where (default: OUT_variants beside)."),
    ] = None,
    seed: SeedOption = 0,
    tries: Annotated[
        int, typer.Option("--tries", min=1, help="Draws per variant before it is reported.")
    ] = 3,
    replace: Annotated[
        int, typer.Option("--replace", min=0, help="Furniture pieces replaced per variant.")
    ] = 1,
    library: LibraryOption = None,
    materials: MaterialsOption = None,
    as_json: JsonOption = False,
    quiet: QuietOption = False,
) -> None:
    """Write N validated variants of the scene folder OUT (materials, lights, assets, drops)."""
    from holomj.jobs.vary import vary_folder

    library_path = library_root(library)
    log = None if (quiet or as_json) else err_console.print
    result = guard(
        lambda: vary_folder(
            folder,
            count,
            out_dir,
            seed=seed,
            tries=tries,
            replace=replace,
            library_path=library_path,
            materials=materials,
            log=log,
        )
    )
    if as_json:
        emit_json(result.to_dict())
    elif not quiet:
        each = result.seconds / max(1, len(result.variants))
        out_console.print(
            f"[bold green]{result.validated}/{len(result.variants)} variants validated[/] in "
            f"{result.out_dir} ({result.seconds:.1f} s, {each:.1f} s each)"
        )
        for variant in result.variants:
            if not variant.ok:
                out_console.print(f"  {variant.name}: not valid after {variant.tries} draws")
    if result.validated < len(result.variants):
        raise typer.Exit(1)
