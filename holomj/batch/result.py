"""Pure data shared by the parent and the workers: the options of every job, a job's result."""

from __future__ import annotations

from pathlib import Path
from typing import Literal

from pydantic import Field

from holomj.batch.job_list import Job
from holomj.spec.base import FrozenModel

Status = Literal["ok", "unstable", "failed"]


class JobOptions(FrozenModel):
    """What every job of a batch shares (the library is resolved once, in the parent)."""

    library: Path
    planner: Literal["offline", "llm"] = "offline"
    render: bool = False
    text_model: Path | None = None
    check_seconds: float = Field(default=1.0, ge=0.0, le=60.0)


class JobResult(FrozenModel):
    """One line of ``summary.jsonl``; also the job's result marker ``DIR/<id>/batch_job.json``.

    ``status`` is ``ok`` when the scene was written and validated ok, ``unstable`` when it was
    written but did not validate ok (an unstable object, a penetration, a MuJoCo warning), and
    ``failed`` when no scene was written (bad input, an error, a crash, a timeout: see ``error``).
    """

    id: str
    input: str
    kind: Literal["prompt", "house"]
    seed: int | None = None
    status: Status
    objects: int | None = None
    stable: int | None = None
    stable_fraction: float | None = Field(default=None, ge=0.0, le=1.0)
    seconds: float = Field(ge=0.0)
    moved: int | None = Field(default=None, description="House jobs: objects moved to stand.")
    left_out: int | None = Field(default=None, description="House jobs: objects left out.")
    substituted: int | None = Field(default=None, description="House jobs: stand-in assets.")
    error: str | None = None
    output: str | None = Field(default=None, description="The job's folder, relative to DIR.")

    def matches(self, job: Job) -> bool:
        """Whether this result belongs to ``job`` (same id, input and seed)."""
        return (self.id, self.input, self.seed, self.kind) == (
            job.id,
            job.input,
            job.seed,
            job.kind,
        )


def failed_result(job: Job, error: str, seconds: float) -> JobResult:
    """The result of a job that wrote no scene."""
    return JobResult(
        id=job.id,
        input=job.input,
        kind=job.kind,
        seed=job.seed,
        status="failed",
        seconds=round(max(seconds, 0.0), 3),
        error=" ".join(error.split())[:2000] or "failed",
    )
