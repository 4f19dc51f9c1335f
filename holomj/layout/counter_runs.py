"""Kitchens as counter runs: the counters, the sink, the cooker and the dishwasher set side by
side into one run along the walls (one wall, L, U or galley), instead of scattered on the walls.

A room's *run modules* are its floor instances of the categories in :data:`RUN_CATEGORIES`; a
kitchen island, when the room has one, stands in front of the run. The run takes one of four
shapes, each made of *legs* (modules side by side along one wall, backs on the wall, the
neighbours :data:`JOIN_GAP_M` apart):

* ``one_wall``: one leg;
* ``galley``: two legs on opposite walls, facing each other across an aisle of at least
  :data:`AISLE_M`;
* ``L``: two legs on the two walls of a convex corner: the *corner leg* owns the corner square
  and leaves it empty (a dead corner under no module: a module there would have the other leg
  standing in front of its doors, which could then not open), the other leg starts at the
  corner leg's front (they meet without overlapping and every front stays free);
* ``U``: three legs on three walls in a row, each of its two junctions an L's (either leg may
  own the corner): the middle leg is laid from one junction and may stop at most
  :data:`FILLER_MAX_M` short of the other (a filler strip in a real kitchen: ``filler_m``).

The end legs of an L or a U reach at least :data:`MIN_ARM_M` past their corner square. A corner
leg's length (:meth:`Arrangement.leg_length`) includes the corner squares it owns.

How it is solved: every leg becomes one composite :class:`LayoutObject` (width: the sum of its
modules' widths, depth: the deepest module, height: the tallest) that the room's solver places
with the other furniture, held in shape by heavy constraints (every leg ``edge``; at a junction
the corner leg ``corner``, the other ``adjacent to`` and ``in front of`` it; galley legs ``face
to`` each other). A leg that abuts a corner leg is declared shorter at that end (the solver's
clearance and grid), since it is laid against the corner leg afterwards. Then the composites are
split back into their modules (:func:`chain_layout` for an L or a U: corner legs from their
corners, the other legs from their fronts), and the finished layout is checked against every
hard rule with the modules' own footprints and heights (:func:`holomj.layout.solve.hard_checks`;
modules of the run may touch). The constraints of the room (the template's, the prompt's) are
moved onto the legs for the solver and judged on the modules at the end, so the result reads
per instance as a plain layout does.

The shape is chosen before solving: :func:`fit` measures each shape's cheapest arrangement
against the free stretches of the room's walls (clear of door zones, and of the zones of windows
lower than the leg; :class:`WallSpace`), then the seeded generator draws among the shapes that
fit (:func:`shape_weights`: a narrow room leans to a galley or one wall, a big square one to an
L or a U), unless the plan asks for one (:attr:`holomj.spec.plan.PlanRoom.counter_run_shape`,
read by the planner from the request's words). Kitchen windows sit above the worktop: when a
shape fits only so, the windows the run stands in front of get their sills raised
(:func:`holomj.layout.window_moves.raise_sill`; the record's ``raised_windows``, applied by
:func:`run_windows`). The order of the modules keeps the sink and the cooker off the open ends
when there are plain modules enough to end the run, the cooker and the dishwasher out of
corners, the dishwasher next to the sink and, among equally good orders, the sink nearest a
window.

A shape that does not fit (the solver leaves a leg out or puts it elsewhere, or the split breaks
a hard rule) gives way to a simpler one (U, then L, then one wall: :data:`FALLBACKS`), then to
the other shapes that fit (at most :data:`MAX_ATTEMPTS` solves), and finally to independent
placement of the modules (today's layout, the template's constraints as they are): no module is
ever dropped for the sake of a run. The record (:func:`solve_counter_run`) says which shape was
asked for and used, how it was chosen, the legs (modules in chain order, from the run's first
open end), and every shape tried with the reason it failed.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
import shapely
from shapely.geometry import Polygon

from holomj.layout import geometry as geo
from holomj.layout.constraints import GLOBAL_KINDS, Constraint, normalize_name
from holomj.layout.open_pockets import ReachMeter
from holomj.layout.place_relations import opening_gap
from holomj.layout.room_problem import LayoutObject, PreparedRoom, RoomProblem
from holomj.layout.solve import (
    HardChecks,
    LayoutResult,
    Placement,
    UnplacedObject,
    constraint_reports,
    hard_checks,
)
from holomj.layout.window_moves import raise_sill
from holomj.spec.scene import Window

RUN_CATEGORIES = frozenset(
    {"kitchen_counter", "sink_counter", "stove", "base_cabinet", "dishwasher"}
)
ISLAND_CATEGORY = "kitchen_island"
SHAPES = ("one_wall", "galley", "L", "U")
SIMPLEST_FIRST = ("one_wall", "L", "galley", "U")
MAX_ATTEMPTS = 3  # shapes solved per layout before the modules are laid out one by one
# A shape that does not fit gives way to these, in order (then to independent placement).
FALLBACKS: dict[str, tuple[str, ...]] = {
    "U": ("U", "L", "one_wall"),
    "L": ("L", "one_wall"),
    "galley": ("galley", "one_wall"),
    "one_wall": ("one_wall",),
}
LEG_COUNT = {"one_wall": 1, "galley": 2, "L": 2, "U": 3}
# Which leg covers the corner of each junction of an L or a U (legs in chain order): an L's
# first leg (the two legs are interchangeable); a U's side legs, its middle leg, or one of each.
OWNERS: dict[str, tuple[tuple[int, ...], ...]] = {
    "one_wall": ((),),
    "galley": ((),),
    "L": ((0,),),
    "U": ((0, 2), (0, 1), (1, 2), (1, 1)),
}
JOIN_GAP_M = 0.002  # between neighbouring modules: they touch, and rounding never overlaps them
FILLER_MAX_M = 0.10  # a U's middle leg may stop this short of its far junction (a filler)
AISLE_M = 0.9  # the least floor between galley legs, and across a U
RUN_WEIGHT = 20.0  # the constraints that hold a run's legs in shape
ISLAND_WEIGHT = 5.0  # an island in front of the run
MAX_MODULES = 8  # more modules than this are laid out independently
MAX_FIT_TRIALS = 400  # arrangements tried against the room's walls per shape
GOOD_SLACK_M = 0.15  # free wall beyond a leg that makes a fit comfortable
MIN_ARM_M = 0.4  # an end leg of an L or a U reaches at least this far past its corner square
FRONT_BAND_M = 0.3  # the floor in front of a module next to a dead corner the other leg keeps
MAX_ORDER_COMBOS = 64  # equally cheap orders of the legs compared for the sink's window
EPS = 1e-6
LEG_PREFIX = "counter run "

# Penalties of an arrangement: a module at an open end (when there are modules enough to end
# the run with plain ones), in a corner, or next to a corner leg; pairs side by side. A cooker
# or a dishwasher never covers a corner (the other leg would block its front).
OPEN_END_PENALTY = {"sink_counter": 3.0, "stove": 4.0}
CORNER_PENALTY = {"stove": math.inf, "dishwasher": math.inf, "sink_counter": 2.0}
JUNCTION_PENALTY = {"stove": 1.0, "dishwasher": 2.0}
SINK_BY_STOVE_PENALTY = 1.0
DISHWASHER_AWAY_PENALTY = 1.0
PLAIN_CATEGORIES = frozenset({"kitchen_counter", "base_cabinet"})


@dataclass(frozen=True)
class RunModule:
    """One module of a run: a floor instance, its library category and its real footprint
    (``width`` left-right, ``depth`` front-back) and layout height, in metres."""

    id: str
    category: str
    width: float
    depth: float
    height: float
    priority: int = 1

    @property
    def signature(self) -> tuple[str, float, float, float]:
        """What makes two modules interchangeable in a run."""
        return (self.category, round(self.width, 4), round(self.depth, 4), round(self.height, 4))


def leg_ends(shape: str, owners: Sequence[int]) -> tuple[tuple[str, str], ...]:
    """The ends of each leg of ``shape``, from its first module to its last: "open" (the run
    ends there), "corner" (the module covers a corner square) or "junction" (it abuts the front
    of the leg that covers the corner); ``owners`` as in :data:`OWNERS`."""
    n = LEG_COUNT[shape]
    if shape in ("one_wall", "galley"):
        return (("open", "open"),) * n
    out = []
    for k in range(n):
        start = "open" if k == 0 else ("corner" if owners[k - 1] == k else "junction")
        end = "open" if k == n - 1 else ("corner" if owners[k] == k else "junction")
        out.append((start, end))
    return tuple(out)


@dataclass(frozen=True)
class Arrangement:
    """Modules grouped into legs, each ordered from its first end to its last (in chain order
    for an L or a U: see :func:`leg_ends`), which leg covers each corner, and how much the order
    costs. ``options`` holds every equally cheap order of each leg (``legs`` is the first)."""

    shape: str
    legs: tuple[tuple[RunModule, ...], ...]
    penalty: float
    owners: tuple[int, ...] = ()
    options: tuple[tuple[tuple[RunModule, ...], ...], ...] = ()

    def ends(self, k: int) -> tuple[str, str]:
        """The ends of leg ``k``."""
        return leg_ends(self.shape, self.owners)[k]

    def leg_length(self, k: int) -> float:
        """Length of leg ``k`` along its wall, neighbours :data:`JOIN_GAP_M` apart, with the
        corner squares it owns (:meth:`corner_square`)."""
        leg = self.legs[k]
        return sum(m.width for m in leg) + JOIN_GAP_M * (len(leg) - 1) + self.corner_square(k)

    def corner_square(self, k: int) -> float:
        """The length of wall leg ``k`` leaves empty at the corners it owns: per corner, the
        other leg's depth and a gap (a dead corner, so that no module stands with the other
        leg in front of its doors)."""
        total = 0.0
        for j, owner in enumerate(self.owners):  # junction j joins legs j and j + 1
            if owner == k:
                total += self.leg_depth(j + 1 if owner == j else j) + JOIN_GAP_M
        return total

    def leg_depth(self, k: int) -> float:
        """The deepest module of leg ``k``."""
        return max(m.depth for m in self.legs[k])

    def leg_height(self, k: int) -> float:
        """The tallest module of leg ``k``."""
        return max(m.height for m in self.legs[k])

    def joined(self, k: int) -> int:
        """How many ends of leg ``k`` abut a corner leg's front (0, 1 or 2)."""
        return sum(end == "junction" for end in self.ends(k))


