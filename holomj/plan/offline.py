"""The offline planner: prompt text + seed -> ScenePlan, from the knowledge base, no network.

Steps, each drawing from one generator (``stage_rng(seed, "plan")``) in a fixed order, so the
same prompt and seed give the same plan:

1. **Scene type**: the keyword the prompt's head names (``a small kitchen``), refined by words
   anywhere (``an office for a professor``); rooms named without a scene (``3 bedrooms and a
   bathroom``) make a home; anything else goes to the nearest scene type by text-embedding
   similarity over names, descriptions and keywords (the encoder is loaded only then).
2. **Rooms**: the scene type's rooms with drawn counts, overridden by the prompt's counts
   (``two-bedroom``), plus rooms it names (``with a home office``) next to a fitting neighbour;
   areas drawn from the templates, scaled by size words, or the prompt's dimensions, clamped to
   what the floor planner accepts.
3. **Materials and wall height** from explicit requests (``oak floor``), style words, or the
   templates' lists.
4. **Furniture** from the room templates (optional objects in or out, quantities in ranges,
   one variant of the template), then the prompt's requests (``two armchairs``, ``lots of
   plants``, ``without a tv``, ``for 8 people``, small objects onto receptacles).
5. **Fit**: at most ``max_floor_instances`` floor objects, a floor footprint under
   ``footprint_fraction`` of the room (rooms whose size was not given grow for requested
   objects), at most ``max_wall_instances`` wall objects and ``max_receptacles`` receptacles with
   small objects; optional, low-priority objects go first, requested ones last. Every drop is
   noted.
6. **Constraints**: the templates' lines (or each kind's defaults) written per instance, with
   targets spread over the target's instances and lines to absent objects left out.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

from holomj.errors import InputError
from holomj.generate.seeds import stage_rng
from holomj.plan.knowledge import (
    KnowledgeBase,
    ObjectKind,
    RoomTemplate,
    SceneType,
    TemplateObject,
    knowledge_base,
)
from holomj.plan.prompt import ObjectRequest, ParsedPrompt, parse_prompt
from holomj.retrieval.text import TextEncoder
from holomj.spec.plan import (
    PlanObject,
    PlanRoom,
    PlanSmallObject,
    PlanWindows,
    ScenePlan,
    instance_name,
)

MAX_PROMPT_CHARS = 2000
HOME_SCENE = "apartment"  # the scene type for rooms named without one
OBJECT_MATCH_MIN = 0.5  # cosine similarity for an unknown object word to take a known kind
WALL_HEIGHT_LIMITS = (2.4, 4.0)
MAX_NOTES = 200
MAX_QUANTITY = 40  # PlanObject's limit


# ---------------------------------------------------------------------------------------------
# Working state


@dataclass
class _Small:
    name: str
    category: str
    quantity: int
    variance: str = "varied"
    requested: bool = False


@dataclass
class _Obj:
    name: str
    kind: ObjectKind
    quantity: int
    priority: int = 5
    variance: str = "same"
    size: tuple[float, float, float] | None = None
    requested: bool = False
    per: str | None = None
    per_max: int = 1
    seat: bool = False
    above: str | None = None
    on_top: list[_Small] = field(default_factory=list)
    adjectives: list[str] = field(default_factory=list)
    asked: str = ""  # the prompt's words for a requested object

    @property
    def floor(self) -> bool:
        return self.kind.placement == "floor"

    @property
    def footprint(self) -> float:
        size = self.size or self.kind.size or (0.0, 0.0, 0.0)
        return size[0] * size[1]


@dataclass
class _Room:
    id: str
    template_id: str
    template: RoomTemplate
    entry_id: str | None = None  # the scene type's room entry it comes from, if any
    adjacent_to: list[str] = field(default_factory=list)
    size: tuple[float, float] | None = None
    area: float = 0.0
    fixed: bool = False
    objects: list[_Obj] = field(default_factory=list)
    lines: list[str] = field(default_factory=list)
    floor: str = ""
    wall: str = ""
    ceiling: str = ""
    windows: int | None = None

    def get(self, name: str) -> _Obj | None:
        return next((o for o in self.objects if o.name == name), None)

    @property
    def floor_area(self) -> float:
        return self.size[0] * self.size[1] if self.size is not None else self.area


@dataclass
class _Plan:
    kb: KnowledgeBase
    rng: np.random.Generator
    parsed: ParsedPrompt
    encoder: TextEncoder | None
    notes: list[str] = field(default_factory=list)
    rooms: list[_Room] = field(default_factory=list)

    def note(self, text: str) -> None:
        if text not in self.notes:
            self.notes.append(text)

    def text_encoder(self) -> TextEncoder:
        if self.encoder is None:
            from holomj.retrieval.text import text_encoder

            self.encoder = text_encoder()
        return self.encoder


# ---------------------------------------------------------------------------------------------
# Entry point


def plan_offline(prompt: str, seed: int, *, encoder: TextEncoder | None = None) -> ScenePlan:
    """Plan the scene a prompt asks for, with the knowledge base alone (no network, no key).

    ``encoder`` matches scene types and object words the knowledge base does not name
    (default: :func:`holomj.retrieval.text.text_encoder`, loaded only when needed). Raises
    :class:`~holomj.errors.InputError` for an empty prompt, one over 2,000 characters, or a
    negative seed.
    """
    text = _check_input(prompt, seed)
    seed = int(seed)
    kb = knowledge_base()
    state = _Plan(kb, stage_rng(seed, "plan"), parse_prompt(text, kb), encoder)
    state.notes.extend(state.parsed.notes)
    scene_id, match = _choose_scene(state)
    scene = kb.scene_types[scene_id]
    _make_rooms(state, scene)
    _size_rooms(state)
    styles = state.parsed.styles
    wall_height = _wall_height(state, scene)
    for room in state.rooms:
        _pick_materials(state, room)
        _furnish(state, room)
    _apply_capacity(state)
    _apply_requests(state)
    _apply_windows(state)
    for room in state.rooms:
        _fit(state, room)
    entrance = _entrance(state, scene)
    rooms = [_plan_room(state, room, styles) for room in state.rooms]
    return ScenePlan(
        prompt=prompt,
        planner="offline",
        seed=seed,
        scene_type=scene_id,
        scene_type_match=match[:500],
        style=styles[:20],
        wall_height=wall_height,
        entrance_room=entrance,
        rooms=rooms,
        notes=state.notes[:MAX_NOTES],
    )


def _check_input(prompt: object, seed: object) -> str:
    if not isinstance(prompt, str):
        raise InputError(f"the prompt must be text, not {type(prompt).__name__}", where="prompt")
    text = prompt.strip()
    if not text:
        raise InputError("the prompt is empty", where="prompt", fix="describe the scene to build")
    if len(prompt) > MAX_PROMPT_CHARS:
        raise InputError(
            f"the prompt has {len(prompt)} characters, more than {MAX_PROMPT_CHARS}",
            where="prompt",
            fix="shorten it",
        )
    if isinstance(seed, bool) or not isinstance(seed, int | np.integer) or seed < 0:
        raise InputError(f"invalid seed {seed!r}", where="seed", fix="use an integer >= 0")
    return text


# ---------------------------------------------------------------------------------------------
# 1. Scene type

_SCENE_VECTORS: dict[tuple[int, int], tuple[object, object, np.ndarray]] = {}
_OBJECT_VECTORS: dict[tuple[int, int], tuple[object, object, list[str], np.ndarray]] = {}


def _choose_scene(state: _Plan) -> tuple[str, str]:
    """(scene type, how it was chosen)."""
    parsed, kb = state.parsed, state.kb
    if parsed.scene is not None:
        scene, match = parsed.scene, f"keyword '{parsed.scene_keyword}'"
    elif any(not r.excluded for r in parsed.rooms):
        scene = HOME_SCENE
        names = ", ".join(dict.fromkeys(kb.rooms[r.template].name for r in parsed.rooms))
        match = f"rooms named without a scene type ({names}): planned a home ({scene})"
        state.note(f"the prompt names rooms ({names}) but no scene type; planned a home ({scene})")
    else:
        scene, match = _nearest_scene(state)
    for refined, word in parsed.refinements:
        if kb.scene_types[refined].refines == scene:
            scene = refined
            match += f", refined to '{kb.scene_types[refined].name}' by '{word}'"
            break
    return scene, match


def _nearest_scene(state: _Plan) -> tuple[str, str]:
    """The scene type nearest to the prompt's head (or whole text) by embedding similarity."""
    kb = state.kb
    encoder = state.text_encoder()
    query = state.parsed.head or state.parsed.text
    key = (id(encoder), id(kb))
    cached = _SCENE_VECTORS.get(key)
    if cached is None or cached[0] is not encoder or cached[1] is not kb:
        vectors = encoder.encode([s.embedding_text() for s in kb.scene_types.values()])
        cached = (encoder, kb, np.asarray(vectors, dtype=np.float32))
        _SCENE_VECTORS[key] = cached
    names = list(kb.scene_types)
    sims = cached[2] @ np.asarray(encoder.encode([query[:500]]), dtype=np.float32)[0]
    order = np.argsort(-sims, kind="stable")
    best, second = int(order[0]), int(order[1]) if len(order) > 1 else int(order[0])
    scene = names[best]
    shown = query if len(query) <= 80 else query[:77] + "..."
    match = (
        f"text embedding ({getattr(encoder, 'name', 'encoder')}): '{shown}' is nearest to "
        f"'{kb.scene_types[scene].name}' (cosine {sims[best]:.2f}; next "
        f"'{kb.scene_types[names[second]].name}' {sims[second]:.2f})"
    )
    state.note(
        f"'{shown}' is not a scene type the knowledge base knows; planned the nearest one, "
        f"'{kb.scene_types[scene].name}' (text similarity {sims[best]:.2f})"
    )
    return scene, match


