"""Scene type choice, and matching unknown words to the knowledge base by text embedding.

The scene type is the keyword the prompt's head names, refined by words anywhere (``an office
for a professor``); rooms named without a scene make a home (:data:`HOME_SCENE`); anything else
goes to the nearest scene type by cosine similarity of text embeddings. Unknown object words
take the nearest object kind when it is similar enough (:data:`OBJECT_MATCH_MIN`). Embeddings of
the knowledge base are cached per encoder and knowledge base.
"""

from __future__ import annotations

import numpy as np

from holomj.plan.draft import DraftPlan

HOME_SCENE = "apartment"  # the scene type for rooms named without one
OBJECT_MATCH_MIN = 0.5  # cosine similarity for an unknown object word to take a known kind

# Embeddings of the knowledge base's scene types and object kinds, per (encoder, knowledge base).
_SCENE_VECTORS: dict[tuple[int, int], tuple[object, object, np.ndarray]] = {}
_OBJECT_VECTORS: dict[tuple[int, int], tuple[object, object, list[str], np.ndarray]] = {}


def choose_scene(state: DraftPlan) -> tuple[str, str]:
    """(scene type, how it was chosen)."""
    parsed, kb = state.parsed, state.kb
    if parsed.scene is not None:
        scene, match = parsed.scene, f"keyword '{parsed.scene_keyword}'"
    elif (single := _single_room_scene(state)) is not None:
        scene, state.only_room = single
        name = kb.rooms[state.only_room].name
        match = f"one room named without a scene type: planned that room alone ({name})"
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


def _single_room_scene(state: DraftPlan) -> tuple[str, str] | None:
    """(scene type, room template) when the prompt names one kind of room, once, and no scene
    ("a veterinary exam room with ..."): the scene type with the fewest rooms that has that
    room, to be planned with that room alone; else None."""
    kb = state.kb
    rooms = [r for r in state.parsed.rooms if not r.excluded and not r.location]
    if any(not r.zone for r in rooms):  # "a daycare room with a reading corner": the daycare
        rooms = [r for r in rooms if not r.zone]
    wanted = {r.template for r in rooms}
    counts = [r.count for r in rooms]
    if len(wanted) != 1 or any(c is not None and c > 1 for c in counts):
        return None
    (template,) = wanted
    having = sorted(
        (len(st.rooms), sid)
        for sid, st in kb.scene_types.items()
        if any(e.template == template for e in st.rooms)
    )
    return (having[0][1], template) if having else None


def _nearest_scene(state: DraftPlan) -> tuple[str, str]:
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


def nearest_object(state: DraftPlan, phrase: str) -> tuple[str | None, float]:
    """The object kind nearest to an unknown phrase, if similar enough."""
    (name, sim), *_ = nearest_objects(state, phrase, 1)
    return (name if sim >= OBJECT_MATCH_MIN else None), sim


def nearest_objects(state: DraftPlan, phrase: str, count: int) -> list[tuple[str, float]]:
    """The ``count`` object kinds nearest to a phrase by text embedding, nearest first."""
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
    order = np.argsort(-sims, kind="stable")[:count]
    return [(cached[2][int(i)], float(sims[int(i)])) for i in order]
