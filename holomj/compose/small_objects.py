"""Which small objects go on and into which receptacle: the asset choices of the small-object
stage, made before anything is dropped (:mod:`holomj.physics.small_object_drops` drops them).

On top: the plan's ``on_top`` lists of each placed receptacle, one pick per object. **Inside**
(``inside=True``, what ``generate`` does): articulated storage also gets objects on its interior
surfaces (a fridge's shelves, a drawer's bottom, a cupboard's shelf), drawn from
``holomj/data/small_objects_inside.json`` (per receptacle category: the share of such receptacles
that get anything, how many, and which categories, weighted) with a generator of its own per
receptacle, so what goes on top is drawn exactly as without it. A receptacle with no top surface
but room inside (a toy box with a lid) takes its planned objects inside; one with neither reports
them as failures. Every requested object ends up chosen or listed with the reason it was not.
"""

from __future__ import annotations

import functools
import json
from collections.abc import Sequence
from dataclasses import dataclass
from importlib import resources
from typing import Any

import numpy as np

from holomj.compose.room_assets import on_demand_record
from holomj.errors import HolomjError, SpecError
from holomj.library.store import AssetLibrary
from holomj.retrieval.chooser import AssetChooser, Pick
from holomj.seeds import stage_rng
from holomj.spec.plan import PlanObject
from holomj.spec.scene import SceneSpec

INSIDE_FILE = "small_objects_inside.json"
Request = tuple[str, int]  # (asset id, how many)


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


@dataclass(frozen=True)
class ReceptacleDrop:
    """The small objects chosen for one receptacle: assets to drop on top and inside, the
    objects that could not be chosen or have no place on it (with the reason), and the
    receptacle's generator, which the drop continues (its stream served the choices first)."""

    receptacle: str
    on_top: tuple[Request, ...]
    inside: tuple[Request, ...]
    failures: tuple[dict[str, str], ...]
    unserved: int  # objects asked but neither chosen nor droppable (counted as requested)
    rng: np.random.Generator


@dataclass(frozen=True)
class SmallObjectChoices:
    """Every receptacle's drop, in order, and one record per pick (for ``generate.json``)."""

    drops: tuple[ReceptacleDrop, ...]
    picks: tuple[dict[str, Any], ...]


def choose_small_objects(
    scene: SceneSpec,
    receptacles: Sequence[tuple[str, PlanObject]],
    library: AssetLibrary,
    chooser: AssetChooser,
    seed: int,
    *,
    inside: bool = False,
) -> SmallObjectChoices:
    """The assets for the planned ``on_top`` objects of every receptacle and, with ``inside``,
    for the scene's articulated storage (see the module docstring)."""
    targets: list[tuple[str, PlanObject | None]] = list(receptacles)
    rules = inside_rules() if inside else {}
    if rules:
        listed = {rid for rid, _ in receptacles}
        targets += [
            (o.id, None)
            for o in scene.objects
            if o.id not in listed and _interior_category(library, o.asset) in rules
        ]
    choosing = _Choosing(scene, library, chooser, rules, seed)
    drops, picks = [], []
    for receptacle_id, plan_obj in targets:
        drop, chosen = choosing.for_receptacle(receptacle_id, plan_obj)
        picks += chosen
        if plan_obj is None and not drop.inside and not drop.failures:
            continue  # storage the draw left empty: nothing to report
        drops.append(drop)
    return SmallObjectChoices(tuple(drops), tuple(picks))


