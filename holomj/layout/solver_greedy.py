"""Fast greedy placement with bounded backtracking: the fallback and the CP-SAT warm start.

Objects go in dependency order (targets before the objects that refer to them, larger first).
For each object every grid position and quarter turn is tested at once with summed-area tables
over the occupancy raster (walls, door zones, windows for tall objects, objects placed so far),
candidates are scored by the weight of the constraints they satisfy with what is already placed,
and the best one that keeps the doors connected is taken. When an object finds no room, up to
``max_backtracks`` times a recently placed object is moved to one of its alternative positions
to make room; if that fails too, the object is reported unplaced with the reason. A few restarts
that put the unplaced objects first run while time is left; the best attempt wins.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field

import numpy as np

from holomj.layout.geometry import Pose
from holomj.layout.greedy_candidates import CandidateFinder, Occupancy, diverse_poses
from holomj.layout.room_problem import PreparedRoom


@dataclass
class GreedyOutcome:
    """Poses in grid units, unplaced objects with reasons, and search statistics."""

    poses: dict[int, Pose] = field(default_factory=dict)
    unplaced: dict[int, str] = field(default_factory=dict)
    score: float = 0.0
    attempts: int = 0
    backtracks: int = 0


def dependency_order(prep: PreparedRoom) -> list[int]:
    """Targets before the objects that refer to them; among the ready ones, the highest
    priority first, then the largest."""
    deps: dict[int, set[int]] = {item.index: set() for item in prep.items}
    for c in prep.constraints:
        if c.target is not None:
            deps[prep.index[c.object]].add(prep.index[c.target])
    order: list[int] = []
    left = set(deps)
    while left:
        ready = [i for i in left if not (deps[i] & left)]
        pool = ready or list(left)  # a cycle: break it at the largest object
        pick = max(pool, key=lambda i: (prep.items[i].priority, prep.items[i].area, -i))
        order.append(pick)
        left.remove(pick)
    return order


def solve_greedy(
    prep: PreparedRoom,
    rng: np.random.Generator,
    time_limit_s: float = 1.0,
    *,
    max_backtracks: int = 20,
    max_restarts: int = 3,
    path_tries: int = 40,
) -> GreedyOutcome:
    """Place every object it can; never drops one without a reason."""
    start = time.perf_counter()
    deadline = start + time_limit_s
    finder = CandidateFinder(prep, rng)
    order = dependency_order(prep)
    best: GreedyOutcome | None = None
    for attempt in range(max_restarts + 1):
        outcome = _attempt(prep, finder, order, deadline, max_backtracks, path_tries)
        outcome.attempts = attempt + 1
        if best is None or (len(outcome.poses), outcome.score) > (len(best.poses), best.score):
            best = outcome
        if not outcome.unplaced or time.perf_counter() > deadline:
            break
        failed = [i for i in order if i in outcome.unplaced]
        order = failed + [i for i in order if i not in outcome.unplaced]
    assert best is not None
    return best


def _attempt(
    prep: PreparedRoom,
    finder: CandidateFinder,
    order: list[int],
    deadline: float,
    max_backtracks: int,
    path_tries: int,
) -> GreedyOutcome:
    occ = Occupancy(prep)
    alternatives: dict[int, list[Pose]] = {}
    placed_order: list[int] = []
    outcome = GreedyOutcome()
    spread = max(prep.units_up(0.5), 1)
    for i in order:
        pose, why = _best_pose(prep, finder, occ, i, path_tries, alternatives, spread)
        if pose is None and outcome.backtracks < max_backtracks:
            pose = _backtrack(
                prep,
                finder,
                occ,
                i,
                placed_order,
                alternatives,
                outcome,
                max_backtracks,
                path_tries,
                deadline,
                spread,
            )
        if pose is None:
            if why == "full" and not finder.fits_empty(i):
                why = "fit"
            outcome.unplaced[i] = _reason(prep, i, why, occ)
            continue
        occ.place(i, pose)
        placed_order.append(i)
    outcome.poses = dict(occ.poses)
    outcome.score = satisfied_weight(prep, occ.metres())
    return outcome


def _best_pose(
    prep: PreparedRoom,
    finder: CandidateFinder,
    occ: Occupancy,
    i: int,
    path_tries: int,
    alternatives: dict[int, list[Pose]],
    spread: int,
) -> tuple[Pose | None, str]:
    ranked = finder.ranked(i, occ)
    if not ranked:
        return None, "full"
    alternatives[i] = diverse_poses(ranked, 4, spread)
    if not prep.walk.applicable:
        return ranked[0][1], ""
    g = prep.grid
    for _, pose in ranked[:path_tries]:
        rect = prep.footprint(i, pose[0] * g, pose[1] * g, pose[2])
        if prep.walk.check([*occ.rects(), rect]).ok:
            return pose, ""
    return None, "path"


def _backtrack(
    prep: PreparedRoom,
    finder: CandidateFinder,
    occ: Occupancy,
    i: int,
    placed_order: list[int],
    alternatives: dict[int, list[Pose]],
    outcome: GreedyOutcome,
    max_backtracks: int,
    path_tries: int,
    deadline: float,
    spread: int,
) -> Pose | None:
    """Move one of the last few placed objects to an alternative pose to make room for ``i``."""
    for j in reversed(placed_order[-4:]):
        for alt in alternatives.get(j, [])[1:]:
            if outcome.backtracks >= max_backtracks or time.perf_counter() > deadline:
                return None
            outcome.backtracks += 1
            old = occ.remove(j)
            if not _pose_free(prep, finder, occ, j, alt):
                occ.place(j, old)
                continue
            occ.place(j, alt)
            pose, _ = _best_pose(prep, finder, occ, i, path_tries, {}, spread)
            if pose is not None:
                return pose
            occ.remove(j)
            occ.place(j, old)
    return None


def _pose_free(
    prep: PreparedRoom, finder: CandidateFinder, occ: Occupancy, i: int, pose: Pose
) -> bool:
    x, y, k = pose
    res = finder.valid_mask(i, k, occ.mask)
    if res is None:
        return False
    xs, ys, ok = res
    hit = (xs == x) & (ys == y) & ok
    if not hit.any():
        return False
    if prep.walk.applicable:
        g = prep.grid
        return prep.walk.check([*occ.rects(), prep.footprint(i, x * g, y * g, k)]).ok
    return True


def _reason(prep: PreparedRoom, i: int, why: str, occ: Occupancy) -> str:
    item = prep.items[i]
    size = f"{item.width:.2f} x {item.depth:.2f} m"
    if why == "fit":
        extra = (
            " and the windows (it is taller than a sill)" if item.tall and prep.window_zones else ""
        )
        return (
            f"does not fit in the room in any orientation ({size}) clear of the walls, "
            f"the door zones{extra}"
        )
    if why == "path":
        return "every free position left would block the walkable path between the doors"
    placed = [prep.items[j].id for j in occ.poses]
    shown = ", ".join(placed[:6]) + (f" and {len(placed) - 6} more" if len(placed) > 6 else "")
    return f"no room left ({size}) after placing {shown or 'nothing'}"


def satisfied_weight(prep: PreparedRoom, poses_m: dict[int, tuple[float, float, int]]) -> float:
    """Total weight of the constraints that hold for these poses (metres)."""
    return sum(c.weight for c in prep.constraints if prep.evaluate(c, poses_m)[0])


def insert_unplaced(
    prep: PreparedRoom,
    poses: dict[int, Pose],
    missing: list[int],
    rng: np.random.Generator,
) -> tuple[dict[int, Pose], dict[int, str]]:
    """Greedily add ``missing`` objects into a finished layout (no object is moved)."""
    finder = CandidateFinder(prep, rng)
    occ = Occupancy(prep)
    for i, placed in poses.items():
        occ.place(i, placed)
    reasons: dict[int, str] = {}
    spread = max(prep.units_up(0.5), 1)
    for i in missing:
        pose, why = _best_pose(prep, finder, occ, i, 40, {}, spread)
        if pose is None:
            if why == "full" and not finder.fits_empty(i):
                why = "fit"
            reasons[i] = _reason(prep, i, why, occ)
            continue
        occ.place(i, pose)
    return dict(occ.poses), reasons
