"""The objathor import job (``holomj assets import-objathor DIR``): Objaverse assets of an
objathor directory, the ones Holodeck houses name by uid, become library assets whose ids are
those uids (see :mod:`asset_pipeline.objathor` for the layout and the frames, and
:mod:`asset_pipeline.objathor_import` for the import).

The asset pipeline is imported inside the function: holomj's core never depends on it.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace
from pathlib import Path
from typing import Literal

from holomj.errors import InputError
from holomj.jobs.assets import DEFAULT_IMPORT_RUN, AssetImport, ImportRun
from holomj.jobs.library import resolve_library
from holomj.library.store import AssetLibrary
from holomj.spec.choices import one_of

ColliderMode = Literal["shipped", "coacd"]
COLLIDER_MODES: tuple[ColliderMode, ...] = ("shipped", "coacd")


def parse_uids(text: str | Sequence[str] | None) -> list[str] | None:
    """``"a,b"`` (or a list of such strings) -> ``["a", "b"]``; None or nothing -> None."""
    if text is None:
        return None
    items = [text] if isinstance(text, str) else list(text)
    uids = [u.strip() for item in items for u in item.split(",") if u.strip()]
    return uids or None


def import_objathor(
    directory: Path,
    *,
    library: Path | None = None,
    uids: Sequence[str] | None = None,
    colliders: str = "shipped",
    run: ImportRun = DEFAULT_IMPORT_RUN,
) -> AssetImport:
    """Import the assets of the objathor ``directory`` (only ``uids`` when given) into
    ``library`` (default: the default library; a new folder becomes an empty library first).

    ``colliders``: ``shipped`` (the asset's own convex pieces; CoACD where it has none) or
    ``coacd`` (the pipeline's decomposition with ``run``'s CoACD settings); ``run``: how it
    runs (workers, thumbnails, progress hooks). The options and the directory are checked
    before anything is written; a uid that fails is reported in the summary and the others go
    on. Re-importing unchanged assets takes them from the library's cache.
    """
    from asset_pipeline.objathor import plan_objathor
    from asset_pipeline.objathor_import import ObjathorOptions, run_objathor_imports

    mode = one_of(colliders, COLLIDER_MODES)
    if mode is None:
        raise InputError(
            f"unknown collider source {colliders!r}",
            where="--colliders",
            fix=f"use one of: {', '.join(COLLIDER_MODES)}",
        )
    options = ObjathorOptions(colliders=mode, coacd=run.coacd())
    jobs = plan_objathor(directory, uids)  # checked before anything is written
    root = resolve_library(library, create=True)
    held = set(AssetLibrary.open(root).ids())
    note = "replaces the library's asset {!r}"
    jobs = [replace(j, id_note=note.format(j.uid)) if j.uid in held else j for j in jobs]
    run.planned(len(jobs))
    summary = run_objathor_imports(
        jobs,
        Path(root),
        options,
        workers=run.workers,
        thumbnails=run.thumbnails,
        accept_fallback=run.accept_fallback,
        on_done=run.on_done,
    )
    return AssetImport(Path(root), summary)
