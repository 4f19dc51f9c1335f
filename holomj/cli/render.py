"""``holomj render OUT``: headless views of an output folder, the annotated plan and the page
(the job: :mod:`holomj.jobs.render`).

Writes ``OUT/renders/`` (atomically) and, unless ``--no-report``, ``OUT/report.html``. Exit
codes: 0 on success, 2 for bad input (not a holomj folder, unknown view, absurd size), 1 when
rendering fails (no OpenGL backend works: the message names MUJOCO_GL).
"""

from __future__ import annotations

from typing import Annotated

import typer

from holomj.cli.options import FolderArg, JsonOption, QuietOption
from holomj.cli.output import emit_json, err_console, guard, out_console, spinner


def render_command(
    out: FolderArg,
    width: Annotated[int, typer.Option("--width", help="Image width in pixels.")] = 640,
    height: Annotated[int, typer.Option("--height", help="Image height in pixels.")] = 480,
    views: Annotated[
        str,
        typer.Option(
            "--views",
            help="Comma-separated: top (top-down view + plan), rooms (one view per room), "
            "objects (close-ups of receptacles with what rests on them).",
        ),
    ] = "top,rooms",
    depth: Annotated[
        bool, typer.Option("--depth", help="Also write depth images (16-bit PNG, millimetres).")
    ] = False,
    segmentation: Annotated[
        bool,
        typer.Option(
            "--segmentation",
            help="Also write segmentation images (16-bit PNG of labels) and their legend.",
        ),
    ] = False,
    no_shadows: Annotated[
        bool, typer.Option("--no-shadows", help="Render without shadows (much faster on a CPU).")
    ] = False,
    no_report: Annotated[
        bool, typer.Option("--no-report", help="Do not write OUT/report.html.")
    ] = False,
    as_json: JsonOption = False,
    quiet: QuietOption = False,
) -> None:
    """Render top-down, per-room and close-up views of OUT, the plan, and OUT/report.html."""
    from holomj.jobs.render import render_folder, write_report_html

    with spinner(f"rendering {out}", show=not (quiet or as_json) and err_console.is_terminal):
        summary = guard(
            lambda: render_folder(
                out,
                views=views,
                width=width,
                height=height,
                depth=depth,
                segmentation=segmentation,
                shadows=not no_shadows,
            )
        )
        page = None if no_report else guard(lambda: write_report_html(out))
    if as_json:
        emit_json({**summary.to_dict(), "report_html": str(page) if page else None})
    elif not quiet:
        images = [f for f in summary.files if f.endswith(".png")]
        out_console.print(
            f"[bold green]rendered[/] {len(images)} images into {out}/renders "
            f"({summary.timings_s.get('total', 0.0):.1f} s, MUJOCO_GL={summary.backend}, "
            f"{summary.gl_renderer})"
        )
        if page is not None:
            out_console.print(f"  report: {page}")
