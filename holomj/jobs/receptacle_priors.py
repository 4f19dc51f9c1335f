"""What goes on a receptacle when the user names nothing: AI2-THOR's own statistics.

``holomj populate OUT --on ID`` without ``--objects`` draws the small objects from
``holomj/data/thor_receptacle_priors.json``: how often each AI2-THOR object type sits on each
receptacle type in AI2-THOR's hand-built scenes (what ProcTHOR samples small objects from;
derived from allenai/procthor, Apache-2.0, see the file's ``_source``). The receptacle's holomj
category is matched to the THOR receptacle types that map to it
(:mod:`holomj.importers.thor_assets`: ``DiningTable`` -> ``dining_table``, ``CounterTop`` ->
``kitchen_counter``...), their counts are pooled, the object types become holomj categories,
and only those the libraries hold a small-object asset of are kept. A receptacle no THOR type
maps to uses the planner's own tables (``small_objects_on_receptacles.json`` and
``knowledge/receptacles.json``). Draws
are made with the job's seed, in proportion to the counts, at most :data:`MAX_SAME` of one
category. With an instruction instead (offline), the small objects it names that the library
holds are dropped (:func:`instruction_requests`).
"""

from __future__ import annotations

import json
from collections import Counter
from functools import cache
from importlib import resources

import numpy as np

from holomj.errors import InputError
from holomj.importers.thor_assets import thor_category, thor_stand_ins
from holomj.library.store import AssetLibrary
from holomj.spec.categories import normalise_category, receptacle_table

DEFAULT_COUNT = 3
MAX_SAME = 2


def _read(*parts: str) -> dict:
    return json.loads(resources.files("holomj.data").joinpath(*parts).read_text("utf-8"))


@cache
def thor_priors() -> dict[str, dict[str, int]]:
    """THOR receptacle type -> {THOR object type: count}."""
    table = _read("thor_receptacle_priors.json")
    return {
        receptacle: {obj: int(entry[0]) for obj, entry in objects.items()}
        for receptacle, objects in table.items()
        if not receptacle.startswith("_")
    }


@cache
def _holomj_table() -> dict[str, dict[str, float]]:
    """Normalised receptacle category -> small-object category -> weight: the planner's
    receptacle roles (:func:`holomj.spec.categories.receptacle_table`)."""
    out: dict[str, dict[str, float]] = {}
    for key, items in receptacle_table().items():
        out.setdefault(normalise_category(key), dict(items))
    return out


def receptacle_weights(category: str) -> tuple[dict[str, float], str]:
    """Small-object category -> weight for a receptacle of ``category``, and the source
    (``"ai2thor"`` or ``"holomj"``); empty when neither table knows the receptacle."""
    key = normalise_category(category)
    pooled: Counter[str] = Counter()
    for receptacle, objects in thor_priors().items():
        own = thor_category(receptacle)
        names = {normalise_category(c) for c in (own or "", *thor_stand_ins(receptacle))}
        if own is None or key not in names:
            continue
        for thor_type, count in objects.items():
            small = thor_category(thor_type)
            if small is not None:
                pooled[small] += count
    if pooled:
        return {k: float(v) for k, v in pooled.items()}, "ai2thor"
    return dict(_holomj_table().get(key, {})), "holomj"


def prior_requests(
    category: str,
    library: AssetLibrary,
    rng: np.random.Generator,
    count: int = DEFAULT_COUNT,
) -> tuple[list[tuple[str, int]], str]:
    """``count`` small-object requests ``[(category, n), ...]`` drawn for a receptacle of
    ``category``, and the table they came from. Raises :class:`~holomj.errors.InputError`
    when no table knows the receptacle or the libraries hold none of its objects."""
    weights, source = receptacle_weights(category)
    held = {
        c: w
        for c, w in sorted(weights.items())
        if any("object" in a.meta.placement for a in library.by_category(c))
    }
    if not held:
        why = "no statistics for it" if not weights else "the library has none of its objects"
        raise InputError(
            f"nothing to put on a {category!r} by default ({why})",
            where="--on",
            fix="name the objects with --objects CAT[:N],...",
        )
    names = list(held)
    p = np.array([held[n] for n in names], dtype=float)
    drawn: Counter[str] = Counter()
    for _ in range(count):
        allowed = np.array([drawn[n] < MAX_SAME for n in names])
        if not allowed.any():
            break
        q = p * allowed
        pick = names[int(rng.choice(len(names), p=q / q.sum()))]
        drawn[pick] += 1
    return [(name, n) for name, n in drawn.items()], source


def instruction_requests(
    instruction: str, library: AssetLibrary, count: int
) -> list[tuple[str, int]]:
    """The small objects an instruction names that the library holds (at most ``count``)."""
    from holomj.plan.knowledge import knowledge_base
    from holomj.plan.prompt import parse_prompt

    kb = knowledge_base()
    requests: list[tuple[str, int]] = []
    left = count
    for request in parse_prompt(instruction, kb).objects:
        kind = kb.objects.get(request.kind)
        if request.excluded or kind is None or kind.placement != "object" or left <= 0:
            continue
        assets = [a for a in library.by_category(kind.category) if "object" in a.meta.placement]
        if not assets:
            continue
        n = min(request.quantity or (2 if request.plural else 1), left)
        requests.append((kind.category, n))
        left -= n
    return requests
