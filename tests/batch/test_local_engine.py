"""The local engine: worker processes that survive nothing they should not, and fail one job
at a time (crash, segfault, exception, timeout), with resume and the summary."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest

from holomj.batch.job_list import Job, job_id
from holomj.batch.local import LocalEngine
from holomj.batch.ray_engine import import_ray
from holomj.batch.result import JobOptions
from holomj.batch.resume import MARKER
from holomj.batch.run import run_batch
from holomj.batch.summary import SUMMARY, read_summary
from holomj.errors import InputError
from tests.batch.fake_jobs import fake_job


def make_jobs(*inputs: str) -> list[Job]:
    return [
        Job(id=job_id(n, text, 0), line=n, kind="prompt", input=text, seed=0)
        for n, text in enumerate(inputs, start=1)
    ]


def options(tmp_path: Path) -> JobOptions:
    return JobOptions(library=tmp_path / "unused_library")


def pid(out: Path, job: Job) -> int:
    return int((out / job.id / "pid.txt").read_text())


@pytest.mark.slow
def test_crashes_errors_and_timeouts_fail_only_their_own_job(tmp_path: Path) -> None:
    jobs = make_jobs("ok a", "crash", "segfault", "ok b", "raise", "bad", "hang", "ok unstable")
    out = tmp_path / "runs"
    engine = LocalEngine(workers=2, timeout_s=4.0, function=fake_job)
    seen: list[str] = []
    outcome = run_batch(jobs, out, options(tmp_path), engine, on_done=lambda r: seen.append(r.id))

    by_input = {r.input: r for r in outcome.results}
    assert [r.id for r in outcome.results] == [j.id for j in jobs]
    assert sorted(seen) == sorted(j.id for j in jobs)
    assert by_input["ok a"].status == by_input["ok b"].status == "ok"
    assert by_input["ok unstable"].status == "unstable"
    assert by_input["crash"].error == "worker process died (exit code 3)"
    assert by_input["segfault"].error == "worker process died (killed by SIGSEGV)"
    assert by_input["raise"].error.startswith("internal error ValueError: boom at fake_jobs.py:")
    assert by_input["bad"].error == "0006-bad-s0: bad input"
    assert by_input["hang"].error.startswith("timed out after 4 s")
    assert 4.0 <= by_input["hang"].seconds < 30.0
    assert outcome.totals.failed == 5 and not outcome.all_ok
    for job in jobs:
        folder = out / job.id
        assert (folder / MARKER).is_file() == job.input.startswith("ok"), job.input
        if not job.input.startswith("ok"):
            assert not folder.exists(), f"half-done folder left: {folder}"
    assert not list(out.glob(".*.new-*"))
    assert read_summary(out / SUMMARY) == outcome.results
    # Two at the start, a new one after the crash and after the segfault; none after the
    # timeout (the last job went to the other slot while ``hang`` held its own).
    assert engine.workers_started == 4


@pytest.mark.slow
def test_workers_keep_their_process_between_jobs_unless_told(tmp_path: Path) -> None:
    jobs = make_jobs("ok a", "ok b", "ok c")
    reuse = LocalEngine(workers=1, function=fake_job)
    run_batch(jobs, tmp_path / "reuse", options(tmp_path), reuse)
    assert len({pid(tmp_path / "reuse", j) for j in jobs}) == 1
    assert reuse.workers_started == 1
    assert (tmp_path / "reuse" / jobs[0].id / "env.txt").read_text() == "1"  # one thread

    fresh = LocalEngine(workers=1, max_jobs_per_worker=1, function=fake_job)
    run_batch(jobs, tmp_path / "fresh", options(tmp_path), fresh)
    assert len({pid(tmp_path / "fresh", j) for j in jobs}) == 3
    assert fresh.workers_started == 3

    crash = make_jobs("ok a", "crash", "ok c")
    replaced = LocalEngine(workers=1, function=fake_job)
    outcome = run_batch(crash, tmp_path / "crash", options(tmp_path), replaced)
    assert [r.status for r in outcome.results] == ["ok", "failed", "ok"]
    assert pid(tmp_path / "crash", crash[0]) != pid(tmp_path / "crash", crash[2])


def test_a_rerun_skips_complete_jobs_and_runs_failed_ones_again(tmp_path: Path) -> None:
    out = tmp_path / "runs"
    first = make_jobs("ok a", "raise", "ok b")
    outcome = run_batch(first, out, options(tmp_path), LocalEngine(function=fake_job))
    assert outcome.totals.ran == 3 and outcome.totals.failed == 1
    marker_before = (out / first[0].id / MARKER).stat().st_mtime_ns
    # The user fixed line 2 of the jobs file: its job id changes, the others are complete.
    second = make_jobs("ok a", "ok fixed", "ok b")
    skipped: list[str] = []
    outcome = run_batch(
        second,
        out,
        options(tmp_path),
        LocalEngine(function=fake_job),
        on_skip=lambda r: skipped.append(r.id),
    )
    assert skipped == [second[0].id, second[2].id] == outcome.skipped
    assert outcome.totals.ran == 1 and outcome.all_ok
    assert (out / first[0].id / MARKER).stat().st_mtime_ns == marker_before
    assert [r.id for r in read_summary(out / SUMMARY)] == [j.id for j in second]
    record = json.loads((out / "batch.json").read_text())
    assert record["engine"] == "local" and len(record["jobs"]) == 3


def test_missing_ray_names_the_extra(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(sys.modules, "ray", None)
    with pytest.raises(InputError, match=r"holomj\[ray\]"):
        import_ray()


def test_a_jobs_timeout_does_not_count_its_workers_start_up(tmp_path: Path) -> None:
    # A spawned worker takes longer than 0.3 s to import holomj; the job itself is instant.
    job = Job(id=job_id(1, "ok quick", 0), line=1, kind="prompt", input="ok quick", seed=0)
    engine = LocalEngine(workers=1, timeout_s=0.3, function=fake_job)
    outcome = run_batch([job], tmp_path / "runs", JobOptions(library=tmp_path), engine)
    assert [r.status for r in outcome.results] == ["ok"], outcome.results[0].error
