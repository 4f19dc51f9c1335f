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
hard rule with the modules' own footprints and heights (:func:`~.hard_rules.hard_checks`;
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

from collections.abc import Callable, Mapping, Sequence
from typing import Any

import numpy as np
from shapely.geometry import box

from holomj.layout import geometry as geo
from holomj.layout.composite import check_split, composite_failure, composite_ids, split_result
from holomj.layout.counter_run_arrangements import (
    FALLBACKS,
    ISLAND_CATEGORY,
    LEG_PREFIX,
    MAX_ATTEMPTS,
    MAX_MODULES,
    RUN_CATEGORIES,
    SHAPES,
    SIMPLEST_FIRST,
    Arrangement,
    RunModule,
)
from holomj.layout.counter_run_legs import composite_problem, real_problem, split_legs
from holomj.layout.counter_run_walls import WallSpace, choose_arrangement, shape_weights
from holomj.layout.room_problem import PreparedRoom, RoomProblem
from holomj.layout.solve import LayoutResult
from holomj.layout.window_moves import raise_sill
from holomj.spec.scene import Window

__all__ = [
    "ISLAND_CATEGORY",
    "RUN_CATEGORIES",
    "RunModule",
    "run_modules",
    "run_windows",
    "solve_counter_run",
]

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
    choices, reasons = _shape_choices(space, high, modules, rng)
    order = _shape_order(space, choices, reasons, requested, island is not None, rng, record)
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


def _shape_choices(
    space: WallSpace,
    high: WallSpace | None,
    modules: Sequence[RunModule],
    rng: np.random.Generator,
) -> tuple[dict[str, tuple[Arrangement, bool]], dict[str, str]]:
    """Each shape's chosen arrangement with whether it needs the windows raised (it fits only
    on ``high``, the walls with the raisable windows' sills raised), and why each other shape
    does not fit."""
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
    return choices, reasons


def _shape_order(
    space: WallSpace,
    choices: Mapping[str, tuple[Arrangement, bool]],
    reasons: Mapping[str, str],
    requested: str | None,
    island: bool,
    rng: np.random.Generator,
    record: dict[str, Any],
) -> list[str]:
    """The shapes to solve, in order: the requested one and its fallbacks, else the drawn one
    and its fallbacks, then the other shapes that fit, simplest first (at most
    :data:`MAX_ATTEMPTS`). Notes in ``record`` how the first was chosen."""
    weights = shape_weights(space, island)
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
    return order[:MAX_ATTEMPTS]


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
    legs = composite_ids(problem, LEG_PREFIX, len(arr.legs))
    composite = composite_problem(_with_windows(problem, raisable), arr, legs, island)
    solved = solve(composite)
    failure = composite_failure(problem, solved, legs, defining_priority)
    if failure is not None:
        what, item, why = failure
        if what == "composite":
            return None, f"the layout left out leg {legs.index(item)} ({why})"
        return None, f"{item} did not fit beside the run ({why})"
    run = {m.id for seq in arr.legs for m in seq}
    split = split_legs(arr, [solved.placements[leg] for leg in legs], space, problem)
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
            if (
                tall
                and box(*geo.footprint(p.x, p.y, geo.yaw_index(p.yaw_deg), p.width, p.depth))
                .intersection(zone)
                .area
                > 1e-9
            ):
                needed[k] = window
                break
    real = real_problem(_with_windows(problem, needed), arr)
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
