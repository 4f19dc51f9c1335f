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

Modules: :mod:`~holomj.plan.prompt_words` (tokens, numbers, word lists),
:mod:`~holomj.plan.prompt_index` (the phrase index), :mod:`~holomj.plan.prompt_reader` (parse
state, phrase matching, modifiers), :mod:`~holomj.plan.prompt_sizes`,
:mod:`~holomj.plan.prompt_materials` and :mod:`~holomj.plan.prompt_clauses`; this module holds
the result types and puts the parse together.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Literal

from pydantic import Field

from holomj.plan.knowledge_schema import KnowledgeBase
from holomj.plan.prompt_clauses import (
    find_refinements,
    first_size_word,
    head_text,
    negation_scopes,
    read_capacity,
    scene_mention,
    unknown_phrases,
    with_scopes,
)
from holomj.plan.prompt_index import PhraseIndex, phrase_index
from holomj.plan.prompt_materials import lone_materials, read_materials
from holomj.plan.prompt_parts import part_after
from holomj.plan.prompt_reader import Mention, Mods, Reader, match_phrases, read_modifiers
from holomj.plan.prompt_relations import RelationRequest, read_relations
from holomj.plan.prompt_sizes import SizeRead, read_sizes
from holomj.plan.prompt_words import (
    HEAD_END,
    MANY,
    NEG,
    WITH_START,
    is_number,
    normalise_words,
    plural_forms,
    tokenize,
)
from holomj.spec.base import FrozenModel

Surface = Literal["floor", "wall", "ceiling"]


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
    parts: list[str] = Field(
        default_factory=list, description="Parts asked of it: 'brass handles', 'a red seat'."
    )
    each_room: bool = Field(
        default=False,
        description="Asked for every room of that template: 'two bedrooms each with a bunk bed'.",
    )
    excluded: bool = False
    definite: bool = Field(
        default=False, description="Named with 'the' and no number: maybe a reference."
    )
    phrase: str


class RoomMention(FrozenModel):
    """A room named in the prompt (besides the scene itself): template, count, size."""

    template: str
    count: int | None = None
    size_word: str | None = None
    dims: tuple[float, float] | None = None
    area_m2: float | None = None
    excluded: bool = False
    zone: bool = Field(
        default=False, description="Named as a part of a room: 'a reading corner', 'a play area'."
    )
    location: bool = Field(
        default=False,
        description="Where the scene itself is: 'a home gym in the garage' (not another room).",
    )
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
    relations: list[RelationRequest] = Field(
        default_factory=list, description="Where the prompt puts its objects."
    )
    refused: list[RefusedRequest] = Field(default_factory=list)
    unknown: list[str] = Field(default_factory=list)
    capacity: int | None = None
    windows: int | None = None
    notes: list[str] = Field(default_factory=list)


def parse_prompt(text: str, kb: KnowledgeBase) -> ParsedPrompt:
    """Read a prompt into a :class:`ParsedPrompt` (no model, no randomness)."""
    reader = Reader(normalise_words(tokenize(text)), phrase_index(kb), kb)
    sizes = read_sizes(reader)
    materials = read_materials(reader)
    match_phrases(reader)
    materials.update(lone_materials(reader, materials))
    head_end = next((i for i, w in enumerate(reader.words) if w in HEAD_END), len(reader.words))
    scene = scene_mention(reader, head_end)
    found = _read_mentions(reader, scene, sizes)
    _attach_parts(reader, found)
    scene_sizes = sizes.pop(-1, None)
    for start in sorted(sizes):  # sizes next to no room phrase: they describe the scene
        scene_sizes = scene_sizes or sizes[start]
    size_word = read_modifiers(reader, scene.start).size_word if scene is not None else None
    scene_meaning = scene.meaning("scene") if scene is not None else None
    return ParsedPrompt(
        text=text,
        head=head_text(reader, head_end),
        scene=scene_meaning.key if scene_meaning is not None else None,
        scene_keyword=reader.text(scene.start, scene.end) if scene is not None else None,
        refinements=find_refinements(reader),
        size_word=size_word or first_size_word(reader, head_end),
        dims=scene_sizes.dims if scene_sizes is not None else None,
        area_m2=scene_sizes.area_m2 if scene_sizes is not None else None,
        wall_height_m=reader.heights[0] if reader.heights else None,
        rooms=found.rooms,
        styles=found.styles,
        materials=materials,
        objects=found.objects,
        relations=read_relations(
            reader.words,
            found.spans,
            [(m.start, m.end) for m in reader.mentions if m.meaning("room") or m.meaning("scene")],
        ),
        refused=found.refused,
        unknown=unknown_phrases(reader, with_scopes(reader.words)),
        capacity=read_capacity(reader.words),
        windows=found.windows,
        notes=reader.notes,
    )


