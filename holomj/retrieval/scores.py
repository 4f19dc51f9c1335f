"""The terms of a retrieval score and what they are computed from: the weights of
M = α·V + β·T − γ·S, one scored candidate, the text an asset is compared with (its category,
the category's other names, its description) and the size term S."""

from __future__ import annotations

import functools
import json
from collections.abc import Sequence
from dataclasses import dataclass
from importlib import resources
from typing import cast

import numpy as np

from holomj.errors import InputError
from holomj.library.store import LibraryAsset
from holomj.spec.assets import PLACEMENTS

SIZE_CAP_M = 1.5


@dataclass(frozen=True)
class RetrievalWeights:
    """α, β, γ of M = α·V + β·T − γ·S."""

    visual: float = 100.0
    text: float = 1.0
    size: float = 10.0


DEFAULT_WEIGHTS = RetrievalWeights()


@dataclass(frozen=True)
class ScoredAsset:
    """One candidate with its score and the terms it was made of (V None: left out)."""

    asset_id: str
    category: str
    score: float
    visual: float | None
    text: float
    size: float
    how: str = "ranked"
    attributes_asked: dict[str, str] | None = None
    attributes_honoured: dict[str, str] | None = None
    proxy: bool = False
    attributes_how: dict[str, str] | None = None
    """Per part asked (``handles``...): how it was honoured, or why not."""


def asset_text(asset: LibraryAsset) -> str:
    """What T compares a description with: ``"nightstand (bedside table, night table): a
    walnut nightstand ..."``: the category, its other names, the description."""
    words = " ".join(asset.meta.category.replace("_", " ").replace("-", " ").split())
    others = [n for n in category_synonyms().get(asset.meta.category, ()) if n != words]
    if others:
        words = f"{words} ({', '.join(others[:MAX_SYNONYMS])})"
    description = " ".join(asset.meta.description.split())
    return f"{words}: {description}" if description else words


MAX_SYNONYMS = 4


@functools.cache
def category_synonyms() -> dict[str, tuple[str, ...]]:
    """Other names of each category, from the knowledge base's object kinds (data only: the
    kinds' names and aliases in ``holomj/data/knowledge/objects.json``)."""
    data = json.loads(
        resources.files("holomj.data").joinpath("knowledge/objects.json").read_text("utf-8")
    )
    out: dict[str, list[str]] = {}
    for name, kind in data.get("objects", {}).items():
        names = out.setdefault(kind["category"], [])
        for word in [name, *kind.get("aliases", [])]:
            if word not in names:
                names.append(word)
    return {k: tuple(v) for k, v in out.items()}


def check_placement(placement: str, description: str) -> None:
    """Refuse a placement that is not one of :data:`holomj.spec.assets.PLACEMENTS`."""
    if placement not in PLACEMENTS:
        raise InputError(
            f"unknown placement {placement!r}",
            where=description,
            fix=f"use one of: {', '.join(PLACEMENTS)}",
        )


def size_discrepancy(
    requested: tuple[float, float, float], asset_size: tuple[float, float, float]
) -> float:
    """S in metres: ``requested`` is (width, depth, height), ``asset_size`` the asset's (x, y, z).

    The asset's width is its y extent and its depth its x extent (front faces +X); the
    footprint may also be turned by 90°. Each difference is capped at :data:`SIZE_CAP_M`.
    """
    width, depth, height = requested
    x, y, z = asset_size
    dz = min(abs(z - height), SIZE_CAP_M)

    def footprint(w: float, d: float) -> float:
        return min(abs(w - width), SIZE_CAP_M) + min(abs(d - depth), SIZE_CAP_M)

    return (min(footprint(y, x), footprint(x, y)) + dz) / 3.0


def check_size(size: Sequence[float], description: str) -> tuple[float, float, float]:
    """A requested size as three positive floats (width, depth, height); else refused."""
    values = tuple(float(v) for v in size)
    if len(values) != 3 or not all(np.isfinite(v) and v > 0 for v in values):
        raise InputError(
            f"size must be three positive numbers (width, depth, height), got {list(size)}",
            where=description,
        )
    return cast(tuple[float, float, float], values)
