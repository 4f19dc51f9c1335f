"""Attributes a plan asks of an asset (colour, material, shape, style, and the colour or
material of its parts), and how they are read from text.

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

The words come from :mod:`.attribute_words`; :mod:`.conditioning` builds designs honouring them.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from asset_pipeline.procedural.attribute_words import (
    COLOUR_SYNONYMS,
    COLOURS,
    DARKER,
    LIGHTER,
    MATERIAL_SYNONYMS,
    MATERIALS,
    PART_NOUNS,
    PART_ROLES,
    PART_TARGETS,
    SECONDARY,
    SHAPE_SYNONYMS,
    SHAPES,
    STYLE_BIAS,
    STYLE_SYNONYMS,
    STYLES,
    colour_rgb,
    part_targets,
)

__all__ = [
    "COLOURS",
    "MATERIALS",
    "PART_NOUNS",
    "PART_ROLES",
    "PART_TARGETS",
    "SECONDARY",
    "SHAPES",
    "STYLES",
    "STYLE_BIAS",
    "Attributes",
    "PartAttributes",
    "attributes_from_text",
    "colour_rgb",
    "part_targets",
]

# Words that end the head of a description: attributes after them describe something else.
_STOPS = frozenset(
    {"with", "on", "of", "in", "under", "beside", "near", "next", "for", "from", "and", "full",
     "holding", "containing", "that", "which", "by", "against", "above", "below", "behind"}
)  # fmt: skip
_WORD = re.compile(r"[a-z]+(?:-[a-z]+)*")
_BREAK = re.compile(r"[,.;:()!?]")  # punctuation that ends a part phrase
_SECTION_WORDS = frozenset({"and", "or", "plus"})  # may follow a part noun
_ARTICLES = frozenset({"a", "an", "the"})


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
