"""The ``holomj`` Typer app: every command registered, and the console-script entry point.

The command modules import only typer and rich at module level; each command imports its job
inside its function, so ``holomj --help`` loads no MuJoCo, torch, OR-Tools or CoACD.
"""

from __future__ import annotations

import sys

import typer

from holomj.cli.assets import assets_app
from holomj.cli.batch import batch_command
from holomj.cli.compile import compile_command
from holomj.cli.edit import edit_command
from holomj.cli.eval import eval_command
from holomj.cli.export import export_command
from holomj.cli.generate import generate_command, plan_command
from holomj.cli.info import info_command
from holomj.cli.layout import layout_app
from holomj.cli.materials import materials_app
from holomj.cli.pack import pack_command
from holomj.cli.populate import populate_command
from holomj.cli.refine import refine_command
from holomj.cli.render import render_command
from holomj.cli.robot import add_robot_command
from holomj.cli.schema import schema_command
from holomj.cli.tasks import tasks_command
from holomj.cli.validate import validate_command
from holomj.cli.vary import vary_command

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
app.command("compile")(compile_command)
app.command("info")(info_command)
app.command("eval")(eval_command)
app.command("edit")(edit_command)
app.command("refine")(refine_command)
app.command("export")(export_command)
app.command("schema")(schema_command)
app.command("tasks")(tasks_command)
app.command("pack")(pack_command)
app.command("vary")(vary_command)


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
