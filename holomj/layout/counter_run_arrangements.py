"""What a counter run is made of and how its modules can be ordered: the run's categories and
shapes, its modules (:class:`RunModule`), the legs of each shape with the kind of each leg end
(open, corner, junction: :func:`leg_ends`), and the arrangements of the modules into legs,
cheapest first (:func:`arrangements`: the sink and the cooker off the open ends, the cooker and
the dishwasher out of corners, the dishwasher beside the sink).

See :mod:`holomj.layout.counter_runs` for the whole method.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

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
