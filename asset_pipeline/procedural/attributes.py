"""Attributes a plan asks of an asset (colour, material, shape, style, and the colour or
material of its parts) and how a procedural design honours them.

:func:`attributes_from_text` reads them from an object description with this module's own word
lists (``"a pink velvet sofa"`` -> ``Attributes(colour="pink", material="velvet")``). The
object's own attributes come from the head of the description only, up to the first
``with``/``on``/``of``/... (``"a banquet table with a white cloth"`` asks no colour of the
table); **part attributes** come from part phrases anywhere in it: colours and materials right
before a part noun (:data:`PART_NOUNS`: handles, legs, top, seat, shade, frame, doors,
drawers, cushions...) that ends a phrase (``"white kitchen cabinets with brass handles"``,
``"a coffee table with a glass top and black metal legs"``, ``"a glass-topped table"``,
``"legs in black metal"``): ``PartAttributes("handles", material="brass")``, as a dict
``{"handles.material": "brass"}``.

:func:`conditioned_design` builds a category's design with them:

- **shape** (``round``/``oval``/``square``) for coffee, side and dining tables, (round,
  square) for stools, (round) for mirrors and (``l-shaped``) for desks. Round and square
  tables and stools are the category's own generator at a square footprint (the side is the
  smaller of the planned two), re-drawn until it yields that shape; oval tables, round mirrors
  and L-shaped desks have their own builders here (an elliptic top on a pedestal; a framed
  disc; a top along the back with a return wing reaching the front, on five legs).
- **parts**: generators tag their parts with roles (:mod:`.roles`); a part request recolours
  only the parts of that role (a seat also its cushion; a table without legs, its base:
  :data:`PART_TARGETS`), with one new material per material replaced, so the asset's visual
  meshes show it. The design is re-drawn (up to :data:`PART_DRAWS` times) until it has the
  part (a sofa on legs rather than a plinth); a part the design lacks is reported, not faked
  (:func:`condition` gives per part how it was honoured or why not).
- **colour / material** go to the design's MAIN material: the material with the largest visual
  surface area, bedding, screens, mirror glass, soil and foliage left out (so a bed's frame, a
  mirror's frame, a plant's pot), parts that a part request names left out too ("a wooden
  table with a glass top": the legs are the wood); every part of that material changes with
  it. A colour alone
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

from asset_pipeline.procedural.parts import (
    Box,
    Collider,
    Material,
    Mesh,
    Part,
    Surface,
    Vec3,
    add3,
)
from asset_pipeline.procedural.roles import ROLES, Tagged, role_of, tagged, with_material
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
# Words that end the head of a description: attributes after them describe something else.
_STOPS = frozenset(
    {"with", "on", "of", "in", "under", "beside", "near", "next", "for", "from", "and", "full",
     "holding", "containing", "that", "which", "by", "against", "above", "below", "behind"}
)  # fmt: skip
_WORD = re.compile(r"[a-z]+(?:-[a-z]+)*")
_BREAK = re.compile(r"[,.;:()!?]")  # punctuation that ends a part phrase

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
_PLURAL_ROLES = frozenset(
    {"legs", "cushions", "arms", "bedding", "doors", "drawers", "handles", "shelves", "fronts"}
)
_SECTION_WORDS = frozenset({"and", "or", "plus"})  # may follow a part noun
_ARTICLES = frozenset({"a", "an", "the"})


def part_targets(role: str) -> tuple[tuple[str, ...], tuple[str, ...]]:
    """(roles a request for ``role`` applies to, roles used instead when none is there)."""
    return PART_TARGETS.get(role, ((role,), ()))


@dataclass(frozen=True)
class PartAttributes:
    """The colour and/or material asked of one part of an asset (``"brass handles"``)."""

    role: str
    colour: str | None = None
    material: str | None = None

    def __post_init__(self) -> None:
        if self.role not in PART_ROLES:
            raise ValueError(f"unknown part {self.role!r} (known: {', '.join(PART_ROLES)})")
        if self.colour is None and self.material is None:
            raise ValueError(f"the {self.role} ask no colour or material")
        if self.colour is not None and colour_rgb(self.colour) is None:
            raise ValueError(f"unknown colour {self.colour!r}")
        if self.material is not None and self.material not in MATERIALS:
            raise ValueError(f"unknown material {self.material!r}")

    def finish(self) -> Attributes:
        """The colour and material as whole-object attributes (what :func:`finished` takes)."""
        return Attributes(colour=self.colour, material=self.material)

    def words(self) -> str:
        """``"black metal legs"``: how a description names the request."""
        material = MATERIALS[self.material].label if self.material else None
        return " ".join(w for w in (self.colour, material, self.role) if w)


@dataclass(frozen=True)
class Attributes:
    """What is asked of an asset; None where nothing is.

    ``parts`` are requests for parts of it (``"with brass handles"``), one per role, in the
    order of :data:`PART_ROLES`; as a dict they read ``{"handles.material": "brass"}``.
    """

    colour: str | None = None
    material: str | None = None
    shape: str | None = None
    style: str | None = None
    parts: tuple[PartAttributes, ...] = ()

    def __post_init__(self) -> None:
        if self.colour is not None and colour_rgb(self.colour) is None:
            raise ValueError(f"unknown colour {self.colour!r}")
        if self.material is not None and self.material not in MATERIALS:
            raise ValueError(f"unknown material {self.material!r}")
        if self.shape is not None and self.shape not in SHAPES:
            raise ValueError(f"unknown shape {self.shape!r}")
        if self.style is not None and self.style not in STYLES:
            raise ValueError(f"unknown style {self.style!r}")
        roles = [p.role for p in self.parts]
        if len(set(roles)) != len(roles):
            raise ValueError(f"a part is asked twice: {roles}")
        ordered = tuple(sorted(self.parts, key=lambda p: PART_ROLES.index(p.role)))
        object.__setattr__(self, "parts", ordered)

    @classmethod
    def from_dict(cls, data: dict[str, str] | None) -> Attributes:
        """The attributes of a ``to_dict`` result (unknown keys ignored)."""
        data = data or {}
        asked: dict[str, dict[str, str]] = {}
        for key, value in data.items():
            role, dot, kind = key.partition(".")
            if dot and role in PART_ROLES and kind in ("colour", "material"):
                asked.setdefault(role, {})[kind] = value
        parts = tuple(PartAttributes(role, **kinds) for role, kinds in asked.items())
        whole = {k: data[k] for k in ("colour", "material", "shape", "style") if k in data}
        return cls(**whole, parts=parts)

    def to_dict(self) -> dict[str, str]:
        """The asked attributes only, in a fixed order (the object's, then its parts')."""
        out = {}
        for key in ("colour", "material", "shape", "style"):
            value = getattr(self, key)
            if value is not None:
                out[key] = value
        for part in self.parts:
            for key in ("colour", "material"):
                value = getattr(part, key)
                if value is not None:
                    out[f"{part.role}.{key}"] = value
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


@dataclass(frozen=True)
class _Token:
    word: str
    compound: int  # index of the (hyphenated) word it came from
    boundary: bool  # punctuation follows it


def _tokens(text: str) -> list[_Token]:
    """The words of ``text``; a hyphenated word ending in a part noun is split
    (``glass-topped`` -> ``glass``, ``topped``), other hyphenated words stay whole."""
    out: list[_Token] = []
    lower = text.lower()
    matches = list(_WORD.finditer(lower))
    for k, match in enumerate(matches):
        end = matches[k + 1].start() if k + 1 < len(matches) else len(lower)
        boundary = bool(_BREAK.search(lower[match.end() : end]))
        pieces = match.group().split("-")
        if len(pieces) > 1 and pieces[-1] in PART_NOUNS and _classify(match.group()) is None:
            out += [_Token(p, k, False) for p in pieces[:-1]] + [_Token(pieces[-1], k, boundary)]
        else:
            out.append(_Token(match.group(), k, boundary))
    return out


def _attribute_at(words: list[str], end: int, backwards: bool) -> tuple[str, str, int] | None:
    """A colour or material phrase (one to three words) ending (``backwards``) or starting at
    ``end``: (kind, value, words taken), or None."""
    for size in (3, 2, 1):
        lo, hi = (end - size + 1, end + 1) if backwards else (end, end + size)
        if lo < 0 or hi > len(words):
            continue
        hit = _classify(" ".join(words[lo:hi]))
        if hit is not None and hit[0] in ("colour", "material"):
            return hit[0], hit[1], size
    return None


def _part_phrases(
    tokens: list[_Token], skip: set[str]
) -> tuple[dict[str, dict[str, str]], set[int]]:
    """The part requests in ``tokens`` (role -> {colour, material}) and the token indices they
    use. A part noun counts when colours or materials come right before it (``brass handles``,
    ``metal-legged``) or after ``in``/``of`` (``legs in black metal``), and when it ends a
    phrase: nothing, punctuation, a stop word (``with``, ``and``...) or a category word follows
    it (``a glass top coffee table``; ``a white base cabinet`` asks nothing of a base)."""
    words = [t.word for t in tokens]
    found: dict[str, dict[str, str]] = {}
    used: set[int] = set()
    j = 0
    while j < len(tokens):
        size = next(
            (n for n in (2, 1) if " ".join(words[j : j + n]) in PART_NOUNS and j + n <= len(words)),
            0,
        )
        if not size or any(w in skip for w in words[j : j + size]):
            j += 1
            continue
        end = j + size
        last = tokens[end - 1]
        after = words[end] if end < len(words) else None
        # "metal-legged": the part noun ends a hyphenated word, and only its words count
        compound = j > 0 and tokens[j - 1].compound == tokens[j].compound
        if not (
            compound
            or after is None
            or last.boundary
            or after in _STOPS
            or after in _SECTION_WORDS
            or after in skip
        ):
            j += 1
            continue
        asked: dict[str, str] = {}
        taken: list[int] = []
        k = j - 1
        while k >= 0 and not tokens[k].boundary:
            if compound and tokens[k].compound != tokens[j].compound:
                break
            hit = _attribute_at(words, k, backwards=True)
            if hit is None or any(w in skip for w in words[k - hit[2] + 1 : k + 1]):
                break
            asked.setdefault(hit[0], hit[1])
            taken += range(k - hit[2] + 1, k + 1)
            k -= hit[2]
        if not asked and after in ("in", "of") and not last.boundary:
            k = end + 1
            while k < len(words):
                hit = _attribute_at(words, k, backwards=False)
                if hit is None:
                    break
                asked.setdefault(hit[0], hit[1])
                taken += range(k, k + hit[2])
                k += hit[2]
            if asked:
                taken.append(end)
        if asked:
            role = PART_NOUNS[" ".join(words[j:end])]
            for kind, value in asked.items():
                found.setdefault(role, {}).setdefault(kind, value)
            used.update(taken)
            used.update(range(j, end))
        j = end
    return found, used


def attributes_from_text(text: str, category: str | None = None) -> Attributes:
    """The attributes named in ``text`` (see the module docstring): the object's from the head
    of the text, its parts' from part phrases anywhere (``"with brass handles"``).

    Words of ``category`` never count (an ``orange`` is not asked to be orange).
    """
    skip = set(_WORD.findall((category or "").lower().replace("_", " ").replace("-", " ")))
    tokens = _tokens(text)
    asked_parts, used = _part_phrases(tokens, skip)
    words: list[str] = []
    for index, token in enumerate(tokens):
        if token.word in _STOPS and words:
            break
        if index in used:
            words.append("")  # a part's word: keeps phrases from joining across it
            continue
        words.append(token.word)
    found: dict[str, str] = {}
    i = 0
    while i < len(words):
        taken = 1
        for size in (3, 2, 1):
            window = words[i : i + size]
            if len(window) < size or "" in window or any(w in skip for w in window):
                continue
            hit = _classify(" ".join(window))
            if hit is not None:
                kind, value = hit
                found.setdefault(kind, value)
                taken = size
                break
        i += taken
    parts = tuple(PartAttributes(role, **kinds) for role, kinds in asked_parts.items())
    return Attributes(**found, parts=parts)


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
    return tuple(with_material(p, material) if p.material.name == base.name else p for p in parts)


# --- shapes ----------------------------------------------------------------------------------
TABLES = ("coffee_table", "side_table", "dining_table")
TABLE_SHAPES = ("round", "oval", "square")
SHAPED = {
    "coffee_table": TABLE_SHAPES,
    "side_table": TABLE_SHAPES,
    "dining_table": TABLE_SHAPES,
    "stool": ("round", "square"),
    "mirror": ("round",),
    "desk": ("l-shaped",),
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
        *tagged(
            "base",
            [
                Cylinder((0.0, 0.0, 0.02), foot_r, 0.02, leg),
                Cylinder((0.0, 0.0, 0.5 * (h - t + 0.04)), 0.055, 0.5 * (h - t - 0.04), leg),
            ],
        ),
        *tagged(
            "top",
            [EllipticSlab((0.0, 0.0, h - 0.5 * t), 0.5 * d, 0.5 * w, 0.5 * t, top, surface=True)],
        ),
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
        Tagged(Cylinder((-0.5 * d + 0.5 * back, 0.0, r), r, 0.5 * back, frame, axis="x"), "frame"),
        Cylinder((0.5 * d - 0.5 * glass, 0.0, r), r - rim, 0.5 * glass, MIRROR, axis="x"),
    ]
    return parts, {"frame": frame.words}


def _l_desk(size: Vec3, rng: np.random.Generator) -> tuple[list[Part], dict[str, str]]:
    """An L-shaped corner desk: a top along the back (-X) and a return wing on its +Y end
    reaching the front, both support surfaces, on square legs at the L's five outer corners."""
    from asset_pipeline.procedural.kit import BLACK_METAL, CASE_FINISHES, chance, pick, uniform

    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    top = pick(rng, CASE_FINISHES)
    leg = top if chance(rng, 0.5) else BLACK_METAL
    t = uniform(rng, 0.025, 0.04)
    main = min(max(0.6 * d, 0.45), d - 0.25)  # depth of the top along the back
    wing = min(max(0.35 * w, 0.45), 0.6 * w)  # width of the return
    side = 0.05
    x_main = -hd + main
    y_wing = hw - wing
    parts: list[Part] = [
        *tagged("top", [Box((0.5 * (x_main - hd), 0.0, h - 0.5 * t), (0.5 * main, hw, 0.5 * t),
                            top, surface=True)]),
        *tagged("top", [Box((0.5 * (x_main + hd), 0.5 * (y_wing + hw), h - 0.5 * t),
                            (0.5 * (hd - x_main), 0.5 * wing, 0.5 * t), top, surface=True)]),
    ]  # fmt: skip
    corners = ((-hd, -hw), (x_main - side, -hw), (-hd, hw - side), (hd - side, hw - side),
               (hd - side, y_wing))  # fmt: skip
    half = (0.5 * side, 0.5 * side, 0.5 * (h - t))
    legs = [Box((x + half[0], y + half[1], half[2]), half, leg) for x, y in corners]
    parts += tagged("legs", legs)
    legs_words = "" if leg is top else f" on {leg.words} legs"
    words = {
        "top": top.words,
        "shape": "l-shaped",
        "style": f"with an l-shaped corner return{legs_words}",
    }
    return parts, words


