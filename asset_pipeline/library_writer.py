"""Write asset libraries to disk, atomically and byte-deterministically.

A library folder holds ``library.json`` (a :class:`~holomj.spec.assets.LibraryIndex`) and one
folder per asset with its ``asset.json`` (an :class:`~holomj.spec.assets.AssetMeta`) and files.

A new library is built whole in a temporary folder beside the target (same parent, so the
final rename stays on one file system) and then swapped in. Adding to or removing from an
existing library writes new asset folders first and commits by replacing ``library.json`` in
one rename. Invalid input is rejected before anything touches the disk; a failure (even a
kill) leaves the library as its last committed index describes it.

PNG images (textures, thumbnails) are content-addressed: each distinct image is written once to
``LIB/.blobs/<sha256>.png`` and hard-linked into every asset folder that uses it, so a texture
shared by hundreds of procedural assets takes its bytes once on disk. Where a link cannot be
made (another file system, no hard links) the file is written as a copy. Blobs no asset links
any more are swept away with the folders the index no longer names.
"""

from __future__ import annotations

import contextlib
import errno
import fcntl
import hashlib
import itertools
import json
import os
import re
import shutil
from collections.abc import Callable, Iterable, Iterator, Sequence
from dataclasses import dataclass, field
from pathlib import Path, PurePosixPath
from typing import Any

from holomj.atomic import replace_folder, write_file
from holomj.errors import AssetNotFoundError, OutputExistsError, SpecError
from holomj.file_names import LIBRARY_BLOBS, LIBRARY_INDEX, LIBRARY_META
from holomj.spec.assets import AssetMeta, LibraryIndex
from holomj.spec.base import read_json, validate_model

SHARED_SUFFIXES = (".png",)

_SAFE_PART = re.compile(r"^[A-Za-z0-9_][A-Za-z0-9_.\-]*$")
_FOLDER_UNSAFE = re.compile(r"[^A-Za-z0-9_.\-]")


@dataclass(frozen=True)
class AssetBundle:
    """One asset ready to write: its metadata and its files (relative path -> bytes).

    ``asset.json`` is written from ``meta`` and must not appear in ``files``. ``folder`` is
    the asset's folder inside the library; by default it is derived from the id.
    """

    meta: AssetMeta
    files: dict[str, bytes] = field(default_factory=dict)
    folder: str | None = None

    @property
    def folder_name(self) -> str:
        """The folder this asset is written to inside the library."""
        return self.folder if self.folder is not None else folder_for(self.meta.id)


def folder_for(asset_id: str) -> str:
    """A folder name for an asset id: characters a path may not hold become ``_``."""
    name = _FOLDER_UNSAFE.sub("_", asset_id)
    return name if not name.startswith(".") else "_" + name[1:]


def dumps_json(data: Any) -> bytes:
    """The one JSON encoding of the library: sorted keys, 2-space indent, final newline."""
    text = json.dumps(data, indent=2, sort_keys=True, ensure_ascii=False, allow_nan=False)
    return (text + "\n").encode("utf-8")


def meta_bytes(meta: AssetMeta) -> bytes:
    """``asset.json`` content for ``meta``."""
    return dumps_json(meta.model_dump(mode="json"))


def index_bytes(index: LibraryIndex) -> bytes:
    """``library.json`` content for ``index``."""
    return dumps_json(index.model_dump(mode="json"))


def write_library(
    root: Path | str, name: str, assets: Sequence[AssetBundle], overwrite: bool = False
) -> Path:
    """Write a new library with ``assets`` at ``root`` and return ``root``.

    Raises :class:`~holomj.errors.OutputExistsError` if ``root`` exists and ``overwrite`` is
    false, and :class:`~holomj.errors.SpecError` for an invalid asset, a duplicate id or
    folder, or an unsafe file path; nothing is written in those cases.
    """
    root = Path(root)
    if root.exists() and not overwrite:
        raise OutputExistsError(
            "the library folder exists", where=str(root), fix="pass overwrite=True to replace it"
        )
    bundles = _checked_bundles(assets, existing={})
    index = validate_model(
        LibraryIndex,
        {"name": name, "assets": {b.meta.id: b.folder_name for b in bundles}},
        f"{root / LIBRARY_INDEX}",
    )

    def fill(tmp: Path) -> None:
        for bundle in bundles:
            _write_bundle(tmp, bundle, tmp / LIBRARY_BLOBS)
        _write_file(tmp / LIBRARY_INDEX, index_bytes(index))

    replace_folder(root, fill)
    return root


