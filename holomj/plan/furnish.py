"""Template furniture of an offline plan: objects, small objects on receptacles, seats, windows.

Each room gets its template's objects (one variant, optional ones drawn in or out, quantities
drawn in their ranges, per-anchor counts multiplied out) and small objects on its receptacles
(the template's list, or drawn from the knowledge base's table). ``for 8 people`` sets the seats
of the first room with seats; a window count goes to the largest room.
"""

from __future__ import annotations

import math

import numpy as np

from holomj.plan.draft import (
    MAX_QUANTITY,
    DraftObject,
    DraftPlan,
    DraftRoom,
    DraftSmall,
    plural_name,
    remove_object,
)
from holomj.plan.knowledge_schema import ObjectKind, TemplateObject
from holomj.plan.seating import seat_pairs


def furnish(state: DraftPlan, room: DraftRoom) -> None:
    """Objects of the room's template: one variant, optional ones drawn, quantities drawn."""
    rng, kb = state.rng, state.kb
    template = room.template
    entries, lines = list(template.objects), list(template.constraints)
    if template.variants:
        weights = np.array([v.weight for v in template.variants], dtype=float)
        variant = template.variants[int(rng.choice(len(weights), p=weights / weights.sum()))]
        entries += variant.objects
        lines += variant.constraints
    room.lines = lines
    for entry in entries:
        keep = rng.random() < entry.probability
        count = int(rng.integers(entry.quantity[0], entry.quantity[1] + 1))
        variance = entry.variance
        if variance == "random":
            variance = "same" if rng.random() < 0.5 else "varied"
        anchor = room.get(entry.per) if entry.per is not None else None
        if not keep or (entry.per is not None and anchor is None):
            continue
        if anchor is not None:
            count *= anchor.quantity
        if entry.above is not None and room.get(entry.above) is None:
            continue
        if count <= 0:
            continue
        kind = kb.objects[entry.object]
        obj = DraftObject(
            name=entry.object,
            kind=kind,
            quantity=min(count, MAX_QUANTITY),
            priority=entry.priority,
            variance=variance,
            size=kind.size_for(entry.size),
            per=entry.per,
            per_max=entry.quantity[1],
            seat=entry.seat,
            above=entry.above,
        )
        obj.on_top = draw_on_top(state, room, entry, kind)
        room.objects.append(obj)


def draw_on_top(
    state: DraftPlan, room: DraftRoom, entry: TemplateObject | None, kind: ObjectKind
) -> list[DraftSmall]:
    """Small objects for one receptacle: the template's list, or drawn from the table."""
    rng, kb = state.rng, state.kb
    cap = kb.limits.max_small_per_receptacle
    out: list[DraftSmall] = []
    spec = entry.on_top if entry is not None else "auto"
    if spec is None:
        return out
    if spec == "auto":
        choices = [
            (c, w)
            for c, w in kb.small_choices(room.template.type, kind.category)
            if kb.kinds_of_category(c, "object")
        ]
        if not choices:
            return out
        weights = np.array([w for _, w in choices], dtype=float)
        if weights.sum() <= 0:
            return out
        n = min(len(choices), int(rng.integers(1, 3)))
        picks = rng.choice(len(choices), size=n, replace=False, p=weights / weights.sum())
        for pick in sorted(int(p) for p in picks):
            category = choices[pick][0]
            name = kb.kinds_of_category(category, "object")[0]
            out.append(DraftSmall(name, category, int(rng.integers(1, 3))))
    else:
        for item in spec:
            keep = rng.random() < item.probability
            count = int(rng.integers(item.quantity[0], item.quantity[1] + 1))
            if keep and count > 0:
                small = kb.objects[item.object]
                out.append(DraftSmall(item.object, small.category, count, item.variance))
    return _trim_small(out, cap)


def _trim_small(items: list[DraftSmall], cap: int) -> list[DraftSmall]:
    """Keep at most ``cap`` small objects per receptacle instance, requested ones first."""
    order = sorted(range(len(items)), key=lambda i: (not items[i].requested, i))
    left = cap
    kept: dict[int, DraftSmall] = {}
    for i in order:
        if left <= 0:
            break
        take = min(items[i].quantity, left)
        items[i].quantity = take
        kept[i] = items[i]
        left -= take
    return [kept[i] for i in sorted(kept)]


