"""Parts of an asked-for object: "cabinets with brass handles", "a chair with a red seat".

A ``with`` right after an object phrase may name a part of that object rather than another
object: the item up to the next separator ends in a part noun (:data:`PART_NOUNS`) and has only
colour, material and other modifier words before it. Such an item is kept with the object (its
``parts``: ``brass handles``) for the asset stage, which colours or makes only that part, and is
neither planned as an object of its own nor reported as unknown.
"""

from __future__ import annotations

from collections.abc import Sequence

from holomj.plan.prompt_words import DETERMINERS, SEPARATORS

# Part nouns of furniture (and their plurals); the asset stage knows which parts they name.
PART_NOUNS = frozenset(
    {
        "top", "tabletop", "worktop", "countertop", "leg", "legs", "feet", "base", "pedestal",
        "plinth", "frame", "seat", "seats", "cushion", "cushions", "back", "backrest", "arms",
        "armrests", "headboard", "bedding", "sheets", "duvet", "pillows", "door", "doors",
        "drawer", "drawers", "fronts", "handle", "handles", "pulls", "knobs", "hardware",
        "shade", "lampshade", "shelves", "pole", "stem",
    }
)  # fmt: skip
PART_LEAD = frozenset({"with", "having"})
ITEM_END = SEPARATORS | {".", ";", "!", "?"}
MAX_PART_WORDS = 4  # modifier words before the part noun


def part_after(words: Sequence[str], object_end: int) -> tuple[int, int] | None:
    """The span ``(start, end)`` of a part phrase right after an object phrase ending at
    ``object_end`` ("... with brass handles"), without its article; else None."""
    if object_end >= len(words) or words[object_end] not in PART_LEAD:
        return None
    start = object_end + 1
    while start < len(words) and words[start] in DETERMINERS:
        start += 1
    end = start
    while end < len(words) and words[end] not in ITEM_END:
        end += 1
    if end == start or end - start > MAX_PART_WORDS + 1 or words[end - 1] not in PART_NOUNS:
        return None
    return start, end