def _nearest_object(state: _Plan, phrase: str) -> tuple[str | None, float]:
    """The object kind nearest to an unknown phrase, if similar enough."""
    kb = state.kb
    encoder = state.text_encoder()
    key = (id(encoder), id(kb))
    cached = _OBJECT_VECTORS.get(key)
    if cached is None or cached[0] is not encoder or cached[1] is not kb:
        names = list(kb.objects)
        texts = [
            f"{name}: {kind.description}. Also called: {', '.join(kind.aliases)}"
            for name, kind in kb.objects.items()
        ]
        cached = (encoder, kb, names, np.asarray(encoder.encode(texts), dtype=np.float32))
        _OBJECT_VECTORS[key] = cached
    sims = cached[3] @ np.asarray(encoder.encode([phrase]), dtype=np.float32)[0]
    best = int(np.argmax(sims))
    if float(sims[best]) < OBJECT_MATCH_MIN:
        return None, float(sims[best])
    return cached[2][best], float(sims[best])


# ---------------------------------------------------------------------------------------------
# 2. Rooms


def _make_rooms(state: _Plan, scene: SceneType) -> None:
    """Room instances of the scene with counts from the prompt, plus rooms it adds."""
    kb, rng, parsed = state.kb, state.rng, state.parsed
    counts: dict[str, int] = {}
    for entry in scene.rooms:
        drawn = int(rng.integers(entry.count[0], entry.count[1] + 1))
        keep = rng.random() < entry.probability
        counts[entry.id] = drawn if keep else 0
    single = len(scene.rooms) == 1
    extra: dict[str, int] = {}  # template -> count, for rooms the scene type does not have
    for mention in parsed.rooms:
        template = mention.template
        direct = [e for e in scene.rooms if e.template == template]
        counted = [e for e in scene.rooms if kb.rooms[e.template].counts_as == template]
        wanted = mention.count
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


