"""The evaluator's own vocabulary (``holomj/data/evaluation/vocabulary.json``), written by hand
and independent of the planner's knowledge base: annotation names and synonyms -> scene
categories, room-type names -> scene room types, the defining furniture per room type, colour,
material and shape words, and how things rest and are used (support, front access, window
dressings)."""

from __future__ import annotations

import json
from importlib import resources
from pathlib import Path
from typing import TYPE_CHECKING, Any

from holomj.evaluation.text import find_words, normalise, singular_forms, slug

if TYPE_CHECKING:
    from holomj.evaluation.objects import EvaluatedRoom


def default_vocabulary_file() -> Path:
    """The shipped vocabulary file."""
    return Path(str(resources.files("holomj.data").joinpath("evaluation/vocabulary.json")))


class Vocabulary:
    """The evaluator's mapping of annotation names to scene categories, room types and words."""

    def __init__(self, data: dict[str, Any]) -> None:
        self.data = data
        self.categories: dict[str, list[str]] = {}
        self.lookup: dict[str, str] = {}
        for canon, entry in data["names"].items():
            key = normalise(canon)
            self.categories[key] = list(entry.get("categories") or [slug(canon)])
            self.lookup[key] = key
            for syn in entry.get("synonyms", []):
                self.lookup.setdefault(normalise(syn), key)
        self.room_lookup: dict[str, str] = {}
        self.room_types: dict[str, list[str]] = {}
        for canon, entry in data["room_types"].items():
            key = normalise(canon)
            self.room_types[key] = [t.lower() for t in entry["types"]]
            self.room_lookup[key] = key
            for syn in entry.get("synonyms", []):
                self.room_lookup.setdefault(normalise(syn), key)
        self.defining: dict[str, list[dict[str, Any]]] = {
            normalise(k): v for k, v in data["defining"].items()
        }
        self.colors = {normalise(k): set(v) for k, v in data["colors"].items()}
        self.materials = {normalise(k): v for k, v in data["materials"].items()}
        self.shapes = {normalise(k): v for k, v in data["shapes"].items()}
        self.faces_away = {c.lower() for c in data.get("faces_away_from_front", [])}
        support = data.get("support", {})
        self.floor_furniture = {c.lower() for c in support.get("floor_furniture", [])}
        self.wall_mounted = {c.lower() for c in support.get("wall_mounted", [])}
        self.ceiling_mounted = {c.lower() for c in support.get("ceiling_mounted", [])}
        self.floor_like = {c.lower() for c in support.get("floor_like", [])}
        self.front_access = {c.lower() for c in data.get("front_access", [])}
        self.window_dressing = {c.lower() for c in data.get("window_dressing", [])}
        self.pull_out_seats = {c.lower() for c in data.get("pull_out_seats", [])}

    @classmethod
    def load(cls, path: Path | None = None) -> Vocabulary:
        """Read a vocabulary file (default: the shipped one)."""
        return cls(json.loads(Path(path or default_vocabulary_file()).read_text()))

    def canonical(self, name: str) -> str | None:
        """The vocabulary entry ``name`` (or a singular form of it) belongs to, if any."""
        return _looked_up(self.lookup, name)

    def resolve(self, name: str) -> set[str]:
        """The scene categories that count as ``name``."""
        canon = self.canonical(name)
        if canon is not None:
            return set(self.categories[canon])
        key = normalise(name)
        return {slug(key)} | {slug(form) for form in singular_forms(key)}

    def room_canonical(self, name: str) -> str | None:
        """The canonical room type of an annotation's room name, if the vocabulary knows it."""
        return _looked_up(self.room_lookup, name)

    def room_type_of(self, room: EvaluatedRoom) -> str | None:
        """The first canonical room type of a scene room: by its ``type``, else its id's stem."""
        for value in (room.type, room.stem):
            if not value:
                continue
            for canon, types in self.room_types.items():
                if value.lower() in types:
                    return canon
        return None

    def room_is(self, room: EvaluatedRoom, canon: str) -> bool:
        """Whether a scene room counts as the canonical room type ``canon``."""
        types = self.room_types.get(canon, [canon.replace(" ", "_")])
        return any(v and v.lower() in types for v in (room.type, room.stem))

    def colour_words(self, text: str) -> set[str]:
        """Colour families named in ``text`` (longest words first, each word used once)."""
        return {fam for word in find_words(text, self.colors) for fam in self.colors[word]}

    def material_words(self, text: str) -> set[str]:
        """Material families named in ``text``."""
        return {self.materials[w] for w in find_words(text, self.materials)}


def _looked_up(lookup: dict[str, str], name: str) -> str | None:
    """The entry of ``lookup`` that ``name`` (normalised), or a singular form of it, names."""
    key = normalise(name)
    for cand in [key, *singular_forms(key)]:
        if cand in lookup:
            return lookup[cand]
    return None