def apply_capacity(state: DraftPlan) -> None:
    """``for 8 people``: seats (and the tables they belong to) of the first room with seats."""
    capacity = state.parsed.capacity
    if not capacity:
        return
    room = next((r for r in state.rooms if any(o.seat for o in r.objects)), None)
    if room is None and not _seat_the_table(state, capacity):
        state.note(f"seating for {capacity} was asked, but no room of this plan has seats")
        return
    if room is None:
        return
    seats = [o for o in room.objects if o.seat]
    seat = next((o for o in seats if o.per is not None), seats[0])
    if seat.requested:  # the prompt's own count of seats stands
        return
    anchor = room.get(seat.per) if seat.per is not None else None
    asked = f"seating for {capacity}"
    if anchor is not None and not anchor.requested:  # a table asked for stays one
        anchor.quantity = min(MAX_QUANTITY, max(1, math.ceil(capacity / max(1, seat.per_max))))
        anchor.requested = True
        anchor.asked = f"{asked}: {anchor.quantity} {plural_name(anchor.name, anchor.quantity)}"
    seat.quantity = min(MAX_QUANTITY, capacity)
    seat.requested = True
    seat.asked = f"{asked}: {seat.quantity} {plural_name(seat.name, seat.quantity)}"
    seat.per = None


def _seat_the_table(state: DraftPlan, capacity: int) -> bool:
    """``a dining table for two`` in a room without seats: the table's own seats, as many as
    asked; False when no room has a table with seats of its own."""
    for room in state.rooms:
        for table in room.objects:
            seats = seat_pairs(state.kb).get(table.name)
            if not seats:
                continue
            kind = state.kb.objects[seats[0]]
            seat = DraftObject(seats[0], kind, min(MAX_QUANTITY, capacity), variance="same")
            seat.size, seat.seat, seat.requested = kind.size, True, True
            seat.asked = f"seating for {capacity} at the {table.name}"
            room.objects.append(seat)
            return True
    return False


def apply_windows(state: DraftPlan) -> None:
    """Template window counts; the prompt's count (at most 12) goes to the largest room."""
    windows = state.parsed.windows
    for room in state.rooms:
        room.windows = room.template.windows
    if windows is None:
        return
    if windows == 0:
        for room in state.rooms:
            room.windows = 0
        state.note("no windows, as asked")
        return
    main = max(state.rooms, key=lambda r: r.floor_area)
    main.windows = min(windows, 12)
    if windows > 12:
        state.note(f"asked for {windows} windows; planned 12 in the {main.template.name}")


WINDOW_DRESSINGS = frozenset({"curtains", "blinds"})
MAX_WINDOWS = 12


def apply_window_dressings(state: DraftPlan) -> None:
    """Curtains and blinds asked for dress the room's windows: one per window unless the prompt
    counts them; a room with fewer windows than dressings gets windows added (not when the
    prompt wants no windows: then the dressings are left out, noted)."""
    counted = {
        state.request_homes[i][:2]: request.quantity
        for i, request in enumerate(state.parsed.objects)
        if i in state.request_homes and request.quantity is not None
    }
    for room in state.rooms:
        for obj in list(room.objects):
            if obj.kind.category not in WINDOW_DRESSINGS:
                continue
            if state.parsed.windows == 0:
                remove_object(room, obj)
                state.note(f"left out the {obj.name} of the {room.template.name}: no windows asked")
                continue
            wanted = counted.get((room.id, obj.name))
            default = 1 if room.windows is None else max(1, room.windows)
            obj.quantity = min(MAX_WINDOWS, wanted if wanted is not None else default)
            if room.windows is None and obj.quantity == 1:
                continue  # the room type's default windows (one at least, on an outside wall)
            if room.windows is None or room.windows < obj.quantity:
                state.note(
                    f"gave the {room.template.name} {obj.quantity} window(s) for the {obj.name} "
                    f"asked for (it had {room.windows or 'the default'})"
                )
                room.windows = obj.quantity
