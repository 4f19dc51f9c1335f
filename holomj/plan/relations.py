"""The prompt's relations, made part of an offline plan.

Each :class:`~holomj.plan.prompt_relations.RelationRequest` names two of the prompt's object
requests (or one and a place). Once the requests are in rooms (:mod:`~holomj.plan.object_requests`
records where each went), a relation between objects of one room becomes a
:class:`~holomj.spec.plan.PlanRelation` of that room:

* place and object relations (corner, wall, middle, under / by a window, by a door, next to,
  near, in front of, behind, facing, across from, around, on each side of, in a row) become
  weighted layout constraints (:mod:`holomj.layout.relation_constraints`);
* ``on``: the small object goes on that receptacle (and only there); a TV put on a piece of
  furniture stands on it instead of hanging on the wall;
* ``above``: the wall object hangs above that floor object; a relation to a wall object that
  hangs above a floor object (``facing the TV``) is one to that floor object; a wall object
  faced by a floor object (``salon chairs facing a mirror``, ``a TV facing the bed``) hangs
  where the floor object looks;
* ``X with Y`` (``holds``): a small Y goes on X (one on each X when Y has no number: two
  nightstands with lamps), a seat at X (``around``), anything else next to it;
* ``on each side of``: two of the subject per target instance (a nightstand on each side of
  the bed is two nightstands);
* ``side by side`` after one object is ``next to`` the object before it (a car and a
  motorcycle side by side), after several it is ``in a row``.

Anything else is noted and left out of the layout: relations across rooms, an object under another.
"""

from __future__ import annotations

from holomj.plan.draft import (
    MAX_QUANTITY,
    DraftObject,
    DraftPlan,
    DraftRoom,
    DraftSmall,
    plural_name,
    spread,
)
from holomj.plan.prompt_relations import RelationRequest
from holomj.spec.plan import PlanRelation
from holomj.spec.relations import LAYOUT_KINDS  # the kinds that go to the layout as they are

SEAT_CATEGORIES = frozenset(
    {
        "dining_chair", "office_chair", "stool", "armchair", "chair", "bar_stool",
        "salon_chair", "sofa", "bench",
    }
)  # fmt: skip
# Wall objects that may stand on furniture instead, when the prompt puts them on it.
STANDING_ON = frozenset({"television"})
_UNSUPPORTED = {"under": "an object under another object is not planned"}


def apply_relations(state: DraftPlan) -> None:
    """Turn the prompt's relations into plan relations of the rooms (see the module doc)."""
    for rel in state.parsed.relations:
        phrase = rel.phrase
        subject = _home(state, rel.subject)
        if subject is None:
            continue  # the object itself was left out (noted where)
        room, obj, small = subject
        if rel.kind in _UNSUPPORTED:
            state.note(f"'{_asked(state, rel)}': {_UNSUPPORTED[rel.kind]}; left to the defaults")
            continue
        subject_obj = room.get(obj)
        single = subject_obj is not None and subject_obj.quantity == 1
        if rel.kind == "in_row" and single and rel.subject > 0:
            # "a car and a motorcycle side by side": the two, next to each other
            rel = rel.model_copy(update={"kind": "adjacent_to", "target": rel.subject - 1})
        if rel.target is None:
            _place_relation(state, room, obj, small, rel)
            continue
        target = _home(state, rel.target)
        if target is None:
            continue
        t_room, t_obj, t_small = target
        if t_room is not room:
            state.note(
                f"'{_asked(state, rel)}': the {obj} and the {t_obj} are in different rooms; "
                "the relation is left out"
            )
            continue
        kind = rel.kind
        if kind == "holds":  # "X with Y": Y relative to X
            obj, t_obj, small, t_small = t_obj, obj, t_small, small
            kind = _held_kind(state, room, obj, small)
        _object_relation(state, room, obj, small, kind, t_obj, t_small, phrase)
        if rel.kind == "holds" and small and rel.target is not None:
            held = state.parsed.objects[rel.target]
            if held.quantity is None and not held.many:  # "nightstands with lamps": one each
                holder = room.get(t_obj)
                for item in holder.on_top if holder is not None else []:
                    if item.name == obj:
                        item.quantity = 1


def _home(state: DraftPlan, index: int) -> tuple[DraftRoom, str, bool] | None:
    """The room and object name request ``index`` became, and whether it is a small object."""
    home = state.request_homes.get(index)
    if home is None:
        return None
    room_id, name, small = home
    room = next((r for r in state.rooms if r.id == room_id), None)
    return (room, name, small) if room is not None else None


def _asked(state: DraftPlan, rel: RelationRequest) -> str:
    return f"{state.parsed.objects[rel.subject].phrase} {rel.phrase}".strip()


def _held_kind(state: DraftPlan, room: DraftRoom, held: str, small: bool) -> str:
    if small:
        return "on"
    obj = room.get(held)
    if obj is not None and obj.kind.category in SEAT_CATEGORIES:
        return "around"
    return "adjacent_to"


def _add(room: DraftRoom, relation: PlanRelation) -> None:
    key = (relation.subject, relation.kind, relation.target)
    if all((r.subject, r.kind, r.target) != key for r in room.relations):
        room.relations.append(relation)


