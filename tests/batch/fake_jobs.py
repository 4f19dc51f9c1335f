"""Job functions for engine tests: they behave as the job's input says (no scene is built).

``ok ...`` writes the job folder and its marker like the real job (the worker's pid goes into
``pid.txt``), ``crash`` calls ``os._exit``, ``segfault`` dereferences NULL, ``hang`` sleeps past
any test timeout, ``raise`` raises a ValueError and ``bad`` an InputError.
"""

from __future__ import annotations

import ctypes
import os
import time
from pathlib import Path

from holomj.atomic import write_file
from holomj.batch.job_list import Job
from holomj.batch.result import JobOptions, JobResult
from holomj.batch.resume import MARKER, job_folder
from holomj.errors import InputError


def fake_job(job: Job, out_dir: Path, options: JobOptions) -> JobResult:
    """Do what ``job.input`` names (see the module docstring)."""
    word = job.input.split()[0]
    folder = job_folder(out_dir, job)
    if word == "crash":
        folder.mkdir()  # a half-done folder the engine must clean up
        os._exit(3)
    if word == "segfault":
        ctypes.string_at(0)
    if word == "hang":
        folder.mkdir()
        time.sleep(120)
    if word == "raise":
        raise ValueError("boom")
    if word == "bad":
        raise InputError("bad input", where=job.id)
    folder.mkdir()
    (folder / "pid.txt").write_text(str(os.getpid()))
    (folder / "env.txt").write_text(os.environ.get("OMP_NUM_THREADS", ""))
    result = JobResult(
        id=job.id,
        input=job.input,
        kind=job.kind,
        seed=job.seed,
        status="unstable" if "unstable" in job.input else "ok",
        objects=4,
        stable=3 if "unstable" in job.input else 4,
        stable_fraction=0.75 if "unstable" in job.input else 1.0,
        seconds=0.01,
        output=job.id,
    )
    write_file(folder / MARKER, result.model_dump_json())
    return result
