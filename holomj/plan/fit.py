"""Room limits for an offline plan: dropping and shrinking objects until a room's furniture fits.

:func:`fit_room` keeps at most ``max_floor_instances`` floor objects (raised to the number
asked for, up to :data:`MAX_FLOOR_INSTANCES`), the floor the objects need in use
(:mod:`holomj.plan.use_area`: a table with its chairs and aisles, a pool table with room for
the cue) under ``footprint_fraction`` of the room (rooms whose size was not given grow for
requested objects, up to ``max_grown_side`` a side;
optional objects and extra requested instances go first, then objects take their smaller
sizes, then extra essential instances go), no object too big for the room, at most
``max_wall_instances`` wall objects and ``max_receptacles`` receptacles with small objects.
Optional, low-priority objects go first, requested ones last. Every drop is noted, with its
reason.
"""

from __future__ import annotations

from collections.abc import Sequence

from holomj.plan.draft import DraftObject, DraftPlan, DraftRoom, plural_name, remove_object
from holomj.plan.use_area import floor_needs, least_area


def fit_room(state: DraftPlan, room: DraftRoom) -> None:
    """Keep the room's furniture within the limits (see :mod:`holomj.plan.fit`)."""
    limits = state.kb.limits
    start = _counts(room)
    reasons: dict[str, list[str]] = {}

    def floor() -> list[DraftObject]:
        return [o for o in room.objects if o.floor]

    def footprint() -> float:
        return sum(o.footprint * o.quantity for o in floor())

    def in_use() -> float:  # the floor the objects need in use (holomj.plan.use_area)
        needs = floor_needs(state.kb, room, limits.footprint_fraction)
        return sum(needs[o.name] * o.quantity for o in floor())

    def phase(before: dict[str, tuple[int, bool, str]], why: str) -> None:
        for name, (count, _, _) in before.items():
            obj = room.get(name)
            if obj is None or obj.quantity < count:
                reasons.setdefault(name, []).append(why)

    before = _counts(room)
    cap = floor_cap(state, room)
    while sum(o.quantity for o in floor()) > cap:
        if not _shrink(room, floor(), max_tier=4):
            break
    phase(before, f"at most {cap} floor objects per room")
    budget = limits.footprint_fraction * room.floor_area
    needs = floor_needs(state.kb, room, limits.footprint_fraction)
    needed = sum(needs[o.name] * o.quantity for o in floor() if _tier(o, room) > 0)
    least = max(needed / limits.footprint_fraction, least_area(room))
    if least > room.floor_area + 1e-6 and not room.fixed and any(o.requested for o in floor()):
        area = min(limits.max_grown_area, least)
        state.note(
            f"enlarged {room.id} from {room.area:.1f} to {area:.1f} m² to fit the objects asked for"
        )
        room.area = round(area, 1)
        budget = limits.footprint_fraction * room.floor_area
    before = _counts(room)
    while in_use() > budget:
        if not (
            _shrink(room, floor(), max_tier=1)
            or _downsize(state, room)
            or _shrink(room, floor(), max_tier=2)
        ):
            break
    phase(
        before,
        f"furniture footprint in use under {limits.footprint_fraction:.0%} of "
        f"{room.floor_area:.1f} m²",
    )
    before = _counts(room)
    hard_budget = limits.single_fraction * room.floor_area
    while footprint() > hard_budget + 1e-6:  # counts asked for, beyond what a room can hold
        if not _shrink(room, floor(), max_tier=3):
            break
    phase(before, f"furniture footprint under {limits.single_fraction:.0%} of the floor at most")
    before = _counts(room)
    _drop_misfits(state, room)
    phase(before, "too big for the room")
    if in_use() > budget + 1e-6:
        names = ", ".join(o.name for o in floor())
        state.note(
            f"{room.id} keeps its {names} although they cover "
            f"{footprint() / room.floor_area:.0%} of the floor, with too little room "
            "to use them"
        )
    before = _counts(room)
    while sum(o.quantity for o in room.objects if not o.floor) > limits.max_wall_instances:
        if not _shrink(room, [o for o in room.objects if not o.floor], max_tier=4):
            break
    phase(before, f"at most {limits.max_wall_instances} wall objects per room")
    _limit_receptacles(state, room)
    for obj in room.objects:
        if obj.above is not None and room.get(obj.above) is None:
            obj.above = None
        if obj.faced_by is not None and room.get(obj.faced_by) is None:
            obj.faced_by = None
    _note_drops(state, room, start, reasons)


ESSENTIAL = 9  # template priority from which an object is essential to its room
MAX_FLOOR_INSTANCES = 56  # floor objects of one room, however many are asked for


def floor_cap(state: DraftPlan, room: DraftRoom) -> int:
    """How many floor objects the room may keep: the knowledge base's limit, raised to the
    number asked for (plus the room's defining furniture) up to ``MAX_FLOOR_INSTANCES``."""
    asked = sum(
        o.quantity for o in room.objects if o.floor and (o.requested or _tier(o, room) == 4)
    )
    return max(state.kb.limits.max_floor_instances, min(asked, MAX_FLOOR_INSTANCES))


def _tier(obj: DraftObject, room: DraftRoom) -> int:
    """Drop order: 0 optional, 2 extra essential instances and lesser essentials, 3 extra
    instances of a requested object, 4 a requested object or the room's defining object.

    The footprint limit never takes from tiers 3 and 4: counts asked for are kept exactly (the
    room grows for them when its size is open); only the hard caps on object numbers take
    extra requested instances, and those before anything the room is defined by."""
    if obj.name in room.template.defining:
        return 4
    if not obj.requested and obj.priority < ESSENTIAL:
        return 0
    if obj.requested:
        return 3 if obj.quantity > 1 else 4
    return 2 if obj.quantity > 1 or obj.priority < 10 else 4


