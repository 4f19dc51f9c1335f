"""The words attributes are asked in: colours, materials (with their finish), shapes, styles,
the style biases, and the part nouns with the roles they ask (:mod:`.attributes` reads them,
:mod:`.finishes` and :mod:`.conditioning` apply them)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from asset_pipeline.procedural.roles import ROLES

# --- word lists ------------------------------------------------------------------------------
# Named colours (linear-ish sRGB in [0, 1]); "light X"/"pale X" and "dark X"/"deep X" blend
# them towards white or black.
COLOURS: dict[str, tuple[float, float, float]] = {
    "white": (0.93, 0.93, 0.91),
    "off-white": (0.90, 0.88, 0.83),
    "black": (0.06, 0.06, 0.07),
    "grey": (0.50, 0.50, 0.52),
    "charcoal": (0.21, 0.22, 0.24),
    "silver": (0.75, 0.76, 0.78),
    "red": (0.72, 0.12, 0.12),
    "crimson": (0.66, 0.08, 0.18),
    "burgundy": (0.45, 0.09, 0.15),
    "maroon": (0.42, 0.10, 0.10),
    "pink": (0.93, 0.55, 0.68),
    "hot pink": (0.95, 0.30, 0.60),
    "magenta": (0.80, 0.15, 0.60),
    "purple": (0.45, 0.22, 0.58),
    "violet": (0.55, 0.35, 0.75),
    "lavender": (0.72, 0.65, 0.86),
    "lilac": (0.78, 0.64, 0.80),
    "blue": (0.18, 0.32, 0.70),
    "navy": (0.10, 0.15, 0.35),
    "royal blue": (0.16, 0.28, 0.75),
    "sky blue": (0.52, 0.74, 0.90),
    "baby blue": (0.62, 0.78, 0.92),
    "teal": (0.08, 0.48, 0.48),
    "turquoise": (0.20, 0.72, 0.70),
    "cyan": (0.15, 0.75, 0.85),
    "green": (0.20, 0.52, 0.25),
    "forest green": (0.12, 0.33, 0.16),
    "olive": (0.45, 0.45, 0.18),
    "sage": (0.58, 0.66, 0.55),
    "mint": (0.65, 0.88, 0.75),
    "emerald": (0.06, 0.52, 0.34),
    "lime": (0.55, 0.80, 0.20),
    "yellow": (0.95, 0.82, 0.20),
    "mustard": (0.80, 0.62, 0.16),
    "gold": (0.83, 0.66, 0.22),
    "orange": (0.93, 0.50, 0.12),
    "coral": (0.95, 0.50, 0.42),
    "peach": (0.96, 0.72, 0.58),
    "salmon": (0.94, 0.55, 0.48),
    "terracotta": (0.72, 0.38, 0.24),
    "rust": (0.62, 0.30, 0.16),
    "brown": (0.42, 0.27, 0.16),
    "chocolate": (0.30, 0.18, 0.10),
    "tan": (0.78, 0.64, 0.46),
    "beige": (0.84, 0.77, 0.64),
    "khaki": (0.74, 0.69, 0.50),
    "cream": (0.95, 0.92, 0.82),
    "ivory": (0.96, 0.94, 0.87),
}
COLOUR_SYNONYMS = {
    "gray": "grey",
    "offwhite": "off-white",
    "off white": "off-white",
    "navy blue": "navy",
    "golden": "gold",
    "scarlet": "red",
    "rose": "pink",
    "aqua": "turquoise",
}
LIGHTER = ("light", "pale")
DARKER = ("dark", "deep")


@dataclass(frozen=True)
class Finish:
    """A material's look: its colour and highlight, the family it belongs to, its words."""

    rgba: tuple[float, float, float, float]
    specular: float
    shininess: float
    family: str  # wood, painted, metal, leather, fabric, stone, glass, plastic, ceramic, wicker
    label: str


