"""Free floor a robot cannot reach: measured on a layout, and reduced by nudging furniture.

A robot stands where its disc fits between the walls and the footprints (a raster of :data:`CELL_M`
cells). The *reachable share* is the part of that free floor a robot reaches from a door's keep-out
zone, with a margin both ways (:data:`FREE_RADIUS_M`, :data:`PASSAGE_RADIUS_M` around
:data:`ROBOT_RADIUS_M`). Furniture clusters can cut off pockets (the corner behind an armchair and
a side table); :func:`open_pockets` moves the furniture around a pocket, a grid step at a time up
to :data:`MAX_SHIFT_M`, pushing ahead of it, just clear, what it would come too close to, then on
to :data:`MAX_PUSH_SHIFT_M` while it pushes something (a bed slides with its nightstand: the floor
beside a bed fenced by a wardrobe opposite its foot opens only when the bed clears the wardrobe,
and its nightstand stands in the way), keeping a move only when every hard rule still holds, the
reachable share grows and no satisfied constraint is lost, except that below :data:`TEMPLATE_SHARE`
the templates' constraints (not the prompt's, :data:`RELATION_WEIGHT`) may give way, and below
:data:`CUT_OFF_SHARE` (the door is cut off) any soft constraint may; until the share reaches
:data:`TARGET_SHARE`, no move helps or :data:`MAX_TRIALS` poses were tried
(:data:`MAX_TRIALS_SHORT` when less than :data:`TEMPLATE_SHARE` is reachable; a move that opens the
pocket and keeps every constraint is taken at once). While a door is cut off, only what borders
both the pocket and the floor reached is moved.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from functools import partial
from typing import Any

import numpy as np
import shapely
from scipy import ndimage

from holomj.layout import geometry as geo
from holomj.layout.constraints import RELATION_WEIGHT
from holomj.layout.geometry import Pose
from holomj.layout.hard_rules import hard_checks
from holomj.layout.room_problem import PreparedRoom

ROBOT_RADIUS_M = 0.2
# Free floor is where a slightly smaller robot fits (what another measure may count as free); it
# is reached only through passages a slightly larger one fits through, so that a move counts
# only when it opens a passage with room to spare or closes the pocket. Passages are judged
# between footprints grown to the navigation map's cells (a map marks a cell blocked wherever
# furniture touches it, so a passage there is up to a cell narrower on each side: 0.5 m between
# two desks is closed to a 0.2 m robot); the desk grid, whose aisles are built to measure and
# whose seats are smaller than their footprints, judges them between the bare footprints.
FREE_RADIUS_M = 0.17
PASSAGE_RADIUS_M = 0.25  # between bare footprints
NAV_CELL_M = 0.05  # the navigation map's cells, on the world grid (holomj.robots.occupancy)
# ... and the robot that must pass between footprints grown to them: an evaluator's 0.2 m robot
# fits where the blocked cells are 0.2 m away, this one with a little to spare
NAV_PASSAGE_RADIUS_M = 0.225
CELL_M = 0.05
TARGET_SHARE = 0.985
MAX_SHIFT_M = 0.8
MAX_PUSH_SHIFT_M = 1.2  # ... for a move that pushes others along (a group clears more)
MAX_ROUNDS = 8
CUT_OFF_SHARE = 0.9  # below this share a door is cut off: moves may then cost soft constraints
TEMPLATE_SHARE = 0.97  # below this share moves may cost the templates' (not the prompt's) ones
MAX_TRIALS = 600  # poses tried in all, so that a crowded room stays fast
MAX_TRIALS_SHORT = 1500  # ... when less than TEMPLATE_SHARE of the floor is reachable
MAX_WINDOWS = 20000  # rect masks a meter keeps


class ReachMeter:
    """The reachable share of a room's free floor for given footprints (empty-room work once)."""

    def __init__(self, prep: PreparedRoom, *, nav_cells: bool = True) -> None:
        self.nav_cells = nav_cells  # grow footprints to the navigation map's cells for passages
        self._windows: dict[tuple, tuple[int, int, int, int, np.ndarray] | None] = {}
        self.passage = NAV_PASSAGE_RADIUS_M if nav_cells else PASSAGE_RADIUS_M
        self.raster = geo.Raster.around(prep.room, CELL_M)
        self.base_free = geo.free_walk_mask(prep.room, [], self.raster, FREE_RADIUS_M)
        self.base_pass = geo.free_walk_mask(prep.room, [], self.raster, self.passage)
        xs, ys = self.raster.centres()
        self.xs, self.ys = xs, ys
        seeds = np.zeros(self.base_free.shape, dtype=bool)
        for zone in prep.door_zones:
            seeds |= np.asarray(shapely.contains_xy(zone, xs, ys), dtype=bool)
        self.seeds = seeds
        self.applicable = bool((seeds & self.base_pass).any())
        steps = int(np.ceil((self.passage - FREE_RADIUS_M) / CELL_M)) + 1
        self.sweep = ndimage.generate_binary_structure(2, 2)
        self.sweep_steps = steps

    def pockets(self, rects: Sequence[Sequence[float]]) -> tuple[float, np.ndarray]:
        """The reachable share and the mask of free cells not reachable from a door."""
        share, pocket, _ = self.split(rects)
        return share, pocket

    def split(self, rects: Sequence[Sequence[float]]) -> tuple[float, np.ndarray, np.ndarray]:
        """The reachable share, the mask of free cells not reachable from a door and the mask
        of those reachable."""
        free = self._clear_of(self.base_free, rects, FREE_RADIUS_M)
        passable = self._clear_of(
            self.base_pass,
            [_to_nav_cells(r) for r in rects] if self.nav_cells else rects,
            self.passage,
        )
        total = int(free.sum())
        if total == 0 or not self.applicable:
            return 1.0, np.zeros_like(free), free
        labels, _ = ndimage.label(passable)
        reached = set(np.unique(labels[passable & self.seeds]).tolist()) - {0}
        core = np.isin(labels, list(reached)) & passable
        # what the larger robot reaches, grown by the difference of the radii: the floor the
        # smaller one covers from there
        reach = ndimage.binary_dilation(core, self.sweep, iterations=self.sweep_steps) & free
        return float(reach.sum()) / total, free & ~reach, reach

    def _clear_of(
        self, free: np.ndarray, rects: Sequence[Sequence[float]], radius: float
    ) -> np.ndarray:
        """:func:`geo.clear_of`, working only on the cells around each rect (the same mask,
        many times faster in a large room: the poses tried are many)."""
        free = free.copy()
        for rect in rects:
            window = self._window(tuple(rect), radius)
            if window is not None:
                i0, i1, j0, j1, clear = window
                free[i0:i1, j0:j1] &= clear
        return free

    def _window(
        self, rect: tuple[float, ...], radius: float
    ) -> tuple[int, int, int, int, np.ndarray] | None:
        """The cells around ``rect`` and which of them are at least ``radius`` from it (kept:
        most poses tried move one or two objects, and the others' windows are the same)."""
        key = (rect, radius)
        if key in self._windows:
            return self._windows[key]
        if len(self._windows) > MAX_WINDOWS:
            self._windows.clear()
        xmin, ymin, xmax, ymax = rect
        r = self.raster
        nx, ny = self.base_free.shape
        # one cell more than the radius each way: the cells left out are farther than it
        i0 = max(int(np.floor((xmin - radius - r.x0) / r.cell)) - 1, 0)
        i1 = min(int(np.ceil((xmax + radius - r.x0) / r.cell)) + 1, nx)
        j0 = max(int(np.floor((ymin - radius - r.y0) / r.cell)) - 1, 0)
        j1 = min(int(np.ceil((ymax + radius - r.y0) / r.cell)) + 1, ny)
        window = None
        if i0 < i1 and j0 < j1:
            xs, ys = self.xs[i0:i1, j0:j1], self.ys[i0:i1, j0:j1]
            dx = np.maximum(np.maximum(xmin - xs, xs - xmax), 0.0)
            dy = np.maximum(np.maximum(ymin - ys, ys - ymax), 0.0)
            window = (i0, i1, j0, j1, dx * dx + dy * dy >= radius * radius)
        self._windows[key] = window
        return window