def shaped_size(category: str, shape: str | None, size: Vec3) -> Vec3:
    """The size a shaped asset gets: square footprints for round and square tables (the smaller
    side), a round mirror as wide as tall (the smaller of the two), an L-shaped desk as deep as
    a desk may be (so that its return reaches forward)."""
    d, w, h = size
    if shape is None or shape not in SHAPED.get(category, ()):
        return size
    if category == "mirror":
        side = min(w, h)
        return (d, side, side)
    if shape == "l-shaped":
        from asset_pipeline.procedural.registry import category_info

        return (category_info(category).size_max[0], w, h)
    if shape in ("round", "square"):
        side = min(d, w)
        return (side, side, h)
    return size


@dataclass(frozen=True)
class Conditioned:
    """A design built to a request: the design, the size it fills, the attributes honoured
    (as :meth:`Attributes.to_dict` keys) and, per part asked, how it was honoured or why not."""

    design: Any
    size: Vec3
    honoured: dict[str, str]
    parts_report: dict[str, str]


PART_DRAWS = 16
"""Designs drawn at most to find one with every part asked (a sofa on legs, not on a plinth)."""


def condition(info: Any, size: Vec3, seed: int, attributes: Attributes) -> Conditioned:
    """The design of ``info`` (a CategoryInfo) at ``size`` honouring ``attributes``.

    A shape the category cannot take is left out of the honoured attributes. Part requests
    (``"brass handles"``) recolour the parts carrying that role (:mod:`.roles`) only: the
    design is re-drawn (up to :data:`PART_DRAWS` times) until it has such parts; without them
    the request goes to the roles standing in for them (:data:`PART_TARGETS`: a table's base
    for its legs), else it is reported as not honoured. The object's own colour or material
    goes to the main material of the parts no request names.
    """
    from asset_pipeline.procedural.registry import Design, rng_for

    honoured: dict[str, str] = {}
    shape = attributes.shape
    name = info.name
    size = shaped_size(name, shape, size)
    size = info.check_size(size)
    rng = rng_for(name, seed)
    shaped = shape is not None and shape in SHAPED.get(name, ())
    if shaped and name == "mirror":
        parts, words = _round_mirror(size, rng)
        design = Design(tuple(parts), words)
    elif shaped and shape == "oval":
        parts, words = _oval_table(size, rng)
        design = Design(tuple(parts), words)
    elif shaped and shape == "l-shaped":
        parts, words = _l_desk(size, rng)
        design = Design(tuple(parts), words)
    elif shaped or attributes.parts:
        design = _drawn(info, size, seed, rng, shape if shaped else None, attributes.parts)
    else:
        design = info.builder(size, rng)
    if shaped:
        honoured["shape"] = shape  # type: ignore[assignment]
    targets = {p.role: _targets(design.parts, p.role) for p in attributes.parts}
    named = {k for indices, _ in targets.values() for k in indices}
    rest = [p for k, p in enumerate(design.parts) if k not in named]
    base = main_material(rest or design.parts)
    wanted = styled(attributes, base)
    words = dict(design.words)
    parts = design.parts
    if wanted.colour is not None or wanted.material is not None:
        material = finished(base, wanted)
        parts = recoloured(parts, base, material)
        _reworded(words, base.words, material.words)
        for key in ("colour", "material"):
            if getattr(attributes, key) is not None:
                honoured[key] = getattr(attributes, key)
    if attributes.style is not None and (
        wanted is not attributes or attributes.colour or attributes.material
    ):
        honoured["style"] = attributes.style
    report: dict[str, str] = {}
    for request in attributes.parts:
        indices, stand_in = targets[request.role]
        if not indices:
            noun = request.role.replace("_", " ")
            report[request.role] = f"not honoured: this {name.replace('_', ' ')} has no {noun}"
            continue
        parts = _finished_parts(parts, indices, request, words)
        for key in ("colour", "material"):
            if getattr(request, key) is not None:
                honoured[f"{request.role}.{key}"] = getattr(request, key)
        look = " ".join(w for w in (request.colour, _label(request.material)) if w)
        roles = sorted({role_of(parts[k]) or "" for k in indices}, key=ROLES.index)
        where = " and ".join(roles)
        text = f"{look} on the {where} ({len(indices)} part{'s' if len(indices) > 1 else ''})"
        if stand_in:
            text += f": this {name.replace('_', ' ')} has no {request.role}"
        report[request.role] = text
    return Conditioned(
        Design(tuple(parts), words), size, dict(sorted(honoured.items(), key=_order)), report
    )


