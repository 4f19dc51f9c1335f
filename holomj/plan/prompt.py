"""Request parsing for the offline planner: what a prompt asks for, in the knowledge base's words.

:func:`parse_prompt` reads a prompt such as ``"a cozy reading room with two armchairs and a
large bookshelf"`` and returns a :class:`ParsedPrompt`: the scene type named in the prompt's head
(``reading_room``), rooms and their counts (``two-bedroom``, ``3 bedrooms``, ``with a home
office``), sizes (``small``, ``8 by 5 meters``, ``8x5 m``, ``40 square meters``), style words,
materials per surface (``oak floor`` -> ``oak wood floor``), objects with quantities
(``two armchairs``, ``lots of plants``), objects to leave out (``without a tv``), things the
planner refuses (rugs) and phrases it did not understand. It never guesses a scene type that
the prompt does not name: that is the planner's job (:mod:`holomj.plan.offline`).

How it reads: the text is lower-cased and split into words; number words become digits
(``two`` -> 2, ``a dozen`` -> 12) and quantity words a ``MANY`` marker (``lots of``, ``loves``).
Sizes and material phrases are found first; then every phrase the knowledge base knows
(scene keywords, room aliases, object names and aliases with derived plurals, style words) is
matched, longest first, left to right. The words just before a match give its quantity, size
word and adjectives. The *head* of the prompt is what comes before the first ``with``,
``for``, ``and``, comma, ...: its last scene keyword names the scene type.
"""

from __future__ import annotations

import re
import unicodedata
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Literal

from pydantic import Field

from holomj.plan.knowledge import KnowledgeBase
from holomj.spec.base import FrozenModel

MANY = "MANY"  # marker token for "lots of", "many", "loves", ...
NEG = "NEG"  # marker token for "without", "no"
MAX_PHRASE_WORDS = 5
ADJECTIVE_RUN = 4  # words looked back from a match for its quantity and adjectives

Surface = Literal["floor", "wall", "ceiling"]

_NUMBERS = {
    "zero": 0, "none": 0, "one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6,
    "seven": 7, "eight": 8, "nine": 9, "ten": 10, "eleven": 11, "twelve": 12, "thirteen": 13,
    "fourteen": 14, "fifteen": 15, "sixteen": 16, "seventeen": 17, "eighteen": 18,
    "nineteen": 19, "twenty": 20, "thirty": 30, "forty": 40, "fifty": 50, "sixty": 60,
    "seventy": 70, "eighty": 80, "ninety": 90, "dozen": 12, "couple": 2, "pair": 2,
    "few": 3, "several": 3, "handful": 3,
}  # fmt: skip
_TENS = {"twenty", "thirty", "forty", "fifty", "sixty", "seventy", "eighty", "ninety"}
_SCALES = {"hundred": 100, "thousand": 1000}
# Multi-word quantity phrases, replaced before numbers are read (longest first).
_PHRASES: list[tuple[tuple[str, ...], tuple[str, ...]]] = [
    (("a", "lot", "of"), (MANY,)),
    (("lots", "of"), (MANY,)),
    (("lot", "of"), (MANY,)),
    (("plenty", "of"), (MANY,)),
    (("loads", "of"), (MANY,)),
    (("tons", "of"), (MANY,)),
    (("a", "bunch", "of"), (MANY,)),
    (("bunch", "of"), (MANY,)),
    (("dozens", "of"), (MANY,)),
    (("hundreds", "of"), (MANY,)),
    (("full", "of"), ("with", MANY)),
    (("filled", "with"), ("with", MANY)),
    (("packed", "with"), ("with", MANY)),
    (("obsessed", "with"), (MANY,)),
    (("a", "couple", "of"), ("2",)),
    (("couple", "of"), ("2",)),
    (("a", "pair", "of"), ("2",)),
    (("pair", "of"), ("2",)),
    (("a", "few"), ("3",)),
    (("a", "handful", "of"), ("3",)),
    (("handful", "of"), ("3",)),
    (("a", "dozen"), ("12",)),
    (("a", "hundred"), ("100",)),
    (("a", "thousand"), ("1000",)),
    (("as", "well", "as"), ("and",)),
    (("along", "with"), ("with",)),
    (("do", "not", "want"), (NEG,)),
    (("dont", "want"), (NEG,)),
    (("no", "need", "for"), (NEG,)),
    (("free", "of"), (NEG,)),
]
_MANY_WORDS = {"many", "numerous", "loves", "love", "loving", "adores", "adore", "countless"}
_NEG_WORDS = {"without", "no", "not", "never", "except"}

