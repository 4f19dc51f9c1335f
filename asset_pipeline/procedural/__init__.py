"""Procedural assets built from boxes, cylinders and surfaces of revolution.

:func:`default_assets` builds the bundles of holomj's default library and
:func:`build_default_library` writes them (``scripts/build_default_library.py`` calls it).
"""

from __future__ import annotations

from pathlib import Path

from asset_pipeline.library_writer import AssetBundle, write_library
from asset_pipeline.procedural.assembly import AssetDesign, assemble, assemble_all
from asset_pipeline.procedural.catalog import default_designs

DEFAULT_LIBRARY_NAME = "holomj-default"

__all__ = [
    "DEFAULT_LIBRARY_NAME",
    "AssetDesign",
    "assemble",
    "build_default_library",
    "default_assets",
]


def default_assets() -> list[AssetBundle]:
    """The bundles of the default library, in catalogue order."""
    return assemble_all(default_designs())


def build_default_library(root: Path | str, overwrite: bool = True) -> Path:
    """Write the default library to ``root`` (atomically) and return ``root``."""
    return write_library(Path(root), DEFAULT_LIBRARY_NAME, default_assets(), overwrite=overwrite)
