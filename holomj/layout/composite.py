"""Composite objects: a group of a room's instances (a counter run's leg, a block of desks)
solved as one layout object, then split back into its instances.

The callers build the composite problem (:func:`composite_room`, the heaviest constraint per key
kept by :class:`HeaviestConstraints`, the composites named by :func:`composite_ids`), solve it
with the room's solver, check that every composite and every defining object was placed
(:func:`composite_failure`), lay the instances out from the composites' placements and judge
the result on the instances' own footprints (:func:`check_split`, :func:`split_result`).
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence

from holomj.layout import geometry as geo
from holomj.layout.constraints import Constraint, normalize_name
from holomj.layout.hard_rules import hard_checks
from holomj.layout.layout_result import HardChecks, LayoutResult, Placement, UnplacedObject
from holomj.layout.open_pockets import ReachMeter
from holomj.layout.room_problem import LayoutObject, PreparedRoom, RoomProblem
from holomj.layout.solve import constraint_reports


def composite_ids(problem: RoomProblem, prefix: str, n: int) -> list[str]:
    """``n`` names ``<prefix><k>`` that no object of ``problem`` has (in the text form's
    spelling)."""
    taken = {normalize_name(o.id) for o in problem.objects}
    out: list[str] = []
    k = 0
    while len(out) < n:
        name = f"{prefix}{k}"
        if normalize_name(name) not in taken:
            out.append(name)
        k += 1
    return out


class HeaviestConstraints:
    """Constraints by key (object, kind, target), each the heaviest one added."""

    def __init__(self) -> None:
        self._kept: dict[tuple[str, str, str | None], Constraint] = {}

    def add(self, c: Constraint) -> None:
        """Keep ``c`` unless a constraint of its key weighs more (or as much)."""
        old = self._kept.get(c.key)
        if old is None or old.weight < c.weight:
            self._kept[c.key] = c

    def all(self) -> list[Constraint]:
        """The kept constraints, in the order their keys were first added."""
        return list(self._kept.values())


def composite_room(
    problem: RoomProblem, objects: Sequence[LayoutObject], constraints: Iterable[Constraint]
) -> RoomProblem:
    """``problem``'s room and openings with ``objects`` and ``constraints`` instead of its own
    (the text form left out: ``constraints`` are all there is)."""
    return RoomProblem(
        room_id=problem.room_id,
        polygon=problem.polygon,
        size_unit=problem.size_unit,
        doors=problem.doors,
        windows=problem.windows,
        objects=list(objects),
        constraints=list(constraints),
        settings=problem.settings,
    )


def composite_failure(
    problem: RoomProblem, solved: LayoutResult, ids: Sequence[str], defining_priority: int
) -> tuple[str, str, str] | None:
    """Why the solve of a composite problem fails, or None: ``("composite", id, reason)`` for
    the first composite of ``ids`` left out, ``("defining", id, reason)`` for the first object
    of ``problem`` of at least ``defining_priority`` left out."""
    for k in ids:
        if k not in solved.placements:
            why = next((u.reason for u in solved.unplaced if u.id == k), "not placed")
            return "composite", k, why
    by_id = {o.id: o for o in problem.objects}
    for item in solved.unplaced:
        if item.id in by_id and by_id[item.id].priority >= defining_priority:
            return "defining", item.id, item.reason
    return None


def check_split(
    problem: RoomProblem, placements: dict[str, Placement], members: set[str]
) -> HardChecks:
    """The hard rules on the finished layout: the solver's post-check with the instances' own
    footprints and heights, the ``members`` of the composites allowed to touch each other
    (every other pair keeps the clearance)."""
    touching = problem.settings.model_copy(update={"clearance_m": 0.0})
    prep = PreparedRoom(problem.model_copy(update={"settings": touching}))
    g = prep.grid
    poses = {
        prep.index[i]: (p.x / g, p.y / g, geo.yaw_index(p.yaw_deg)) for i, p in placements.items()
    }
    checks, _ = hard_checks(prep, poses)
    clearance = problem.settings.clearance_m
    rects = {
        i: geo.footprint(p.x, p.y, geo.yaw_index(p.yaw_deg), p.width, p.depth)
        for i, p in placements.items()
    }
    for a in sorted(members & set(rects)):
        for b in sorted(set(rects) - members):
            gx, gy = geo.rect_gaps(rects[a], rects[b])
            if not (gx < -1e-7 and gy < -1e-7) and max(gx, gy) < clearance - 1e-6:
                checks.clearance.append(f"{a} and {b} are {max(gx, gy):.3f} m apart")
    return checks


def split_result(
    problem: RoomProblem,
    solved: LayoutResult,
    placements: dict[str, Placement],
    checks: HardChecks,
    composites: list[str],
) -> LayoutResult:
    """The layout per instance, every constraint of ``problem`` judged on it (the
    ``composites`` of the solve are no longer objects of it)."""
    prep = PreparedRoom(problem)
    ordered = {o.id: placements[o.id] for o in problem.objects if o.id in placements}
    metres = {prep.index[i]: (p.x, p.y, geo.yaw_index(p.yaw_deg)) for i, p in ordered.items()}
    reports = constraint_reports(prep, metres)
    unplaced = [
        UnplacedObject(id=u.id, reason=u.reason) for u in solved.unplaced if u.id not in composites
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
