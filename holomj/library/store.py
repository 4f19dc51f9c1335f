"""The asset library as holomj reads it: an index folder of AssetMeta + mesh files.

Every library also offers ``builtin:box``, a 1 m unit box shipped with holomj, so an importer
can always stand in a box of the right size (via ``scale``) for an asset it cannot find.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from importlib import resources
from pathlib import Path
from typing import TypeVar

from holomj.errors import AssetNotFoundError, SpecError, closest_names
from holomj.file_names import LIBRARY_INDEX, LIBRARY_META
from holomj.library.location import default_library_root
from holomj.spec.assets import AssetMeta, LibraryIndex
from holomj.spec.base import read_json, validate_model
from holomj.spec.categories import category_aliases, normalise_category

BUILTIN_BOX = "builtin:box"


def _package_data(*parts: str) -> Path:
    return Path(str(resources.files("holomj.data").joinpath(*parts)))


@dataclass(frozen=True)
class LibraryAsset:
    """An asset's metadata and the folder its relative paths start from."""

    meta: AssetMeta
    root: Path

    def path(self, relative: str) -> Path:
        """Absolute path of a file named in the metadata."""
        return self.root / relative


_Library = TypeVar("_Library", bound="AssetLibrary")


class AssetLibrary:
    """An on-disk asset library (read-only view)."""

    def __init__(self, root: Path, name: str, assets: dict[str, LibraryAsset]) -> None:
        self.root = root
        self.name = name
        self._assets = assets

    @classmethod
    def open(cls: type[_Library], root: Path | str | None = None) -> _Library:
        """Open the library at ``root`` (default: :func:`default_library_root`)."""
        root = Path(root) if root is not None else default_library_root()
        index_path = root / LIBRARY_INDEX
        if not index_path.is_file():
            raise SpecError(
                "not an asset library (no library.json)",
                where=str(root),
                fix="build the default one with 'holomj assets build-default' or pass --library",
            )
        index = validate_model(LibraryIndex, read_json(index_path), str(index_path))
        assets = {BUILTIN_BOX: _load_asset(_package_data("builtin", "box"), BUILTIN_BOX)}
        for asset_id, folder in sorted(index.assets.items()):
            asset_root = (root / folder).resolve()
            if root.resolve() not in asset_root.parents:
                raise SpecError(
                    f"asset folder {folder!r} leaves the library", where=str(index_path)
                )
            assets[asset_id] = _load_asset(asset_root, asset_id)
        return cls(root, index.name, assets)

    def __contains__(self, asset_id: object) -> bool:
        return asset_id in self._assets

    def __len__(self) -> int:
        return len(self._assets)

    def ids(self) -> list[str]:
        """All asset ids, sorted."""
        return sorted(self._assets)

    def get(self, asset_id: str) -> LibraryAsset:
        """The asset with this id, or an error listing close matches."""
        try:
            return self._assets[asset_id]
        except KeyError:
            near = closest_names(asset_id, self._assets)
            hint = f"did you mean: {near}" if near else f"the library has {len(self)} assets"
            raise AssetNotFoundError(
                f"asset {asset_id!r} is not in library {self.name!r}", fix=hint
            ) from None

    def add_loaded(self, asset_id: str, folder: Path) -> LibraryAsset:
        """Load an asset written into ``folder`` after this view was opened (an asset made on
        demand, :mod:`holomj.jobs.synthesis`) and make it part of this view."""
        asset = _load_asset(Path(folder), asset_id)
        self._assets[asset_id] = asset
        return asset

    def categories(self) -> list[str]:
        """All categories, sorted."""
        return sorted({a.meta.category for a in self._assets.values()})

    def by_category(self, category: str) -> list[LibraryAsset]:
        """Assets of a category (case and separator insensitive), sorted by id."""
        key = normalise_category(category)
        return [
            self._assets[i]
            for i in sorted(self._assets)
            if normalise_category(self._assets[i].meta.category) == key
        ]

    def closest(self, category: str, size: tuple[float, float, float]) -> LibraryAsset | None:
        """The asset of ``category`` whose bounding box is closest in size (log-ratio distance).

        When the library has no asset of that exact category, the category's aliases
        (``holomj/data/category_facts.json``, e.g. ``HousePlant`` -> ``potted_plant``) are tried
        in order. A rotation by 90° about Z is allowed, so a 2 x 1 m bed matches a 1 x 2 m one.
        """
        for name in [category, *category_aliases().get(normalise_category(category), [])]:
            candidates = [a for a in self.by_category(name) if a.meta.id != BUILTIN_BOX]
            if candidates:
                return min(candidates, key=lambda a: (size_distance(a.meta.size, size), a.meta.id))
        return None


def size_distance(a: tuple[float, float, float], b: tuple[float, float, float]) -> float:
    """Sum of squared log ratios of extents, taking the better of the two footprint turns."""

    def dist(x: tuple[float, float, float]) -> float:
        return sum(math.log(max(p, 1e-3) / max(q, 1e-3)) ** 2 for p, q in zip(x, b))

    return min(dist(a), dist((a[1], a[0], a[2])))


def _load_asset(folder: Path, asset_id: str) -> LibraryAsset:
    meta_path = folder / LIBRARY_META
    meta = validate_model(AssetMeta, read_json(meta_path), str(meta_path))
    if meta.id != asset_id:
        raise SpecError(
            f"asset id {meta.id!r} differs from the index entry {asset_id!r}", where=str(meta_path)
        )
    asset = LibraryAsset(meta=meta, root=folder)
    files = [f for f in meta.files() if f not in meta.thumbnails]  # moving parts' too
    for rel in files:
        if not asset.path(rel).is_file():
            raise SpecError(f"file {rel!r} named in the metadata is missing", where=str(meta_path))
    return asset
