"""Nouns the knowledge base does not know, kept as themselves (open vocabulary, offline).

A prompt's unknown phrase (``a trampoline``, ``a hamster cage``) is matched by text embedding
against every known object kind:

* a phrase about the scene rather than a thing in it (its first word in :data:`NOT_THINGS`: a
  view, the light) or about a surface finish (its last word a material of the knowledge base or
  in :data:`SURFACE_WORDS`: white tiles) needs :data:`OBJECT_MATCH_MIN`, any other phrase
  :data:`NEW_KIND_MIN`; below that it names nothing the planner can place and is left out with a
  note;
* at :data:`SAME_KIND_MIN` or above, or at :data:`CLEAR_KIND_MIN` with a margin of
  :data:`CLEAR_MARGIN` over the second nearest, it *is* the nearest kind (``a grandfather
  timepiece`` is a grandfather clock);
* in between it stays itself: :func:`new_kind` makes an object kind named by the phrase, whose
  placement is the nearest kind's and whose size is the median of the :data:`NEIGHBOURS`
  nearest kinds of that placement, bounded to :data:`SIZE_BOUNDS`.

The asset stage then gives a new kind an asset of its own category (synthesised, or an honest
proxy), and the plan's notes say what it was made like.
"""

from __future__ import annotations

import re

import numpy as np

from holomj.plan.draft import DraftPlan
from holomj.plan.knowledge_schema import ObjectKind
from holomj.plan.prompt_relations import RELATIONS
from holomj.plan.scene_match import OBJECT_MATCH_MIN, nearest_objects

SAME_KIND_MIN = 0.75  # an unknown phrase this similar to a known kind is that kind
CLEAR_KIND_MIN = 0.55  # ... or this similar, and CLEAR_MARGIN nearer than to any other kind
CLEAR_MARGIN = 0.15
NEW_KIND_MIN = 0.3  # below this similarity to every known kind a phrase names no object
# Head words of phrases that describe the scene, not a thing in it ("a view of the sea").
NOT_THINGS = frozenset(
    {
        "view", "views", "feel", "feeling", "atmosphere", "vibe", "vibes", "mood", "style",
        "theme", "look", "space", "area", "light", "lighting", "sunlight", "daylight", "air",
        "colour", "color", "colours", "colors", "scent", "smell", "sound", "music", "noise",
        "decor", "design", "layout", "interior", "ambience", "ambiance", "touch", "charm",
        "warmth", "comfort", "privacy", "storage", "seating", "room", "rooms", "floor",
        "walls", "wall", "ceiling", "corner", "side", "middle", "centre", "center", "lots",
        "plenty", "people", "person", "family", "guests", "kids", "children",
    }
)  # fmt: skip
NEIGHBOURS = 3
# (min, max) of width, depth and height per placement, metres
SIZE_BOUNDS: dict[str, tuple[tuple[float, float, float], tuple[float, float, float]]] = {
    "floor": ((0.2, 0.2, 0.1), (3.0, 3.0, 2.5)),
    "wall": ((0.2, 0.02, 0.2), (3.0, 0.4, 2.0)),
    "ceiling": ((0.2, 0.2, 0.1), (2.0, 2.0, 1.5)),
    "object": ((0.03, 0.03, 0.02), (0.8, 0.6, 0.8)),
}
# Last words of phrases that name a surface finish, not an object ("white tiles").
SURFACE_WORDS = frozenset(
    {"tiles", "tile", "tiling", "wallpaper", "paint", "parquet", "plaster", "bricks", "brick"}
)
_RELATION_WORDS = frozenset(
    {first for words in RELATIONS for first in words[:1]} - {"face", "faces"}
)
_PLACEMENT_WORDS = {
    "floor": "a floor object",
    "wall": "a wall object",
    "ceiling": "a ceiling object",
    "object": "a small object",
}
_ARTICLES = re.compile(r"^(a|an|the|some|one)(\s+|$)")


