"""Physical defaults per category (``data/categories.json``) and the asset's mass.

The table holds, per category, an *effective* density of the collision volume (hollow things
get low densities, because convex hulls fill them), sliding friction, placement flags, an
``upright`` flag and a plausible mass range. Unknown categories get the table's ``default``
entry, with placement ``["object"]`` for assets under :data:`SMALL_OBJECT_M` and ``["floor"]``
otherwise.

Mass is the given mass, else density x collision volume; it is never clamped, but a mass
outside the category's plausible range is reported as a warning.
"""

from __future__ import annotations

import functools
import json
import re
from dataclasses import dataclass
from importlib import resources
from pathlib import Path

SMALL_OBJECT_M = 0.6
DEFAULT_CATEGORY = "object"


@dataclass(frozen=True)
class CategoryInfo:
    name: str
    known: bool
    density_kg_m3: float
    friction: float
    placement: tuple[str, ...]
    upright: bool
    mass_range_kg: tuple[float, float]


@functools.cache
def _table() -> dict:
    text = resources.files("asset_pipeline").joinpath("data/categories.json").read_text("utf-8")
    return json.loads(text)


def categories() -> list[str]:
    """All category names of the table, sorted."""
    return sorted(_table()["categories"])


def category_info(name: str, size: tuple[float, float, float] | None = None) -> CategoryInfo:
    """The table's entry for ``name`` (case and separators ignored), else the default."""
    key = _key(name)
    for category, row in _table()["categories"].items():
        if _key(category) == key:
            return CategoryInfo(
                name=category,
                known=True,
                density_kg_m3=row["density_kg_m3"],
                friction=row["friction"],
                placement=tuple(row["placement"]),
                upright=row["upright"],
                mass_range_kg=tuple(row["mass_range_kg"]),  # type: ignore[arg-type]
            )
    row = _table()["default"]
    small = size is None or max(size) < SMALL_OBJECT_M
    return CategoryInfo(
        name=name,
        known=False,
        density_kg_m3=row["density_kg_m3"],
        friction=row["friction"],
        placement=("object",) if small else ("floor",),
        upright=row["upright"],
        mass_range_kg=tuple(row["mass_range_kg"]),  # type: ignore[arg-type]
    )


def guess_category(path: Path) -> str | None:
    """A category named in the file name, else in its folder's name (longest match wins).

    Names and aliases match as whole ``_``-separated words, so ``coffee_table.glb`` is a
    coffee_table, ``bedside_table_01.glb`` a nightstand and ``ycb_005_tomato_soup_can/
    textured.obj`` a can. A trailing plural ``s`` is ignored.
    """
    for text in (path.stem, path.parent.name):
        best = _best_match(_words(text))
        if best is not None:
            return best
    return None


def resolve_mass(
    given: float | None, density: float, volume: float, info: CategoryInfo
) -> tuple[float, str, list[str]]:
    """(mass, how it was found, warnings)."""
    if given is not None:
        mass, source = float(given), "given"
    else:
        mass, source = density * volume, "density x collision volume"
    warnings = []
    lo, hi = info.mass_range_kg
    if not lo <= mass <= hi:
        warnings.append(
            f"mass {mass:.4g} kg ({source}) is outside the plausible range {lo:g}-{hi:g} kg "
            f"of category {info.name!r}: check the size/units or give mass_kg"
        )
    return mass, source, warnings


def _key(name: str) -> str:
    return "".join(ch for ch in name.lower() if ch.isalnum())


def _words(text: str) -> list[str]:
    words = [w for w in re.split(r"[^a-z]+", text.lower()) if w]
    return [w[:-1] if len(w) > 3 and w.endswith("s") and not w.endswith("ss") else w for w in words]


@functools.cache
def _names() -> list[tuple[tuple[str, ...], str]]:
    """(words of a name or alias, category), longest first."""
    out = []
    for category, row in _table()["categories"].items():
        for name in [category, *row.get("aliases", [])]:
            out.append((tuple(_words(name)), category))
    return sorted(out, key=lambda item: (-len(item[0]), item[0], item[1]))


def _best_match(words: list[str]) -> str | None:
    for name, category in _names():
        n = len(name)
        if n and any(tuple(words[i : i + n]) == name for i in range(len(words) - n + 1)):
            return category
    return None
