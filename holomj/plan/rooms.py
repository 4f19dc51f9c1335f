"""Rooms of an offline plan: which rooms, how big, their materials and the wall height.

Room counts are drawn from the scene type and overridden by the prompt (``two-bedroom``,
``with a home office``), capped at ``max_rooms``; rooms the scene type lacks are added next to a
fitting neighbour. Areas are drawn from the templates and scaled by size words, or set by the
prompt's dimensions and areas, clamped to what the floor planner accepts. Materials come from
explicit requests, style words or the templates' lists.
"""

from __future__ import annotations

from holomj.plan.draft import DraftPlan, DraftRoom
from holomj.plan.knowledge_schema import RoomTemplate, SceneType
from holomj.plan.prompt import RoomMention

WALL_HEIGHT_LIMITS = (2.4, 4.0)


LISTED_ROOMS = 3  # a prompt naming this many kinds of room lists the rooms it wants


def make_rooms(state: DraftPlan, scene: SceneType) -> None:
    """Room instances of the scene with counts from the prompt, plus rooms it adds."""
    kb, rng, parsed = state.kb, state.rng, state.parsed
    counts: dict[str, int] = {}
    for entry in scene.rooms:
        drawn = int(rng.integers(entry.count[0], entry.count[1] + 1))
        keep = rng.random() < entry.probability
        counts[entry.id] = drawn if keep else 0
    if state.only_room is not None:  # one room asked for, alone
        counts = {e.id: int(e.template == state.only_room) for e in scene.rooms}
        alone = [e.id for e in scene.rooms if counts[e.id]]
        counts = {k: int(k == alone[0]) for k in counts} if alone else counts
    if scene.kind == "commercial" and state.only_room is None:
        _main_room_alone(state, scene, counts)
    single = len(scene.rooms) == 1 or state.only_room is not None
    # A prompt that lists its rooms ("a house with a kitchen, a dining room, a living room and
    # a bedroom") gets those rooms: each listed room once unless counted, the others of the
    # scene type only at their minimum ("a bedroom" is one bedroom, not three).
    mentions = [m for m in parsed.rooms if not _part_of_a_room(state, scene, counts, m)]
    listed = len({m.template for m in mentions if not m.excluded}) >= LISTED_ROOMS
    if listed:
        named = {m.template for m in mentions}
        for entry in scene.rooms:
            counts_as = kb.rooms[entry.template].counts_as
            if entry.template not in named and counts_as not in named:
                counts[entry.id] = entry.count[0] if entry.probability >= 1.0 else 0
    extra: dict[str, int] = {}  # template -> count, for rooms the scene type does not have
    for mention in mentions:
        template = mention.template
        direct = [e for e in scene.rooms if e.template == template]
        counted = [e for e in scene.rooms if kb.rooms[e.template].counts_as == template]
        wanted = mention.count if mention.count is not None or not listed else 1
        if single and direct and wanted is None:
            continue  # "a bedroom with ... a bedroom": the scene's own room
        if wanted == 0:
            state.note(f"no {kb.rooms[template].name}, as asked")
        fixed = sum(counts[e.id] for e in counted)
        if wanted is None:
            if not any(counts[e.id] for e in direct + counted):
                if direct:
                    counts[direct[0].id] = 1
                else:
                    extra[template] = max(extra.get(template, 0), 1)
            continue
        if wanted < fixed:
            for entry in counted:
                counts[entry.id] = 0
            fixed = 0
        if direct:
            for i, entry in enumerate(direct):
                counts[entry.id] = wanted - fixed if i == 0 else 0
        else:
            extra[template] = wanted - fixed
    _cap_rooms(state, counts, extra)
    if sum(counts.values()) + sum(extra.values()) == 0:
        first = scene.rooms[0]
        counts[first.id] = 1
        state.note(f"no room was left; planned one {kb.rooms[first.template].name}")
    _build_rooms(state, scene, counts, extra)


def _part_of_a_room(
    state: DraftPlan, scene: SceneType, counts: dict[str, int], mention: RoomMention
) -> bool:
    """Whether a room mention is no room of its own (noted): where the scene is ("a home gym in
    the garage"), or, for a room the scene type lacks, a part of one of its rooms ("a reading
    corner" in a daycare; "a small kitchen" in a studio, whose room has the kitchen's defining
    furniture already)."""
    kb = state.kb
    name = kb.rooms[mention.template].name
    if mention.location:
        state.note(f"'{mention.phrase}' says where the {scene.name} is; planned no {name} besides")
        return True
    if mention.excluded or mention.count is not None or "separate" in mention.phrase.split():
        return False
    if any(
        e.template == mention.template or kb.rooms[e.template].counts_as == mention.template
        for e in scene.rooms
        if counts.get(e.id)
    ):
        return False
    defining = set(kb.rooms[mention.template].defining)
    one_room = sum(1 for e in scene.rooms if counts.get(e.id)) == 1
    for entry in scene.rooms:
        host = kb.rooms[entry.template]
        open_plan = _open_plan(state, host)
        inside = defining <= set(host.kinds()) and open_plan
        # an area ("a reading corner") is part of a scene of one room, or of an open-plan room
        if counts.get(entry.id) and ((mention.zone and (one_room or open_plan)) or inside):
            state.note(f"planned '{mention.phrase}' as part of the {host.name}")
            return True
    return False


