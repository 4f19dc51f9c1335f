"""The ``holomj`` command line: thin wrappers that build a config and call one library function.

Bad input prints one line on stderr and exits with 2; failures exit with 1. Nothing prompts.
"""

from __future__ import annotations

import contextlib
import json
import sys
from pathlib import Path
from typing import Annotated

import typer
from rich.table import Table

from holomj.cli_assets import assets_app, resolve_library
from holomj.cli_batch import batch_command
from holomj.cli_common import (
    LibraryOption,
    emit_json,
    err_console,
    guard,
    out_console,
    write_text,
)
from holomj.cli_generate import generate_command, plan_command
from holomj.cli_layout import layout_app
from holomj.cli_materials import materials_app
from holomj.cli_populate import populate_command
from holomj.cli_render import render_command
from holomj.cli_robot import ProfileOption, RobotOption, add_robot_command
from holomj.cli_validate import validate_command
from holomj.importers.detect import FORMATS

app = typer.Typer(
    name="holomj",
    help="Physically valid indoor scenes for MuJoCo.",
    no_args_is_help=True,
    pretty_exceptions_enable=False,
    add_completion=False,
)
app.add_typer(assets_app, name="assets")
app.add_typer(layout_app, name="layout")
app.add_typer(materials_app, name="materials")
app.command("validate")(validate_command)
app.command("populate")(populate_command)
app.command("render")(render_command)
app.command("generate")(generate_command)
app.command("plan")(plan_command)
app.command("add-robot")(add_robot_command)
app.command("batch")(batch_command)


@app.command("compile")
def compile_command(
    input_path: Annotated[
        Path,
        typer.Argument(
            metavar="INPUT",
            help="holomj scene.json, ProcTHOR/Holodeck house JSON or SceneDef JSON.",
        ),
    ],
    out: Annotated[Path, typer.Option("--out", "-o", help="Output folder to create.")],
    fmt: Annotated[
        str | None, typer.Option("--format", help=f"Force the input format: {', '.join(FORMATS)}.")
    ] = None,
    library: LibraryOption = None,
    overwrite: Annotated[
        bool, typer.Option("--overwrite", help="Replace OUT if it exists.")
    ] = False,
    check_seconds: Annotated[
        float,
        typer.Option(
            "--check-seconds",
            min=0.0,
            max=60.0,
            help="Seconds to simulate as a smoke test (0 skips).",
        ),
    ] = 1.0,
    robot: RobotOption = None,
    profile: ProfileOption = "default",
    seed: Annotated[
        int, typer.Option("--seed", min=0, max=2**32 - 1, help="Seed of the robot's spot.")
    ] = 0,
    as_json: Annotated[bool, typer.Option("--json", help="Print the report as JSON.")] = False,
    quiet: Annotated[bool, typer.Option("--quiet", "-q", help="Print nothing on success.")] = False,
) -> None:
    """Compile a scene or house file into a self-contained MuJoCo package in OUT."""
    from holomj.jobs.compile import compile_file

    library_root = resolve_library(library)
    with (
        err_console.status(f"compiling {input_path}", spinner="dots")
        if not (quiet or as_json)
        else contextlib.nullcontext()
    ):
        report = guard(
            lambda: compile_file(
                input_path,
                out,
                library_path=library_root,
                fmt=fmt,
                overwrite=overwrite,
                check_seconds=check_seconds,
                robot=robot,
                profile=profile,
                seed=seed,
            )
        )
    if as_json:
        emit_json(report.to_dict())
    elif not quiet:
        scene, model = report.scene, report.model
        out_console.print(
            f"[bold green]compiled[/] {report.input} ({report.format}) -> {report.output}/scene.xml"
        )
        out_console.print(
            f"  {len(scene['rooms'])} rooms, {scene['walls']} walls, {scene['doors']} doors, "
            f"{scene['windows']} windows, {scene['objects']} objects; "
            f"{model['bodies']} bodies, {model['geoms']} geoms, {model['total_mass_kg']} kg"
        )
        if report.robot is not None:
            x, y, _ = report.robot["position"]
            out_console.print(
                f"  robot {report.robot['name']} at ({x:.2f}, {y:.2f}), yaw "
                f"{report.robot['yaw_deg']:.1f}°, in {report.robot['room']}"
            )
        if report.substitutions:
            out_console.print(
                f"  {len(report.substitutions)} assets substituted (see import_report.json)"
            )
        for warning in report.warnings:
            out_console.print(f"  [yellow]warning:[/] {warning}", markup=True)
        if report.sim_warnings:
            out_console.print(f"  [red]MuJoCo warnings in the smoke run:[/] {report.sim_warnings}")