def conditioned_design(
    info: Any, size: Vec3, seed: int, attributes: Attributes
) -> tuple[Any, Vec3, dict[str, str]]:
    """The design of ``info`` (a CategoryInfo) at ``size`` honouring ``attributes``.

    Returns the design, the size it fills and the attributes honoured (see :func:`condition`).
    """
    made = condition(info, size, seed, attributes)
    return made.design, made.size, made.honoured


def parts_report(
    category: str,
    size: Vec3 | None,
    seed: int,
    attributes: Attributes,
    *,
    articulated: bool = False,
) -> dict[str, str]:
    """How each part request of ``attributes`` is honoured by the asset ``generate_asset``
    (``generate_articulated`` when ``articulated``) builds of ``category`` at ``size`` in style
    ``seed`` (the design only, nothing assembled): role -> ``"brass on the handles (8
    parts)"`` or ``"not honoured: ..."``."""
    if not attributes.parts:
        return {}
    if articulated:
        from asset_pipeline.procedural.articulated import articulated_info

        info = articulated_info(category)
    else:
        from asset_pipeline.procedural.registry import category_info

        info = category_info(category)
    return condition(info, info.check_size(size), seed, attributes).parts_report


def _drawn(
    info: Any,
    size: Vec3,
    seed: int,
    rng: np.random.Generator,
    shape: str | None,
    asked: tuple[PartAttributes, ...],
) -> Any:
    """The category's design, re-drawn until it has ``shape`` (up to 32 draws) and, within
    :data:`PART_DRAWS` draws, parts for every request of ``asked`` (else the first draw of the
    shape)."""
    first = None
    draws = 32 if shape is not None else PART_DRAWS
    for k in range(draws):
        attempt = (
            rng
            if k == 0
            else np.random.default_rng([int(seed), zlib.crc32(info.name.encode()), 1000 + k])
        )
        candidate = info.builder(size, attempt)
        if shape is not None and candidate.words.get("shape") != shape:
            continue
        if first is None:
            first = candidate
        if all(_targets(candidate.parts, p.role)[0] and not _targets(candidate.parts, p.role)[1]
               for p in asked):  # fmt: skip
            return candidate
        if k >= PART_DRAWS - 1 or not any(role_of(p) for p in candidate.parts):
            break  # an untagged generator: no draw will have the parts
    if first is None:  # pragma: no cover - 32 draws at 60 % each
        raise ValueError(f"no {shape} {info.name} in {draws} draws")
    return first


