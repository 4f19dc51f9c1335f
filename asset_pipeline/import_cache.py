"""The import cache: every import's result stored under a content address (the pipeline's code,
the options, the source bytes), so that importing the same bytes again is instant; degraded
results wait in a pending folder until they reach a library."""

from __future__ import annotations

import dataclasses
import functools
import hashlib
import json
import secrets
import shutil
import time
from pathlib import Path
from typing import Any

from asset_pipeline.library_writer import AssetBundle, dumps_json
from holomj.atomic import replace_folder
from holomj.errors import HolomjError
from holomj.file_names import LIBRARY_META
from holomj.spec.assets import AssetMeta
from holomj.spec.base import read_json, validate_model

CACHE_DIR = ".cache"
PENDING_DIR = "pending"  # inside CACHE_DIR: degraded results on their way to the library
COMPANION_SUFFIXES = (".bin", ".mtl", ".png", ".jpg", ".jpeg")
PENDING_MAX_AGE_S = 3600.0  # older pending folders are debris of killed runs


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


def store_result(cache_root: Path, key: str, bundle: AssetBundle, final: bool) -> str:
    """Store ``bundle`` as the cache entry ``key`` or, if not ``final``, in a pending folder.

    Returns the folder (relative to ``cache_root``) that holds it.
    """
    entry = key if final else f"{PENDING_DIR}/{key}-{secrets.token_hex(4)}"
    store_cached(cache_root, entry, bundle)
    return entry


def sweep_pending(cache_root: Path, max_age_s: float = PENDING_MAX_AGE_S) -> None:
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


DERIVATION_FILE = "derivation.json"


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
