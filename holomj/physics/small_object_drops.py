"""Small objects dropped onto and into their receptacles with physics.

The assets are chosen before (:func:`holomj.compose.small_objects.choose_small_objects`); this
module gets the choices as data. Each receptacle is populated in turn with
:func:`holomj.physics.spawn.populate` (candidate poses on its support surfaces, spawn-collision
rejection, a drop, acceptance only when the object rests on that receptacle), so later
receptacles see the objects already dropped. A receptacle's objects on top and inside are dropped
in one call. Every requested object ends up placed or listed with the reason it was not; a
receptacle's record lists those inside under ``inside``.
"""

from __future__ import annotations

import time
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any, Protocol

import numpy as np

from holomj.library.store import AssetLibrary
from holomj.physics.spawn import populate
from holomj.spec.scene import SceneSpec

MAX_ATTEMPTS = 12


class Drop(Protocol):
    """One receptacle's chosen small objects (what
    :class:`holomj.compose.small_objects.ReceptacleDrop` holds)."""

    @property
    def receptacle(self) -> str: ...
    @property
    def on_top(self) -> tuple[tuple[str, int], ...]: ...
    @property
    def inside(self) -> tuple[tuple[str, int], ...]: ...
    @property
    def failures(self) -> tuple[dict[str, str], ...]: ...
    @property
    def unserved(self) -> int: ...
    @property
    def rng(self) -> np.random.Generator: ...


@dataclass
class SmallObjects:
    """The scene with its small objects, and what happened on each receptacle."""

    scene: SceneSpec
    requested: int = 0
    placed: int = 0
    receptacles: list[dict[str, Any]] = field(default_factory=list)
    seconds: float = 0.0
    inside: int = 0  # of ``placed``: how many inside a receptacle


def drop_small_objects(
    scene: SceneSpec,
    drops: Sequence[Drop],
    library: AssetLibrary,
    *,
    max_attempts: int = MAX_ATTEMPTS,
) -> SmallObjects:
    """Drop every receptacle's chosen objects onto (and into) it, in order (see the module
    docstring)."""
    start = time.perf_counter()
    out = SmallObjects(scene)
    for drop in drops:
        out.requested += drop.unserved
        record: dict[str, Any] = {"receptacle": drop.receptacle, "failures": list(drop.failures)}
        if drop.on_top or drop.inside:
            result = populate(
                out.scene,
                library,
                drop.receptacle,
                list(drop.on_top),
                drop.rng,
                max_attempts=max_attempts,
                inside=list(drop.inside) or None,
            )
            out.scene = result.scene
            placed = [p for p in result.placements if p.accepted]
            out.requested += len(result.placements)
            out.placed += len(placed)
            record["placed"] = [p.object_id for p in placed if not p.inside]
            if drop.inside:
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
