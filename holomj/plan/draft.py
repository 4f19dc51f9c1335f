"""Working state of one offline plan: rooms, objects and small objects as they are drafted.

The planner's steps (:mod:`holomj.plan.offline`) change these mutable records in place; the
finished draft is written out as a :class:`~holomj.spec.plan.ScenePlan`. Also here: the few
helpers every step shares (removing an object with the objects that depend on it, plurals in
notes).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from holomj.plan.knowledge_schema import KnowledgeBase, ObjectKind, RoomTemplate
from holomj.plan.prompt import ParsedPrompt
from holomj.retrieval.text import TextEncoder
from holomj.spec.plan import PlanRelation, Variance

MAX_QUANTITY = 40  # PlanObject's limit


@dataclass
class DraftSmall:
    """Small objects of one kind on a receptacle (``quantity`` on each receptacle instance, or
    on the first ``instances`` of them)."""

    name: str
    category: str
    quantity: int
    variance: Variance = "varied"
    requested: bool = False
    instances: int | None = None


def spread(total: int, holders: int) -> tuple[int, int | None]:
    """``total`` small objects over ``holders`` receptacle instances: how many on each, and on
    how many of them (None: all). A printer for eight desks is one printer on one desk, ten
    books for eight shelves two on each of five."""
    each = max(1, -(-total // max(1, holders)))
    used = -(-total // each)
    return each, (used if used < holders else None)


@dataclass
class DraftObject:
    """An object kind in a room, with its count, priority and what it depends on."""

    name: str
    kind: ObjectKind
    quantity: int
    priority: int = 5
    variance: Variance = "same"
    size: tuple[float, float, float] | None = None
    requested: bool = False
    per: str | None = None
    per_max: int = 1
    seat: bool = False
    above: str | None = None
    faced_by: str | None = None  # wall objects: the floor object that looks at it
    on_top: list[DraftSmall] = field(default_factory=list)
    adjectives: list[str] = field(default_factory=list)
    parts: list[str] = field(default_factory=list)  # "brass handles": parts asked of it
    asked: str = ""  # the prompt's words for a requested object

    @property
    def floor(self) -> bool:
        """Whether the object stands on the floor (not on a wall)."""
        return self.kind.placement == "floor"

    @property
    def footprint(self) -> float:
        """Floor area of one instance in m² (0 for a kind without a size, and for a rug: the
        furniture stands on it)."""
        if self.kind.category == "rug":
            return 0.0
        size = self.size or self.kind.size or (0.0, 0.0, 0.0)
        return size[0] * size[1]


@dataclass
class DraftRoom:
    """A room being planned: its template, size, materials, objects and layout lines."""

    id: str
    template_id: str
    template: RoomTemplate
    entry_id: str | None = None  # the scene type's room entry it comes from, if any
    adjacent_to: list[str] = field(default_factory=list)
    size: tuple[float, float] | None = None
    area: float = 0.0
    fixed: bool = False
    objects: list[DraftObject] = field(default_factory=list)
    lines: list[str] = field(default_factory=list)
    relations: list[PlanRelation] = field(default_factory=list)  # from the prompt
    floor: str = ""
    wall: str = ""
    ceiling: str = ""
    windows: int | None = None

    def get(self, name: str) -> DraftObject | None:
        """The room's object of kind ``name``, if it has one."""
        return next((o for o in self.objects if o.name == name), None)

    @property
    def floor_area(self) -> float:
        """The room's floor area: from its sides when set, else its drawn area."""
        return self.size[0] * self.size[1] if self.size is not None else self.area


@dataclass
class DraftPlan:
    """The whole draft: knowledge base, random generator, parsed prompt, rooms and notes."""

    kb: KnowledgeBase
    rng: np.random.Generator
    parsed: ParsedPrompt
    encoder: TextEncoder | None
    notes: list[str] = field(default_factory=list)
    rooms: list[DraftRoom] = field(default_factory=list)
    only_room: str | None = None  # the one room template the prompt asked for, alone
    # parsed object request index -> (room id, object name, is a small object)
    request_homes: dict[int, tuple[str, str, bool]] = field(default_factory=dict)
    # kinds made for nouns the knowledge base does not know, and the known kind each is like
    new_kinds: dict[str, ObjectKind] = field(default_factory=dict)
    like: dict[str, str] = field(default_factory=dict)

    def object_kind(self, name: str) -> ObjectKind:
        """A known object kind, or one made for a noun the prompt asked for."""
        return self.new_kinds[name] if name in self.new_kinds else self.kb.objects[name]

    def note(self, text: str) -> None:
        """Add a note for the plan (once)."""
        if text not in self.notes:
            self.notes.append(text)

    def text_encoder(self) -> TextEncoder:
        """The text encoder, loading the default one on first use."""
        if self.encoder is None:
            from holomj.retrieval.text import text_encoder

            self.encoder = text_encoder()
        return self.encoder


def remove_object(room: DraftRoom, obj: DraftObject) -> None:
    """Remove an object from a room, with the unrequested objects counted per it (its chairs).

    Requested objects that were counted per it stay, with their own count.
    """
    room.objects.remove(obj)
    for other in list(room.objects):
        if other.per == obj.name:
            if other.requested:
                other.per = None
            elif other in room.objects:
                remove_object(room, other)


def plural_name(name: str, count: int) -> str:
    """``name`` as written for ``count`` of it in a note (``bookshelf`` -> ``bookshelves``)."""
    if count == 1:
        return name
    if name.endswith(("s", "sh", "ch", "x")):
        return name + "es"
    if name.endswith("f"):
        return name[:-1] + "ves"
    return name + "s"
