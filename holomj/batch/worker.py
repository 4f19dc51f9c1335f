"""The long-lived worker process of the local engine: receives jobs on a pipe, runs them one at
a time, sends back each result.

The worker keeps its process-level caches (the text model, retrieval embeddings) from job to
job, which saves ~10 s per job. It runs in its own process group and dies with its parent
(``PR_SET_PDEATHSIG`` on Linux), so a ``kill -9`` of the batch leaves no worker writing behind
the next run's back. It uses one thread for torch and OpenMP, as Ray workers do, so K workers
fill K cores and both engines compute the same numbers.
"""

from __future__ import annotations

import contextlib
import os
import signal
import sys
from multiprocessing.connection import Connection

from holomj.batch.runner import JobFunction, execute

THREAD_VARIABLES = ("OMP_NUM_THREADS", "MKL_NUM_THREADS", "OPENBLAS_NUM_THREADS")


STARTED = "started"  # sent when a job begins, before its result


def worker_main(conn: Connection, parent_pid: int, function: JobFunction) -> None:
    """Serve ``(job, out_dir, options)`` messages until ``None`` or the pipe closes."""
    _die_with_parent(parent_pid)
    with contextlib.suppress(OSError):
        os.setpgrp()
    for name in THREAD_VARIABLES:
        os.environ.setdefault(name, "1")
    while True:
        try:
            message = conn.recv()
        except (EOFError, OSError):
            return
        if message is None:
            return
        job, out_dir, options = message
        try:
            conn.send(STARTED)  # the job's timeout counts from here, not from the process start
        except (BrokenPipeError, OSError):
            return
        result = execute(function, job, out_dir, options)
        try:
            conn.send(result)
        except (BrokenPipeError, OSError):
            return


def _die_with_parent(parent_pid: int) -> None:
    """Ask Linux to SIGKILL this process when its parent dies; exit if it already has."""
    if sys.platform.startswith("linux"):
        import ctypes

        with contextlib.suppress(OSError, AttributeError):
            libc = ctypes.CDLL(None, use_errno=True)
            pr_set_pdeathsig = 1
            libc.prctl(pr_set_pdeathsig, int(signal.SIGKILL), 0, 0, 0)
    if os.getppid() != parent_pid:
        os._exit(0)
