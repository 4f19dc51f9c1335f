"""The offline planner's knowledge base: scene types, room templates, objects, styles, materials.

The knowledge is data, in ``holomj/data/knowledge/*.json``; this module loads it, its schema is
:mod:`holomj.plan.knowledge_schema` and the checks that its parts agree
:mod:`holomj.plan.knowledge_checks`:

* ``objects.json``: object kinds (plan names such as ``"dining chair"``) with a category (the
  default library's, else a new one equal to the kind's name in snake_case), a size (width,
  depth, height in metres, within sane ranges for its placement), optional small/large sizes,
  placement (floor, wall, ceiling, or ``object`` for small objects that go on receptacles), the
  words that name them in a prompt, whether small objects go on it (``receptacle``), the room
  templates it belongs in (``rooms``) and default layout constraints; ``generics``
  (``"chair"``: the kinds it may mean) and ``refused`` (things the planner never plans, and
  why).
* ``rooms.json``: room templates: floor-plan type, typical area, materials, the objects with
  quantity ranges, probabilities, priorities and what goes on top of them, layout constraints
  (the layout language's text form over object kind names), alternative object sets
  (``variants``) and the ``defining`` kinds that make the room what it is (never dropped).
* ``scene_types.json``: scene types (residential and commercial) with a description, keywords,
  their rooms (count ranges, adjacency wishes) and entrance; ``limits`` (what a room may hold).
* ``styles.json``: style words with materials and wall heights; material words (``oak``,
  ``white``, ``brick``) and how each surface describes them.
* ``receptacles.json`` (optional): small-object lists for receptacles that the shared table
  ``holomj/data/small_objects_on_receptacles.json`` lacks (that table wins where it has an
  entry): the new receptacle categories and ``room type:category`` keys of new room types.

:func:`knowledge_base` returns the shipped knowledge (cached); :func:`load_knowledge` reads any
folder of the same files. A broken file raises :class:`~holomj.errors.SpecError` naming the file
and the entry.
"""

from __future__ import annotations

import functools
from collections.abc import Mapping
from importlib import resources
from pathlib import Path
from typing import TYPE_CHECKING, Any

from holomj.errors import SpecError
from holomj.layout.proposals import default_catalogue
from holomj.plan.knowledge_checks import check_knowledge
from holomj.plan.knowledge_schema import (
    KnowledgeBase,
    ObjectsFile,
    RoomsFile,
    ScenesFile,
    StylesFile,
)
from holomj.spec.base import parse_json, validate_model

if TYPE_CHECKING:
    from importlib.abc import Traversable

KNOWLEDGE_FILES = ("objects.json", "rooms.json", "scene_types.json", "styles.json")
RECEPTACLES_FILE = "receptacles.json"


@functools.cache
def knowledge_base() -> KnowledgeBase:
    """The shipped knowledge base (``holomj/data/knowledge``), loaded and checked once."""
    return load_knowledge(resources.files("holomj.data").joinpath("knowledge"))


def load_knowledge(folder: Path | Traversable) -> KnowledgeBase:
    """Load and check the knowledge files of ``folder`` (a SpecError names file and entry)."""
    texts = {}
    for name in (*KNOWLEDGE_FILES, RECEPTACLES_FILE):
        entry = folder.joinpath(name)
        if not entry.is_file():
            if name == RECEPTACLES_FILE:
                continue
            raise SpecError("knowledge file missing", where=f"{folder}/{name}")
        texts[name] = entry.read_text(encoding="utf-8")
    objects = validate_model(ObjectsFile, _data(texts, "objects.json"), "objects.json")
    rooms = validate_model(RoomsFile, _data(texts, "rooms.json"), "rooms.json")
    scenes = validate_model(ScenesFile, _data(texts, "scene_types.json"), "scene_types.json")
    styles = validate_model(StylesFile, _data(texts, "styles.json"), "styles.json")
    receptacles = default_catalogue()
    if RECEPTACLES_FILE in texts:
        from holomj.layout.proposals import parse_catalogue

        extra = parse_catalogue(
            parse_json(texts[RECEPTACLES_FILE], RECEPTACLES_FILE), RECEPTACLES_FILE
        )
        for key, items in extra.items():
            receptacles.setdefault(key, list(items))
    kb = KnowledgeBase(
        objects=objects.objects,
        generics=objects.generics,
        refused=objects.refused,
        rooms=rooms.rooms,
        scene_types=scenes.scene_types,
        limits=scenes.limits,
        styles=styles.styles,
        materials=styles.materials,
        modifiers=styles.modifiers,
        surfaces=styles.surfaces,
        receptacles={k: [(c, float(w)) for c, w in v] for k, v in receptacles.items()},
    )
    check_knowledge(kb)
    return kb


def _data(texts: Mapping[str, str], name: str) -> Any:
    data = parse_json(texts[name], name)
    if isinstance(data, dict):
        data = {k: v for k, v in data.items() if not k.startswith("_")}
    return data
