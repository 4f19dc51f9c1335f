"""Reading asset libraries from disk."""

from holomj.library.location import default_library_root, holomj_home
from holomj.library.store import AssetLibrary

__all__ = ["AssetLibrary", "default_library_root", "holomj_home"]
