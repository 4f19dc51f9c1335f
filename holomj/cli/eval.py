"""``holomj eval OUT``: measure a scene folder from its geometry (the job:
:mod:`holomj.jobs.eval`; the metrics: :mod:`holomj.evaluation.report`).

Exit codes: 0 when the measurement was made (whatever it found: eval is a measurement, not a
judgement), 2 for bad input (not a scene folder, a bad spec, both --prompt and --spec).
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer
from rich.table import Table

from holomj.cli.options import FolderArg, QuietOption, SeedOption
from holomj.cli.output import err_console, guard, out_console, spinner

if TYPE_CHECKING:
    from holomj.jobs.eval import EvalReport

_ISSUES_PER_METRIC = 5


def eval_command(
    folder: FolderArg,
    prompt: Annotated[
        str | None,
        typer.Option(
            "--prompt",
            metavar="TEXT",
            help="What the scene was asked to be: measured against the folder's plan.json when "
            "it has one, else against the offline planner's plan of TEXT (requested objects "
            "and relations only).",
        ),
    ] = None,
    spec: Annotated[
        Path | None,
        typer.Option(
            "--spec",
            metavar="SPEC.json",
            help="An annotation to measure against (.json, or .jsonl with --id), in the format "
            "of scripts/eval/prompts_dev.jsonl.",
        ),
    ] = None,
    spec_id: Annotated[
        str | None, typer.Option("--id", help="Which annotation of a .jsonl --spec.")
    ] = None,
    json_out: Annotated[
        Path | None,
        typer.Option("--json", metavar="R", help="Write the report as JSON ('-': stdout)."),
    ] = None,
    validate: Annotated[
        bool,
        typer.Option(
            "--validate",
            help="When the folder has no report.json, run the validation (in memory) for the "
            "stability score.",
        ),
    ] = False,
    seed: SeedOption = 0,
    quiet: QuietOption = False,
) -> None:
    """Measure a scene: counts, attributes and relations against its plan or a spec, colliding
    pairs, objects outside their room, support, navigability, front access, doors and windows
    clear, stability. Exit 0 when measured, 2 for bad input."""
    from holomj.jobs.eval import evaluate
    from holomj.jobs.folder import write_json_file

    show = not quiet and str(json_out) != "-"
    with spinner(f"evaluating {folder}", show=show and err_console.is_terminal):
        report = guard(
            lambda: evaluate(
                folder, prompt=prompt, spec=spec, spec_id=spec_id, validate=validate, seed=seed
            )
        )
    if json_out is not None:
        guard(lambda: write_json_file(json_out, report.to_json()))
    if show:
        print_report(report)


def print_report(report: EvalReport) -> None:
    """The scores as a table, then what failed, item by item (a few per metric)."""
    against = report.against.get("source") or "nothing (no plan, prompt or spec)"
    table = Table(title=f"eval of {report.folder} (against {against})")
    table.add_column("metric")
    table.add_column("score", justify="right")
    table.add_column("ok")
    table.add_column("summary", overflow="fold")
    for name, score in report.scores.items():
        value = score.get("score")
        ok = score.get("ok")
        table.add_row(
            name,
            "-" if value is None else f"{value:.3f}",
            "-" if ok is None else ("[green]yes[/]" if ok else "[red]no[/]"),
            score.get("summary", ""),
        )
    out_console.print(table)
    for line in issues(report):
        out_console.print(f"  [red]{line}[/]", markup=True, highlight=False)
    for note in report.notes:
        out_console.print(f"  note: {note}", markup=False)
    overall = report.overall
    out_console.print(
        f"overall {'-' if overall is None else f'{overall:.3f}'} (mean of the measured scores); "
        f"{report.n_objects} objects, {len(report.rooms)} rooms; "
        f"{report.timings.get('total', 0.0):.2f} s"
    )


def issues(report: EvalReport) -> list[str]:
    """One line per failed item, a few per metric."""
    by_metric: dict[str, list[str]] = {}
    for metric, text in report.problems():
        by_metric.setdefault(metric, []).append(text)
    lines = []
    for metric, items in by_metric.items():
        lines += [f"{metric}: {item}" for item in items[:_ISSUES_PER_METRIC]]
        if len(items) > _ISSUES_PER_METRIC:
            lines.append(f"{metric}: ... and {len(items) - _ISSUES_PER_METRIC} more")
    return lines
