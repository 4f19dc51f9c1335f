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
   targets spread over the target's instances and lines to absent objects left out; and the
   prompt's relations (``a desk under the window``), made plan relations after step 4
   (:mod:`~holomj.plan.relations`), which the layout weighs above the defaults.

Modules: :mod:`~holomj.plan.scene_match` (step 1), :mod:`~holomj.plan.rooms` (2, 3),
:mod:`~holomj.plan.furnish` and :mod:`~holomj.plan.object_requests` (4), :mod:`~holomj.plan.fit`
(5), :mod:`~holomj.plan.constraints_text` (6), on the working state of
:mod:`~holomj.plan.draft`; this module checks the input, runs the steps in order and writes the
:class:`~holomj.spec.plan.ScenePlan`.
"""

from __future__ import annotations

import numpy as np

from holomj.errors import InputError, SpecError
from holomj.plan.arrangement_words import with_arrangement_words
from holomj.plan.constraints_text import constraint_lines
from holomj.plan.draft import MAX_QUANTITY, DraftObject, DraftPlan, DraftRoom
from holomj.plan.fit import ESSENTIAL, fit_room
from holomj.plan.furnish import apply_capacity, apply_window_dressings, apply_windows, furnish
from holomj.plan.knowledge import knowledge_base
from holomj.plan.object_requests import apply_requests
from holomj.plan.prompt import parse_prompt
from holomj.plan.relations import apply_relations, room_relations
from holomj.plan.rooms import (
    WALL_HEIGHT_LIMITS,
    choose_wall_height,
    entrance_room,
    make_rooms,
    pick_materials,
    size_rooms,
)
from holomj.plan.scene_match import HOME_SCENE, OBJECT_MATCH_MIN, choose_scene
from holomj.retrieval.text import TextEncoder
from holomj.seeds import stage_rng
from holomj.spec.plan import PlanObject, PlanRoom, PlanSmallObject, PlanWindows, ScenePlan

MAX_PROMPT_CHARS = 2000
MAX_NOTES = 200


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
    state = DraftPlan(kb, stage_rng(seed, "plan"), parse_prompt(text, kb), encoder)
    state.notes.extend(state.parsed.notes)
    scene_id, match = choose_scene(state)
    scene = kb.scene_types[scene_id]
    make_rooms(state, scene)
    size_rooms(state)
    styles = state.parsed.styles
    wall_height = choose_wall_height(state, scene)
    for room in state.rooms:
        pick_materials(state, room)
        furnish(state, room)
    apply_requests(state)
    apply_capacity(state)
    apply_relations(state)
    apply_windows(state)
    apply_window_dressings(state)
    for room in state.rooms:
        fit_room(state, room)
    entrance = entrance_room(state, scene)
    rooms = [with_arrangement_words(_plan_room(state, r, styles), prompt) for r in state.rooms]
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


def _plan_room(state: DraftPlan, room: DraftRoom, styles: list[str]) -> PlanRoom:
    # defining: the template's defining kinds, or what took their place (same category)
    defining = set(room.template.defining)
    categories = {state.kb.objects[n].category for n in defining if n in state.kb.objects}
    objects = [
        _plan_object(state, obj, styles, obj.name in defining or obj.kind.category in categories)
        for obj in room.objects
    ]
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
        constraints=constraint_lines(room),
        relations=room_relations(state, room),
    )


def _plan_object(
    state: DraftPlan, obj: DraftObject, styles: list[str], defining: bool
) -> PlanObject:
    description = obj.kind.description
    if obj.adjectives or obj.parts:
        description = " ".join([*obj.adjectives, obj.name])
    if obj.parts:  # "white kitchen cabinet with brass handles": the asset stage reads parts
        description += " with " + " and ".join(obj.parts)
    if styles:
        description += f" in {styles[0]} style"
    placement = obj.kind.placement
    if placement == "object":  # small kinds are planned on receptacles (on_top), never alone
        raise SpecError(f"{obj.name!r} is a small object: it goes on a receptacle", where="plan")
    return PlanObject(
        name=obj.name,
        description=description[:500],
        category=obj.kind.category,
        size=obj.size,
        quantity=obj.quantity,
        variance=obj.variance,
        placement=placement,
        above=obj.above,
        faced_by=obj.faced_by,
        on_top=[
            PlanSmallObject(
                name=s.name,
                description=state.object_kind(s.name).description,
                category=s.category,
                quantity=s.quantity,
                variance=s.variance,
                instances=s.instances,
            )
            for s in obj.on_top
        ],
        requested=obj.requested,
        defining=defining,
    )


__all__ = [
    "ESSENTIAL",
    "HOME_SCENE",
    "MAX_NOTES",
    "MAX_PROMPT_CHARS",
    "MAX_QUANTITY",
    "OBJECT_MATCH_MIN",
    "WALL_HEIGHT_LIMITS",
    "plan_offline",
]
