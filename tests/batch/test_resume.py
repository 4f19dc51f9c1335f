"""Completeness markers, cleaning half-done jobs, the folder lock, summary.jsonl."""

from __future__ import annotations

from pathlib import Path

import pytest

from holomj.batch.job_list import Job
from holomj.batch.result import JobResult, failed_result
from holomj.batch.resume import (
    MARKER,
    batch_lock,
    clean_partial,
    completed,
    read_marker,
)
from holomj.batch.summary import SUMMARY, append_result, read_summary, totals, write_summary
from holomj.errors import InputError

KITCHEN = Job(id="0001-a_kitchen-s0", line=1, kind="prompt", input="a kitchen", seed=0)
KITCHEN_S1 = Job(id="0001-a_kitchen-s1", line=1, kind="prompt", input="a kitchen", seed=1)


def ok_result(job: Job) -> JobResult:
    return JobResult(
        id=job.id,
        input=job.input,
        kind=job.kind,
        seed=job.seed,
        status="ok",
        objects=2,
        stable=2,
        stable_fraction=1.0,
        seconds=1.5,
        output=job.id,
    )


def complete(out: Path, job: Job, result: JobResult | None = None) -> Path:
    folder = out / job.id
    folder.mkdir(parents=True)
    (folder / "scene.xml").write_text("<mujoco/>")
    (folder / MARKER).write_text((result or ok_result(job)).model_dump_json())
    return folder


def test_a_job_is_complete_only_with_its_own_valid_marker(tmp_path: Path) -> None:
    complete(tmp_path, KITCHEN)
    assert read_marker(tmp_path, KITCHEN) == ok_result(KITCHEN)
    other = KITCHEN.model_copy(update={"input": "a large kitchen"})  # the jobs file changed
    assert read_marker(tmp_path, other) is None
    half = tmp_path / KITCHEN_S1.id
    half.mkdir()
    (half / MARKER).write_text('{"id": "0001-a_kitchen-s1", "status": "ok"')  # torn write
    assert read_marker(tmp_path, KITCHEN_S1) is None
    assert set(completed(tmp_path, [KITCHEN, KITCHEN_S1])) == {KITCHEN.id}


def test_clean_partial_removes_half_done_work_but_not_complete_jobs(tmp_path: Path) -> None:
    done = complete(tmp_path, KITCHEN)
    half = tmp_path / KITCHEN_S1.id
    (half / "assets").mkdir(parents=True)
    temp_new = tmp_path / f".{KITCHEN_S1.id}.new-abc123"
    temp_old = tmp_path / f".{KITCHEN_S1.id}.old-def456"
    temp_new.mkdir()
    temp_old.mkdir()
    unrelated = tmp_path / "notes.txt"
    unrelated.write_text("mine")
    clean_partial(tmp_path, KITCHEN)
    clean_partial(tmp_path, KITCHEN_S1)
    assert (done / "scene.xml").is_file()
    assert not half.exists() and not temp_new.exists() and not temp_old.exists()
    assert unrelated.read_text() == "mine"


def test_the_lock_refuses_a_second_batch_and_is_released(tmp_path: Path) -> None:
    with (
        batch_lock(tmp_path),
        pytest.raises(InputError, match="another holomj batch"),
        batch_lock(tmp_path),
    ):
        pass
    with batch_lock(tmp_path):
        pass


def test_summary_append_then_rewrite_and_totals(tmp_path: Path) -> None:
    failed = failed_result(KITCHEN_S1, "worker process died\n(killed by SIGSEGV)", 2.0)
    assert failed.error == "worker process died (killed by SIGSEGV)"
    append_result(tmp_path, ok_result(KITCHEN))
    append_result(tmp_path, failed)
    append_result(tmp_path, ok_result(KITCHEN_S1))  # a later run's result for the same job
    assert len(read_summary(tmp_path / SUMMARY)) == 3
    write_summary(tmp_path, [ok_result(KITCHEN), ok_result(KITCHEN_S1)])
    assert read_summary(tmp_path / SUMMARY) == [ok_result(KITCHEN), ok_result(KITCHEN_S1)]
    line = (tmp_path / SUMMARY).read_text().splitlines()[0]
    for key in ("id", "input", "seed", "status", "objects", "stable_fraction", "seconds", "error"):
        assert f'"{key}":' in line

    t = totals([ok_result(KITCHEN), failed], skipped=1, ran=1, wall_s=10.0)
    assert (t.jobs, t.ok, t.failed, t.skipped, t.ran) == (2, 1, 1, 1, 1)
    assert t.scenes_per_hour == 0.0  # the only scene written was made by an earlier run
