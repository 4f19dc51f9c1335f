"""What a Holodeck house says about its own objects, beyond the ProcTHOR fields.

Holodeck names most objects by Objaverse uid, whose meshes and sizes a user rarely has. The
house itself still says what each object is and how big it was meant to be:

* ``object_selection_plan[room][name]``: the object's ``size`` in centimetres (width, depth,
  height) as the planner asked for it, and its ``location`` (``floor`` or ``wall``);
* ``wall_objects`` / ``selected_objects[room]["wall"]``: which objects hang on a wall;
* ``receptacle2small_objects[receptacle id]``: ``[name, asset, extent]`` for each small object,
  ``extent`` its largest side in metres;
* the object's own name (``object_name``, or the id's first part: ``"books-0|coffee table-0
  (living room)"`` -> ``books``).

:func:`category_for_name` turns a name into a category of the asset library with the
knowledge base's names and aliases of each kind (``holomj/data/knowledge/objects.json``, the
words the planner and retrieval use): ``"media unit"`` -> ``tv_stand``, ``"floor lamp"`` ->
``floor_lamp``, ``"small decorative box"`` -> ``box`` (leading words dropped until a name is
known), ``"books"`` -> ``book`` (plurals). Nothing here invents a vocabulary of its own.
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from dataclasses import dataclass, field
from functools import cache
from typing import Any

from holomj.spec.categories import KnownKind, knowledge_kinds, normalise_category

Size = tuple[float, float, float]  # x = depth, y = width, z = height, metres

_INSTANCE = re.compile(r"-\d+$")  # "sofa-0" -> "sofa"
_HEAD_OF = re.compile(r"\s+(with|of|for|on)\s+.*$")  # "vase with flowers" -> "vase"
_ROOM_SUFFIX = re.compile(r"\s*\([^)]*\)\s*$")  # "sofa-0 (living room)" -> "sofa-0"
_MIN_EXTENT_M = 0.01
_MAX_SMALL_EXTENT_M = 3.0


def base_name(text: str) -> str:
    """``"sofa-0 (living room)"``, ``"sofa-0"`` -> ``"sofa"``; ``"books-1|table-0 (x)"`` ->
    ``"books"``."""
    first = text.split("|", 1)[0]
    return _INSTANCE.sub("", _ROOM_SUFFIX.sub("", first)).strip().lower()


@cache
def _knowledge_names() -> dict[str, KnownKind]:
    """Normalised name or alias -> its kind, from the knowledge base's object kinds."""
    kinds: dict[str, KnownKind] = {}
    for kind in knowledge_kinds():
        for word in (kind.name, kind.category, *kind.aliases):
            kinds.setdefault(normalise_category(word), kind)
    return kinds


def _singulars(word: str) -> Iterable[str]:
    yield word
    if word.endswith("ies"):
        yield word[:-3] + "y"
    if word.endswith("es"):
        yield word[:-2]
    if word.endswith("s"):
        yield word[:-1]


def category_for_name(name: str, categories: Iterable[str]) -> KnownKind | None:
    """The library category ``name`` speaks of (see the module notes), or None. The head of a
    phrase goes first (``"vase with flowers"`` is a vase).

    ``categories``: the library's categories; a knowledge-base kind counts only when the
    library has assets of its category, a library category named outright always counts."""
    names = list(categories)
    head = _HEAD_OF.sub("", name)
    found = _category_for(head, names) if head != name else None
    return found or _category_for(name, names)


def _category_for(name: str, categories: list[str]) -> KnownKind | None:
    library = {normalise_category(c): c for c in categories}
    known = _knowledge_names()
    words = [w for w in re.split(r"[^a-z0-9]+", name.lower()) if w]
    runs = [words[start:] for start in range(len(words))]
    runs += [words[:end] for end in range(len(words) - 1, 0, -1)]
    for tail in runs:
        for last in _singulars(tail[-1]):
            key = normalise_category("".join([*tail[:-1], last]))
            if key in library:
                kind = known.get(key)
                return KnownKind(library[key], kind.size if kind else None, _placement(kind))
            kind = known.get(key)
            if kind is not None and normalise_category(kind.category) in library:
                return kind
    return None