# Words that end the head of a prompt (what comes before them names the scene).
_HEAD_END = {
    "with", "for", "who", "that", "which", "where", "featuring", "including", "containing",
    "has", "having", "plus", "and", ",", ".", ";", ":", "!", "?", "(", ")", "in", "but",
    "whose", "near", "next", "like", "to", "on", NEG,
}  # fmt: skip
# Words that open a list of things wanted in the room.
_WITH_START = {"with", "featuring", "including", "containing", "has", "having", "plus", "add"}
# Words that close such a list (a new clause starts).
_WITH_END = {"for", "who", "that", "which", "where", "whose", ".", ";", "!", "?", "but", "so"}
_SEPARATORS = {",", "and", "or", "&", "plus", "with", "also", "then", "(", ")", ":"}
_DETERMINERS = {"a", "an", "the", "some", "one", "any", "each", "every", "another", "extra"}
_STOPWORDS = {
    "a", "an", "the", "some", "of", "to", "in", "on", "at", "by", "from", "into", "onto", "its",
    "it", "their", "my", "our", "your", "his", "her", "this", "these", "those", "very", "really",
    "quite", "nice", "beautiful", "lovely", "pretty", "great", "good", "new", "old", "also", "too",
    "please", "i", "we", "want", "need", "like", "would", "be", "is", "are", "there", "have",
    "room", "rooms", "space", "area", "place", "corner", "side", "each", "every", "one", "ones",
    "other", "another", "more", "extra", "enough", "lot", "lots", "all", "any", "both", "own", "s",
    "just", "only", "even", "well", "as", "so", "much", "little", "bit", "set", "sets", "kind",
    "kinds", "type", "types", "style", "styled", "themed", "looking", "plenty", "tons", "loads",
    "bunch", "couple", "pair", "number", "few", "several", "against", "along", "around", "under",
    "over", "above", "below", "between", "behind", "front", "middle", "center", "centre", "near",
    "next", "beside", "up", "down", "out", "off", "for", "who", "that", "which", "where", "whose",
    "but", "or", "and", "with", "without", "featuring", "including", "containing", "has", "having",
    "plus", "add", "put", "placed", "filled", "full", "big", "large", "small", "huge", "tiny",
    "medium", "here", "them", "they", "he", "she", "you", "me", "us", "can", "could", "should",
    "will", "make", "made", "give", "get", "include", "includes", "included", "decorated",
    "furnished",
}  # fmt: skip
_ROOM_WORDS = {"room", "rooms", "space", "area", "place", "scene", "interior"}
# Length units (metres per unit) and area units (square metres per unit).
_LENGTH = {
    "m": 1.0, "meter": 1.0, "meters": 1.0, "metre": 1.0, "metres": 1.0, "mtr": 1.0,
    "cm": 0.01, "centimeter": 0.01, "centimeters": 0.01, "centimetre": 0.01,
    "centimetres": 0.01, "ft": 0.3048, "feet": 0.3048, "foot": 0.3048, "yard": 0.9144,
    "yards": 0.9144,
}  # fmt: skip
_AREA_WORDS = {"sqm": 1.0, "sqft": 0.09290304}
_BY = {"x", "by", "times", "*"}
_CEILING = {"ceiling", "ceilings"}
_HEIGHT_WORDS = {"tall", "high", "height"}
_PEOPLE = {
    "people", "persons", "person", "guests", "guest", "students", "student", "kids", "children",
    "pupils", "diners", "employees", "workers", "seats", "users", "players", "musicians",
    "patients", "visitors", "colleagues", "staff", "learners", "toddlers", "adults", "friends",
    "participants", "attendees", "customers", "family", "members",
}  # fmt: skip


class ObjectRequest(FrozenModel):
    """An object the prompt asks for (or, with ``excluded``, does not want)."""

    kind: str = Field(description="An object kind, or a generic word's name when generic.")
    generic: bool = False
    quantity: int | None = Field(default=None, description="A number given in the prompt.")
    many: bool = Field(default=False, description="'lots of', 'many', 'loves'.")
    plural: bool = False
    size: Literal["small", "large"] | None = None
    adjectives: list[str] = Field(default_factory=list)
    room: str | None = Field(default=None, description="Template of the room it was asked in.")
    excluded: bool = False
    phrase: str


class RoomMention(FrozenModel):
    """A room named in the prompt (besides the scene itself): template, count, size."""

    template: str
    count: int | None = None
    size_word: str | None = None
    dims: tuple[float, float] | None = None
    area_m2: float | None = None
    excluded: bool = False
    phrase: str


class RefusedRequest(FrozenModel):
    """Something the planner never plans, as asked."""

    name: str
    phrase: str
    reason: str


