"""``holomj export OUT --format glb|usd|urdf [-o FILE_OR_DIR]``: the scene in other formats (the
job: :mod:`holomj.jobs.export`).

GLB (glTF 2.0 binary, Y-up) for Blender and three.js, USD with UsdPhysics (needs the ``export``
extra: usd-core) for Isaac Sim and Isaac Lab, URDF per articulated asset (doors, jointed
furniture). Exit codes: 0 when written, 2 for bad input (not a holomj folder, unknown format,
wrong kind of target, usd-core missing), 1 when writing fails.
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from holomj.cli.options import FolderArg, JsonOption, QuietOption
from holomj.cli.output import emit_json, err_console, guard, out_console, spinner
from holomj.spec.export_details import UrdfDetails, UsdDetails


def export_command(
    out: FolderArg,
    fmt: Annotated[
        str,
        typer.Option(
            "--format",
            "-f",
            metavar="glb|usd|urdf",
            help="glb: the scene as seen (glTF 2.0 binary, Y-up); usd: a USD stage with "
            "UsdPhysics (rigid bodies, masses, colliders, joints; Z-up); urdf: one URDF per "
            "articulated asset.",
        ),
    ],
    target: Annotated[
        Path | None,
        typer.Option(
            "--out",
            "-o",
            metavar="FILE_OR_DIR",
            help="Where to write: a .glb file; a .usdz file (one package) or .usd/.usdc/.usda "
            "(textures/ beside it); a folder for urdf. Default: OUT/export/scene.glb, "
            "OUT/export/scene.usdz, OUT/export/urdf/.",
        ),
    ] = None,
    colliders: Annotated[
        bool,
        typer.Option(
            "--colliders", help="glb: also the collision-only geoms, as <id>/colliders nodes."
        ),
    ] = False,
    as_json: JsonOption = False,
    quiet: QuietOption = False,
) -> None:
    """Export the scene folder OUT as GLB, USD or URDF."""
    from holomj.jobs.export import export_folder

    show = not (quiet or as_json) and err_console.is_terminal
    with spinner(f"exporting {out} as {fmt}", show=show):
        result = guard(lambda: export_folder(out, fmt, target, colliders=colliders))
    if as_json:
        emit_json(result.to_dict())
        return
    if quiet:
        return
    seconds = result.timings_s.get("total", 0.0)
    out_console.print(
        f"[bold green]exported[/] {result.format}: {result.target} "
        f"({_size(result.bytes)} in {len(result.files)} files, {seconds:.1f} s)"
    )
    details = result.details
    if isinstance(details, UsdDetails):
        out_console.print(
            f"  {details.rigid_bodies} rigid bodies, {details.colliders} colliders, "
            f"{details.joints} joints, {details.textures} textures"
        )
        for note in details.notes:
            out_console.print(f"  note: {note}", markup=False)
    if isinstance(details, UrdfDetails):
        assets = details.assets
        if not assets:
            out_console.print(
                "  no articulated assets (no hinge or slide joints): nothing to write"
            )
        for asset in assets:
            joints = ", ".join(f"{j['name']} ({j['type']})" for j in asset["joints"])
            out_console.print(f"  {asset['urdf']}: {joints}", markup=False)


def _size(count: int) -> str:
    if count >= 1 << 20:
        return f"{count / (1 << 20):.1f} MB"
    if count >= 1 << 10:
        return f"{count / (1 << 10):.0f} KB"
    return f"{count} B"