# The rooms of a home by function: a room template with the defining furniture of two of these
# besides its own is open plan.
HOME_FUNCTIONS = ("bedroom", "kitchen", "living_room", "dining_room", "bathroom")


def _open_plan(state: DraftPlan, host: RoomTemplate) -> bool:
    """Whether a room template serves as rooms of two or more other types (a studio: bedroom,
    kitchen and living room), so that one of those named in a prompt is an area of it."""
    kinds = set(host.kinds())
    served = [
        name
        for name in HOME_FUNCTIONS
        if name in state.kb.rooms
        and state.kb.rooms[name].type != host.type
        and set(state.kb.rooms[name].defining) <= kinds
    ]
    return len(served) >= 2


def _main_room_alone(state: DraftPlan, scene: SceneType, counts: dict[str, int]) -> None:
    """A commercial scene (a hotel room, a restaurant) is its main room: the rooms that serve it
    (an en-suite bathroom, a kitchen) are planned only when the prompt names them."""
    kb = state.kb
    named = {m.template for m in state.parsed.rooms if not m.excluded}
    dropped = []
    for entry in scene.rooms:
        template = kb.rooms[entry.template]
        if entry.id == scene.entrance or entry.template in named or template.counts_as in named:
            continue
        if counts.get(entry.id):
            dropped.append(template.name)
        counts[entry.id] = 0
    if dropped:
        state.note(
            f"planned the {scene.name} as its main room; no {', no '.join(dropped)} (not asked for)"
        )


def _cap_rooms(state: DraftPlan, counts: dict[str, int], extra: dict[str, int]) -> None:
    """At most ``max_rooms`` rooms: take one from the most numerous kind until it fits."""
    cap = state.kb.limits.max_rooms
    total = sum(counts.values()) + sum(extra.values())
    if total <= cap:
        return
    state.note(f"asked for {total} rooms; planned {cap} (at most {cap} rooms per scene)")
    while total > cap:
        merged = {
            **{("scene", k): n for k, n in counts.items()},
            **{("extra", k): n for k, n in extra.items()},
        }
        side, key = max(merged, key=lambda k: (merged[k], k))
        (counts if side == "scene" else extra)[key] -= 1
        total -= 1


def _build_rooms(
    state: DraftPlan, scene: SceneType, counts: dict[str, int], extra: dict[str, int]
) -> None:
    kb = state.kb
    taken: set[str] = set()
    first_id: dict[str, str] = {}
    for entry in scene.rooms:
        for _ in range(counts[entry.id]):
            room_id = _unique(entry.id, taken)
            first_id.setdefault(entry.id, room_id)
            template = kb.rooms[entry.template]
            state.rooms.append(DraftRoom(room_id, entry.template, template, entry_id=entry.id))
    entries = {entry.id: entry for entry in scene.rooms}
    for room in state.rooms:
        if room.entry_id is None:  # every room so far is of a scene type's entry
            continue
        wishes = [first_id[a] for a in entries[room.entry_id].adjacent_to if a in first_id]
        room.adjacent_to = [w for w in dict.fromkeys(wishes) if w != room.id]
    for template_id, n in extra.items():
        for _ in range(n):
            template = kb.rooms[template_id]
            room = DraftRoom(_unique(template_id, taken), template_id, template)
            neighbour = _neighbour(state, template)
            if neighbour is not None:
                room.adjacent_to = [neighbour]
            state.rooms.append(room)
            state.note(f"added a {template.name} ('{room.id}') as asked")


def _unique(base: str, taken: set[str]) -> str:
    name, k = base, 2
    while name in taken:
        name, k = f"{base}_{k}", k + 1
    taken.add(name)
    return name


def _neighbour(state: DraftPlan, template: RoomTemplate) -> str | None:
    """The room an added room should touch: the first of its template's neighbours present."""
    for wanted in template.neighbours:
        for room in state.rooms:
            if room.template_id == wanted or room.template.counts_as == wanted:
                return room.id
    return state.rooms[0].id if state.rooms else None


def size_rooms(state: DraftPlan) -> None:
    """Areas from the templates (jittered, scaled by size words) or the prompt's sizes."""
    parsed, limits, rng = state.parsed, state.kb.limits, state.rng
    mentions = {}
    for asked in parsed.rooms:
        room = next((r for r in state.rooms if r.template_id == asked.template), None)
        if room is not None and room.id not in mentions:
            mentions[room.id] = asked
    for room in state.rooms:
        lo, hi = room.template.area
        room.area = float(rng.uniform(lo, hi))
        mention = mentions.get(room.id)
        word = mention.size_word if mention is not None else None
        if word is None and room.entry_id is not None:
            word = parsed.size_word
        room.area *= limits.size_words.get(word or "", 1.0)
        if mention is not None and mention.dims is not None:
            _exact_size(state, room, mention.dims, mention.phrase)
        elif mention is not None and mention.area_m2 is not None:
            _exact_area(state, room, mention.area_m2, mention.phrase)
    if parsed.dims is not None or parsed.area_m2 is not None:
        _scene_size(state, parsed.dims, parsed.area_m2)
    for room in state.rooms:
        if room.size is None:
            room.area = round(_clamp(room.area, limits.min_area, limits.max_area), 1)