class ParsedPrompt(FrozenModel):
    """What a prompt asks for, in the knowledge base's terms."""

    text: str
    head: str = Field(description="Content words of the head, for matching unknown scenes.")
    scene: str | None = None
    scene_keyword: str | None = None
    refinements: list[tuple[str, str]] = Field(
        default_factory=list, description="(scene type, word) of refine words found."
    )
    size_word: str | None = None
    dims: tuple[float, float] | None = None
    area_m2: float | None = None
    wall_height_m: float | None = None
    rooms: list[RoomMention] = Field(default_factory=list)
    styles: list[str] = Field(default_factory=list)
    materials: dict[str, str] = Field(default_factory=dict)
    objects: list[ObjectRequest] = Field(default_factory=list)
    refused: list[RefusedRequest] = Field(default_factory=list)
    unknown: list[str] = Field(default_factory=list)
    capacity: int | None = None
    windows: int | None = None
    notes: list[str] = Field(default_factory=list)


# ---------------------------------------------------------------------------------------------
# Words


def tokenize(text: str) -> list[str]:
    """Lower-case words, digits (``2.5``) and punctuation of ``text``; ``'s`` dropped."""
    text = unicodedata.normalize("NFKD", text)
    text = "".join(c for c in text if not unicodedata.combining(c)).lower()
    text = re.sub(r"[\u2018\u2019`\u00b4]", "'", text).replace("\u00d7", " x ")
    text = re.sub(r"'s\b", "", text).replace("'", "")
    text = re.sub(
        r"(\d)\s*(?:m\^?2|sq\.?\s*m|sqm|square\s+met(?:er|re)s?|square\s+m)\b", r"\1 sqm ", text
    )
    text = re.sub(r"(\d)\s*(?:ft\^?2|sq\.?\s*ft|sqft|square\s+f(?:ee|oo)t)\b", r"\1 sqft ", text)
    return re.findall(r"\d+(?:\.\d+)?|[a-z]+|[,.;:!?()&*]", text)


def normalise_words(tokens: Sequence[str]) -> list[str]:
    """Number words to digits and quantity phrases to markers (:data:`MANY`, :data:`NEG`)."""
    out: list[str] = []
    i = 0
    while i < len(tokens):
        for phrase, replacement in _PHRASES:
            if tuple(tokens[i : i + len(phrase)]) == phrase:
                out.extend(replacement)
                i += len(phrase)
                break
        else:
            word = tokens[i]
            if word in _MANY_WORDS:
                out.append(MANY)
            elif word in _NEG_WORDS:
                out.append(NEG)
            elif word in _NUMBERS or word in _SCALES:
                value, i = _read_number(tokens, i)
                out.append(str(value))
                continue
            else:
                out.append(word)
            i += 1
    return out


def _read_number(tokens: Sequence[str], i: int) -> tuple[int, int]:
    """Read ``twenty five``, ``two hundred``, ``two dozen`` from ``tokens[i]``."""
    word = tokens[i]
    value = _SCALES.get(word, _NUMBERS.get(word, 0))
    i += 1
    if word in _TENS and i < len(tokens) and tokens[i] in _NUMBERS and _NUMBERS[tokens[i]] < 10:
        value += _NUMBERS[tokens[i]]
        i += 1
    while i < len(tokens) and (tokens[i] in _SCALES or tokens[i] == "dozen"):
        value *= _SCALES.get(tokens[i], 12)
        i += 1
    return value, i


def is_number(token: str) -> bool:
    """Whether a token is a number (``2``, ``2.5``)."""
    return bool(re.fullmatch(r"\d+(?:\.\d+)?", token))


def plural_forms(phrase: str) -> list[str]:
    """English plurals of a phrase's last word (``bookshelf`` -> ``bookshelves``)."""
    *head, last = phrase.split()
    forms: list[str] = []
    if last.endswith(("s", "x", "z", "ch", "sh")):
        forms.append(last + "es")
    elif last.endswith("y") and len(last) > 1 and last[-2] not in "aeiou":
        forms.append(last[:-1] + "ies")
    elif last.endswith("fe"):
        forms += [last[:-2] + "ves", last + "s"]
    elif last.endswith("f"):
        forms += [last[:-1] + "ves", last + "s"]
    elif last.endswith("o"):
        forms += [last + "s", last + "es"]
    else:
        forms.append(last + "s")
    return [" ".join([*head, form]) for form in forms]


# ---------------------------------------------------------------------------------------------
# The phrase index


@dataclass(frozen=True)
class Meaning:
    """What a phrase names: kind (scene, room, object, generic, refused, style, window), key."""

    kind: str
    key: str
    plural: bool = False


@dataclass(frozen=True)
class PhraseIndex:
    """Phrases (word tuples) of the knowledge base and what they name."""

    phrases: dict[tuple[str, ...], tuple[Meaning, ...]]
    materials: dict[tuple[str, ...], str]
    surfaces: dict[str, str]
    modifiers: frozenset[str]
    size_words: dict[str, float]
    refine: dict[str, list[str]]  # refine word -> scene types


