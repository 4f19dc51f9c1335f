"""The Ray engine: the same job function run by Ray workers, so a batch scales out to a cluster.

``address``: ``local`` starts a private Ray instance on this machine with ``workers`` CPUs;
``auto`` joins the cluster started with ``ray start`` on this machine; ``ray://HOST:PORT``
connects a Ray client to a remote head. Every node needs holomj installed and must see ``DIR``
and the asset library at the same paths (a shared filesystem), since each task writes its scene
folder itself. When Ray is already initialised in this process, that session is used as is.

Each of the ``workers`` slots is a Ray actor (one worker process, one CPU) that runs one job at a
time, so the text model is loaded once per worker, as in the local engine. A job is handed to a
slot only once its actor has started, so a job's timeout counts from when it starts running, not
from when a (possibly slow, loaded or remote) worker process is being brought up. An actor that
dies (segfault, ``os._exit``, out of memory) fails its job alone; a job past its timeout has its
actor killed. Either way a fresh actor takes the slot.
"""

from __future__ import annotations

import contextlib
import time
from collections.abc import Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

from holomj.batch.engine import DEFAULT_TIMEOUT_S, EngineRun, OnDone, timeout_message
from holomj.batch.job_list import Job
from holomj.batch.result import JobOptions, JobResult, failed_result
from holomj.batch.resume import clean_partial
from holomj.batch.runner import JobFunction, execute, run_job
from holomj.errors import InputError

RAY_FIX = "pip install 'holomj[ray]'"
ADDRESS_FIX = "use local, auto (a cluster started with 'ray start --head') or ray://HOST:PORT"
CANCEL_WAIT_S = 30.0
MAX_START_FAILURES = 3  # worker actors that fail to start, in a row, before the batch gives up


def import_ray() -> Any:
    """The ``ray`` module, or an InputError naming the extra that provides it."""
    try:
        import ray
    except ImportError:
        raise InputError("Ray is not installed", where="--ray", fix=RAY_FIX) from None
    return ray


class JobWorker:
    """The body of every worker actor: runs job functions, their exceptions turned into results."""

    def ready(self) -> bool:
        """Answered once the actor's process is up."""
        return True

    def run(self, function: JobFunction, job: Job, out_dir: Path, options: JobOptions) -> JobResult:
        """Run one job."""
        return execute(function, job, out_dir, options)


@dataclass
class _Slots:
    """The worker actors by state: starting (keyed by their ready() ref), idle, or busy (keyed by
    their run() ref, with the job and the time it started)."""

    starting: dict[Any, Any] = field(default_factory=dict)
    idle: list[Any] = field(default_factory=list)
    busy: dict[Any, tuple[Any, Job, float]] = field(default_factory=dict)

    def count(self) -> int:
        return len(self.starting) + len(self.idle) + len(self.busy)


class RayEngine:
    """Runs jobs on Ray worker actors, at most ``workers`` at a time (see the module docstring)."""

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

    def run(self, jobs: Sequence[Job], run: EngineRun) -> None:
        """Run ``jobs`` on Ray workers; connect first and disconnect afterwards."""
        ray = import_ray()
        owned = self._connect(ray)
        try:
            self._run(ray, list(jobs), replace(run, out_dir=Path(run.out_dir).absolute()))
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
            raise InputError(
                f"cannot start or reach Ray at {self.address!r}: {_first_line(err)}",
                where="--ray",
                fix=ADDRESS_FIX,
            ) from None
        return True

    def _run(self, ray: Any, jobs: list[Job], run: EngineRun) -> None:
        out_dir, on_done = run.out_dir, run.on_done
        actor_class = ray.remote(num_cpus=1, max_restarts=0, max_task_retries=0)(JobWorker)
        pending = list(reversed(jobs))
        slots = _Slots()
        start_failures = 0
        try:
            while pending or slots.busy:
                while slots.count() < min(self.workers, len(pending) + len(slots.busy)):
                    actor = actor_class.remote()
                    slots.starting[actor.ready.remote()] = actor
                while pending and slots.idle:
                    job = pending.pop()
                    actor = slots.idle.pop()
                    ref = actor.run.remote(self.function, job, out_dir, run.options)
                    slots.busy[ref] = (actor, job, time.monotonic())
                    run.on_start(job)
                timeout = None
                if slots.busy:
                    first = min(started for _, _, started in slots.busy.values())
                    timeout = max(0.0, first + self.timeout_s - time.monotonic())
                ready, _ = ray.wait([*slots.starting, *slots.busy], num_returns=1, timeout=timeout)
                for ref in ready:
                    if ref in slots.starting:
                        start_failures = self._started(ray, ref, slots, start_failures)
                    else:
                        actor, job, started = slots.busy.pop(ref)
                        on_done(self._result(ray, ref, actor, job, started, out_dir, slots))
                self._time_out(ray, slots, out_dir, on_done)
        finally:
            for actor in [*slots.starting.values(), *slots.idle]:
                with contextlib.suppress(Exception):
                    ray.kill(actor)

    @staticmethod
    def _started(ray: Any, ref: Any, slots: _Slots, failures: int) -> int:
        """Move a started actor to the idle slots; count (and past a limit, report) failures."""
        from ray import exceptions

        actor = slots.starting.pop(ref)
        try:
            ray.get(ref)
        except exceptions.RayError as err:
            if failures + 1 >= MAX_START_FAILURES:
                raise RuntimeError(f"Ray workers fail to start: {_first_line(err)}") from None
            return failures + 1
        slots.idle.append(actor)
        return 0

    @staticmethod
    def _result(
        ray: Any,
        ref: Any,
        actor: Any,
        job: Job,
        started: float,
        out_dir: Path,
        slots: _Slots,
    ) -> JobResult:
        """The job's result (its actor back to idle), or a failed result saying how Ray lost it."""
        from ray import exceptions

        try:
            result = ray.get(ref)
        except (exceptions.RayActorError, exceptions.WorkerCrashedError) as err:
            error = f"worker process died (Ray {type(err).__name__})"
        except exceptions.RayError as err:
            error = f"Ray {type(err).__name__}: {_first_line(err)}".strip()
        else:
            slots.idle.append(actor)
            if isinstance(result, JobResult):
                return result
            error = f"unexpected task result {type(result).__name__}"
        clean_partial(out_dir, job)
        return failed_result(job, error, time.monotonic() - started)

    def _time_out(self, ray: Any, slots: _Slots, out_dir: Path, on_done: OnDone) -> None:
        """Kill the actors of jobs past their timeout and fail those jobs."""
        now = time.monotonic()
        for ref, (actor, job, started) in list(slots.busy.items()):
            if now - started >= self.timeout_s:
                del slots.busy[ref]
                _kill(ray, actor, ref)
                clean_partial(out_dir, job)
                on_done(failed_result(job, timeout_message(self.timeout_s), now - started))


def _kill(ray: Any, actor: Any, ref: Any) -> None:
    """Kill an actor and wait (bounded) until Ray confirms its running call is gone."""
    from ray import exceptions

    ray.kill(actor, no_restart=True)
    with contextlib.suppress(exceptions.RayError):
        ray.get(ref, timeout=CANCEL_WAIT_S)


def _first_line(err: BaseException) -> str:
    """The first line of an exception's message, else its type's name."""
    text = str(err).strip()
    return text.splitlines()[0] if text else type(err).__name__
