"""The schema of the offline planner's knowledge files (see :mod:`holomj.plan.knowledge`): one
pydantic model per part of ``objects.json``, ``rooms.json``, ``scene_types.json`` and
``styles.json``, and :class:`KnowledgeBase`, all of them together."""

from __future__ import annotations

from collections.abc import Iterable
from typing import Annotated, Literal

from pydantic import Field, model_validator

from holomj.spec.base import FrozenModel, Identifier
from holomj.spec.categories import normal_type
from holomj.spec.plan import ObjectName, Size3

Phrase = Annotated[str, Field(min_length=1, max_length=64, pattern=r"^[a-z0-9]+( [a-z0-9]+)*$")]
Count = Annotated[int, Field(ge=0, le=40)]
Probability = Annotated[float, Field(ge=0.0, le=1.0)]
Area = Annotated[float, Field(ge=1.0, le=400.0)]
Height = Annotated[float, Field(ge=2.2, le=6.0)]
MaterialText = Annotated[str, Field(min_length=1, max_length=200)]
Category = Annotated[str, Field(min_length=1, max_length=64, pattern=r"^[a-z0-9]+(_[a-z0-9]+)*$")]
Placement = Literal["floor", "wall", "ceiling", "object"]


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


class RefusedThings(FrozenModel):
    """Things the planner never plans, with the reason it gives."""

    aliases: list[Phrase] = Field(min_length=1)
    reason: str = Field(min_length=1, max_length=200)


class ObjectsFile(FrozenModel):
    """The contents of ``objects.json``."""

    objects: dict[ObjectName, ObjectKind]
    generics: dict[ObjectName, Generic] = Field(default_factory=dict)
    refused: dict[ObjectName, RefusedThings] = Field(default_factory=dict)


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
    refused: dict[ObjectName, RefusedThings]
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
