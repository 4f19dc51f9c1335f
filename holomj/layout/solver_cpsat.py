"""The CP-SAT model of one room's floor layout (OR-Tools).

Variables, per object ``i``: presence ``p_i``; four yaw literals ``o_ik`` (``sum o_ik = p_i``);
integer centre ``(X_i, Y_i)`` on the grid (``grid_m``, default 5 cm).

Hard constraints:

* one ``NoOverlap2D`` over every object's collision box (footprint grown by half the clearance,
  rounded up to the grid; one optional rectangle per axis class, present when the object is
  placed with that class of yaw) and fixed obstacles: the cells of the room's bounding box not
  inside the room polygon (exact for rooms whose corners lie on the grid, conservative
  otherwise), a frame around the box, the door keep-out/swing zones, and extra corridor cells
  when the walkable path had to be reserved;
* one more ``NoOverlap2D`` per window: the objects taller than its sill against its zone;
* per object, a ``NoOverlap2D`` of a 2-cell-wide strip in front of the front face (present for
  the chosen yaw) against the walls: no object faces a wall closer than ``front_clearance_m``.

Soft constraints: one literal ``s_c`` per constraint, which implies both objects are placed and
enforces (through ``OnlyEnforceIf`` on ``s_c`` and the yaw literals) a conservative integer form
of the geometric test of :mod:`holomj.layout.geometry`: sizes are rounded the safe way so that
whatever the model calls satisfied passes the post-check. Objective: maximise
``W * sum q_i p_i + sum w_c * s_c`` (``q_i`` the object's priority) with ``W`` above the total
constraint weight, so placing one more object always wins over any number of relations, and an
object of priority ``q`` over ``q`` objects of priority 1; objects that cannot fit stay absent
(``p_i = 0``) and are reported, never dropped silently.

Determinism: with ``deterministic=True`` (the default) CP-SAT runs one worker stopped by a
deterministic time budget (``max_deterministic_time``, scaled from the time limit), so a seed gives
the same layout on every run, even on a loaded machine; the wall-clock limit (10x the budget) is
only a safety net, and the status says when it cut the search. ``deterministic=False`` runs
``workers`` (default 2) parallel workers on the wall clock: better on hard instances, not
reproducible.
"""

from __future__ import annotations

import time
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np
from ortools.sat.python import cp_model

from holomj.layout import geometry as geo
from holomj.layout.cpsat_soft_rules import SoftRules
from holomj.layout.geometry import CellRect, Pose
from holomj.layout.room_problem import PreparedRoom

# CP-SAT's deterministic time per second of wall time, measured on a 2-core machine on the
# living-room benchmark (about 0.07): the deterministic budget stays inside the wall-clock limit.
DETERMINISTIC_PER_SECOND = 0.05
WALL_SAFETY_FACTOR = 10.0


@dataclass
class CpSatOutcome:
    """The best layout CP-SAT found (grid units), with the solver's own account of it."""

    poses: dict[int, Pose] = field(default_factory=dict)
    status: str = "UNKNOWN"
    objective: float | None = None
    bound: float | None = None
    wall_time_s: float = 0.0
    found: bool = False