def _cap_rooms(state: _Plan, counts: dict[str, int], extra: dict[str, int]) -> None:
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
    state: _Plan, scene: SceneType, counts: dict[str, int], extra: dict[str, int]
) -> None:
    kb = state.kb
    taken: set[str] = set()
    first_id: dict[str, str] = {}
    for entry in scene.rooms:
        for _ in range(counts[entry.id]):
            room_id = _unique(entry.id, taken)
            first_id.setdefault(entry.id, room_id)
            template = kb.rooms[entry.template]
            state.rooms.append(_Room(room_id, entry.template, template, entry_id=entry.id))
    entries = {entry.id: entry for entry in scene.rooms}
    for room in state.rooms:
        wishes = [first_id[a] for a in entries[room.entry_id].adjacent_to if a in first_id]  # type: ignore[index]
        room.adjacent_to = [w for w in dict.fromkeys(wishes) if w != room.id]
    for template_id, n in extra.items():
        for _ in range(n):
            template = kb.rooms[template_id]
            room = _Room(_unique(template_id, taken), template_id, template)
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


def _neighbour(state: _Plan, template: RoomTemplate) -> str | None:
    """The room an added room should touch: the first of its template's neighbours present."""
    for wanted in template.neighbours:
        for room in state.rooms:
            if room.template_id == wanted or room.template.counts_as == wanted:
                return room.id
    return state.rooms[0].id if state.rooms else None


