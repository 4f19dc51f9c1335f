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
from typing import Literal

import numpy as np

from asset_pipeline.procedural.parts import Part, Vec3
from holomj.errors import InputError, closest_names

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
"""The rigid categories, filled as the generator modules are imported (:mod:`.catalog` imports
them all, in catalogue order)."""


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
    chosen = (
        variants if variants is not None else ((None, None) if kind == "furniture" else (None,))
    )
    facts = CategoryFacts(
        name, kind, size, low, high, mass, description, placement, friction, yx_ratio, zx_ratio
    )
    return registrar(CATEGORIES, "category", facts, chosen)


@dataclass(frozen=True)
class CategoryFacts:
    """What a registration gives of a category besides its builder and variants."""

    name: str
    kind: Kind
    default_size: Vec3
    size_min: Vec3
    size_max: Vec3
    mass_kg: float
    description: str
    placement: tuple[str, ...]
    friction: float
    yx_ratio: tuple[float, float] | None
    zx_ratio: tuple[float, float] | None


def registrar(
    table: dict[str, CategoryInfo],
    what: str,
    facts: CategoryFacts,
    variants: tuple[Vec3 | None, ...],
) -> Callable[[Builder], Generator]:
    """The decorator registering a builder in ``table`` (``what`` names the table in errors)
    with ``facts``; every size it names is checked against the category's own range."""

    def register(builder: Builder) -> Generator:
        if facts.name in table:
            raise ValueError(f"{what} {facts.name!r} registered twice")
        info = CategoryInfo(builder=builder, variants=variants, **vars(facts))
        for variant in (info.default_size, *(v for v in variants if v is not None)):
            info.check_size(variant)
        table[facts.name] = info

        @functools.wraps(builder)
        def generate(size: Vec3 | None, rng: np.random.Generator) -> Design:
            return info.generate(size, rng)

        return generate

    return register


def lookup(table: dict[str, CategoryInfo], name: str, unknown: str) -> CategoryInfo:
    """The category ``name`` of ``table`` (case and separators ignored), or an InputError
    saying ``unknown`` and the nearest known names."""
    if name in table:
        return table[name]
    key = _normalised(name)
    for known, info in table.items():
        if _normalised(known) == key:
            return info
    near = closest_names(name, table)
    hint = f"did you mean: {near}" if near else f"known: {', '.join(sorted(table))}"
    raise InputError(unknown, fix=hint)


def category_info(name: str) -> CategoryInfo:
    """The registered category ``name`` (case and separators ignored), or an InputError."""
    return lookup(CATEGORIES, name, f"unknown procedural category {name!r}")


def rng_for(category_name: str, seed: int) -> np.random.Generator:
    """The style generator of (category, seed): independent streams per category."""
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or seed < 0:
        raise InputError(f"seed must be a non-negative integer, got {seed!r}")
    return np.random.default_rng([int(seed), zlib.crc32(category_name.encode())])


def _normalised(name: str) -> str:
    return "".join(ch for ch in name.lower() if ch.isalnum())


def _fmt(size: Vec3) -> str:
    return "(" + ", ".join(f"{v:g}" for v in size) + ")"
