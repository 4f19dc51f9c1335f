"""Category names, written one way: how a category's name is compared, its other names and its
typical size.

- :func:`normalise_category` is the one name normalisation of categories (and of the other
  tables keyed by name, materials included): the library, retrieval, the importers, the
  procedural registries and the physical table all compare names through it.
- ``holomj/data/category_facts.json`` holds, per name the library may not hold (ProcTHOR
  object types, plurals, near-synonyms), the categories that may stand in for it
  (:func:`category_aliases`, best first) and its typical size (:func:`category_sizes`, in the
  asset axes: x = depth, y = width, z = height).
- Receptacle roles (which categories small objects go on, and which small categories, with
  weights) are read here and nowhere else: :func:`parse_receptacle_table` checks a table,
  :func:`receptacle_file_table` reads one shipped file (``small_objects_on_receptacles.json``,
  the table layout draws from; ``knowledge/receptacles.json``, the planner's additions) and
  :func:`receptacle_table` merges the two (the shared table wins), for whoever asks "is X a
  receptacle, and of what" (the planner's knowledge base, populate's fallback priors).
- :func:`knowledge_kinds` reads the planner's object kinds (``knowledge/objects.json``) as
  category facts (category, typical size in the asset axes, placement, the words naming it)
  for the readers outside the planner (the importers' name hints, retrieval's synonyms).

Sizes, one convention: every size holomj stores (an asset's, a generator's, these tables',
the planner's ``holomj/data/knowledge/objects.json`` as ``[depth, width, height]`` arrays) is
in the asset axes, x = depth (front to back, the front faces +x), y = width, z = height,
metres; ``category_facts.json`` names its axes (``width``/``depth``/``height`` keys). Only a
plan (``holomj.spec.plan``, the edit language and the planner's in-memory object kinds) speaks
(width, depth, height). :func:`asset_axes` and :func:`plan_axes` are the only conversions
between the two: the planner's knowledge loader turns ``objects.json`` into plan sizes with
:func:`plan_axes`, retrieval turns a plan size into the asset axes with :func:`asset_axes`.
"""

from __future__ import annotations

import functools
import json
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from importlib import resources
from typing import Any

from holomj.errors import SpecError

Size = tuple[float, float, float]
FACTS_FILE = "category_facts.json"
SHARED_RECEPTACLES_FILE = "small_objects_on_receptacles.json"
KNOWLEDGE_RECEPTACLES_FILE = "knowledge/receptacles.json"
KNOWLEDGE_OBJECTS_FILE = "knowledge/objects.json"
ReceptacleTable = dict[str, tuple[tuple[str, float], ...]]


def normalise_category(category: str) -> str:
    """``Dining Table``, ``dining-table`` and ``DiningTable`` all become ``diningtable``."""
    return "".join(ch for ch in category.lower() if ch.isalnum())


def asset_axes(plan_size: Size) -> Size:
    """A plan size (width, depth, height) in the asset axes (x = depth, y = width, z)."""
    width, depth, height = plan_size
    return (depth, width, height)


def plan_axes(asset_size: Size) -> Size:
    """An asset size (x = depth, y = width, z) as a plan size (width, depth, height)."""
    depth, width, height = asset_size
    return (width, depth, height)


@functools.cache
def _facts() -> dict[str, dict[str, Any]]:
    """``category_facts.json`` by normalised name, without its ``_comment``."""
    text = resources.files("holomj.data").joinpath(FACTS_FILE).read_text(encoding="utf-8")
    table: dict[str, Any] = json.loads(text)
    return {normalise_category(k): v for k, v in table.items() if not k.startswith("_")}


@functools.cache
def category_aliases() -> dict[str, list[str]]:
    """Normalised name -> categories that may stand in for it, best first."""
    return {k: list(v["stand_ins"]) for k, v in _facts().items() if "stand_ins" in v}


@functools.cache
def category_sizes() -> dict[str, Size]:
    """Typical sizes (x = depth, y = width, z = height, metres) by normalised name."""
    return {
        k: asset_axes((float(s["width"]), float(s["depth"]), float(s["height"])))
        for k, v in _facts().items()
        if (s := v.get("size")) is not None
    }


