"""The asset-library jobs (``holomj assets ...``): build the default library, import meshes as
simulation-ready assets, list, show and remove assets.

The asset pipeline is imported inside the functions: holomj's core never depends on it.
"""

from __future__ import annotations

import json
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Literal, cast, get_args

from holomj.errors import InputError
from holomj.jobs.library import resolve_library
from holomj.library.store import AssetLibrary
from holomj.spec.categories import normalise_category

UpAxis = Literal["y", "z"]
Front = Literal["+x", "-x", "+y", "-y"]
UP_AXES: tuple[str, ...] = get_args(UpAxis)
FRONTS: tuple[str, ...] = get_args(Front)


@dataclass(frozen=True)
class DefaultLibrary:
    """The default library after a build: where, how many assets, how long it took."""

    root: Path
    assets: int
    seconds: float


@dataclass(frozen=True)
class AssetImport:
    """What an import did: the library imported into and the per-file summary."""

    library: Path
    summary: Any  # asset_pipeline.manage.ImportSummary

    def to_dict(self) -> dict[str, Any]:
        """JSON-able: the library and the summary's outcomes."""
        return {"library": str(self.library), **self.summary.to_dict()}


@dataclass(frozen=True)
class ImportRun:
    """How an import job runs, whatever it imports: the CoACD settings (``preset`` with the
    ``threshold`` / ``max_hulls`` / ``timeout_s`` overrides, None keeping the preset's), the
    parallel ``workers``, ``thumbnails``, whether fallback decompositions are cached as final
    (``accept_fallback``), and the progress hooks: ``on_planned`` gets the number of files once
    they are listed, ``on_done`` each file's outcome as it finishes."""

    preset: str = "default"
    threshold: float | None = None
    max_hulls: int | None = None
    timeout_s: float | None = None
    workers: int = 1
    thumbnails: bool = True
    accept_fallback: bool = False
    on_planned: Callable[[int], None] | None = None
    on_done: Callable[[Any], None] | None = None

    def coacd(self) -> Any:
        """The pipeline's CoacdParams of these settings; an InputError for an unknown preset."""
        from asset_pipeline.manage import coacd_params

        return coacd_params(
            self.preset,
            threshold=self.threshold,
            max_convex_hull=self.max_hulls,
            timeout_s=self.timeout_s,
        )

    def planned(self, count: int) -> None:
        """Tell ``on_planned`` (when given) that ``count`` files will be imported."""
        if self.on_planned is not None:
            self.on_planned(count)


DEFAULT_IMPORT_RUN = ImportRun()


@dataclass(frozen=True)
class AssetListing:
    """The assets of a library: its name and root, one row per asset."""

    name: str
    root: Path
    rows: list[dict[str, Any]]


def check_library(root: Path) -> Path:
    """``root`` when it holds an asset library, else the one-line error opening it gives."""
    AssetLibrary.open(root)
    return root


def build_default_library(library: Path | None = None, *, force: bool = False) -> DefaultLibrary:
    """Build (or refresh) the procedural default library at ``library`` (default location if
    None); ``force`` rebuilds it even when it is current."""
    from asset_pipeline.default_library import ensure_default_library

    start = time.perf_counter()
    root = ensure_default_library(library, force=force)
    count = len(AssetLibrary.open(root))
    return DefaultLibrary(Path(root), count, time.perf_counter() - start)