_INDEXES: dict[int, tuple[KnowledgeBase, PhraseIndex]] = {}


def phrase_index(kb: KnowledgeBase) -> PhraseIndex:
    """The phrase index of a knowledge base (built once per knowledge base object)."""
    cached = _INDEXES.get(id(kb))
    if cached is None or cached[0] is not kb:
        cached = (kb, _build_index(kb))
        _INDEXES[id(kb)] = cached
    return cached[1]


def _build_index(kb: KnowledgeBase) -> PhraseIndex:
    explicit: dict[tuple[str, ...], list[Meaning]] = {}
    derived: dict[tuple[str, ...], list[Meaning]] = {}

    def add(phrases: Sequence[str], kind: str, key: str, plurals: bool) -> None:
        for phrase in phrases:
            words = tuple(tokenize(phrase))
            _add_meaning(explicit, words, Meaning(kind, key))
            if plurals:
                for form in plural_forms(phrase):
                    _add_meaning(derived, tuple(tokenize(form)), Meaning(kind, key, plural=True))

    for key, scene in kb.scene_types.items():
        add(scene.keywords, "scene", key, plurals=False)
    for key, room in kb.rooms.items():
        add(room.aliases, "room", key, plurals=True)
    for key, kind in kb.objects.items():
        add([key, *kind.aliases], "object", key, plurals=True)
    for key, generic in kb.generics.items():
        add(generic.aliases, "generic", key, plurals=True)
    for key, refused in kb.refused.items():
        add(refused.aliases, "refused", key, plurals=True)
    for key, style in kb.styles.items():
        add(style.aliases, "style", key, plurals=False)
    add(["window"], "window", "window", plurals=True)
    phrases = {words: tuple(meanings) for words, meanings in explicit.items()}
    for words, meanings in derived.items():
        kinds = {m.kind for m in phrases.get(words, ())}
        extra = tuple(m for m in meanings if m.kind not in kinds)
        if extra:
            phrases[words] = phrases.get(words, ()) + extra
    materials = {
        tuple(tokenize(alias)): key for key, term in kb.materials.items() for alias in term.aliases
    }
    surfaces = {word: surface for surface, words in kb.surfaces.items() for word in words}
    refine: dict[str, list[str]] = {}
    for key, scene in kb.scene_types.items():
        for word in scene.refine_keywords:
            refine.setdefault(word, []).append(key)
    return PhraseIndex(
        phrases=phrases,
        materials=materials,
        surfaces=surfaces,
        modifiers=frozenset(kb.modifiers),
        size_words=dict(kb.limits.size_words),
        refine=refine,
    )


def _add_meaning(
    table: dict[tuple[str, ...], list[Meaning]], words: tuple[str, ...], m: Meaning
) -> None:
    meanings = table.setdefault(words, [])
    if all(other.kind != m.kind for other in meanings):
        meanings.append(m)


# ---------------------------------------------------------------------------------------------
# Parsing


@dataclass
class _Mention:
    start: int
    end: int
    meanings: tuple[Meaning, ...]

    def meaning(self, kind: str) -> Meaning | None:
        return next((m for m in self.meanings if m.kind == kind), None)


@dataclass
class _Reader:
    """Working state of one parse."""

    words: list[str]
    index: PhraseIndex
    kb: KnowledgeBase
    used: list[bool] = field(default_factory=list)
    mentions: list[_Mention] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    heights: list[float] = field(default_factory=list)
    claimed_sizes: set[int] = field(default_factory=set)

    def __post_init__(self) -> None:
        self.used = [False] * len(self.words)

    def text(self, start: int, end: int) -> str:
        return " ".join(w for w in self.words[start:end] if w not in (MANY, NEG))


