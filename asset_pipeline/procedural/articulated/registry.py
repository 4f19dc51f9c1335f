"""The articulated categories: category name -> generator of a design with moving parts.

They are kept apart from :data:`asset_pipeline.procedural.registry.CATEGORIES` (which makes the
default library): the same category names (``base_cabinet``, ``fridge``) get a rigid asset
there and an articulated one here, and a library chooses which it holds (see
:func:`asset_pipeline.procedural.articulated.library_assets`). Generators take the size and
style seed of the rigid ones, honour the same attributes (colour, material, style, parts such
as "brass handles") and give the same kind of :class:`~.registry.Design`; their moving parts
are :class:`~.links.Moving` parts.
"""

from __future__ import annotations

from collections.abc import Callable

from asset_pipeline.library_writer import AssetBundle
from asset_pipeline.procedural.articulated.assembly import assemble_articulated
from asset_pipeline.procedural.attributes import Attributes
from asset_pipeline.procedural.conditioning import asset_design
from asset_pipeline.procedural.parts import Vec3
from asset_pipeline.procedural.registry import (
    Builder,
    CategoryFacts,
    CategoryInfo,
    Generator,
    Kind,
    lookup,
    registrar,
)

ARTICULATED: dict[str, CategoryInfo] = {}
"""The articulated categories, filled as this package's generator modules are imported."""


def articulated(
    name: str,
    kind: Kind,
    *,
    size: Vec3,
    low: Vec3,
    high: Vec3,
    mass: float,
    description: str,
    placement: tuple[str, ...] = ("floor",),
    friction: float = 0.6,
    variants: tuple[Vec3 | None, ...] = (None,),
    yx_ratio: tuple[float, float] | None = None,
) -> Callable[[Builder], Generator]:
    """Register the decorated builder as the articulated generator of category ``name``
    (as :func:`asset_pipeline.procedural.registry.category` does for rigid ones)."""
    facts = CategoryFacts(
        name, kind, size, low, high, mass, description, placement, friction, yx_ratio, None
    )
    return registrar(ARTICULATED, "articulated category", facts, variants)


def articulated_info(name: str) -> CategoryInfo:
    """The articulated category ``name`` (case and separators ignored), or an InputError."""
    return lookup(ARTICULATED, name, f"no articulated generator for category {name!r}")


def generate_articulated(
    category_name: str,
    asset_id: str,
    size: Vec3 | None = None,
    seed: int = 0,
    attributes: Attributes | None = None,
) -> AssetBundle:
    """Build articulated asset ``asset_id`` of a category at ``size`` (None: default) in style
    ``seed``, honouring ``attributes`` as rigid generators do. Deterministic; InputError for an
    unknown category, a size out of range or a negative seed."""
    asset, resolved = asset_design(
        articulated_info(category_name), asset_id, size, seed, attributes
    )
    return assemble_articulated(asset, expected_size=resolved)
