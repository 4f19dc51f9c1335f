"""Importing many mesh files into a library: ids, a content-addressed cache, a process pool.

Each file becomes one asset. Its processed bundle (meshes, hulls, textures, thumbnails,
``derivation.json``) is cached under ``LIB/.cache/<key>/``, where the key hashes the pipeline's
own source code, the import options and the bytes of the file and its companions (``.bin``,
``.mtl``, textures). Re-importing the same bytes with the same options is instant; changing an
option re-processes. Every finished asset is committed to the library index at once (see
:func:`asset_pipeline.library_writer.add_assets`), so an import killed half-way keeps what it
finished and a second run resumes from the cache.

A *degraded* result (CoACD unavailable, crashed or timed out, so coarser settings or the single
convex hull stood in; see :mod:`asset_pipeline.decompose`) is still added to the library, marked
``degraded`` in its ``derivation.json``, but it is cached as final only when the caller accepts
fallbacks (``accept_fallback``, ``--accept-fallback``). Otherwise it travels to the library
through a pending folder (``LIB/.cache/pending/<key>-<nonce>/``, deleted once committed), and a
degraded cache entry is not reused: the next import of the file tries CoACD again.
"""

from __future__ import annotations

import dataclasses
import multiprocessing
import shutil
import time
from collections.abc import Callable, Iterable, Sequence
from concurrent.futures import Future, ProcessPoolExecutor, as_completed
from concurrent.futures.process import BrokenProcessPool
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from asset_pipeline.import_cache import (
    CACHE_DIR,
    DERIVATION_FILE,
    PENDING_DIR,
    cache_key,
    load_cached,
    pipeline_version,
    store_result,
    sweep_pending,
)
from asset_pipeline.import_plan import (
    ImportJob,
)
from asset_pipeline.library_writer import AssetBundle, add_assets, dumps_json
from holomj.errors import HolomjError, InputError
from holomj.spec.assets import AssetMeta

PRESETS: dict[str, dict[str, float | int | None]] = {
    # Seconds per object: previews, tests, CI.
    "fast": {
        "threshold": 0.3,
        "preprocessed_threshold": None,
        "max_convex_hull": 4,
        "preprocess_resolution": 20,
        "resolution": 500,
        "mcts_iterations": 20,
    },
    # CoacdParams' own defaults: seconds per object, tens for dense scans.
    "default": {},
    # Closer hulls for contact-rich manipulation: CoACD's own search settings with a finer
    # threshold and more hulls; minutes per object.
    "fine": {
        "threshold": 0.03,
        "preprocessed_threshold": None,
        "max_convex_hull": 32,
        "preprocess_resolution": 50,
        "resolution": 2000,
        "mcts_nodes": 20,
        "mcts_iterations": 300,
        "mcts_max_depth": 4,
        "timeout_s": 900.0,
    },
}


def coacd_params(preset: str = "default", **overrides: float | int | None) -> Any:
    """CoacdParams of a named preset, with explicit overrides (None means keep)."""
    from asset_pipeline.decompose import CoacdParams

    if preset not in PRESETS:
        raise InputError(
            f"unknown preset {preset!r}", where="--preset", fix=f"use one of: {', '.join(PRESETS)}"
        )
    given: dict[str, float | int | None] = {k: v for k, v in overrides.items() if v is not None}
    if "threshold" in given and "preprocessed_threshold" not in given:
        given["preprocessed_threshold"] = None  # a threshold asked for holds for every mesh
    values: dict[str, Any] = {**PRESETS[preset], **given}  # field name -> value, as the table
    return dataclasses.replace(CoacdParams(), **values)


@dataclass
class JobOutcome:
    """What happened to one file."""

    path: str
    asset_id: str
    ok: bool
    cached: bool = False
    seconds: float = 0.0
    error: str | None = None
    hulls: int | None = None
    mass_kg: float | None = None
    cache_key: str | None = None
    degraded: bool = False
    degraded_reason: str | None = None
    entry: str | None = None  # folder under the cache root holding the bundle to commit
    id_note: str | None = None  # see ImportJob.id_note


