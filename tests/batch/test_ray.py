"""The Ray engine on a local Ray instance started by the test: same scenes as the local engine,
and a crash or a timeout fails only its own task."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from holomj.batch.job_list import Job, job_id
from holomj.batch.ray_engine import RayEngine
from holomj.batch.result import JobOptions
from holomj.batch.resume import MARKER
from holomj.batch.run import run_batch
from holomj.cli import app
from tests.batch import fake_jobs

ray = pytest.importorskip("ray")


def clock_cut(folder: Path) -> bool:
    """Whether a room's layout search was cut by the wall clock (then it may vary per run)."""
    layout = json.loads((folder / "generate.json").read_text())["layout"]
    return any("wall clock" in str(room.get("status", "")) for room in layout.values())


@pytest.mark.slow
def test_same_seeds_give_byte_identical_scenes_on_both_engines(
    tmp_path: Path, default_library
) -> None:
    jobs = tmp_path / "jobs.txt"
    jobs.write_text("a small kitchen\n")
    runner = CliRunner()
    common = ["--seeds", "0:2", "--library", str(default_library.root), "--json"]
    local = runner.invoke(app, ["batch", str(jobs), "-o", str(tmp_path / "local"), *common])
    assert local.exit_code == 0, local.output
    # One worker each: two model loads at once on a 2-core machine slow the layout enough to
    # hit its wall-clock safety net (see clock_cut below).
    on_ray = runner.invoke(
        app, ["batch", str(jobs), "-o", str(tmp_path / "ray"), "--ray", "local", *common]
    )
    assert on_ray.exit_code == 0, on_ray.output
    assert not ray.is_initialized()  # the engine shut down the instance it started

    local_report, ray_report = json.loads(local.stdout), json.loads(on_ray.stdout)
    assert (local_report["engine"], ray_report["engine"]) == ("local", "ray")
    ids = [j["id"] for j in local_report["jobs"]]
    assert ids == ["0001-a_small_kitchen-s0", "0001-a_small_kitchen-s1"]
    assert [j["id"] for j in ray_report["jobs"]] == ids
    for key in ("status", "objects", "stable"):
        assert [j[key] for j in ray_report["jobs"]] == [j[key] for j in local_report["jobs"]]
    cut = [f"{e}/{j}" for e in ("local", "ray") for j in ids if clock_cut(tmp_path / e / j)]
    if cut:
        pytest.xfail(f"layout stopped by the wall clock under load in {cut}: not comparable")
    for job in ids:
        xml = (tmp_path / "ray" / job / "scene.xml").read_bytes()
        assert xml == (tmp_path / "local" / job / "scene.xml").read_bytes(), job
        assert (tmp_path / "ray" / job / MARKER).is_file()
    seeds = {(tmp_path / "ray" / job / "scene.xml").read_bytes() for job in ids}
    assert len(seeds) == 2


@pytest.mark.slow
def test_a_crashed_or_timed_out_task_fails_only_its_job(tmp_path: Path) -> None:
    # The timeout counts from when a job starts on a running worker: a slow worker start-up on a
    # loaded machine (CI once took over 8 s) must not time out quick jobs.
    # Ship the fake job functions by value: the Ray workers need not import the tests package.
    ray.cloudpickle.register_pickle_by_value(fake_jobs)
    try:
        inputs = ["ok a", "crash", "hang", "raise", "ok b"]
        jobs = [
            Job(id=job_id(n, text, 0), line=n, kind="prompt", input=text, seed=0)
            for n, text in enumerate(inputs, start=1)
        ]
        engine = RayEngine("local", workers=2, timeout_s=8.0, function=fake_jobs.fake_job)
        outcome = run_batch(jobs, tmp_path / "runs", JobOptions(library=tmp_path), engine)
    finally:
        ray.cloudpickle.unregister_pickle_by_value(fake_jobs)
    by_input = {r.input: r for r in outcome.results}
    assert by_input["ok a"].status == by_input["ok b"].status == "ok"
    assert by_input["crash"].error == "worker process died (Ray ActorDiedError)"
    assert by_input["hang"].error.startswith("timed out after 8 s")
    assert by_input["raise"].error.startswith("internal error ValueError: boom")
    assert not (tmp_path / "runs" / jobs[1].id).exists()  # the crash's half-done folder
    assert not (tmp_path / "runs" / jobs[2].id).exists()
    assert outcome.totals.failed == 3 and not ray.is_initialized()
