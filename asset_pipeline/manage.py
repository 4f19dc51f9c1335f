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
import functools
import hashlib
import json
import multiprocessing
import re
import secrets
import shutil
import time
from collections.abc import Callable, Iterable, Sequence
from concurrent.futures import Future, ProcessPoolExecutor, as_completed
from concurrent.futures.process import BrokenProcessPool
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from asset_pipeline.library_writer import AssetBundle, add_assets, dumps_json
from holomj.atomic import replace_folder
from holomj.errors import HolomjError, InputError
from holomj.file_names import LIBRARY_INDEX, LIBRARY_META
from holomj.spec.assets import AssetMeta
from holomj.spec.base import read_json, validate_model

MESH_SUFFIXES = (".glb", ".gltf", ".obj", ".stl", ".ply")
# URDF and MJCF files: articulated assets (asset_pipeline.articulated_import).
ARTICULATED_SUFFIXES = (".urdf", ".xml", ".mjcf")
COMPANION_SUFFIXES = (".bin", ".mtl", ".png", ".jpg", ".jpeg")
# Collision meshes shipped beside real assets (V-HACD, LIBERO): not assets themselves.
_COLLISION_STEMS = re.compile(r"(_vhacd|_col|_collision|_coll)$", re.IGNORECASE)
# Path components that say nothing about the asset (scanner, exporter and dataset layouts):
# an id comes from the nearest component that is not one of these.
_GENERIC_NAMES = frozenset(
    {
        "textured", "texture", "textures", "model", "models", "mesh", "meshes", "scene",
        "untitled", "object", "objects", "base", "obj", "glb", "gltf", "fbx", "source",
        "sources", "src", "tsdf", "poisson", "visual", "visuals", "collision", "export",
        "exports", "output", "default", "final", "asset", "assets", "data", "file", "files",
        "geometry", "raw", "processed", "merged", "clean", "cleaned", "simplified", "lod",
        "urdf", "sdf", "mjcf", "normalized", "normalised", "optimized", "optimised",
        "model_normalized", "model_watertight",
    }
)  # fmt: skip
# Generic by pattern: scan resolutions (google_16k, google_512k, 4k), levels of detail
# (lod0), and bare runs of digits and separators (0001, 2024-01).
_GENERIC_PATTERN = re.compile(
    r"(google_\d+k|\d+k|lod_?\d*|[\d_.\-]*|untitled[_\-]?\d*|mesh[_\-]?\d*|model[_\-]?\d*)",
    re.IGNORECASE,
)
CACHE_DIR = ".cache"
PENDING_DIR = "pending"  # inside CACHE_DIR: degraded results on their way to the library
PENDING_MAX_AGE_S = 3600.0  # older pending folders are debris of killed runs
DERIVATION_FILE = "derivation.json"
MAX_ID_TEXT = 100  # ids may have 128 characters: room for a "-N" suffix


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
    given = {k: v for k, v in overrides.items() if v is not None}
    if "threshold" in given and "preprocessed_threshold" not in given:
        given["preprocessed_threshold"] = None  # a threshold asked for holds for every mesh
    values = {**PRESETS[preset], **given}
    return dataclasses.replace(CoacdParams(), **values)


@dataclass(frozen=True)
class ImportJob:
    """One file to import as one asset."""

    path: Path
    asset_id: str
    id_note: str | None = None  # why the id is not the one the file name gives, if so


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


def find_mesh_files(paths: Sequence[Path]) -> list[Path]:
    """Mesh files named directly, or found (recursively, sorted) in named folders.

    In folders, URDF files and MJCF files (``.xml``/``.mjcf`` with a ``<mujoco>`` root) count
    too, and the meshes in and below a folder holding one are its links, not assets of their
    own (a PartNet-Mobility model folder is one asset).
    """
    from asset_pipeline.articulated_import import articulated_format

    found: list[Path] = []
    for path in paths:
        path = Path(path)
        if path.is_dir():
            files = [p for p in sorted(path.rglob("*")) if p.is_file()]
            described = [
                p
                for p in files
                if p.suffix.lower() in ARTICULATED_SUFFIXES and articulated_format(p) is not None
            ]
            owners = {p.parent for p in described}
            found.extend(
                p
                for p in files
                if p in described
                or (
                    p.suffix.lower() in MESH_SUFFIXES
                    and not _COLLISION_STEMS.search(p.stem)
                    and not owners.intersection(p.parents)
                )
            )
        elif path.exists():
            found.append(path)
        else:
            raise InputError("file not found", where=str(path))
    return found


