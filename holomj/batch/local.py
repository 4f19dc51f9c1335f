"""The local engine: K slots, each a long-lived worker process that runs one job at a time.

Why long-lived workers rather than a fresh process per job: a fresh process pays the imports and
the text model (~10 s on a 2-core machine) for every job, while a scene takes ~1-3 s; see
``scripts/bench_batch.py`` (``max_jobs_per_worker=1`` is the fresh-process mode, kept for
comparison and for jobs that must not share a process).

A job's timeout counts from when its worker says it has begun the job, so the start-up of a
fresh worker (imports; slow on a loaded machine) does not count against it; a worker that has not
begun within ``WORKER_START_LIMIT_S`` fails the job.

Isolation is kept: the parent enforces each job's timeout by killing the worker's process group,
and a worker that dies (segfault, ``os._exit``, out of memory) fails only the job it was running.
Either way the slot starts a new worker for its next job and the job's leftovers are removed.
"""

from __future__ import annotations

import contextlib
import multiprocessing
import os
import signal
import time
from collections import deque
from collections.abc import Sequence
from dataclasses import dataclass
from multiprocessing.connection import Connection, wait
from multiprocessing.process import BaseProcess
from pathlib import Path

from holomj.batch.engine import DEFAULT_TIMEOUT_S, EngineRun, timeout_message
from holomj.batch.job_list import Job
from holomj.batch.result import JobOptions, JobResult, failed_result
from holomj.batch.resume import clean_partial
from holomj.batch.runner import JobFunction, run_job
from holomj.batch.worker import STARTED, worker_main

STOP_GRACE_S = 5.0
WORKER_START_LIMIT_S = 300.0  # a worker that has not begun its job by then fails it


@dataclass
class _Slot:
    """One worker process and the job it is running."""

    index: int
    process: BaseProcess | None = None
    conn: Connection | None = None
    job: Job | None = None
    sent: float = 0.0  # when the job was handed over
    started: float | None = None  # when the worker began it (its timeout counts from here)
    jobs_run: int = 0

    def deadline(self, timeout_s: float) -> float:
        """When the job times out, or (not begun yet) when its worker is too slow to start."""
        if self.started is None:
            return self.sent + WORKER_START_LIMIT_S
        return self.started + timeout_s


