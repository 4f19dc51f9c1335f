"""The procedural default library: built on first use, rebuilt when the generators change.

It lives at :func:`holomj.library.default_library_root` (``$HOLOMJ_HOME/library`` or the user
cache dir), next to any assets the user imports there. ``.default_version`` in the library
records which generator version built its procedural assets.
"""

from __future__ import annotations

from pathlib import Path

from asset_pipeline.library_writer import (
    INDEX_FILE,
    add_assets,
    library_lock,
    remove_assets,
)
from holomj.library.location import default_library_root
from holomj.library.store import AssetLibrary

VERSION_FILE = ".default_version"
PROCEDURAL_SOURCE = "holomj procedural"
# Assets made on demand (holomj.library.synthesis) name the generator version in their ids:
# a refresh removes them with the stale procedural assets.
STALE_SOURCES = frozenset({PROCEDURAL_SOURCE, "holomj synthesised", "holomj proxy"})


def ensure_default_library(root: Path | None = None, *, force: bool = False) -> Path:
    """Make sure the library at ``root`` (default location if None) holds the current
    procedural assets, building or refreshing them if needed; returns the library root.

    User-imported assets in the same library are kept. ``force`` rebuilds the procedural
    assets even when they are current.
    """
    from asset_pipeline.procedural import (
        DEFAULT_LIBRARY_VERSION,
        build_default_library,
        default_assets,
    )

    root = Path(root) if root is not None else default_library_root()
    with library_lock(root):
        marker = root / VERSION_FILE
        if not (root / INDEX_FILE).is_file():
            build_default_library(root, overwrite=True)
        elif force or not marker.is_file() or marker.read_text().strip() != DEFAULT_LIBRARY_VERSION:
            bundles = default_assets()
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
        marker.write_text(DEFAULT_LIBRARY_VERSION + "\n")
    return root