def _placement(kind: KnownKind | None) -> str:
    return kind.placement if kind is not None else "floor"


@dataclass
class HolodeckHints:
    """The house's own words about its objects (see the module notes)."""

    plan_sizes: dict[tuple[str, str], Size] = field(default_factory=dict)
    wall: set[str] = field(default_factory=set)  # base names (per room) of wall objects
    extents: dict[tuple[str, str], float] = field(default_factory=dict)

    @classmethod
    def read(cls, data: dict[str, Any]) -> HolodeckHints:
        """Hints from a Holodeck house dict; anything malformed is simply not a hint."""
        hints = cls()
        plan = data.get("object_selection_plan")
        for room, objects in plan.items() if isinstance(plan, dict) else ():
            for name, entry in objects.items() if isinstance(objects, dict) else ():
                name = str(name)
                if not isinstance(entry, dict):
                    continue
                size = _cm_size(entry.get("size"))
                if size is not None:
                    hints.plan_sizes[(str(room).lower(), name.lower())] = size
                if entry.get("location") == "wall":
                    hints.wall.add(f"{str(room).lower()}/{name.lower()}")
        walls = data.get("wall_objects")
        for item in walls if isinstance(walls, list) else ():
            if isinstance(item, dict) and isinstance(item.get("id"), str):
                hints.wall.add(f"{_room_of(item)}/{base_name(item['id'])}")
        smalls = data.get("receptacle2small_objects")
        for receptacle, rows in smalls.items() if isinstance(smalls, dict) else ():
            for row in rows if isinstance(rows, list) else ():
                if isinstance(row, list) and len(row) >= 3 and isinstance(row[2], int | float):
                    extent = min(max(float(row[2]), _MIN_EXTENT_M), _MAX_SMALL_EXTENT_M)
                    hints.extents[(str(receptacle), str(row[0]))] = extent
        return hints

    def plan_size(self, room: str | None, name: str) -> Size | None:
        """The planned size of ``name`` in ``room`` (any room when it is not known)."""
        if room is not None and (room.lower(), name) in self.plan_sizes:
            return self.plan_sizes[(room.lower(), name)]
        sizes = [s for (_, n), s in self.plan_sizes.items() if n == name]
        return sizes[0] if sizes else None

    def on_wall(self, room: str | None, name: str) -> bool:
        """Whether the house hangs ``name`` (in ``room``) on a wall."""
        return f"{(room or '').lower()}/{name}" in self.wall or any(
            w.endswith(f"/{name}") for w in self.wall if room is None
        )

    def small_extent(self, raw_id: str) -> float | None:
        """The largest side of a small object ``"<name>-N|<receptacle id>"``, if listed."""
        if "|" not in raw_id:
            return None
        name, receptacle = raw_id.split("|", 1)
        return self.extents.get((receptacle, name))


def _room_of(item: dict[str, Any]) -> str:
    room = item.get("roomId")
    if isinstance(room, str):
        return room.lower()
    found = re.search(r"\(([^)]*)\)\s*$", item.get("id", ""))
    return found.group(1).lower() if found else ""


def _cm_size(raw: Any) -> Size | None:
    """Holodeck's ``[width, depth, height]`` in cm -> ``(depth, width, height)`` in metres."""
    if not isinstance(raw, list) or len(raw) != 3:
        return None
    if not all(isinstance(v, int | float) and 0 < v < 10_000 for v in raw):
        return None
    width, depth, height = (max(float(v) / 100.0, _MIN_EXTENT_M) for v in raw)
    return (depth, width, height)


def scaled_to_extent(size: Size, extent: float) -> Size:
    """``size`` scaled uniformly so that its largest side is ``extent``."""
    factor = extent / max(size)
    return (size[0] * factor, size[1] * factor, size[2] * factor)
