"""Procedural articulated assets: furniture and appliances with doors, drawers and lids.

Every category of :data:`ARTICULATED` builds an asset whose moving parts are recorded in its
metadata (:class:`holomj.spec.assets.Articulation`: parts with their meshes, colliders, joint,
handle; interior surfaces) and compiled by holomj with real hinge and slide joints.

:func:`library_assets` is the articulated variant of the default library (what
``asset_pipeline.default_library.ARTICULATED_BY_DEFAULT`` builds, on by default): the same
assets, except that every category of :data:`LIBRARY_ARTICULATED` gets articulated assets (ids
``<category>_art_NNN``) in place of its rigid ones, so retrieval picks them for kitchens and
bedrooms, and synthesis on demand makes them (:func:`in_library`). The laptop is the one
articulated category left out (:data:`KEPT_RIGID`): the planner puts laptops on desks open, as
the rigid one stands (23 cm tall), while the articulated one is closed (2 cm); it stays
available through :func:`build_articulated_library` and :func:`generate_articulated`.
:data:`ARTICULATED_VERSION` covers these generators and the rigid ones (this package is outside
``DEFAULT_LIBRARY_VERSION``).
"""

from __future__ import annotations

import hashlib
from pathlib import Path

from asset_pipeline.library_writer import AssetBundle, write_library
from asset_pipeline.procedural import DEFAULT_LIBRARY_VERSION, default_assets
from asset_pipeline.procedural.articulated import (  # noqa: F401
    appliances,
    cabinets,
    counters,
    lids,
)
from asset_pipeline.procedural.articulated.registry import (
    ARTICULATED,
    articulated_info,
    generate_articulated,
)

__all__ = [
    "ARTICULATED",
    "ARTICULATED_VERSION",
    "KEPT_RIGID",
    "LIBRARY_ARTICULATED",
    "articulated_assets",
    "articulated_info",
    "articulated_variants",
    "build_articulated_library",
    "generate_articulated",
    "in_library",
    "library_assets",
]

KEPT_RIGID = frozenset({"laptop"})
"""Articulated categories whose rigid assets the library variant keeps (see the module
docstring)."""
LIBRARY_ARTICULATED = frozenset(ARTICULATED) - KEPT_RIGID
"""The categories the library variant holds articulated."""


def in_library(category: str) -> bool:
    """True when the articulated variant of the default library holds ``category``
    articulated (and synthesis on demand, with the switch on, makes it articulated)."""
    return category in LIBRARY_ARTICULATED


def _version() -> str:
    digest = hashlib.sha256(f"rigid {DEFAULT_LIBRARY_VERSION}\0".encode())
    for path in sorted(Path(__file__).parent.glob("*.py")):
        digest.update(path.name.encode() + b"\0" + path.read_bytes() + b"\0")
    return "art-" + digest.hexdigest()[:12]


ARTICULATED_VERSION: str = _version()


def articulated_variants(
    categories: list[str] | None = None,
) -> list[tuple[str, str, tuple[float, float, float] | None, int]]:
    """(asset id, category, size or None for the default, seed) of every articulated asset of
    the library variant (of ``categories`` only, when given)."""
    wanted = set(categories) if categories is not None else None
    return [
        (f"{name}_art_{seed:03d}", name, size, seed)
        for name, info in ARTICULATED.items()
        if wanted is None or name in wanted
        for seed, size in enumerate(info.variants)
    ]


def articulated_assets(categories: list[str] | None = None) -> list[AssetBundle]:
    """The articulated assets of the library variant (of ``categories`` only, when given)."""
    return [
        generate_articulated(name, asset_id, size, seed)
        for asset_id, name, size, seed in articulated_variants(categories)
    ]


def library_assets() -> list[AssetBundle]:
    """The articulated variant of the default library: the default assets with those of every
    category of :data:`LIBRARY_ARTICULATED` replaced by articulated ones."""
    rigid = [b for b in default_assets() if b.meta.category not in LIBRARY_ARTICULATED]
    return rigid + articulated_assets(sorted(LIBRARY_ARTICULATED))


def build_articulated_library(
    root: Path | str, categories: list[str] | None = None, overwrite: bool = True
) -> Path:
    """Write a library of articulated assets only (of ``categories``, when given) to ``root``,
    atomically; for tests and for adding them to another library."""
    return write_library(
        Path(root),
        f"holomj-articulated-{ARTICULATED_VERSION}",
        articulated_assets(categories),
        overwrite=overwrite,
    )
