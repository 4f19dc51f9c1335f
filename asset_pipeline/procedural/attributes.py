"""Attributes a plan asks of an asset (colour, material, shape, style) and how a procedural
design honours them.

:func:`attributes_from_text` reads them from an object description with this module's own word
lists (``"a pink velvet sofa"`` -> ``Attributes(colour="pink", material="velvet")``); only the
head of the description counts, up to the first ``with``/``on``/``of``/... (``"a banquet table
with a white cloth"`` asks no colour of the table).

:func:`conditioned_design` builds a category's design with them:

- **shape** (``round``/``oval``/``square``) for coffee, side and dining tables and (round) for
  mirrors. Round and square tables are the category's own generator at a square footprint
  (the side is the smaller of the planned two), re-drawn until it yields that shape; oval tables
  and round mirrors have their own builders here (an elliptic top on a pedestal; a framed disc).
- **colour / material** go to the design's MAIN material: the material with the largest visual
  surface area, bedding, screens, mirror glass, soil and foliage left out (so a bed's frame, a
  mirror's frame, a plant's pot); every part of that material changes with it. A colour alone
  keeps the finish (specular, shininess) of the material it replaces; a material alone brings
  its own colour.
- **style** biases the main material when no colour or material is asked (rustic -> pine,
  victorian -> burgundy velvet upholstery, industrial -> black metal, ...), so a style still
  shows; it is recorded as honoured then.

Everything is deterministic: the same inputs give the same design.
"""

from __future__ import annotations

import math
import re
import zlib
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from asset_pipeline.procedural.parts import Collider, Material, Mesh, Part, Surface, Vec3, add3
from asset_pipeline.procedural.round_parts import INSCRIBED, Cylinder

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
SHAPES = ("round", "oval", "square")
SHAPE_SYNONYMS = {"circular": "round", "elliptical": "oval", "oblong": "oval"}
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
# Words that end the head of a description: attributes after them describe something else.
_STOPS = frozenset(
    {"with", "on", "of", "in", "under", "beside", "near", "next", "for", "from", "and", "full",
     "holding", "containing", "that", "which", "by", "against", "above", "below", "behind"}
)  # fmt: skip
_WORD = re.compile(r"[a-z]+(?:-[a-z]+)*")


@dataclass(frozen=True)
class Attributes:
    """What is asked of an asset; None where nothing is."""

    colour: str | None = None
    material: str | None = None
    shape: str | None = None
    style: str | None = None

    def __post_init__(self) -> None:
        if self.colour is not None and colour_rgb(self.colour) is None:
            raise ValueError(f"unknown colour {self.colour!r}")
        if self.material is not None and self.material not in MATERIALS:
            raise ValueError(f"unknown material {self.material!r}")
        if self.shape is not None and self.shape not in SHAPES:
            raise ValueError(f"unknown shape {self.shape!r}")
        if self.style is not None and self.style not in STYLES:
            raise ValueError(f"unknown style {self.style!r}")

    @classmethod
    def from_dict(cls, data: dict[str, str] | None) -> Attributes:
        """The attributes of a ``to_dict`` result (unknown keys ignored)."""
        data = data or {}
        return cls(**{k: data[k] for k in ("colour", "material", "shape", "style") if k in data})

    def to_dict(self) -> dict[str, str]:
        """The asked attributes only, in a fixed order."""
        out = {}
        for key in ("colour", "material", "shape", "style"):
            value = getattr(self, key)
            if value is not None:
                out[key] = value
        return out

    def __bool__(self) -> bool:
        return bool(self.to_dict())

    @property
    def hard(self) -> dict[str, str]:
        """Colour, material and shape: what a library asset must match to be taken."""
        return {k: v for k, v in self.to_dict().items() if k != "style"}

    def key(self) -> str:
        """A stable text of the attributes (for content hashes)."""
        return ";".join(f"{k}={v}" for k, v in self.to_dict().items())

    def words(self) -> str:
        """``"modern pink velvet"``: how a description names them (shape left out)."""
        material = MATERIALS[self.material].label if self.material else None
        return " ".join(w for w in (self.style, self.colour, material) if w)


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
        return tuple(round(float(v), 4) for v in mixed)  # type: ignore[return-value]
    return None


def attributes_from_text(text: str, category: str | None = None) -> Attributes:
    """The attributes named in the head of ``text`` (see the module docstring).

    Words of ``category`` never count (an ``orange`` is not asked to be orange).
    """
    skip = set(_WORD.findall((category or "").lower().replace("_", " ")))
    words = []
    for word in _WORD.findall(text.lower()):
        if word in _STOPS and words:
            break
        words.append(word)
    found: dict[str, str] = {}
    i = 0
    while i < len(words):
        taken = 1
        for size in (3, 2, 1):
            phrase = " ".join(words[i : i + size])
            if len(words[i : i + size]) < size or any(w in skip for w in words[i : i + size]):
                continue
            hit = _classify(phrase)
            if hit is not None:
                kind, value = hit
                found.setdefault(kind, value)
                taken = size
                break
        i += taken
    return Attributes(**found)