def resolve_unknown(state: DraftPlan, phrase: str) -> str | None:
    """The kind an unknown phrase is planned as (a known one, or a new one made for it), or
    None when it names nothing the planner can place; notes say which."""
    near = nearest_objects(state, phrase, max(NEIGHBOURS * 4, 12))
    best, sim = near[0]
    name = kind_name(phrase)
    thing = name is not None and not _describes_the_scene(state, name)
    if sim < (NEW_KIND_MIN if thing else OBJECT_MATCH_MIN) or (
        sim < OBJECT_MATCH_MIN and not thing
    ):
        state.note(
            f"'{phrase}' is not an object the knowledge base knows (nearest match "
            f"{sim:.2f} < {OBJECT_MATCH_MIN}); left out"
        )
        return None
    runner_up = near[1][1] if len(near) > 1 else 0.0
    if sim >= SAME_KIND_MIN or (sim >= CLEAR_KIND_MIN and sim - runner_up >= CLEAR_MARGIN):
        state.note(f"'{phrase}' is not in the knowledge base; planned the closest kind, '{best}'")
        return best
    if name is None or not thing or name in state.kb.objects:
        state.note(f"'{phrase}' is not in the knowledge base; planned the closest kind, '{best}'")
        return best
    if name not in state.new_kinds:
        state.new_kinds[name] = new_kind(state, phrase, near)
        state.like[name] = best
        placement = _PLACEMENT_WORDS[state.new_kinds[name].placement]
        size = state.new_kinds[name].size
        shown = "x".join(f"{v:.2f}" for v in size) if size else "its receptacle's choice"
        state.note(
            f"'{phrase}' is not in the knowledge base; planned as itself, {placement} "
            f"of {shown} m like a {best} (nearest kinds by text)"
        )
    return name


def _describes_the_scene(state: DraftPlan, name: str) -> bool:
    """A phrase about the scene or its surfaces ("a view of the sea", "white tiles")."""
    words = name.split()
    surfaces = {
        w for term in state.kb.materials.values() for alias in term.aliases for w in alias.split()
    } | {w for ws in state.kb.surfaces.values() for w in ws}
    return bool({words[0]} & NOT_THINGS) or words[-1] in surfaces or words[-1] in SURFACE_WORDS


def kind_name(phrase: str) -> str | None:
    """An object name for a phrase: lower-case words of letters and digits, no article."""
    words = re.sub(r"[^a-z0-9 ]+", " ", phrase.lower()).strip()
    words = _ARTICLES.sub("", words)
    kept = []
    for word in words.split():  # "a bicycle against the wall": the thing is the bicycle
        if word in _RELATION_WORDS:
            break
        kept.append(word)
    name = " ".join(kept[:6])[:64].strip()
    return name or None


def new_kind(state: DraftPlan, phrase: str, near: list[tuple[str, float]]) -> ObjectKind:
    """A kind for ``phrase`` shaped like its nearest known kinds (see the module doc)."""
    kb = state.kb
    first = kb.objects[near[0][0]]
    placement = first.placement
    alike = [kb.objects[n] for n, _ in near if kb.objects[n].placement == placement]
    sizes = [k.size for k in alike[:NEIGHBOURS] if k.size is not None] or (
        [first.size] if first.size is not None else []
    )
    size = None
    if sizes:
        low, high = SIZE_BOUNDS[placement]
        median = np.median(np.asarray(sizes, dtype=float), axis=0)
        width, depth, height = (
            float(round(min(max(v, lo), hi), 3)) for v, lo, hi in zip(median, low, high)
        )
        size = (width, depth, height)
    name = kind_name(phrase) or phrase
    return ObjectKind(
        category=re.sub(r"\s+", "_", name),
        placement=placement,
        size=size,
        description=f"a {name}",
        many=2,
        variance="same",
        constraints=[f"{name} | edge"] if placement == "floor" else [],
        receptacle=False,
        rooms=list(first.rooms),
    )
