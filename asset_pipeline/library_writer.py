"""Write asset libraries to disk, atomically and byte-deterministically.

A library folder holds ``library.json`` (a :class:`~holomj.spec.assets.LibraryIndex`) and one
folder per asset with its ``asset.json`` (an :class:`~holomj.spec.assets.AssetMeta`) and files.

Every write builds the complete new library in a temporary folder beside the target (same
parent, so the final rename stays on one file system) and then swaps it in. Invalid input is
rejected before anything touches the disk; a failure while writing removes the temporary
folder and leaves the old library as it was.
"""

from __future__ import annotations

import json
import os
import re
import shutil
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from pathlib import Path, PurePosixPath
from typing import Any

from holomj.atomic import replace_folder
from holomj.errors import OutputExistsError, SpecError
from holomj.spec.assets import AssetMeta, LibraryIndex
from holomj.spec.base import read_json, validate_model

INDEX_FILE = "library.json"
META_FILE = "asset.json"

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
        f"{root / INDEX_FILE}",
    )

    def fill(tmp: Path) -> None:
        for bundle in bundles:
            _write_bundle(tmp, bundle)
        _write_file(tmp / INDEX_FILE, index_bytes(index))

    replace_folder(root, fill)
    return root


def add_assets(root: Path | str, bundles: Sequence[AssetBundle]) -> Path:
    """Add assets to the library at ``root``, replacing assets with the same id.

    The whole library is rebuilt beside ``root`` and swapped in, so a failure leaves the old
    library untouched. Returns ``root``.
    """
    root = Path(root)
    index_path = root / INDEX_FILE
    if not index_path.is_file():
        raise SpecError(
            "not an asset library (no library.json)",
            where=str(root),
            fix="create it first with write_library()",
        )
    index = validate_model(LibraryIndex, read_json(index_path), str(index_path))
    checked = _checked_bundles(bundles, existing=dict(index.assets))
    replaced = {b.meta.id for b in checked}
    kept = {i: f for i, f in index.assets.items() if i not in replaced}
    new_assets = {**kept, **{b.meta.id: b.folder_name for b in checked}}
    new_index = validate_model(
        LibraryIndex, {"name": index.name, "assets": new_assets}, str(index_path)
    )
    dropped = {index.assets[i] for i in replaced if i in index.assets} - set(kept.values())

    def fill(tmp: Path) -> None:
        for entry in sorted(root.iterdir()):
            if entry.name == INDEX_FILE or entry.name in dropped:
                continue
            if entry.is_dir() and not entry.is_symlink():
                shutil.copytree(entry, tmp / entry.name, symlinks=True)
            else:
                shutil.copy2(entry, tmp / entry.name, follow_symlinks=False)
        for bundle in checked:
            _write_bundle(tmp, bundle)
        _write_file(tmp / INDEX_FILE, index_bytes(new_index))

    replace_folder(root, fill)
    return root


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
        if folder == INDEX_FILE or folder in folders:
            other = folders.get(folder, INDEX_FILE)
            raise SpecError(
                f"folder {folder!r} is already used by {other!r}",
                where=where,
                fix="give the asset its own folder",
            )
        folders[folder] = meta.id
        files = {_safe_relpath(rel, where): data for rel, data in bundle.files.items()}
        if META_FILE in files:
            raise SpecError(
                f"{META_FILE} is written from the metadata", where=where, fix="leave it out"
            )
        for rel in _named_files(meta):
            if _safe_relpath(rel, where) not in files:
                raise SpecError(f"file {rel!r} named in the metadata is missing", where=where)
        checked.append(AssetBundle(meta=meta, files=files, folder=folder))
    return checked


def _named_files(meta: AssetMeta) -> list[str]:
    files = [p.mesh for p in meta.visual] + [p.texture for p in meta.visual if p.texture]
    files += [c.mesh for c in meta.collision if c.mesh] + list(meta.thumbnails)
    return files


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


def _write_bundle(library: Path, bundle: AssetBundle) -> None:
    folder = library / bundle.folder_name
    folder.mkdir()
    for rel, data in sorted(bundle.files.items()):
        target = folder / rel
        target.parent.mkdir(parents=True, exist_ok=True)
        _write_file(target, data)
    _write_file(folder / META_FILE, meta_bytes(bundle.meta))


def _write_file(path: Path, data: bytes) -> None:
    with open(path, "xb") as handle:
        handle.write(data)
        handle.flush()
        os.fsync(handle.fileno())