def parse_prompt(text: str, kb: KnowledgeBase) -> ParsedPrompt:
    """Read a prompt into a :class:`ParsedPrompt` (no model, no randomness)."""
    reader = _Reader(normalise_words(tokenize(text)), phrase_index(kb), kb)
    sizes = _read_sizes(reader)
    materials = _read_materials(reader)
    _match_phrases(reader)
    materials.update(_lone_materials(reader, materials))
    head_end = next((i for i, w in enumerate(reader.words) if w in _HEAD_END), len(reader.words))
    scene = _scene_mention(reader, head_end)
    found = _read_mentions(reader, scene, sizes)
    scene_sizes = sizes.pop(-1, {})
    for start in sorted(sizes):  # sizes next to no room phrase: they describe the scene
        scene_sizes = scene_sizes or sizes[start]
    size_word = _modifiers(reader, scene.start).size_word if scene is not None else None
    scene_meaning = scene.meaning("scene") if scene is not None else None
    return ParsedPrompt(
        text=text,
        head=_head_text(reader, head_end),
        scene=scene_meaning.key if scene_meaning is not None else None,
        scene_keyword=reader.text(scene.start, scene.end) if scene is not None else None,
        refinements=_refinements(reader),
        size_word=size_word or _first_size_word(reader, head_end),
        dims=scene_sizes.get("dims"),  # type: ignore[arg-type]
        area_m2=scene_sizes.get("area_m2"),  # type: ignore[arg-type]
        wall_height_m=reader.heights[0] if reader.heights else None,
        rooms=found.rooms,
        styles=found.styles,
        materials=materials,
        objects=found.objects,
        refused=found.refused,
        unknown=_unknown_phrases(reader, _with_scopes(reader.words)),
        capacity=_capacity(reader.words),
        windows=found.windows,
        notes=reader.notes,
    )


@dataclass
class _Found:
    """What the phrases of a prompt name, apart from the scene."""

    rooms: list[RoomMention] = field(default_factory=list)
    objects: list[ObjectRequest] = field(default_factory=list)
    refused: list[RefusedRequest] = field(default_factory=list)
    styles: list[str] = field(default_factory=list)
    windows: int | None = None


def _read_mentions(
    reader: _Reader, scene: _Mention | None, sizes: dict[int, dict[str, object]]
) -> _Found:
    """Rooms, objects, refused things, styles and windows, with their quantities."""
    found = _Found()
    neg_scopes = _neg_scopes(reader.words)
    context: str | None = None  # template of the room whose "with ..." list this is
    last_end = 0
    for mention in reader.mentions:
        if any(w in {".", ";", "!", "?"} for w in reader.words[last_end : mention.start]):
            context = None  # a new sentence
        last_end = mention.end
        if mention is scene:
            context = None
            continue
        mods = _modifiers(reader, mention.start)
        excluded = mods.negated or any(a <= mention.start < b for a, b in neg_scopes)
        phrase = reader.text(mods.start, mention.end)
        room = mention.meaning("room")
        thing = mention.meaning("object") or mention.meaning("generic")
        refusal = mention.meaning("refused")
        style = mention.meaning("style")
        if room is not None:
            found.rooms.append(
                RoomMention(
                    template=room.key,
                    count=0 if excluded else (mods.count if mods.counted else None),
                    size_word=mods.size_word,
                    excluded=excluded,
                    phrase=phrase,
                    **sizes.pop(mention.start, {}),  # type: ignore[arg-type]
                )
            )
            follows = reader.words[mention.end] if mention.end < len(reader.words) else ""
            context = room.key if follows in _WITH_START | {"where"} else None
        elif thing is not None:
            found.objects.append(
                ObjectRequest(
                    kind=thing.key,
                    generic=thing.kind == "generic",
                    quantity=mods.count,
                    many=mods.many,
                    plural=thing.plural,
                    size=_size_class(mods.size_word, reader.index),
                    adjectives=mods.adjectives,
                    room=context,
                    excluded=excluded,
                    phrase=phrase,
                )
            )
        elif refusal is not None and not excluded:
            reason = reader.kb.refused[refusal.key].reason
            found.refused.append(RefusedRequest(name=refusal.key, phrase=phrase, reason=reason))
        elif mention.meaning("window") is not None:
            if excluded:
                found.windows = 0
            elif mods.count is not None:
                found.windows = mods.count
            elif mods.many:
                found.windows = 4
        elif style is not None and style.key not in found.styles:
            found.styles.append(style.key)
    return found


def _size_class(word: str | None, index: PhraseIndex) -> Literal["small", "large"] | None:
    if word is None:
        return None
    factor = index.size_words.get(word, 1.0)
    if factor < 1.0:
        return "small"
    if factor > 1.0:
        return "large"
    return None


# --- sizes ------------------------------------------------------------------------------------


def _read_sizes(reader: _Reader) -> dict[int, dict[str, object]]:
    """Room dimensions and areas, keyed by the start of the room phrase they describe.

    Key -1: no room phrase close by (the scene's size). Lengths next to ``ceiling`` become the
    wall height (``reader.heights``); sizes of single objects are ignored, with a note.
    """
    words = reader.words
    out: dict[int, dict[str, object]] = {}
    i = 0
    while i < len(words):
        found = _size_at(words, i)
        if found is None:
            i += 1
            continue
        end, value = found
        for k in range(i, end):
            reader.used[k] = True
        text = reader.text(i, end)
        if "height" in value:
            reader.heights.append(float(value["height"]))  # type: ignore[arg-type]
        elif value.pop("tall", False):
            reader.notes.append(f"'{text}' describes an object's height, which is not planned")
        else:
            target = _nearest_room_word(reader, i, end)
            if target is None:
                reader.notes.append(
                    f"'{text}' is an object size; objects keep the knowledge base's sizes"
                )
            else:
                if value.pop("side", False):
                    side = value["dims"][0]  # type: ignore[index]
                    reader.notes.append(f"read '{text}' as a square room of {side:g} x {side:g} m")
                out.setdefault(target, value)
        i = end
    return out