@dataclass
class ImportSummary:
    """All outcomes of one ``holomj assets import`` run."""

    outcomes: list[JobOutcome] = field(default_factory=list)

    @property
    def succeeded(self) -> list[JobOutcome]:
        """Outcomes that added an asset."""
        return [o for o in self.outcomes if o.ok]

    @property
    def failed(self) -> list[JobOutcome]:
        """Outcomes that did not."""
        return [o for o in self.outcomes if not o.ok]

    @property
    def degraded(self) -> list[JobOutcome]:
        """Outcomes that added an asset from a fallback decomposition."""
        return [o for o in self.outcomes if o.ok and o.degraded]

    def to_dict(self) -> dict[str, Any]:
        """JSON-able form."""
        return {
            "succeeded": len(self.succeeded),
            "failed": len(self.failed),
            "degraded": len(self.degraded),
            "cached": sum(1 for o in self.outcomes if o.cached),
            "outcomes": [_outcome_dict(o) for o in self.outcomes],
        }


def _outcome_dict(outcome: JobOutcome) -> dict[str, Any]:
    """JSON-able form of one outcome (without the transient ``entry``)."""
    data = dataclasses.asdict(outcome)
    data.pop("entry")
    return data


def process_job(
    job: ImportJob,
    options: Any,
    cache_root: Path,
    thumbnails: bool,
    accept_fallback: bool = False,
) -> JobOutcome:
    """Import one file into the cache (or find it there); never raises for bad input.

    A degraded cache entry is reused only with ``accept_fallback``; a new degraded result is
    cached as final only with it, else stored in a pending folder (see the module docstring).
    """
    return import_cached(
        JobOutcome(path=str(job.path), asset_id=job.asset_id, ok=False, id_note=job.id_note),
        cache_root,
        lambda: cache_key(job.path, options),
        lambda key: _import_bundle(job, options, key, thumbnails, accept_fallback),
        accept_fallback,
    )


def import_cached(
    outcome: JobOutcome,
    cache_root: Path,
    key: Callable[[], str],
    build: Callable[[str], tuple[AssetBundle, dict]],
    accept_fallback: bool,
) -> JobOutcome:
    """Fill ``outcome`` (a new, failed one) for one job: its bundle from the cache entry
    ``key()``, else ``build(key)`` (bundle, report) stored there (or in a pending folder when
    degraded and not ``accept_fallback``); a HolomjError becomes the outcome's error."""
    start = time.perf_counter()
    try:
        entry_key = key()
        outcome.cache_key = entry_key
        cached = load_cached(cache_root, entry_key, outcome.asset_id)
        if cached is not None and (accept_fallback or not cached[1].get("degraded")):
            bundle, report = cached
            outcome.cached, outcome.entry = True, entry_key
        else:
            bundle, report = build(entry_key)
            final = not report["degraded"] or report["fallback_accepted"]
            outcome.entry = store_result(cache_root, entry_key, bundle, final)
        outcome.ok = True
        outcome.degraded = bool(report.get("degraded"))
        outcome.degraded_reason = report.get("degraded_reason")
        outcome.hulls = len(bundle.meta.collision)
        outcome.mass_kg = round(bundle.meta.mass, 4)
    except HolomjError as err:
        outcome.error = err.one_line()
    outcome.seconds = round(time.perf_counter() - start, 3)
    return outcome


def _import_bundle(
    job: ImportJob, options: Any, key: str, thumbnails: bool, accept_fallback: bool
) -> tuple[AssetBundle, dict]:
    """Import ``job``'s file: the bundle (with thumbnails and ``derivation.json``), the report."""
    from asset_pipeline.importer import import_asset

    imported = import_asset(job.path, job.asset_id, options)
    return finish_bundle(imported, key, thumbnails, accept_fallback)


def finish_bundle(
    imported: Any, key: str, thumbnails: bool, accept_fallback: bool
) -> tuple[AssetBundle, dict]:
    """An :class:`~asset_pipeline.importer.ImportedAsset`'s bundle with thumbnails (if
    ``thumbnails``) and ``derivation.json`` (its report, the cache key, the pipeline version),
    and that report."""
    bundle = imported.bundle
    if thumbnails:
        from asset_pipeline.thumbnails import with_thumbnails

        bundle = with_thumbnails(bundle)
    report = {
        **imported.report,
        "fallback_accepted": bool(imported.report["degraded"] and accept_fallback),
        "cache_key": key,
        "pipeline_version": pipeline_version(),
    }
    files = {**bundle.files, DERIVATION_FILE: dumps_json(report)}
    return AssetBundle(meta=bundle.meta, files=files), report


