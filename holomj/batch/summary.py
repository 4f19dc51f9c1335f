"""``summary.jsonl`` (one line per job) and the totals of a batch.

While a batch runs, each finished job's line is appended and fsynced, so the file can be
followed live and survives ``kill -9``; at the end it is rewritten atomically with exactly one
line per job of the jobs file, in job order (jobs completed by an earlier run included).
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from pydantic import Field

from holomj.atomic import write_file
from holomj.batch.files import append_line_synced
from holomj.batch.result import JobResult
from holomj.spec.base import FrozenModel

SUMMARY = "summary.jsonl"


def summary_line(result: JobResult) -> str:
    """The JSON line of ``result`` (every field, nulls included)."""
    return result.model_dump_json()


def append_result(out_dir: Path, result: JobResult) -> None:
    """Append ``result`` to ``out_dir/summary.jsonl`` durably."""
    append_line_synced(Path(out_dir) / SUMMARY, summary_line(result))


def write_summary(out_dir: Path, results: Sequence[JobResult]) -> Path:
    """Replace ``out_dir/summary.jsonl`` with ``results``, one line each; return its path."""
    path = Path(out_dir) / SUMMARY
    write_file(path, "".join(summary_line(r) + "\n" for r in results))
    return path


def read_summary(path: Path) -> list[JobResult]:
    """The results in a ``summary.jsonl`` file (for scripts and tests)."""
    lines = Path(path).read_text(encoding="utf-8").splitlines()
    return [JobResult.model_validate_json(line) for line in lines if line.strip()]


class BatchTotals(FrozenModel):
    """Counts and throughput of a batch run."""

    jobs: int = Field(ge=0)
    ok: int = Field(ge=0)
    unstable: int = Field(ge=0)
    failed: int = Field(ge=0)
    skipped: int = Field(ge=0, description="Complete before this run, not run again.")
    ran: int = Field(ge=0, description="Run by this run.")
    wall_s: float = Field(ge=0.0, description="Wall time of this run.")
    scenes_per_hour: float = Field(
        ge=0.0, description="Scenes written by this run (ok or unstable) per hour of wall time."
    )


def totals(results: Sequence[JobResult], skipped: int, ran: int, wall_s: float) -> BatchTotals:
    """Totals over every job's latest result; throughput over the jobs this run ran."""
    ok = sum(r.status == "ok" for r in results)
    unstable = sum(r.status == "unstable" for r in results)
    written = ok + unstable - skipped
    return BatchTotals(
        jobs=len(results),
        ok=ok,
        unstable=unstable,
        failed=sum(r.status == "failed" for r in results),
        skipped=skipped,
        ran=ran,
        wall_s=round(wall_s, 3),
        scenes_per_hour=round(max(written, 0) * 3600.0 / wall_s, 1) if wall_s > 0 else 0.0,
    )
