"""Parametric procedural assets: furniture, fixtures and small objects for holomj scenes.

Every category in :data:`CATEGORIES` has a generator taking a target size (its bounding box,
x = depth, y = width, z = height, metres) and a seed for style variation.
:func:`generate_asset` builds one asset; :func:`default_assets` the default library (two style
variants of each piece of furniture, one or two of each small object) and
:func:`build_default_library` writes it. :data:`DEFAULT_LIBRARY_VERSION` changes whenever the
generators do, so a library built earlier can be recognised as stale.
"""

from __future__ import annotations

import hashlib
from pathlib import Path

import numpy as np

from asset_pipeline.library_writer import write_library
from asset_pipeline.procedural.assembly import AssetDesign, assemble
from asset_pipeline.procedural.catalog import default_assets, default_variants, generate_asset
from asset_pipeline.procedural.registry import CATEGORIES, CategoryInfo, Design, category_info
from holomj.spec.assets import ASSET_SCHEMA_VERSION


def _source_hash() -> str:
    """sha256 over the generator sources, the asset schema and numpy's version (its RNG).

    The generators' sources include the modules outside this package whose output lands in
    the assets: the collider audit (``collider_gap_m``) and the texture patterns.
    """
    digest = hashlib.sha256(f"schema {ASSET_SCHEMA_VERSION} numpy {np.__version__}\0".encode())
    here = Path(__file__).parent
    outside = [here.parent / "collider_audit.py", here.parents[1] / "holomj/mjcf/textures.py"]
    for path in [*sorted(here.glob("*.py")), *outside]:
        digest.update(path.name.encode() + b"\0" + path.read_bytes() + b"\0")
    return digest.hexdigest()[:12]


DEFAULT_LIBRARY_VERSION: str = _source_hash()
DEFAULT_LIBRARY_NAME = f"holomj-default-{DEFAULT_LIBRARY_VERSION}"

__all__ = [
    "CATEGORIES",
    "DEFAULT_LIBRARY_NAME",
    "DEFAULT_LIBRARY_VERSION",
    "AssetDesign",
    "CategoryInfo",
    "Design",
    "assemble",
    "build_default_library",
    "category_info",
    "default_assets",
    "default_variants",
    "generate_asset",
]


def build_default_library(root: Path | str, overwrite: bool = True) -> Path:
    """Write the default library to ``root`` (atomically) and return ``root``."""
    return write_library(Path(root), DEFAULT_LIBRARY_NAME, default_assets(), overwrite=overwrite)