def _to_nav_cells(rect: Sequence[float]) -> tuple[float, float, float, float]:
    """A footprint grown to the navigation map's cells it touches: a map marks a cell blocked
    wherever furniture meets it, so a passage there is up to a cell narrower on each side."""
    xmin, ymin, xmax, ymax = rect
    c = NAV_CELL_M  # a cell that only touches the footprint's edge is blocked too
    return (
        float((np.ceil(xmin / c - 1e-6) - 1) * c),
        float((np.ceil(ymin / c - 1e-6) - 1) * c),
        float((np.floor(xmax / c + 1e-6) + 1) * c),
        float((np.floor(ymax / c + 1e-6) + 1) * c),
    )


def reachable_share(prep: PreparedRoom, poses: dict[int, Pose]) -> float:
    """The reachable share of the room's free floor with the objects at ``poses``."""
    return ReachMeter(prep).pockets(prep.footprints(poses))[0]


def open_pockets(prep: PreparedRoom, poses: dict[int, Pose]) -> dict[int, Pose]:
    """Nudge the furniture around unreachable pockets (see the module docstring)."""
    from holomj.layout.solver_greedy import satisfied_weight

    meter = ReachMeter(prep)
    if not meter.applicable or not poses:
        return poses
    g = prep.grid
    share, pocket, reached = meter.split(prep.footprints(poses))
    if share >= TARGET_SHARE:
        return poses
    poses = dict(poses)
    weight = satisfied_weight(prep, prep.metres(poses))
    asked = asked_weight(prep, poses)
    steps = max(1, round(MAX_SHIFT_M / g))
    push_steps = max(steps, round(MAX_PUSH_SHIFT_M / g))
    budget = MAX_TRIALS if share >= TEMPLATE_SHARE else MAX_TRIALS_SHORT
    trials = 0
    for _ in range(MAX_ROUNDS):
        best: tuple[tuple[bool, float, float], dict[int, Pose]] | None = None
        # a door cut off is reopened by what stands between the floor reached and the rest
        frontier = reached if share < CUT_OFF_SHARE else None
        for i in _bordering(prep, poses, pocket, meter, frontier):
            for dx, dy in ((1, 0), (-1, 0), (0, 1), (0, -1)):
                for n in range(1, push_steps + 1):
                    trial = _shifted(prep, poses, i, dx, dy, n)
                    if n > steps and sum(trial[j] != poses[j] for j in trial) < 2:
                        break  # alone, it goes no farther than MAX_SHIFT_M
                    trials += 1
                    if trials > budget:
                        break
                    # the reach first: it is the cheapest test, and most poses open nothing
                    new_share, _ = meter.pockets(prep.footprints(trial))
                    if new_share <= share + 1e-6:
                        continue
                    checks, _ = hard_checks(prep, trial)
                    if not checks.ok:
                        break
                    new_weight = satisfied_weight(prep, prep.metres(trial))
                    if new_weight < weight - 1e-9 and not _may_give_way(
                        share, asked, partial(asked_weight, prep, trial)
                    ):
                        continue
                    # while the door is cut off, the largest share; among the moves that
                    # reconnect it, the one that keeps the most constraints
                    reconnected = new_share >= CUT_OFF_SHARE
                    key = (
                        (True, new_weight, new_share)
                        if reconnected
                        else (False, new_share, new_weight)
                    )
                    if new_share > share + 1e-6 and (best is None or key > best[0]):
                        best = (key, trial)
                    if new_share >= TARGET_SHARE and new_weight >= weight - 1e-9:
                        break  # the pocket is open and nothing is lost: look no further
                if _solved(best, weight):
                    break
            if _solved(best, weight):
                break
        if best is None:
            break
        _, poses = best
        weight = satisfied_weight(prep, prep.metres(poses))
        asked = asked_weight(prep, poses)
        share, pocket, reached = meter.split(prep.footprints(poses))
        if share >= TARGET_SHARE:
            break
    return poses