MATERIALS: dict[str, Finish] = {
    "wood": Finish((0.62, 0.45, 0.28, 1.0), 0.2, 0.3, "wood", "wooden"),
    "oak": Finish((0.66, 0.49, 0.31, 1.0), 0.2, 0.3, "wood", "oak"),
    "walnut": Finish((0.40, 0.27, 0.17, 1.0), 0.2, 0.3, "wood", "walnut"),
    "pine": Finish((0.82, 0.68, 0.48, 1.0), 0.15, 0.2, "wood", "pine"),
    "cherry": Finish((0.55, 0.27, 0.17, 1.0), 0.25, 0.35, "wood", "cherry wood"),
    "maple": Finish((0.85, 0.72, 0.52, 1.0), 0.2, 0.3, "wood", "maple"),
    "teak": Finish((0.58, 0.40, 0.22, 1.0), 0.2, 0.3, "wood", "teak"),
    "mahogany": Finish((0.43, 0.17, 0.11, 1.0), 0.3, 0.4, "wood", "mahogany"),
    "birch": Finish((0.88, 0.80, 0.65, 1.0), 0.15, 0.2, "wood", "birch"),
    "ash": Finish((0.86, 0.78, 0.64, 1.0), 0.15, 0.2, "wood", "ash"),
    "ebony": Finish((0.12, 0.09, 0.07, 1.0), 0.3, 0.4, "wood", "ebony"),
    "bamboo": Finish((0.84, 0.74, 0.50, 1.0), 0.2, 0.3, "wood", "bamboo"),
    "painted wood": Finish((0.92, 0.91, 0.88, 1.0), 0.35, 0.45, "painted", "painted wood"),
    "lacquer": Finish((0.92, 0.91, 0.88, 1.0), 0.5, 0.6, "painted", "lacquered"),
    "metal": Finish((0.55, 0.56, 0.58, 1.0), 0.7, 0.7, "metal", "metal"),
    "steel": Finish((0.72, 0.74, 0.76, 1.0), 0.8, 0.8, "metal", "steel"),
    "chrome": Finish((0.85, 0.86, 0.88, 1.0), 0.95, 0.95, "metal", "chrome"),
    "brass": Finish((0.78, 0.62, 0.30, 1.0), 0.8, 0.8, "metal", "brass"),
    "copper": Finish((0.72, 0.45, 0.28, 1.0), 0.8, 0.8, "metal", "copper"),
    "bronze": Finish((0.55, 0.40, 0.22, 1.0), 0.7, 0.7, "metal", "bronze"),
    "iron": Finish((0.20, 0.20, 0.21, 1.0), 0.5, 0.5, "metal", "iron"),
    "aluminium": Finish((0.78, 0.79, 0.80, 1.0), 0.6, 0.6, "metal", "aluminium"),
    "leather": Finish((0.36, 0.22, 0.14, 1.0), 0.35, 0.45, "leather", "leather"),
    "fabric": Finish((0.55, 0.55, 0.56, 1.0), 0.05, 0.1, "fabric", "fabric"),
    "velvet": Finish((0.45, 0.20, 0.30, 1.0), 0.15, 0.25, "fabric", "velvet"),
    "linen": Finish((0.88, 0.85, 0.78, 1.0), 0.05, 0.1, "fabric", "linen"),
    "cotton": Finish((0.92, 0.91, 0.88, 1.0), 0.05, 0.1, "fabric", "cotton"),
    "wool": Finish((0.80, 0.76, 0.68, 1.0), 0.02, 0.05, "fabric", "wool"),
    "marble": Finish((0.92, 0.91, 0.89, 1.0), 0.7, 0.8, "stone", "marble"),
    "granite": Finish((0.35, 0.34, 0.34, 1.0), 0.6, 0.7, "stone", "granite"),
    "stone": Finish((0.62, 0.60, 0.56, 1.0), 0.2, 0.2, "stone", "stone"),
    "concrete": Finish((0.62, 0.62, 0.60, 1.0), 0.1, 0.1, "stone", "concrete"),
    "glass": Finish((0.80, 0.88, 0.90, 0.55), 0.95, 0.95, "glass", "glass"),
    "plastic": Finish((0.90, 0.90, 0.90, 1.0), 0.3, 0.3, "plastic", "plastic"),
    "ceramic": Finish((0.95, 0.95, 0.93, 1.0), 0.6, 0.7, "ceramic", "ceramic"),
    "porcelain": Finish((0.97, 0.97, 0.96, 1.0), 0.7, 0.8, "ceramic", "porcelain"),
    "wicker": Finish((0.76, 0.60, 0.38, 1.0), 0.05, 0.1, "wicker", "wicker"),
    "rattan": Finish((0.80, 0.65, 0.42, 1.0), 0.05, 0.1, "wicker", "rattan"),
}
MATERIAL_SYNONYMS = {
    "wooden": "wood",
    "timber": "wood",
    "painted": "painted wood",
    "lacquered": "lacquer",
    "metallic": "metal",
    "stainless steel": "steel",
    "stainless": "steel",
    "steel": "steel",
    "cast iron": "iron",
    "wrought iron": "iron",
    "aluminum": "aluminium",
    "faux leather": "leather",
    "leathers": "leather",
    "upholstery": "fabric",
    "cloth": "fabric",
    "tweed": "wool",
    "cherry wood": "cherry",
    "cherrywood": "cherry",
    "glazed": "ceramic",
    "wicker": "wicker",
}
SHAPES = ("round", "oval", "square", "l-shaped")
SHAPE_SYNONYMS = {
    "circular": "round",
    "elliptical": "oval",
    "oblong": "oval",
    "l shaped": "l-shaped",
    "l-shape": "l-shaped",
}
STYLES = (
    "modern",
    "rustic",
    "industrial",
    "scandinavian",
    "victorian",
    "minimalist",
    "mid-century",
    "traditional",
    "vintage",
    "farmhouse",
    "bohemian",
    "art deco",
)
STYLE_SYNONYMS = {
    "contemporary": "modern",
    "nordic": "scandinavian",
    "minimal": "minimalist",
    "midcentury": "mid-century",
    "mid century": "mid-century",
    "classic": "traditional",
    "retro": "vintage",
    "boho": "bohemian",
    "deco": "art deco",
}
# What a style makes of the main material when no colour or material is asked:
# family of the material it replaces -> (material, colour or None).
STYLE_BIAS: dict[str, dict[str, tuple[str, str | None]]] = {
    "modern": {"wood": ("walnut", None), "fabric": ("fabric", "grey"), "metal": ("chrome", None)},
    "rustic": {"wood": ("pine", None), "fabric": ("linen", "beige"), "metal": ("iron", None)},
    "industrial": {
        "wood": ("walnut", None),
        "fabric": ("leather", "brown"),
        "metal": ("iron", None),
    },
    "scandinavian": {"wood": ("birch", None), "fabric": ("wool", "light grey")},
    "victorian": {
        "wood": ("mahogany", None),
        "fabric": ("velvet", "burgundy"),
        "metal": ("brass", None),
    },
    "minimalist": {"wood": ("painted wood", "white"), "fabric": ("fabric", "off-white")},
    "mid-century": {"wood": ("teak", None), "fabric": ("fabric", "mustard")},
    "traditional": {"wood": ("cherry", None), "fabric": ("fabric", "beige")},
    "vintage": {"wood": ("walnut", None), "fabric": ("velvet", "teal")},
    "farmhouse": {"wood": ("painted wood", "cream"), "fabric": ("linen", "cream")},
    "bohemian": {"wood": ("rattan", None), "fabric": ("fabric", "terracotta")},
    "art deco": {
        "wood": ("ebony", None),
        "fabric": ("velvet", "emerald"),
        "metal": ("brass", None),
    },
}
# Materials that are never an asset's main material (bedding, screens, mirror glass, plants).
SECONDARY = frozenset(
    {"linen", "screen", "mirror_glass", "soil", "foliage", "dark_foliage", "wick", "paper", "tape"}
)
# --- parts -----------------------------------------------------------------------------------
# Nouns (one or two words) naming a part of an asset -> the role asked. Adjectival forms
# ("metal-legged", "glass-topped") count inside a hyphenated word.
PART_NOUNS: dict[str, str] = {
    "top": "top", "tops": "top", "tabletop": "top", "table top": "top", "worktop": "top",
    "countertop": "top", "counter top": "top", "topped": "top",
    "leg": "legs", "legs": "legs", "legged": "legs", "feet": "legs",
    "base": "base", "pedestal": "base", "plinth": "base", "foot": "base",
    "stand": "stand", "pole": "pole", "stem": "pole", "column": "pole",
    "frame": "frame", "frames": "frame", "framed": "frame", "body": "body", "carcass": "body",
    "seat": "seat", "seats": "seat", "cushion": "cushions", "cushions": "cushions",
    "seat cushion": "cushions", "seat cushions": "cushions",
    "back": "back", "backrest": "back", "backs": "back",
    "arm": "arms", "arms": "arms", "armrest": "arms", "armrests": "arms",
    "headboard": "headboard", "bedding": "bedding", "sheets": "bedding", "mattress": "bedding",
    "duvet": "bedding", "pillows": "bedding",
    "door": "doors", "doors": "doors", "drawer": "drawers", "drawers": "drawers",
    "drawer fronts": "drawers", "fronts": "fronts", "cabinet doors": "doors",
    "handle": "handles", "handles": "handles", "handled": "handles", "pull": "handles",
    "pulls": "handles", "knob": "handles", "knobs": "handles", "hardware": "handles",
    "shade": "shade", "shades": "shade", "lampshade": "shade", "lamp shade": "shade",
    "shaded": "shade", "shelf": "shelves", "shelves": "shelves",
}  # fmt: skip
# A role asked -> (roles of the parts it applies to, roles used instead when none of those is
# in the design): a seat is the seat board and its cushion; a table without legs stands on its
# base; a stand is a lamp's base and pole.
PART_TARGETS: dict[str, tuple[tuple[str, ...], tuple[str, ...]]] = {
    "seat": (("seat", "cushions"), ()),
    "cushions": (("cushions",), ("seat",)),
    "legs": (("legs",), ("base",)),
    "base": (("base",), ("legs",)),
    "stand": (("base", "pole", "legs"), ()),
    "frame": (("frame",), ("legs", "base")),
    "fronts": (("doors", "drawers"), ()),
}
PART_ROLES = (*ROLES, "stand", "fronts")
"""Every role a request may name, in the order reports list them."""
PLURAL_ROLES = frozenset(
    {"legs", "cushions", "arms", "bedding", "doors", "drawers", "handles", "shelves", "fronts"}
)


def part_targets(role: str) -> tuple[tuple[str, ...], tuple[str, ...]]:
    """(roles a request for ``role`` applies to, roles used instead when none is there)."""
    return PART_TARGETS.get(role, ((role,), ()))


def colour_rgb(name: str) -> tuple[float, float, float] | None:
    """RGB of a colour name (with ``light``/``dark`` variants), or None if unknown."""
    name = COLOUR_SYNONYMS.get(name, name)
    if name in COLOURS:
        return COLOURS[name]
    head, _, rest = name.partition(" ")
    rest = COLOUR_SYNONYMS.get(rest, rest)
    if rest in COLOURS and head in LIGHTER + DARKER:
        rgb = np.asarray(COLOURS[rest])
        mixed = rgb + 0.4 * (1.0 - rgb) if head in LIGHTER else rgb * 0.55
        r, g, b = (round(float(v), 4) for v in mixed)
        return (r, g, b)
    return None