# --------------------------------------------------------------------------- inputs


def run_modules(
    problem: RoomProblem,
    categories: Mapping[str, str],
    sizes: Mapping[str, Sequence[float]],
) -> list[RunModule]:
    """The problem's objects that belong in a counter run, with their real sizes.

    ``categories``: instance -> library category; ``sizes``: instance -> the asset's
    ``(x, y, z)`` size (depth, width, height). The height is the layout's (it may count a wall
    object hung above); the width is the asset's own, so that modules really touch."""
    out = []
    for obj in problem.objects:
        if categories.get(obj.id) not in RUN_CATEGORIES or obj.id not in sizes:
            continue
        depth, width, height = (float(v) for v in sizes[obj.id][:3])
        _, _, layout_height = problem.object_size_m(obj)
        out.append(
            RunModule(
                obj.id,
                categories[obj.id],
                width,
                depth,
                max(height, layout_height or height),
                obj.priority,
            )
        )
    return out


# --------------------------------------------------------------------------- arrangements


def _slot_penalty(category: str, ends: set[str], plain_enough: bool) -> float:
    penalty = 0.0
    if "open" in ends and plain_enough:
        penalty += OPEN_END_PENALTY.get(category, 0.0)
    if "corner" in ends:
        penalty += CORNER_PENALTY.get(category, 0.0)
    if "junction" in ends:
        penalty += JUNCTION_PENALTY.get(category, 0.0)
    return penalty


def leg_penalty(seq: Sequence[RunModule], ends: tuple[str, str], plain_enough: bool) -> float:
    """What an order of one leg costs (0: the sink and the cooker set in, nothing awkward)."""
    penalty = 0.0
    last = len(seq) - 1
    for pos, module in enumerate(seq):
        slot = set()
        if pos == 0:
            slot.add(ends[0])
        if pos == last:
            slot.add(ends[1])
        penalty += _slot_penalty(module.category, slot, plain_enough)
    for a, b in itertools.pairwise(seq):
        if {a.category, b.category} == {"sink_counter", "stove"}:
            penalty += SINK_BY_STOVE_PENALTY
    for pos, module in enumerate(seq):
        if module.category != "dishwasher":
            continue
        neighbours = {seq[p].category for p in (pos - 1, pos + 1) if 0 <= p <= last}
        if "sink_counter" not in neighbours:
            penalty += DISHWASHER_AWAY_PENALTY
    return penalty


def _plain_enough(modules: Sequence[RunModule], shape: str) -> bool:
    """Whether the run has plain modules (counters, cabinets) enough to end every open end."""
    open_ends = sum(end == "open" for ends in leg_ends(shape, OWNERS[shape][0]) for end in ends)
    plain = sum(m.category in PLAIN_CATEGORIES for m in modules)
    return len(modules) >= 3 and plain >= open_ends


