"""The offline planner's knowledge base: scene types, room templates, objects, styles, materials.

The knowledge is data, in ``holomj/data/knowledge/*.json``; this module only defines its schema,
loads it and checks that its parts agree:

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
from collections.abc import Iterable, Mapping
from importlib import resources
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any, Literal

from pydantic import Field, model_validator

from holomj.errors import SpecError, closest_names
from holomj.layout.constraints import parse_constraint_text
from holomj.layout.floorplan import normal_type
from holomj.layout.proposals import default_catalogue
from holomj.spec.base import FrozenModel, Identifier, parse_json, validate_model
from holomj.spec.plan import ObjectName, Size3

if TYPE_CHECKING:
    from importlib.abc import Traversable

KNOWLEDGE_FILES = ("objects.json", "rooms.json", "scene_types.json", "styles.json")
RECEPTACLES_FILE = "receptacles.json"

Phrase = Annotated[str, Field(min_length=1, max_length=64, pattern=r"^[a-z0-9]+( [a-z0-9]+)*$")]
Count = Annotated[int, Field(ge=0, le=40)]
Probability = Annotated[float, Field(ge=0.0, le=1.0)]
Area = Annotated[float, Field(ge=1.0, le=400.0)]
Height = Annotated[float, Field(ge=2.2, le=6.0)]
MaterialText = Annotated[str, Field(min_length=1, max_length=200)]
Category = Annotated[str, Field(min_length=1, max_length=64, pattern=r"^[a-z0-9]+(_[a-z0-9]+)*$")]
Placement = Literal["floor", "wall", "ceiling", "object"]

# Sane (width, depth, height) ranges in metres, per placement: sizes outside are data errors.
SIZE_RANGES: dict[str, tuple[tuple[float, float], tuple[float, float], tuple[float, float]]] = {
    "floor": ((0.1, 6.0), (0.05, 6.0), (0.01, 4.0)),
    "wall": ((0.05, 5.0), (0.01, 1.0), (0.05, 3.0)),
    "ceiling": ((0.05, 4.0), (0.05, 4.0), (0.02, 2.0)),
    "object": ((0.005, 1.0), (0.005, 1.0), (0.005, 1.0)),
}
MAX_FOOTPRINT_M2 = 16.0  # one floor object's width x depth
DEFINING_PRIORITY = 8  # the lowest priority a defining kind may have in its template


def _ordered_range(value: tuple[float, float], what: str) -> None:
    if value[0] > value[1]:
        raise ValueError(f"{what} range {list(value)} is not ordered low, high")


# ---------------------------------------------------------------------------------------------
# objects.json


class ObjectKind(FrozenModel):
    """A kind of object the planner knows: its category, size, names in prompts and rooms."""

    category: Category
    placement: Placement
    size: Size3 | None = Field(default=None, description="(width, depth, height) in metres.")
    small: Size3 | None = None
    large: Size3 | None = None
    aliases: list[Phrase] = Field(default_factory=list)
    description: str = Field(default="", max_length=300)
    many: Annotated[int, Field(ge=1, le=12)] = 4
    variance: Literal["same", "varied"] = Field(
        default="same", description="Same or varied instances when the prompt asks for several."
    )
    constraints: list[str] = Field(
        default_factory=list,
        description="Default layout lines over kind names, for rooms "
        "whose template says nothing about this kind.",
    )
    receptacle: bool = Field(
        description="Small objects go on it (its category has a receptacle table entry)."
    )
    rooms: list[Identifier] = Field(
        min_length=1, description="Room templates (rooms.json) this kind belongs in."
    )

    @model_validator(mode="after")
    def _check(self) -> ObjectKind:
        if self.placement != "object" and self.size is None:
            raise ValueError("floor, wall and ceiling objects need a size")
        if self.size is None and (self.small is not None or self.large is not None):
            raise ValueError("small and large sizes need a default size")
        if self.placement != "floor" and self.constraints:
            raise ValueError("only floor objects take layout constraints")
        if self.receptacle and self.placement != "floor":
            raise ValueError("only floor objects are receptacles")
        return self

    def size_for(self, word: str | None) -> tuple[float, float, float] | None:
        """The size for a size word (``"small"``, ``"large"``, else the default size)."""
        if word == "small" and self.small is not None:
            return self.small
        if word == "large" and self.large is not None:
            return self.large
        return self.size


class Generic(FrozenModel):
    """A word that may mean several kinds (``chair``): the first one the room has wins."""

    kinds: list[ObjectName] = Field(min_length=1)
    aliases: list[Phrase] = Field(min_length=1)


class Refused(FrozenModel):
    """Things the planner never plans, with the reason it gives."""

    aliases: list[Phrase] = Field(min_length=1)
    reason: str = Field(min_length=1, max_length=200)


class ObjectsFile(FrozenModel):
    """The contents of ``objects.json``."""

    objects: dict[ObjectName, ObjectKind]
    generics: dict[ObjectName, Generic] = Field(default_factory=dict)
    refused: dict[ObjectName, Refused] = Field(default_factory=dict)


# ---------------------------------------------------------------------------------------------
# rooms.json


class SmallItem(FrozenModel):
    """A small object a template puts on a receptacle (per instance of the receptacle)."""

    object: ObjectName
    quantity: tuple[Count, Count] = (1, 1)
    variance: Literal["same", "varied"] = "varied"
    probability: Probability = 1.0

    @model_validator(mode="after")
    def _check(self) -> SmallItem:
        _ordered_range(self.quantity, "quantity")
        return self


class TemplateObject(FrozenModel):
    """One object kind of a room template and how many of it a room gets."""

    object: ObjectName
    quantity: tuple[Count, Count] = (1, 1)
    probability: Probability = 1.0
    priority: Annotated[int, Field(ge=1, le=10)] = 5
    variance: Literal["same", "varied", "random"] = "same"
    size: Literal["small", "default", "large"] = "default"
    per: ObjectName | None = Field(
        default=None, description="Quantity counts per instance of this other object."
    )
    seat: bool = Field(default=False, description="Seats people ('for 8 people' sets these).")
    above: ObjectName | None = Field(default=None, description="Wall objects: hang above it.")
    on_top: list[SmallItem] | Literal["auto"] | None = None

    @model_validator(mode="after")
    def _check(self) -> TemplateObject:
        _ordered_range(self.quantity, "quantity")
        if self.per is not None and self.per == self.object:
            raise ValueError("an object cannot count per itself")
        return self


class RoomVariant(FrozenModel):
    """An alternative set of objects of a template (one variant is drawn per room)."""

    name: str = Field(min_length=1, max_length=64)
    weight: Annotated[float, Field(gt=0.0)] = 1.0
    objects: list[TemplateObject] = Field(default_factory=list)
    constraints: list[str] = Field(default_factory=list)


class RoomTemplate(FrozenModel):
    """A kind of room: floor-plan type, area, materials, furniture and its layout."""

    name: str = Field(min_length=1, max_length=64)
    type: str = Field(min_length=1, max_length=64)
    aliases: list[Phrase] = Field(default_factory=list)
    counts_as: Identifier | None = Field(
        default=None, description="Counted as this template in '3 bedrooms' (master bedroom)."
    )
    area: tuple[Area, Area]
    neighbours: list[Identifier] = Field(
        default_factory=list, description="Templates a room added by the prompt should touch."
    )
    floor: list[MaterialText] = Field(min_length=1)
    wall: list[MaterialText] = Field(min_length=1)
    ceiling: list[MaterialText] = Field(default_factory=lambda: ["white painted ceiling"])
    fixed_floor: bool = Field(default=False, description="Styles do not change the floor.")
    windows: Annotated[int, Field(ge=0, le=12)] | None = None
    objects: list[TemplateObject] = Field(default_factory=list)
    constraints: list[str] = Field(default_factory=list)
    variants: list[RoomVariant] = Field(default_factory=list)
    defining: list[ObjectName] = Field(
        description="Kinds that make the room what it is: never dropped when it is too full."
    )

    @model_validator(mode="after")
    def _check(self) -> RoomTemplate:
        _ordered_range(self.area, "area")
        return self

    def defining_in(self, names: Iterable[str]) -> list[str]:
        """The defining kinds among ``names`` (a room's objects), in template order."""
        present = set(names)
        return [name for name in self.defining if name in present]

    def object_sets(self) -> list[tuple[str, list[TemplateObject], list[str]]]:
        """(variant name, objects, constraint lines) of every variant (or the base alone)."""
        if not self.variants:
            return [("base", list(self.objects), list(self.constraints))]
        return [
            (v.name, [*self.objects, *v.objects], [*self.constraints, *v.constraints])
            for v in self.variants
        ]

    def kinds(self) -> list[str]:
        """Every object kind the template may hold, in order, without repeats."""
        names = [o.object for _, objects, _ in self.object_sets() for o in objects]
        return list(dict.fromkeys(names))


# ---------------------------------------------------------------------------------------------
# scene_types.json


class SceneRoom(FrozenModel):
    """A room of a scene type: which template, how many, and whom it should touch."""

    id: Identifier
    template: Identifier
    count: tuple[Count, Count] = (1, 1)
    probability: Probability = 1.0
    adjacent_to: list[Identifier] = Field(default_factory=list)

    @model_validator(mode="after")
    def _check(self) -> SceneRoom:
        _ordered_range(self.count, "count")
        return self


class SceneType(FrozenModel):
    """A scene the planner knows (``kitchen``, ``apartment``, ``cafe``)."""

    name: str = Field(min_length=1, max_length=64)
    kind: Literal["residential", "commercial"]
    description: str = Field(min_length=1, max_length=500)
    keywords: list[Phrase] = Field(min_length=1)
    refines: Identifier | None = Field(
        default=None, description="Chosen instead of that scene type when a refine word appears."
    )
    refine_keywords: list[Phrase] = Field(default_factory=list)
    rooms: list[SceneRoom] = Field(min_length=1)
    entrance: Identifier
    wall_height: tuple[Height, Height] = (2.6, 2.8)

    @model_validator(mode="after")
    def _check(self) -> SceneType:
        _ordered_range(self.wall_height, "wall_height")
        if (self.refines is None) != (not self.refine_keywords):
            raise ValueError("give both refines and refine_keywords, or neither")
        return self

    def embedding_text(self) -> str:
        """What the text encoder sees of this scene type when matching unknown requests."""
        return f"{self.name}. {self.description} Also called: {', '.join(self.keywords)}."


class Limits(FrozenModel):
    """What one room may hold and how big it may be."""

    footprint_fraction: Annotated[float, Field(gt=0.0, le=1.0)] = 0.35
    single_fraction: Annotated[float, Field(gt=0.0, le=1.0)] = 0.6
    max_floor_instances: Annotated[int, Field(ge=1, le=40)] = 12
    max_wall_instances: Annotated[int, Field(ge=0, le=20)] = 4
    max_receptacles: Annotated[int, Field(ge=0, le=20)] = 4
    max_small_per_receptacle: Annotated[int, Field(ge=1, le=20)] = 6
    min_side: Annotated[float, Field(ge=1.0, le=10.0)] = 2.5
    max_side: Annotated[float, Field(ge=2.0, le=40.0)] = 8.0
    max_grown_side: Annotated[float, Field(ge=2.0, le=40.0)] = 12.0
    max_rooms: Annotated[int, Field(ge=1, le=30)] = 12
    size_words: dict[Phrase, Annotated[float, Field(gt=0.1, le=5.0)]] = Field(default_factory=dict)
    area_jitter: Annotated[float, Field(ge=0.0, le=0.5)] = 0.1

    @property
    def min_area(self) -> float:
        """The smallest room the floor planner accepts."""
        return self.min_side**2

    @property
    def max_area(self) -> float:
        """The largest room the floor planner accepts."""
        return self.max_side**2

    @property
    def max_grown_area(self) -> float:
        """The largest a room of open size grows to hold the objects asked for in it."""
        return max(self.max_side, self.max_grown_side) ** 2


class ScenesFile(FrozenModel):
    """The contents of ``scene_types.json``."""

    limits: Limits = Field(default_factory=Limits)
    scene_types: dict[Identifier, SceneType]


class RoomsFile(FrozenModel):
    """The contents of ``rooms.json``."""

    rooms: dict[Identifier, RoomTemplate]


# ---------------------------------------------------------------------------------------------
# styles.json


class Style(FrozenModel):
    """A style word: materials drawn for rooms in that style, wall height, object adjective."""

    aliases: list[Phrase] = Field(min_length=1)
    floor: list[MaterialText] = Field(default_factory=list)
    wall: list[MaterialText] = Field(default_factory=list)
    ceiling: list[MaterialText] = Field(default_factory=list)
    wall_height: tuple[Height, Height] | None = None

    @model_validator(mode="after")
    def _check(self) -> Style:
        if self.wall_height is not None:
            _ordered_range(self.wall_height, "wall_height")
        return self


class MaterialTerm(FrozenModel):
    """A material or colour word and how each surface describes it (``oak`` -> ``oak wood``)."""

    aliases: list[Phrase] = Field(min_length=1)
    floor: str | None = Field(default=None, max_length=80)
    wall: str | None = Field(default=None, max_length=80)
    ceiling: str | None = Field(default=None, max_length=80)
    alone: Literal["floor", "wall"] | None = Field(
        default=None, description="The surface meant when no surface word follows ('carpet')."
    )

    def for_surface(self, surface: str) -> str | None:
        """How this word reads on ``surface`` (None: not a material for it)."""
        return {"floor": self.floor, "wall": self.wall, "ceiling": self.ceiling}[surface]


class StylesFile(FrozenModel):
    """The contents of ``styles.json``."""

    styles: dict[Phrase, Style]
    materials: dict[Phrase, MaterialTerm]
    modifiers: list[Phrase] = Field(
        default_factory=list, description="Words kept in a material description ('light')."
    )
    surfaces: dict[Literal["floor", "wall", "ceiling"], list[Phrase]]


# ---------------------------------------------------------------------------------------------
# The whole knowledge base


class KnowledgeBase(FrozenModel):
    """Everything the offline planner knows, checked for consistency by :func:`load_knowledge`."""

    objects: dict[ObjectName, ObjectKind]
    generics: dict[ObjectName, Generic]
    refused: dict[ObjectName, Refused]
    rooms: dict[Identifier, RoomTemplate]
    scene_types: dict[Identifier, SceneType]
    limits: Limits
    styles: dict[Phrase, Style]
    materials: dict[Phrase, MaterialTerm]
    modifiers: list[Phrase]
    surfaces: dict[Literal["floor", "wall", "ceiling"], list[Phrase]]
    receptacles: dict[str, list[tuple[str, float]]] = Field(
        description="Receptacle category (or 'room_type:category') -> [(small category, weight)]."
    )

    def small_choices(self, room_type: str, category: str) -> list[tuple[str, float]]:
        """Small-object categories (with weights) for a receptacle category in a room type."""
        key = f"{normal_type(room_type)}:{category}"
        return list(self.receptacles.get(key, self.receptacles.get(category, [])))

    def is_receptacle(self, category: str) -> bool:
        """Whether small objects may go on objects of this category."""
        return category in self.receptacles

    def allowed_small(self, category: str) -> set[str]:
        """Every small category allowed on ``category`` in some room type."""
        allowed: set[str] = set()
        for key, items in self.receptacles.items():
            if key == category or key.endswith(f":{category}"):
                allowed.update(name for name, _ in items)
        return allowed

    def kinds_in_room(self, template: str, placement: str | None = None) -> list[str]:
        """Object kinds that belong in a room template (their ``rooms``), in file order."""
        return [
            name
            for name, kind in self.objects.items()
            if template in kind.rooms and (placement is None or kind.placement == placement)
        ]

    def kinds_of_category(self, category: str, placement: str) -> list[str]:
        """Object kinds of a category and placement, in file order."""
        return [
            name
            for name, kind in self.objects.items()
            if kind.category == category and kind.placement == placement
        ]


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


# ---------------------------------------------------------------------------------------------
# Consistency checks


def check_knowledge(kb: KnowledgeBase) -> None:
    """Raise a SpecError for the first disagreement between the knowledge files."""
    _check_sizes(kb)
    _check_objects(kb)
    _check_phrases(kb)
    for name, template in kb.rooms.items():
        _check_template(kb, name, template)
    for name, scene in kb.scene_types.items():
        _check_scene(kb, name, scene)


def _unknown(name: str, known: Iterable[str], what: str, where: str) -> SpecError:
    close = closest_names(name, known)
    return SpecError(
        f"unknown {what} {name!r}", where=where, fix=f"did you mean {close}" if close else None
    )


def _check_sizes(kb: KnowledgeBase) -> None:
    """Sizes within the sane ranges of their placement; small <= default <= large."""
    for name, kind in kb.objects.items():
        ranges = SIZE_RANGES[kind.placement]
        sizes = {"size": kind.size, "small": kind.small, "large": kind.large}
        for key, size in sizes.items():
            if size is None:
                continue
            where = f"objects.json: objects.{name}.{key}"
            for axis, value, (low, high) in zip(("width", "depth", "height"), size, ranges):
                if not low <= value <= high:
                    raise SpecError(
                        f"{axis} {value:g} m is outside the sane range {low:g}-{high:g} m "
                        f"for {kind.placement} objects",
                        where=where,
                    )
            if kind.placement == "floor" and size[0] * size[1] > MAX_FOOTPRINT_M2:
                raise SpecError(
                    f"footprint {size[0] * size[1]:.1f} m2 is larger than {MAX_FOOTPRINT_M2:g} m2",
                    where=where,
                )
        if kind.size is None:
            continue
        default = _measures(kind.placement, kind.size)
        for key, size, sign in (("small", kind.small, -1), ("large", kind.large, 1)):
            if size is None:
                continue
            measures = _measures(kind.placement, size)
            if all(sign * (m - d) < 0 for m, d in zip(measures, default)):
                relation = "smaller" if sign > 0 else "larger"
                raise SpecError(
                    f"the {key} size {list(size)} is {relation} than the default size "
                    f"{list(kind.size)} (in area and in volume)",
                    where=f"objects.json: objects.{name}.{key}",
                )


def _measures(placement: str, size: tuple[float, float, float]) -> tuple[float, float]:
    """(visible area, volume) of a size: the face of wall objects, else the footprint."""
    width, depth, height = size
    area = width * height if placement == "wall" else width * depth
    return area, width * depth * height


def _check_objects(kb: KnowledgeBase) -> None:
    floor = {n for n, k in kb.objects.items() if k.placement == "floor"}
    receptacles = _receptacle_categories(kb)
    for name, kind in kb.objects.items():
        where = f"objects.json: objects.{name}"
        for room in kind.rooms:
            if room not in kb.rooms:
                raise _unknown(room, kb.rooms, "room template", f"{where}.rooms")
        if len(set(kind.rooms)) != len(kind.rooms):
            repeated = next(r for r in kind.rooms if kind.rooms.count(r) > 1)
            raise SpecError(f"room template {repeated!r} listed twice", where=f"{where}.rooms")
        has_table = kind.placement == "floor" and kind.category in receptacles
        if kind.receptacle and not has_table:
            raise SpecError(
                f"marked receptacle, but the receptacle table lists no small objects for "
                f"category {kind.category!r}",
                where=f"{where}.receptacle",
                fix="add the category to receptacles.json or set receptacle to false",
            )
        if has_table and not kind.receptacle:
            raise SpecError(
                f"the receptacle table lists small objects for category {kind.category!r}: "
                "set receptacle to true",
                where=f"{where}.receptacle",
            )
        if kind.placement == "object" and not any(
            kind.category in kb.allowed_small(rec) for rec in _receptacle_categories(kb)
        ):
            raise SpecError(
                f"small object category {kind.category!r} fits no receptacle", where=where
            )
        for i, line in enumerate(kind.constraints):
            subject = line.split("|", 1)[0].strip()
            if subject != name:
                raise SpecError(
                    f"a default constraint line must start with {name!r}, not {subject!r}",
                    where=f"{where}.constraints[{i}]",
                )
            for target in _targets(line):
                if target not in floor:
                    raise _unknown(target, floor, "floor object", f"{where}.constraints[{i}]")
            _check_lines([line], [name, *_targets(line)], f"{where}.constraints[{i}]")
    for name, generic in kb.generics.items():
        for kind in generic.kinds:
            if kind not in kb.objects:
                raise _unknown(kind, kb.objects, "object kind", f"objects.json: generics.{name}")
    for name in kb.refused:
        if name in kb.objects:
            raise SpecError(
                "a refused thing cannot also be an object kind", where=f"refused.{name}"
            )


def _receptacle_categories(kb: KnowledgeBase) -> set[str]:
    return {key.split(":")[-1] for key in kb.receptacles}


def _check_phrases(kb: KnowledgeBase) -> None:
    """A phrase may name one object kind, generic, refused thing, room template or style."""
    owners: dict[str, str] = {}

    def claim(phrases: Iterable[str], owner: str) -> None:
        for phrase in phrases:
            if phrase in owners and owners[phrase] != owner:
                raise SpecError(
                    f"the phrase {phrase!r} names both {owners[phrase]} and {owner}",
                    where=f"{owner}.aliases",
                    fix="keep each alias in one place",
                )
            owners[phrase] = owner

    for name, kind in kb.objects.items():
        claim([name, *kind.aliases], f"objects.json: objects.{name}")
    for name, generic in kb.generics.items():
        claim(generic.aliases, f"objects.json: generics.{name}")
    for name, refused in kb.refused.items():
        claim(refused.aliases, f"objects.json: refused.{name}")
    for name, template in kb.rooms.items():
        claim(template.aliases, f"rooms.json: rooms.{name}")
    for name, style in kb.styles.items():
        claim(style.aliases, f"styles.json: styles.{name}")
    keywords: dict[str, str] = {}
    for name, scene in kb.scene_types.items():
        for keyword in scene.keywords:
            if keyword in keywords:
                raise SpecError(
                    f"keyword {keyword!r} names scene types {keywords[keyword]!r} and {name!r}",
                    where=f"scene_types.json: scene_types.{name}.keywords",
                )
            keywords[keyword] = name


def _check_template(kb: KnowledgeBase, name: str, template: RoomTemplate) -> None:
    where = f"rooms.json: rooms.{name}"
    if template.counts_as is not None and template.counts_as not in kb.rooms:
        raise _unknown(template.counts_as, kb.rooms, "room template", f"{where}.counts_as")
    for neighbour in template.neighbours:
        if neighbour not in kb.rooms:
            raise _unknown(neighbour, kb.rooms, "room template", f"{where}.neighbours")
    for variant, objects, lines in template.object_sets():
        here = where if variant == "base" else f"{where} (variant {variant!r})"
        names = [o.object for o in objects]
        dupes = sorted({n for n in names if names.count(n) > 1})
        if dupes:
            raise SpecError(f"object {dupes[0]!r} listed twice", where=here)
        for i, entry in enumerate(objects):
            _check_entry(kb, template.type, entry, names, f"{here}.objects[{i}]")
            _check_belongs(kb, name, entry)
        floor = [n for n in names if kb.objects[n].placement == "floor"]
        _check_lines(lines, floor, f"{here}.constraints")
    _check_defining(kb, name, template)


def _check_belongs(kb: KnowledgeBase, template: str, entry: TemplateObject) -> None:
    """A kind a template lists (on the floor, a wall or a receptacle) names it in its rooms."""
    listed = [entry.object]
    if isinstance(entry.on_top, list):
        listed += [item.object for item in entry.on_top]
    for name in listed:
        if template not in kb.objects[name].rooms:
            raise SpecError(
                f"rooms.json: rooms.{template} lists {name!r}, but {template!r} is not in its "
                "rooms",
                where=f"objects.json: objects.{name}.rooms",
            )


def _check_defining(kb: KnowledgeBase, name: str, template: RoomTemplate) -> None:
    """Defining kinds: known floor or wall kinds the template always has when it lists them."""
    where = f"rooms.json: rooms.{name}.defining"
    if len(set(template.defining)) != len(template.defining):
        repeated = next(k for k in template.defining if template.defining.count(k) > 1)
        raise SpecError(f"defining kind {repeated!r} listed twice", where=where)
    kinds = template.kinds()
    for kind_name in template.defining:
        kind = kb.objects.get(kind_name)
        if kind is None:
            raise _unknown(kind_name, kb.objects, "object kind", where)
        if kind.placement not in ("floor", "wall"):
            raise SpecError(
                f"defining kind {kind_name!r} is a {kind.placement} object: only floor and wall "
                "objects define a room",
                where=where,
            )
        if kind_name not in kinds:
            raise _unknown(kind_name, kinds, "object of this template", where)
    for variant, objects, _ in template.object_sets():
        here = where if variant == "base" else f"{where} (variant {variant!r})"
        by_name = {o.object: o for o in objects}
        for kind_name in template.defining_in(by_name):
            entry = by_name[kind_name]
            if entry.priority < DEFINING_PRIORITY or entry.probability < 1.0:
                raise SpecError(
                    f"defining kind {kind_name!r} has priority {entry.priority} and probability "
                    f"{entry.probability:g}: it needs priority >= {DEFINING_PRIORITY} and "
                    "probability 1",
                    where=here,
                )
            for anchor, what in ((entry.per, "counts per"), (entry.above, "hangs above")):
                if anchor is not None and anchor not in template.defining:
                    raise SpecError(
                        f"defining kind {kind_name!r} {what} {anchor!r}, which is not defining",
                        where=here,
                    )


def _check_entry(
    kb: KnowledgeBase, room_type: str, entry: TemplateObject, names: list[str], where: str
) -> None:
    kind = kb.objects.get(entry.object)
    if kind is None:
        raise _unknown(entry.object, kb.objects, "object kind", where)
    if kind.placement == "object":
        raise SpecError(
            f"{entry.object!r} is a small object: list it in a receptacle's on_top", where=where
        )
    if entry.above is not None:
        if kind.placement != "wall":
            raise SpecError("only wall objects hang above others", where=where)
        if entry.above not in names or kb.objects[entry.above].placement != "floor":
            raise _unknown(entry.above, names, "floor object of this room", f"{where}.above")
    if entry.per is not None and entry.per not in names:
        raise _unknown(entry.per, names, "object of this room", f"{where}.per")
    if entry.on_top is not None:
        if not kind.receptacle:
            raise SpecError(
                f"{entry.object!r} is not a receptacle (receptacle: false)", where=f"{where}.on_top"
            )
        choices = kb.small_choices(room_type, kind.category)
        if not choices:
            raise SpecError(f"{kind.category!r} is not a receptacle", where=f"{where}.on_top")
        allowed = {name for name, _ in choices}
        small_categories = {k.category for k in kb.objects.values() if k.placement == "object"}
        unknown = sorted(allowed - small_categories)
        if unknown:
            raise SpecError(
                f"no small object kind of category {unknown[0]!r} (receptacle table entry for "
                f"{kind.category!r} in {room_type!r})",
                where=f"{where}.on_top",
            )
        if entry.on_top != "auto":
            for j, item in enumerate(entry.on_top):
                small = kb.objects.get(item.object)
                if small is None or small.placement != "object":
                    smalls = [n for n, k in kb.objects.items() if k.placement == "object"]
                    raise _unknown(item.object, smalls, "small object", f"{where}.on_top[{j}]")
                if small.category not in allowed:
                    raise SpecError(
                        f"{small.category!r} does not go on {kind.category!r} "
                        f"(allowed: {', '.join(sorted(allowed))})",
                        where=f"{where}.on_top[{j}]",
                    )


def _check_lines(lines: list[str], names: list[str], where: str) -> None:
    """Every line parses without warnings over ``names``."""
    for i, line in enumerate(lines):
        parsed = parse_constraint_text(line, names)
        if parsed.warnings or not parsed.constraints:
            problem = parsed.warnings[0] if parsed.warnings else "no constraint in it"
            raise SpecError(f"constraint {line!r}: {problem}", where=f"{where}[{i}]")


def _targets(line: str) -> list[str]:
    """Target names of a constraint line (the text after the comma of each segment)."""
    out = []
    for segment in line.split("|")[1:]:
        if "," in segment:
            out.append(" ".join(segment.split(",", 1)[1].split()))
    return out


def _check_scene(kb: KnowledgeBase, name: str, scene: SceneType) -> None:
    where = f"scene_types.json: scene_types.{name}"
    ids = [room.id for room in scene.rooms]
    dupes = sorted({i for i in ids if ids.count(i) > 1})
    if dupes:
        raise SpecError(f"room id {dupes[0]!r} repeats", where=f"{where}.rooms")
    if scene.entrance not in ids:
        raise _unknown(scene.entrance, ids, "room id", f"{where}.entrance")
    if scene.refines is not None and scene.refines not in kb.scene_types:
        raise _unknown(scene.refines, kb.scene_types, "scene type", f"{where}.refines")
    for i, room in enumerate(scene.rooms):
        if room.template not in kb.rooms:
            raise _unknown(room.template, kb.rooms, "room template", f"{where}.rooms[{i}].template")
        for other in room.adjacent_to:
            if other not in ids or other == room.id:
                raise _unknown(other, ids, "room id", f"{where}.rooms[{i}].adjacent_to")


__all__ = [
    "DEFINING_PRIORITY",
    "SIZE_RANGES",
    "Generic",
    "KnowledgeBase",
    "Limits",
    "MaterialTerm",
    "ObjectKind",
    "Refused",
    "RoomTemplate",
    "RoomVariant",
    "SceneRoom",
    "SceneType",
    "SmallItem",
    "Style",
    "TemplateObject",
    "check_knowledge",
    "knowledge_base",
    "load_knowledge",
]
