"""The catalogue: every registered category (this module imports every generator module, so
they all register, and sorts them in catalogue order), one asset of any of them, and the
variants of the default library."""

from __future__ import annotations

from asset_pipeline.library_writer import AssetBundle

# Importing the generator modules registers their categories.
from asset_pipeline.procedural import (
    appliances,
    bath_fixtures,
    furniture,
    home_cabinets,
    home_ceiling,
    home_counters_racks,
    home_decor,
    home_hanging_decor,
    home_laundry,
    home_lounge,
    home_seating,
    home_standing,
    home_tables,
    home_utility,
    home_wall,
    home_wall_fittings,
    household,
    leisure_games,
    leisure_gym,
    leisure_hospitality,
    leisure_machines,
    leisure_music_art,
    leisure_wall_decor,
    objects,
    office_seating,
    seating,
    shelving,
    small_appliances,
    small_bath_wardrobe,
    small_decor,
    small_electronics,
    small_kitchenware,
    small_media,
    small_office,
    small_toys_sport,
    small_workshop,
    storage,
    tables,
    work_boards,
    work_health,
    work_office,
    work_shop,
    work_studio,
    work_warehouse,
    work_workshop_lab,
)
from asset_pipeline.procedural.assembly import AssetDesign, assemble
from asset_pipeline.procedural.attributes import Attributes
from asset_pipeline.procedural.conditioning import asset_design
from asset_pipeline.procedural.parts import Vec3
from asset_pipeline.procedural.registry import CATEGORIES, category_info

# Catalogue order: furniture, home pieces, storage and fixtures, appliances, leisure, work,
# small objects. Each module's categories keep the order in which the module registers them.
_MODULES = (
    furniture,
    seating,
    office_seating,
    tables,
    home_seating,
    home_lounge,
    home_cabinets,
    home_tables,
    home_counters_racks,
    home_laundry,
    home_utility,
    home_standing,
    home_wall,
    home_wall_fittings,
    home_ceiling,
    home_hanging_decor,
    storage,
    shelving,
    bath_fixtures,
    appliances,
    home_decor,
    leisure_gym,
    leisure_games,
    leisure_music_art,
    leisure_hospitality,
    leisure_machines,
    leisure_wall_decor,
    work_workshop_lab,
    work_office,
    work_shop,
    work_health,
    work_studio,
    work_warehouse,
    work_boards,
    objects,
    household,
    small_electronics,
    small_media,
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


def design_for(
    category_name: str,
    asset_id: str,
    size: Vec3 | None = None,
    seed: int = 0,
    attributes: Attributes | None = None,
) -> tuple[AssetDesign, Vec3]:
    """The design of asset ``asset_id`` of a category (not yet assembled) and its checked size
    (see :func:`~.conditioning.asset_design`)."""
    return asset_design(category_info(category_name), asset_id, size, seed, attributes)


def generate_asset(
    category_name: str,
    asset_id: str,
    size: Vec3 | None = None,
    seed: int = 0,
    attributes: Attributes | None = None,
) -> AssetBundle:
    """Build asset ``asset_id`` of a category at ``size`` (None: default) in style ``seed``.

    ``attributes`` (colour, material, shape, style; see :mod:`.attributes`) condition the
    design; those honoured are recorded in the metadata (``attributes``). A shape may change
    the size (a round table's footprint is square: its side is the smaller planned one).
    Deterministic: the same (category, size, seed, attributes) gives byte-identical files.
    Raises :class:`~holomj.errors.InputError` for an unknown category, a size outside the
    category's range or a negative seed.
    """
    asset, resolved = design_for(category_name, asset_id, size, seed, attributes)
    return assemble(asset, expected_size=resolved)


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