def _shifted(
    prep: PreparedRoom, poses: dict[int, Pose], i: int, dx: int, dy: int, n: int
) -> dict[int, Pose]:
    """``poses`` with object ``i`` moved ``n`` grid steps along ``(dx, dy)``, pushing ahead of it
    what it would come closer to than the clearance (and what that would, in turn), just far
    enough to keep the clearance: a bed slides with its nightstand, a desk with its chair."""
    g = prep.grid
    gap_min = prep.settings.clearance_m - 1e-6  # what hard_checks tolerates
    x, y, k = poses[i]
    out = {**poses, i: (x + dx * n, y + dy * n, k)}
    rects = {j: prep.footprint(j, px * g, py * g, pk) for j, (px, py, pk) in out.items()}

    def ahead(r: Sequence[float]) -> float:
        return (r[0] + r[2]) * dx + (r[1] + r[3]) * dy

    movers = [i]
    for _ in range(len(out) ** 2):  # pushes only go forward: a bound that is never reached
        if not movers:
            break
        a = movers.pop()
        for j in out:
            if j in (i, a) or ahead(rects[j]) <= ahead(rects[a]):
                continue  # what is behind is left, and hard_checks judges it
            gx, gy = geo.rect_gaps(rects[a], rects[j])
            if max(gx, gy) >= gap_min:
                continue
            m = int(np.ceil(((gap_min - (gx if dx else gy)) / g) - 1e-9))
            px, py, pk = out[j]
            out[j] = (px + dx * m, py + dy * m, pk)
            rects[j] = prep.footprint(j, out[j][0] * g, out[j][1] * g, pk)
            movers.append(j)
    return out