class _Model(SoftRules):
    """The room's CP-SAT model: variables, hard constraints, objective and hints."""

    def __init__(self, prep: PreparedRoom, extra_obstacles: Sequence[CellRect]) -> None:
        self.prep = prep
        self.m = cp_model.CpModel()
        self.extra = list(extra_obstacles)
        n = len(prep.items)
        self.p = [self.m.new_bool_var(f"p{i}") for i in range(n)]
        self.o = [[self.m.new_bool_var(f"o{i}_{k}") for k in range(4)] for i in range(n)]
        x_lo, x_hi = prep.i0, prep.i0 + prep.raster.nx
        y_lo, y_hi = prep.j0, prep.j0 + prep.raster.ny
        self.x = [self.m.new_int_var(x_lo, x_hi, f"x{i}") for i in range(n)]
        self.y = [self.m.new_int_var(y_lo, y_hi, f"y{i}") for i in range(n)]
        self.s: list[cp_model.IntVar] = []
        self.near_gaps: list[
            tuple[cp_model.IntVar, cp_model.LinearExpr, int]
        ] = []  # s, excess, cap
        for i in range(n):
            self.m.add(sum(self.o[i]) == self.p[i])

    # -------------------------------------------------------------- obstacles

    def _frame(self) -> list[CellRect]:
        prep = self.prep
        reach = 2
        for i in range(len(prep.items)):
            for k in range(2):
                hx, hy = prep.coll_half(i, k)
                reach = max(reach, 2 * max(hx, hy))
        reach += prep.units_up(prep.settings.front_clearance_m + prep.settings.middle_gap_m) + 4
        a0, b0 = prep.i0, prep.j0
        a1, b1 = a0 + prep.raster.nx, b0 + prep.raster.ny
        return [
            (a0 - reach, b0 - reach, a0, b1 + reach),
            (a1, b0 - reach, a1 + reach, b1 + reach),
            (a0, b0 - reach, a1, b0),
            (a0, b1, a1, b1 + reach),
        ]

    def _cells_to_units(self, rects: Sequence[CellRect]) -> list[CellRect]:
        i0, j0 = self.prep.i0, self.prep.j0
        return [(a + i0, b + j0, c + i0, d + j0) for a, b, c, d in rects]

    # -------------------------------------------------------------- hard part

    def build_hard(self) -> None:
        prep = self.prep
        frame = self._frame()
        walls = self._cells_to_units(geo.merge_cells(prep.wall_block)) + frame
        doors = self._cells_to_units(geo.merge_cells(prep.door_block & ~prep.wall_block))
        main_x, main_y = self._fixed(walls + doors + self.extra, "ob")
        self.wall_rects = walls
        # per window: the boxes of the objects taller than its sill, which keep clear of it
        tall_x: list[list] = [[] for _ in prep.window_blocks]
        tall_y: list[list] = [[] for _ in prep.window_blocks]
        self.parity: list[list] = []
        for i in range(len(prep.items)):
            lits = self._parity_lits(i)
            self.parity.append(lits)
            for k, lit in lits:
                hx, hy = prep.coll_half(i, k)
                ix = self.m.new_optional_fixed_size_interval_var(
                    self.x[i] - hx, 2 * hx, lit, f"bx{i}_{k}"
                )
                iy = self.m.new_optional_fixed_size_interval_var(
                    self.y[i] - hy, 2 * hy, lit, f"by{i}_{k}"
                )
                main_x.append(ix)
                main_y.append(iy)
                for w in prep.items[i].windows:
                    tall_x[w].append(ix)
                    tall_y[w].append(iy)
        self.m.add_no_overlap_2d(main_x, main_y)
        for w, block in enumerate(prep.window_blocks):
            rects = self._cells_to_units(geo.merge_cells(block & ~prep.wall_block))
            if tall_x[w] and rects:
                wx, wy = self._fixed(rects, f"win{w}_")
                self.m.add_no_overlap_2d(tall_x[w] + wx, tall_y[w] + wy)
        length = prep.units_up(prep.settings.front_clearance_m)
        if length > 0:
            for i in range(len(prep.items)):
                fx, fy = self._fixed(walls, f"fw{i}_")
                for k in range(4):
                    hx, hy = prep.coll_half(i, k)
                    xi, yi = self.x[i], self.y[i]
                    if k == 0:
                        sx, lx, sy, ly = xi + hx, length, yi - 1, 2
                    elif k == 1:
                        sx, lx, sy, ly = xi - 1, 2, yi + hy, length
                    elif k == 2:
                        sx, lx, sy, ly = xi - hx - length, length, yi - 1, 2
                    else:
                        sx, lx, sy, ly = xi - 1, 2, yi - hy - length, length
                    fx.append(
                        self.m.new_optional_fixed_size_interval_var(
                            sx, lx, self.o[i][k], f"fsx{i}_{k}"
                        )
                    )
                    fy.append(
                        self.m.new_optional_fixed_size_interval_var(
                            sy, ly, self.o[i][k], f"fsy{i}_{k}"
                        )
                    )
                self.m.add_no_overlap_2d(fx, fy)

    def _parity_lits(self, i: int) -> list[tuple[int, cp_model.IntVar]]:
        """(yaw index of the class, presence literal) per axis class of object i's box."""
        prep = self.prep
        if prep.coll_half(i, 0) == prep.coll_half(i, 1):
            return [(0, self.p[i])]
        lits = []
        for k in (0, 1):
            lit = self.m.new_bool_var(f"c{i}_{k}")
            self.m.add(lit == self.o[i][k] + self.o[i][k + 2])
            lits.append((k, lit))
        return lits

    def objective(self) -> None:
        """Placed objects (by priority) first, then constraint weights, then (tie-break) small
        near gaps.

        The scale makes one unit of constraint weight worth more than all tie-breaks together.
        """
        prep = self.prep
        penalties: list[tuple[cp_model.IntVar, int]] = []
        for s, excess, limit in self.near_gaps:
            # Counts only when the constraint holds: ``pen >= excess - limit * (1 - s)``.
            pen = self.m.new_int_var(0, limit, f"pen{len(penalties)}")
            self.m.add(pen >= excess - limit * (1 - s))
            penalties.append((pen, limit))
        scale = 1 + sum(limit for _, limit in penalties)
        self.scale = scale
        weights = [round(c.weight * scale) for c in prep.constraints]
        big = sum(weights) + scale
        # An object of priority q outweighs q objects of priority 1 and every constraint.
        self.m.maximize(
            sum(big * item.priority * p for item, p in zip(prep.items, self.p))
            + sum(w * s for w, s in zip(weights, self.s))
            - sum(pen for pen, _ in penalties)
        )

    def add_hint(self, hint: dict[int, Pose]) -> None:
        prep = self.prep
        g = prep.grid
        for i in range(len(prep.items)):
            if i in hint:
                x, y, k = hint[i]
                self.m.add_hint(self.p[i], 1)
                self.m.add_hint(self.x[i], x)
                self.m.add_hint(self.y[i], y)
                for q in range(4):
                    self.m.add_hint(self.o[i][q], int(q == k))
            else:
                self.m.add_hint(self.p[i], 0)
        metres = {i: (x * g, y * g, k) for i, (x, y, k) in hint.items()}
        for c, s in zip(prep.constraints, self.s):
            self.m.add_hint(s, int(prep.evaluate(c, metres)[0]))


