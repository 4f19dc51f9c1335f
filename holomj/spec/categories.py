"""Category names, written one way: how a category's name is compared, its other names and its
typical size.

- :func:`normalise_category` is the one name normalisation of categories (and of the other
  tables keyed by name, materials included): the library, retrieval, the importers, the
  procedural registries and the physical table all compare names through it.
- :func:`category_aliases` reads ``holomj/data/category_aliases.json`` (other names of a
  category, the categories that may stand in for it, best first).
- :func:`category_sizes` reads ``holomj/data/category_sizes.json`` (typical sizes of
  ProcTHOR/Holodeck object types), in the asset axes (x = depth, y = width, z = height).

Sizes: a plan (and the planner's knowledge base) gives an object's size as (width, depth,
height); an asset's, a generator's and these tables' are (x = depth, y = width, z = height).
:func:`asset_axes` and :func:`plan_axes` turn one into the other.
"""

from __future__ import annotations

import functools
import json
from importlib import resources
from typing import Any

Size = tuple[float, float, float]


def normalise_category(category: str) -> str:
    """``Dining Table``, ``dining-table`` and ``DiningTable`` all become ``diningtable``."""
    return "".join(ch for ch in category.lower() if ch.isalnum())


def asset_axes(plan_size: Size) -> Size:
    """A plan size (width, depth, height) in the asset axes (x = depth, y = width, z)."""
    width, depth, height = plan_size
    return (depth, width, height)


def plan_axes(asset_size: Size) -> Size:
    """An asset size (x = depth, y = width, z) as a plan size (width, depth, height)."""
    depth, width, height = asset_size
    return (width, depth, height)


def _table(name: str) -> dict[str, Any]:
    """A category table of ``holomj/data`` without its ``_comment`` entries."""
    text = resources.files("holomj.data").joinpath(name).read_text(encoding="utf-8")
    table: dict[str, Any] = json.loads(text)
    return {k: v for k, v in table.items() if not k.startswith("_")}


@functools.cache
def category_aliases() -> dict[str, list[str]]:
    """Normalised category name -> categories that may stand in for it, best first."""
    return {normalise_category(k): list(v) for k, v in _table("category_aliases.json").items()}


@functools.cache
def category_sizes() -> dict[str, Size]:
    """Typical sizes (x = depth, y = width, z = height, metres) by normalised category."""
    return {
        normalise_category(name): asset_axes(
            (float(v["width"]), float(v["depth"]), float(v["height"]))
        )
        for name, v in _table("category_sizes.json").items()
    }


def category_size(category: str) -> Size | None:
    """The typical size of a category (asset axes), if the table knows it."""
    return category_sizes().get(normalise_category(category))
