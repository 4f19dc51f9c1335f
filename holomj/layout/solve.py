"""Solve one room's floor layout and check the answer independently.

:func:`solve_room` runs the greedy solver (the whole answer with ``solver="greedy"``, else the
warm start), then CP-SAT with the rest of the time budget. If CP-SAT's layout cuts the doors
apart, a walkway is reserved and CP-SAT runs again; if it finds nothing, the greedy layout is
used and the result says so. Objects CP-SAT left out are offered to the greedy inserter.

The post-check does not trust either solver: it rebuilds every footprint in metres and tests
overlaps and clearance, containment in the room polygon, door zones, windows against tall
objects, the space in front of each object and the walkable path between doors with shapely and
the occupancy grid, and evaluates every constraint with the geometric predicates. An object that
fails a hard test is taken out and listed as unplaced with the reason: nothing is dropped
silently.
"""

from __future__ import annotations

import time
from typing import Literal

import numpy as np

from holomj.errors import InputError
from holomj.layout import geometry as geo
from holomj.layout.geometry import Pose
from holomj.layout.hard_rules import hard_checks
from holomj.layout.layout_result import (
    ConstraintReport,
    LayoutResult,
    Placement,
    UnplacedObject,
)
from holomj.layout.open_pockets import open_pockets, reachable_share
from holomj.layout.room_problem import PreparedRoom, RoomProblem
from holomj.layout.solver_cpsat import corridor_obstacles, solve_cpsat
from holomj.layout.solver_greedy import insert_unplaced, satisfied_weight, solve_greedy

SOLVERS = ("cpsat", "greedy")
GREEDY_SHARE = 0.3  # of the time limit, for the greedy warm start before CP-SAT
SAFETY_FACTOR = 10.0  # deterministic runs: the wall clock stops a search only this far past it


def solve_room(
    problem: RoomProblem,
    *,
    solver: Literal["cpsat", "greedy"] = "cpsat",
    time_limit_s: float = 1.0,
    rng: np.random.Generator | None = None,
    deterministic: bool = True,
    workers: int = 2,
) -> LayoutResult:
    """Place the problem's objects; see the module docstring for the strategy.

    ``rng`` drives tie-breaking in the greedy solver and CP-SAT's seed (default: seed 0).
    """
    if solver not in SOLVERS:
        raise InputError(
            f"unknown solver {solver!r}", where="solver", fix=f"use one of: {', '.join(SOLVERS)}"
        )
    if not time_limit_s > 0:
        raise InputError("time limit must be positive", where="time_limit_s")
    start = time.perf_counter()
    rng = rng if rng is not None else np.random.default_rng(0)
    prep = PreparedRoom(problem)
    warnings = list(prep.warnings)
    if not prep.items:
        return _report(prep, {}, {}, start, "none", "no objects", warnings)
    greedy_share = 1.0 if solver == "greedy" else GREEDY_SHARE
    # Deterministic runs bound the greedy search by its attempts and backtracks; the wall clock
    # only stops it as a safety net, so a loaded machine does not change the layout.
    greedy_clock = time_limit_s * greedy_share * (SAFETY_FACTOR if deterministic else 1.0)
    greedy = solve_greedy(prep, rng, greedy_clock)
    poses: dict[int, Pose] = greedy.poses
    reasons: dict[int, str] = dict(greedy.unplaced)
    used, status = "greedy", f"{greedy.attempts} attempt(s), {greedy.backtracks} backtrack(s)"
    if solver == "cpsat":
        seed = int(rng.integers(0, 2**31 - 1))
        found, status = _run_cpsat(
            prep, greedy.poses, start, time_limit_s, seed, deterministic, workers
        )
        if found is None:
            used = "greedy"
            warnings.append(f"CP-SAT found no usable layout ({status}); used the greedy one")
        else:
            missing = [i for i in range(len(prep.items)) if i not in found]
            found, extra_reasons = insert_unplaced(prep, found, missing, rng)
            cp_key = (_placed_priority(prep, found), satisfied_weight(prep, prep.metres(found)))
            gr_key = (
                _placed_priority(prep, greedy.poses),
                satisfied_weight(prep, prep.metres(greedy.poses)),
            )
            if cp_key >= gr_key:
                poses, reasons, used = found, extra_reasons, "cpsat"
            else:
                used = "greedy"
                warnings.append(
                    f"the greedy layout beat CP-SAT's within the time limit "
                    f"({gr_key[0]} placed, weight {gr_key[1]:g} vs {cp_key[0]}, {cp_key[1]:g})"
                )
    poses, reasons = _enforce_hard(prep, poses, reasons, warnings)
    poses = snap_to_walls(prep, poses)
    poses = open_pockets(prep, poses)
    return _report(prep, poses, reasons, start, used, status, warnings)


def constraint_reports(
    prep: PreparedRoom, metres: dict[int, tuple[float, float, int]]
) -> list[ConstraintReport]:
    """Every constraint of the room judged on poses in metres ``{index: (x, y, yaw index)}``."""
    reports = []
    for c in prep.constraints:
        ok, detail = prep.evaluate(c, metres)
        reports.append(
            ConstraintReport(
                text=c.text,
                object=c.object,
                kind=c.kind,
                target=c.target,
                weight=c.weight,
                satisfied=ok,
                detail=detail,
                source=c.source,
            )
        )
    return reports


def _placed_priority(prep: PreparedRoom, poses: dict[int, Pose]) -> int:
    """How much of what matters is placed: the sum of the placed objects' priorities."""
    return sum(prep.items[i].priority for i in poses)


