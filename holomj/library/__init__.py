"""Reading asset libraries from disk."""

from holomj.library.store import AssetLibrary, default_library_path

__all__ = ["AssetLibrary", "default_library_path"]
