"""The prompt's object requests, merged into the rooms of an offline plan.

Requested objects go to the room they were asked in, else the roomiest room that has (or would
have) them, else the roomiest room of a type they belong in, else the scene's largest room;
generic words (``chair``) become the kind that room uses; unknown words take the nearest known
kind or stay themselves (:mod:`~holomj.plan.new_kinds`); excluded objects (``without a tv``) are
removed; small objects go onto the room's receptacles, adding one when it has none. Counts: a
number as given ("a pair of" is 2, "a few" and "several" 3), "lots of" the kind's ``many``, and a
plural without a number 2, 3 or 4 by the room's floor area (:data:`PLURAL_AREAS_M2`).
"""

from __future__ import annotations

from holomj.plan.draft import (
    MAX_QUANTITY,
    DraftObject,
    DraftPlan,
    DraftRoom,
    DraftSmall,
    plural_name,
    remove_object,
    spread,
)
from holomj.plan.furnish import draw_on_top
from holomj.plan.knowledge_schema import ObjectKind
from holomj.plan.new_kinds import resolve_unknown
from holomj.plan.prompt import ObjectRequest
from holomj.plan.seating import is_seat_word, seat_for, seating_links, seating_table


def apply_requests(state: DraftPlan) -> None:
    """The prompt's objects: merged into rooms, excluded ones removed, unknown ones matched."""
    parsed = state.parsed
    requests = list(parsed.objects)
    for phrase in parsed.unknown:
        kind = resolve_unknown(state, phrase)
        if kind is not None:
            requests.append(ObjectRequest(kind=kind, quantity=1, phrase=phrase))
    for refused in parsed.refused:
        state.note(f"'{refused.phrase}': {refused.reason}")
    # requests the prompt puts on something ("a lamp on the desk", "a desk with a lamp")
    put_on = {r.subject for r in parsed.relations if r.kind == "on"} | {
        r.target for r in parsed.relations if r.kind == "holds" and r.target is not None
    }
    on_wall = {r.subject for r in parsed.relations if r.kind == "wall" and r.phrase[:3] == "on "}
    seats = seating_links(state.kb, requests, parsed.relations)
    for index, request in enumerate(requests):
        if request.excluded or request.quantity == 0:
            _exclude(state, request)
            continue
        reference = _reference(state, request) if request.definite else None
        if reference is not None:  # "the bed" after "a queen bed": the same bed
            state.request_homes[index] = reference
            continue
        for room in _request_rooms(state, request):
            _request_in(state, requests, index, room, put_on, on_wall, seats)


def _request_in(
    state: DraftPlan,
    requests: list[ObjectRequest],
    index: int,
    room: DraftRoom,
    put_on: set[int],
    on_wall: set[int],
    seats: dict[int, int],
) -> None:
    """Request ``index`` merged into ``room``."""
    request = requests[index]
    name = _resolve_kind(state, request, room, index in put_on)
    if index in on_wall:
        _hang_flat_kind(state, name)
    paired = None
    if request.generic and index in set(seats.values()):  # "a table with four chairs"
        paired = seating_table(state.kb, request.kind, _present(room))
    elif index in seats:  # "six chairs around the table": the seat that goes with it
        table = _table_kind(state, requests[seats[index]], room)
        paired = seat_for(state.kb, request.kind, table, _present(room))
    elif is_seat_word(state.kb, request) and room.get(name) is None:
        paired = _seat_at_room_table(state, request, room)
    if paired is not None and paired not in _taken(room, request):
        name = paired
    kind = state.object_kind(name)
    quantity = _quantity(request, kind, room)
    if kind.placement == "object":
        _add_small(state, room, name, kind, quantity)
    else:
        _add_object(state, room, name, kind, quantity, request)
    state.request_homes.setdefault(index, (room.id, name, kind.placement == "object"))


def _request_rooms(state: DraftPlan, request: ObjectRequest) -> list[DraftRoom]:
    """The rooms a request goes to: every room of its template for "two bedrooms each with a
    bunk bed", else the one room :func:`_request_room` picks."""
    if request.each_room and request.room is not None:
        rooms = [r for r in state.rooms if request.room in (r.template_id, r.template.counts_as)]
        if rooms:
            return rooms
    return [_request_room(state, request)]