def _size_at(words: Sequence[str], i: int) -> tuple[int, dict[str, object]] | None:
    """A size starting at ``words[i]``: (end, {dims | area_m2 | height | side | tall})."""
    if not is_number(words[i]):
        return None
    value = float(words[i])
    j = i + 1
    unit = _LENGTH.get(words[j]) if j < len(words) else None
    if unit is not None:
        j += 1
    if j < len(words) and words[j] in _AREA_WORDS:
        return j + 1, {"area_m2": value * _AREA_WORDS[words[j]]}
    if j + 1 < len(words) and words[j] in _BY and is_number(words[j + 1]):
        other = float(words[j + 1])
        k = j + 2
        unit2 = _LENGTH.get(words[k]) if k < len(words) else None
        if unit2 is not None:
            k += 1
        scale = unit or unit2 or 1.0
        return k, {"dims": (value * (unit or scale), other * (unit2 or scale))}
    if unit is None:
        return None
    if _CEILING & set(words[max(0, i - 3) : j + 3]):
        return j, {"height": value * unit}
    if j < len(words) and words[j] in _HEIGHT_WORDS:
        return j + 1, {"tall": True}
    return j, {"dims": (value * unit, value * unit), "side": True}


def _nearest_room_word(reader: _Reader, start: int, end: int) -> int | None:
    """Start of the scene/room phrase a size describes: -1 for none close by, None for an object.

    Looks up to four words ahead (``a 4 by 5 m kitchen``), then three back (``kitchen of 4x5
    m``); an object phrase ahead means the size is the object's (``a 2 by 1 m table``).
    """
    for k in range(end, min(len(reader.words), end + 4)):
        hit = _longest_at(reader, k)
        if hit is not None:
            kinds = {m.kind for m in hit[1]}
            if kinds & {"scene", "room"}:
                return k
            if kinds & {"object", "generic"}:
                return None
        if reader.words[k] in _SEPARATORS | {".", ";", "for", "who", "that"}:
            break
    for k in range(start - 1, max(-1, start - 4), -1):
        if reader.words[k] in {"with", ",", ";", "."}:
            break
        for begin in range(max(0, k - MAX_PHRASE_WORDS + 1), k + 1):
            hit = _longest_at(reader, begin)
            ends_here = hit is not None and begin + len(hit[0]) == k + 1
            if ends_here and {m.kind for m in hit[1]} & {"scene", "room"}:  # type: ignore[index]
                return begin
    return -1


# --- materials --------------------------------------------------------------------------------


def _read_materials(reader: _Reader) -> dict[str, str]:
    """``oak floor`` -> ``oak wood floor``; ``white walls`` -> ``white painted wall``."""
    out: dict[str, str] = {}
    words = reader.words
    for i, word in enumerate(words):
        surface = reader.index.surfaces.get(word)
        if surface is None or reader.used[i]:
            continue
        parts = _material_run(reader, i)
        if not parts:
            continue
        start = parts[0][0]
        description = _describe(reader, parts, surface)
        for k in range(start, i + 1):
            reader.used[k] = True
        if surface not in out:
            out[surface] = f"{description} {surface}"
    return out


def _material_run(reader: _Reader, end: int) -> list[tuple[int, int, str | None]]:
    """(start, end, material key or None for a modifier) of the words before ``end``."""
    parts: list[tuple[int, int, str | None]] = []
    k = end
    while k > 0 and len(parts) < ADJECTIVE_RUN:
        hit = None
        for size in range(min(3, k), 0, -1):
            words = tuple(reader.words[k - size : k])
            if words in reader.index.materials:
                hit = (k - size, k, reader.index.materials[words])
                break
        if hit is None and reader.words[k - 1] in reader.index.modifiers:
            hit = (k - 1, k, None)
        if hit is None or any(reader.used[hit[0] : hit[1]]):
            break
        parts.insert(0, hit)
        k = hit[0]
    return parts if any(p[2] is not None for p in parts) else []


