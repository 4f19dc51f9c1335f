"""``holomj batch``: many scenes from a jobs file, on a local process pool or on Ray.

Exit codes: 0 when every job wrote its scene (``--strict``: and every scene validated ok), 1 when
a job failed (the table says which and why), 2 for bad input (jobs file, options, folder).
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer
from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn
from rich.table import Table

from holomj.cli_common import LibraryOption, emit_json, err_console, guard, out_console
from holomj.errors import InputError

if TYPE_CHECKING:
    from holomj.batch.engine import Engine
    from holomj.batch.job_list import Job
    from holomj.batch.result import JobOptions, JobResult
    from holomj.batch.run import BatchOutcome

PLANNERS = ("offline", "llm")
STATUS_STYLE = {"ok": "green", "unstable": "yellow", "failed": "red"}
ERROR_WIDTH = 80
JOB_WIDTH = 40


def batch_command(
    jobs_file: Annotated[
        Path,
        typer.Argument(
            metavar="INPUT",
            help="Jobs file: one prompt or house JSON path (relative to the file) per line; "
            "blank lines and # comments are ignored.",
        ),
    ],
    out: Annotated[Path, typer.Option("--out", "-o", help="Batch folder: one sub-folder per job.")],
    workers: Annotated[
        int, typer.Option("--workers", "-w", min=1, max=1024, help="Jobs run at once.")
    ] = 1,
    ray: Annotated[
        str | None,
        typer.Option(
            "--ray",
            metavar="ADDRESS",
            help="Run the jobs as Ray tasks: local (start one here), auto (join 'ray start'), "
            "or ray://HOST:PORT. Needs the ray extra: pip install 'holomj\\[ray]'.",
        ),
    ] = None,
    seeds: Annotated[
        str | None,
        typer.Option(
            "--seeds",
            metavar="A:B",
            help="Run every prompt with each seed in [A, B) (default 0:1); house files run once.",
        ),
    ] = None,
    timeout: Annotated[
        float, typer.Option("--timeout", min=1.0, help="Seconds per job before it is killed.")
    ] = 600.0,
    library: LibraryOption = None,
    planner: Annotated[
        str, typer.Option("--planner", help="offline (default, no network) or llm.")
    ] = "offline",
    render: Annotated[
        bool, typer.Option("--render/--no-render", help="Render prompt scenes (off by default).")
    ] = False,
    text_model: Annotated[
        Path | None, typer.Option("--text-model", help="Local sentence-transformers folder.")
    ] = None,
    max_jobs_per_worker: Annotated[
        int,
        typer.Option(
            "--max-jobs-per-worker",
            min=0,
            help="Local engine: replace a worker after N jobs (0: never; 1: a fresh process "
            "per job, ~10 s slower per job).",
        ),
    ] = 0,
    strict: Annotated[
        bool, typer.Option("--strict", help="Exit 1 also when a scene did not validate ok.")
    ] = False,
    as_json: Annotated[bool, typer.Option("--json", help="Print a JSON summary.")] = False,
    quiet: Annotated[bool, typer.Option("--quiet", "-q", help="No progress, no table.")] = False,
) -> None:
    """Build many scenes: each job in its own worker process, resumable, with a summary."""
    from holomj.batch.job_list import parse_seeds, read_jobs
    from holomj.batch.local import LocalEngine
    from holomj.batch.ray_engine import RayEngine, import_ray
    from holomj.batch.result import JobOptions
    from holomj.cli_assets import resolve_library

    if planner not in PLANNERS:
        guard(lambda: _bad(f"unknown planner {planner!r}", "--planner", "use offline or llm"))
    jobs = guard(lambda: read_jobs(jobs_file, parse_seeds(seeds)))
    if ray is not None:
        guard(import_ray)
    library_root = resolve_library(library)
    guard(lambda: _check_inputs(library_root, text_model))
    options = JobOptions(
        library=library_root.absolute(),
        planner=planner,  # type: ignore[arg-type]
        render=render,
        text_model=text_model.absolute() if text_model else None,
    )
    engine: Engine
    if ray is not None:
        engine = guard(lambda: RayEngine(ray, workers, timeout))
    else:
        engine = LocalEngine(workers, timeout, max_jobs_per_worker=max_jobs_per_worker)
    show = not (quiet or as_json)
    outcome = guard(lambda: _run(jobs, out, options, engine, show))
    if as_json:
        emit_json(
            {
                "output": str(out),
                "summary": str(outcome.summary),
                "engine": engine.name,
                "workers": engine.workers,
                "totals": outcome.totals.model_dump(mode="json"),
                "jobs": [r.model_dump(mode="json") for r in outcome.results],
            }
        )
    elif not quiet:
        _print_table(outcome, out)
    if not outcome.all_ok or (strict and outcome.totals.unstable):
        raise typer.Exit(code=1)


def _bad(what: str, where: str, fix: str) -> None:
    raise InputError(what, where=where, fix=fix)


def _check_inputs(library: Path, text_model: Path | None) -> None:
    """Fail once, before any job starts, on what would fail every job."""
    from holomj.library.store import AssetLibrary

    AssetLibrary.open(library)
    if text_model is not None and not text_model.is_dir():
        raise InputError("text model folder not found", where=f"--text-model {text_model}")


def _run(
    jobs: Sequence[Job], out: Path, options: JobOptions, engine: Engine, show: bool
) -> BatchOutcome:
    """Run the batch, with a progress bar and one line per finished job when ``show``."""
    from holomj.batch.run import run_batch

    if not show:
        return run_batch(jobs, out, options, engine)
    progress = Progress(
        TextColumn("[bold]batch[/]"),
        BarColumn(),
        MofNCompleteColumn(),
        TextColumn("{task.description}"),
        TimeElapsedColumn(),
        console=err_console,
        transient=True,
    )
    running: set[str] = set()
    counts = {"ok": 0, "unstable": 0, "failed": 0}
    with progress:
        task = progress.add_task("", total=len(jobs))

        def describe() -> str:
            now = ", ".join(sorted(running)[:2]) + (" ..." if len(running) > 2 else "")
            return (
                f"ok {counts['ok']}, unstable {counts['unstable']}, failed {counts['failed']}"
                + (f" | running {now}" if now else "")
            )

        def started(job: Job) -> None:
            running.add(job.id)
            progress.update(task, description=describe())

        def finished(result: JobResult) -> None:
            running.discard(result.id)
            counts[result.status] += 1
            style = STATUS_STYLE[result.status]
            detail = result.error or f"{result.objects} objects, {result.stable} stable"
            progress.console.print(
                f"[{style}]{result.status:>8}[/] {result.id} ({result.seconds:.1f} s) {detail}",
                highlight=False,
            )
            progress.update(task, advance=1, description=describe())

        def skipped(result: JobResult) -> None:
            counts[result.status] += 1
            progress.update(task, advance=1, description=describe())

        outcome = run_batch(
            jobs, out, options, engine, on_start=started, on_done=finished, on_skip=skipped
        )
    return outcome


def _print_table(outcome: BatchOutcome, out: Path) -> None:
    """The results table and a totals line."""
    table = Table(title=f"holomj batch -> {out}")
    longest = max((len(r.id) for r in outcome.results), default=3)
    table.add_column("job", no_wrap=True, min_width=min(longest, JOB_WIDTH))
    table.add_column("status", no_wrap=True, min_width=8)
    table.add_column("objects", justify="right", no_wrap=True, min_width=7)
    table.add_column("stable", justify="right", no_wrap=True, min_width=6)
    table.add_column("seconds", justify="right", no_wrap=True, min_width=7)
    table.add_column("error", overflow="fold", min_width=20)
    skipped = set(outcome.skipped)
    for result in outcome.results:
        style = STATUS_STYLE[result.status]
        fraction = "" if result.stable_fraction is None else f"{result.stable_fraction:.0%}"
        error = result.error or ""
        table.add_row(
            result.id,
            f"[{style}]{result.status}[/]" + ("*" if result.id in skipped else ""),
            "" if result.objects is None else str(result.objects),
            fraction,
            f"{result.seconds:.1f}",
            error if len(error) <= ERROR_WIDTH else error[: ERROR_WIDTH - 1] + "…",
        )
    out_console.print(table)
    t = outcome.totals
    line = (
        f"{t.jobs} jobs: {t.ok} ok, {t.unstable} unstable, {t.failed} failed; "
        f"ran {t.ran}, skipped {t.skipped} (* complete before); {t.wall_s:.1f} s, "
        f"{t.scenes_per_hour:.0f} scenes/hour; summary -> {outcome.summary}"
    )
    out_console.print(line, highlight=False)
    if t.failed:
        out_console.print(f"[bold red]FAILED:[/] {t.failed} job(s) failed (see the error column)")