def _reference(state: DraftPlan, request: ObjectRequest) -> tuple[str, str, bool] | None:
    """The object an earlier request of the same kind put in a room, for ``the <kind>``."""
    kinds = state.kb.generics[request.kind].kinds if request.generic else [request.kind]
    for room_id, name, small in state.request_homes.values():
        if name in kinds:
            return room_id, name, small
    # "each bench" after "four lab benches": the same head noun
    for room_id, name, small in state.request_homes.values():
        if any(name.endswith(f" {kind}") for kind in kinds):
            return room_id, name, small
    return None


# A plural without a number ("bookshelves", "some chairs"): 2 in a room under the first area,
# 3 under the second, else 4.
PLURAL_AREAS_M2 = (15.0, 30.0)


def _quantity(request: ObjectRequest, kind: ObjectKind, room: DraftRoom) -> int:
    if request.quantity is not None:
        return request.quantity
    if request.many:
        return kind.many
    if not request.plural:
        return 1
    return 2 + sum(room.floor_area >= a for a in PLURAL_AREAS_M2)


def _request_room(state: DraftPlan, request: ObjectRequest) -> DraftRoom:
    """The room an object is asked in, else the roomiest room that has (or would have) it, else
    the roomiest room of a type it belongs in, else the scene's main room (its largest)."""
    if request.room is not None:
        for room in state.rooms:
            if room.template_id == request.room:
                return room
    kinds = state.kb.generics[request.kind].kinds if request.generic else [request.kind]
    for want in kinds:
        homes = [r for r in state.rooms if r.get(want) is not None or want in r.template.kinds()]
        if homes:
            return max(homes, key=lambda r: (_free_floor(state, r), -state.rooms.index(r)))
    belongs = {t for want in kinds for t in state.object_kind(want).rooms}
    homes = [r for r in state.rooms if r.template_id in belongs]
    if homes:
        return max(homes, key=lambda r: (_free_floor(state, r), -state.rooms.index(r)))
    # the scene's main room: its largest
    return max(state.rooms, key=lambda r: (r.floor_area, -state.rooms.index(r)))


def _free_floor(state: DraftPlan, room: DraftRoom) -> float:
    """Floor area left under the footprint limit by the room's furniture so far."""
    used = sum(o.footprint * o.quantity for o in room.objects if o.floor)
    return state.kb.limits.footprint_fraction * room.floor_area - used


def _resolve_kind(
    state: DraftPlan, request: ObjectRequest, room: DraftRoom, put_on: bool = False
) -> str:
    """A generic word (``chair``) as the kind the room has, else the first kind it may mean; put
    on something (``a lamp on the desk``), the first small kind it may mean."""
    if not request.generic:
        return request.kind
    kinds = state.kb.generics[request.kind].kinds
    if put_on:
        small = [k for k in kinds if state.kb.objects[k].placement == "object"]
        if small:
            return small[0]
    taken = _taken(room, request)
    for want in kinds:
        if room.get(want) is not None and want not in taken:
            return want
    for want in kinds:
        if want in room.template.kinds() and want not in taken:
            return want
    return next((want for want in kinds if want not in taken), kinds[0])


def _taken(room: DraftRoom, request: ObjectRequest) -> set[str]:
    """The kinds of ``room`` another phrase asked for: a generic word does not mean them ("an
    office chair and two chairs for visitors" are three seats), unless it refers back to one
    ("the chair")."""
    if request.definite:
        return set()
    return {o.name for o in room.objects if o.requested and o.asked != request.phrase}


FLAT_M = 0.05  # a small object this thin (a chart, a map, a print) can hang on a wall


def _hang_flat_kind(state: DraftPlan, name: str) -> None:
    """A flat small kind asked for "on the wall" (a star chart) becomes a wall object of the same
    category for this plan: its top face turned to face the room."""
    kind = state.object_kind(name)
    if kind.placement != "object" or kind.size is None or kind.size[2] > FLAT_M:
        return
    width, depth, height = kind.size
    state.new_kinds[name] = kind.model_copy(
        update={"placement": "wall", "size": (width, height, depth), "receptacle": False}
    )
    state.note(f"the {name} asked for on the wall hangs there (a wall object)")


