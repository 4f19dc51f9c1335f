"""Foreign material names -> holomj materials.

Order of resolution for a ProcTHOR/Holodeck material:

1. a ``color`` given with the material: a scene material of that colour;
2. the name in the table ``holomj/data/procthor_materials.json`` (mapped by meaning);
3. keyword rules on the name (wood, tile, marble, carpet, paint colours...);
4. a deterministic colour from a hash of the name, registered as a scene material, with a
   warning.
"""

from __future__ import annotations

import hashlib
import json
from functools import cache
from importlib import resources

from holomj.importers.ids import sanitise
from holomj.spec.materials import BUILTIN_MATERIALS, Material

# (keywords, material): the first rule with a keyword found in the lower-cased name wins.
_KEYWORD_RULES: tuple[tuple[tuple[str, ...], str], ...] = (
    (("carpet", "rug", "fabric"), "carpet_grey"),
    (("marble",), "marble"),
    (("tile", "ceramic"), "grey_tile"),
    (("concrete", "cement"), "concrete"),
    (("brick",), "brick"),
    (("stone", "granite", "slate", "rock"), "stone"),
    (("metal", "steel", "chrome", "alumin", "iron"), "metal"),
    (("wallpaper",), "wallpaper_cream"),
    (("walnut", "mahogany", "rosewood", "cherry"), "walnut_floor"),
    (("darkwood", "dark_wood", "dark wood", "ebony"), "dark_wood_floor"),
    (("pine", "birch", "maple", "lightwood", "light wood", "whitewood"), "pine_floor"),
    (("wood", "oak", "parquet", "plank", "laminate", "floorboard"), "oak_floor"),
    (("yellow", "mustard"), "yellow_paint"),
    (("blue", "navy", "teal"), "blue_paint"),
    (("green", "olive", "mint", "sage"), "green_paint"),
    (("pink", "red", "rose", "salmon", "peach"), "pink_paint"),
    (("grey", "gray", "silver"), "grey_paint"),
    (("beige", "cream", "ivory", "tan", "eggshell", "sand"), "beige_paint"),
    (("white", "drywall", "plaster", "paint", "wall"), "white_paint"),
)


@cache
def procthor_table() -> dict[str, str]:
    """The name table shipped in ``holomj/data/procthor_materials.json``."""
    text = resources.files("holomj.data").joinpath("procthor_materials.json").read_text("utf-8")
    table = json.loads(text)
    return {k: v for k, v in table.items() if not k.startswith("_") and v in BUILTIN_MATERIALS}


def keyword_material(name: str) -> str | None:
    """The built-in material suggested by keywords in ``name``, if any."""
    lowered = name.lower()
    for keywords, material in _KEYWORD_RULES:
        if any(word in lowered for word in keywords):
            if material == "grey_tile" and "white" in lowered:
                return "white_tile"
            if material == "carpet_grey" and any(w in lowered for w in ("beige", "cream", "tan")):
                return "carpet_beige"
            return material
    return None


def hash_rgba(name: str) -> tuple[float, float, float, float]:
    """A muted, deterministic colour for a name."""
    digest = hashlib.sha256(name.encode("utf-8")).digest()
    return (
        round(0.35 + 0.55 * digest[0] / 255, 3),
        round(0.35 + 0.55 * digest[1] / 255, 3),
        round(0.35 + 0.55 * digest[2] / 255, 3),
        1.0,
    )


class MaterialResolver:
    """Resolves foreign material names and collects the scene materials it had to define."""

    def __init__(self) -> None:
        self.scene_materials: dict[str, Material] = {}
        self.warnings: list[str] = []
        self._cache: dict[tuple[str, tuple[float, ...] | None], str] = {}

    def resolve(
        self, name: str | None, rgb: tuple[float, ...] | None, default: str, where: str
    ) -> str:
        """The holomj material name for a foreign ``name`` and optional colour ``rgb``."""
        if not name and rgb is None:
            return default
        key = (name or "", rgb)
        if key in self._cache:
            return self._cache[key]
        result = self._resolve(name or "", rgb, where)
        self._cache[key] = result
        return result

    def _resolve(self, name: str, rgb: tuple[float, ...] | None, where: str) -> str:
        if rgb is not None:
            clamped = tuple(min(max(c, 0.0), 1.0) for c in rgb[:3])
            alpha = min(max(rgb[3], 0.0), 1.0) if len(rgb) > 3 else 1.0
            label = sanitise(name, "material") if name else "color"
            hexcode = "".join(f"{round(c * 255):02x}" for c in clamped)
            material_id = f"imported_{label}_{hexcode}"[:128]
            self.scene_materials[material_id] = Material(rgba=(*clamped, alpha))  # type: ignore[arg-type]
            return material_id
        if name in BUILTIN_MATERIALS:
            return name
        table = procthor_table()
        if name in table:
            return table[name]
        by_keyword = keyword_material(name)
        if by_keyword is not None:
            return by_keyword
        material_id = f"imported_{sanitise(name, 'material')}"[:128]
        self.scene_materials[material_id] = Material(rgba=hash_rgba(name))
        self.warnings.append(
            f"{where}: unknown material {name!r}; using a plain colour ({material_id})"
        )
        return material_id