def asset_id_for(path: Path) -> str:
    """An asset id from the nearest meaningful component of ``path``.

    The file name, else its folder's name, else the next folder up: generic components
    (``textured.obj``, ``google_16k/``, ``meshes/``, ``tsdf/``, ``model.glb``, bare numbers;
    see :data:`_GENERIC_NAMES`) are skipped, so YCB's ``002_master_chef_can/google_16k/
    textured.obj`` is ``002_master_chef_can``. A texture-resolution suffix (``_1k``) is
    dropped; other characters not allowed in an id become ``_``. When every component is
    generic, the file name is used anyway.
    """
    from asset_pipeline.urdf import asset_id_hint

    path = Path(path)
    hint = asset_id_hint(path)  # PartNet-Mobility's mobility.urdf: <model_cat>_<folder>
    if hint is not None:
        return _id_text(hint) or "asset"
    names = [path.stem, *(p.name for p in path.parents if p.name)]
    for name in names:
        ident = _id_text(name)
        if ident and not _is_generic(ident):
            return ident
    return _id_text(path.stem) or "asset"


def _id_text(name: str) -> str:
    """``name`` as id text: resolution suffix dropped, odd characters as ``_``."""
    name = re.sub(r"[_\-](1k|2k|4k|8k)$", "", name, flags=re.IGNORECASE)
    return re.sub(r"[^A-Za-z0-9_.\-]+", "_", name).strip("_.-")[:MAX_ID_TEXT].rstrip("_.-")


def _is_generic(name: str) -> bool:
    """Whether a path component says nothing about the asset."""
    return name.lower() in _GENERIC_NAMES or bool(_GENERIC_PATTERN.fullmatch(name))


@dataclass(frozen=True)
class ExistingAsset:
    """An asset already in the library: where its files came from, when it says so."""

    asset_id: str
    source_file: str | None = None
    source_sha256: str | None = None

    def same_source(self, path: Path, sha256: str) -> bool:
        """Whether ``path`` (with bytes hashing to ``sha256``) is this asset's source file."""
        if self.source_sha256 is not None and self.source_sha256 == sha256:
            return True
        if self.source_file is None:
            return False
        try:
            return Path(self.source_file).resolve() == Path(path).resolve()
        except OSError:
            return False

    def describe(self) -> str:
        """A few words on where the asset came from, for messages."""
        return f"from {self.source_file}" if self.source_file else "not imported from a file"


def existing_assets(root: Path) -> dict[str, ExistingAsset]:
    """The assets of the library at ``root`` (none when there is no library yet), with the
    source file and hash their ``derivation.json`` records."""
    from holomj.library.store import AssetLibrary

    if not (Path(root) / LIBRARY_INDEX).is_file():
        return {}
    library = AssetLibrary.open(root)
    found = {}
    for asset_id in library.ids():
        source_file = source_sha = None
        try:
            derivation = json.loads((library.get(asset_id).root / DERIVATION_FILE).read_text())
            source = derivation.get("source") or {}
            source_file, source_sha = source.get("file"), source.get("sha256")
        except (HolomjError, OSError, ValueError, AttributeError):
            pass  # a builtin or procedural asset: no derivation of an import
        found[asset_id] = ExistingAsset(asset_id, source_file, source_sha)
    return found


def plan_jobs(
    paths: Sequence[Path],
    asset_id: str | None = None,
    existing: dict[str, ExistingAsset] | None = None,
) -> list[ImportJob]:
    """Jobs for the given files and folders, with ids that never silently reuse another's.

    Ids come from :func:`asset_id_for` (or ``asset_id`` for one file). An id already planned
    in this run, or held in the library (``existing``, see :func:`existing_assets`) by an
    asset imported from another file, gets the first free suffix ``-2``, ``-3``...; the job's
    ``id_note`` says so. The library's asset of the *same* file (same path or same bytes)
    keeps its id: re-importing a file updates its asset. An explicit ``asset_id`` held by
    another asset is an :class:`~holomj.errors.InputError` (nothing is replaced).
    """
    from asset_pipeline.articulated_import import articulated_format, check_articulated_file

    files = find_mesh_files(paths)
    if not files:
        raise InputError("no mesh files found", where=", ".join(str(p) for p in paths))
    for path in files:  # a malformed URDF/MJCF is bad input: refused before anything is written
        if articulated_format(path) is not None:
            check_articulated_file(path)
    if asset_id is not None and len(files) > 1:
        raise InputError("--id names one asset but several files were given", where="--id")
    existing = existing or {}
    jobs: list[ImportJob] = []
    used: set[str] = set()
    for path in files:
        base = asset_id or asset_id_for(path)
        digest = hashlib.sha256(path.read_bytes()).hexdigest() if existing else ""

        def taken(ident: str, path: Path = path, digest: str = digest) -> bool:
            held = existing.get(ident)
            return ident in used or (held is not None and not held.same_source(path, digest))

        if asset_id is not None and taken(asset_id):
            raise InputError(
                f"asset id {asset_id!r} is already in the library "
                f"({existing[asset_id].describe()})",
                where="--id",
                fix=f"choose another --id, or remove the asset first: "
                f"holomj assets remove {asset_id}",
            )
        ident, n = base, 1
        while taken(ident):
            n += 1
            ident = f"{base}-{n}"
        note = None
        if ident != base:
            where = (
                "by another file of this import"
                if base in used
                else f"in the library ({existing[base].describe()})"
            )
            note = f"id {base!r} is taken {where}; imported as {ident!r}"
        elif base in existing:
            note = f"replaces {base!r}, imported before from the same file"
        used.add(ident)
        jobs.append(ImportJob(path=path, asset_id=ident, id_note=note))
    return jobs


