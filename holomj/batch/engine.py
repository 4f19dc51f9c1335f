"""What an engine is: something that runs jobs and reports each one as it starts and ends."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Protocol

from holomj.batch.job_list import Job
from holomj.batch.result import JobOptions, JobResult

OnStart = Callable[[Job], None]
OnDone = Callable[[JobResult], None]

DEFAULT_TIMEOUT_S = 600.0


@dataclass(frozen=True)
class EngineRun:
    """What every job of one engine run shares: the folder the jobs write into, their
    options, and the hooks told when a job starts and when it is done (exactly once per job)."""

    out_dir: Path
    options: JobOptions
    on_start: OnStart
    on_done: OnDone


class Engine(Protocol):
    """Runs every job once; a job's failure (error, crash, timeout) is a failed result."""

    name: str
    workers: int

    def run(self, jobs: Sequence[Job], run: EngineRun) -> None:
        """Run ``jobs`` writing into ``run.out_dir``; call ``run.on_done`` exactly once per
        job."""
        ...


def timeout_message(seconds: float) -> str:
    """The error of a job stopped by the per-job timeout."""
    return f"timed out after {seconds:g} s (the job was killed; raise --timeout to allow more)"