def _size_rooms(state: _Plan) -> None:
    """Areas from the templates (jittered, scaled by size words) or the prompt's sizes."""
    parsed, limits, rng = state.parsed, state.kb.limits, state.rng
    mentions = {}
    for mention in parsed.rooms:
        room = next((r for r in state.rooms if r.template_id == mention.template), None)
        if room is not None and room.id not in mentions:
            mentions[room.id] = mention
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


def _scene_size(state: _Plan, dims: tuple[float, float] | None, area: float | None) -> None:
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
    total = area if area is not None else dims[0] * dims[1]  # type: ignore[index]
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


def _exact_size(state: _Plan, room: _Room, dims: tuple[float, float], what: str) -> None:
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


def _exact_area(state: _Plan, room: _Room, area: float, what: str) -> None:
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


def _entrance(state: _Plan, scene: SceneType) -> str:
    for room in state.rooms:
        if room.id == scene.entrance or room.id.startswith(f"{scene.entrance}_"):
            return room.id
    return state.rooms[0].id


# ---------------------------------------------------------------------------------------------
# 3. Materials and wall height


def _wall_height(state: _Plan, scene: SceneType) -> float:
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
        if state.kb.styles[style].wall_height is not None:
            span = state.kb.styles[style].wall_height  # type: ignore[assignment]
            break
    return round(round(float(rng.uniform(span[0], span[1])) / 0.05) * 0.05, 2)


def _pick_materials(state: _Plan, room: _Room) -> None:
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


# ---------------------------------------------------------------------------------------------
# 4. Furniture


