"""The job function, run inside a worker process (local pool or Ray task).

A prompt job runs ``generate`` (rendering only with ``render=True``); a house job runs
``compile`` then ``validate`` (``report.json`` in the folder, as ``holomj validate OUT --json
OUT/report.json`` writes it). Both write ``DIR/<id>/`` atomically, then, last, the result
marker. A job cleans its own leftovers first, so a job killed half-way simply runs again.
"""

from __future__ import annotations

import time
import traceback
from collections.abc import Callable
from pathlib import Path

from holomj.atomic import write_file
from holomj.batch.job_list import Job
from holomj.batch.result import JobOptions, JobResult, failed_result
from holomj.batch.resume import MARKER, clean_partial, job_folder
from holomj.errors import HolomjError
from holomj.file_names import REPORT_JSON
from holomj.jobs.folder import write_report
from holomj.spec.report import StabilityReport

JobFunction = Callable[[Job, Path, JobOptions], JobResult]


def run_job(job: Job, out_dir: Path, options: JobOptions) -> JobResult:
    """Build ``job``'s scene in ``out_dir/<id>/`` and record its result there; errors propagate."""
    start = time.perf_counter()
    out_dir = Path(out_dir)
    clean_partial(out_dir, job)
    folder = job_folder(out_dir, job)
    house: dict[str, int | None] = {"moved": None, "left_out": None, "substituted": None}
    if job.kind == "prompt":
        report = _generate(job, folder, options)
    else:
        report, house = _compile_and_validate(job, folder, options)
    counts = report.counts
    objects = int(counts.get("objects", len(report.objects)))
    stable = int(counts.get("stable", objects - len(report.unstable())))
    result = JobResult(
        id=job.id,
        input=job.input,
        kind=job.kind,
        seed=job.seed,
        status="ok" if report.ok else "unstable",
        objects=objects,
        stable=stable,
        stable_fraction=round(stable / objects, 4) if objects else 1.0,
        seconds=round(time.perf_counter() - start, 3),
        output=job.id,
        moved=house["moved"],
        left_out=house["left_out"],
        substituted=house["substituted"],
    )
    write_file(folder / MARKER, result.model_dump_json(indent=2) + "\n")
    return result


def execute(function: JobFunction, job: Job, out_dir: Path, options: JobOptions) -> JobResult:
    """Run ``function`` on ``job``; any exception becomes a failed result naming it."""
    start = time.perf_counter()
    try:
        return function(job, Path(out_dir), options)
    except HolomjError as err:
        error = err.one_line()
    except Exception as err:  # recorded as this job's failure, with where it came from
        frame = traceback.extract_tb(err.__traceback__)[-1:]
        where = f" at {Path(frame[0].filename).name}:{frame[0].lineno}" if frame else ""
        error = f"internal error {type(err).__name__}: {err}{where}"
    return failed_result(job, error, time.perf_counter() - start)


def _generate(job: Job, folder: Path, options: JobOptions) -> StabilityReport:
    from holomj.jobs.generate import GenerateOptions, generate_scene

    generate_options = GenerateOptions(
        library=options.library,
        seed=job.seed or 0,
        planner=options.planner,
        render=options.render,
        text_model=options.text_model,
    )
    return generate_scene(job.input, folder, generate_options).report


def _compile_and_validate(
    job: Job, folder: Path, options: JobOptions
) -> tuple[StabilityReport, dict[str, int | None]]:
    """The validation report, and what the import changed (moved, left out, substituted)."""
    from holomj.jobs.compile import compile_file
    from holomj.jobs.validate import validate

    compiled = compile_file(  # an object that cannot be saved makes the job "unstable"
        Path(job.input),
        folder,
        library_path=options.library,
        check_seconds=options.check_seconds,
        allow_invalid=True,
    )
    report = validate(folder)
    write_report(folder, REPORT_JSON, report.model_dump(mode="json"))
    stand = compiled.stand
    return report, {
        "moved": 0 if stand is None else len(stand.moved),
        "left_out": 0 if stand is None else len(stand.left_out),
        "substituted": len(compiled.substitutions),
    }
