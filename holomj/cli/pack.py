"""``holomj pack OUT [--format mjb|zip|all] [-o DIR]``: the scene folder as single files (the job:
:mod:`holomj.jobs.pack`): MuJoCo's binary model ``scene.mjb`` (fastest to load) and a zip archive
``scene.zip`` of the folder. Exit codes: 0 when written, 2 for bad input, 1 when writing fails.
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from holomj.cli.options import FolderArg, JsonOption, QuietOption
from holomj.cli.output import emit_json, guard, out_console


def pack_command(
    out: FolderArg,
    fmt: Annotated[
        str,
        typer.Option(
            "--format",
            "-f",
            metavar="mjb|zip|all",
            help="mjb: MuJoCo's binary model (mujoco.MjModel.from_binary_path); zip: the folder "
            "in one archive (holomj.formats.package.load_package); all: both.",
        ),
    ] = "all",
    target_dir: Annotated[
        Path | None,
        typer.Option("--out", "-o", metavar="DIR", help="Where to write (default OUT/export)."),
    ] = None,
    as_json: JsonOption = False,
    quiet: QuietOption = False,
) -> None:
    """Package the scene folder OUT as scene.mjb and/or scene.zip, each checked by loading it."""
    from holomj.jobs.pack import pack_folder

    result = guard(lambda: pack_folder(out, fmt, target_dir))
    if as_json:
        emit_json(result.to_dict())
        return
    if quiet:
        return
    for name, path in result.files.items():
        size = result.bytes[name] / 1e6
        out_console.print(f"[bold green]packed[/] {name}: {path} ({size:.1f} MB)", markup=True)
