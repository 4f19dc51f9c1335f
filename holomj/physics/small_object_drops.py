"""Small objects on receptacles and inside them: retrieve them, then spawn-and-drop them with
physics.

Each receptacle is populated in turn with :func:`holomj.physics.spawn.populate` (candidate poses
on its support surfaces, spawn-collision rejection, a drop, acceptance only when the object rests
on that receptacle), so later receptacles see the objects already dropped. Every requested object
ends up placed or listed with the reason it was not.

**Inside** (``inside=True``, what ``generate`` does): articulated storage also gets objects on
its interior surfaces (a fridge's shelves, a drawer's bottom, a cupboard's shelf), drawn from
``holomj/data/small_objects_inside.json`` (per receptacle category: the share of such
receptacles that get anything, how many, and which categories, weighted) with a generator of
its own per receptacle, so what goes on top is drawn exactly as without it. The plan's
``on_top`` lists still go on top; a receptacle's objects on top and inside are dropped in one
:func:`~holomj.physics.spawn.populate` call. Its record lists those inside under ``inside``.
"""

from __future__ import annotations

import functools
import json
import time
from collections.abc import Sequence
from dataclasses import dataclass, field
from importlib import resources
from typing import Any

import numpy as np

from holomj.errors import HolomjError, SpecError
from holomj.layout.room_furnishing import AssetChooser, on_demand_record
from holomj.library.store import AssetLibrary
from holomj.physics.spawn import populate
from holomj.seeds import stage_rng
from holomj.spec.plan import PlanObject
from holomj.spec.scene import SceneSpec

MAX_ATTEMPTS = 12
INSIDE_FILE = "small_objects_inside.json"


@dataclass(frozen=True)
class InsideRule:
    """What goes inside receptacles of one category: the share of them that get anything, how
    many objects (least, most) and which categories with their weights."""

    share: float
    count: tuple[int, int]
    objects: tuple[tuple[str, float], ...]

    def draw(self, rng: np.random.Generator) -> list[str]:
        """The categories of the objects one receptacle gets (maybe none)."""
        if rng.random() >= self.share:
            return []
        count = int(rng.integers(self.count[0], self.count[1] + 1))
        weights = np.array([w for _, w in self.objects], dtype=float)
        drawn = rng.choice(len(self.objects), size=count, p=weights / weights.sum())
        return [self.objects[int(k)][0] for k in drawn]


def parse_inside_rules(data: dict[str, Any], where: str) -> dict[str, InsideRule]:
    """The rules of a table shaped as :data:`INSIDE_FILE`; :class:`SpecError` naming the entry
    when one is malformed."""
    rules = {}
    for category, entry in data.items():
        if category.startswith("_"):
            continue
        at = f"{where}: {category}"
        try:
            share = float(entry["share"])
            low, high = (int(v) for v in entry["count"])
            objects = tuple((str(name), float(w)) for name, w in entry["objects"])
        except (KeyError, TypeError, ValueError) as err:
            raise SpecError(f"malformed entry ({err})", where=at) from err
        if not 0.0 <= share <= 1.0 or not 0 <= low <= high or not objects:
            raise SpecError("share must lie in [0, 1], count be [least, most]", where=at)
        if any(w <= 0 for _, w in objects):
            raise SpecError("object weights must be positive", where=at)
        rules[category] = InsideRule(share, (low, high), objects)
    return rules


@functools.cache
def inside_rules() -> dict[str, InsideRule]:
    """The packaged table of what goes inside which receptacles (:data:`INSIDE_FILE`)."""
    text = resources.files("holomj.data").joinpath(INSIDE_FILE).read_text(encoding="utf-8")
    return parse_inside_rules(json.loads(text), INSIDE_FILE)


@dataclass
class SmallObjects:
    """The scene with its small objects, and what happened on each receptacle."""

    scene: SceneSpec
    requested: int = 0
    placed: int = 0
    receptacles: list[dict[str, Any]] = field(default_factory=list)
    picks: list[dict[str, Any]] = field(default_factory=list)
    seconds: float = 0.0
    inside: int = 0  # of ``placed``: how many inside a receptacle