SNAP_REACH_M = 1.0  # how far an edge object may be pushed back towards its wall


def snap_to_walls(prep: PreparedRoom, poses: dict[int, Pose]) -> dict[int, Pose]:
    """Objects asked to stand at an ``edge`` pushed back, a grid step at a time (up to
    :data:`SNAP_REACH_M`), until their back meets the wall (as Holodeck moves edge objects onto
    the wall; one the search left short of its wall gets there too); a step is kept only while
    every hard rule still holds and no satisfied constraint is lost."""
    edge = sorted({prep.index[c.object] for c in prep.constraints if c.kind == "edge"})
    if not edge:
        return poses
    poses = dict(poses)
    g = prep.grid
    checks, _ = hard_checks(prep, poses)
    if not checks.ok:
        return poses
    weight = satisfied_weight(prep, prep.metres(poses))
    steps = max(1, prep.units_up(max(prep.settings.edge_tolerance_m + g, SNAP_REACH_M)))
    for i in edge:
        if i not in poses:
            continue
        for _ in range(steps):
            x, y, k = poses[i]
            fx, fy = geo.FRONT[k]
            trial = {**poses, i: (x - fx, y - fy, k)}
            checks, _ = hard_checks(prep, trial)
            if not checks.ok:
                break
            new_weight = satisfied_weight(prep, prep.metres(trial))
            if new_weight < weight - 1e-9:
                break
            poses, weight = trial, new_weight
    return poses


def _walk_ok(prep: PreparedRoom, poses: dict[int, Pose]) -> bool:
    return prep.walk.check(prep.footprints(poses)).ok


def _run_cpsat(
    prep: PreparedRoom,
    hint: dict[int, Pose],
    start: float,
    time_limit_s: float,
    seed: int,
    deterministic: bool,
    workers: int,
) -> tuple[dict[int, Pose] | None, str]:
    # Deterministic: the budgets come from the nominal limit (CP-SAT's deterministic time), not
    # from the time left on the clock.
    if deterministic:
        remaining = time_limit_s * (1.0 - GREEDY_SHARE)
    else:
        remaining = max(time_limit_s - (time.perf_counter() - start), 0.05)
    share = 0.6 if prep.walk.applicable else 1.0
    out = solve_cpsat(
        prep,
        time_limit_s=remaining * share,
        seed=seed,
        hint=hint,
        workers=workers,
        deterministic=deterministic,
    )
    if not out.found:
        return None, out.status
    if not prep.walk.applicable or _walk_ok(prep, out.poses):
        return out.poses, out.status
    corridor = corridor_obstacles(prep, out.poses)
    if deterministic:
        remaining = time_limit_s * (1.0 - GREEDY_SHARE) * (1.0 - share)
    else:
        remaining = max(time_limit_s - (time.perf_counter() - start), 0.1)
    again = solve_cpsat(
        prep,
        time_limit_s=remaining,
        seed=seed,
        hint=hint,
        extra_obstacles=corridor,
        workers=workers,
        deterministic=deterministic,
    )
    if again.found and _walk_ok(prep, again.poses):
        return again.poses, f"{again.status} (with a reserved walkway)"
    return None, "layouts blocked the walkable path between the doors"


# --------------------------------------------------------------------------- post-check


def _enforce_hard(
    prep: PreparedRoom,
    poses: dict[int, Pose],
    reasons: dict[int, str],
    warnings: list[str],
) -> tuple[dict[int, Pose], dict[int, str]]:
    """Take out objects that break a hard rule (a solver bug if it ever happens), with reasons."""
    poses, reasons = dict(poses), dict(reasons)
    for _ in range(len(poses) + 1):
        checks, blame = hard_checks(prep, poses)
        if checks.ok:
            break
        if blame:
            i = max(blame)
            reasons[i] = f"removed by the post-check: {blame[i]}"
        else:  # only the walkway is blocked: take out the smallest object that reopens it
            candidates = sorted(poses, key=lambda j: (prep.items[j].area, j))
            i = next(
                (
                    j
                    for j in candidates
                    if _walk_ok(prep, {q: p for q, p in poses.items() if q != j})
                ),
                candidates[0],
            )
            reasons[i] = "removed by the post-check: it blocked the walkable path between doors"
        warnings.append(f"{prep.items[i].id}: {reasons[i]}")
        del poses[i]
    return poses, reasons


def _report(
    prep: PreparedRoom,
    poses: dict[int, Pose],
    reasons: dict[int, str],
    start: float,
    used: str,
    status: str,
    warnings: list[str],
) -> LayoutResult:
    metres = prep.metres(poses)
    placements = {
        prep.items[i].id: Placement(
            x=round(x, 6),
            y=round(y, 6),
            yaw_deg=90.0 * k,
            width=prep.items[i].width,
            depth=prep.items[i].depth,
        )
        for i, (x, y, k) in sorted(metres.items())
    }
    reports = constraint_reports(prep, metres)
    unplaced = [
        UnplacedObject(
            id=item.id, reason=reasons.get(item.index, "not placed (no reason recorded)")
        )
        for item in prep.items
        if item.index not in poses
    ]
    checks, _ = hard_checks(prep, poses)
    return LayoutResult(
        room_id=prep.problem.room_id,
        placements=placements,
        constraints=reports,
        satisfied=sum(r.satisfied for r in reports),
        total=len(reports),
        unplaced=unplaced,
        solve_time_s=round(time.perf_counter() - start, 4),
        solver_used=used,
        solver_status=status,
        hard_checks=checks,
        warnings=warnings,
        reachable_share=round(reachable_share(prep, poses), 4),
    )
