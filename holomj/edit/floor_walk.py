"""The walkway between a room's doors and its floor reachable from them (for a 0.3 m robot):
what a new footprint would block, cut off or leave out of reach."""

from __future__ import annotations

import numpy as np
import shapely
from scipy import ndimage
from shapely.geometry import Polygon

from holomj.layout import geometry as geo
from holomj.layout.room_problem import (
    PreparedRoom,
)

NAV_RADIUS_M = 0.15  # a 0.3 m robot must reach the new object and keep the floor it reached


NAV_CELL_M = 0.05


REACH_M = 0.1  # the robot gets this close to the object's footprint


LOST_FLOOR_M2 = 0.1


class FloorWalk:
    """The walkway between doors and the reachable floor of a room, with its objects held."""

    def __init__(
        self, polygon: Polygon, rects: list[tuple[float, float, float, float]], prep: PreparedRoom
    ) -> None:
        self.prep = prep
        self.rects = rects
        self.walk_ok = prep.walk.check(self.rects).ok
        self.raster = geo.Raster.around(polygon, NAV_CELL_M)
        self.base = geo.free_walk_mask(polygon, self.rects, self.raster, NAV_RADIUS_M)
        self.xs, self.ys = self.raster.centres()
        seeds = np.zeros_like(self.base)
        for zone in prep.door_zones:
            seeds |= np.asarray(shapely.contains_xy(zone, self.xs, self.ys), dtype=bool)
        self.seeds = seeds
        self.reach = self._reach(self.base)

    def _reach(self, free: np.ndarray) -> np.ndarray:
        labels, _ = ndimage.label(free)
        found = set(np.unique(labels[free & self.seeds]).tolist()) - {0}
        return np.isin(labels, list(found)) & free

    def problems(self, poly: Polygon) -> list[str]:
        rect = poly.bounds
        if self.walk_ok and not self.prep.walk.check([*self.rects, rect]).ok:
            return ["blocks the way between the doors"]
        if not self.seeds.any():
            return []
        free = geo.clear_of(self.base, self.xs, self.ys, [rect], NAV_RADIUS_M)
        reach = self._reach(free)
        lost = float((self.reach & free & ~reach).sum()) * NAV_CELL_M**2
        if lost > LOST_FLOOR_M2:
            return [f"cuts {lost:.2f} m² of floor off from the doors"]
        xmin, ymin, xmax, ymax = rect
        dx = np.maximum(np.maximum(xmin - self.xs, self.xs - xmax), 0.0)
        dy = np.maximum(np.maximum(ymin - self.ys, self.ys - ymax), 0.0)
        close = np.hypot(dx, dy) <= NAV_RADIUS_M + REACH_M + NAV_CELL_M
        if not (reach & close).any():
            return ["cannot be reached from a door"]
        return []