def _place_relation(
    state: DraftPlan, room: DraftRoom, name: str, small: bool, rel: RelationRequest
) -> None:
    obj = room.get(name)
    if small or obj is None:
        return  # a small object's place is its receptacle
    if rel.kind == "ceiling" or (rel.kind == "wall" and not obj.floor):
        return  # where the object hangs anyway
    if not obj.floor:
        state.note(f"'{_asked(state, rel)}': the {name} hangs on a wall; left to the defaults")
        return
    if rel.kind in LAYOUT_KINDS:
        _add(room, PlanRelation(subject=name, kind=rel.kind, phrase=rel.phrase))


def _object_relation(
    state: DraftPlan,
    room: DraftRoom,
    name: str,
    small: bool,
    kind: str,
    target: str,
    target_small: bool,
    phrase: str,
) -> None:
    obj, other = room.get(name), room.get(target)
    if _stands_on(kind, small, obj, other):
        # "a TV on the TV stand": the TV stands on it instead of hanging on the wall
        assert obj is not None and other is not None
        room.objects.remove(obj)
        other.on_top = [s for s in other.on_top if s.name != name]
        other.on_top.append(DraftSmall(name, obj.kind.category, 1, "same", requested=True))
        small = True
    if kind == "on":
        if small and other is not None and other.floor:
            _move_small(room, name, other)
            if {"each", "every"} & set(phrase.split()):
                _on_each(other, name)
            _add(room, PlanRelation(subject=name, kind="on", target=target, phrase=phrase))
        elif not small:
            state.note(f"'{name} {phrase}': only small objects are put on others; not kept")
        return
    if other is not None and not other.floor and other.above is not None:
        # "a sofa facing the TV": the TV hangs above its stand; face the stand
        target, other = other.above, room.get(other.above)
    if small or target_small or obj is None or other is None:
        return
    if kind == "above":
        if not obj.floor and other.floor:
            obj.above = target
            if "each" in phrase.split() and obj.quantity < other.quantity:
                # "a mobile above each crib": one above every crib
                obj.quantity = min(other.quantity, MAX_QUANTITY)
            _add(room, PlanRelation(subject=name, kind="above", target=target, phrase=phrase))
        else:
            state.note(f"'{name} {phrase}': only a wall object hangs above a floor object")
        return
    if kind in ("facing", "across_from") and obj.floor != other.floor:
        # a floor object facing a wall object (or a wall object facing a floor object): the
        # wall object hangs where the floor object looks
        looker, hung = (obj, other) if obj.floor else (other, obj)
        if hung.above is None:
            hung.faced_by = looker.name
            if phrase.split()[:1] == ["each"] and hung.quantity < looker.quantity:
                # "three salon chairs, each facing a mirror": a mirror for each chair
                state.note(f"'{name} {phrase}': {looker.quantity} {plural_name(hung.name, 2)}")
                hung.quantity = min(looker.quantity, MAX_QUANTITY)
            _add(room, PlanRelation(subject=name, kind="facing", target=target, phrase=phrase))
            return
    if not (obj.floor and other.floor):
        state.note(f"'{name} {phrase}': a layout relation between floor objects only; not kept")
        return
    if kind == "both_sides":
        want = min(2 * other.quantity, MAX_QUANTITY)
        if obj.quantity < want:
            state.note(f"'{name} {phrase}': {want} {name}s, one on each side of each {target}")
            obj.quantity = want
    if kind in LAYOUT_KINDS:
        _add(room, PlanRelation(subject=name, kind=kind, target=target, phrase=phrase))


def _stands_on(kind: str, small: bool, obj: DraftObject | None, other: DraftObject | None) -> bool:
    return (
        kind == "on"
        and not small
        and obj is not None
        and other is not None
        and obj.kind.category in STANDING_ON
        and other.floor
        and not obj.floor
    )


def _on_each(holder: DraftObject, name: str) -> None:
    """ "A computer on each desk", "two books on every shelf": the count asked goes on every
    instance of the holder."""
    for item in holder.on_top:
        if item.name == name and item.instances is not None:
            item.quantity, item.instances = item.quantity * item.instances, None


def _move_small(room: DraftRoom, name: str, holder: DraftObject) -> None:
    """Small objects ``name`` go onto ``holder`` alone, with the count the prompt asked for
    (the template's own of that name go)."""
    count = 0
    template: DraftSmall | None = None
    for obj in room.objects:
        for item in list(obj.on_top):
            if item.name != name or (obj is holder and item.requested):
                continue
            obj.on_top.remove(item)
            if item.requested:
                count += item.quantity * (item.instances or obj.quantity)
                template = template or item
    if template is None:
        return
    existing = next((s for s in holder.on_top if s.name == name), None)
    each, instances = spread(count, holder.quantity)
    if existing is not None:
        existing.quantity += each
        existing.instances = None
    else:
        holder.on_top.append(
            DraftSmall(name, template.category, each, template.variance, True, instances)
        )


def room_relations(state: DraftPlan, room: DraftRoom) -> list[PlanRelation]:
    """The room's relations whose objects are still in the plan (the others noted)."""
    names = {o.name for o in room.objects}
    small = {s.name for o in room.objects for s in o.on_top}
    out = []
    for rel in room.relations:
        known = names | (small if rel.kind == "on" else set())
        missing = [n for n in (rel.subject, rel.target) if n is not None and n not in known]
        if missing:
            state.note(
                f"'{rel.subject} {rel.phrase}' is left out: no {missing[0]} in the "
                f"{room.template.name}"
            )
            continue
        out.append(rel)
    return out
