"""``holomj compile INPUT -o OUT``: a scene or house file -> a self-contained MuJoCo package
(the job: :mod:`holomj.jobs.compile`). Imported houses and SceneDefs are made to stand
(``--no-fix`` compiles them as imported; ``--fix`` makes a holomj scene stand too).

Exit codes: 0 when OUT was written, 2 for bad input (OUT is then not created, and an existing
OUT is untouched), 1 for a failure of ours, and when objects could not be made to stand
(nothing is written then, unless ``--allow-invalid``).
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer
from rich.markup import escape

from holomj.cli.options import (
    JsonOption,
    LibraryOption,
    OutFolderOption,
    OverwriteOption,
    ProfileOption,
    QuietOption,
    RobotOption,
    SeedOption,
)
from holomj.cli.output import emit_json, guard, library_root, out_console, spinner
from holomj.importers.detect import FORMATS

if TYPE_CHECKING:
    from holomj.jobs.compile import CompileReport
    from holomj.spec.stand_record import StandRecord

InputArgument = Annotated[
    Path,
    typer.Argument(
        metavar="INPUT",
        help="holomj scene.json, ProcTHOR/Holodeck house JSON or SceneDef JSON.",
    ),
]

FormatOption = Annotated[
    str | None, typer.Option("--format", help=f"Force the input format: {', '.join(FORMATS)}.")
]

CheckSecondsOption = Annotated[
    float,
    typer.Option(
        "--check-seconds",
        min=0.0,
        max=60.0,
        help="Seconds to simulate as a smoke test (0 skips).",
    ),
]

FixOption = Annotated[
    bool | None,
    typer.Option(
        "--fix/--no-fix",
        help="Make the scene stand: objects on the floor or dropped onto their receptacles, "
        "clear of walls and each other, settled and validated (default: on for "
        "ProcTHOR/Holodeck houses and SceneDefs, off for holomj scenes).",
        show_default=False,
    ),
]

AllowInvalidOption = Annotated[
    bool,
    typer.Option(
        "--allow-invalid",
        help="Write the scene even when objects could not be made to stand (marked "
        '"valid": false in import_report.json).',
    ),
]

StrictOption = Annotated[
    bool,
    typer.Option(
        "--strict",
        help="Refuse the house (exit 1, nothing written) when any object would be left "
        "out; by default what cannot stand anywhere is left out and listed.",
    ),
]

ObjathorOption = Annotated[
    Path | None,
    typer.Option(
        "--objathor",
        help="objathor asset folder: the Objaverse assets a Holodeck house names by uid "
        "are imported from it into the library first, so the real meshes are used where "
        "it has them (stand-ins of the same kind elsewhere).",
    ),
]


def compile_command(
    input_path: InputArgument,
    out: OutFolderOption,
    fmt: FormatOption = None,
    library: LibraryOption = None,
    overwrite: OverwriteOption = False,
    check_seconds: CheckSecondsOption = 1.0,
    robot: RobotOption = None,
    profile: ProfileOption = "default",
    seed: SeedOption = 0,
    fix: FixOption = None,
    allow_invalid: AllowInvalidOption = False,
    strict: StrictOption = False,
    objathor: ObjathorOption = None,
    as_json: JsonOption = False,
    quiet: QuietOption = False,
) -> None:
    """Compile a scene or house file into a self-contained MuJoCo package in OUT."""
    from holomj.jobs.compile import compile_file

    library_path = library_root(library)
    with spinner(f"compiling {input_path}", show=not (quiet or as_json)):
        report = guard(
            lambda: compile_file(
                input_path,
                out,
                library_path=library_path,
                fmt=fmt,
                overwrite=overwrite,
                check_seconds=check_seconds,
                robot=robot,
                profile=profile,
                seed=seed,
                fix=fix,
                allow_invalid=allow_invalid,
                strict=strict,
                objathor=objathor,
            )
        )
    if as_json:
        emit_json(report.to_dict())
    elif not quiet:
        _print_report(report)


def _print_report(report: CompileReport) -> None:
    """What was compiled: counts, the robot, making it stand, substitutions and warnings."""
    scene, model, robot = report.scene, report.model, report.robot
    out_console.print(
        f"[bold green]compiled[/] {report.input} ({report.format}) -> {report.output}/scene.xml"
    )
    out_console.print(
        f"  {len(scene.rooms)} rooms, {scene.walls} walls, {scene.doors} doors, "
        f"{scene.windows} windows, {scene.objects} objects; "
        f"{model.bodies} bodies, {model.geoms} geoms, {model.total_mass_kg} kg"
    )
    if robot is not None:
        x, y, _ = robot.position
        out_console.print(
            f"  robot {robot.name} at ({x:.2f}, {y:.2f}), yaw {robot.yaw_deg:.1f}°, in {robot.room}"
        )
    if report.stand is not None:
        _print_stand(report.stand)
    if report.substitutions:
        out_console.print(
            f"  {len(report.substitutions)} assets substituted (see import_report.json)"
        )
    for warning in report.warnings:
        out_console.print(f"  [yellow]warning:[/] {warning}", markup=True)
    if report.sim_warnings:
        out_console.print(f"  [red]MuJoCo warnings in the smoke run:[/] {report.sim_warnings}")


def _print_stand(stand: StandRecord) -> None:
    """What making the scene stand changed, and the verdict."""
    before, after = stand.penetrations_before, stand.penetrations_after
    out_console.print(
        f"  made it stand: {len(stand.moved)} moved, {len(stand.dropped)} dropped onto "
        f"receptacles, {len(stand.separated)} separated; penetrations "
        f"{before['count']} (max {before['max_m'] * 1000:.0f} mm) -> {after['count']} "
        f"(max {after['max_m'] * 1000:.1f} mm)"
    )
    _print_kept(stand)
    validation = stand.validation or {}
    if stand.valid:
        out_console.print(
            f"  [green]valid:[/] {validation['stable']}/{validation['objects']} objects stable"
        )
        return
    out_console.print(
        f"  [bold red]INVALID[/] (written with --allow-invalid): {escape(str(stand.refusal))}"
    )
    for row in stand.unsaved[:8]:
        out_console.print(f"    {row['object']}: {row['why']}", markup=False)


def _print_kept(stand: StandRecord) -> None:
    """The objects moved to another receptacle or left out, and the share kept."""
    relocated, left = stand.relocated, stand.left_out
    if not relocated and not left:
        return
    out_console.print(
        f"  kept {stand.objects_kept}/{stand.objects_imported} objects "
        f"({stand.kept_share:.1%}): {len(relocated)} moved to another receptacle, "
        f"{len(left)} left out (see import_report.json)"
    )
    for row in (relocated + left)[:8]:
        to = row["to"]["support"] if row["to"] else "left out"
        out_console.print(
            f"    {row['object']}: {row['from']['support']} -> {to}: {row['why']}", markup=False
        )
