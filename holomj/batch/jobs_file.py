"""The batch job as ``holomj batch`` runs it: a jobs file and options in, every job run on the
local pool or on Ray, the outcome out.

What would fail every job (the jobs file, the seeds, the planner, Ray missing, the library, the
text model) fails once, before any job starts, with a one-line InputError.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from holomj.batch.engine import DEFAULT_TIMEOUT_S, Engine, OnDone, OnStart
from holomj.batch.run import BatchOutcome
from holomj.errors import InputError


@dataclass(frozen=True)
class BatchRun:
    """A finished batch: its folder, the engine that ran it and every job's result."""

    output: Path
    engine: str
    workers: int
    outcome: BatchOutcome

    def to_dict(self) -> dict[str, Any]:
        """JSON-able: folder, summary file, engine, totals and one entry per job."""
        return {
            "output": str(self.output),
            "summary": str(self.outcome.summary),
            "engine": self.engine,
            "workers": self.workers,
            "totals": self.outcome.totals.model_dump(mode="json"),
            "jobs": [r.model_dump(mode="json") for r in self.outcome.results],
        }


def run_jobs_file(
    jobs_file: Path,
    out: Path,
    *,
    seeds: str | None = None,
    workers: int = 1,
    ray: str | None = None,
    timeout_s: float = DEFAULT_TIMEOUT_S,
    library: Path | None = None,
    planner: str = "offline",
    render: bool = False,
    text_model: Path | None = None,
    max_jobs_per_worker: int = 0,
    on_planned: Callable[[int], None] | None = None,
    on_start: OnStart | None = None,
    on_done: OnDone | None = None,
    on_skip: OnDone | None = None,
) -> BatchRun:
    """Run every job of ``jobs_file`` (each prompt once per seed of ``seeds``, ``A:B``) into
    ``out``: on Ray when ``ray`` names a cluster (local, auto or ray://HOST:PORT), else on
    ``workers`` local worker processes; complete jobs of an earlier run are skipped.

    ``library`` defaults to the default library (built on first use). ``on_planned`` gets the
    number of jobs once everything is checked; ``on_start``, ``on_done`` and ``on_skip`` see the
    jobs as they start, end, or are skipped as complete.
    """
    from holomj.batch.job_list import parse_seeds, read_jobs
    from holomj.batch.local import LocalEngine
    from holomj.batch.ray_engine import RayEngine, import_ray
    from holomj.batch.result import JobOptions
    from holomj.batch.run import run_batch
    from holomj.jobs.library import resolve_library
    from holomj.jobs.plan import check_planner

    checked_planner = check_planner(planner)
    jobs = read_jobs(jobs_file, parse_seeds(seeds))
    if ray is not None:
        import_ray()
    library_root = resolve_library(library)
    _check_inputs(library_root, text_model)
    options = JobOptions(
        library=library_root.absolute(),
        planner=checked_planner,
        render=render,
        text_model=text_model.absolute() if text_model else None,
    )
    engine: Engine
    if ray is not None:
        engine = RayEngine(ray, workers, timeout_s)
    else:
        engine = LocalEngine(workers, timeout_s, max_jobs_per_worker=max_jobs_per_worker)
    if on_planned is not None:
        on_planned(len(jobs))
    outcome = run_batch(
        jobs, out, options, engine, on_start=on_start, on_done=on_done, on_skip=on_skip
    )
    return BatchRun(Path(out), engine.name, engine.workers, outcome)


def _check_inputs(library: Path, text_model: Path | None) -> None:
    """Fail once, before any job starts, on what would fail every job."""
    from holomj.jobs.assets import check_library

    check_library(library)
    if text_model is not None and not text_model.is_dir():
        raise InputError("text model folder not found", where=f"--text-model {text_model}")