def _shrink(room: DraftRoom, candidates: Sequence[DraftObject], max_tier: int) -> bool:
    """Take one instance from the lowest tier (False when no object of tier <= max_tier)."""
    pool = [o for o in candidates if _tier(o, room) <= max_tier]
    if not pool:
        return False
    tier = min(_tier(o, room) for o in pool)
    pool = [o for o in pool if _tier(o, room) == tier]
    if tier in (1, 3):
        victim = max(pool, key=lambda o: (o.quantity, -room.objects.index(o)))
    else:
        victim = min(pool, key=lambda o: (o.priority, -room.objects.index(o)))
    victim.quantity -= 1
    if victim.quantity <= 0:
        remove_object(room, victim)
        return True
    for dependent in room.objects:
        if dependent.per == victim.name and not dependent.requested and dependent.quantity > 1:
            share = max(1, dependent.quantity // (victim.quantity + 1))
            dependent.quantity = max(1, dependent.quantity - share)
    return True


def _downsize(state: DraftPlan, room: DraftRoom) -> bool:
    """Give the object that saves the most floor its smaller size (False: none has one)."""
    best: tuple[float, DraftObject, tuple[float, float, float]] | None = None
    for obj in room.objects:
        if not obj.floor or obj.requested:
            continue
        for size in (obj.kind.size, obj.kind.small):
            if size is None:
                continue
            saving = (obj.footprint - size[0] * size[1]) * obj.quantity
            if saving > 1e-6 and (best is None or saving > best[0]):
                best = (saving, obj, size)
    if best is None:
        return False
    _, obj, size = best
    obj.size = size
    state.note(f"made the {obj.name} in {room.id} smaller to fit: {_dims(size)}")
    return True


def _counts(room: DraftRoom) -> dict[str, tuple[int, bool, str]]:
    return {o.name: (o.quantity, o.requested, o.asked or o.name) for o in room.objects}


def _drop_misfits(state: DraftPlan, room: DraftRoom) -> None:
    """Objects that cannot stand in the room at all: longer than the room, or together covering
    more than ``single_fraction`` of it (the biggest go first)."""
    limits = state.kb.limits
    for obj in [o for o in room.objects if o.floor]:
        if not _fits_room(obj.size, room):
            smaller = [s for s in (obj.kind.size, obj.kind.small) if _fits_room(s, room)]
            if smaller:
                obj.size = smaller[0]
                shown = _dims(obj.size) if obj.size is not None else "its kind's size"
                state.note(f"made the {obj.name} in {room.id} smaller to fit: {shown}")
            else:
                remove_object(room, obj)
    while True:
        floor = [o for o in room.objects if o.floor]
        total = sum(o.footprint * o.quantity for o in floor)
        if not floor or total <= limits.single_fraction * room.floor_area:
            break
        victim = max(floor, key=lambda o: (o.footprint * o.quantity, room.objects.index(o)))
        small = victim.kind.small
        if victim.quantity == 1 and small is not None and small[0] * small[1] < victim.footprint:
            victim.size = small
            state.note(f"made the {victim.name} in {room.id} smaller to fit: {_dims(small)}")
        elif victim.quantity > 1:
            victim.quantity -= 1
        else:
            remove_object(room, victim)


def _dims(size: tuple[float, float, float]) -> str:
    return f"{size[0]:g} x {size[1]:g} m"


def _fits_room(size: tuple[float, float, float] | None, room: DraftRoom) -> bool:
    """Whether a footprint fits inside the room's rectangle (with 10 cm to spare)."""
    if size is None or room.size is None:
        return True
    long_side, short_side = max(size[0], size[1]), min(size[0], size[1])
    return long_side <= max(room.size) - 0.1 and short_side <= min(room.size) - 0.1


def _limit_receptacles(state: DraftPlan, room: DraftRoom) -> None:
    cap = state.kb.limits.max_receptacles
    holders = [o for o in room.objects if o.on_top]
    order = sorted(
        holders,
        key=lambda o: (
            any(s.requested for s in o.on_top),
            o.requested,
            o.priority,
            -room.objects.index(o),
        ),
    )
    count = sum(o.quantity for o in holders)
    for obj in order:
        if count <= cap:
            break
        # what the prompt asked for stays (the printer on one of eight desks); the rest goes
        asked = [s for s in obj.on_top if s.requested]
        obj.on_top = asked
        if not asked:
            count -= obj.quantity


def _note_drops(
    state: DraftPlan,
    room: DraftRoom,
    start: dict[str, tuple[int, bool, str]],
    reasons: dict[str, list[str]],
) -> None:
    dropped, whys = [], []
    for name, (count, requested, asked) in start.items():
        obj = room.get(name)
        now = obj.quantity if obj is not None else 0
        if now >= count:
            continue
        why = "; ".join(dict.fromkeys(reasons.get(name, ["a limit of the room"])))
        if requested:
            state.note(f"asked for '{asked}' in {room.id}; planned {now} ({why})")
        else:
            dropped.append(f"{count - now} {plural_name(name, count - now)}")
            whys.extend(reasons.get(name, []))
    if dropped:
        why = "; ".join(dict.fromkeys(whys)) or "a limit of the room"
        state.note(f"dropped {', '.join(dropped)} from {room.id} ({why})")
