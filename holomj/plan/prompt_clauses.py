"""Clause-level reading of a prompt: its head and scene, ``with``/``without`` lists, capacity.

The head is what comes before the first ``with``, ``for``, ``and``, comma, ...: its last scene
keyword names the scene and its content words are matched against scene types when none does.
``with ...`` lists yield the phrases the knowledge base does not know, ``without ...`` the
scopes of exclusions, and ``for 8 people`` the seating capacity.
"""

from __future__ import annotations

from collections.abc import Sequence

from holomj.plan.prompt_reader import Mention, Reader
from holomj.plan.prompt_words import (
    MANY,
    NEG,
    PEOPLE,
    ROOM_WORDS,
    SEPARATORS,
    STOPWORDS,
    WITH_END,
    WITH_START,
    is_number,
)


def scene_mention(reader: Reader, head_end: int) -> Mention | None:
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


def first_size_word(reader: Reader, head_end: int) -> str | None:
    """The first size word of the head that qualifies no object or room phrase."""
    for k, word in enumerate(reader.words[:head_end]):
        if word in reader.index.size_words and k not in reader.claimed_sizes:
            return word
    return None


def head_text(reader: Reader, head_end: int) -> str:
    """Content words of the head, for matching a scene type; empty when only room words."""
    words = [
        w
        for i, w in enumerate(reader.words[:head_end])
        if not reader.used[i] or any(m.start <= i < m.end for m in reader.mentions)
    ]
    content = [
        w
        for w in words
        if (w not in STOPWORDS or w in ROOM_WORDS) and not is_number(w) and w not in (MANY, NEG)
    ]
    if content and not set(content) <= ROOM_WORDS:
        return " ".join(content)
    return ""


def find_refinements(reader: Reader) -> list[tuple[str, str]]:
    """(scene type, word) for each scene refine word anywhere in the prompt, in order."""
    found: list[tuple[str, str]] = []
    for word in reader.words:
        for scene in reader.index.refine.get(word, []):
            if (scene, word) not in found:
                found.append((scene, word))
    return found


def with_scopes(words: Sequence[str]) -> list[tuple[int, int]]:
    """(start, end) word ranges of ``with ...`` lists, each up to the end of its clause."""
    scopes = []
    start = None
    for i, word in enumerate(words):
        if word in WITH_START and start is None:
            start = i + 1
        elif word in WITH_END and start is not None:
            scopes.append((start, i))
            start = None
    if start is not None:
        scopes.append((start, len(words)))
    return scopes


def negation_scopes(words: Sequence[str]) -> list[tuple[int, int]]:
    """``without a tv or a sofa``: from NEG to the next ``with`` or end of clause."""
    scopes = []
    for i, word in enumerate(words):
        if word != NEG:
            continue
        end = next(
            (k for k in range(i + 1, len(words)) if words[k] in WITH_END | {"with", "but"}),
            len(words),
        )
        scopes.append((i, end))
    return scopes


def unknown_phrases(reader: Reader, scopes: list[tuple[int, int]]) -> list[str]:
    """Items of ``with ...`` lists that name nothing the knowledge base knows."""
    out: list[str] = []
    covered = [False] * len(reader.words)
    for m in reader.mentions:
        for k in range(m.start, m.end):
            covered[k] = True
    for start, end in scopes:
        item: list[int] = []
        for k in range(start, end + 1):
            if k == end or reader.words[k] in SEPARATORS:
                phrase = _unknown_item(reader, item, covered)
                if phrase and phrase not in out:
                    out.append(phrase)
                item = []
            else:
                item.append(k)
    return out


def _unknown_item(reader: Reader, item: list[int], covered: list[bool]) -> str | None:
    if not item or any(covered[k] or reader.used[k] for k in item):
        return None
    if any(reader.words[k] == NEG for k in item):
        return None  # "no car": nothing to plan
    content = [k for k in item if _is_content(reader, reader.words[k])]
    if not content:
        return None
    span = range(content[0], min(content[-1], content[0] + 5) + 1)
    return " ".join(reader.words[k] for k in span if not is_number(reader.words[k]))


def _is_content(reader: Reader, word: str) -> bool:
    """A word that could name a thing (not a stopword, number, size or people word)."""
    return (
        len(word) > 1
        and word not in STOPWORDS
        and not is_number(word)
        and word not in (MANY, NEG)
        and word not in reader.index.size_words
        and word not in reader.index.modifiers
        and word not in PEOPLE
        and word not in reader.index.refine
    )


def read_capacity(words: Sequence[str]) -> int | None:
    """``for 8 people``, ``seating for 20``, ``a class of 20 students``."""
    for i, word in enumerate(words[:-1]):
        if word in {"for", "of", "seats", "seating", "fits", "holds"} and is_number(words[i + 1]):
            nxt = words[i + 2] if i + 2 < len(words) else ""
            if nxt in PEOPLE or (word == "for" and nxt in {"", ".", ",", "!", ";"}):
                return max(0, int(float(words[i + 1])))
    return None
