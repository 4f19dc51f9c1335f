"""The phrase index: every phrase the knowledge base knows, as word tuples, and what it names.

Scene keywords, room aliases, object names and aliases (with derived plurals), generic words,
refused things, style words and ``window``; material aliases, surface words, modifiers, size
words and scene refine words. Built once per knowledge base object.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from holomj.plan.knowledge_schema import KnowledgeBase
from holomj.plan.prompt_words import plural_forms, tokenize


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
        # an alias that is the plural of another (``bookshelves``) is read as a plural
        forms = {tuple(tokenize(f)) for p in phrases for f in plural_forms(p)} if plurals else set()
        for phrase in phrases:
            words = tuple(tokenize(phrase))
            _add_meaning(explicit, words, Meaning(kind, key, plural=words in forms))
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
    surfaces: dict[str, str] = {
        word: surface for surface, words in kb.surfaces.items() for word in words
    }
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
