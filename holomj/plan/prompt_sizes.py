"""Sizes in a prompt: room dimensions and areas, ceiling heights, object sizes (noted).

``8 by 5 meters``, ``8x5 m``, ``40 square meters``, ``200 sqft`` and ``a 4 m room`` (a square)
are read as numbers with units; each goes to the scene or room phrase it stands next to. Lengths
next to ``ceiling`` are the wall height; sizes of objects and heights of things are noted and
not planned.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from holomj.plan.prompt_reader import Reader, longest_at
from holomj.plan.prompt_words import MAX_PHRASE_WORDS, SEPARATORS, is_number

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


@dataclass(frozen=True)
class SizeRead:
    """A room's (or the scene's) size as the prompt gives it: dimensions (metres) or an area."""

    dims: tuple[float, float] | None = None
    area_m2: float | None = None


@dataclass(frozen=True)
class _FoundSize:
    """A size in the words: a room size, a wall height, or an object's height (``tall``);
    ``side``: one length read as a square."""

    size: SizeRead = SizeRead()
    height: float | None = None
    side: bool = False
    tall: bool = False


def read_sizes(reader: Reader) -> dict[int, SizeRead]:
    """Room dimensions and areas, keyed by the start of the room phrase they describe.

    Key -1: no room phrase close by (the scene's size). Lengths next to ``ceiling`` become the
    wall height (``reader.heights``); sizes of single objects are ignored, with a note.
    """
    words = reader.words
    out: dict[int, SizeRead] = {}
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
        if value.height is not None:
            reader.heights.append(value.height)
        elif value.tall:
            reader.notes.append(f"'{text}' describes an object's height, which is not planned")
        else:
            target = _nearest_room_word(reader, i, end)
            if target is None:
                reader.notes.append(
                    f"'{text}' is an object size; objects keep the knowledge base's sizes"
                )
            else:
                if value.side and value.size.dims is not None:
                    side = value.size.dims[0]
                    reader.notes.append(f"read '{text}' as a square room of {side:g} x {side:g} m")
                out.setdefault(target, value.size)
        i = end
    return out


def _size_at(words: Sequence[str], i: int) -> tuple[int, _FoundSize] | None:
    """A size starting at ``words[i]``: (end, what it is)."""
    if not is_number(words[i]):
        return None
    value = float(words[i])
    j = i + 1
    unit = _LENGTH.get(words[j]) if j < len(words) else None
    if unit is not None:
        j += 1
    if j < len(words) and words[j] in _AREA_WORDS:
        return j + 1, _FoundSize(SizeRead(area_m2=value * _AREA_WORDS[words[j]]))
    if j + 1 < len(words) and words[j] in _BY and is_number(words[j + 1]):
        other = float(words[j + 1])
        k = j + 2
        unit2 = _LENGTH.get(words[k]) if k < len(words) else None
        if unit2 is not None:
            k += 1
        scale = unit or unit2 or 1.0
        return k, _FoundSize(SizeRead(dims=(value * (unit or scale), other * (unit2 or scale))))
    if unit is None:
        return None
    if _CEILING & set(words[max(0, i - 3) : j + 3]):
        return j, _FoundSize(height=value * unit)
    if j < len(words) and words[j] in _HEIGHT_WORDS:
        return j + 1, _FoundSize(tall=True)
    return j, _FoundSize(SizeRead(dims=(value * unit, value * unit)), side=True)


def _nearest_room_word(reader: Reader, start: int, end: int) -> int | None:
    """Start of the scene/room phrase a size describes: -1 for none close by, None for an object.

    Looks up to four words ahead (``a 4 by 5 m kitchen``), then three back (``kitchen of 4x5
    m``); an object phrase ahead means the size is the object's (``a 2 by 1 m table``).
    """
    for k in range(end, min(len(reader.words), end + 4)):
        hit = longest_at(reader, k)
        if hit is not None:
            kinds = {m.kind for m in hit[1]}
            if kinds & {"scene", "room"}:
                return k
            if kinds & {"object", "generic"}:
                return None
        if reader.words[k] in SEPARATORS | {".", ";", "for", "who", "that"}:
            break
    for k in range(start - 1, max(-1, start - 4), -1):
        if reader.words[k] in {"with", ",", ";", "."}:
            break
        for begin in range(max(0, k - MAX_PHRASE_WORDS + 1), k + 1):
            hit = longest_at(reader, begin)
            if hit is None or begin + len(hit[0]) != k + 1:
                continue
            if {m.kind for m in hit[1]} & {"scene", "room"}:
                return begin
    return -1