def _targets(parts: tuple[Part, ...], role: str) -> tuple[list[int], bool]:
    """Indices of the parts a request for ``role`` recolours, and whether they stand in for
    parts the design lacks (a table's base for its legs)."""
    primary, instead = part_targets(role)
    found = [k for k, p in enumerate(parts) if role_of(p) in primary]
    if found:
        return found, False
    return [k for k, p in enumerate(parts) if role_of(p) in instead], True


def _finished_parts(
    parts: tuple[Part, ...], indices: list[int], request: PartAttributes, words: dict[str, str]
) -> tuple[Part, ...]:
    """``parts`` with those at ``indices`` finished as ``request`` asks (one new material per
    material replaced), the design's words following."""
    made: dict[str, Material] = {}
    out = list(parts)
    for k in indices:
        base = parts[k].material
        if base.name not in made:
            new = finished(base, request.finish())
            slug = new.name.removeprefix(f"{base.name}__")
            made[base.name] = replace(new, name=f"{base.name}__{request.role}_{slug}")
            for key in _word_keys(request.role):
                if words.get(key):
                    words[key] = _renamed(words[key], base.words, made[base.name].words)
                    break
        out[k] = with_material(parts[k], made[base.name])
    return tuple(out)


def _word_keys(role: str) -> tuple[str, ...]:
    """The keys of a design's words that may name the material of ``role`` parts."""
    return {
        "handles": ("handle", "handles"),
        "seat": ("cushion",),
        "cushions": ("cushion",),
        "legs": ("legs", "leg"),
        "base": ("legs", "base"),
        "top": ("top",),
        "shade": ("shade",),
        "frame": ("frame",),
        "headboard": ("headboard",),
        "pole": ("metal",),
    }.get(role, (role,))