def _solved(best: tuple[tuple[bool, float, float], Any] | None, weight: float) -> bool:
    """Whether the best move so far reaches the target share and keeps every constraint."""
    if best is None:
        return False
    (reconnected, first, second), _ = best
    return reconnected and second >= TARGET_SHARE and first >= weight - 1e-9


def _may_give_way(share: float, asked: float, asked_after: Callable[[], float]) -> bool:
    """Whether a move that costs satisfied constraints may be made: any while the door is cut
    off, the templates' only while the share is under :data:`TEMPLATE_SHARE`."""
    if share < CUT_OFF_SHARE:
        return True
    return share < TEMPLATE_SHARE and asked_after() >= asked - 1e-9


def asked_weight(prep: PreparedRoom, poses: dict[int, Pose]) -> float:
    """Total weight of the prompt's constraints (weight at least ``RELATION_WEIGHT``) that hold."""
    metres = prep.metres(poses)
    return sum(
        c.weight
        for c in prep.constraints
        if c.weight >= RELATION_WEIGHT - 1e-9 and prep.evaluate(c, metres)[0]
    )


def _bordering(
    prep: PreparedRoom,
    poses: dict[int, Pose],
    pocket: np.ndarray,
    meter: ReachMeter,
    frontier: np.ndarray | None = None,
) -> list[int]:
    """Objects whose footprint comes within the robot's reach of a pocket (and, given a
    ``frontier`` mask, of it too: the floor reached from a door), lowest priority first."""
    if not pocket.any():
        return []
    masks = [pocket] if frontier is None or not frontier.any() else [pocket, frontier]
    out = []
    g = prep.grid
    for i, (x, y, k) in poses.items():
        box = prep.footprint(i, x * g, y * g, k)
        if all(_within_reach(box, meter.xs[m], meter.ys[m]) for m in masks):
            out.append(i)
    return sorted(out, key=lambda i: (prep.items[i].priority, i))


def _within_reach(box: Sequence[float], px: np.ndarray, py: np.ndarray) -> bool:
    """Whether any of the points comes within the robot's reach of the box."""
    xmin, ymin, xmax, ymax = box
    reach = PASSAGE_RADIUS_M + 2 * CELL_M
    dx = np.maximum(np.maximum(xmin - px, px - xmax), 0.0)
    dy = np.maximum(np.maximum(ymin - py, py - ymax), 0.0)
    return bool((dx * dx + dy * dy <= reach * reach).any())
