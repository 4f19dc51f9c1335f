"""Choosing a library asset for a foreign object: the asset itself, a stand-in, or a box.

1. The requested asset id is in the library: use it.
2. Otherwise the library's asset of the object's category closest in size.
3. Otherwise ``builtin:box`` scaled to the object's size.

The object's size is what the source tells us (Holodeck footprints) or a typical size of its
category from ``holomj/data/category_sizes.json``; unknown categories get a 0.5 m cube.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from functools import cache
from importlib import resources

from holomj.importers.result import Substitution
from holomj.library.store import BUILTIN_BOX, AssetLibrary, normalise_category

FALLBACK_SIZE = (0.5, 0.5, 0.5)

Size = tuple[float, float, float]


@cache
def category_sizes() -> dict[str, Size]:
    """Typical sizes (x = depth, y = width, z = height, metres) by normalised category."""
    text = resources.files("holomj.data").joinpath("category_sizes.json").read_text("utf-8")
    table = json.loads(text)
    return {
        normalise_category(name): (float(v["depth"]), float(v["width"]), float(v["height"]))
        for name, v in table.items()
        if not name.startswith("_")
    }


def category_size(category: str) -> Size | None:
    """The typical size of a category, if the table knows it."""
    return category_sizes().get(normalise_category(category))


@dataclass(frozen=True)
class AssetChoice:
    """The asset used for an object, its scale, its height once scaled, and any substitution."""

    asset: str
    scale: float | tuple[float, float, float]
    height: float
    substitution: Substitution | None


def choose_asset(
    library: AssetLibrary,
    *,
    object_id: str,
    requested: str,
    category: str,
    size: Size | None,
) -> tuple[AssetChoice, str | None]:
    """Pick the asset for an object; also returns a warning when the size had to be guessed."""
    if requested and requested in library:
        return AssetChoice(requested, 1.0, library.get(requested).meta.size[2], None), None
    warning = None
    if size is None:
        size = category_size(category) if category else None
    if size is None:
        size = FALLBACK_SIZE
        warning = (
            f"object {object_id!r}: no size known for category {category!r}; assuming a 0.5 m cube"
        )
    stand_in = library.closest(category, size) if category else None
    if stand_in is not None:
        sub = Substitution(
            object_id=object_id,
            requested_asset=requested,
            category=category,
            used_asset=stand_in.meta.id,
            reason="not in library; same category, closest size",
        )
        return AssetChoice(stand_in.meta.id, 1.0, stand_in.meta.size[2], sub), warning
    sub = Substitution(
        object_id=object_id,
        requested_asset=requested,
        category=category,
        used_asset=BUILTIN_BOX,
        reason=f"no asset of category {category!r}; box of the object's size",
    )
    box_height = library.get(BUILTIN_BOX).meta.size[2] * size[2]
    return AssetChoice(BUILTIN_BOX, size, box_height, sub), warning