def _best_orders(
    group: Sequence[RunModule], ends: tuple[str, str], plain_enough: bool
) -> tuple[float, list[tuple[RunModule, ...]]]:
    """The cheapest orders of one leg (distinct by module signature) and their cost."""
    best, orders, seen = math.inf, [], set()
    for perm in itertools.permutations(group):
        key = tuple(m.signature for m in perm)
        if key in seen:
            continue
        seen.add(key)
        cost = leg_penalty(perm, ends, plain_enough)
        if cost < best - EPS:
            best, orders = cost, [perm]
        elif cost <= best + EPS:
            orders.append(perm)
    return best, orders


def _arms_ok(arr: Arrangement) -> bool:
    """Whether each end leg of an L or a U reaches :data:`MIN_ARM_M` past the corner square it
    meets (a lone corner module is no leg)."""
    if arr.shape not in ("L", "U"):
        return True
    last = len(arr.legs) - 1
    for k, j, other in ((0, 0, 1), (last, last - 1, last - 1)):
        beyond = arr.leg_length(k)
        if arr.owners[j] == k:
            beyond -= arr.leg_depth(other)
        if beyond < MIN_ARM_M - EPS:
            return False
    return True


def arrangements(modules: Sequence[RunModule], shape: str) -> list[Arrangement]:
    """Every grouping of ``modules`` into the legs of ``shape`` (each leg at least one module),
    with every choice of corner legs, each leg in its cheapest order, cheapest first (ties in a
    fixed order)."""
    n_legs = LEG_COUNT[shape]
    if len(modules) < n_legs:
        return []
    modules = sorted(modules, key=lambda m: m.id)
    plain = _plain_enough(modules, shape)
    memo: dict[tuple[Any, ...], tuple[float, list[tuple[RunModule, ...]]]] = {}
    out: list[Arrangement] = []
    for owners in OWNERS[shape]:
        ends = leg_ends(shape, owners)
        seen: set[Any] = set()
        for assign in itertools.product(range(n_legs), repeat=len(modules)):
            if len(set(assign)) < n_legs:
                continue
            groups = [tuple(m for m, a in zip(modules, assign) if a == k) for k in range(n_legs)]
            key = tuple(tuple(sorted(m.signature for m in g)) for g in groups)
            if shape == "galley":
                key = tuple(sorted(key))
            if key in seen:
                continue
            seen.add(key)
            options, cost = [], 0.0
            for group, ends_k in zip(groups, ends):
                memo_key = (tuple(m.id for m in group), ends_k)
                if memo_key not in memo:
                    memo[memo_key] = _best_orders(group, ends_k, plain)
                leg_cost, orders = memo[memo_key]
                options.append(tuple(orders))
                cost += leg_cost
            if math.isinf(cost):
                continue
            arr = Arrangement(
                shape, tuple(o[0] for o in options), round(cost, 6), tuple(owners), tuple(options)
            )
            if _arms_ok(arr):
                out.append(arr)
    out.sort(key=lambda a: a.penalty)
    return out


# --------------------------------------------------------------------------- the room's walls


class WallSpace:
    """Free stretches of a room's walls for a leg of a given depth and height: the wall's band
    that lies in the room, clear of door zones and of the zones of windows lower than the leg."""

    def __init__(self, prep: PreparedRoom, sills: Mapping[int, float] | None = None) -> None:
        self.prep = prep
        self.walls = prep.walls
        self.room = prep.room
        # window index -> its sill height (``sills`` overrides the problem's: raised windows)
        self.sills = {k: w.sill_height for k, w in enumerate(prep.problem.windows)}
        self.sills.update(sills or {})
        self._cache: dict[tuple[int, float, tuple[int, ...]], list[tuple[float, float]]] = {}

    def corner_at_start(self, i: int) -> bool:
        """Whether wall ``i`` starts at a convex right-angled corner with the previous wall."""
        prev, wall = self.walls[i - 1], self.walls[i]
        if math.dist(prev.b, wall.a) > 1e-6:
            return False
        (tx0, ty0), (tx1, ty1) = prev.tangent, wall.tangent
        return tx0 * ty1 - ty0 * tx1 > 1 - 1e-6

    def free(self, i: int, depth: float, height: float) -> list[tuple[float, float]]:
        """Free ``(from, to)`` stretches along wall ``i`` for a leg ``depth`` deep and ``height``
        tall."""
        windows = tuple(k for k, sill in self.sills.items() if height > sill)
        key = (i, round(depth, 4), windows)
        if key not in self._cache:
            self._cache[key] = self._free(i, depth, windows)
        return self._cache[key]

    def _free(self, i: int, depth: float, windows: tuple[int, ...]) -> list[tuple[float, float]]:
        wall = self.walls[i]
        band = _band(wall, 0.0, wall.length, depth)
        blocked = [band.difference(self.room.buffer(1e-7))]
        blocked += list(self.prep.door_zones)
        blocked += [self.prep.window_zones[k] for k in windows]
        spans = []
        for zone in blocked:
            hit = band.intersection(zone)
            if hit.is_empty or hit.area < 1e-9:
                continue
            along = [wall.locate(p)[0] for p in shapely.get_coordinates(hit)]
            spans.append((max(min(along), 0.0), min(max(along), wall.length)))
        free, start = [], 0.0
        for a, b in sorted(spans):
            if a > start + EPS:
                free.append((start, a))
            start = max(start, b)
        if wall.length > start + EPS:
            free.append((start, wall.length))
        return free


def _band(wall: geo.WallSegment, a0: float, a1: float, depth: float) -> Polygon:
    (ax, ay), (tx, ty), (nx, ny) = wall.a, wall.tangent, wall.inward
    return Polygon(
        [
            (ax + tx * s + nx * d, ay + ty * s + ny * d)
            for s, d in ((a0, 0.0), (a1, 0.0), (a1, depth), (a0, depth))
        ]
    )


def _margin(
    spans: Sequence[tuple[float, float]], a0: float, a1: float, free_ends: str = "both"
) -> float | None:
    """The free wall beyond ``[a0, a1]`` in the stretch that holds it (at its ``free_ends``:
    "lo", "hi", "both" or "none", an end at a corner or a junction has none to spare), else
    None."""
    for s0, s1 in spans:
        if s0 - EPS <= a0 and a1 <= s1 + EPS:
            lo = a0 - s0 if free_ends in ("lo", "both") else math.inf
            hi = s1 - a1 if free_ends in ("hi", "both") else math.inf
            return min(lo, hi)
    return None


