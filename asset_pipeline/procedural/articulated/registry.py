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

import functools
from collections.abc import Callable

import numpy as np

from asset_pipeline.library_writer import AssetBundle
from asset_pipeline.procedural.articulated.assembly import assemble_articulated
from asset_pipeline.procedural.assembly import AssetDesign
from asset_pipeline.procedural.parts import Vec3
from asset_pipeline.procedural.registry import (
    Builder,
    CategoryInfo,
    Design,
    Generator,
    Kind,
    rng_for,
)
from holomj.errors import InputError, closest_names

ARTICULATED: dict[str, CategoryInfo] = {}


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

    def register(builder: Builder) -> Generator:
        if name in ARTICULATED:
            raise ValueError(f"articulated category {name!r} registered twice")
        info = CategoryInfo(
            name=name,
            kind=kind,
            builder=builder,
            default_size=size,
            size_min=low,
            size_max=high,
            mass_kg=mass,
            description=description,
            placement=placement,
            friction=friction,
            yx_ratio=yx_ratio,
            variants=variants,
        )
        for variant in (size, *(v for v in variants if v is not None)):
            info.check_size(variant)
        ARTICULATED[name] = info

        @functools.wraps(builder)
        def generate(size: Vec3 | None, rng: np.random.Generator) -> Design:
            return info.generate(size, rng)

        return generate

    return register


def articulated_info(name: str) -> CategoryInfo:
    """The articulated category ``name`` (case and separators ignored), or an InputError."""
    if name in ARTICULATED:
        return ARTICULATED[name]
    key = "".join(ch for ch in name.lower() if ch.isalnum())
    for known, info in ARTICULATED.items():
        if "".join(ch for ch in known.lower() if ch.isalnum()) == key:
            return info
    near = closest_names(name, ARTICULATED)
    hint = f"did you mean: {near}" if near else f"known: {', '.join(sorted(ARTICULATED))}"
    raise InputError(f"no articulated generator for category {name!r}", fix=hint)


def generate_articulated(
    category_name: str,
    asset_id: str,
    size: Vec3 | None = None,
    seed: int = 0,
    attributes: object | None = None,
) -> AssetBundle:
    """Build articulated asset ``asset_id`` of a category at ``size`` (None: default) in style
    ``seed``, honouring ``attributes`` (:class:`~asset_pipeline.procedural.attributes.
    Attributes`) as rigid generators do. Deterministic; InputError for an unknown category, a
    size out of range or a negative seed."""
    info = articulated_info(category_name)
    resolved = info.check_size(size)
    honoured: dict[str, str] = {}
    if attributes:
        from asset_pipeline.procedural.attributes import conditioned_design, described

        design, resolved, honoured = conditioned_design(info, resolved, seed, attributes)
    else:
        design = info.builder(resolved, rng_for(info.name, seed))
    description = " ".join(info.description.format(**design.words).split())
    if attributes:
        description = described(description, info.name, attributes, honoured)  # type: ignore[arg-type]
    asset = AssetDesign(
        id=asset_id,
        category=info.name,
        description=description,
        mass_kg=info.mass_for(resolved),
        friction=info.friction,
        placement=info.placement,
        parts=design.parts,
        attributes=tuple(honoured.items()),
    )
    return assemble_articulated(asset, expected_size=resolved)
