"""Seats that go with a table: which chair kind "six chairs around the table" means.

The room templates say which seats go with which table (``per`` and ``seat`` in rooms.json:
dining chairs per dining table, school chairs per student desk, bar stools per bar table...).
A generic seat word (``chairs``) that the prompt puts around or at a table, or that a table is
asked "with", becomes the seat kind paired with that table's kind; a generic ``table`` that seats
gather around becomes a table kind that has paired seats (preferring the room's own). Without such
a link the room's usual kind is kept (:func:`holomj.plan.object_requests.apply_requests`).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from types import MappingProxyType

from holomj.layout.constraints import parse_constraint_text
from holomj.plan.knowledge_schema import KnowledgeBase
from holomj.plan.prompt import ObjectRequest
from holomj.plan.prompt_relations import RelationRequest

# Relations by which a seat is linked to a table: subject seat, target table (``holds``: the
# other way round, "a table with four chairs").
SEAT_RELATIONS = frozenset({"around", "adjacent_to", "near", "in_front_of", "facing"})


# seat pairs per knowledge base (kept with it, so that its id is not reused while cached)
_PAIRS: dict[int, tuple[KnowledgeBase, Mapping[str, tuple[str, ...]]]] = {}


def seat_pairs(kb: KnowledgeBase) -> Mapping[str, tuple[str, ...]]:
    """Table kind -> the seat kinds the templates put per instance of it, or gather near it
    (``seat`` without ``per``, "office chair | near, conference table"), in template order.
    Worked out once per knowledge base: the planner asks for every seat word."""
    cached = _PAIRS.get(id(kb))
    if cached is None or cached[0] is not kb:
        cached = _PAIRS[id(kb)] = (kb, MappingProxyType(_seat_pairs(kb)))
    return cached[1]


def _seat_pairs(kb: KnowledgeBase) -> dict[str, tuple[str, ...]]:
    pairs: dict[str, list[str]] = {}
    gathered: list[tuple[str, str]] = []
    tables = set(kb.generics["table"].kinds) if "table" in kb.generics else set()
    for template in kb.rooms.values():
        for _, objects, lines in template.object_sets():
            kinds = {o.object for o in objects}
            for obj in objects:
                if not obj.seat:
                    continue
                if obj.per is not None:
                    seats = pairs.setdefault(obj.per, [])
                    if obj.object not in seats:
                        seats.append(obj.object)
                    continue
                target = _gathered_at(obj.object, lines)
                if target in kinds and target in tables and _sat_at(kb, target):
                    gathered.append((target, obj.object))
    for table, seat in gathered:  # after the seats put per table
        seats = pairs.setdefault(table, [])
        if seat not in seats:
            seats.append(seat)
    return {table: tuple(seats) for table, seats in pairs.items()}


SEATED_TABLE_M = 0.6  # a table people sit at is at least this tall (not a coffee table)


def _sat_at(kb: KnowledgeBase, table: str) -> bool:
    """Whether ``table`` is tall enough to sit at."""
    size = kb.objects[table].size
    return size is not None and size[2] >= SEATED_TABLE_M


def _gathered_at(seat: str, lines: Sequence[str]) -> str | None:
    """The object a template's constraint lines put ``seat`` near, if any."""
    parsed = parse_constraint_text("\n".join(lines))
    return next(
        (c.target for c in parsed.constraints if c.object == seat and c.kind == "near"), None
    )


def seat_kinds(kb: KnowledgeBase) -> frozenset[str]:
    """Every kind a template counts as a seat next to a table."""
    return frozenset(seat for seats in seat_pairs(kb).values() for seat in seats)


def is_seat_word(kb: KnowledgeBase, request: ObjectRequest) -> bool:
    """Whether a generic request (``chairs``, ``seats``) may mean a seat that goes with a table."""
    if not request.generic:
        return False
    return any(kind in seat_kinds(kb) for kind in kb.generics[request.kind].kinds)


def seating_links(
    kb: KnowledgeBase, objects: Sequence[ObjectRequest], relations: Sequence[RelationRequest]
) -> dict[int, int]:
    """Seat request index -> the index of the table request it goes with."""
    links: dict[int, int] = {}
    for rel in relations:
        if rel.target is None:
            continue
        seat, table = (
            (rel.target, rel.subject) if rel.kind == "holds" else (rel.subject, rel.target)
        )
        if rel.kind != "holds" and rel.kind not in SEAT_RELATIONS:
            continue
        if is_seat_word(kb, objects[seat]) and seat not in links:
            links[seat] = table
    return links


def seating_table(kb: KnowledgeBase, generic: str, present: Sequence[str]) -> str | None:
    """The kind a generic table word means when seats go around it: a kind of the generic with
    paired seats, the first of ``present`` (the room's own kinds, in order of preference) that
    is one, else the generic's first such kind; None when it has none."""
    pairs = seat_pairs(kb)
    candidates = [k for k in kb.generics[generic].kinds if k in pairs]
    for kind in present:
        if kind in candidates:
            return kind
    return candidates[0] if candidates else None


def seat_for(kb: KnowledgeBase, generic: str, table: str, present: Sequence[str]) -> str | None:
    """The kind a generic seat word means at ``table``: a seat paired with the table that the
    generic may mean, the first of ``present`` that is one, else the first; None when none."""
    paired = [k for k in seat_pairs(kb).get(table, ()) if k in kb.generics[generic].kinds]
    for kind in present:
        if kind in paired:
            return kind
    return paired[0] if paired else None