Span = tuple[RunModule, float, float]  # a module and its stretch (from, to) along its wall


@dataclass(frozen=True)
class ChainLayout:
    """An L or a U laid on its walls: per leg, its wall and its modules' stretches along it in
    chain order; the U's filler (the gap its middle leg leaves at its far junction)."""

    walls: tuple[int, ...]
    legs: tuple[tuple[Span, ...], ...]
    filler: float | None = None


def chain_walls(space: WallSpace, n_legs: int) -> list[tuple[int, ...]]:
    """Runs of ``n_legs`` consecutive walls that meet at convex right-angled corners, in both
    directions round the room."""
    n = len(space.walls)
    out = []
    for i in range(n):
        ccw = tuple((i + k) % n for k in range(n_legs))
        if len(set(ccw)) == n_legs and all(
            space.corner_at_start(ccw[k + 1]) for k in range(n_legs - 1)
        ):
            out.append(ccw)
        cw = tuple((i - k) % n for k in range(n_legs))
        if len(set(cw)) == n_legs and all(space.corner_at_start(cw[k]) for k in range(n_legs - 1)):
            out.append(cw)
    return out


def _stretch(start: float, direction: int, seq: Sequence[RunModule]) -> list[Span]:
    """Modules side by side from ``start`` towards ``direction`` (+1 or -1 along the wall)."""
    out, at = [], start
    for module in seq:
        end = at + direction * module.width
        out.append((module, min(at, end), max(at, end)))
        at = end + direction * JOIN_GAP_M
    return out


def _near_end(seq: Sequence[RunModule], extent: float) -> float:
    """The deepest of the modules ``seq`` (in order from one end of a leg) that start within
    ``extent`` of that end, neighbours :data:`JOIN_GAP_M` apart."""
    at, deepest = 0.0, 0.0
    for module in seq:
        if at >= extent - EPS:
            break
        deepest = max(deepest, module.depth)
        at += module.width + JOIN_GAP_M
    return deepest


def chain_layout(
    space: WallSpace,
    arr: Arrangement,
    walls: tuple[int, ...],
    orders: Sequence[tuple[RunModule, ...]],
) -> ChainLayout | str:
    """The L or U of ``arr`` (legs in ``orders``) laid on consecutive ``walls``: each corner leg
    from its corner square (left empty: :meth:`Arrangement.corner_square`), each other leg
    from the front of the corner leg it abuts; or why not (a U's middle leg too long for its
    wall, or more than :data:`FILLER_MAX_M` short)."""
    ws = space.walls
    ccw = walls[1] == (walls[0] + 1) % len(ws)
    d = 1 if ccw else -1  # chain direction along every wall of the chain

    def first(k: int) -> float:  # where leg k's wall meets the previous leg's wall
        return 0.0 if ccw else ws[walls[k]].length

    def last(k: int) -> float:  # where leg k's wall meets the next leg's wall
        return ws[walls[k]].length if ccw else 0.0

    def forward(k: int, start: float) -> list[Span]:
        return _stretch(start, d, orders[k])

    def backward(k: int, end: float) -> list[Span]:
        return _stretch(end, -d, orders[k][::-1])[::-1]

    legs: list[list[Span]] = [[] for _ in walls]
    gap = JOIN_GAP_M

    def square(owner: int, other: int, other_from_junction: Sequence[RunModule]) -> float:
        """The side of the empty corner square the owner leaves: the depth of the other leg's
        modules that meet the owner's front band there, and a gap."""
        extent = arr.leg_depth(owner) + gap + FRONT_BAND_M
        return _near_end(other_from_junction, extent) + gap

    # Junction 0 joins leg 0 (its last module) and leg 1 (its first).
    if arr.owners[0] == 0:
        side = square(0, 1, orders[1])
        legs[0] = backward(0, last(0) - d * side)
        depth = _near_end(orders[0][::-1], side + FRONT_BAND_M)
        legs[1] = forward(1, first(1) + d * (depth + gap))
    else:
        side = square(1, 0, orders[0][::-1])
        legs[1] = forward(1, first(1) + d * side)
        depth = _near_end(orders[1], side + FRONT_BAND_M)
        legs[0] = backward(0, last(0) - d * (depth + gap))
    filler = None
    if len(walls) == 3:  # junction 1 joins leg 1 (its last module) and leg 2 (its first)
        reached = legs[1][-1][2] if d > 0 else legs[1][-1][1]
        if arr.owners[1] == 2:
            side = square(2, 1, orders[1][::-1])
            legs[2] = forward(2, first(2) + d * side)
            stop = last(1) - d * (_near_end(orders[2], side + FRONT_BAND_M) + gap)
        else:
            side = square(1, 2, orders[2])
            stop = last(1) - d * side
        filler = (stop - reached) * d
        if filler < -EPS:
            return "the U's middle leg is longer than its wall leaves room for"
        if filler > FILLER_MAX_M + EPS:
            return f"the U's middle leg stops {filler:.2f} m short of its far junction"
        if arr.owners[1] == 1:
            depth = _near_end(orders[1][::-1], side + FRONT_BAND_M)
            legs[2] = forward(2, first(2) + d * (depth + gap))
    return ChainLayout(walls, tuple(tuple(leg) for leg in legs), filler)


