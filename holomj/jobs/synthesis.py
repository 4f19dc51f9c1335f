"""Assets on demand: synthesise a procedural asset (or build an honest proxy) into a library.

:func:`synthesise` builds an asset of a registered procedural category at a target size, style
seed and attributes (colour, material, shape, style, and colours or materials of parts such as
"brass handles": :mod:`asset_pipeline.procedural.attributes`), with its articulated generator
(doors, drawers and lids on joints) when the default library holds the category articulated
(``asset_pipeline.default_library.articulated_synthesis``: on by default);
:func:`synthesise_proxy` builds a proxy (:mod:`asset_pipeline.procedural.proxies`) for a
category no generator makes. Both write the asset into the library under a **content-addressed
id**, ``<category>_<hash12>``: the hash covers the kind (asset or proxy), the category, the size
(to the millimetre), the seed, the attributes, the placement and the generators' version
(``DEFAULT_LIBRARY_VERSION``; ``ARTICULATED_VERSION`` and a flag for an articulated asset).
An asset already there is reused, never rewritten; a new one is
built outside the lock, then added under the library's lock (``add_assets``: written into a
temporary folder and renamed, the index replaced in one rename), after checking again that no
other process added it meanwhile, so two batch workers synthesising the same asset leave one.

The size is clamped into the category's valid range (and ratios) first; every clamp is reported
in :attr:`Synthesis.notes`. On-demand assets carry ``source`` :data:`SYNTHESISED_SOURCE` or
:data:`PROXY_SOURCE`: retrieval never ranks them (only their id, recomputed from the request,
finds them), so what a run picks never depends on what earlier runs synthesised; the default
library's refresh removes them with its stale procedural assets (their ids name the generator
version, so they would never be reused).

**Where they go:** into the library the run uses (the default one, or ``--library X``) when it
is writable, else into the cache library ``$HOLOMJ_HOME/synthesised`` (made on first use); the
open :class:`~holomj.library.store.AssetLibrary` learns the new asset either way, so the rest of
the run (layout, compile, export) sees it. The asset pipeline is imported inside the functions.
"""

from __future__ import annotations

import hashlib
import json
import os
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from holomj.errors import InputError
from holomj.file_names import LIBRARY_INDEX, LIBRARY_META
from holomj.library.location import holomj_home
from holomj.library.store import AssetLibrary, LibraryAsset

SYNTHESISED_SOURCE = "holomj synthesised"
PROXY_SOURCE = "holomj proxy"
ON_DEMAND_SOURCES = frozenset({SYNTHESISED_SOURCE, PROXY_SOURCE})
CACHE_LIBRARY = "synthesised"  # under holomj_home(): for read-only libraries
SIZE_DECIMALS = 3

Size = tuple[float, float, float]


@dataclass(frozen=True)
class Synthesis:
    """What a synthesis gave: the asset, how it was made and what it honoured."""

    asset_id: str
    category: str
    how: str  # "synthesised" or "proxy"
    size: Size  # the asset's (x, y, z)
    attributes_honoured: dict[str, str]
    reused: bool
    library: Path
    notes: tuple[str, ...] = ()
    family: str | None = None  # a proxy's family
    folder: str = field(default="", repr=False)
    parts_how: dict[str, str] = field(default_factory=dict)
    """Per part asked (``handles``, ``legs``...): how it was honoured (``"brass on the handles
    (8 parts)"``) or why not (``"not honoured: this sofa has no handles"``)."""


def generator_for(category: str | None) -> str | None:
    """The registered procedural category serving ``category`` (case and separators ignored),
    or None."""
    if not category:
        return None
    from asset_pipeline.procedural import category_info

    try:
        return category_info(category).name
    except InputError:
        return None


def parse_attributes(text: str, category: str | None = None) -> dict[str, str]:
    """The attributes asked in ``text`` (see :func:`attributes_from_text`), as a dict."""
    from asset_pipeline.procedural.attributes import attributes_from_text

    return attributes_from_text(text, category).to_dict()


def recorded_attributes(asset: LibraryAsset) -> dict[str, str]:
    """An asset's attributes: recorded in its metadata, else read from its description."""
    if asset.meta.attributes:
        return dict(asset.meta.attributes)
    return parse_attributes(asset.meta.description, asset.meta.category)


def _generator_info(category: str) -> tuple[Any, bool]:
    """(the CategoryInfo that makes ``category`` on demand, whether it is articulated): the
    articulated generator when the default library holds the category articulated
    (``asset_pipeline.default_library.articulated_synthesis``), else the rigid one."""
    from asset_pipeline.default_library import articulated_synthesis
    from asset_pipeline.procedural import category_info

    info = category_info(category)
    if articulated_synthesis(info.name):
        from asset_pipeline.procedural.articulated import articulated_info

        return articulated_info(info.name), True
    return info, False


