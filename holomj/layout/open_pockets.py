"""Free floor a robot cannot reach: measured on a layout, and reduced by nudging furniture.

A robot of radius :data:`ROBOT_RADIUS_M` stands where its disc fits between the walls and the
footprints (a raster of :data:`CELL_M` cells). The *reachable share* is the part of those cells
connected to a door's keep-out zone. Furniture clusters can cut off pockets (the corner behind
an armchair and a side table); :func:`open_pockets` moves the furniture around a pocket, a grid
step at a time up to :data:`MAX_SHIFT_M`, keeping a move only when every hard rule still holds,
no satisfied constraint is lost and the reachable share grows, until the share reaches
:data:`TARGET_SHARE` or no move helps.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import shapely
from scipy import ndimage

from holomj.layout import geometry as geo
from holomj.layout.room_problem import PreparedRoom

Pose = tuple[int, int, int]
ROBOT_RADIUS_M = 0.22  # a 0.2 m robot and a little slack for the walls' rasterisation
CELL_M = 0.05
TARGET_SHARE = 0.985
MAX_SHIFT_M = 0.4
MAX_ROUNDS = 8


class ReachMeter:
    """The reachable share of a room's free floor for given footprints (empty-room work once)."""

    def __init__(self, prep: PreparedRoom) -> None:
        self.raster = geo.Raster.around(prep.room, CELL_M)
        self.base = geo.free_walk_mask(prep.room, [], self.raster, ROBOT_RADIUS_M)
        xs, ys = self.raster.centres()
        self.xs, self.ys = xs, ys
        seeds = np.zeros(self.base.shape, dtype=bool)
        for zone in prep.door_zones:
            seeds |= np.asarray(shapely.contains_xy(zone, xs, ys), dtype=bool)
        self.seeds = seeds
        self.applicable = bool((seeds & self.base).any())

    def free(self, rects: Sequence[Sequence[float]]) -> np.ndarray:
        """Cells where the robot's centre fits beside these footprints."""
        free = self.base.copy()
        r2 = ROBOT_RADIUS_M * ROBOT_RADIUS_M
        for xmin, ymin, xmax, ymax in rects:
            dx = np.maximum(np.maximum(xmin - self.xs, self.xs - xmax), 0.0)
            dy = np.maximum(np.maximum(ymin - self.ys, self.ys - ymax), 0.0)
            free &= dx * dx + dy * dy >= r2
        return free

    def pockets(self, rects: Sequence[Sequence[float]]) -> tuple[float, np.ndarray]:
        """The reachable share and the mask of free cells not reachable from a door."""
        free = self.free(rects)
        total = int(free.sum())
        if total == 0 or not self.applicable:
            return 1.0, np.zeros_like(free)
        labels, _ = ndimage.label(free)
        reached = set(np.unique(labels[free & self.seeds]).tolist()) - {0}
        reach = np.isin(labels, list(reached)) & free
        return float(reach.sum()) / total, free & ~reach


def reachable_share(prep: PreparedRoom, poses: dict[int, Pose]) -> float:
    """The reachable share of the room's free floor with the objects at ``poses``."""
    return ReachMeter(prep).pockets(_rects(prep, poses))[0]


def open_pockets(prep: PreparedRoom, poses: dict[int, Pose]) -> dict[int, Pose]:
    """Nudge the furniture around unreachable pockets (see the module docstring)."""
    from holomj.layout.solve import hard_checks
    from holomj.layout.solver_greedy import satisfied_weight

    meter = ReachMeter(prep)
    if not meter.applicable or not poses:
        return poses
    g = prep.grid
    share, pocket = meter.pockets(_rects(prep, poses))
    if share >= TARGET_SHARE:
        return poses
    poses = dict(poses)
    weight = satisfied_weight(prep, _metres(poses, g))
    steps = max(1, round(MAX_SHIFT_M / g))
    for _ in range(MAX_ROUNDS):
        best: tuple[float, dict[int, Pose]] | None = None
        for i in _bordering(prep, poses, pocket, meter):
            x, y, k = poses[i]
            for dx, dy in ((1, 0), (-1, 0), (0, 1), (0, -1)):
                for n in range(1, steps + 1):
                    trial = {**poses, i: (x + dx * n, y + dy * n, k)}
                    checks, _ = hard_checks(prep, trial)
                    if not checks.ok:
                        break
                    if satisfied_weight(prep, _metres(trial, g)) < weight - 1e-9:
                        continue
                    new_share, _ = meter.pockets(_rects(prep, trial))
                    if new_share > share + 1e-6 and (best is None or new_share > best[0]):
                        best = (new_share, trial)
        if best is None:
            break
        share, poses = best
        share, pocket = meter.pockets(_rects(prep, poses))
        if share >= TARGET_SHARE:
            break
    return poses


def _bordering(
    prep: PreparedRoom, poses: dict[int, Pose], pocket: np.ndarray, meter: ReachMeter
) -> list[int]:
    """Objects whose footprint comes within the robot's reach of a pocket, lowest priority
    first."""
    if not pocket.any():
        return []
    px, py = meter.xs[pocket], meter.ys[pocket]
    reach = ROBOT_RADIUS_M + 2 * CELL_M
    out = []
    g = prep.grid
    for i, (x, y, k) in poses.items():
        xmin, ymin, xmax, ymax = prep.footprint(i, x * g, y * g, k)
        dx = np.maximum(np.maximum(xmin - px, px - xmax), 0.0)
        dy = np.maximum(np.maximum(ymin - py, py - ymax), 0.0)
        if (dx * dx + dy * dy <= reach * reach).any():
            out.append(i)
    return sorted(out, key=lambda i: (prep.items[i].priority, i))


def _rects(prep: PreparedRoom, poses: dict[int, Pose]) -> list[tuple[float, ...]]:
    g = prep.grid
    return [prep.footprint(i, x * g, y * g, k) for i, (x, y, k) in poses.items()]


def _metres(poses: dict[int, Pose], g: float) -> dict[int, tuple[float, float, int]]:
    return {i: (x * g, y * g, k) for i, (x, y, k) in poses.items()}