def _describe(reader: _Reader, parts: list[tuple[int, int, str | None]], surface: str) -> str:
    last = max(i for i, p in enumerate(parts) if p[2] is not None)
    words: list[str] = []
    for i, (start, end, key) in enumerate(parts):
        raw = " ".join(reader.words[start:end])
        if i == last and key is not None:
            words.append(reader.kb.materials[key].for_surface(surface) or raw)
        else:
            words.append(raw)
    return " ".join(words)


def _lone_materials(reader: _Reader, found: dict[str, str]) -> dict[str, str]:
    """Material words with no surface word after them (``a carpeted bedroom``)."""
    out: dict[str, str] = {}
    covered = {k for m in reader.mentions for k in range(m.start, m.end)}
    for i in range(len(reader.words)):
        if reader.used[i] or i in covered:
            continue
        for size in (3, 2, 1):
            words = tuple(reader.words[i : i + size])
            key = reader.index.materials.get(words)
            if key is None:
                continue
            term = reader.kb.materials[key]
            nxt = next((m for m in reader.mentions if m.start >= i + size), None)
            before_object = (
                nxt is not None
                and nxt.start <= i + size + 1
                and (nxt.meaning("object") or nxt.meaning("generic"))
            )
            if term.alone is not None and not before_object:
                surface = term.alone
                if surface not in found and surface not in out:
                    text = term.for_surface(surface) or " ".join(words)
                    out[surface] = f"{text} {surface}"
            break
    return out


# --- phrases ----------------------------------------------------------------------------------


def _longest_at(reader: _Reader, i: int) -> tuple[tuple[str, ...], tuple[Meaning, ...]] | None:
    for size in range(min(MAX_PHRASE_WORDS, len(reader.words) - i), 0, -1):
        words = tuple(reader.words[i : i + size])
        meanings = reader.index.phrases.get(words)
        if meanings and not any(reader.used[i : i + size]):
            return words, meanings
    return None


def _match_phrases(reader: _Reader) -> None:
    i = 0
    while i < len(reader.words):
        hit = None if reader.used[i] else _longest_at(reader, i)
        if hit is None:
            i += 1
            continue
        words, meanings = hit
        reader.mentions.append(_Mention(i, i + len(words), meanings))
        i += len(words)
    _bedroom_shorthand(reader)


def _bedroom_shorthand(reader: _Reader) -> None:
    """``2 bed 1 bath apartment``: a number before ``bed``/``br`` counts bedrooms."""
    for mention in reader.mentions:
        words = reader.words[mention.start : mention.end]
        if words not in (["bed"], ["beds"], ["br"], ["bd"]):
            continue
        before = reader.words[mention.start - 1] if mention.start > 0 else ""
        after = next((m for m in reader.mentions if m.start >= mention.end), None)
        if (
            is_number(before)
            and after is not None
            and after.start <= mention.end + 3
            and (after.meaning("scene") or after.meaning("room"))
        ):
            mention.meanings = (Meaning("room", "bedroom"),)


@dataclass
class _Mods:
    start: int
    count: int | None = None
    counted: bool = False  # a number, not an article
    many: bool = False
    negated: bool = False
    size_word: str | None = None
    adjectives: list[str] = field(default_factory=list)


def _modifiers(reader: _Reader, start: int) -> _Mods:
    """Quantity, size word and adjectives in the words just before a phrase."""
    mods = _Mods(start)
    ends = {m.end: m for m in reader.mentions}
    k = start
    skipped = 0
    while k > 0 and start - k < ADJECTIVE_RUN + 2:
        word = reader.words[k - 1]
        if k in ends and not (ends[k].meaning("style") and len(ends[k].meanings) == 1):
            break  # another phrase ends here (style words are adjectives)
        if word in _SEPARATORS or word in {".", ";", "!", "?", "for", "in", "of"}:
            break
        if is_number(word):
            mods.count = int(min(float(word), 10_000))
            mods.counted = True
            mods.start = k - 1
            break
        if word == MANY:
            mods.many = True
            mods.start = k - 1
            break
        if word == NEG:
            mods.negated = True
            mods.start = k - 1
            break
        if word in _DETERMINERS:
            if word in {"a", "an", "one", "another"}:
                mods.count = 1
            mods.start = k - 1
            break
        if word in reader.index.size_words:
            mods.size_word = mods.size_word or word
            reader.claimed_sizes.add(k - 1)
        elif k in ends or word in reader.index.modifiers or _is_material(reader, word):
            mods.adjectives.insert(0, word)
        elif word in _STOPWORDS or reader.used[k - 1]:
            break
        else:
            skipped += 1
            if skipped > 2:
                break
            mods.adjectives.insert(0, word)
        mods.start = k - 1
        k -= 1
    if mods.count is not None and mods.start > 0 and reader.words[mods.start - 1] == NEG:
        mods.negated = True
    return mods


def _is_material(reader: _Reader, word: str) -> bool:
    return (word,) in reader.index.materials