class LocalEngine:
    """A pool of ``workers`` worker processes on this machine (``multiprocessing`` spawn)."""

    name = "local"

    def __init__(
        self,
        workers: int = 1,
        timeout_s: float = DEFAULT_TIMEOUT_S,
        *,
        max_jobs_per_worker: int = 0,
        function: JobFunction = run_job,
    ) -> None:
        """``max_jobs_per_worker``: replace a worker after that many jobs (0: never; 1: a fresh
        process per job). ``function``: the job function (a module-level function)."""
        self.workers = max(1, workers)
        self.timeout_s = timeout_s
        self.max_jobs_per_worker = max(0, max_jobs_per_worker)
        self.function = function
        self.workers_started = 0
        self._context = multiprocessing.get_context("spawn")

    def run(self, jobs: Sequence[Job], run: EngineRun) -> None:
        """Run ``jobs``, at most ``workers`` at a time; see the module docstring."""
        out_dir = run.out_dir
        pending = deque(jobs)
        slots = [_Slot(i) for i in range(min(self.workers, len(pending)))]
        try:
            while pending or any(s.job is not None for s in slots):
                for slot in slots:
                    if slot.job is None and pending:
                        job = pending.popleft()
                        self._assign(slot, job, out_dir, run.options)
                        run.on_start(job)
                self._wait(slots)
                for slot in slots:
                    result = self._collect(slot, out_dir)
                    if result is not None:
                        run.on_done(result)
        finally:
            for slot in slots:
                self._stop(slot, graceful=slot.job is None)

    def _assign(self, slot: _Slot, job: Job, out_dir: Path, options: JobOptions) -> None:
        """Send ``job`` to ``slot``'s worker, starting one if it has none."""
        message = (job, Path(out_dir).absolute(), options)
        if slot.process is None or slot.conn is None or not slot.process.is_alive():
            self._stop(slot, graceful=False)
            conn = self._start(slot)
        else:
            conn = slot.conn
        try:
            conn.send(message)
        except (BrokenPipeError, OSError):
            # The idle worker died since the check: start a fresh one and try once more.
            self._stop(slot, graceful=False)
            self._start(slot).send(message)
        slot.job = job
        slot.sent, slot.started = time.monotonic(), None

    def _start(self, slot: _Slot) -> Connection:
        """Start a worker process for ``slot``; return the parent's end of its pipe."""
        parent_end, child_end = self._context.Pipe(duplex=True)
        process = self._context.Process(
            target=worker_main,
            args=(child_end, os.getpid(), self.function),
            name=f"holomj-batch-{slot.index}",
        )
        process.start()
        child_end.close()
        slot.process, slot.conn, slot.jobs_run = process, parent_end, 0
        self.workers_started += 1
        return parent_end

    def _wait(self, slots: list[_Slot]) -> None:
        """Block until a busy worker answers or dies, or the earliest deadline passes."""
        busy = [s for s in slots if s.job is not None]
        if not busy:
            return
        now = time.monotonic()
        timeout = max(0.0, min(s.deadline(self.timeout_s) for s in busy) - now)
        handles: list[Connection | int] = []
        for slot in busy:
            assert slot.conn is not None and slot.process is not None
            handles += [slot.conn, slot.process.sentinel]
        wait(handles, timeout=timeout)

    def _collect(self, slot: _Slot, out_dir: Path) -> JobResult | None:
        """The result of ``slot``'s job if it has ended (answered, died or timed out)."""
        job = slot.job
        if job is None or slot.conn is None or slot.process is None:
            return None
        result: JobResult | None = None
        try:
            while result is None and slot.conn.poll():
                message = slot.conn.recv()
                if message == STARTED:
                    slot.started = time.monotonic()
                else:
                    result = message
        except (EOFError, OSError):
            result = None
        now = time.monotonic()
        elapsed = now - (slot.sent if slot.started is None else slot.started)
        if result is not None:
            slot.job = None
            slot.jobs_run += 1
            if self.max_jobs_per_worker and slot.jobs_run >= self.max_jobs_per_worker:
                self._stop(slot, graceful=True)
            return result
        if not slot.process.is_alive():
            slot.process.join()
            error = f"worker process died ({_exit_reason(slot.process.exitcode)})"
        elif slot.started is None and now >= slot.deadline(self.timeout_s):
            error = f"worker process did not start within {WORKER_START_LIMIT_S:.0f} s"
        elif slot.started is not None and now >= slot.deadline(self.timeout_s):
            error = timeout_message(self.timeout_s)
        else:
            return None
        self._stop(slot, graceful=False)
        slot.job = None
        clean_partial(out_dir, job)
        return failed_result(job, error, elapsed)

    def _stop(self, slot: _Slot, *, graceful: bool) -> None:
        """End ``slot``'s worker: ask it to exit when idle, else kill its process group."""
        process, conn = slot.process, slot.conn
        slot.process, slot.conn = None, None
        if process is None:
            return
        if graceful and process.is_alive() and conn is not None:
            with contextlib.suppress(OSError):
                conn.send(None)
            process.join(STOP_GRACE_S)
        if process.is_alive() and process.pid is not None:
            with contextlib.suppress(OSError):
                os.killpg(process.pid, signal.SIGKILL)
            with contextlib.suppress(OSError):
                process.kill()
        process.join()
        if conn is not None:
            conn.close()
        with contextlib.suppress(ValueError):
            process.close()


def _exit_reason(code: int | None) -> str:
    """``exit code 3`` or ``killed by SIGSEGV`` from a process exit code."""
    if code is None:
        return "unknown exit"
    if code < 0:
        try:
            return f"killed by {signal.Signals(-code).name}"
        except ValueError:
            return f"killed by signal {-code}"
    return f"exit code {code}"