def _classify(phrase: str) -> tuple[str, str] | None:
    """(kind, canonical value) of a one- to three-word phrase, or None."""
    if phrase in MATERIAL_SYNONYMS:
        return "material", MATERIAL_SYNONYMS[phrase]
    if phrase in MATERIALS and phrase not in COLOURS:
        return "material", phrase
    head, _, rest = phrase.partition(" ")
    if rest and head in LIGHTER + DARKER and colour_rgb(f"{head} {rest}") is not None:
        canonical = COLOUR_SYNONYMS.get(rest, rest)
        return "colour", f"{'light' if head in LIGHTER else 'dark'} {canonical}"
    if phrase in COLOURS or phrase in COLOUR_SYNONYMS:
        return "colour", COLOUR_SYNONYMS.get(phrase, phrase)
    if phrase in SHAPES or phrase in SHAPE_SYNONYMS:
        return "shape", SHAPE_SYNONYMS.get(phrase, phrase)
    if phrase in STYLES or phrase in STYLE_SYNONYMS:
        return "style", STYLE_SYNONYMS.get(phrase, phrase)
    return None


# --- materials -------------------------------------------------------------------------------
def family_of(material: Material) -> str:
    """The family of an existing palette material, from its name."""
    name = material.name
    for word, family in (
        ("leather", "leather"),
        ("fabric", "fabric"),
        ("linen", "fabric"),
        ("lacquer", "painted"),
        ("laminate", "painted"),
        ("painted", "painted"),
        ("chair", "painted"),
        ("metal", "metal"),
        ("steel", "metal"),
        ("chrome", "metal"),
        ("brass", "metal"),
        ("gilt", "metal"),
        ("aluminium", "metal"),
        ("glass", "glass"),
        ("plastic", "plastic"),
        ("ceramic", "ceramic"),
        ("porcelain", "ceramic"),
        ("terracotta", "ceramic"),
        ("concrete", "stone"),
    ):
        if word in name:
            return family
    if name in ("oak", "walnut", "pine", "ash", "bark"):
        return "wood"
    return "other"


def styled(attributes: Attributes, base: Material) -> Attributes:
    """``attributes`` with the style's bias filled in when no colour or material is asked."""
    if attributes.style is None or attributes.colour or attributes.material:
        return attributes
    family = family_of(base)
    bias = STYLE_BIAS[attributes.style].get(
        "wood" if family == "painted" else ("fabric" if family == "leather" else family)
    )
    if bias is None:
        return attributes
    material, colour = bias
    return replace(attributes, material=material, colour=colour)


def finished(base: Material, attributes: Attributes) -> Material:
    """The material replacing ``base`` under ``attributes`` (colour and/or material)."""
    rgba, specular, shininess = base.rgba, base.specular, base.shininess
    label_parts = []
    if attributes.material is not None:
        finish = MATERIALS[attributes.material]
        rgba, specular, shininess = finish.rgba, finish.specular, finish.shininess
    if attributes.colour is not None:
        rgb = colour_rgb(attributes.colour)
        assert rgb is not None  # checked by Attributes
        rgba = (*rgb, rgba[3])
        label_parts.append(attributes.colour)
    if attributes.material is not None:
        label_parts.append(MATERIALS[attributes.material].label)
    elif "leather" in base.name:
        label_parts.append("leather")
    slug = re.sub(r"[^a-z0-9]+", "_", " ".join(label_parts)).strip("_")
    return Material(
        f"{base.name}__{slug}",
        tuple(round(float(v), 4) for v in rgba),  # type: ignore[arg-type]
        specular,
        shininess,
        " ".join(label_parts),
    )


def _mesh_area(mesh: Mesh) -> float:
    tri = mesh.vertices[mesh.faces]
    cross = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    return float(0.5 * np.linalg.norm(cross, axis=1).sum())


def main_material(parts: tuple[Part, ...] | list[Part]) -> Material:
    """The material of the largest visual surface area (secondary materials only if alone)."""
    area: dict[str, float] = {}
    by_name: dict[str, Material] = {}
    for part in parts:
        mesh = part.mesh()
        if mesh is None:
            continue
        by_name[part.material.name] = part.material
        area[part.material.name] = area.get(part.material.name, 0.0) + _mesh_area(mesh)
    names = [n for n in area if n not in SECONDARY] or list(area)
    best = max(sorted(names), key=lambda n: area[n])
    return by_name[best]


