"""``holomj add-robot OUT SPEC``: a robot attached to a scene folder at a free floor spot (the
job: :mod:`holomj.jobs.add_robot`). The ``--robot`` and ``--profile`` options of compile and
generate are in :mod:`holomj.cli.options`.

Exit codes: 0 when the robot was attached, 2 for bad input (not a scene folder, unknown robot
with the available ones listed, no free spot, a robot already there, unknown profile), 1 for a
failure of ours.
"""

from __future__ import annotations

from typing import Annotated

import typer

from holomj.cli.options import FolderArg, JsonOption, ProfileOption, QuietOption, SeedOption
from holomj.cli.output import emit_json, err_console, guard, out_console


def add_robot_command(
    folder: FolderArg,
    spec: Annotated[
        str,
        typer.Argument(metavar="SPEC", help="An MJCF file, or a robot name (panda, jaco)."),
    ],
    seed: SeedOption = 0,
    clearance: Annotated[
        float,
        typer.Option(
            "--clearance", min=0.0, max=2.0, help="Free floor kept around the robot, metres."
        ),
    ] = 0.1,
    room: Annotated[
        str | None, typer.Option("--room", help="Place the robot in this room.")
    ] = None,
    profile: ProfileOption = "default",
    replace: Annotated[
        bool, typer.Option("--replace", help="Replace a robot the folder already has.")
    ] = False,
    as_json: JsonOption = False,
    quiet: QuietOption = False,
) -> None:
    """Attach a robot to an exported scene at a free floor spot reachable from the entrance.

    --json prints robot.json.
    """
    from holomj.jobs.add_robot import add_robot_to_folder

    result = guard(
        lambda: add_robot_to_folder(
            folder,
            spec,
            seed=seed,
            clearance=clearance,
            room=room,
            profile=profile,
            replace=replace,
        )
    )
    robot = result.robot
    if as_json:
        emit_json(robot.model_dump(mode="json"))
        return
    if quiet:
        return
    x, y, _ = robot.position
    out_console.print(
        f"[bold green]added[/] {robot.name} to {folder}/scene.xml at ({x:.2f}, {y:.2f}), "
        f"yaw {robot.yaw_deg:.1f}°, in {robot.room} (footprint {robot.footprint.radius_m:.2f} m)"
    )
    if result.warnings:
        err_console.print(f"  MuJoCo warnings in the smoke run: {result.warnings}")
    out_console.print("  run 'holomj validate' to refresh report.json", markup=False)
