"""End to end, real scenes: ``holomj batch`` killed with SIGKILL mid-run, then run again,
completes only the remaining jobs; prompt jobs and house jobs both leave a validated scene."""

from __future__ import annotations

import json
import os
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from holomj.batch.resume import MARKER
from holomj.batch.summary import SUMMARY, read_summary
from tests.conftest import FIXTURES

REPO = Path(__file__).resolve().parents[2]
JOB_IDS = [
    "0002-a_small_kitchen-s0",
    "0002-a_small_kitchen-s1",
    "0002-a_small_kitchen-s2",
    "0003-two_room_scene",
    "0004-a_bathroom_with_white_tiles-s0",
    "0004-a_bathroom_with_white_tiles-s1",
    "0004-a_bathroom_with_white_tiles-s2",
]
KILL_AFTER_MARKERS = 2
WAIT_S = 240.0


def batch_args(jobs: Path, out: Path, library: Path, *extra: str) -> list[str]:
    return [
        sys.executable,
        "-m",
        "holomj",
        "batch",
        str(jobs),
        "-o",
        str(out),
        "--library",
        str(library),
        "--workers",
        "1",
        "--seeds",
        "0:3",
        *extra,
    ]


def markers(out: Path) -> list[Path]:
    return sorted(out.glob(f"*/{MARKER}"))


def children(pid: int) -> list[int]:
    """Pids whose parent is ``pid`` (Linux /proc)."""
    found = []
    for stat in Path("/proc").glob("[0-9]*/stat"):
        try:
            fields = stat.read_text().rsplit(")", 1)[1].split()
        except OSError:
            continue
        if int(fields[1]) == pid:
            found.append(int(stat.parent.name))
    return found


def alive(pid: int) -> bool:
    try:
        state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except OSError:
        return False
    return state != "Z"


@pytest.mark.slow
@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="uses /proc and SIGKILL")
def test_kill_9_mid_run_then_rerun_completes_only_the_remaining_jobs(
    tmp_path: Path, default_library
) -> None:
    shutil.copy(FIXTURES / "two_room_scene.json", tmp_path / "two_room_scene.json")
    jobs = tmp_path / "jobs.txt"
    jobs.write_text(
        "# kill test\na small kitchen\ntwo_room_scene.json\na bathroom with white tiles\n"
    )
    out = tmp_path / "runs"

    batch = subprocess.Popen(
        batch_args(jobs, out, default_library.root, "--quiet"),
        cwd=REPO,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
    )
    deadline = time.monotonic() + WAIT_S
    while len(markers(out)) < KILL_AFTER_MARKERS:
        assert batch.poll() is None, batch.communicate()
        assert time.monotonic() < deadline, "the batch made no progress"
        time.sleep(0.05)
    workers = children(batch.pid)
    assert workers, "the batch runs its jobs in worker processes"
    os.kill(batch.pid, signal.SIGKILL)
    batch.wait()
    done_before = {p.parent.name: p.stat().st_mtime_ns for p in markers(out)}
    assert KILL_AFTER_MARKERS <= len(done_before) < len(JOB_IDS)
    logged = [r.id for r in read_summary(out / SUMMARY)]
    assert set(logged) <= set(done_before)  # appended + fsynced as each job finished
    for pid in workers:  # the workers die with the batch (no job keeps writing)
        limit = time.monotonic() + 10
        while alive(pid) and time.monotonic() < limit:
            time.sleep(0.05)
        assert not alive(pid), f"worker {pid} outlived the batch"

    # What a kill during the export stage leaves: the atomic writer's temp folder, and a job
    # folder renamed into place before its marker was written.
    pending = [job for job in JOB_IDS if job not in done_before]
    (out / f".{pending[-1]}.new-x1y2z3" / "assets").mkdir(parents=True)
    (out / pending[-2]).mkdir(exist_ok=True)
    (out / pending[-2] / "scene.xml").write_text("<mujoco/>")

    rerun = subprocess.run(
        batch_args(jobs, out, default_library.root, "--json"),
        cwd=REPO,
        capture_output=True,
        text=True,
        timeout=WAIT_S,
    )
    assert rerun.returncode == 0, rerun.stderr
    report = json.loads(rerun.stdout)
    totals = report["totals"]
    assert totals["skipped"] == len(done_before)
    assert totals["ran"] == len(JOB_IDS) - len(done_before)
    assert totals["ok"] + totals["unstable"] == len(JOB_IDS) and totals["failed"] == 0
    for job, mtime in done_before.items():  # complete jobs were not touched
        assert (out / job / MARKER).stat().st_mtime_ns == mtime

    results = read_summary(out / SUMMARY)
    assert [r.id for r in results] == JOB_IDS
    assert sorted(p.name for p in out.iterdir() if not p.name.startswith(".")) == sorted(
        [*JOB_IDS, SUMMARY, "batch.json"]
    )
    assert not [p for p in out.iterdir() if ".new-" in p.name or ".old-" in p.name]
    for result in results:
        folder = out / result.id
        assert (folder / "scene.xml").is_file() and not (folder / "renders").exists()
        validated = json.loads((folder / "report.json").read_text())
        assert validated["counts"]["objects"] == result.objects
        assert validated["counts"]["stable"] == result.stable
        assert result.status == ("ok" if validated["ok"] else "unstable")
        assert result.seconds > 0
    house = next(r for r in results if r.kind == "house")
    assert house.seed is None and (out / house.id / "import_report.json").is_file()
    kitchens = [out / job / "scene.xml" for job in JOB_IDS[:3]]
    assert len({p.read_bytes() for p in kitchens}) == 3  # seeds differ, so do the scenes