def run_imports(
    jobs: Sequence[ImportJob],
    library_root: Path,
    options: Any,
    *,
    workers: int = 1,
    thumbnails: bool = True,
    on_done: Callable[[JobOutcome], None] | None = None,
    accept_fallback: bool = False,
) -> ImportSummary:
    """Import ``jobs`` into the library at ``library_root`` with ``workers`` processes.

    A file that fails (bad mesh, crash of its worker) is reported and the others go on.
    Each success is committed to the library as soon as it is done; a degraded one too, but it
    is cached as final only with ``accept_fallback`` (see :func:`process_job`).
    """
    root = Path(library_root)
    cache_root = root / CACHE_DIR
    cache_root.mkdir(parents=True, exist_ok=True)
    sweep_pending(cache_root)
    args = (options, cache_root, thumbnails, accept_fallback)
    summary = run_jobs(
        jobs, process_job, args, root, workers=workers, on_done=on_done, key=_job_key
    )
    if workers > 1 and len(jobs) > 1:  # a parallel run finishes in any order
        summary.outcomes.sort(key=lambda o: o.path)
    return summary


def _job_key(job: ImportJob) -> tuple[str, str]:
    return str(job.path), job.asset_id


def run_jobs(
    jobs: Sequence[Any],
    process: Callable[..., JobOutcome],
    args: tuple,
    root: Path,
    *,
    workers: int,
    on_done: Callable[[JobOutcome], None] | None,
    key: Callable[[Any], tuple[str, str]],
) -> ImportSummary:
    """Run ``process(job, *args)`` for every job (in ``workers`` spawned processes when more
    than one) and commit each success to the library at ``root`` as soon as it is done.

    ``process`` imports one job into the cache under ``root`` (a module-level function, so a
    worker can run it); ``key(job)`` is the job's (path, asset id). A job whose worker dies is
    reported as failed and the others go on. The outcomes are in the order they finished.
    """
    cache_root = root / CACHE_DIR
    summary = ImportSummary()

    def finish(job: Any, outcome: JobOutcome) -> None:
        _commit(root, cache_root, key(job)[1], outcome)
        summary.outcomes.append(outcome)
        if on_done is not None:
            on_done(outcome)

    if workers <= 1 or len(jobs) <= 1:
        for job in jobs:
            finish(job, process(job, *args))
        return summary
    context = multiprocessing.get_context("spawn")
    with ProcessPoolExecutor(max_workers=workers, mp_context=context) as pool:
        futures: dict[Future[JobOutcome], Any] = {
            pool.submit(process, job, *args): job for job in jobs
        }
        for future in as_completed(futures):
            job = futures[future]
            try:
                outcome = future.result()
            except BrokenProcessPool:
                path, asset_id = key(job)
                outcome = JobOutcome(
                    path, asset_id, ok=False, error="worker process died", id_note=job.id_note
                )
            finish(job, outcome)
    return summary


def _commit(root: Path, cache_root: Path, asset_id: str, outcome: JobOutcome) -> None:
    """Add a successful outcome's bundle to the library as ``asset_id``; then drop its pending
    folder, if any."""
    if not outcome.ok or outcome.entry is None:
        return
    try:
        cached = load_cached(cache_root, outcome.entry, asset_id)
        if cached is None:
            outcome.ok, outcome.error = False, "cache entry vanished before commit"
        else:
            add_assets(root, [cached[0]])
    finally:
        if outcome.entry.startswith(f"{PENDING_DIR}/"):
            shutil.rmtree(cache_root / outcome.entry, ignore_errors=True)


def iter_assets(root: Path) -> Iterable[AssetMeta]:
    """The metadata of every asset in a library, sorted by id."""
    from holomj.library.store import AssetLibrary

    library = AssetLibrary.open(root)
    for asset_id in library.ids():
        yield library.get(asset_id).meta