def add_assets(root: Path | str, bundles: Sequence[AssetBundle]) -> Path:
    """Add assets to the library at ``root``, replacing assets with the same id.

    Each new asset is written to a fresh folder inside the library (an unused name, so an
    asset being replaced stays intact), then ``library.json`` is replaced in one rename: that
    rename is the commit. A crash before it leaves the index as it was; folders it does not
    name are swept away by the next write. Returns ``root``.
    """
    root = Path(root)
    with library_lock(root):
        index = _read_index(root)
        taken = set(index.assets.values()) | {p.name for p in root.iterdir()}
        staged: list[AssetBundle] = []
        for bundle in bundles:
            folder = _free_folder(folder_for(bundle.meta.id), taken)
            taken.add(folder)
            staged.append(AssetBundle(meta=bundle.meta, files=bundle.files, folder=folder))
        checked = _checked_bundles(staged, existing={})
        replaced = {b.meta.id for b in checked}
        kept = {i: f for i, f in index.assets.items() if i not in replaced}
        in_use = set(kept.values())
        clash = next((b for b in checked if b.folder_name in in_use), None)
        if clash is not None:
            raise SpecError(f"folder {clash.folder_name!r} is in use", where=str(root))
        new_index = validate_model(
            LibraryIndex,
            {"name": index.name, "assets": {**kept, **{b.meta.id: b.folder_name for b in checked}}},
            str(root / LIBRARY_INDEX),
        )
        try:
            for bundle in checked:
                replace_folder(root / bundle.folder_name, _filler(bundle, root / LIBRARY_BLOBS))
            _commit_index(root, new_index)
        except BaseException:
            for bundle in checked:
                shutil.rmtree(root / bundle.folder_name, ignore_errors=True)
            raise
        sweep_unindexed(root, new_index)
    return root


def remove_assets(root: Path | str, asset_ids: Sequence[str]) -> list[str]:
    """Remove assets from the library at ``root``; returns the folders that were deleted."""
    root = Path(root)
    with library_lock(root):
        index = _read_index(root)
        missing = [i for i in asset_ids if i not in index.assets]
        if missing:
            raise AssetNotFoundError(
                f"asset {missing[0]!r} is not in the library",
                where=str(root),
                fix="see 'holomj assets list'",
            )
        kept = {i: f for i, f in index.assets.items() if i not in set(asset_ids)}
        new_index = validate_model(
            LibraryIndex, {"name": index.name, "assets": kept}, str(root / LIBRARY_INDEX)
        )
        _commit_index(root, new_index)
        return sweep_unindexed(root, new_index)


def sweep_unindexed(root: Path, index: LibraryIndex) -> list[str]:
    """Delete asset folders and leftovers the index does not name (crash debris, removed assets).

    Hidden entries (``.cache``, ``.lock``) and files are kept, and so are the blobs some asset
    folder still links (:data:`LIBRARY_BLOBS`); the others are deleted.
    """
    named = set(index.assets.values())
    removed = []
    for entry in sorted(root.iterdir()):
        hidden_leftover = entry.name.startswith(".") and (
            ".new-" in entry.name or ".old-" in entry.name
        )
        if entry.is_dir() and (
            (not entry.name.startswith(".") and entry.name not in named) or hidden_leftover
        ):
            shutil.rmtree(entry, ignore_errors=True)
            removed.append(entry.name)
    store = root / LIBRARY_BLOBS
    if store.is_dir():
        for blob in sorted(store.iterdir()):
            if blob.is_file() and blob.stat().st_nlink <= 1:
                blob.unlink(missing_ok=True)
    return removed


_HELD_LOCKS: dict[Path, int] = {}


@contextlib.contextmanager
def library_lock(root: Path) -> Iterator[None]:
    """An exclusive lock on a library, so concurrent writers take turns (re-entrant).

    The lock file sits beside the library (``.<name>.lock``), so it survives the library folder
    being replaced as a whole.
    """
    key = Path(root).absolute()
    if _HELD_LOCKS.get(key):
        _HELD_LOCKS[key] += 1
        try:
            yield
        finally:
            _HELD_LOCKS[key] -= 1
        return
    key.parent.mkdir(parents=True, exist_ok=True)
    with open(key.parent / f".{key.name}.lock", "a+b") as handle:
        fcntl.flock(handle.fileno(), fcntl.LOCK_EX)
        _HELD_LOCKS[key] = 1
        try:
            yield
        finally:
            _HELD_LOCKS.pop(key, None)
            fcntl.flock(handle.fileno(), fcntl.LOCK_UN)


def _read_index(root: Path) -> LibraryIndex:
    index_path = root / LIBRARY_INDEX
    if not index_path.is_file():
        raise SpecError(
            "not an asset library (no library.json)",
            where=str(root),
            fix="create it first with write_library()",
        )
    return validate_model(LibraryIndex, read_json(index_path), str(index_path))