def source_files(path: Path) -> list[Path]:
    """The file and its companions (same folder, and a ``textures/`` folder) that shape it."""
    folder = path.parent
    companions = [
        p
        for p in sorted(folder.iterdir())
        if p.is_file() and p != path and p.suffix.lower() in COMPANION_SUFFIXES
    ]
    textures = folder / "textures"
    if textures.is_dir():
        companions += sorted(p for p in textures.iterdir() if p.is_file())
    from asset_pipeline.articulated_import import articulated_format, articulated_sources

    if articulated_format(path) is not None:  # the link meshes it names, wherever they are
        companions += [p for p in articulated_sources(path) if p not in companions]
    return [path, *companions]


@functools.cache
def pipeline_version() -> str:
    """A hash of the asset pipeline's own code: a code change invalidates every cache entry."""
    digest = hashlib.sha256()
    package = Path(__file__).parent
    for source in sorted(package.rglob("*.py")) + sorted((package / "data").glob("*.json")):
        if "procedural" in source.parts:
            continue
        digest.update(source.relative_to(package).as_posix().encode())
        digest.update(source.read_bytes())
    return digest.hexdigest()[:16]


def cache_key(path: Path, options: Any) -> str:
    """Content address of one import: pipeline code + options + source bytes."""
    digest = hashlib.sha256()
    digest.update(pipeline_version().encode())
    digest.update(options_json(options).encode())
    for source in source_files(path):
        digest.update(source.name.encode())
        digest.update(hashlib.sha256(source.read_bytes()).digest())
    return digest.hexdigest()[:32]


def options_json(options: Any) -> str:
    """Import options (dataclasses, nested) as sorted JSON, for cache keys."""
    return json.dumps(_jsonable(options), sort_keys=True)


def _jsonable(value: Any) -> Any:
    if dataclasses.is_dataclass(value):
        return {f.name: _jsonable(getattr(value, f.name)) for f in dataclasses.fields(value)}
    if isinstance(value, (list, tuple)):
        return [_jsonable(v) for v in value]
    if isinstance(value, Path):
        return str(value)
    return value


def load_cached(cache_root: Path, key: str, asset_id: str) -> tuple[AssetBundle, dict] | None:
    """The cached bundle for ``key``, re-labelled with ``asset_id``; None if absent or broken."""
    folder = cache_root / key
    meta_path = folder / LIBRARY_META
    if not meta_path.is_file():
        return None
    try:
        meta = validate_model(AssetMeta, read_json(meta_path), str(meta_path))
        files = {
            p.relative_to(folder).as_posix(): p.read_bytes()
            for p in sorted(folder.rglob("*"))
            if p.is_file() and p.name != LIBRARY_META
        }
        report = json.loads(files.get(DERIVATION_FILE, b"{}"))
    except (HolomjError, OSError, ValueError):
        return None
    return AssetBundle(meta=meta.model_copy(update={"id": asset_id}), files=files), report


def store_cached(cache_root: Path, key: str, bundle: AssetBundle) -> None:
    """Cache ``bundle`` under ``key`` (atomically: a killed write leaves no entry)."""

    def fill(folder: Path) -> None:
        for rel, data in bundle.files.items():
            target = folder / rel
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_bytes(data)
        (folder / LIBRARY_META).write_bytes(dumps_json(bundle.meta.model_dump(mode="json")))

    replace_folder(cache_root / key, fill)


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
            outcome.entry = _store_result(cache_root, entry_key, bundle, final)
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


def _store_result(cache_root: Path, key: str, bundle: AssetBundle, final: bool) -> str:
    """Store ``bundle`` as the cache entry ``key`` or, if not ``final``, in a pending folder.

    Returns the folder (relative to ``cache_root``) that holds it.
    """
    entry = key if final else f"{PENDING_DIR}/{key}-{secrets.token_hex(4)}"
    store_cached(cache_root, entry, bundle)
    return entry


def _sweep_pending(cache_root: Path, max_age_s: float = PENDING_MAX_AGE_S) -> None:
    """Delete pending folders older than ``max_age_s`` (left behind by killed imports)."""
    pending = cache_root / PENDING_DIR
    if not pending.is_dir():
        return
    cutoff = time.time() - max_age_s
    for entry in pending.iterdir():
        try:
            stale = entry.stat().st_mtime < cutoff
        except OSError:
            continue
        if stale:
            shutil.rmtree(entry, ignore_errors=True)


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
    _sweep_pending(cache_root)
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
