"""The procedural default library: built on first use, rebuilt when the generators change.

It lives at :func:`holomj.library.default_library_root` (``$HOLOMJ_HOME/library`` or the user
cache dir), next to any assets the user imports there. ``.default_version`` in the library
records which generator version built its procedural assets.
"""

from __future__ import annotations

from pathlib import Path

from asset_pipeline.library_writer import (
    add_assets,
    library_lock,
    remove_assets,
    write_library,
)
from holomj.file_names import LIBRARY_INDEX
from holomj.library.location import default_library_root
from holomj.library.store import AssetLibrary

VERSION_FILE = ".default_version"
PROCEDURAL_SOURCE = "holomj procedural"
# Assets made on demand (holomj.library.synthesis) name the generator version in their ids:
# a refresh removes them with the stale procedural assets.
STALE_SOURCES = frozenset({PROCEDURAL_SOURCE, "holomj synthesised", "holomj proxy"})


ARTICULATED_BY_DEFAULT = True
"""The one-line switch to articulated furniture: when True (the default), the default library
is built as its articulated variant (:func:`asset_pipeline.procedural.articulated.
library_assets`: counters, cabinets, wardrobes, dressers, appliances... with doors, drawers and
lids on real joints), retrieval picks those for every scene and synthesis on demand makes
articulated assets of those categories (:func:`articulated_synthesis`). False gives the rigid
library of before."""


def articulated_synthesis(category: str) -> bool:
    """True when assets of ``category`` made on demand are articulated: the switch is on and
    the articulated library holds the category articulated."""
    if not ARTICULATED_BY_DEFAULT:
        return False
    from asset_pipeline.procedural.articulated import in_library

    return in_library(category)


def ensure_default_library(
    root: Path | None = None, *, force: bool = False, articulated: bool | None = None
) -> Path:
    """Make sure the library at ``root`` (default location if None) holds the current
    procedural assets, building or refreshing them if needed; returns the library root.

    User-imported assets in the same library are kept. ``force`` rebuilds the procedural
    assets even when they are current. ``articulated`` (default
    :data:`ARTICULATED_BY_DEFAULT`) builds the articulated variant instead; switching either
    way refreshes the library (the version marker differs).
    """
    from asset_pipeline.procedural import DEFAULT_LIBRARY_NAME

    if ARTICULATED_BY_DEFAULT if articulated is None else articulated:
        from asset_pipeline.procedural.articulated import ARTICULATED_VERSION as version
        from asset_pipeline.procedural.articulated import library_assets as bundles_of
    else:
        from asset_pipeline.procedural import DEFAULT_LIBRARY_VERSION as version
        from asset_pipeline.procedural import default_assets as bundles_of

    root = Path(root) if root is not None else default_library_root()
    with library_lock(root):
        marker = root / VERSION_FILE
        if not (root / LIBRARY_INDEX).is_file():
            write_library(root, DEFAULT_LIBRARY_NAME, bundles_of(), overwrite=True)
        elif force or not marker.is_file() or marker.read_text().strip() != version:
            bundles = bundles_of()
            fresh = {b.meta.id for b in bundles}
            library = AssetLibrary.open(root)
            stale = [
                i
                for i in library.ids()
                if library.get(i).meta.source in STALE_SOURCES
                and i not in fresh
                and not i.startswith("builtin:")
            ]
            if stale:
                remove_assets(root, stale)
            add_assets(root, bundles)
        else:
            return root
        marker.write_text(version + "\n")
    return root
