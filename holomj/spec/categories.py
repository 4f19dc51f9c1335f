"""Category names, written one way: how a category's name is compared, its other names and its
typical size.

- :func:`normalise_category` is the one name normalisation of categories (and of the other
  tables keyed by name, materials included): the library, retrieval, the importers, the
  procedural registries and the physical table all compare names through it.
- ``holomj/data/category_facts.json`` holds, per name the library may not hold (ProcTHOR
  object types, plurals, near-synonyms), the categories that may stand in for it
  (:func:`category_aliases`, best first) and its typical size (:func:`category_sizes`, in the
  asset axes: x = depth, y = width, z = height).

Sizes, one convention: every size holomj stores (an asset's, a generator's, these tables',
the planner's ``holomj/data/knowledge/objects.json`` as ``[depth, width, height]`` arrays) is
in the asset axes, x = depth (front to back, the front faces +x), y = width, z = height,
metres; ``category_facts.json`` names its axes (``width``/``depth``/``height`` keys). Only a
plan (``holomj.spec.plan``, the edit language and the planner's in-memory object kinds) speaks
(width, depth, height). :func:`asset_axes` and :func:`plan_axes` are the only conversions
between the two: the planner's knowledge loader turns ``objects.json`` into plan sizes with
:func:`plan_axes`, retrieval turns a plan size into the asset axes with :func:`asset_axes`.
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
