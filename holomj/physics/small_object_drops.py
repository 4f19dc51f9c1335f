"""Small objects on receptacles: retrieve them, then spawn-and-drop them with physics.

Each receptacle is populated in turn with :func:`holomj.physics.spawn.populate` (candidate poses
on its support surfaces, spawn-collision rejection, a drop, acceptance only when the object rests
on that receptacle), so later receptacles see the objects already dropped. Every requested object
ends up placed or listed with the reason it was not.
"""

from __future__ import annotations

import time
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

from holomj.errors import HolomjError
from holomj.layout.room_furnishing import AssetChooser, on_demand_record
from holomj.library.store import AssetLibrary
from holomj.physics.spawn import populate
from holomj.seeds import stage_rng
from holomj.spec.plan import PlanObject
from holomj.spec.scene import SceneSpec

MAX_ATTEMPTS = 12


@dataclass
class SmallObjects:
    """The scene with its small objects, and what happened on each receptacle."""

    scene: SceneSpec
    requested: int = 0
    placed: int = 0
    receptacles: list[dict[str, Any]] = field(default_factory=list)
    picks: list[dict[str, Any]] = field(default_factory=list)
    seconds: float = 0.0


def drop_small_objects(
    scene: SceneSpec,
    receptacles: Sequence[tuple[str, PlanObject]],
    library: AssetLibrary,
    chooser: AssetChooser,
    seed: int,
    *,
    max_attempts: int = MAX_ATTEMPTS,
) -> SmallObjects:
    """Put the planned ``on_top`` objects of every receptacle onto it (see module docstring)."""
    start = time.perf_counter()
    out = SmallObjects(scene)
    for receptacle_id, plan_obj in receptacles:
        rng = stage_rng(seed, "small_objects", receptacle_id)
        requests: list[tuple[str, int]] = []
        failures: list[dict[str, str]] = []
        for small in plan_obj.on_top:
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
        record: dict[str, Any] = {"receptacle": receptacle_id, "failures": failures}
        if requests:
            result = populate(
                out.scene, library, receptacle_id, requests, rng, max_attempts=max_attempts
            )
            out.scene = result.scene
            placed = [p for p in result.placements if p.accepted]
            out.requested += len(result.placements)
            out.placed += len(placed)
            record["placed"] = [p.object_id for p in placed]
            record["failures"] += [
                {"object": p.asset, "reason": p.reason} for p in result.placements if not p.accepted
            ]
            record["receptacle_drift_m"] = round(result.receptacle_drift_m, 6)
            record["seconds"] = round(result.seconds, 3)
        out.receptacles.append(record)
    out.seconds = time.perf_counter() - start
    return out