@dataclass(frozen=True)
class _Choosing:
    """What every receptacle's choices read: the scene, the library, the chooser, the inside
    rules (empty: nothing inside) and the seed."""

    scene: SceneSpec
    library: AssetLibrary
    chooser: AssetChooser
    rules: dict[str, InsideRule]
    seed: int

    def for_receptacle(
        self, receptacle_id: str, plan_obj: PlanObject | None
    ) -> tuple[ReceptacleDrop, list[dict[str, Any]]]:
        """One receptacle's drop and the records of its picks."""
        rng = stage_rng(self.seed, "small_objects", receptacle_id)
        on_top: list[Request] = []
        failures: list[dict[str, str]] = []
        picks: list[dict[str, Any]] = []
        unserved = 0
        for small in plan_obj.on_top if plan_obj is not None else ():
            try:
                chosen = self.chooser.choose(
                    small.description.strip() or small.name,
                    quantity=small.quantity,
                    variance=small.variance,
                    rng=rng,
                    placement="object",
                    category=small.category,
                )
            except HolomjError as err:
                failures.append({"object": small.name, "reason": err.one_line()})
                unserved += small.quantity
                continue
            for pick in chosen:
                on_top.append((pick.asset_id, 1))
                picks.append(_pick_record(receptacle_id, small.name, pick))
        inner, missed = self._inside(receptacle_id, failures, picks)
        on_top, inner, unfit = _where_they_fit(
            self.scene, self.library, receptacle_id, on_top, inner, failures
        )
        unserved += missed + unfit
        drop = ReceptacleDrop(
            receptacle_id, tuple(on_top), tuple(inner), tuple(failures), unserved, rng
        )
        return drop, picks

    def _inside(
        self, receptacle_id: str, failures: list[dict[str, str]], picks: list[dict[str, Any]]
    ) -> tuple[list[Request], int]:
        """The assets drawn to go inside ``receptacle_id`` (none without a rule for it), and
        how many drawn objects found no asset (each reported in ``failures``)."""
        obj = next((o for o in self.scene.objects if o.id == receptacle_id), None)
        category = _interior_category(self.library, obj.asset) if obj is not None else None
        if category is None or category not in self.rules:
            return [], 0
        rng = stage_rng(self.seed, "small_objects_inside", receptacle_id)
        inner: list[Request] = []
        missed = 0
        for name in self.rules[category].draw(rng):
            try:
                (pick,) = self.chooser.choose(
                    name, quantity=1, variance="same", rng=rng, placement="object", category=name
                )
            except HolomjError as err:
                failures.append({"object": name, "reason": err.one_line()})
                missed += 1
                continue
            inner.append((pick.asset_id, 1))
            picks.append(_pick_record(receptacle_id, name, pick, inside=True))
        return inner, missed


def _where_they_fit(
    scene: SceneSpec,
    library: AssetLibrary,
    receptacle_id: str,
    on_top: list[Request],
    inside: list[Request],
    failures: list[dict[str, str]],
) -> tuple[list[Request], list[Request], int]:
    """The objects for on top and inside, moved to where the receptacle holds them, and how
    many it cannot hold (reported in ``failures``)."""
    if not on_top:
        return on_top, inside, 0
    obj = next(o for o in scene.objects if o.id == receptacle_id)
    meta = library.get(obj.asset).meta
    if meta.surfaces:
        return on_top, inside, 0
    if meta.articulation is not None and meta.articulation.interior:
        return [], inside + on_top, 0
    why = f"{receptacle_id} has no surface to put things on"
    failures.extend({"object": asset_id, "reason": why} for asset_id, _ in on_top)
    return [], inside, sum(n for _, n in on_top)


def _interior_category(library: AssetLibrary, asset_id: str) -> str | None:
    """The category of an asset with interior surfaces, else None."""
    meta = library.get(asset_id).meta
    if meta.articulation is None or not meta.articulation.interior:
        return None
    return meta.category


def _pick_record(
    receptacle_id: str, name: str, pick: Pick, *, inside: bool = False
) -> dict[str, Any]:
    """The ``generate.json`` record of one small object's pick."""
    record: dict[str, Any] = {"receptacle": receptacle_id, "name": name, "asset": pick.asset_id}
    if inside:
        record["inside"] = True
    return {**record, **on_demand_record(pick)}
