"""Where a prompt puts its objects: relation phrases after an object, read into requests.

After an object phrase, the words up to the next list separator may say where it goes:
``a desk under the window``, ``a floor lamp in the corner``, ``four chairs around it``,
``a nightstand on each side of the bed``, ``a mirror above the washbasin``, ``a coat rack by
the door``, ``three salon chairs, each facing a mirror``. :func:`read_relations` finds them:
filler words (``placed``, ``standing``, ``each``, ...) are skipped, the longest relation phrase
of :data:`RELATIONS` (the vocabulary's, :mod:`holomj.spec.relations`) is matched, then articles
and up to two adjectives, then the target: an object phrase, ``it`` / ``them`` (the object named
before the subject), or a place word (wall, corner, middle, window, door, entrance, ceiling).
``X with Y`` is read as X ``holds`` Y (the planner decides: a small Y goes on X, a seat at it),
``side by side`` and ``in a row`` as ``in_row``. Relations the planner cannot use are still
returned (the planner notes them); phrases it does not recognise are left alone.
"""

from __future__ import annotations

from collections.abc import Sequence

from pydantic import Field

from holomj.spec.base import FrozenModel
from holomj.spec.relations import KIND_OF_WORDS, PHRASE_FAMILIES, PLACE_WORDS
from holomj.spec.relations import ReadRelationKind as RelationKind

# Words between an object phrase and its relation phrase that say nothing about where.
FILLER = frozenset(
    {
        "placed", "standing", "stands", "stand", "set", "positioned", "located", "sitting",
        "sits", "sit", "is", "are", "which", "that", "hanging", "hangs", "hang", "mounted",
        "tucked", "lined", "up", "pushed", "right", "directly", "just", "each", "all", "both",
        "arranged", ",",
    }
)  # fmt: skip
ARTICLES = frozenset(
    {"the", "a", "an", "one", "1", "its", "their", "his", "her", "each", "every", "either", "both"}
)
ADJECTIVES_SKIPPED = 2
PRONOUNS = frozenset({"it", "them", "this", "that", "these", "those"})
# The relation phrases and place words (:data:`holomj.spec.relations.PHRASE_FAMILIES`,
# :data:`~holomj.spec.relations.PLACE_WORDS`), and the kind each (family, target) reads as.
RELATIONS = PHRASE_FAMILIES
_KIND = KIND_OF_WORDS
MAX_PHRASE = max(len(k) for k in RELATIONS)
MAX_LEAD = 3  # filler words skipped before a relation phrase


class RelationRequest(FrozenModel):
    """Where the prompt puts one of its objects: ``subject`` (an index into the parsed objects)
    in relation ``kind`` to ``target`` (an object index; None for a place: corner, window...)."""

    subject: int
    kind: RelationKind
    target: int | None = None
    phrase: str = Field(max_length=300)


def read_relations(
    words: Sequence[str],
    objects: Sequence[tuple[int, int]],
    stops: Sequence[tuple[int, int]] = (),
) -> list[RelationRequest]:
    """Relations after each object phrase.

    ``objects`` are the spans ``(start, end)`` of the parsed object requests, in order (index =
    the request's index); ``stops`` are spans of other known phrases (rooms, ...) that end a
    relation's reach.
    """
    starts = {start: n for n, (start, _) in enumerate(objects)}
    ends = dict(objects)
    blocked = {i for a, b in stops for i in range(a, b)}
    out: list[RelationRequest] = []
    for n, (_, end) in enumerate(objects):
        out.extend(_relations_of(n, end, words, objects, starts, ends, blocked))
    return out


MAX_CHAIN = 3  # relations read one after another: "in a row facing a long mirror"


