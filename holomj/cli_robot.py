"""``holomj add-robot OUT SPEC`` and the ``--robot`` / ``--profile`` options of compile/generate.

Exit codes: 0 when the robot was attached, 2 for bad input (not a scene folder, unknown robot
with the available ones listed, no free spot, a robot already there), 1 for a failure of ours.
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from holomj.cli_common import emit_json, err_console, guard, out_console

RobotOption = Annotated[
    str | None,
    typer.Option(
        "--robot",
        metavar="SPEC",
        help="Attach a robot on a free floor spot: an MJCF file, or panda (dm-robotics-panda, "
        "installed with --no-deps) or jaco (dm_control).",
    ),
]
ProfileOption = Annotated[
    str,
    typer.Option(
        "--profile",
        help="default, or mjx: primitive/low-vertex colliders and options MJX accepts.",
    ),
]


def add_robot_command(
    folder: Annotated[
        Path, typer.Argument(metavar="OUT", help="A folder written by compile or generate.")
    ],
    spec: Annotated[
        str,
        typer.Argument(metavar="SPEC", help="An MJCF file, or a robot name (panda, jaco)."),
    ],
    seed: Annotated[
        int, typer.Option("--seed", min=0, max=2**32 - 1, help="Seed of the robot's spot.")
    ] = 0,
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
    as_json: Annotated[bool, typer.Option("--json", help="Print robot.json.")] = False,
    quiet: Annotated[bool, typer.Option("--quiet", "-q", help="Print nothing on success.")] = False,
) -> None:
    """Attach a robot to an exported scene at a free floor spot reachable from the entrance."""
    from holomj.jobs.add_robot import add_robot_to_folder
    from holomj.mjcf.compiler import check_profile

    checked = guard(lambda: check_profile(profile))
    result = guard(
        lambda: add_robot_to_folder(
            folder,
            spec,
            seed=seed,
            clearance=clearance,
            room=room,
            profile=checked,
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