@dataclass
class _PromptMentions:
    """What the phrases of a prompt name, apart from the scene."""

    rooms: list[RoomMention] = field(default_factory=list)
    objects: list[ObjectRequest] = field(default_factory=list)
    spans: list[tuple[int, int]] = field(default_factory=list)  # words of each object
    refused: list[RefusedRequest] = field(default_factory=list)
    styles: list[str] = field(default_factory=list)
    windows: int | None = None


def _read_mentions(
    reader: Reader, scene: Mention | None, sizes: dict[int, SizeRead]
) -> _PromptMentions:
    """Rooms, objects, refused things, styles and windows, with their quantities."""
    found = _PromptMentions()
    neg_scopes = negation_scopes(reader.words)
    context: str | None = None  # template of the room whose "with ..." list this is
    last_end = 0
    head: Mention | None = None  # the first room or scene named: what the prompt is about
    each_room = False  # the room list is "each with ...": its objects go to every such room
    starts = {m.start: m for m in reader.mentions}
    attributive: list[str] = []  # "an orange sofa": a noun right before an object's noun
    for mention in reader.mentions:
        if any(w in {".", ";", "!", "?"} for w in reader.words[last_end : mention.start]):
            context = None  # a new sentence
        following = starts.get(mention.end)
        if _object_of(mention) and following is not None and _object_of(following):
            attributive.extend(reader.words[mention.start : mention.end])
            continue
        located = head is not None and _located_in(reader, head, mention)
        last_end = mention.end
        if head is None and (mention is scene or mention.meaning("room") is not None):
            head = mention
        if mention is scene:
            context = None
            continue
        mods = read_modifiers(reader, mention.start)
        excluded = mods.negated or any(a <= mention.start < b for a, b in neg_scopes)
        phrase = reader.text(mods.start, mention.end)
        room = mention.meaning("room")
        thing = mention.meaning("object") or mention.meaning("generic")
        refusal = mention.meaning("refused")
        style = mention.meaning("style")
        if room is not None:
            room_size = sizes.pop(mention.start, SizeRead())
            found.rooms.append(
                RoomMention(
                    template=room.key,
                    count=0 if excluded else (mods.count if mods.counted else None),
                    size_word=mods.size_word,
                    excluded=excluded,
                    zone=reader.words[mention.end - 1] in ZONE_WORDS,
                    location=located,
                    phrase=phrase,
                    dims=room_size.dims,
                    area_m2=room_size.area_m2,
                )
            )
            follows = reader.words[mention.end : mention.end + 2]
            each_room = bool(follows[:1] == ["each"] and follows[1:] and follows[1] in WITH_START)
            starts_list = follows[:1] and follows[0] in WITH_START | {"where"}
            context = (
                room.key if starts_list or each_room or _one_of_them(reader, mention) else None
            )
        elif thing is not None and _is_part_of_previous(reader, found, mention):
            continue  # "a chair with a red seat": the chair's seat (kept by _attach_parts)
        elif thing is not None:
            found.objects.append(
                ObjectRequest(
                    kind=thing.key,
                    generic=thing.kind == "generic",
                    quantity=_per_each(
                        reader,
                        mods.start,
                        mention.end,
                        _pair_count(reader, mention, mods),
                        found.objects,
                    ),
                    many=mods.many,
                    plural=thing.plural,
                    size=_size_class(mods.size_word, reader.index),
                    adjectives=[*attributive, *mods.adjectives],
                    room=context,
                    each_room=bool(context and each_room),
                    excluded=excluded,
                    definite=not mods.counted and reader.words[mods.start] in REFERRING_WORDS,
                    phrase=phrase,
                )
            )
            found.spans.append((mention.start, mention.end))
            attributive = []
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