def _scene_mention(reader: _Reader, head_end: int) -> _Mention | None:
    """The last scene keyword of the head, else the first one anywhere.

    None when the head names rooms but no scene (``3 bedrooms and a bathroom``): the planner
    then picks a home for them.
    """
    head = [m for m in reader.mentions if m.start < head_end]
    in_head = [m for m in head if m.meaning("scene")]
    if in_head:
        return in_head[-1]
    if any(m.meaning("room") for m in head):
        return None
    return next((m for m in reader.mentions if m.meaning("scene")), None)


def _first_size_word(reader: _Reader, head_end: int) -> str | None:
    """The first size word of the head that qualifies no object or room phrase."""
    for k, word in enumerate(reader.words[:head_end]):
        if word in reader.index.size_words and k not in reader.claimed_sizes:
            return word
    return None


def _head_text(reader: _Reader, head_end: int) -> str:
    words = [
        w
        for i, w in enumerate(reader.words[:head_end])
        if not reader.used[i] or any(m.start <= i < m.end for m in reader.mentions)
    ]
    content = [
        w
        for w in words
        if (w not in _STOPWORDS or w in _ROOM_WORDS) and not is_number(w) and w not in (MANY, NEG)
    ]
    if content and not set(content) <= _ROOM_WORDS:
        return " ".join(content)
    return ""


def _refinements(reader: _Reader) -> list[tuple[str, str]]:
    found: list[tuple[str, str]] = []
    for word in reader.words:
        for scene in reader.index.refine.get(word, []):
            if (scene, word) not in found:
                found.append((scene, word))
    return found


def _with_scopes(words: Sequence[str]) -> list[tuple[int, int]]:
    scopes = []
    start = None
    for i, word in enumerate(words):
        if word in _WITH_START and start is None:
            start = i + 1
        elif word in _WITH_END and start is not None:
            scopes.append((start, i))
            start = None
    if start is not None:
        scopes.append((start, len(words)))
    return scopes


def _neg_scopes(words: Sequence[str]) -> list[tuple[int, int]]:
    """``without a tv or a sofa``: from NEG to the next ``with`` or end of clause."""
    scopes = []
    for i, word in enumerate(words):
        if word != NEG:
            continue
        end = next(
            (k for k in range(i + 1, len(words)) if words[k] in _WITH_END | {"with", "but"}),
            len(words),
        )
        scopes.append((i, end))
    return scopes


def _unknown_phrases(reader: _Reader, scopes: list[tuple[int, int]]) -> list[str]:
    """Items of ``with ...`` lists that name nothing the knowledge base knows."""
    out: list[str] = []
    covered = [False] * len(reader.words)
    for m in reader.mentions:
        for k in range(m.start, m.end):
            covered[k] = True
    for start, end in scopes:
        item: list[int] = []
        for k in range(start, end + 1):
            if k == end or reader.words[k] in _SEPARATORS:
                phrase = _unknown_item(reader, item, covered)
                if phrase and phrase not in out:
                    out.append(phrase)
                item = []
            else:
                item.append(k)
    return out


def _unknown_item(reader: _Reader, item: list[int], covered: list[bool]) -> str | None:
    if not item or any(covered[k] or reader.used[k] for k in item):
        return None
    content = [k for k in item if _is_content(reader, reader.words[k])]
    if not content:
        return None
    return " ".join(reader.words[content[0] : min(content[-1], content[0] + 5) + 1])


def _is_content(reader: _Reader, word: str) -> bool:
    """A word that could name a thing (not a stopword, number, size or people word)."""
    return (
        len(word) > 1
        and word not in _STOPWORDS
        and not is_number(word)
        and word not in (MANY, NEG)
        and word not in reader.index.size_words
        and word not in reader.index.modifiers
        and word not in _PEOPLE
        and word not in reader.index.refine
    )


def _capacity(words: Sequence[str]) -> int | None:
    """``for 8 people``, ``seating for 20``, ``a class of 20 students``."""
    for i, word in enumerate(words[:-1]):
        if word in {"for", "of", "seats", "seating", "fits", "holds"} and is_number(words[i + 1]):
            nxt = words[i + 2] if i + 2 < len(words) else ""
            if nxt in _PEOPLE or (word == "for" and nxt in {"", ".", ",", "!", ";"}):
                return max(0, int(float(words[i + 1])))
    return None


__all__ = [
    "MANY",
    "NEG",
    "ObjectRequest",
    "ParsedPrompt",
    "PhraseIndex",
    "RefusedRequest",
    "RoomMention",
    "is_number",
    "normalise_words",
    "parse_prompt",
    "phrase_index",
    "plural_forms",
    "tokenize",
]
