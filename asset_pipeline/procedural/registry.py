"""The category registry: category name -> parametric generator and its physical facts.

Every generator is registered with :func:`category` and called as
``CATEGORIES[name].generate(size, rng)``: ``size`` is the asset's bounding box (x = depth,
y = width, z = height, metres; None for the category's default) and ``rng`` drives the style
(proportions, colours, leg style, number of drawers, ...). The generated visual bounding box
equals ``size`` (checked within 1 mm when assembled).
"""

from __future__ import annotations

import functools
import math
import zlib
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Literal

import numpy as np

from asset_pipeline.library_writer import AssetBundle
from asset_pipeline.procedural.assembly import AssetDesign, assemble
from asset_pipeline.procedural.parts import Part, Vec3
from holomj.errors import InputError, closest_names

if TYPE_CHECKING:
    from asset_pipeline.procedural.attributes import Attributes

Kind = Literal["furniture", "object"]
SIZE_TOLERANCE = 1e-3  # generated bbox vs requested size, and round footprints' x vs y


@dataclass(frozen=True)
class Design:
    """What a generator returns: the parts (any frame) and the words for the description."""

    parts: tuple[Part, ...]
    words: dict[str, str] = field(default_factory=dict)


Builder = Callable[[Vec3, np.random.Generator], Design]
Generator = Callable[[Vec3 | None, np.random.Generator], Design]


@dataclass(frozen=True)
class CategoryInfo:
    """A category's generator and facts.

    ``mass_kg`` is the mass at ``default_size``; other sizes scale it with the bounding-box
    volume (:meth:`mass_for`). ``yx_ratio`` bounds width / depth (``(1, 1)``: a round
    footprint, x and y equal). ``variants`` lists the sizes of the default library's
    variants (seed i gets ``variants[i]``; None is the default size).
    """

    name: str
    kind: Kind
    builder: Builder
    default_size: Vec3
    size_min: Vec3
    size_max: Vec3
    mass_kg: float
    description: str
    placement: tuple[str, ...] = ("floor",)
    friction: float = 0.8
    yx_ratio: tuple[float, float] | None = None
    zx_ratio: tuple[float, float] | None = None
    variants: tuple[Vec3 | None, ...] = (None, None)

    @property
    def round(self) -> bool:
        """True if the footprint is round (x and y must be equal)."""
        return self.yx_ratio == (1.0, 1.0)

    def check_size(self, size: Vec3 | None) -> Vec3:
        """``size`` (or the default) as floats, or an InputError naming the valid range."""
        if size is None:
            return self.default_size
        where = f"category {self.name!r}"
        try:
            values = tuple(float(v) for v in size)
        except (TypeError, ValueError):
            values = ()
        if len(values) != 3 or not all(math.isfinite(v) for v in values):
            raise InputError(
                f"size must be three finite numbers (x, y, z), got {size!r}", where=where
            )
        x, y, z = values
        out = [
            f"{axis} = {v:g} m not in [{lo:g}, {hi:g}]"
            for axis, v, lo, hi in zip("xyz", values, self.size_min, self.size_max, strict=True)
            if not (lo - 1e-9 <= v <= hi + 1e-9)
        ]
        if out:
            raise InputError(
                f"size {_fmt(values)} is outside the valid range: {'; '.join(out)}",
                where=where,
                fix=f"use a size between {_fmt(self.size_min)} and {_fmt(self.size_max)} m",
            )
        if self.yx_ratio is not None:
            low, high = self.yx_ratio
            if self.round and abs(y - x) > SIZE_TOLERANCE:
                raise InputError(
                    f"size {_fmt(values)}: a {self.name} is round, so x and y must be equal",
                    where=where,
                    fix=f"use e.g. ({x:g}, {x:g}, {z:g})",
                )
            if not self.round and not (low - 1e-9 <= y / x <= high + 1e-9):
                raise InputError(
                    f"size {_fmt(values)}: y / x = {y / x:.3f} is not in [{low:g}, {high:g}]",
                    where=where,
                    fix=f"give y between {low * x:.3f} and {high * x:.3f} m for x = {x:g} m",
                )
        if self.zx_ratio is not None:
            low, high = self.zx_ratio
            if not (low - 1e-9 <= z / x <= high + 1e-9):
                raise InputError(
                    f"size {_fmt(values)}: z / x = {z / x:.3f} is not in [{low:g}, {high:g}]",
                    where=where,
                    fix=f"give z between {low * x:.3f} and {high * x:.3f} m for x = {x:g} m",
                )
        return (x, x if self.round else y, z)

    def sample_size(self, rng: np.random.Generator) -> Vec3:
        """A random valid size (for tests and variation)."""
        x_low, x_high = self.size_min[0], self.size_max[0]
        y_low, y_high = self.size_min[1], self.size_max[1]
        z_low, z_high = self.size_min[2], self.size_max[2]
        # Keep x where some y and some z satisfy both the ratios and their ranges.
        for ratio, (low, high) in (
            (self.yx_ratio, (y_low, y_high)),
            (self.zx_ratio, (z_low, z_high)),
        ):
            if ratio is not None:
                x_low, x_high = max(x_low, low / ratio[1]), min(x_high, high / ratio[0])
        x = float(rng.uniform(x_low, x_high))
        if self.yx_ratio is not None:
            y_low, y_high = max(y_low, self.yx_ratio[0] * x), min(y_high, self.yx_ratio[1] * x)
        if self.zx_ratio is not None:
            z_low, z_high = max(z_low, self.zx_ratio[0] * x), min(z_high, self.zx_ratio[1] * x)
        y = x if self.round else float(rng.uniform(y_low, y_high))
        z = float(rng.uniform(z_low, z_high))
        return (x, y, z)

    def mass_for(self, size: Vec3) -> float:
        """Mass in kg at ``size``: the default mass scaled by the bounding-box volume."""
        ratio = math.prod(size) / math.prod(self.default_size)
        return float(f"{self.mass_kg * ratio:.4g}")

    def generate(self, size: Vec3 | None, rng: np.random.Generator) -> Design:
        """The design of one asset of this category at ``size`` (None: default size)."""
        return self.builder(self.check_size(size), rng)