def _renamed(text: str, old: str, new: str) -> str:
    """``text`` naming ``new`` where it named ``old`` (or, when it did not, ``new`` put in
    front: ``"square legs"`` -> ``"black metal square legs"``, ``"a pedestal"`` -> ``"a black
    metal pedestal"``)."""
    if old and old in text:
        return text.replace(old, new)
    if new in text or text != text.strip() or text.startswith(("and ", "with ", "on ")):
        return text  # not a noun phrase (" and a grey seat cushion")
    head, _, rest = text.partition(" ")
    if head in ("a", "an") and rest:
        return f"{_article(new)} {new} {rest}"
    return f"{new} {text}"


def _reworded(words: dict[str, str], old: str, new: str) -> None:
    for key, value in words.items():
        if old and old in value:
            words[key] = value.replace(old, new)


def _label(material: str | None) -> str | None:
    return MATERIALS[material].label if material else None


def _order(item: tuple[str, str]) -> tuple[int, int, int]:
    role, dot, kind = item[0].partition(".")
    if not dot:
        return (0, ("colour", "material", "shape", "style").index(role), 0)
    return (1, PART_ROLES.index(role), ("colour", "material").index(kind))


def described(description: str, category: str, attributes: Attributes, honoured: dict) -> str:
    """``description`` saying what was honoured: the words asked, where the text lacks them
    (the object's in front, its parts' after it: ``"... with brass handles"``)."""
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
    for part in shown.parts:
        look = part.words().rsplit(" ", 1)[0]
        primary, instead = part_targets(part.role)
        roles = {part.role, *primary, *instead}
        nouns = "|".join(re.escape(n) for n, role in PART_NOUNS.items() if role in roles)
        if re.search(rf"\b{re.escape(look)}(?: [a-z-]+){{0,2}} (?:{nouns})\b", text):
            continue  # "white conical shade", "metal square legs", "black metal pedestal"
        phrase = part.words() if part.role in _PLURAL_ROLES else f"{_article(look)} {part.words()}"
        text += f" and {phrase}" if " with " in text else f" with {phrase}"
    return text


def _article(word: str) -> str:
    return "an" if word[:1].lower() in "aeiou" else "a"