def fit(space: WallSpace, arr: Arrangement) -> float | None:
    """How comfortably ``arr`` fits the room's walls (the least free wall left beyond an open
    end of the run, in metres), or None when no walls of the room hold it."""
    walls = space.walls
    n = len(walls)
    dims = [(arr.leg_length(k), arr.leg_depth(k), arr.leg_height(k)) for k in range(len(arr.legs))]

    def free(i: int, k: int) -> list[tuple[float, float]]:
        return space.free(i, dims[k][1], dims[k][2])

    best: float | None = None

    def keep(value: float | None) -> None:
        nonlocal best
        if value is not None and (best is None or value > best):
            best = value

    if arr.shape == "one_wall":
        for i in range(n):
            for s0, s1 in free(i, 0):
                if s1 - s0 >= dims[0][0] - EPS:
                    keep(s1 - s0 - dims[0][0])
        return best
    if arr.shape == "galley":
        for i, j in itertools.permutations(range(n), 2):
            wi, wj = walls[i], walls[j]
            if wi.facing_k is None or wj.facing_k != (wi.facing_k + 2) % 4:
                continue
            if wi.locate(wj.a)[1] < dims[0][1] + dims[1][1] + AISLE_M - EPS:
                continue
            ends = sorted(wi.locate(p)[0] for p in (wj.a, wj.b))
            if min(ends[1], wi.length) - max(ends[0], 0.0) < 0.5:
                continue  # the walls do not face each other
            ma = max((s1 - s0 - dims[0][0] for s0, s1 in free(i, 0)), default=-1.0)
            mb = max((s1 - s0 - dims[1][0] for s0, s1 in free(j, 1)), default=-1.0)
            if ma >= -EPS and mb >= -EPS:
                keep(min(ma, mb))
        return best
    for chain in chain_walls(space, len(arr.legs)):
        laid = chain_layout(space, arr, chain, arr.legs)
        if isinstance(laid, str):
            continue
        if arr.shape == "U":
            base = walls[chain[1]].length
            if base - dims[0][1] - dims[2][1] < AISLE_M - EPS:
                continue
            assert laid.filler is not None
            other = laid.filler + walls[chain[0]].length - base
            if other > FILLER_MAX_M + EPS:
                continue  # the solver could as well turn the U onto the other walls
        ccw = chain[1] == (chain[0] + 1) % n
        margins = []
        for k, (i, leg) in enumerate(zip(chain, laid.legs)):
            a0, a1 = min(span[1] for span in leg), max(span[2] for span in leg)
            open_ends = []
            if k == 0:
                open_ends.append("lo" if ccw else "hi")
            if k == len(chain) - 1:
                open_ends.append("hi" if ccw else "lo")
            free_ends = "both" if len(open_ends) == 2 else open_ends[0] if open_ends else "none"
            margins.append(_margin(free(i, k), a0, a1, free_ends))
        if all(m is not None for m in margins):
            keep(min(m for m in margins if m is not None))
    return best


def shape_weights(space: WallSpace, island: bool) -> dict[str, float]:
    """How likely each shape is drawn for the room: a narrow room (short side under 2.6 m, or
    sides 1.6 : 1 or longer) leans to a galley or one wall, a big square one to an L or a U; a
    room with an island gets no galley."""
    minx, miny, maxx, maxy = space.room.bounds
    short, long = sorted((maxx - minx, maxy - miny))
    aspect = long / max(short, EPS)
    narrow = short < 2.6 or aspect >= 1.6
    weights = {
        "one_wall": 1.0,
        "galley": 2.0 if narrow else 0.4,
        "L": 0.3 if narrow else 2.0,
        "U": 1.5 if aspect < 1.4 and short >= 3.0 else 0.2,
    }
    if island:
        weights["galley"] = 0.0
        weights["U"] *= 0.5
    return weights


def choose_arrangement(
    space: WallSpace, modules: Sequence[RunModule], shape: str, rng: np.random.Generator
) -> tuple[Arrangement | None, str]:
    """The cheapest arrangement of ``modules`` as ``shape`` that the room's walls hold (drawn
    among equals, comfortable fits first), or None and why not."""
    candidates = arrangements(modules, shape)
    settings = space.prep.settings
    # what the solver's clearance and its grid (at both ends of a leg) take from a wall
    need = settings.clearance_m + 2 * settings.grid_m
    draw = float(rng.random())  # one draw per call, whatever is found: runs stay reproducible
    if not candidates:
        return None, f"{len(modules)} module(s) cannot make {LEG_COUNT[shape]} legs"
    found: list[tuple[Arrangement, float]] = []
    for arr in candidates[:MAX_FIT_TRIALS]:
        if found and arr.penalty > found[0][0].penalty + EPS:
            break
        slack = fit(space, arr)
        if slack is not None and slack >= need - EPS:
            found.append((arr, slack))
    if not found:
        total = sum(m.width for m in modules)
        return None, (
            f"no walls of the room hold the {total:.2f} m of modules as {shape} legs clear of "
            "doors and windows"
        )
    good = [a for a, s in found if s >= GOOD_SLACK_M] or [a for a, _ in found]
    return good[min(int(draw * len(good)), len(good) - 1)], ""


# --------------------------------------------------------------------------- solving


def solve_counter_run(
    problem: RoomProblem,
    modules: Sequence[RunModule],
    *,
    solve: Callable[[RoomProblem], LayoutResult],
    rng: np.random.Generator,
    requested: str | None = None,
    island: str | None = None,
    defining_priority: int = 100,
    windows: Sequence[Window] = (),
    wall_height: float | None = None,
) -> tuple[LayoutResult, dict[str, Any] | None]:
    """Lay out ``problem`` with its run ``modules`` as one counter run (see the module
    docstring); ``solve`` solves a layout problem (the room's solver). Returns the layout, per
    instance as the plain solve gives it, and the record of the run (None when the room has no
    run: fewer than two modules, or neither a sink nor a cooker among them).

    ``island``: the instance of the room's kitchen island, if any; ``defining_priority``: an
    object of at least this priority (the room's defining furniture) left out by a shape makes
    that shape fail. ``windows`` (the room's, as in the scene) and ``wall_height``: when a
    shape fits only with windows above the worktop, as kitchen windows are, the windows the
    run stands in front of get their sills raised above it (:func:`raise_sill`); the record's
    ``raised_windows`` lists them and :func:`run_windows` applies them."""
    if len(modules) < 2 or not any(m.category in ("sink_counter", "stove") for m in modules):
        return solve(problem), None
    record: dict[str, Any] = {
        "shape": "independent",
        "requested": requested,
        "chosen_by": None,
        "modules": [m.id for m in modules],
        "legs": [],
        "tried": [],
        "fallback": None,
    }
    if len(modules) > MAX_MODULES:
        record["fallback"] = f"{len(modules)} modules, more than {MAX_MODULES} in one run"
        return solve(problem), record
    prep = PreparedRoom(problem)
    space = WallSpace(prep)
    raisable = _raisable(problem, modules, windows, wall_height)
    high = WallSpace(prep, {k: w.base_height for k, w in raisable.items()}) if raisable else None
    choices: dict[str, tuple[Arrangement, bool]] = {}
    reasons: dict[str, str] = {}
    for shape in SHAPES:
        arr, why = choose_arrangement(space, modules, shape, rng)
        if arr is None and high is not None:
            arr, _ = choose_arrangement(high, modules, shape, rng)
            if arr is not None:
                choices[shape] = (arr, True)
                continue
        if arr is not None:
            choices[shape] = (arr, False)
        else:
            reasons[shape] = why
    weights = shape_weights(space, island is not None)
    feasible = [s for s in SHAPES if s in choices and weights[s] > 0]
    drawn = None
    if feasible:
        p = np.array([weights[s] for s in feasible], dtype=float)
        drawn = feasible[int(rng.choice(len(feasible), p=p / p.sum()))]
    order: list[str] = []
    if requested in FALLBACKS:
        order += [s for s in FALLBACKS[requested] if s in choices]
        record["chosen_by"] = "request"
        if requested not in choices:
            record["tried"].append({"shape": requested, "outcome": reasons[requested]})
    if not order and drawn is not None:
        order = [s for s in FALLBACKS[drawn] if s in choices]
        record["chosen_by"] = "room"
    # then the other shapes that fit, simplest first, before giving up on a run
    order += [s for s in SIMPLEST_FIRST if s in feasible and s not in order]
    order = order[:MAX_ATTEMPTS]
    for shape in order:
        arr, raise_them = choices[shape]
        result, outcome = _attempt(
            problem,
            arr,
            space,
            solve,
            island,
            defining_priority,
            raisable if raise_them else {},
        )
        if result is not None:
            record.update(outcome)
            record["shape"] = shape
            if record["tried"]:
                record["fallback"] = "; ".join(
                    f"{t['shape']}: {t['outcome']}" for t in record["tried"]
                )
            return result, record
        record["tried"].append({"shape": shape, "outcome": outcome})
    if not order:
        listed = {t["shape"] for t in record["tried"]}
        record["tried"].extend(
            {"shape": s, "outcome": reasons[s]} for s in SHAPES if s in reasons and s not in listed
        )
    record["fallback"] = (
        "; ".join(f"{t['shape']}: {t['outcome']}" for t in record["tried"])
        or "no run shape fits the room"
    ) + "; the modules are laid out one by one"
    return solve(problem), record