def _present(room: DraftRoom) -> list[str]:
    """The room's kinds in order of preference: those it has, then its template's."""
    return [o.name for o in room.objects] + room.template.kinds()


def _seat_at_room_table(state: DraftPlan, request: ObjectRequest, room: DraftRoom) -> str | None:
    """For seats the room does not have yet: the seat that goes with a table it has."""
    for obj in room.objects:
        seat = seat_for(state.kb, request.kind, obj.name, _present(room))
        if seat is not None:
            return seat
    return None


def _table_kind(state: DraftPlan, table: ObjectRequest, room: DraftRoom) -> str:
    """The kind a table request means, as seats around it see it (resolved the same way as the
    table itself, whichever of the two the prompt names first)."""
    if not table.generic:
        return table.kind
    chosen = seating_table(state.kb, table.kind, _present(room))
    return chosen or _resolve_kind(state, table, room)


def _exclude(state: DraftPlan, request: ObjectRequest) -> None:
    kinds = state.kb.generics[request.kind].kinds if request.generic else [request.kind]
    removed = 0
    for room in state.rooms:
        if request.room is not None and room.template_id != request.room:
            continue
        for obj in list(room.objects):
            if obj.name in kinds:
                removed += obj.quantity
                remove_object(room, obj)
        for obj in room.objects:
            obj.on_top = [s for s in obj.on_top if s.name not in kinds]
    what = request.phrase or request.kind
    state.note(f"left out '{what}' as asked" if removed else f"no '{what}' planned, as asked")


def _add_object(
    state: DraftPlan,
    room: DraftRoom,
    name: str,
    kind: ObjectKind,
    quantity: int,
    request: ObjectRequest,
) -> None:
    if quantity > MAX_QUANTITY:
        state.note(
            f"asked for '{request.phrase or name}' in {room.id}; planned {MAX_QUANTITY} "
            f"(at most {MAX_QUANTITY} of one kind per room)"
        )
        quantity = MAX_QUANTITY
    obj = room.get(name)
    size = kind.size_for(request.size)
    if obj is None:
        _replace_same_category(state, room, name, kind, request)
    if obj is None:
        variance = kind.variance if quantity > 1 else "same"
        obj = DraftObject(name=name, kind=kind, quantity=quantity, variance=variance)
        obj.size = size
        if kind.placement == "wall" and name == "television" and room.get("tv stand") is not None:
            obj.above = "tv stand"
        if kind.placement == "floor" and state.kb.is_receptacle(kind.category):
            obj.on_top = draw_on_top(state, room, None, kind)
        room.objects.append(obj)
    elif obj.requested and obj.asked != request.phrase and not request.definite:
        obj.quantity = min(MAX_QUANTITY, obj.quantity + quantity)  # asked for again, elsewhere
    else:
        obj.quantity = quantity
        if request.size is not None:
            obj.size = size
    obj.requested = True
    obj.per = None
    obj.adjectives = list(request.adjectives)
    obj.parts = list(request.parts)
    obj.asked = request.phrase


def _replace_same_category(
    state: DraftPlan, room: DraftRoom, name: str, kind: ObjectKind, request: ObjectRequest
) -> None:
    """A requested kind takes the place of the template's object of the same category (a
    twin bed asked for is the room's bed, not a second one); a generic word asked for takes the
    place of the template's kinds that are named by it ("ten chairs" in a meeting room are its
    chairs: the template's office chairs go)."""
    named = _named_by_generic(state, request)
    for other in list(room.objects):
        if other.requested or other.name == name:
            continue
        same = other.kind.category == kind.category and other.kind.placement == kind.placement
        generic = other.name in named and other.kind.placement == kind.placement
        if same or generic or _another_bed(other.kind, kind):
            remove_object(room, other)
            state.note(f"the {name} asked for takes the place of the {other.name} in {room.id}")


def _named_by_generic(state: DraftPlan, request: ObjectRequest) -> set[str]:
    """The kinds of a generic request whose names end in its word ("office chair" for
    "chairs"; not "armchair" or "stool", which the word only stands for at a stretch)."""
    if not request.generic or request.kind not in state.kb.generics:
        return set()
    word = request.kind.split()[-1]
    return {k for k in state.kb.generics[request.kind].kinds if k.split()[-1] == word}