def recoloured(parts: tuple[Part, ...], base: Material, material: Material) -> tuple[Part, ...]:
    """``parts`` with every part of material ``base`` made of ``material``."""
    return tuple(
        replace(p, material=material) if p.material.name == base.name else p  # type: ignore[type-var]
        for p in parts
    )


# --- shapes ----------------------------------------------------------------------------------
TABLES = ("coffee_table", "side_table", "dining_table")
SHAPED = {
    "coffee_table": SHAPES,
    "side_table": SHAPES,
    "dining_table": SHAPES,
    "mirror": ("round",),
}


@dataclass(frozen=True)
class EllipticSlab:
    """A vertical prism over an ellipse (semi-axes ``a`` along X, ``b`` along Y).

    Its visual is a 24-gon with vertices on the ellipse (and on both axes, so the bounding box
    is exact); its colliders are five boxes inside the inscribed ellipse; its top may be a
    support surface (the inscribed ellipse eroded by the edge margin).
    """

    center: Vec3
    a: float
    b: float
    half_height: float
    material: Material
    surface: bool = False

    def mesh(self) -> Mesh | None:
        disc = Cylinder((0.0, 0.0, 0.0), self.a, self.half_height, self.material).mesh()
        assert disc is not None
        vertices = disc.vertices * np.array([1.0, self.b / self.a, 1.0])
        return Mesh(vertices, disc.faces).translated(self.center)

    def colliders(self) -> list[Collider]:
        a, b = self.a * INSCRIBED, self.b * INSCRIBED
        out = []
        edges = (0.0, 0.45, 0.75, 0.92)
        for lo, hi in zip(edges, edges[1:], strict=False):
            half_y = b * math.sqrt(1.0 - hi * hi)
            if lo == 0.0:
                out.append(Collider("box", (hi * a, half_y, self.half_height), self.center))
                continue
            for sign in (-1.0, 1.0):
                cx = sign * 0.5 * (lo + hi) * a
                size = (0.5 * (hi - lo) * a, half_y, self.half_height)
                out.append(Collider("box", size, add3(self.center, (cx, 0.0, 0.0))))
        return out

    def bounds(self) -> tuple[Vec3, Vec3] | None:
        cx, cy, cz = self.center
        h = self.half_height
        return (cx - self.a, cy - self.b, cz - h), (cx + self.a, cy + self.b, cz + h)

    def surfaces(self) -> list[Surface]:
        if not self.surface:
            return []
        from asset_pipeline.procedural.parts import EDGE_MARGIN
        from asset_pipeline.procedural.round_parts import SEGMENTS

        a = self.a * INSCRIBED - EDGE_MARGIN
        b = self.b * INSCRIBED - EDGE_MARGIN
        cx, cy, cz = self.center
        polygon = tuple(
            (
                cx + a * math.cos(2.0 * math.pi * k / SEGMENTS),
                cy + b * math.sin(2.0 * math.pi * k / SEGMENTS),
            )
            for k in range(SEGMENTS)
        )
        return [Surface(cz + self.half_height, polygon)]

    def translated(self, offset: Vec3) -> EllipticSlab:
        return replace(self, center=add3(self.center, offset))


def _oval_table(size: Vec3, rng: np.random.Generator) -> tuple[list[Part], dict[str, str]]:
    """An oval table: an elliptic top on a central pedestal with a round foot."""
    from asset_pipeline.procedural.kit import BLACK_METAL, CASE_FINISHES, chance, pick, uniform

    d, w, h = size
    top = pick(rng, CASE_FINISHES)
    leg = top if chance(rng, 0.6) else BLACK_METAL
    t = uniform(rng, 0.025, 0.045)
    foot_r = min(0.6 * min(d, w) / 2.0, 0.32)
    parts: list[Part] = [
        Cylinder((0.0, 0.0, 0.02), foot_r, 0.02, leg),
        Cylinder((0.0, 0.0, 0.5 * (h - t + 0.04)), 0.055, 0.5 * (h - t - 0.04), leg),
        EllipticSlab((0.0, 0.0, h - 0.5 * t), 0.5 * d, 0.5 * w, 0.5 * t, top, surface=True),
    ]
    legs = "a pedestal" if leg is top else f"a {leg.words} pedestal"
    return parts, {"top": top.words, "shape": "oval", "legs": legs, "shelf": ""}