def _raisable(
    problem: RoomProblem,
    modules: Sequence[RunModule],
    windows: Sequence[Window],
    wall_height: float | None,
) -> dict[int, Window]:
    """Problem window index -> the window with its sill above the run's tallest module, for
    every window lower than that whose wall leaves room to raise it."""
    if wall_height is None:
        return {}
    tallest = max(m.height for m in modules)
    scene = {w.id: w for w in windows}
    out = {}
    for k, lw in enumerate(problem.windows):
        window = scene.get(lw.id)
        if window is None or lw.sill_height >= tallest:
            continue
        raised = raise_sill(window, tallest, wall_height)
        if raised is not None:
            out[k] = raised
    return out


def run_windows(
    windows: Sequence[Window], record: Mapping[str, Any]
) -> tuple[list[Window], list[str]]:
    """``windows`` with the sills a counter run's ``record`` raised, and a note per window."""
    raised = {r["id"]: r for r in record.get("raised_windows", [])}
    out, notes = [], []
    for window in windows:
        r = raised.get(window.id)
        if r is None:
            out.append(window)
            continue
        out.append(
            window.model_copy(update={"base_height": r["base_height"], "height": r["height"]})
        )
        notes.append(
            f"raised the sill of window {window.id} from {window.base_height:.2f} to "
            f"{r['base_height']:.2f} m: the kitchen's {record.get('shape')} counter run stands "
            "in front of it"
        )
    return out, notes


def _with_windows(problem: RoomProblem, raised: Mapping[int, Window]) -> RoomProblem:
    """``problem`` with the windows of ``raised`` at their raised sills."""
    windows = [
        w.model_copy(update={"sill_height": raised[k].base_height, "height": raised[k].height})
        if k in raised
        else w
        for k, w in enumerate(problem.windows)
    ]
    return problem.model_copy(update={"windows": windows})


def _attempt(
    problem: RoomProblem,
    arr: Arrangement,
    space: WallSpace,
    solve: Callable[[RoomProblem], LayoutResult],
    island: str | None,
    defining_priority: int,
    raisable: Mapping[int, Window],
) -> tuple[LayoutResult | None, Any]:
    """Solve ``problem`` with ``arr``'s legs as composites (and the ``raisable`` windows
    raised) and split them; the layout and the record's fields, or None and why it failed."""
    legs = _leg_ids(problem, len(arr.legs))
    composite = _composite_problem(_with_windows(problem, raisable), arr, legs, island)
    solved = solve(composite)
    for k, leg in enumerate(legs):
        if leg not in solved.placements:
            why = next((u.reason for u in solved.unplaced if u.id == leg), "not placed")
            return None, f"the layout left out leg {k} ({why})"
    run = {m.id for seq in arr.legs for m in seq}
    by_id = {o.id: o for o in problem.objects}
    for item in solved.unplaced:
        if item.id in by_id and by_id[item.id].priority >= defining_priority:
            return None, f"{item.id} did not fit beside the run ({item.reason})"
    split = _split(arr, [solved.placements[leg] for leg in legs], space, problem)
    if isinstance(split, str):
        return None, split
    modules, fields = split
    placements = {i: p for i, p in solved.placements.items() if i not in legs}
    placements.update(modules)
    # only the windows that something taller than the sill now stands in front of stay raised
    heights = {o.id: problem.object_size_m(o)[2] for o in problem.objects}
    heights.update({m.id: m.height for seq in arr.legs for m in seq})
    needed = {}
    for k, window in raisable.items():
        zone = space.prep.window_zones[k]
        sill = problem.windows[k].sill_height
        for i, p in placements.items():
            height = heights.get(i)
            tall = height is None or height > sill
            if tall and Polygon(_corners(p)).intersection(zone).area > 1e-9:
                needed[k] = window
                break
    real = _real_problem(_with_windows(problem, needed), arr)
    checks = check_split(real, placements, run)
    if not checks.ok:
        problems = checks.problems("the run blocks the way between the doors")
        return None, "the split run breaks a hard rule: " + "; ".join(problems[:3])
    if needed:
        fields["raised_windows"] = [
            {
                "id": w.id,
                "base_height": w.base_height,
                "height": w.height,
                "was": problem.windows[k].sill_height,
            }
            for k, w in sorted(needed.items())
        ]
    if island is not None:
        fields["island"] = {
            "instance": island,
            "placed": island in placements,
            "in_front_of_run": any(
                r.satisfied
                for r in solved.constraints
                if r.object == island and r.kind == "in_front_of" and r.target in legs
            ),
        }
    return split_result(real, solved, placements, checks, legs), fields


def _corners(p: Placement) -> list[tuple[float, float]]:
    x0, y0, x1, y1 = geo.footprint(p.x, p.y, geo.yaw_index(p.yaw_deg), p.width, p.depth)
    return [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]


def _leg_ids(problem: RoomProblem, n: int) -> list[str]:
    taken = {normalize_name(o.id) for o in problem.objects}
    out, k = [], 0
    while len(out) < n:
        name = f"{LEG_PREFIX}{k}"
        if normalize_name(name) not in taken:
            out.append(name)
        k += 1
    return out