def _commit_index(root: Path, index: LibraryIndex) -> None:
    write_file(root / LIBRARY_INDEX, index_bytes(index))


def _free_folder(base: str, taken: set[str]) -> str:
    if base not in taken:
        return base
    for n in itertools.count(2):
        candidate = f"{base}-{n}"
        if candidate not in taken:
            return candidate
    raise AssertionError("unreachable")


def _filler(bundle: AssetBundle, store: Path) -> Callable[[Path], None]:
    """What fills the temporary folder of ``bundle`` (its files, blobs in ``store``)."""

    def fill(folder: Path) -> None:
        _fill_bundle(folder, bundle, store)

    return fill


def _fill_bundle(folder: Path, bundle: AssetBundle, store: Path) -> None:
    for rel, data in sorted(bundle.files.items()):
        target = folder / rel
        target.parent.mkdir(parents=True, exist_ok=True)
        if target.suffix.lower() in SHARED_SUFFIXES:
            _link_or_write(target, data, store)
        else:
            _write_file(target, data)
    _write_file(folder / LIBRARY_META, meta_bytes(bundle.meta))


def _link_or_write(target: Path, data: bytes, store: Path) -> None:
    """Hard-link ``target`` to the blob of ``data`` in ``store`` (writing the blob first if it
    is new); write ``target`` as a copy where links are not possible."""
    blob = store / f"{hashlib.sha256(data).hexdigest()}{target.suffix.lower()}"
    try:
        store.mkdir(exist_ok=True)
        if not blob.is_file() or blob.stat().st_size != len(data):
            blob.unlink(missing_ok=True)
            _write_file(blob, data)
        os.link(blob, target)
    except OSError as err:
        if err.errno not in (errno.EXDEV, errno.EPERM, errno.EMLINK, errno.ENOTSUP, errno.EACCES):
            raise
        _write_file(target, data)


def _checked_bundles(bundles: Iterable[AssetBundle], existing: dict[str, str]) -> list[AssetBundle]:
    """Validate bundles; ``existing`` maps ids already in the library to their folders."""
    bundles = list(bundles)
    new_ids = {bundle.meta.id for bundle in bundles}
    # Folders of assets that stay; the folders of replaced assets are free again.
    folders = {folder: i for i, folder in existing.items() if i not in new_ids}
    checked: list[AssetBundle] = []
    ids: set[str] = set()
    for position, bundle in enumerate(bundles):
        where = f"assets[{position}]"
        meta = validate_model(AssetMeta, bundle.meta.model_dump(mode="json"), where)
        where = f"asset {meta.id!r}"
        if meta.id in ids:
            raise SpecError("duplicate asset id", where=where, fix="give every asset its own id")
        ids.add(meta.id)
        folder = bundle.folder_name
        if not _SAFE_PART.match(folder) or folder in {".", ".."}:
            raise SpecError(
                f"unsafe folder name {folder!r}",
                where=where,
                fix="use letters, digits, '_', '.' and '-' only",
            )
        if folder == LIBRARY_INDEX or folder in folders:
            other = folders.get(folder, LIBRARY_INDEX)
            raise SpecError(
                f"folder {folder!r} is already used by {other!r}",
                where=where,
                fix="give the asset its own folder",
            )
        folders[folder] = meta.id
        files = {_safe_relpath(rel, where): data for rel, data in bundle.files.items()}
        if LIBRARY_META in files:
            raise SpecError(
                f"{LIBRARY_META} is written from the metadata", where=where, fix="leave it out"
            )
        for rel in _named_files(meta):
            if _safe_relpath(rel, where) not in files:
                raise SpecError(f"file {rel!r} named in the metadata is missing", where=where)
        checked.append(AssetBundle(meta=meta, files=files, folder=folder))
    return checked


def _named_files(meta: AssetMeta) -> list[str]:
    return meta.files()  # moving parts' meshes included


def _safe_relpath(rel: str, where: str) -> str:
    """Return ``rel`` normalised, or raise if it is absolute or leaves the asset folder."""
    parts = rel.split("/")
    if (
        not rel
        or "\\" in rel
        or rel.startswith("/")
        or any(not _SAFE_PART.match(p) or p in {".", ".."} for p in parts)
    ):
        raise SpecError(
            f"unsafe file path {rel!r}",
            where=where,
            fix="use a relative path of plain names (letters, digits, '_', '.', '-')",
        )
    return str(PurePosixPath(*parts))


def _write_bundle(library: Path, bundle: AssetBundle, store: Path) -> None:
    folder = library / bundle.folder_name
    folder.mkdir()
    _fill_bundle(folder, bundle, store)


def _write_file(path: Path, data: bytes) -> None:
    with open(path, "xb") as handle:
        handle.write(data)
        handle.flush()
        os.fsync(handle.fileno())
