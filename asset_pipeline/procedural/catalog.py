"""The catalogue: every registered category and the variants of the default library."""

from __future__ import annotations

from asset_pipeline.library_writer import AssetBundle

# Importing the generator modules registers their categories.
from asset_pipeline.procedural import (
    appliances,
    furniture,
    home_cabinets,
    home_ceiling,
    home_counters_racks,
    home_laundry,
    home_seating,
    home_utility,
    home_wall,
    leisure_games,
    leisure_gym,
    leisure_hospitality,
    leisure_music_art,
    leisure_wall_decor,
    objects,
    small_appliances,
    small_bath_wardrobe,
    small_decor,
    small_electronics,
    small_kitchenware,
    small_office,
    small_toys_sport,
    small_workshop,
    storage,
    work_boards,
    work_health,
    work_office,
    work_shop,
    work_studio,
    work_warehouse,
    work_workshop_lab,
)
from asset_pipeline.procedural.registry import CATEGORIES, generate_asset

# Catalogue order: furniture, home pieces, storage and fixtures, appliances, leisure, work,
# small objects. Each module's categories keep the order in which the module registers them.
_MODULES = (
    furniture,
    home_seating,
    home_cabinets,
    home_counters_racks,
    home_laundry,
    home_utility,
    home_wall,
    home_ceiling,
    storage,
    appliances,
    leisure_gym,
    leisure_games,
    leisure_music_art,
    leisure_hospitality,
    leisure_wall_decor,
    work_workshop_lab,
    work_office,
    work_shop,
    work_health,
    work_studio,
    work_warehouse,
    work_boards,
    objects,
    small_electronics,
    small_appliances,
    small_kitchenware,
    small_office,
    small_decor,
    small_toys_sport,
    small_bath_wardrobe,
    small_workshop,
)
_ORDER = {m.__name__: i for i, m in enumerate(_MODULES)}
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