BED_CATEGORIES = frozenset({"bed", "bunk_bed", "single_bed", "crib", "hospital_bed", "loft_bed"})


def _another_bed(template: ObjectKind, asked: ObjectKind) -> bool:
    """Whether the kind asked for is another bed for the room's own bed (a bunk bed asked for
    in a bedroom is its bed, not a second one)."""
    return template.category in BED_CATEGORIES and asked.category in BED_CATEGORIES


def _add_small(
    state: DraftPlan, room: DraftRoom, name: str, kind: ObjectKind, quantity: int
) -> None:
    """Put requested small objects on the room's receptacles (adding one when it has none)."""
    kb = state.kb
    cap = kb.limits.max_small_per_receptacle
    # a kind made for an unknown noun goes where the known kind it is like goes
    like = kb.objects[state.like[name]].category if name in state.like else kind.category

    def weight(obj: DraftObject) -> float:
        return dict(kb.small_choices(room.template.type, obj.kind.category)).get(like, 0)

    for obj in room.objects:  # what is asked for replaces the template's own
        obj.on_top = [s for s in obj.on_top if s.requested or s.name != name]
    holders = sorted(
        (o for o in room.objects if o.floor and weight(o) > 0), key=lambda o: -weight(o)
    )
    if not holders:  # none lists it for this room type: one that holds it in some room type
        holders = sorted(
            (o for o in room.objects if o.floor and like in kb.allowed_small(o.kind.category)),
            key=lambda o: -o.footprint,
        )[:1]
    if not holders:
        holder_kind = _receptacle_for(state, room, like) or _any_receptacle(state, room, like)
        if holder_kind is None:
            state.note(
                f"no receptacle in the knowledge base holds {plural_name(name, 2)}; left out"
            )
            return
        holder = DraftObject(holder_kind, kb.objects[holder_kind], 1, priority=9)
        holder.size = holder.kind.size
        room.objects.append(holder)
        holders = [holder]
        state.note(f"added a {holder_kind} to the {room.template.name} to hold the {name}")
    left = quantity
    for holder in holders:
        if left <= 0:
            break
        holder.on_top = [s for s in holder.on_top if s.requested]
        room_left = cap - sum(s.quantity for s in holder.on_top)
        each, instances = spread(left, holder.quantity)
        each = min(room_left, each)
        if each <= 0:
            continue
        existing = next((s for s in holder.on_top if s.name == name), None)
        if existing is not None:
            existing.quantity += each
            existing.instances = None
            instances = None
        else:
            holder.on_top.append(
                DraftSmall(name, kind.category, each, kind.variance, True, instances)
            )
        left -= each * (instances or holder.quantity)
    if left > 0:
        placed = quantity - left
        state.note(
            f"asked for {quantity} {plural_name(name, quantity)}; {max(placed, 0)} fit on the "
            f"receptacles of the {room.template.name} (at most {cap} on each)"
        )


def _any_receptacle(state: DraftPlan, room: DraftRoom, category: str) -> str | None:
    """The floor kind with the largest top that holds ``category`` in some room type, those
    that belong in this room first (a counter for a microwave in a cafe)."""
    kb = state.kb
    kinds = [
        k
        for k, kind in kb.objects.items()
        if kind.placement == "floor" and category in kb.allowed_small(kind.category)
    ]
    if not kinds:
        return None

    def rank(name: str) -> tuple[bool, float]:
        width, depth, _ = kb.objects[name].size or (0.0, 0.0, 0.0)
        return room.template_id in kb.objects[name].rooms, width * depth

    return max(kinds, key=rank)


def _receptacle_for(state: DraftPlan, room: DraftRoom, category: str) -> str | None:
    """The floor kind that best holds ``category`` in this room type."""
    kb = state.kb
    best: tuple[float, str] | None = None
    for name, kind in kb.objects.items():
        if kind.placement != "floor":
            continue
        weight = dict(kb.small_choices(room.template.type, kind.category)).get(category, 0.0)
        if weight > 0 and (best is None or weight > best[0]):
            best = (weight, name)
    return best[1] if best is not None else None
