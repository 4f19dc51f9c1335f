"""Foreign material names -> holomj materials.

Order of resolution for a ProcTHOR/Holodeck material:

1. a ``color`` given with the material: a scene material of that colour;
2. the name in the table ``holomj/data/procthor_materials.json`` (mapped by meaning), looked up
   as written, then ignoring case, spaces and punctuation (``"BrownMarbleFake 1"`` is
   ``BrownMarbleFake1``), then also ignoring a trailing number (``"YellowDrywall 2"`` is
   ``YellowDrywall``). An entry is a built-in material name, or ``{"like": built-in, "rgba":
   [r, g, b, a]}`` for a colour of its own: a scene material ``procthor_<snake_case name>`` with
   the built-in's finish and that colour (its name's words still pick the procedural pattern);
3. keyword rules on the name (wood, tile, marble, carpet, paint colours...);
4. a deterministic colour from a hash of the name, registered as a scene material, with a
   warning.
"""

from __future__ import annotations

import hashlib
import json
import re
from functools import cache
from importlib import resources

from holomj.importers.frames import triple
from holomj.importers.ids import sanitise
from holomj.spec.categories import normalise_category
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


Entry = tuple[str, tuple[float, float, float, float] | None]  # (built-in, own colour)


@cache
def procthor_entries() -> dict[str, Entry]:
    """The name table shipped in ``holomj/data/procthor_materials.json``: name -> (built-in
    material, own colour or None). Entries naming no built-in material are left out."""
    text = resources.files("holomj.data").joinpath("procthor_materials.json").read_text("utf-8")
    entries: dict[str, Entry] = {}
    for name, value in json.loads(text).items():
        if name.startswith("_"):
            continue
        if isinstance(value, str):
            entries[name] = (value, None)
        elif isinstance(value, dict) and isinstance(value.get("rgba"), list):
            r, g, b, a = [*(float(c) for c in value["rgba"]), 1.0][:4]
            entries[name] = (value.get("like", ""), (r, g, b, a))
    return {k: v for k, v in entries.items() if v[0] in BUILTIN_MATERIALS}


def procthor_table() -> dict[str, str]:
    """Table names that map to a built-in material as it is."""
    return {k: v for k, (v, rgba) in procthor_entries().items() if rgba is None}


def _key(name: str, drop_number: bool = False) -> str:
    key = normalise_category(name)
    return key.rstrip("0123456789") or key if drop_number else key


@cache
def _entries_by_key(drop_number: bool) -> dict[str, str]:
    keyed: dict[str, str] = {}
    for name in sorted(procthor_entries()):
        keyed.setdefault(_key(name, drop_number), name)
    return keyed


def table_name(name: str) -> str | None:
    """The table entry a foreign material name refers to (see the module notes), or None."""
    if name in procthor_entries():
        return name
    for drop_number in (False, True):
        found = _entries_by_key(drop_number).get(_key(name, drop_number))
        if found is not None:
            return found
    return None


def snake_case(name: str) -> str:
    """``"RoseGraniteTiles"`` -> ``"rose_granite_tiles"``."""
    spaced = re.sub(r"(?<=[a-z0-9])(?=[A-Z])", "_", name)
    return "_".join(re.findall(r"[a-z0-9]+", spaced.lower())) or "material"


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
            clamped = triple(min(max(c, 0.0), 1.0) for c in rgb[:3])
            alpha = min(max(rgb[3], 0.0), 1.0) if len(rgb) > 3 else 1.0
            label = sanitise(name, "material") if name else "color"
            hexcode = "".join(f"{round(c * 255):02x}" for c in clamped)
            material_id = f"imported_{label}_{hexcode}"[:128]
            self.scene_materials[material_id] = Material(rgba=(*clamped, alpha))
            return material_id
        if name in BUILTIN_MATERIALS:
            return name
        entry_name = table_name(name)
        if entry_name is not None:
            base, rgba = procthor_entries()[entry_name]
            if rgba is None:
                return base
            material_id = f"procthor_{snake_case(entry_name)}"[:128]
            look = BUILTIN_MATERIALS[base].model_copy(update={"rgba": rgba})
            self.scene_materials[material_id] = look
            return material_id
        by_keyword = keyword_material(name)
        if by_keyword is not None:
            return by_keyword
        material_id = f"imported_{sanitise(name, 'material')}"[:128]
        self.scene_materials[material_id] = Material(rgba=hash_rgba(name))
        self.warnings.append(
            f"{where}: unknown material {name!r}; using a plain colour ({material_id})"
        )
        return material_id