# Words before an object phrase that refer to objects already named ("the bed", "each crib").
REFERRING_WORDS = frozenset({"the", "each", "every"})
# The last word of a room phrase that names a part of a room rather than a room.
ZONE_WORDS = frozenset({"corner", "nook", "area", "zone", "space", "station"})
LOCATION_WORDS = (("in", "the"), ("in", "a"), ("in", "an"), ("inside", "the"), ("inside", "a"))


def _located_in(reader: Reader, head: Mention, mention: Mention) -> bool:
    """Whether ``mention`` says where the head is: "a home gym in the garage" (the words between
    are only ``in the``)."""
    between = tuple(reader.words[head.end : mention.start])
    return between in LOCATION_WORDS


def _object_of(mention: Mention) -> bool:
    """Whether a phrase names an object (a known kind or a generic word)."""
    return mention.meaning("object") is not None or mention.meaning("generic") is not None


def _is_part_of_previous(reader: Reader, found: _PromptMentions, mention: Mention) -> bool:
    """Whether an object phrase names a part of the object before it ("with a red seat")."""
    if not found.spans:
        return False
    part = part_after(reader.words, found.spans[-1][1])
    return part is not None and part[0] <= mention.start and mention.end == part[1]


def _attach_parts(reader: Reader, found: _PromptMentions) -> None:
    """Part phrases after each object ("cabinets with brass handles") kept with the object, and
    their words taken out of the unknown-noun search."""
    for n, (_, end) in enumerate(found.spans):
        part = part_after(reader.words, end)
        if part is None or any(start < part[1] and e > part[0] for start, e in found.spans):
            continue
        obj = found.objects[n]
        found.objects[n] = obj.model_copy(update={"parts": [*obj.parts, reader.text(*part)]})
        for k in range(*part):
            reader.used[k] = True


def _one_of_them(reader: Reader, room: Mention) -> bool:
    """``two bedrooms, one with twin beds``: the list after the rooms is one room's."""
    follows = [w for w in reader.words[room.end : room.end + 4] if w != ","]
    return follows[:1] in (["one"], ["1"]) and follows[1:2] in (["with"], ["has"], ["having"])


PAIR_WORDS = frozenset({"twin", "matching"})  # "twin beds", "matching armchairs": a pair


def _pair_count(reader: Reader, mention: Mention, mods: Mods) -> int | None:
    """The count a thing is asked in: as given, else two for ``twin beds``."""
    if mods.counted:
        return mods.count
    words = reader.words[mods.start : mention.end]
    plural = reader.words[mention.end - 1].endswith("s")
    return 2 if plural and any(w in PAIR_WORDS for w in words) else mods.count


def _per_each(
    reader: Reader, start: int, end: int, count: int | None, before: list[ObjectRequest]
) -> int | None:
    """``eight tables, each with four chairs`` or ``eight tables with four chairs each``: four
    per table, 32 chairs."""
    lead = [w for w in reader.words[max(start - 3, 0) : start] if w != ","]
    each_with = lead[-2:] in (["each", "with"], ["each", "having"])
    with_each = bool(lead) and lead[-1] in {"with", "having"} and end < len(reader.words)
    with_each = with_each and reader.words[end] in {"each", "apiece", "per"}
    if not (each_with or with_each) or not before:
        return count
    per = before[-1].quantity
    if per is None or before[-1].excluded:
        return count
    return min((count or 1) * per, 10_000)


def _size_class(word: str | None, index: PhraseIndex) -> Literal["small", "large"] | None:
    if word is None:
        return None
    factor = index.size_words.get(word, 1.0)
    if factor < 1.0:
        return "small"
    if factor > 1.0:
        return "large"
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
