"""``holomj batch``: many scenes from a jobs file, on a local process pool or on Ray (the job:
:mod:`holomj.batch.jobs_file`).

Exit codes: 0 when every job wrote its scene (``--strict``: and every scene validated ok), 1 when
a job failed (the table says which and why), 2 for bad input (jobs file, options, folder).
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any

import typer
from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn
from rich.table import Table

from holomj.cli.options import (
    JsonOption,
    LibraryOption,
    PlannerOption,
    QuietOption,
    RenderOption,
    StrictOption,
    TextModelOption,
)
from holomj.cli.output import emit_json, err_console, guard, out_console

if TYPE_CHECKING:
    from holomj.batch.job_list import Job
    from holomj.batch.result import JobResult
    from holomj.batch.run import BatchOutcome

STATUS_STYLE = {"ok": "green", "unstable": "yellow", "failed": "red"}
ERROR_WIDTH = 80
JOB_WIDTH = 40


JobsFileArg = Annotated[
    Path,
    typer.Argument(
        metavar="INPUT",
        help="Jobs file: one prompt or house JSON path (relative to the file) per line; "
        "blank lines and # comments are ignored.",
    ),
]
BatchFolderOption = Annotated[
    Path, typer.Option("--out", "-o", help="Batch folder: one sub-folder per job.")
]
WorkersOption = Annotated[
    int, typer.Option("--workers", "-w", min=1, max=1024, help="Jobs run at once.")
]
RayOption = Annotated[
    str | None,
    typer.Option(
        "--ray",
        metavar="ADDRESS",
        help="Run the jobs as Ray tasks: local (start one here), auto (join 'ray start'), "
        "or ray://HOST:PORT. Needs the ray extra: pip install 'holomj\\[ray]'.",
    ),
]
SeedsOption = Annotated[
    str | None,
    typer.Option(
        "--seeds",
        metavar="A:B",
        help="Run every prompt with each seed in [A, B) (default 0:1); house files run once.",
    ),
]
TimeoutOption = Annotated[
    float, typer.Option("--timeout", min=1.0, help="Seconds per job before it is killed.")
]
MaxJobsPerWorkerOption = Annotated[
    int,
    typer.Option(
        "--max-jobs-per-worker",
        min=0,
        help="Local engine: replace a worker after N jobs (0: never; 1: a fresh process "
        "per job, ~10 s slower per job).",
    ),
]


def batch_command(
    jobs_file: JobsFileArg,
    out: BatchFolderOption,
    workers: WorkersOption = 1,
    ray: RayOption = None,
    seeds: SeedsOption = None,
    timeout: TimeoutOption = 600.0,
    library: LibraryOption = None,
    planner: PlannerOption = "offline",
    render: RenderOption = False,
    text_model: TextModelOption = None,
    max_jobs_per_worker: MaxJobsPerWorkerOption = 0,
    strict: StrictOption = False,
    as_json: JsonOption = False,
    quiet: QuietOption = False,
) -> None:
    """Build many scenes: each job in its own worker process, resumable, with a summary.

    Prompt scenes are rendered only with --render. --strict: exit 1 also when a scene did not
    validate ok.
    """
    from holomj.batch.jobs_file import run_jobs_file

    progress = _BatchProgress() if not (quiet or as_json) else None
    callbacks: dict[str, Any] = {}
    if progress is not None:
        callbacks = {
            "on_planned": progress.planned,
            "on_start": progress.started,
            "on_done": progress.finished,
            "on_skip": progress.skipped,
        }
    try:
        run = guard(
            lambda: run_jobs_file(
                jobs_file,
                out,
                seeds=seeds,
                workers=workers,
                ray=ray,
                timeout_s=timeout,
                library=library,
                planner=planner,
                render=render,
                text_model=text_model,
                max_jobs_per_worker=max_jobs_per_worker,
                **callbacks,
            )
        )
    finally:
        if progress is not None:
            progress.stop()
    outcome = run.outcome
    if as_json:
        emit_json(run.to_dict())
    elif not quiet:
        _print_table(outcome, out)
    if not outcome.all_ok or (strict and outcome.totals.unstable):
        raise typer.Exit(code=1)


class _BatchProgress:
    """A progress bar on stderr (started once the jobs are known) and one line per finished
    job."""

    def __init__(self) -> None:
        self.progress = Progress(
            TextColumn("[bold]batch[/]"),
            BarColumn(),
            MofNCompleteColumn(),
            TextColumn("{task.description}"),
            TimeElapsedColumn(),
            console=err_console,
            transient=True,
        )
        self.task: Any = None
        self.running: set[str] = set()
        self.counts = {"ok": 0, "unstable": 0, "failed": 0}

    def planned(self, total: int) -> None:
        """Show the bar for ``total`` jobs."""
        self.progress.start()
        self.task = self.progress.add_task("", total=total)

    def stop(self) -> None:
        """Take the bar away (it is transient)."""
        self.progress.stop()

    def describe(self) -> str:
        """Counts so far and the jobs running now."""
        counts, running = self.counts, self.running
        now = ", ".join(sorted(running)[:2]) + (" ..." if len(running) > 2 else "")
        return f"ok {counts['ok']}, unstable {counts['unstable']}, failed {counts['failed']}" + (
            f" | running {now}" if now else ""
        )

    def started(self, job: Job) -> None:
        """A job started."""
        self.running.add(job.id)
        self.progress.update(self.task, description=self.describe())

    def finished(self, result: JobResult) -> None:
        """A job ended: one line, and the bar moves on."""
        self.running.discard(result.id)
        self.counts[result.status] += 1
        style = STATUS_STYLE[result.status]
        detail = result.error or f"{result.objects} objects, {result.stable} stable"
        self.progress.console.print(
            f"[{style}]{result.status:>8}[/] {result.id} ({result.seconds:.1f} s) {detail}",
            highlight=False,
        )
        self.progress.update(self.task, advance=1, description=self.describe())

    def skipped(self, result: JobResult) -> None:
        """A job was complete before this run."""
        self.counts[result.status] += 1
        self.progress.update(self.task, advance=1, description=self.describe())


def _counts(result: JobResult) -> tuple[str, str, str]:
    """A house job's moved, left-out and substituted objects (blank when not known)."""
    moved, left, substituted = (
        "" if v is None else str(v) for v in (result.moved, result.left_out, result.substituted)
    )
    return (moved, left, substituted)


def _print_table(outcome: BatchOutcome, out: Path) -> None:
    """The results table and a totals line."""
    table = Table(title=f"holomj batch -> {out}")
    longest = max((len(r.id) for r in outcome.results), default=3)
    table.add_column("job", no_wrap=True, min_width=min(longest, JOB_WIDTH))
    table.add_column("status", no_wrap=True, min_width=8)
    table.add_column("objects", justify="right", no_wrap=True, min_width=7)
    table.add_column("stable", justify="right", no_wrap=True, min_width=6)
    houses = any(r.kind == "house" for r in outcome.results)
    for name in ("moved", "left out", "substituted") if houses else ():
        table.add_column(name, justify="right", no_wrap=True, min_width=len(name))
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
            *(_counts(result) if houses else ()),
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