def drop_small_objects(
    scene: SceneSpec,
    receptacles: Sequence[tuple[str, PlanObject]],
    library: AssetLibrary,
    chooser: AssetChooser,
    seed: int,
    *,
    max_attempts: int = MAX_ATTEMPTS,
    inside: bool = False,
) -> SmallObjects:
    """Put the planned ``on_top`` objects of every receptacle onto it, and with ``inside``
    objects into the scene's articulated storage (see module docstring)."""
    start = time.perf_counter()
    out = SmallObjects(scene)
    targets: list[tuple[str, PlanObject | None]] = list(receptacles)
    rules = inside_rules() if inside else {}
    if rules:
        listed = {rid for rid, _ in receptacles}
        targets += [
            (o.id, None)
            for o in scene.objects
            if o.id not in listed and _interior_category(library, o.asset) in rules
        ]
    for receptacle_id, plan_obj in targets:
        rng = stage_rng(seed, "small_objects", receptacle_id)
        requests: list[tuple[str, int]] = []
        failures: list[dict[str, str]] = []
        for small in plan_obj.on_top if plan_obj is not None else ():
            try:
                picks = chooser.choose(
                    small.description.strip() or small.name,
                    quantity=small.quantity,
                    variance=small.variance,
                    rng=rng,
                    placement="object",
                    category=small.category,
                )
            except HolomjError as err:
                failures.append({"object": small.name, "reason": err.one_line()})
                out.requested += small.quantity
                continue
            for pick in picks:
                requests.append((pick.asset_id, 1))
                out.picks.append(
                    {
                        "receptacle": receptacle_id,
                        "name": small.name,
                        "asset": pick.asset_id,
                        **on_demand_record(pick),
                    }
                )
        inner = _inside_requests(out, scene, library, chooser, rules, seed, receptacle_id, failures)
        requests, inner = _where_they_fit(out, library, receptacle_id, requests, inner, failures)
        if plan_obj is None and not inner and not failures:
            continue  # storage the draw left empty: nothing to report
        record: dict[str, Any] = {"receptacle": receptacle_id, "failures": failures}
        if requests or inner:
            result = populate(
                out.scene,
                library,
                receptacle_id,
                requests,
                rng,
                max_attempts=max_attempts,
                inside=inner or None,
            )
            out.scene = result.scene
            placed = [p for p in result.placements if p.accepted]
            out.requested += len(result.placements)
            out.placed += len(placed)
            record["placed"] = [p.object_id for p in placed if not p.inside]
            if inner:
                record["inside"] = [p.object_id for p in placed if p.inside]
                out.inside += len(record["inside"])
            record["failures"] += [
                {"object": p.asset, "reason": p.reason} for p in result.placements if not p.accepted
            ]
            record["receptacle_drift_m"] = round(result.receptacle_drift_m, 6)
            record["seconds"] = round(result.seconds, 3)
        out.receptacles.append(record)
    out.seconds = time.perf_counter() - start
    return out


def _where_they_fit(
    out: SmallObjects,
    library: AssetLibrary,
    receptacle_id: str,
    on_top: list[tuple[str, int]],
    inside: list[tuple[str, int]],
    failures: list[dict[str, str]],
) -> tuple[list[tuple[str, int]], list[tuple[str, int]]]:
    """The objects for on top and inside, moved to where the receptacle holds them: a
    receptacle with no top surface but room inside (a toy box with a lid) takes its planned
    objects inside; one with neither reports them as failures."""
    if not on_top:
        return on_top, inside
    obj = next(o for o in out.scene.objects if o.id == receptacle_id)
    meta = library.get(obj.asset).meta
    if meta.surfaces:
        return on_top, inside
    if meta.articulation is not None and meta.articulation.interior:
        return [], inside + on_top
    why = f"{receptacle_id} has no surface to put things on"
    failures.extend({"object": asset_id, "reason": why} for asset_id, _ in on_top)
    out.requested += sum(n for _, n in on_top)
    return [], inside


def _interior_category(library: AssetLibrary, asset_id: str) -> str | None:
    """The category of an asset with interior surfaces, else None."""
    meta = library.get(asset_id).meta
    if meta.articulation is None or not meta.articulation.interior:
        return None
    return meta.category


def _inside_requests(
    out: SmallObjects,
    scene: SceneSpec,
    library: AssetLibrary,
    chooser: AssetChooser,
    rules: dict[str, Any],
    seed: int,
    receptacle_id: str,
    failures: list[dict[str, str]],
) -> list[tuple[str, int]]:
    """The assets drawn to go inside ``receptacle_id`` (none without a rule for it)."""
    obj = next((o for o in scene.objects if o.id == receptacle_id), None)
    category = _interior_category(library, obj.asset) if obj is not None else None
    if category not in rules:
        return []
    rng = stage_rng(seed, "small_objects_inside", receptacle_id)
    inner: list[tuple[str, int]] = []
    for name in rules[category].draw(rng):
        try:
            (pick,) = chooser.choose(
                name, quantity=1, variance="same", rng=rng, placement="object", category=name
            )
        except HolomjError as err:
            failures.append({"object": name, "reason": err.one_line()})
            out.requested += 1
            continue
        inner.append((pick.asset_id, 1))
        out.picks.append(
            {
                "receptacle": receptacle_id,
                "name": name,
                "asset": pick.asset_id,
                "inside": True,
                **on_demand_record(pick),
            }
        )
    return inner