CATEGORIES: dict[str, CategoryInfo] = {}


def category(
    name: str,
    kind: Kind,
    *,
    size: Vec3,
    low: Vec3,
    high: Vec3,
    mass: float,
    description: str,
    placement: tuple[str, ...] = ("floor",),
    friction: float = 0.8,
    yx_ratio: tuple[float, float] | None = None,
    zx_ratio: tuple[float, float] | None = None,
    variants: tuple[Vec3 | None, ...] | None = None,
) -> Callable[[Builder], Generator]:
    """Register the decorated builder as the generator of category ``name``.

    The builder receives a checked size; the decorated name becomes the category's public
    generator ``generate(size, rng)``, which also takes None (the default size) and raises
    :class:`~holomj.errors.InputError` for a size outside the category's range.
    """

    def register(builder: Builder) -> Generator:
        if name in CATEGORIES:
            raise ValueError(f"category {name!r} registered twice")
        chosen = (
            variants if variants is not None else ((None, None) if kind == "furniture" else (None,))
        )
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
            zx_ratio=zx_ratio,
            variants=chosen,
        )
        for variant in (size, *(v for v in chosen if v is not None)):
            info.check_size(variant)
        CATEGORIES[name] = info

        @functools.wraps(builder)
        def generate(size: Vec3 | None, rng: np.random.Generator) -> Design:
            return info.generate(size, rng)

        return generate

    return register


def category_info(name: str) -> CategoryInfo:
    """The registered category ``name`` (case and separators ignored), or an InputError."""
    if name in CATEGORIES:
        return CATEGORIES[name]
    key = _normalised(name)
    for known, info in CATEGORIES.items():
        if _normalised(known) == key:
            return info
    near = closest_names(name, CATEGORIES)
    hint = f"did you mean: {near}" if near else f"known: {', '.join(sorted(CATEGORIES))}"
    raise InputError(f"unknown procedural category {name!r}", fix=hint)


def rng_for(category_name: str, seed: int) -> np.random.Generator:
    """The style generator of (category, seed): independent streams per category."""
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or seed < 0:
        raise InputError(f"seed must be a non-negative integer, got {seed!r}")
    return np.random.default_rng([int(seed), zlib.crc32(category_name.encode())])


def design_for(
    category_name: str,
    asset_id: str,
    size: Vec3 | None = None,
    seed: int = 0,
    attributes: Attributes | None = None,
) -> tuple[AssetDesign, Vec3]:
    """The design of asset ``asset_id`` (not yet assembled) and its checked size.

    With ``attributes`` (:mod:`.attributes`) the design honours the colour, material, shape and
    style asked where it can; the honoured ones are recorded in the design and its description
    says so. Without them the design is exactly the category generator's.
    """
    info = category_info(category_name)
    resolved = info.check_size(size)
    honoured: dict[str, str] = {}
    if attributes:
        from asset_pipeline.procedural.attributes import conditioned_design, described

        design, resolved, honoured = conditioned_design(info, resolved, seed, attributes)
    else:
        design = info.builder(resolved, rng_for(info.name, seed))
    description = " ".join(info.description.format(**design.words).split())
    if attributes:
        description = described(description, info.name, attributes, honoured)
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
    return asset, resolved


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


def _normalised(name: str) -> str:
    return "".join(ch for ch in name.lower() if ch.isalnum())


def _fmt(size: Vec3) -> str:
    return "(" + ", ".join(f"{v:g}" for v in size) + ")"