def _furnish(state: _Plan, room: _Room) -> None:
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
        obj = _Obj(
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
        obj.on_top = _draw_on_top(state, room, entry, kind)
        room.objects.append(obj)


def _draw_on_top(
    state: _Plan, room: _Room, entry: TemplateObject | None, kind: ObjectKind
) -> list[_Small]:
    """Small objects for one receptacle: the template's list, or drawn from the table."""
    rng, kb = state.rng, state.kb
    cap = kb.limits.max_small_per_receptacle
    out: list[_Small] = []
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
            out.append(_Small(name, category, int(rng.integers(1, 3))))
    else:
        for item in spec:
            keep = rng.random() < item.probability
            count = int(rng.integers(item.quantity[0], item.quantity[1] + 1))
            if keep and count > 0:
                small = kb.objects[item.object]
                out.append(_Small(item.object, small.category, count, item.variance))
    return _trim_small(out, cap)


def _trim_small(items: list[_Small], cap: int) -> list[_Small]:
    """Keep at most ``cap`` small objects per receptacle instance, requested ones first."""
    order = sorted(range(len(items)), key=lambda i: (not items[i].requested, i))
    left = cap
    kept: dict[int, _Small] = {}
    for i in order:
        if left <= 0:
            break
        take = min(items[i].quantity, left)
        items[i].quantity = take
        kept[i] = items[i]
        left -= take
    return [kept[i] for i in sorted(kept)]


def _apply_capacity(state: _Plan) -> None:
    """``for 8 people``: seats (and the tables they belong to) of the first room with seats."""
    capacity = state.parsed.capacity
    if not capacity:
        return
    room = next((r for r in state.rooms if any(o.seat for o in r.objects)), None)
    if room is None:
        state.note(f"seating for {capacity} was asked, but no room of this plan has seats")
        return
    seats = [o for o in room.objects if o.seat]
    seat = next((o for o in seats if o.per is not None), seats[0])
    anchor = room.get(seat.per) if seat.per is not None else None
    asked = f"seating for {capacity}"
    if anchor is not None:
        anchor.quantity = min(MAX_QUANTITY, max(1, math.ceil(capacity / max(1, seat.per_max))))
        anchor.requested = True
        anchor.asked = f"{asked}: {anchor.quantity} {_plural(anchor.name, anchor.quantity)}"
    seat.quantity = min(MAX_QUANTITY, capacity)
    seat.requested = True
    seat.asked = f"{asked}: {seat.quantity} {_plural(seat.name, seat.quantity)}"
    seat.per = None


def _apply_requests(state: _Plan) -> None:
    """The prompt's objects: merged into rooms, excluded ones removed, unknown ones matched."""
    parsed, kb = state.parsed, state.kb
    requests = list(parsed.objects)
    for phrase in parsed.unknown:
        kind, sim = _nearest_object(state, phrase)
        if kind is None:
            state.note(
                f"'{phrase}' is not an object the knowledge base knows (nearest match "
                f"{sim:.2f} < {OBJECT_MATCH_MIN}); left out"
            )
            continue
        state.note(f"'{phrase}' is not in the knowledge base; planned the closest kind, '{kind}'")
        requests.append(ObjectRequest(kind=kind, quantity=1, phrase=phrase))
    for refused in parsed.refused:
        state.note(f"'{refused.phrase}': {refused.reason}")
    for request in requests:
        if request.excluded or request.quantity == 0:
            _exclude(state, request)
            continue
        room = _request_room(state, request)
        name = _resolve_kind(state, request, room)
        kind = kb.objects[name]
        quantity = _quantity(request, kind)
        if kind.placement == "object":
            _add_small(state, room, name, kind, quantity)
        else:
            _add_object(state, room, name, kind, quantity, request)


def _quantity(request: ObjectRequest, kind: ObjectKind) -> int:
    if request.quantity is not None:
        return request.quantity
    if request.many:
        return kind.many
    return 2 if request.plural else 1


def _request_room(state: _Plan, request: ObjectRequest) -> _Room:
    """The room an object is asked in, else the roomiest room that has (or would have) it, else
    the roomiest room of the scene."""
    if request.room is not None:
        for room in state.rooms:
            if room.template_id == request.room:
                return room
    kinds = state.kb.generics[request.kind].kinds if request.generic else [request.kind]
    for want in kinds:
        homes = [r for r in state.rooms if r.get(want) is not None or want in r.template.kinds()]
        if homes:
            return max(homes, key=lambda r: (_free_floor(state, r), -state.rooms.index(r)))
    main = [r for r in state.rooms if r.entry_id is not None] or state.rooms
    return max(main, key=lambda r: (_free_floor(state, r), -state.rooms.index(r)))


def _free_floor(state: _Plan, room: _Room) -> float:
    """Floor area left under the footprint limit by the room's furniture so far."""
    used = sum(o.footprint * o.quantity for o in room.objects if o.floor)
    return state.kb.limits.footprint_fraction * room.floor_area - used


def _resolve_kind(state: _Plan, request: ObjectRequest, room: _Room) -> str:
    """A generic word (``chair``) as the kind the room has, else the first kind it may mean."""
    if not request.generic:
        return request.kind
    kinds = state.kb.generics[request.kind].kinds
    for want in kinds:
        if room.get(want) is not None:
            return want
    for want in kinds:
        if want in room.template.kinds():
            return want
    return kinds[0]


def _exclude(state: _Plan, request: ObjectRequest) -> None:
    kinds = state.kb.generics[request.kind].kinds if request.generic else [request.kind]
    removed = 0
    for room in state.rooms:
        if request.room is not None and room.template_id != request.room:
            continue
        for obj in list(room.objects):
            if obj.name in kinds:
                removed += obj.quantity
                _remove(room, obj)
        for obj in room.objects:
            obj.on_top = [s for s in obj.on_top if s.name not in kinds]
    what = request.phrase or request.kind
    state.note(f"left out '{what}' as asked" if removed else f"no '{what}' planned, as asked")


def _add_object(
    state: _Plan, room: _Room, name: str, kind: ObjectKind, quantity: int, request: ObjectRequest
) -> None:
    if quantity > MAX_QUANTITY:
        quantity = MAX_QUANTITY
    obj = room.get(name)
    size = kind.size_for(request.size)
    if obj is None:
        variance = kind.variance if quantity > 1 else "same"
        obj = _Obj(name=name, kind=kind, quantity=quantity, variance=variance)
        obj.size = size
        if kind.placement == "wall" and name == "television" and room.get("tv stand") is not None:
            obj.above = "tv stand"
        if kind.placement == "floor" and state.kb.is_receptacle(kind.category):
            obj.on_top = _draw_on_top(state, room, None, kind)
        room.objects.append(obj)
    else:
        obj.quantity = quantity
        if request.size is not None:
            obj.size = size
    obj.requested = True
    obj.per = None
    obj.adjectives = list(request.adjectives)
    obj.asked = request.phrase


def _add_small(state: _Plan, room: _Room, name: str, kind: ObjectKind, quantity: int) -> None:
    """Put requested small objects on the room's receptacles (adding one when it has none)."""
    kb = state.kb
    cap = kb.limits.max_small_per_receptacle

    def weight(obj: _Obj) -> float:
        return dict(kb.small_choices(room.template.type, obj.kind.category)).get(kind.category, 0)

    holders = sorted(
        (o for o in room.objects if o.floor and weight(o) > 0), key=lambda o: -weight(o)
    )
    if not holders:
        holder_kind = _receptacle_for(state, room, kind.category)
        if holder_kind is None:
            state.note(f"no receptacle in the knowledge base holds {_plural(name, 2)}; left out")
            return
        holder = _Obj(holder_kind, kb.objects[holder_kind], 1, priority=9)
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
        each = min(room_left, math.ceil(left / holder.quantity))
        if each <= 0:
            continue
        existing = next((s for s in holder.on_top if s.name == name), None)
        if existing is not None:
            existing.quantity += each
        else:
            holder.on_top.append(_Small(name, kind.category, each, kind.variance, requested=True))
        left -= each * holder.quantity
    if left > 0:
        placed = quantity - left
        state.note(
            f"asked for {quantity} {_plural(name, quantity)}; {max(placed, 0)} fit on the "
            f"receptacles of the {room.template.name} (at most {cap} on each)"
        )


def _receptacle_for(state: _Plan, room: _Room, category: str) -> str | None:
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


def _apply_windows(state: _Plan) -> None:
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


# ---------------------------------------------------------------------------------------------
# 5. Fit


def _fit(state: _Plan, room: _Room) -> None:
    """Keep the room's furniture within the limits (see the module docstring)."""
    limits = state.kb.limits
    start = _counts(room)
    reasons: dict[str, list[str]] = {}

    def floor() -> list[_Obj]:
        return [o for o in room.objects if o.floor]

    def footprint() -> float:
        return sum(o.footprint * o.quantity for o in floor())

    def phase(before: dict[str, tuple[int, bool, str]], why: str) -> None:
        for name, (count, _, _) in before.items():
            obj = room.get(name)
            if obj is None or obj.quantity < count:
                reasons.setdefault(name, []).append(why)

    before = _counts(room)
    while sum(o.quantity for o in floor()) > limits.max_floor_instances:
        _shrink(room, floor(), max_tier=3)
    phase(before, f"at most {limits.max_floor_instances} floor objects per room")
    budget = limits.footprint_fraction * room.floor_area
    needed = sum(o.footprint * o.quantity for o in floor() if _tier(o) > 0)
    if needed > budget and not room.fixed and any(o.requested for o in floor()):
        area = min(limits.max_area, needed / limits.footprint_fraction)
        state.note(
            f"enlarged {room.id} from {room.area:.1f} to {area:.1f} m² to fit the objects asked for"
        )
        room.area = round(area, 1)
        budget = limits.footprint_fraction * room.floor_area
    before = _counts(room)
    while footprint() > budget:
        if not (
            _shrink(room, floor(), max_tier=1)
            or _downsize(state, room)
            or _shrink(room, floor(), max_tier=2)
        ):
            break
    phase(
        before,
        f"furniture footprint under {limits.footprint_fraction:.0%} of {room.floor_area:.1f} m²",
    )
    before = _counts(room)
    _drop_misfits(state, room)
    phase(before, "too big for the room")
    if footprint() > budget + 1e-6:
        names = ", ".join(o.name for o in floor())
        state.note(
            f"{room.id} keeps its {names} although they cover "
            f"{footprint() / room.floor_area:.0%} of the floor"
        )
    before = _counts(room)
    while sum(o.quantity for o in room.objects if not o.floor) > limits.max_wall_instances:
        _shrink(room, [o for o in room.objects if not o.floor], max_tier=3)
    phase(before, f"at most {limits.max_wall_instances} wall objects per room")
    _limit_receptacles(state, room)
    for obj in room.objects:
        if obj.above is not None and room.get(obj.above) is None:
            obj.above = None
    _note_drops(state, room, start, reasons)


ESSENTIAL = 9  # template priority from which an object is essential to its room


def _tier(obj: _Obj) -> int:
    """Drop order: 0 optional, 1 extra requested instances, 2 extra essential instances and
    lesser essentials, 3 a requested object or the room's defining object (kept if it fits)."""
    if not obj.requested and obj.priority < ESSENTIAL:
        return 0
    if obj.requested:
        return 1 if obj.quantity > 1 else 3
    return 2 if obj.quantity > 1 or obj.priority < 10 else 3


def _shrink(room: _Room, candidates: Sequence[_Obj], max_tier: int) -> bool:
    """Take one instance from the lowest tier (False when no object of tier <= max_tier)."""
    pool = [o for o in candidates if _tier(o) <= max_tier]
    if not pool:
        return False
    tier = min(_tier(o) for o in pool)
    pool = [o for o in pool if _tier(o) == tier]
    if tier == 1:
        victim = max(pool, key=lambda o: (o.quantity, -room.objects.index(o)))
    else:
        victim = min(pool, key=lambda o: (o.priority, -room.objects.index(o)))
    victim.quantity -= 1
    if victim.quantity <= 0:
        _remove(room, victim)
        return True
    for dependent in room.objects:
        if dependent.per == victim.name and not dependent.requested and dependent.quantity > 1:
            share = max(1, dependent.quantity // (victim.quantity + 1))
            dependent.quantity = max(1, dependent.quantity - share)
    return True


def _downsize(state: _Plan, room: _Room) -> bool:
    """Give the object that saves the most floor its smaller size (False: none has one)."""
    best: tuple[float, _Obj, tuple[float, float, float]] | None = None
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


def _counts(room: _Room) -> dict[str, tuple[int, bool, str]]:
    return {o.name: (o.quantity, o.requested, o.asked or o.name) for o in room.objects}


def _remove(room: _Room, obj: _Obj) -> None:
    room.objects.remove(obj)
    for other in list(room.objects):
        if other.per == obj.name:
            if other.requested:
                other.per = None
            elif other in room.objects:
                _remove(room, other)


def _drop_misfits(state: _Plan, room: _Room) -> None:
    """Objects that cannot stand in the room at all: longer than the room, or together covering
    more than ``single_fraction`` of it (the biggest go first)."""
    limits = state.kb.limits
    for obj in [o for o in room.objects if o.floor]:
        if not _fits_room(obj.size, room):
            smaller = [s for s in (obj.kind.size, obj.kind.small) if _fits_room(s, room)]
            if smaller:
                obj.size = smaller[0]
                state.note(f"made the {obj.name} in {room.id} smaller to fit: {_dims(obj.size)}")
            else:
                _remove(room, obj)
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
            _remove(room, victim)


def _dims(size: tuple[float, float, float]) -> str:
    return f"{size[0]:g} x {size[1]:g} m"


def _fits_room(size: tuple[float, float, float] | None, room: _Room) -> bool:
    """Whether a footprint fits inside the room's rectangle (with 10 cm to spare)."""
    if size is None or room.size is None:
        return True
    long_side, short_side = max(size[0], size[1]), min(size[0], size[1])
    return long_side <= max(room.size) - 0.1 and short_side <= min(room.size) - 0.1


def _limit_receptacles(state: _Plan, room: _Room) -> None:
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
        if any(s.requested for s in obj.on_top):
            names = ", ".join(sorted({s.name for s in obj.on_top if s.requested}))
            state.note(
                f"only {cap} receptacles per room get small objects; {names} on the "
                f"{obj.name} left out"
            )
        obj.on_top = []
        count -= obj.quantity


def _note_drops(
    state: _Plan,
    room: _Room,
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
            dropped.append(f"{count - now} {_plural(name, count - now)}")
            whys.extend(reasons.get(name, []))
    if dropped:
        why = "; ".join(dict.fromkeys(whys)) or "a limit of the room"
        state.note(f"dropped {', '.join(dropped)} from {room.id} ({why})")


def _plural(name: str, count: int) -> str:
    if count == 1:
        return name
    if name.endswith(("s", "sh", "ch", "x")):
        return name + "es"
    if name.endswith("f"):
        return name[:-1] + "ves"
    return name + "s"


# ---------------------------------------------------------------------------------------------
# 6. Constraints and the plan


def _constraints(room: _Room) -> list[str]:
    """Layout lines per instance: the template's lines for a kind, else the kind's defaults."""
    floor = {o.name: o for o in room.objects if o.floor}
    by_subject: dict[str, list[str]] = {}
    for line in room.lines:
        by_subject.setdefault(line.split("|", 1)[0].strip(), []).append(line)
    out: list[str] = []
    for obj in room.objects:
        if not obj.floor:
            continue
        lines = by_subject.get(obj.name) or obj.kind.constraints
        segments = [seg.strip() for line in lines for seg in line.split("|")[1:]]
        for k in range(obj.quantity):
            parts: list[str] = []
            for segment in segments:
                phrase, _, target = (p.strip() for p in segment.partition(","))
                if target:
                    other = floor.get(target)
                    if other is None or other is obj:
                        continue
                    index = k * other.quantity // obj.quantity
                    part = f"{phrase}, {instance_name(target, index)}"
                else:
                    part = phrase
                if part not in parts:
                    parts.append(part)
            if parts:
                out.append(" | ".join([instance_name(obj.name, k), *parts]))
    return out


def _plan_room(state: _Plan, room: _Room, styles: list[str]) -> PlanRoom:
    objects = [_plan_object(state, obj, styles) for obj in room.objects]
    return PlanRoom(
        id=room.id,
        type=room.template.type,
        size=room.size,
        area_m2=None if room.size is not None else room.area,
        adjacent_to=[a for a in room.adjacent_to if a != room.id],
        floor_material=room.floor,
        wall_material=room.wall,
        ceiling_material=room.ceiling,
        windows=PlanWindows(count=room.windows),
        objects=objects,
        constraints=_constraints(room),
    )


def _plan_object(state: _Plan, obj: _Obj, styles: list[str]) -> PlanObject:
    description = obj.kind.description
    if obj.adjectives:
        description = f"{' '.join(obj.adjectives)} {obj.name}"
    if styles:
        description += f" in {styles[0]} style"
    return PlanObject(
        name=obj.name,
        description=description[:500],
        category=obj.kind.category,
        size=obj.size,
        quantity=obj.quantity,
        variance=obj.variance,  # type: ignore[arg-type]
        placement=obj.kind.placement,  # type: ignore[arg-type]
        above=obj.above,
        on_top=[
            PlanSmallObject(
                name=s.name,
                description=state.kb.objects[s.name].description,
                category=s.category,
                quantity=s.quantity,
                variance=s.variance,  # type: ignore[arg-type]
            )
            for s in obj.on_top
        ],
        requested=obj.requested,
    )