@app.command("info")
def info_command(
    folder: Annotated[
        Path, typer.Argument(metavar="OUT", help="A folder written by 'holomj compile'.")
    ],
    as_json: Annotated[bool, typer.Option("--json", help="Print JSON.")] = False,
) -> None:
    """Rooms, objects, bodies, geoms and mass of an exported scene."""
    from holomj.jobs.info import folder_summary

    summary = guard(lambda: folder_summary(folder))
    if as_json:
        emit_json(summary)
        return
    table = Table(title=f"{summary['name']} ({summary['folder']})")
    table.add_column("room")
    table.add_column("type")
    table.add_column("area m²", justify="right")
    for room in summary["rooms"]:
        table.add_row(room["id"], room["type"], f"{room['area_m2']:.2f}")
    out_console.print(table)
    model = summary["model"]
    out_console.print(
        f"walls {summary['walls']}, doors {summary['doors']}, windows {summary['windows']}, "
        f"objects {summary['objects']} ({summary['dynamic_objects']} dynamic, "
        f"{summary['static_objects']} static), lights {summary['lights']}"
    )
    out_console.print(
        f"bodies {model['bodies']}, geoms {model['geoms']}, joints {model['joints']} "
        f"({model['free_joints']} free, {model['hinges']} hinges), meshes {model['meshes']}, "
        f"mass {model['total_mass_kg']} kg"
    )


@app.command("schema")
def schema_command(
    kind: Annotated[str, typer.Argument(help="scene, asset, library, report or plan.")] = "scene",
    out: Annotated[
        Path | None, typer.Option("--out", "-o", help="Write to this file instead of stdout.")
    ] = None,
) -> None:
    """Print the JSON Schema of a holomj data format."""
    from holomj.spec.schema import json_schema

    text = json.dumps(guard(lambda: json_schema(kind)), indent=2, sort_keys=True) + "\n"
    if out is None:
        sys.stdout.write(text)
    else:
        guard(lambda: write_text(out, text))


def main() -> None:
    """Console-script entry point: bad options and arguments give one line and exit 2."""
    click = _click_exceptions()
    try:
        result = app(prog_name="holomj", standalone_mode=False)
    except click.NoArgsIsHelpError as err:
        help_text = err.format_message()  # rich help is printed as the error is made
        if help_text.strip():
            print(help_text, file=sys.stderr)
        sys.exit(2)
    except click.UsageError as err:
        where = err.ctx.command_path if err.ctx else "holomj"
        message = " ".join(err.format_message().split())
        print(f"error: {where}: {message}", file=sys.stderr)
        sys.exit(2)
    except typer.Abort:
        print("aborted", file=sys.stderr)
        sys.exit(1)
    except click.ClickException as err:
        print(f"error: {' '.join(err.format_message().split())}", file=sys.stderr)
        sys.exit(err.exit_code)
    sys.exit(result if isinstance(result, int) else 0)


def _click_exceptions():
    """The exception classes of the click that typer runs on (typer >= 0.24 vendors its own)."""
    try:
        from typer._click import exceptions
    except ImportError:  # an older typer on the real click
        from click import exceptions
    return exceptions
