"""Which asset library a job uses: the one given, or the default one, built on first use.

The default library lives at ``$HOLOMJ_HOME/library`` (else the user cache folder, see
:mod:`holomj.library.location`); it is the procedural library of ``asset_pipeline``, built there
the first time it is needed and refreshed when its generators change.
"""

from __future__ import annotations

from pathlib import Path

from holomj.file_names import LIBRARY_INDEX
from holomj.library.store import AssetLibrary


def resolve_library(path: Path | str | AssetLibrary | None, create: bool = False) -> Path:
    """The root of the library to use: ``path`` (or an open library's root), or the default
    library (built on first use).

    With ``create``, an empty library is made at ``path`` when it holds none yet (for imports
    into a new library). Raises :class:`~holomj.errors.HolomjError` when the default library
    cannot be built or the empty one cannot be written.
    """
    if path is None:
        from asset_pipeline.default_library import ensure_default_library

        return Path(ensure_default_library())
    if isinstance(path, AssetLibrary):
        return path.root
    path = Path(path)
    if create and not (path / LIBRARY_INDEX).exists():
        from asset_pipeline.library_writer import write_library

        write_library(path, path.name, [], overwrite=path.exists() and not any(path.iterdir()))
    return path


def default_library() -> AssetLibrary:
    """The default library, opened (and built on first use)."""
    return AssetLibrary.open(resolve_library(None))