def _composite_problem(
    problem: RoomProblem, arr: Arrangement, legs: list[str], island: str | None
) -> RoomProblem:
    """The problem with each leg of ``arr`` as one object, the constraints moved onto the legs
    and the shape's own constraints added."""
    owner = {m.id: legs[k] for k, seq in enumerate(arr.legs) for m in seq}
    # A leg that abuts a corner leg is declared shorter at that end by the clearance (which
    # becomes contact) and two grid steps (the solver's grid rounds footprints up); the split
    # lays it against the corner leg, and the check of the split catches any clash.
    shrink = problem.settings.clearance_m + 2 * problem.settings.grid_m
    objects: list[LayoutObject] = []
    for obj in problem.objects:
        if obj.id not in owner:
            objects.append(obj)
            continue
        k = legs.index(owner[obj.id])
        if any(o.id == legs[k] for o in objects):
            continue
        seq = arr.legs[k]
        objects.append(
            LayoutObject(
                id=legs[k],
                width=arr.leg_length(k) - arr.joined(k) * shrink,
                depth=arr.leg_depth(k),
                height=arr.leg_height(k),
                unit="m",
                priority=max(m.priority for m in seq),
            )
        )
    kept: dict[tuple[str, str, str | None], Constraint] = {}

    def add(c: Constraint) -> None:
        old = kept.get(c.key)
        if old is None or old.weight < c.weight:
            kept[c.key] = c

    for c in problem.all_constraints().constraints:
        obj = owner.get(c.object, c.object)
        target = owner.get(c.target, c.target) if c.target is not None else None
        if c.object in owner and c.kind in GLOBAL_KINDS and c.kind in _RUN_OWN_PLACES:
            continue  # the run places its legs itself
        if target is not None and (obj == target or (c.object in owner and c.target in owner)):
            continue  # between modules of the run: kept by the run
        add(c.model_copy(update={"object": obj, "target": target}))
    source = f"counter run: {arr.shape}"

    def shape_rule(obj: str, kind: str, target: str | None = None, weight: float = RUN_WEIGHT):
        add(Constraint(object=obj, kind=kind, target=target, weight=weight, source=source))

    for leg in legs:
        shape_rule(leg, "edge")
    if arr.shape == "galley":
        shape_rule(legs[0], "face_to", legs[1])
        shape_rule(legs[1], "face_to", legs[0])
    for j, corner_leg in enumerate(arr.owners):  # junction j joins legs j and j + 1
        other = j + 1 if corner_leg == j else j
        shape_rule(legs[corner_leg], "corner")
        shape_rule(legs[other], "adjacent_to", legs[corner_leg])
        shape_rule(legs[other], "in_front_of", legs[corner_leg])
    if island is not None and arr.shape != "galley" and any(o.id == island for o in objects):
        main = max(range(len(legs)), key=lambda k: (arr.leg_length(k), -k))
        shape_rule(island, "in_front_of", legs[main], ISLAND_WEIGHT)
    return RoomProblem(
        room_id=problem.room_id,
        polygon=problem.polygon,
        size_unit=problem.size_unit,
        doors=problem.doors,
        windows=problem.windows,
        objects=objects,
        constraints=list(kept.values()),
        settings=problem.settings,
    )


# Place constraints a run module gives up to the run (the rest follow the module's leg).
_RUN_OWN_PLACES = frozenset({"edge", "middle", "corner", "centre"})


def _real_problem(problem: RoomProblem, arr: Arrangement) -> RoomProblem:
    """``problem`` with every run module at its real width (a layout object may be widened
    for a wall object hung above it): what the modules' footprints are checked as."""
    widths = {m.id: m.width for seq in arr.legs for m in seq}
    objects = []
    for obj in problem.objects:
        if obj.id in widths:
            _, depth, height = problem.object_size_m(obj)
            obj = obj.model_copy(
                update={"width": widths[obj.id], "depth": depth, "height": height, "unit": "m"}
            )
        objects.append(obj)
    return problem.model_copy(update={"objects": objects})


# --------------------------------------------------------------------------- splitting


def _placements(wall: geo.WallSegment, spans: Sequence[Span]) -> dict[str, Placement]:
    """Modules at their stretches along ``wall``, backs on it, fronts into the room."""
    k = wall.facing_k
    assert k is not None  # legs stand only at walls along x or y (edge_holds)
    (ax, ay), (tx, ty), (nx, ny) = wall.a, wall.tangent, wall.inward
    out = {}
    for module, a0, a1 in spans:
        mid = (a0 + a1) / 2
        out[module.id] = Placement(
            x=round(ax + tx * mid + nx * module.depth / 2, 6),
            y=round(ay + ty * mid + ny * module.depth / 2, 6),
            yaw_deg=90.0 * k,
            width=module.width,
            depth=module.depth,
        )
    return out


def _leg_wall(space: WallSpace, p: Placement, tolerance: float) -> int | None:
    """The wall a solved leg has its back to (within ``tolerance``), if any."""
    k = geo.yaw_index(p.yaw_deg)
    fx, fy = geo.FRONT[k]
    back = (p.x - fx * p.depth / 2, p.y - fy * p.depth / 2)
    best: tuple[float, int] | None = None
    for i, wall in enumerate(space.walls):
        if wall.facing_k != k:
            continue
        along, off = wall.locate(back)
        on_wall = -EPS <= along <= wall.length + EPS and -EPS <= off <= tolerance + EPS
        if on_wall and (best is None or off < best[0]):
            best = (off, i)
    return None if best is None else best[1]


def _sink_gap(space: WallSpace, placements: Mapping[str, Placement], sinks: set[str]) -> float:
    """How far the ``sinks`` are from the nearest window (0 without sinks or windows)."""
    windows = space.prep.anchors.windows
    out = 0.0
    for module_id, p in placements.items():
        if not windows or module_id not in sinks:
            continue
        k = geo.yaw_index(p.yaw_deg)
        out += min(float(opening_gap(p.x, p.y, k, (p.width, p.depth), w)) for w in windows)
    return out


