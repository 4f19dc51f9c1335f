"""Working state of one prompt parse, and the phrase matching on it.

A :class:`Reader` holds the prompt's normalised words, which of them are used up (by sizes and
materials) and the :class:`Mention` of every known phrase, matched longest first, left to right.
:func:`read_modifiers` reads the quantity, negation, size word and adjectives in the words just
before a phrase.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from holomj.plan.knowledge_schema import KnowledgeBase
from holomj.plan.prompt_index import Meaning, PhraseIndex
from holomj.plan.prompt_words import (
    ADJECTIVE_RUN,
    DETERMINERS,
    MANY,
    MAX_PHRASE_WORDS,
    NEG,
    SEPARATORS,
    STOPWORDS,
    is_number,
)


@dataclass
class Mention:
    """A known phrase at ``words[start:end]`` and what it may name."""

    start: int
    end: int
    meanings: tuple[Meaning, ...]

    def meaning(self, kind: str) -> Meaning | None:
        """The phrase's meaning of this kind (``object``, ``room``, ...), if it has one."""
        return next((m for m in self.meanings if m.kind == kind), None)


@dataclass
class Reader:
    """Working state of one parse."""

    words: list[str]
    index: PhraseIndex
    kb: KnowledgeBase
    used: list[bool] = field(default_factory=list)
    mentions: list[Mention] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    heights: list[float] = field(default_factory=list)
    claimed_sizes: set[int] = field(default_factory=set)

    def __post_init__(self) -> None:
        self.used = [False] * len(self.words)

    def text(self, start: int, end: int) -> str:
        """The words ``start:end`` as text, without markers."""
        return " ".join(w for w in self.words[start:end] if w not in (MANY, NEG))


def longest_at(reader: Reader, i: int) -> tuple[tuple[str, ...], tuple[Meaning, ...]] | None:
    """The longest known phrase starting at word ``i`` with no used word, and its meanings."""
    for size in range(min(MAX_PHRASE_WORDS, len(reader.words) - i), 0, -1):
        words = tuple(reader.words[i : i + size])
        meanings = reader.index.phrases.get(words)
        if meanings and not any(reader.used[i : i + size]):
            return words, meanings
    return None


def match_phrases(reader: Reader) -> None:
    """Record the mentions of known phrases, longest first, left to right."""
    i = 0
    while i < len(reader.words):
        hit = None if reader.used[i] else longest_at(reader, i)
        if hit is None:
            i += 1
            continue
        words, meanings = hit
        reader.mentions.append(Mention(i, i + len(words), meanings))
        i += len(words)
    _bedroom_shorthand(reader)


def _bedroom_shorthand(reader: Reader) -> None:
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
class Mods:
    """What the words before a phrase say about it; ``start`` is where they begin."""

    start: int
    count: int | None = None
    counted: bool = False  # a number, not an article
    many: bool = False
    negated: bool = False
    size_word: str | None = None
    adjectives: list[str] = field(default_factory=list)


def read_modifiers(reader: Reader, start: int) -> Mods:
    """Quantity, size word and adjectives in the words just before a phrase."""
    mods = Mods(start)
    ends = {m.end: m for m in reader.mentions}
    k = start
    skipped = 0
    while k > 0 and start - k < ADJECTIVE_RUN + 2:
        word = reader.words[k - 1]
        if k in ends and not (ends[k].meaning("style") and len(ends[k].meanings) == 1):
            break  # another phrase ends here (style words are adjectives)
        if word in SEPARATORS or word in {".", ";", "!", "?", "for", "in", "of"}:
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
        if word in DETERMINERS:
            if word in {"a", "an", "one", "another"}:
                mods.count = 1
            mods.start = k - 1
            break
        if word in reader.index.size_words:
            mods.size_word = mods.size_word or word
            reader.claimed_sizes.add(k - 1)
        elif k in ends or word in reader.index.modifiers or _is_material(reader, word):
            mods.adjectives.insert(0, word)
        elif word in STOPWORDS or reader.used[k - 1]:
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


def _is_material(reader: Reader, word: str) -> bool:
    return (word,) in reader.index.materials
