"""Access to furniture fronts: the floor in front of furniture used from its front (the
vocabulary's ``front_access``: wardrobes, fridges, desks, dressers, cookers, toilets, ...)
standing on the floor is reachable.

The front is the asset's +X turned by its yaw. The front is accessible when the 0.2 m robot,
driving from the entrance (:mod:`holomj.evaluation.reachability`), can put its centre in front
of the face (within the middle 80 % of its width, at least 20 cm of it) with its body at most
0.5 m from the face, or, when a seat that is pulled out to use the furniture (the vocabulary's
``pull_out_seats``: a chair at a desk, a stool at a counter) stands in that zone, with its body
at most 0.5 m from the seat.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
import shapely
from shapely.geometry import Polygon

from holomj.evaluation.folder import MeasuredFolder
from holomj.evaluation.objects import EvaluatedObject
from holomj.evaluation.reachability import ReachGrid
from holomj.evaluation.vocabulary import Vocabulary

FRONT_REACH_M = 0.5  # the robot's body comes at least this close to the front face
SIDE_MARGIN = 0.1  # share of the width left out on each side
MIN_SPAN_M = 0.2


@dataclass(frozen=True)
class FrontZone:
    """The floor in front of an object's face: ``depth`` deep, ``lo``..``hi`` across."""

    obj: EvaluatedObject
    face: float
    lo: float
    hi: float
    depth: float

    @classmethod
    def of(cls, obj: EvaluatedObject, depth: float) -> FrontZone:
        """The zone in front of ``obj`` (the middle of its width, at least MIN_SPAN_M)."""
        fx, fy = obj.front
        lo, hi = obj.extent((-fy, fx))
        margin = max(0.0, min(SIDE_MARGIN * (hi - lo), (hi - lo - MIN_SPAN_M) / 2))
        return cls(obj, obj.extent(obj.front)[1], lo + margin, hi - margin, depth)

    def along(self, x: np.ndarray, y: np.ndarray) -> np.ndarray:
        """Distance of points from the object's centre along its front."""
        fx, fy = self.obj.front
        return (x - self.obj.center[0]) * fx + (y - self.obj.center[1]) * fy

    def mask(self, x: np.ndarray, y: np.ndarray) -> np.ndarray:
        """Which points lie in the zone."""
        fx, fy = self.obj.front
        lat = (x - self.obj.center[0]) * -fy + (y - self.obj.center[1]) * fx
        along = self.along(x, y)
        return (
            (along >= self.face)
            & (along <= self.face + self.depth)
            & (lat >= self.lo)
            & (lat <= self.hi)
        )

    def polygon(self) -> Polygon:
        """The zone as a polygon."""
        (fx, fy), (cx, cy) = self.obj.front, self.obj.center

        def at(along: float, lat: float) -> tuple[float, float]:
            return (cx + fx * along - fy * lat, cy + fy * along + fx * lat)

        far = self.face + self.depth
        return Polygon(
            [at(self.face, self.lo), at(self.face, self.hi), at(far, self.hi), at(far, self.lo)]
        )


def front_access(
    scene: MeasuredFolder, vocab: Vocabulary, grid: ReachGrid | None, resting: dict[str, str | None]
) -> list[dict[str, Any]]:
    """One row per front-used piece of furniture standing on the floor."""
    rows: list[dict[str, Any]] = []
    if grid is None:
        return rows
    cx, cy = grid.centres()
    for obj in scene.objects:
        if not (obj.labels & vocab.front_access) or resting.get(obj.id) != "floor":
            continue
        zone = FrontZone.of(obj, grid.radius + FRONT_REACH_M)
        inside = zone.mask(cx, cy)
        reached = inside & grid.reach
        row = {"id": obj.id, "category": obj.category or min(obj.labels, default="")}
        if reached.any():
            gap = max(
                float(np.min(zone.along(cx[reached], cy[reached]))) - zone.face - grid.radius, 0.0
            )
            why = f"the robot reaches {gap:.2f} m from its front"
            rows.append({**row, "held": True, "gap_m": round(gap, 3), "reason": why})
            continue
        seat = _seat_reached(scene, vocab, grid, zone, cx, cy)
        if seat is not None:
            why = f"the robot reaches its seat {seat} (pulled out to use it)"
            rows.append({**row, "held": True, "gap_m": None, "reason": why})
            continue
        if (inside & grid.fits).any():
            why = "the floor in front is cut off from the entrance"
        elif (inside & grid.free).any():
            why = f"less than {2 * grid.radius:.1f} m of free floor in front"
        else:
            why = "no free floor in front (blocked)"
        rows.append({**row, "held": False, "gap_m": None, "reason": why})
    return rows


def _seat_reached(
    scene: MeasuredFolder,
    vocab: Vocabulary,
    grid: ReachGrid,
    zone: FrontZone,
    cx: np.ndarray,
    cy: np.ndarray,
) -> str | None:
    """The id of a pull-out seat standing in ``zone`` that the robot comes close to, if any."""
    outline = zone.polygon()
    pad = grid.radius + FRONT_REACH_M
    for seat in scene.objects:
        if seat is zone.obj or not (seat.labels & vocab.pull_out_seats):
            continue
        if not seat.fp.intersects(outline):
            continue
        x0, y0, x1, y1 = seat.fp.bounds
        near = (
            grid.reach & (cx >= x0 - pad) & (cx <= x1 + pad) & (cy >= y0 - pad) & (cy <= y1 + pad)
        )
        if (
            near.any()
            and (shapely.distance(seat.fp, shapely.points(cx[near], cy[near])) <= pad).any()
        ):
            return seat.id
    return None
