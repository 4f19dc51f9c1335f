"""Where a counter run's legs can stand: the free stretches of a room's walls (:class:`WallSpace`:
clear of door zones and of the zones of windows lower than the leg), legs chained along walls
that meet at convex corners (:func:`chain_layout`), how well an arrangement fits them
(:func:`fit`), the seeded choice among the shapes that fit (:func:`shape_weights`,
:func:`choose_arrangement`).

See :mod:`holomj.layout.counter_runs` for the whole method.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np
import shapely
from shapely.geometry import Polygon

from holomj.layout import geometry as geo
from holomj.layout.counter_run_arrangements import (
    AISLE_M,
    EPS,
    FILLER_MAX_M,
    FRONT_BAND_M,
    GOOD_SLACK_M,
    JOIN_GAP_M,
    LEG_COUNT,
    MAX_FIT_TRIALS,
    Arrangement,
    RunModule,
    arrangements,
)
from holomj.layout.room_problem import PreparedRoom

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


def stretch(start: float, direction: int, seq: Sequence[RunModule]) -> list[Span]:
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
        return stretch(start, d, orders[k])

    def backward(k: int, end: float) -> list[Span]:
        return stretch(end, -d, orders[k][::-1])[::-1]

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