def _round_mirror(size: Vec3, rng: np.random.Generator) -> tuple[list[Part], dict[str, str]]:
    """A round wall mirror: a framed disc facing +X (x = thickness, y = z = diameter)."""
    from asset_pipeline.procedural.appliances import MIRROR
    from asset_pipeline.procedural.kit import BLACK_METAL, BRASS, OAK, WALNUT, WHITE_LACQUER, pick

    d, diameter, _ = size
    r = 0.5 * diameter
    frame = pick(rng, (BLACK_METAL, BRASS, OAK, WALNUT, WHITE_LACQUER))
    back = 0.7 * d
    glass = d - back
    rim = min(0.06, 0.12 * r)
    parts: list[Part] = [
        Cylinder((-0.5 * d + 0.5 * back, 0.0, r), r, 0.5 * back, frame, axis="x"),
        Cylinder((0.5 * d - 0.5 * glass, 0.0, r), r - rim, 0.5 * glass, MIRROR, axis="x"),
    ]
    return parts, {"frame": frame.words}


def shaped_size(category: str, shape: str | None, size: Vec3) -> Vec3:
    """The size a shaped asset gets: square footprints for round and square tables (the smaller
    side), a round mirror as wide as tall (the smaller of the two)."""
    d, w, h = size
    if shape is None or shape not in SHAPED.get(category, ()):
        return size
    if category == "mirror":
        side = min(w, h)
        return (d, side, side)
    if shape in ("round", "square"):
        side = min(d, w)
        return (side, side, h)
    return size


def conditioned_design(
    info: Any, size: Vec3, seed: int, attributes: Attributes
) -> tuple[Any, Vec3, dict[str, str]]:
    """The design of ``info`` (a CategoryInfo) at ``size`` honouring ``attributes``.

    Returns the design, the size it fills and the attributes honoured (a shape the category
    cannot take is left out of them).
    """
    from asset_pipeline.procedural.registry import Design, rng_for

    honoured: dict[str, str] = {}
    shape = attributes.shape
    name = info.name
    size = shaped_size(name, shape, size)
    size = info.check_size(size)
    rng = rng_for(name, seed)
    if shape is not None and shape in SHAPED.get(name, ()):
        if name == "mirror":
            parts, words = _round_mirror(size, rng)
            design = Design(tuple(parts), words)
        elif shape == "oval":
            parts, words = _oval_table(size, rng)
            design = Design(tuple(parts), words)
        else:
            design = None
            for k in range(32):
                attempt = (
                    rng
                    if k == 0
                    else np.random.default_rng([int(seed), zlib.crc32(name.encode()), 1000 + k])
                )
                candidate = info.builder(size, attempt)
                if candidate.words.get("shape") == shape:
                    design = candidate
                    break
            if design is None:  # pragma: no cover - 32 draws at 60 % each
                raise ValueError(f"no {shape} {name} in 32 draws")
        honoured["shape"] = shape
    else:
        design = info.builder(size, rng)
    base = main_material(design.parts)
    wanted = styled(attributes, base)
    words = dict(design.words)
    if wanted.colour is not None or wanted.material is not None:
        material = finished(base, wanted)
        design = Design(recoloured(design.parts, base, material), words)
        for key, value in words.items():
            if base.words and base.words in value:
                words[key] = value.replace(base.words, material.words)
        for key in ("colour", "material"):
            if getattr(attributes, key) is not None:
                honoured[key] = getattr(attributes, key)
    if attributes.style is not None and (
        wanted is not attributes or attributes.colour or attributes.material
    ):
        honoured["style"] = attributes.style
    return Design(design.parts, words), size, dict(sorted(honoured.items(), key=_order))


def _order(item: tuple[str, str]) -> int:
    return ("colour", "material", "shape", "style").index(item[0])


def described(description: str, category: str, attributes: Attributes, honoured: dict) -> str:
    """``description`` saying what was honoured: the words asked, where the text lacks them."""
    text = " ".join(description.split())
    shown = Attributes.from_dict(honoured)
    wanted = [w for w in (shown.colour, MATERIALS[shown.material].label if shown.material else None)
              if w]  # fmt: skip
    missing = [w for w in wanted if w not in text]
    if shown.shape and shown.shape not in text:
        missing.append(shown.shape)
    if missing:
        head, _, rest = text.partition(" ")
        if head.lower() in ("a", "an") and rest:
            text = f"a {' '.join(missing)} {rest}"
        else:
            noun = category.replace("_", " ")
            text = f"a {' '.join(missing)} {noun}: {text}"
    if shown.style and shown.style not in text:
        words = text.split(" ", 1)
        if len(words) == 2 and words[0].lower() in ("a", "an"):
            text = f"{_article(shown.style)} {shown.style} {words[1]}"
        else:
            text = f"{shown.style} {text}"
    words = text.split(" ", 2)
    if len(words) >= 2 and words[0] in ("a", "an"):
        words[0] = _article(words[1])
        text = " ".join(words)
    return text


def _article(word: str) -> str:
    return "an" if word[:1].lower() in "aeiou" else "a"
