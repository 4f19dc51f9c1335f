"""Running a batch: lock the folder, skip complete jobs, clean half-done ones, run the rest on an
engine, record every result in ``summary.jsonl``.

``DIR`` holds one folder per complete job (``DIR/<id>/`` with the scene and ``batch_job.json``),
``summary.jsonl``, ``batch.json`` (the jobs and options of the latest run) and ``.batch.lock``.
Run the same command again after a crash or ``kill -9``: complete jobs are skipped, the others
(failed ones included) run again.
"""

from __future__ import annotations

import json
import time
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from holomj.atomic import write_file
from holomj.batch.engine import Engine, EngineRun, OnDone, OnStart
from holomj.batch.job_list import Job
from holomj.batch.result import JobOptions, JobResult
from holomj.batch.resume import batch_lock, clean_partial, completed
from holomj.batch.summary import BatchTotals, append_result, totals, write_summary
from holomj.errors import HolomjError, InputError

BATCH_JSON = "batch.json"


@dataclass(frozen=True)
class BatchOutcome:
    """Every job's result (in job order), the totals and where the summary is."""

    results: list[JobResult]
    totals: BatchTotals
    skipped: list[str]
    summary: Path

    @property
    def all_ok(self) -> bool:
        """No job failed (unstable scenes were written: they count as run)."""
        return self.totals.failed == 0


def run_batch(
    jobs: Sequence[Job],
    out_dir: Path,
    options: JobOptions,
    engine: Engine,
    *,
    on_start: OnStart | None = None,
    on_done: OnDone | None = None,
    on_skip: OnDone | None = None,
) -> BatchOutcome:
    """Run the jobs that are not complete in ``out_dir`` on ``engine``; see the module docstring."""
    out_dir = _prepare(Path(out_dir))
    start = time.perf_counter()
    with batch_lock(out_dir):
        done = completed(out_dir, list(jobs))
        todo = [job for job in jobs if job.id not in done]
        for job in todo:
            clean_partial(out_dir, job)
        _write_batch_json(out_dir, jobs, options, engine)
        for job in jobs:
            if job.id in done and on_skip is not None:
                on_skip(done[job.id])
        results: dict[str, JobResult] = dict(done)

        def finished(result: JobResult) -> None:
            results[result.id] = result
            append_result(out_dir, result)
            if on_done is not None:
                on_done(result)

        if todo:  # (a Ray engine would start a cluster for nothing)
            hooks = EngineRun(out_dir, options, on_start or (lambda job: None), finished)
            engine.run(todo, hooks)
        missing = [job.id for job in todo if job.id not in results]
        if missing:
            raise HolomjError(f"engine {engine.name} reported no result", where=", ".join(missing))
        ordered = [results[job.id] for job in jobs]
        summary = write_summary(out_dir, ordered)
    wall = time.perf_counter() - start
    return BatchOutcome(
        results=ordered,
        totals=totals(ordered, skipped=len(done), ran=len(todo), wall_s=wall),
        skipped=[job.id for job in jobs if job.id in done],
        summary=summary,
    )


def _prepare(out_dir: Path) -> Path:
    """Create ``out_dir`` (absolute) or check that it is a folder."""
    if out_dir.exists() and not out_dir.is_dir():
        raise InputError("exists and is not a folder", where=str(out_dir), fix="pick another -o")
    try:
        out_dir.mkdir(parents=True, exist_ok=True)
    except OSError as err:
        raise InputError(
            f"cannot create the output folder: {err.strerror or err}", where=str(out_dir)
        ) from None
    return out_dir.absolute()


def _write_batch_json(
    out_dir: Path, jobs: Sequence[Job], options: JobOptions, engine: Engine
) -> None:
    record = {
        "engine": engine.name,
        "workers": engine.workers,
        "options": options.model_dump(mode="json"),
        "jobs": [job.model_dump(mode="json") for job in jobs],
    }
    write_file(out_dir / BATCH_JSON, json.dumps(record, indent=2, sort_keys=True) + "\n")