def category_size(category: str) -> Size | None:
    """The typical size of a category (asset axes), if the table knows it."""
    return category_sizes().get(normalise_category(category))


def normal_type(room_type: str) -> str:
    """``"Living Room"`` -> ``"living_room"``: the form room types and the receptacle tables'
    keys take."""
    return "_".join(room_type.strip().lower().replace("-", " ").split())


def parse_receptacle_table(data: object, source: str = "catalogue") -> ReceptacleTable:
    """A receptacle table read from JSON, checked: receptacle category (or ``"<room
    type>:<receptacle category>"``) -> ((small object category, weight >= 0), ...); keys starting
    with ``_`` are comments. A SpecError names the entry that is wrong."""
    if not isinstance(data, Mapping):
        raise SpecError("a catalogue is an object of receptacle -> list", where=source)
    out: ReceptacleTable = {}
    for key, items in data.items():
        if str(key).startswith("_"):
            continue
        where = f"{source}: {key}"
        if not isinstance(items, Sequence) or isinstance(items, str):
            raise SpecError("expected a list of [category, weight] pairs", where=where)
        parsed = []
        for i, item in enumerate(items):
            ok = (
                isinstance(item, Sequence)
                and not isinstance(item, str)
                and len(item) == 2
                and isinstance(item[0], str)
                and isinstance(item[1], int | float)
                and not isinstance(item[1], bool)
                and math.isfinite(item[1])
                and item[1] >= 0
            )
            if not ok:
                raise SpecError(
                    "expected [category, weight >= 0]",
                    where=f"{where}[{i}]",
                    fix='e.g. ["book", 2]',
                )
            parsed.append((item[0], float(item[1])))
        out[receptacle_key(str(key))] = tuple(parsed)
    return out


def receptacle_key(name: str) -> str:
    """A receptacle table's key in its normal form (``"Living Room:coffee-table"`` ->
    ``"living_room:coffee_table"``)."""
    if ":" in name:
        room, _, rec = name.partition(":")
        return f"{normal_type(room)}:{normal_type(rec)}"
    return normal_type(name)


@functools.cache
def receptacle_file_table(name: str) -> ReceptacleTable:
    """One shipped receptacle table (a path under ``holomj/data``), checked."""
    text = resources.files("holomj.data").joinpath(name).read_text(encoding="utf-8")
    return parse_receptacle_table(json.loads(text), name)


@functools.cache
def receptacle_table() -> ReceptacleTable:
    """The shipped receptacle roles: the shared table, then the planner's own entries for the
    receptacles (and room-type keys) it lacks."""
    table = dict(receptacle_file_table(SHARED_RECEPTACLES_FILE))
    for key, items in receptacle_file_table(KNOWLEDGE_RECEPTACLES_FILE).items():
        table.setdefault(key, items)
    return table


@dataclass(frozen=True)
class KnownKind:
    """A kind of the knowledge base: its library category, typical size (asset axes) and
    placement, and (``name``, ``aliases``) the words that name it."""

    category: str
    size: Size | None
    placement: str
    name: str = field(default="", compare=False)
    aliases: tuple[str, ...] = field(default=(), compare=False)


@functools.cache
def knowledge_kinds() -> tuple[KnownKind, ...]:
    """The planner's object kinds (``knowledge/objects.json``), in file order, as category
    facts; sizes stay in the file's asset axes."""
    text = resources.files("holomj.data").joinpath(KNOWLEDGE_OBJECTS_FILE).read_text("utf-8")
    kinds = []
    for name, entry in json.loads(text).get("objects", {}).items():
        raw = entry.get("size")
        size = (float(raw[0]), float(raw[1]), float(raw[2])) if raw and len(raw) == 3 else None
        placement = str(entry.get("placement", "floor"))
        aliases = tuple(entry.get("aliases", []))
        kinds.append(KnownKind(entry["category"], size, placement, name, aliases))
    return tuple(kinds)
