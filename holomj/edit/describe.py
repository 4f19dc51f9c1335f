"""What a description asks for, in the planner's words: kind, size, placement, relations.

The offline planner reads ``"a <room type> with <description>"`` (so the room's kinds resolve
generic words: a chair in a dining room is a dining chair) and the object the description is
about is taken from its plan: its name, retrieval description, library category, size,
placement (floor, wall, ceiling, or ``object``: a small object that goes on a receptacle) and
the relations the words give it ("by the window", "next to the sofa": targets are plan names,
matched to the scene's objects by the caller). Unknown nouns are planned like their nearest
kinds (:mod:`holomj.plan.new_kinds`); words that name nothing placeable are refused with the
planner's note.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any

from holomj.edit.state import Refused
from holomj.errors import HolomjError
from holomj.plan.knowledge import knowledge_base
from holomj.plan.offline import plan_offline
from holomj.plan.prompt import parse_prompt
from holomj.spec.plan import PlanObject, PlanRoom, ScenePlan


@dataclass(frozen=True)
class Described:
    """The object a description asks for."""

    name: str  # plan name ("armchair", "hamster cage")
    description: str  # what retrieval matches ("green armchair")
    category: str | None
    size: tuple[float, float, float] | None
    placement: str  # floor, wall, ceiling or object
    relations: tuple[tuple[str, str | None], ...] = ()  # (plan relation kind, target plan name)
    holder: str | None = None  # a small object: the plan name of what it goes on
    notes: tuple[str, ...] = field(default_factory=tuple)


def room_words(room_type: str) -> str:
    """``living_room`` -> ``living room``; ``LivingRoom`` -> ``living room``."""
    spaced = re.sub(r"(?<=[a-z0-9])(?=[A-Z])", " ", room_type)
    return " ".join(re.findall(r"[a-z0-9]+", spaced.lower())) or "room"


def describe(description: str, room_type: str, seed: int = 0, encoder: Any = None) -> Described:
    """The object ``description`` asks for in a room of ``room_type`` (see the module doc);
    :class:`~holomj.edit.state.Refused` when it names nothing the planner can place."""
    text = " ".join(description.split())
    prompt = f"a {room_words(room_type)} with {_article(text)}"
    try:
        plan = plan_offline(prompt, seed, encoder=encoder)
    except HolomjError as err:
        raise Refused(f"cannot read {description!r}: {err.one_line()}") from None
    kb = knowledge_base()
    parsed = parse_prompt(prompt, kb)
    kinds = [r for r in parsed.objects if not r.excluded]
    wanted = kinds[0].kind if kinds else None
    generic = kinds[0].generic if kinds else False
    options: set[str | None] = (
        set(kb.generics[wanted].kinds) if generic and wanted in kb.generics else {wanted}
    )
    room = _room(plan, room_type)
    notes = tuple(n for n in plan.notes if "not in the knowledge base" in n or "left out" in n)
    subject = _named(room, options) if room is not None else None
    small = _small(plan, options) if subject is None and wanted is not None else None
    if small is not None:
        return small
    if subject is None and room is not None:
        subject = _subject(room, text)
    if subject is not None and room is not None:  # a subject is always of a room
        relations = tuple((r.kind, r.target) for r in room.relations if r.subject == subject.name)
        return Described(
            name=subject.name,
            description=subject.description.strip() or subject.name,
            category=subject.category,
            size=subject.size,
            placement=subject.placement,
            relations=relations,
            notes=notes,
        )
    why = "; ".join(notes) or "the planner found no object in it"
    raise Refused(f"{description!r} names nothing that can be placed ({why})")


def _article(text: str) -> str:
    """The description with an article, so that the planner reads it as one object."""
    first = text.split(" ", 1)[0].lower()
    if first in {"a", "an", "the", "one", "some"} or first.isdigit():
        return text
    return f"a {text}"


def _room(plan: ScenePlan, room_type: str) -> PlanRoom | None:
    """The plan's room of that type (else its first room)."""
    wanted = room_words(room_type)
    for room in plan.rooms:
        if room_words(room.type) == wanted:
            return room
    return plan.rooms[0] if plan.rooms else None


def _named(room: PlanRoom, options: set[str | None]) -> PlanObject | None:
    """The requested plan object of the kind the description names first."""
    return next((o for o in room.objects if o.requested and o.name in options), None)


def _subject(room: PlanRoom, text: str) -> PlanObject | None:
    """For a description whose noun the knowledge base does not know: the requested object
    that relations start from, else the one named earliest."""
    requested = [o for o in room.objects if o.requested]
    if not requested:
        return None
    subjects = {r.subject for r in room.relations}
    targets = {r.target for r in room.relations if r.target}
    candidates = [o for o in requested if o.name in subjects] or [
        o for o in requested if o.name not in targets
    ]
    candidates = candidates or requested
    lower = text.lower()

    def position(obj: PlanObject) -> int:
        found = lower.find(obj.name)
        return found if found >= 0 else len(lower)

    return min(candidates, key=lambda o: (position(o), o.name))


def _small(plan: ScenePlan, options: set[str | None]) -> Described | None:
    """A small object the description names (it went on a receptacle of the plan)."""
    for room in plan.rooms:
        for holder in room.objects:
            for item in holder.on_top:
                if item.name in options:
                    return Described(
                        name=item.name,
                        description=item.description.strip() or item.name,
                        category=item.category,
                        size=None,
                        placement="object",
                        holder=holder.name,
                    )
    return None