def _split(
    arr: Arrangement, solved: list[Placement], space: WallSpace, problem: RoomProblem
) -> tuple[dict[str, Placement], dict[str, Any]] | str:
    """The modules of each solved leg laid side by side (a straight leg where the solver put
    it, an L's or a U's legs from their corners: :func:`chain_layout`) in the cheapest orders
    that bring the sink nearest a window, and the record's fields; or why the solved legs do
    not make the shape."""
    s = problem.settings
    walls = space.walls
    where = [_leg_wall(space, p, s.edge_tolerance_m + s.grid_m) for p in solved]
    if None in where:
        return f"leg {where.index(None)} does not stand with its back to a wall"
    ws = tuple(w for w in where if w is not None)
    best: tuple[float, list[list[Span]], float | None] | None = None
    combos = list(itertools.islice(itertools.product(*arr.options), MAX_ORDER_COMBOS))
    sinks = {m.id for leg in arr.legs for m in leg if m.category == "sink_counter"}
    if arr.shape in ("one_wall", "galley"):
        if arr.shape == "galley":
            wa, wb = walls[ws[0]], walls[ws[1]]
            if wa.facing_k is None or wb.facing_k != (wa.facing_k + 2) % 4:
                return "the galley's legs are not on opposite walls"
        starts = [walls[w].locate((p.x, p.y))[0] - p.width / 2 for w, p in zip(ws, solved)]
        for orders in combos:
            for flips in itertools.product((False, True), repeat=len(ws)):
                legs = [
                    _stretch(start + arr.leg_length(k), -1, order)
                    if flip
                    else _stretch(start, 1, order)
                    for k, (start, order, flip) in enumerate(zip(starts, orders, flips))
                ]
                score = _sink_gap(space, _all_placements(walls, ws, legs), sinks)
                if best is None or score < best[0] - EPS:
                    best = (score, legs, None)
    else:
        if ws not in chain_walls(space, len(ws)):
            return "the legs are not on consecutive walls that meet at corners"
        why = "no order of the legs fits"
        for orders in combos:
            laid = chain_layout(space, arr, ws, orders)
            if isinstance(laid, str):
                why = laid
                continue
            legs = [list(leg) for leg in laid.legs]
            score = _sink_gap(space, _all_placements(walls, ws, legs), sinks)
            if best is None or score < best[0] - EPS:
                best = (score, legs, laid.filler)
        if best is None:
            return why
    assert best is not None
    _, legs, filler = best
    placements = _all_placements(walls, ws, legs)
    if arr.shape == "galley":
        sides = [[placements[m.id] for m, _, _ in leg] for leg in legs]
        if not _face_each_other(sides[0], sides[1]):
            return "the galley's legs do not face each other"
    roles = [
        "run"
        if arr.shape == "one_wall"
        else "side"
        if arr.shape == "galley"
        else "middle"
        if arr.shape == "U" and k == 1
        else "corner"
        if k in arr.owners
        else "arm"
        for k in range(len(legs))
    ]
    extra: dict[str, Any] = {
        "legs": [
            {
                "role": role,
                "modules": [m.id for m, _, _ in leg],
                "wall": [[round(v, 3) for v in walls[w].a], [round(v, 3) for v in walls[w].b]],
                "length_m": round(max(a1 for _, _, a1 in leg) - min(a0 for _, a0, _ in leg), 3),
            }
            for role, leg, w in zip(roles, legs, ws)
        ],
        "penalty": arr.penalty,
    }
    if arr.shape == "U":
        extra["corner_legs"] = sorted(set(arr.owners))
        extra["filler_m"] = round(max(filler or 0.0, 0.0), 3)
    return placements, extra


def _all_placements(
    walls: Sequence[geo.WallSegment], ws: Sequence[int], legs: Sequence[Sequence[Span]]
) -> dict[str, Placement]:
    out: dict[str, Placement] = {}
    for w, leg in zip(ws, legs):
        out.update(_placements(walls[w], leg))
    return out


def _face_each_other(a: Sequence[Placement], b: Sequence[Placement]) -> bool:
    """Whether two legs on opposite walls overlap along them (they face each other)."""
    ra = [geo.footprint(p.x, p.y, geo.yaw_index(p.yaw_deg), p.width, p.depth) for p in a]
    rb = [geo.footprint(p.x, p.y, geo.yaw_index(p.yaw_deg), p.width, p.depth) for p in b]
    axis = 1 if geo.yaw_index(a[0].yaw_deg) % 2 == 0 else 0  # the direction along the walls
    lo_a, hi_a = min(r[axis] for r in ra), max(r[axis + 2] for r in ra)
    lo_b, hi_b = min(r[axis] for r in rb), max(r[axis + 2] for r in rb)
    return min(hi_a, hi_b) - max(lo_a, lo_b) > EPS


# --------------------------------------------------------------------------- checking


def check_split(
    problem: RoomProblem, placements: dict[str, Placement], run: set[str]
) -> HardChecks:
    """The hard rules on the finished layout: the solver's post-check with the modules' own
    footprints and heights, the modules of the run allowed to touch each other (every other
    pair keeps the clearance)."""
    touching = problem.settings.model_copy(update={"clearance_m": 0.0})
    prep = PreparedRoom(problem.model_copy(update={"settings": touching}))
    g = prep.grid
    poses = {
        prep.index[i]: (p.x / g, p.y / g, geo.yaw_index(p.yaw_deg)) for i, p in placements.items()
    }
    checks, _ = hard_checks(prep, poses)  # type: ignore[arg-type]
    clearance = problem.settings.clearance_m
    rects = {
        i: geo.footprint(p.x, p.y, geo.yaw_index(p.yaw_deg), p.width, p.depth)
        for i, p in placements.items()
    }
    for a in sorted(run & set(rects)):
        for b in sorted(set(rects) - run):
            gx, gy = geo.rect_gaps(rects[a], rects[b])
            if not (gx < -1e-7 and gy < -1e-7) and max(gx, gy) < clearance - 1e-6:
                checks.clearance.append(f"{a} and {b} are {max(gx, gy):.3f} m apart")
    return checks


def split_result(
    problem: RoomProblem,
    solved: LayoutResult,
    placements: dict[str, Placement],
    checks: HardChecks,
    legs: list[str],
) -> LayoutResult:
    """The layout per instance, every constraint of ``problem`` judged on it."""
    prep = PreparedRoom(problem)
    ordered = {o.id: placements[o.id] for o in problem.objects if o.id in placements}
    metres = {prep.index[i]: (p.x, p.y, geo.yaw_index(p.yaw_deg)) for i, p in ordered.items()}
    reports = constraint_reports(prep, metres)
    unplaced = [
        UnplacedObject(id=u.id, reason=u.reason) for u in solved.unplaced if u.id not in legs
    ]
    return LayoutResult(
        room_id=problem.room_id,
        placements=ordered,
        constraints=reports,
        satisfied=sum(r.satisfied for r in reports),
        total=len(reports),
        unplaced=unplaced,
        solve_time_s=solved.solve_time_s,
        solver_used=solved.solver_used,
        solver_status=solved.solver_status,
        hard_checks=checks,
        warnings=[*prep.warnings, *solved.warnings],
        reachable_share=round(ReachMeter(prep).pockets(prep.footprints_m(metres))[0], 4),
    )