def fit_size(category: str, size: Size | None) -> tuple[Size, list[str]]:
    """``size`` (x, y, z) clamped into the category's valid range and ratios, with notes."""
    info, _ = _generator_info(category)
    if size is None:
        return info.default_size, []
    x, y, z = (float(v) for v in size)
    x = min(max(x, info.size_min[0]), info.size_max[0])
    y_low, y_high = info.size_min[1], info.size_max[1]
    if info.yx_ratio is not None:
        y_low, y_high = max(y_low, info.yx_ratio[0] * x), min(y_high, info.yx_ratio[1] * x)
    y = x if info.round else min(max(y, y_low), y_high)
    z_low, z_high = info.size_min[2], info.size_max[2]
    if info.zx_ratio is not None:
        z_low, z_high = max(z_low, info.zx_ratio[0] * x), min(z_high, info.zx_ratio[1] * x)
    z = min(max(z, z_low), z_high)
    fitted = (round(x, SIZE_DECIMALS), round(y, SIZE_DECIMALS), round(z, SIZE_DECIMALS))
    asked = tuple(round(float(v), SIZE_DECIMALS) for v in size)
    notes = []
    if any(abs(a - b) > 1e-6 for a, b in zip(asked, fitted, strict=True)):
        notes.append(
            f"size {_fmt(asked)} m clamped to {_fmt(fitted)} m, the valid range of a "
            f"{info.name} being {_fmt(info.size_min)}..{_fmt(info.size_max)} m (x, y, z)"
        )
    return fitted, notes


def synthesise(
    root: Path | str,
    category: str,
    size: Size | None,
    seed: int = 0,
    attributes: dict[str, str] | None = None,
) -> Synthesis:
    """The asset of registered procedural ``category`` at ``size`` (x, y, z; None: default) in
    style ``seed`` with ``attributes``, in the library at ``root`` (written if new)."""
    from asset_pipeline.procedural import DEFAULT_LIBRARY_VERSION, generate_asset
    from asset_pipeline.procedural.attributes import Attributes
    from asset_pipeline.procedural.conditioning import parts_report

    info, articulated = _generator_info(category)
    name = info.name
    fitted, notes = fit_size(name, size)
    wanted = Attributes.from_dict(attributes)
    key = {
        "kind": "asset",
        "category": name,
        "size": list(fitted),
        "seed": int(seed),
        "attributes": wanted.key(),
        "version": DEFAULT_LIBRARY_VERSION,
    }
    if articulated:
        from asset_pipeline.procedural.articulated import ARTICULATED_VERSION

        key["version"] = ARTICULATED_VERSION
        key["articulated"] = True
    asset_id = f"{name}_{_hash(key)}"

    def build() -> Any:
        if articulated:
            from asset_pipeline.procedural.articulated import generate_articulated

            bundle = generate_articulated(name, asset_id, fitted, int(seed), wanted)
        else:
            bundle = generate_asset(name, asset_id, fitted, int(seed), wanted)
        return _on_demand(bundle, SYNTHESISED_SOURCE)

    folder, reused, meta = _store(Path(root), asset_id, build)
    if tuple(meta.size) != fitted:
        notes.append(f"the {wanted.shape or 'asked'} shape made it {_fmt(meta.size)} m")
    return Synthesis(
        asset_id=asset_id,
        category=name,
        how="synthesised",
        size=tuple(meta.size),
        attributes_honoured=dict(meta.attributes),
        reused=reused,
        library=Path(root),
        notes=tuple(notes),
        folder=folder,
        parts_how=parts_report(info, fitted, int(seed), wanted),
    )


def synthesise_proxy(
    root: Path | str,
    category: str,
    size: Size,
    placement: str = "floor",
    attributes: dict[str, str] | None = None,
) -> Synthesis:
    """A proxy for ``category`` at ``size`` (x, y, z), in the library at ``root``."""
    from asset_pipeline.procedural import DEFAULT_LIBRARY_VERSION
    from asset_pipeline.procedural.attributes import Attributes
    from asset_pipeline.procedural.proxies import build_proxy, proxy_family, proxy_size

    label = proxy_category(category)
    x, y, z = (round(float(v), SIZE_DECIMALS) for v in size)
    asked = (x, y, z)
    family = proxy_family(label, asked, placement)
    wanted = Attributes.from_dict(attributes)
    key = {
        "kind": "proxy",
        "category": label,
        "size": list(asked),
        "placement": placement,
        "attributes": wanted.key(),
        "version": DEFAULT_LIBRARY_VERSION,
    }
    asset_id = f"{label}_{_hash(key)}"

    def build() -> Any:
        bundle, _ = build_proxy(label, asset_id, asked, placement, wanted, family)
        return _on_demand(bundle, PROXY_SOURCE)

    folder, reused, meta = _store(Path(root), asset_id, build)
    notes = []
    fitted = proxy_size(family, asked)
    if any(abs(a - b) > 1e-6 for a, b in zip(asked, fitted, strict=True)):
        notes.append(f"a {family} proxy is {_fmt(meta.size)} m (asked {_fmt(asked)} m)")
    return Synthesis(
        asset_id=asset_id,
        category=label,
        how="proxy",
        size=tuple(meta.size),
        attributes_honoured=dict(meta.attributes),
        reused=reused,
        library=Path(root),
        notes=tuple(notes),
        family=family,
        folder=folder,
        parts_how={p.role: "not honoured: a proxy has no parts" for p in wanted.parts},
    )


