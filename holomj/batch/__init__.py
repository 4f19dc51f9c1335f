"""``holomj batch``: many scenes from a jobs file, each job isolated in its own process.

- :mod:`~holomj.batch.job_list`: the jobs file (prompts or house JSON paths) and job ids;
- :mod:`~holomj.batch.runner`: the job function run inside a worker (generate, or compile +
  validate), which writes the job's folder and, last, its result marker;
- :mod:`~holomj.batch.resume`: what is complete, cleaning half-done jobs, the folder lock;
- :mod:`~holomj.batch.local` and :mod:`~holomj.batch.ray_engine`: the engines (a pool of
  long-lived worker processes; Ray tasks);
- :mod:`~holomj.batch.summary`: ``summary.jsonl`` and the totals;
- :mod:`~holomj.batch.run`: the orchestration (:func:`run_batch`);
- :mod:`~holomj.batch.jobs_file`: the batch job as ``holomj batch`` runs it (a jobs file and
  options in, the checks made once, an engine chosen, the outcome out).
"""

from __future__ import annotations

from holomj.batch.job_list import Job, parse_seeds, read_jobs
from holomj.batch.result import JobOptions, JobResult

__all__ = ["Job", "JobOptions", "JobResult", "parse_seeds", "read_jobs"]
