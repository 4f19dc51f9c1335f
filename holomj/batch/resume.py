"""Resuming a batch: which jobs are complete, cleaning half-done ones, one batch per folder.

A job is complete when its folder ``DIR/<id>/`` holds the result marker ``batch_job.json``
(written atomically, last, by the job itself) and the marker names the same job (id, input,
seed). Anything else of that job is half-done: its folder without a marker, and the temp folders
the atomic folder writer leaves beside it (``.<id>.new-*``, ``.<id>.old-*``) when killed.
"""

from __future__ import annotations

import contextlib
import os
import shutil
from collections.abc import Iterator
from pathlib import Path

from pydantic import ValidationError

from holomj.batch.job_list import Job
from holomj.batch.result import JobResult
from holomj.errors import InputError

MARKER = "batch_job.json"
LOCK_FILE = ".batch.lock"


def job_folder(out_dir: Path, job: Job) -> Path:
    """Where ``job`` writes its scene."""
    return Path(out_dir) / job.id


def read_marker(out_dir: Path, job: Job) -> JobResult | None:
    """The result recorded by ``job``'s marker, or None when the job is not complete."""
    path = job_folder(out_dir, job) / MARKER
    try:
        result = JobResult.model_validate_json(path.read_bytes())
    except (OSError, ValidationError, ValueError):
        return None
    return result if result.matches(job) else None


def completed(out_dir: Path, jobs: list[Job]) -> dict[str, JobResult]:
    """The recorded results of the jobs that are complete in ``out_dir``, by job id."""
    found = {}
    for job in jobs:
        result = read_marker(out_dir, job)
        if result is not None:
            found[job.id] = result
    return found


def clean_partial(out_dir: Path, job: Job) -> None:
    """Remove what a half-done ``job`` left in ``out_dir`` (never a complete job's folder)."""
    out_dir = Path(out_dir)
    folder = job_folder(out_dir, job)
    if (folder.exists() or folder.is_symlink()) and read_marker(out_dir, job) is None:
        _remove(folder)
    for pattern in (f".{job.id}.new-*", f".{job.id}.old-*"):
        for leftover in out_dir.glob(pattern):
            _remove(leftover)


def _remove(path: Path) -> None:
    if path.is_dir() and not path.is_symlink():
        shutil.rmtree(path)
    else:
        path.unlink(missing_ok=True)


@contextlib.contextmanager
def batch_lock(out_dir: Path) -> Iterator[None]:
    """Hold an exclusive lock on ``out_dir`` (released by the kernel even after ``kill -9``)."""
    try:
        import fcntl
    except ImportError:  # not POSIX: run without the lock
        yield
        return
    path = Path(out_dir) / LOCK_FILE
    fd = os.open(path, os.O_RDWR | os.O_CREAT, 0o644)
    try:
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:
            raise InputError(
                "another holomj batch is writing this folder",
                where=str(out_dir),
                fix="wait for it to finish, or pick another -o",
            ) from None
        os.ftruncate(fd, 0)
        os.write(fd, f"{os.getpid()}\n".encode())
        yield
    finally:
        os.close(fd)
