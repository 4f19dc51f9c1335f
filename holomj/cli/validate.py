"""``holomj validate SCENE``: penetration audit, settle, stability report (and ``--repair``); the
job: :mod:`holomj.jobs.validate`.

Exit codes: 0 when the report was made (ok or not); with ``--strict``, 1 when it is not ok;
with ``--repair``, 1 when an object could not be saved; 2 for bad input.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer
from rich.table import Table

from holomj.cli.options import FurnitureOption, QuietOption, StrictOption
from holomj.cli.output import err_console, guard, out_console, spinner

if TYPE_CHECKING:
    from holomj.spec.report import StabilityReport

_TABLE_ROWS = 60


def validate_command(
    scene: Annotated[
        Path,
        typer.Argument(
            metavar="SCENE", help="A folder written by 'holomj compile', or an MJCF file."
        ),
    ],
    json_out: Annotated[
        Path | None,
        typer.Option("--json", metavar="REPORT", help="Write the report as JSON ('-': stdout)."),
    ] = None,
    strict: StrictOption = False,
    repair: Annotated[
        bool,
        typer.Option(
            "--repair",
            help="Resolve small initial penetrations, settle and bake the settled poses of the "
            "objects that end stable back into the folder (scene.json, scene.xml with a "
            "'settled' keyframe); exits 1 when an object could not be saved.",
        ),
    ] = False,
    furniture: FurnitureOption = "free",
    tolerance_mm: Annotated[
        float,
        typer.Option("--tolerance-mm", min=0.0, max=100.0, help="Penetration allowed at t = 0."),
    ] = 1.0,
    monitor_s: Annotated[
        float, typer.Option("--monitor-s", min=0.1, max=60.0, help="Monitor window, seconds.")
    ] = 3.0,
    settle_s: Annotated[
        float,
        typer.Option("--settle-s", min=0.0, max=60.0, help="Most time spent settling, seconds."),
    ] = 5.0,
    sleep: Annotated[
        bool,
        typer.Option(
            "--sleep",
            help="Let MuJoCo put resting bodies to sleep: 5-20x faster on big scenes, but "
            "creep slower than MuJoCo's sleep tolerance goes unseen.",
        ),
    ] = False,
    quiet: QuietOption = False,
) -> None:
    """Audit a scene at t = 0, let it settle, and report every object's stability.

    --strict: exit 1 when the report is not ok.
    """
    from holomj.jobs.folder import write_json_file
    from holomj.jobs.validate import validate
    from holomj.spec.report import Thresholds

    thresholds = Thresholds(
        tolerance_m=tolerance_mm / 1000.0, monitor_s=monitor_s, settle_cap_s=settle_s
    )
    show = not quiet and json_out is None
    with spinner(f"validating {scene}", show=show and err_console.is_terminal):
        report = guard(
            lambda: validate(
                scene,
                thresholds=thresholds,
                furniture=furniture,
                sleep=sleep,
                repair=repair,
            )
        )
    if json_out is not None:
        guard(lambda: write_json_file(json_out, report.model_dump(mode="json")))
    if show:
        print_summary(report)
    elif not quiet and str(json_out) != "-":
        status = "ok" if report.ok else "NOT ok"
        err_console.print(f"{status}: {_headline(report)}; report -> {json_out}")
    if strict and not report.ok:
        raise typer.Exit(code=1)
    if repair and report.unsaved:
        # Some objects could not be saved: the folder holds what could be, but the repair failed.
        raise typer.Exit(code=1)


def _headline(report: StabilityReport) -> str:
    c = report.counts
    return (
        f"{c.get('stable', 0)}/{c.get('objects', 0)} objects stable "
        f"({c.get('dynamic', 0)} simulated free, {c.get('static', 0)} static), "
        f"{c.get('penetrations', 0)} penetrations at t = 0, "
        f"{sum(report.warnings.values())} MuJoCo warnings"
    )


def print_summary(report: StabilityReport) -> None:
    """A table of the objects (unstable first) and a verdict."""
    table = Table(title=f"stability of {report.source}")
    longest = max((len(o.name) for o in report.objects), default=6)
    table.add_column("object", min_width=min(longest, 32), overflow="fold")
    table.add_column("stable")
    table.add_column("free")
    table.add_column("moved mm", justify="right")
    table.add_column("turned °", justify="right")
    table.add_column("drift mm", justify="right")
    table.add_column("pen. mm", justify="right")
    table.add_column("support")
    table.add_column("reasons")
    rows = sorted(report.objects, key=lambda o: (o.stable, o.name))
    for obj in rows[:_TABLE_ROWS]:
        table.add_row(
            obj.name,
            "[green]yes[/]" if obj.stable else "[red]no[/]",
            "yes" if obj.dynamic else "static",
            f"{obj.displacement_m * 1000:.1f}",
            f"{obj.rotation_from_authored_deg:.1f}",
            f"{obj.drift_m * 1000:.2f}",
            f"{obj.penetration_m * 1000:.1f}",
            obj.support or "-",
            "; ".join(obj.reasons),
        )
    out_console.print(table)
    if len(rows) > _TABLE_ROWS:
        out_console.print(f"  ... and {len(rows) - _TABLE_ROWS} more stable objects")
    for pair in report.penetrations:
        out_console.print(
            f"  [red]penetration[/] {pair.a} / {pair.b}: {pair.depth_m * 1000:.1f} mm "
            f"({pair.geom_a} / {pair.geom_b})"
        )
    for item in report.below_floor:
        out_console.print(f"  [red]below floor[/] {item.name}: lowest z {item.value_m:.3f} m")
    for item in report.outside_rooms:
        out_console.print(f"  [red]outside rooms[/] {item.name}: {item.value_m:.3f} m away")
    shown = [a for a in report.repaired if a.moved_m >= 0.001 or a.rotation_deg >= 1.0]
    if len(shown) < len(report.repaired):
        out_console.print(
            f"  [cyan]repaired[/] {len(report.repaired) - len(shown)} objects moved less than "
            "1 mm and 1° by settling"
        )
    for action in shown:
        out_console.print(
            f"  [cyan]repaired[/] {action.name}: moved {action.moved_m * 1000:.1f} mm, "
            f"{action.rotation_deg:.2f}° ({action.why})"
        )
    for unsaved in report.unsaved:
        out_console.print(f"  [yellow]unsaved[/] {unsaved.name}: {unsaved.why}")
    if report.warnings:
        out_console.print(f"  [red]MuJoCo warnings:[/] {report.warnings}")
    verdict = "[bold green]ok[/]" if report.ok else "[bold red]not ok[/]"
    out_console.print(
        f"{verdict}: {_headline(report)}; max penetration at t = 0 "
        f"{report.max_penetration_m * 1000:.2f} mm; {report.sim_time_s:.1f} s simulated in "
        f"{report.wall_time_s:.1f} s ({report.realtime_factor:.1f}x real time)"
    )