def proxy_category(category: str) -> str:
    """A category label for a proxy: lower case, words joined by ``_`` (``Weight Bench`` ->
    ``weight_bench``), at most 48 characters."""
    label = re.sub(r"[^a-z0-9]+", "_", category.lower()).strip("_")[:48].strip("_")
    if not label:
        raise InputError(f"cannot make a category name of {category!r}", where="category")
    return label


class LibrarySynthesiser:
    """Synthesis on demand for one open library (what the retriever calls).

    Assets go into the library's own folder when it is writable, else into ``cache_root``
    (default ``$HOLOMJ_HOME/synthesised``); the open library view learns each one.
    """

    def __init__(self, library: AssetLibrary, cache_root: Path | None = None) -> None:
        self.library = library
        self._cache_root = cache_root
        self._target: Path | None = None

    @property
    def target(self) -> Path:
        """The library folder on-demand assets are written to."""
        if self._target is None:
            root = Path(self.library.root)
            if _writable(root):
                self._target = root
            else:
                self._target = self._cache_root or holomj_home() / CACHE_LIBRARY
                _ensure_library(self._target)
        return self._target

    def generator_for(self, category: str | None) -> str | None:
        """See :func:`generator_for`."""
        return generator_for(category)

    def parse(self, text: str, category: str | None) -> dict[str, str]:
        """See :func:`parse_attributes`."""
        return parse_attributes(text, category)

    def recorded(self, asset: LibraryAsset) -> dict[str, str]:
        """See :func:`recorded_attributes`."""
        return recorded_attributes(asset)

    def synthesise(
        self, category: str, size: Size | None, seed: int, attributes: dict[str, str]
    ) -> Synthesis:
        """See :func:`synthesise`; the asset joins the open library."""
        return self._adopt(synthesise(self.target, category, size, seed, attributes))

    def proxy(
        self, category: str, size: Size, placement: str, attributes: dict[str, str]
    ) -> Synthesis:
        """See :func:`synthesise_proxy`; the asset joins the open library."""
        return self._adopt(synthesise_proxy(self.target, category, size, placement, attributes))

    def _adopt(self, made: Synthesis) -> Synthesis:
        if made.asset_id not in self.library:
            self.library.add_loaded(made.asset_id, made.library / made.folder)
        return made


def _hash(key: dict[str, Any]) -> str:
    text = json.dumps(key, sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(text.encode()).hexdigest()[:12]


def _on_demand(bundle: Any, source: str) -> Any:
    from asset_pipeline.library_writer import AssetBundle

    meta = bundle.meta.model_copy(update={"source": source})
    return AssetBundle(meta=meta, files=bundle.files)


def _store(root: Path, asset_id: str, build: Any) -> tuple[str, bool, Any]:
    """(folder, reused, meta) of ``asset_id`` in the library at ``root``, built if absent."""
    from asset_pipeline.library_writer import add_assets, library_lock

    found = _indexed(root, asset_id)
    if found is not None:
        return found, True, _meta(root / found)
    bundle = build()
    with library_lock(root):
        found = _indexed(root, asset_id)
        if found is not None:  # another process was quicker
            return found, True, _meta(root / found)
        add_assets(root, [bundle])
        folder = _indexed(root, asset_id)
    assert folder is not None
    return folder, False, bundle.meta


def _indexed(root: Path, asset_id: str) -> str | None:
    from holomj.spec.assets import LibraryIndex
    from holomj.spec.base import read_json, validate_model

    path = root / LIBRARY_INDEX
    index = validate_model(LibraryIndex, read_json(path), str(path))
    return index.assets.get(asset_id)


def _meta(folder: Path) -> Any:
    from holomj.spec.assets import AssetMeta
    from holomj.spec.base import read_json, validate_model

    path = folder / LIBRARY_META
    return validate_model(AssetMeta, read_json(path), str(path))


def _writable(root: Path) -> bool:
    index = root / LIBRARY_INDEX
    return os.access(root, os.W_OK) and (not index.exists() or os.access(index, os.W_OK))


def _ensure_library(root: Path) -> None:
    from asset_pipeline.library_writer import library_lock, write_library

    with library_lock(root):
        if not (root / LIBRARY_INDEX).is_file():
            write_library(root, "holomj-synthesised", [], overwrite=root.exists())


def _fmt(size: Any) -> str:
    return "(" + ", ".join(f"{float(v):g}" for v in size) + ")"