def solve_cpsat(
    prep: PreparedRoom,
    *,
    time_limit_s: float = 1.0,
    seed: int = 0,
    hint: dict[int, Pose] | None = None,
    extra_obstacles: Sequence[CellRect] = (),
    workers: int = 2,
    deterministic: bool = True,
) -> CpSatOutcome:
    """Build and solve the model; poses of the best solution found within the budget."""
    start = time.perf_counter()
    model = _Model(prep, extra_obstacles)
    model.build_hard()
    model.build_soft()
    model.objective()
    if hint:
        model.add_hint(hint)
    solver = cp_model.CpSolver()
    params = solver.parameters
    params.random_seed = int(seed) % (2**31 - 1)
    if deterministic:
        # One worker and a deterministic budget from the nominal limit: the same seed gives the
        # same layout however loaded the machine is. (With two workers, even
        # interleave_search=True gave different optima between runs here.) The wall clock is a
        # safety net far beyond the budget.
        params.num_workers = 1
        params.max_deterministic_time = time_limit_s * DETERMINISTIC_PER_SECOND
        params.max_time_in_seconds = time_limit_s * WALL_SAFETY_FACTOR
    else:
        params.num_workers = max(1, workers)
        params.max_time_in_seconds = max(time_limit_s - (time.perf_counter() - start), 0.05)
    status = solver.solve(model.m)
    outcome = CpSatOutcome(status=solver.status_name(status))
    if (
        deterministic
        and status != cp_model.OPTIMAL
        and solver.deterministic_time < params.max_deterministic_time * 0.99
    ):
        outcome.status += " (stopped by the wall clock: may differ between runs)"
    outcome.wall_time_s = time.perf_counter() - start
    if status in (cp_model.OPTIMAL, cp_model.FEASIBLE):
        outcome.found = True
        outcome.objective = solver.objective_value / model.scale
        outcome.bound = solver.best_objective_bound / model.scale
        for i in range(len(prep.items)):
            if solver.boolean_value(model.p[i]):
                k = next(q for q in range(4) if solver.boolean_value(model.o[i][q]))
                outcome.poses[i] = (int(solver.value(model.x[i])), int(solver.value(model.y[i])), k)
    return outcome


def corridor_obstacles(prep: PreparedRoom, poses: dict[int, Pose]) -> list[CellRect]:
    """Cells (grid units) of a walkway between the doors that crosses as little furniture as
    possible, to reserve in a re-solve when a layout cut the doors apart."""
    import heapq

    walk = prep.walk
    g = prep.grid
    rects = [prep.footprint(i, x * g, y * g, k) for i, (x, y, k) in poses.items()]
    blocked = walk.blocked_cells(rects)
    free = walk.base
    nx, ny = free.shape
    starts = np.argwhere(walk.zones[0] & free)
    if starts.size == 0:
        return []
    dist = np.full(free.shape, np.inf)
    prev: dict[tuple[int, int], tuple[int, int]] = {}
    heap: list[tuple[float, int, int]] = []
    for a, b in starts:
        dist[a, b] = 0.0
        heapq.heappush(heap, (0.0, int(a), int(b)))
    while heap:
        d, a, b = heapq.heappop(heap)
        if d > dist[a, b]:
            continue
        for da, db in ((1, 0), (-1, 0), (0, 1), (0, -1)):
            u, v = a + da, b + db
            if 0 <= u < nx and 0 <= v < ny and free[u, v]:
                nd = d + 1.0 + (50.0 if blocked[u, v] else 0.0)
                if nd < dist[u, v]:
                    dist[u, v] = nd
                    prev[(u, v)] = (a, b)
                    heapq.heappush(heap, (nd, u, v))
    cells: set[tuple[int, int]] = set()
    for zone in walk.zones[1:]:
        targets = np.argwhere(zone & free)
        if targets.size == 0:
            continue
        end = min(((int(t[0]), int(t[1])) for t in targets), key=lambda t: dist[t])
        if not np.isfinite(dist[end]):
            continue
        node = end
        while node in prev:
            cells.add(node)
            node = prev[node]
        cells.add(node)
    if not cells:
        return []
    from shapely.geometry import Point
    from shapely.ops import unary_union

    xs, ys = walk.raster.centres()
    shapes = [Point(float(xs[c]), float(ys[c])).buffer(walk.radius, quad_segs=2) for c in cells]
    corridor = unary_union(shapes)
    mask = prep.raster.touched(corridor) & ~prep.wall_block
    i0, j0 = prep.i0, prep.j0
    return [(a + i0, b + j0, c + i0, d + j0) for a, b, c, d in geo.merge_cells(mask)]
