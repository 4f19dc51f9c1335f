"""Where the default asset library lives: ``$HOLOMJ_HOME/library``, else the user cache dir."""

from __future__ import annotations

import os
from pathlib import Path


def holomj_home() -> Path:
    """``$HOLOMJ_HOME`` if set, else ``$XDG_CACHE_HOME/holomj`` (default ``~/.cache/holomj``)."""
    home = os.environ.get("HOLOMJ_HOME")
    if home:
        return Path(home).expanduser()
    cache = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
    return Path(cache).expanduser() / "holomj"


def default_library_root() -> Path:
    """The library every command uses unless it is given ``--library``."""
    return holomj_home() / "library"