def import_assets(
    paths: Sequence[Path],
    *,
    library: Path | None = None,
    asset_id: str | None = None,
    category: str | None = None,
    size: tuple[float, float, float] | None = None,
    description: str | None = None,
    mass_kg: float | None = None,
    up: str | None = None,
    front: str = "+x",
    run: ImportRun = DEFAULT_IMPORT_RUN,
) -> AssetImport:
    """Import the mesh files (or folders of them) ``paths`` into ``library`` (default: the
    default library; a new folder becomes an empty library first).

    ``run``: how it runs (CoACD settings, workers, thumbnails, progress hooks). The options are
    checked and the files listed before anything is written. Ids never silently take over
    another asset's (see :func:`asset_pipeline.import_plan.plan_jobs`: a clash gets a ``-2``
    suffix and a note, a clashing ``asset_id`` fails). A file that fails is reported in the
    summary and the others go on; see :func:`asset_pipeline.manage.run_imports` for degraded
    (fallback) decompositions.
    """
    from asset_pipeline.import_plan import existing_assets, plan_jobs
    from asset_pipeline.manage import run_imports

    options = _import_options(category, size, description, mass_kg, up, front, run)
    plan_jobs(paths, asset_id)  # the files are checked before anything is written
    root = resolve_library(library, create=True)
    jobs = plan_jobs(paths, asset_id, existing_assets(root))
    run.planned(len(jobs))
    summary = run_imports(
        jobs,
        root,
        options,
        workers=run.workers,
        thumbnails=run.thumbnails,
        on_done=run.on_done,
        accept_fallback=run.accept_fallback,
    )
    return AssetImport(root, summary)


def _import_options(
    category: str | None,
    size: tuple[float, float, float] | None,
    description: str | None,
    mass_kg: float | None,
    up: str | None,
    front: str,
    run: ImportRun,
) -> Any:
    """The pipeline's ImportOptions; an InputError for a bad axis, front or CoACD preset."""
    from asset_pipeline.importer import ImportOptions

    if up is not None and up not in UP_AXES:
        raise InputError(f"unknown up axis {up!r}", where="--up", fix="use y or z")
    if front not in FRONTS:
        raise InputError(f"unknown front {front!r}", where="--front", fix="use +x, -x, +y or -y")
    return ImportOptions(
        category=category,
        size=size,
        description=description,
        mass_kg=mass_kg,
        up_axis=cast(UpAxis | None, up),  # checked against UP_AXES above
        front=cast(Front, front),  # checked against FRONTS above
        coacd=run.coacd(),  # after the axes, as the options are checked in order
    )


def list_assets(library: Path, category: str | None = None) -> AssetListing:
    """The assets of ``library`` (only ``category`` when given): id, category, size, mass,
    placement, surfaces, colliders, and whether a fallback decomposition made it (degraded)."""
    lib = AssetLibrary.open(library)
    assets = [lib.get(i) for i in lib.ids()]
    if category is not None:
        wanted = normalise_category(category)
        assets = [a for a in assets if normalise_category(a.meta.category) == wanted]
    rows = [
        {
            "id": a.meta.id,
            "category": a.meta.category,
            "size_m": [round(v, 3) for v in a.meta.size],
            "mass_kg": round(a.meta.mass, 3),
            "placement": a.meta.placement,
            "surfaces": len(a.meta.surfaces),
            "colliders": len(a.meta.collision),
            "degraded": _is_degraded(a.root),
        }
        for a in assets
    ]
    return AssetListing(lib.name, Path(library), rows)


def _is_degraded(asset_root: Path) -> bool:
    """Whether the asset's ``derivation.json`` marks it degraded (False when there is none)."""
    derivation = asset_root / "derivation.json"
    if not derivation.is_file():
        return False
    try:
        return bool(json.loads(derivation.read_text()).get("degraded"))
    except (OSError, ValueError, AttributeError):
        return False


def show_asset(library: Path, asset_id: str) -> dict[str, Any]:
    """An asset's folder, metadata and, when it has one, how it was derived."""
    asset = AssetLibrary.open(library).get(asset_id)
    data: dict[str, Any] = {"folder": str(asset.root), "meta": asset.meta.model_dump(mode="json")}
    derivation = asset.root / "derivation.json"
    if derivation.is_file():
        data["derivation"] = json.loads(derivation.read_text())
    return data


def remove_assets(library: Path, asset_ids: Sequence[str]) -> list[str]:
    """Remove the assets ``asset_ids`` from ``library``; returns the folders deleted."""
    from asset_pipeline.library_writer import remove_assets as remove

    return remove(library, asset_ids)