def _scene_size(state: DraftPlan, dims: tuple[float, float] | None, area: float | None) -> None:
    """The prompt's size: the room's, in a one-room scene; else shared out over the rooms."""
    limits = state.kb.limits
    what = _size_text(dims, area)
    free = [r for r in state.rooms if not r.fixed]
    if len(state.rooms) == 1 and free:
        if dims is not None:
            _exact_size(state, free[0], dims, what)
        else:
            _exact_area(state, free[0], area or 0.0, what)
        return
    if not free:
        return
    if area is not None:
        total = area
    elif dims is not None:
        total = dims[0] * dims[1]
    else:
        return
    fixed = sum(r.floor_area for r in state.rooms if r.fixed)
    share = sum(r.area for r in free)
    for room in free:
        room.area *= max(total - fixed, 0.0) / share
        room.fixed = True
    planned = fixed + sum(_clamp(r.area, limits.min_area, limits.max_area) for r in free)
    if abs(planned - total) > 0.05 * total:
        state.note(
            f"{what} cannot hold these {len(state.rooms)} rooms with sides of "
            f"{limits.min_side:g}-{limits.max_side:g} m; planned {planned:.0f} m² in all"
        )


def _size_text(dims: tuple[float, float] | None, area: float | None) -> str:
    if dims is not None:
        return f"{dims[0]:g} x {dims[1]:g} m"
    return f"{area:g} m²"


def _exact_size(state: DraftPlan, room: DraftRoom, dims: tuple[float, float], what: str) -> None:
    limits = state.kb.limits
    sides = tuple(round(_clamp(s, limits.min_side, limits.max_side), 2) for s in dims)
    if sides != tuple(round(s, 2) for s in dims):
        state.note(
            f"'{what}' for the {room.template.name} is outside the {limits.min_side:g}-"
            f"{limits.max_side:g} m the floor planner accepts per side; planned "
            f"{sides[0]:g} x {sides[1]:g} m"
        )
    room.size = (sides[0], sides[1])
    room.area = sides[0] * sides[1]
    room.fixed = True


def _exact_area(state: DraftPlan, room: DraftRoom, area: float, what: str) -> None:
    limits = state.kb.limits
    clamped = round(_clamp(area, limits.min_area, limits.max_area), 1)
    if abs(clamped - area) > 0.05:
        state.note(
            f"'{what}' for the {room.template.name} is outside the {limits.min_area:g}-"
            f"{limits.max_area:g} m² a room may have; planned {clamped:g} m²"
        )
    room.area = clamped
    room.fixed = True


def _clamp(value: float, lo: float, hi: float) -> float:
    return min(max(value, lo), hi)


def entrance_room(state: DraftPlan, scene: SceneType) -> str:
    """The first room from the scene type's entrance entry, else the first room."""
    for room in state.rooms:
        if room.id == scene.entrance or room.id.startswith(f"{scene.entrance}_"):
            return room.id
    return state.rooms[0].id


def choose_wall_height(state: DraftPlan, scene: SceneType) -> float:
    """The prompt's ceiling height (clamped), else drawn from the style's or scene's span."""
    parsed, rng = state.parsed, state.rng
    if parsed.wall_height_m is not None:
        height = _clamp(parsed.wall_height_m, *WALL_HEIGHT_LIMITS)
        if abs(height - parsed.wall_height_m) > 1e-6:
            state.note(
                f"a {parsed.wall_height_m:g} m ceiling is outside {WALL_HEIGHT_LIMITS[0]:g}-"
                f"{WALL_HEIGHT_LIMITS[1]:g} m; planned {height:g} m"
            )
        return round(height, 2)
    span = scene.wall_height
    for style in parsed.styles:
        style_span = state.kb.styles[style].wall_height
        if style_span is not None:
            span = style_span
            break
    return round(round(float(rng.uniform(span[0], span[1])) / 0.05) * 0.05, 2)


def pick_materials(state: DraftPlan, room: DraftRoom) -> None:
    """Floor, wall and ceiling: the prompt's, else drawn from the style's or template's list."""
    parsed, kb, rng = state.parsed, state.kb, state.rng
    for surface in ("floor", "wall", "ceiling"):
        choices = list(getattr(room.template, surface))
        if not (surface == "floor" and room.template.fixed_floor):
            for style in parsed.styles:
                options = getattr(kb.styles[style], surface)
                if options:
                    choices = list(options)
                    break
        value = choices[int(rng.integers(len(choices)))]
        setattr(room, surface, parsed.materials.get(surface, value))
