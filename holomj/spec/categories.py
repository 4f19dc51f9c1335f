"""Category names, written one way: how a category's name is compared, its other names and its
typical size.

- :func:`normalise_category` is the one name normalisation of categories (and of the other
  tables keyed by name, materials included): the library, retrieval, the importers, the
  procedural registries and the physical table all compare names through it.
- ``holomj/data/category_facts.json`` holds, per name the library may not hold (ProcTHOR
  object types, plurals, near-synonyms), the categories that may stand in for it
  (:func:`category_aliases`, best first) and its typical size (:func:`category_sizes`, in the
  asset axes: x = depth, y = width, z = height).

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
FACTS_FILE = "category_facts.json"


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


@functools.cache
def _facts() -> dict[str, dict[str, Any]]:
    """``category_facts.json`` by normalised name, without its ``_comment``."""
    text = resources.files("holomj.data").joinpath(FACTS_FILE).read_text(encoding="utf-8")
    table: dict[str, Any] = json.loads(text)
    return {normalise_category(k): v for k, v in table.items() if not k.startswith("_")}


@functools.cache
def category_aliases() -> dict[str, list[str]]:
    """Normalised name -> categories that may stand in for it, best first."""
    return {k: list(v["stand_ins"]) for k, v in _facts().items() if "stand_ins" in v}


@functools.cache
def category_sizes() -> dict[str, Size]:
    """Typical sizes (x = depth, y = width, z = height, metres) by normalised name."""
    return {
        k: asset_axes((float(s["width"]), float(s["depth"]), float(s["height"])))
        for k, v in _facts().items()
        if (s := v.get("size")) is not None
    }


def category_size(category: str) -> Size | None:
    """The typical size of a category (asset axes), if the table knows it."""
    return category_sizes().get(normalise_category(category))
