"""The Ray engine: the same job function as Ray tasks, so a batch scales out to a cluster.

``address``: ``local`` starts a private Ray instance on this machine with ``workers`` CPUs;
``auto`` joins the cluster started with ``ray start`` on this machine; ``ray://HOST:PORT``
connects a Ray client to a remote head. Every node needs holomj installed and must see ``DIR``
and the asset library at the same paths (a shared filesystem), since each task writes its scene
folder itself. When Ray is already initialised in this process, that session is used as is.

Isolation relies on Ray's worker processes: each task runs in a Ray worker with
``max_retries=0``; a worker that dies (segfault, ``os._exit``, out of memory) fails its task
alone with ``WorkerCrashedError``, and a task past its timeout is cancelled with ``force=True``,
which kills its worker. Ray reuses workers between tasks, so the text model is loaded once per
worker, as in the local engine. At most ``workers`` tasks are in flight, so a task starts when it
is submitted and its timeout counts from then.
"""

from __future__ import annotations

import contextlib
import time
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from holomj.batch.engine import DEFAULT_TIMEOUT_S, OnDone, OnStart, timeout_message
from holomj.batch.job_list import Job
from holomj.batch.result import JobOptions, JobResult, failed_result
from holomj.batch.resume import clean_partial
from holomj.batch.runner import JobFunction, execute, run_job
from holomj.errors import InputError

RAY_FIX = "pip install 'holomj[ray]'"
ADDRESS_FIX = "use local, auto (a cluster started with 'ray start --head') or ray://HOST:PORT"
CANCEL_WAIT_S = 30.0


def import_ray() -> Any:
    """The ``ray`` module, or an InputError naming the extra that provides it."""
    try:
        import ray
    except ImportError:
        raise InputError("Ray is not installed", where="--ray", fix=RAY_FIX) from None
    return ray


def _task(function: JobFunction, job: Job, out_dir: Path, options: JobOptions) -> JobResult:
    """The body of every Ray task: the job function, its exceptions turned into results."""
    return execute(function, job, out_dir, options)


class RayEngine:
    """Runs jobs as Ray tasks, at most ``workers`` at a time (see the module docstring)."""

    name = "ray"

    def __init__(
        self,
        address: str = "local",
        workers: int = 1,
        timeout_s: float = DEFAULT_TIMEOUT_S,
        *,
        function: JobFunction = run_job,
    ) -> None:
        """``function``: the job function (a module-level function importable on the workers)."""
        if not address.strip():
            raise InputError("empty Ray address", where="--ray", fix=ADDRESS_FIX)
        self.address = address.strip()
        self.workers = max(1, workers)
        self.timeout_s = timeout_s
        self.function = function

    def run(
        self,
        jobs: Sequence[Job],
        out_dir: Path,
        options: JobOptions,
        on_start: OnStart,
        on_done: OnDone,
    ) -> None:
        """Run ``jobs`` as Ray tasks; connect first and disconnect afterwards."""
        ray = import_ray()
        owned = self._connect(ray)
        try:
            self._run(ray, list(jobs), Path(out_dir).absolute(), options, on_start, on_done)
        finally:
            if owned:
                ray.shutdown()

    def _connect(self, ray: Any) -> bool:
        """Initialise Ray for ``address``; True when this engine owns the session."""
        if ray.is_initialized():
            return False
        kwargs: dict[str, Any] = {"log_to_driver": False, "configure_logging": False}
        if self.address == "local":
            kwargs.update(num_cpus=self.workers, include_dashboard=False)
        else:
            kwargs["address"] = self.address
        try:
            ray.init(**kwargs)
        except (ConnectionError, RuntimeError, ValueError, TimeoutError) as err:
            first = str(err).strip().splitlines()[0] if str(err).strip() else type(err).__name__
            raise InputError(
                f"cannot start or reach Ray at {self.address!r}: {first}",
                where="--ray",
                fix=ADDRESS_FIX,
            ) from None
        return True

    def _run(
        self,
        ray: Any,
        jobs: list[Job],
        out_dir: Path,
        options: JobOptions,
        on_start: OnStart,
        on_done: OnDone,
    ) -> None:
        remote = ray.remote(num_cpus=1, max_retries=0)(_task)
        pending = list(reversed(jobs))
        inflight: dict[Any, tuple[Job, float]] = {}
        while pending or inflight:
            while pending and len(inflight) < self.workers:
                job = pending.pop()
                ref = remote.remote(self.function, job, out_dir, options)
                inflight[ref] = (job, time.monotonic())
                on_start(job)
            deadline = min(started for _, started in inflight.values()) + self.timeout_s
            ready, _ = ray.wait(
                list(inflight), num_returns=1, timeout=max(0.0, deadline - time.monotonic())
            )
            for ref in ready:
                job, started = inflight.pop(ref)
                on_done(self._result(ray, ref, job, started, out_dir))
            now = time.monotonic()
            for ref, (job, started) in list(inflight.items()):
                if now - started >= self.timeout_s:
                    del inflight[ref]
                    self._cancel(ray, ref)
                    clean_partial(out_dir, job)
                    on_done(failed_result(job, timeout_message(self.timeout_s), now - started))

    @staticmethod
    def _result(ray: Any, ref: Any, job: Job, started: float, out_dir: Path) -> JobResult:
        """The task's result, or a failed result saying how Ray lost it."""
        from ray import exceptions

        try:
            result = ray.get(ref)
        except exceptions.WorkerCrashedError:
            error = "worker process died (Ray WorkerCrashedError)"
        except exceptions.RayError as err:
            text = str(err).strip().splitlines()
            error = f"Ray {type(err).__name__}: {text[0] if text else ''}".strip()
        else:
            if isinstance(result, JobResult):
                return result
            error = f"unexpected task result {type(result).__name__}"
        clean_partial(out_dir, job)
        return failed_result(job, error, time.monotonic() - started)

    @staticmethod
    def _cancel(ray: Any, ref: Any) -> None:
        """Kill the task's worker and wait (bounded) until Ray confirms it is gone."""
        from ray import exceptions

        ray.cancel(ref, force=True)
        with contextlib.suppress(exceptions.RayError):
            ray.get(ref, timeout=CANCEL_WAIT_S)
