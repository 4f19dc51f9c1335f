"""The catalogue: every registered category and the variants of the default library."""

from __future__ import annotations

from asset_pipeline.library_writer import AssetBundle

# Importing the generator modules registers their categories.
from asset_pipeline.procedural import (
    appliances,
    furniture,
    home,
    leisure,
    objects,
    small_items,
    storage,
    work,
)
from asset_pipeline.procedural.registry import CATEGORIES, generate_asset

# Catalogue order: furniture, storage and fixtures, appliances and decor, small objects.
_ORDER = {
    m.__name__: i
    for i, m in enumerate(
        (furniture, home, storage, appliances, leisure, work, objects, small_items)
    )
}
_SORTED = sorted(CATEGORIES.items(), key=lambda item: _ORDER[item[1].builder.__module__])
CATEGORIES.clear()
CATEGORIES.update(_SORTED)


def default_variants() -> list[tuple[str, str, tuple[float, float, float] | None, int]]:
    """(asset id, category, size or None for the default, seed) of every default asset."""
    return [
        (f"{name}_{seed:03d}", name, size, seed)
        for name, info in CATEGORIES.items()
        for seed, size in enumerate(info.variants)
    ]


def default_assets() -> list[AssetBundle]:
    """The bundles of the default library, in catalogue order."""
    return [
        generate_asset(name, asset_id, size, seed)
        for asset_id, name, size, seed in default_variants()
    ]
