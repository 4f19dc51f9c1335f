"""Planning an import run: the mesh and articulated files under the paths given, and a job for
each with an asset id from its file name that never silently reuses another asset's (the
library's asset of the same file keeps its id)."""

from __future__ import annotations

import hashlib
import json
import re
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from asset_pipeline.import_cache import DERIVATION_FILE
from holomj.errors import HolomjError, InputError
from holomj.file_names import LIBRARY_INDEX

MESH_SUFFIXES = (".glb", ".gltf", ".obj", ".stl", ".ply")
# URDF and MJCF files: articulated assets (asset_pipeline.articulated_import).
ARTICULATED_SUFFIXES = (".urdf", ".xml", ".mjcf")
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


MAX_ID_TEXT = 100  # ids may have 128 characters: room for a "-N" suffix


@dataclass(frozen=True)
class ImportJob:
    """One file to import as one asset."""

    path: Path
    asset_id: str
    id_note: str | None = None  # why the id is not the one the file name gives, if so


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
    from asset_pipeline.urdf_kinematics import asset_id_hint

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