def _relations_of(
    n: int,
    end: int,
    words: Sequence[str],
    objects: Sequence[tuple[int, int]],
    starts: dict[int, int],
    ends: dict[int, int],
    blocked: set[int],
) -> list[RelationRequest]:
    """The relations after object ``n``'s phrase: one after another while each names a place
    ("in the corner by the window"); one naming an object ends the chain, since what follows
    that object is its own."""
    out: list[RelationRequest] = []
    at = end
    for _ in range(MAX_CHAIN):
        found = _relation_after(words, at, starts, ends, blocked)
        if found is None:
            break
        family, target_at, place, stop = found
        phrase = " ".join(w for w in words[at:stop] if w != ",")
        at = stop
        if place is not None:
            kind = _KIND.get((family, place))
            if kind is not None:
                out.append(RelationRequest(subject=n, kind=kind, phrase=phrase))
            continue
        out.extend(_object_relation(n, family, target_at, phrase, words, objects, starts))
        break
    return out


def _object_relation(
    n: int,
    family: str,
    target_at: int | None,
    phrase: str,
    words: Sequence[str],
    objects: Sequence[tuple[int, int]],
    starts: dict[int, int],
) -> list[RelationRequest]:
    """The relation of object ``n`` to the object at ``target_at`` (else the one before it)."""
    target = starts.get(target_at) if target_at is not None else _previous(n, objects, words)
    if family == "sides_of_previous":
        family, target = "sides", _previous(n, objects, words)
    kind = _KIND.get((family, "object"))
    if kind is None or target is None or target == n:
        return []
    return [RelationRequest(subject=n, kind=kind, target=target, phrase=phrase)]


def _relation_after(
    words: Sequence[str],
    end: int,
    starts: dict[int, int],
    ends: dict[int, int],
    blocked: set[int],
) -> tuple[str, int | None, str | None, int] | None:
    """(family, target object start or None, place word or None, end of the phrase)."""
    i, lead = end, 0
    while i < len(words) and lead <= MAX_LEAD:
        match = _longest(words, i)
        if match is not None:
            family, after = match
            return _target(words, family, after, ends, blocked)
        if words[i] not in FILLER or i in blocked:
            return None
        if words[i] == "," and i + 1 < len(words) and words[i + 1] != "each":
            return None  # a comma ends the object's phrase unless "..., each facing ..."
        i += 1
        lead += 1
    return None


def _longest(words: Sequence[str], i: int) -> tuple[str, int] | None:
    for size in range(min(MAX_PHRASE, len(words) - i), 0, -1):
        family = RELATIONS.get(tuple(words[i : i + size]))
        if family is not None:
            return family, i + size
    return None


def _target(
    words: Sequence[str],
    family: str,
    i: int,
    ends: dict[int, int],
    blocked: set[int],
) -> tuple[str, int | None, str | None, int] | None:
    if family == "sides_of_previous":
        return family, None, None, i
    if family == "row":
        return family, None, "row", i
    if i < len(words) and words[i] in PRONOUNS:
        return family, None, None, i + 1
    skipped = 0
    while i < len(words):
        word = words[i]
        if i in ends:
            return family, i, None, ends[i]
        if word in PLACE_WORDS:
            place = PLACE_WORDS[word]
            end = i + 1
            if place == "middle" and words[end : end + 3] in (["of", "the", "room"],):
                end += 3
            return family, None, place, end
        if word in ARTICLES or word in {"back", "front", "far", "side", "long", "short", "main"}:
            i += 1
            continue
        if i in blocked or word in {",", ".", ";", "and", "with", "!", "?"}:
            return None
        skipped += 1
        if skipped > ADJECTIVES_SKIPPED:
            return None
        i += 1
    return None


def _previous(n: int, objects: Sequence[tuple[int, int]], words: Sequence[str]) -> int | None:
    """The object named before object ``n`` in the same sentence (what ``it`` refers to)."""
    if n == 0:
        return None
    start = objects[n][0]
    prev_end = objects[n - 1][1]
    if any(w in {".", ";", "!", "?"} for w in words[prev_end:start]):
        return None
    return n - 1


__all__ = ["RELATIONS", "RelationKind", "RelationRequest", "read_relations"]
