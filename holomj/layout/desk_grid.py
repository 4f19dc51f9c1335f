"""Classrooms, computer labs, open offices and lab rooms: many identical desks and their seats
laid out in rows facing one front wall, with aisles between the rows, instead of a jumble that
cuts the floor into pockets.

A room's *grid group* is a floor kind (instances ``student desk-0`` ... ``student desk-15``) of
a work surface used from one side (:data:`GRID_CATEGORIES`: desks, lab benches, drafting
tables, workbenches...; a table of :data:`TABLE_CATEGORIES` only when its name says it is a work
or canteen table, and then it is used from both sides) with at least :data:`MIN_INSTANCES`
instances, or two when the plan asks for rows (:attr:`holomj.spec.plan.PlanObject.rows`, its
``in_row`` relation). Its *seats* are the chairs and stools whose constraints point at exactly
one of its desks (``school chair-3 | near, student desk-3 | face to, student desk-3``): each desk
and its seats make a *station*. A desk's +X front is where its user sits, so a station puts its
seats side by side at the desk's front, :data:`SEAT_GAP_M` away and facing it.

How it is solved (the composite approach of :mod:`holomj.layout.counter_runs`): the stations
are laid out as a *block*, a grid of ``rows x columns`` slots, each row's desks side by side
(in pairs, or one by one, with a column aisle between pairs), all facing the front; behind
every row of seats there is a row aisle, and in front of the first row a front zone as deep as
the aisle behind the last row (the block is then symmetric front to back, so that the front
can be chosen after the solve). The block becomes one :class:`LayoutObject`, the room's solver
places it with the other furniture (softly in the ``middle`` of the room), then it is split
back into desks and seats and the layout is checked against every hard rule with their own
footprints, and the free floor inside the block must all be reachable from the doors. The front
wall is the side of the solved block that the plan's relations name (desks facing the window or the
door), else the one away from the room's doors, else the one with a free stretch for the
board; the station of the first seat takes the front row's middle, so that a whiteboard, a TV
or a projector screen hung where that seat looks (:func:`front_lookers`) hangs on the front
wall.

Shapes are tried from the roomiest: aisles of :data:`STANDARD` widths (0.9 m behind each seat
row, 0.6 m between column pairs), then :data:`COMPACT` ones (still wider than a robot), rows
and columns chosen to fit the room's free floor (a raster test before any solve), then the
stations in two blocks, and finally independent placement (the plan's constraints as they
are): no desk or seat is ever dropped for the sake of a grid. The record
(:func:`solve_desk_grid`) says which group, the rows and columns, the aisles, the front wall,
every shape tried and the fallback with its reason.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, replace
from typing import Any

from holomj.layout import geometry as geo
from holomj.layout.composite import check_split, composite_failure, composite_ids, split_result
from holomj.layout.desk_grid_blocks import (
    BOARD_WIDTH_M,
    assign_slots,
    block_pieces,
    block_record,
    choose_front,
    composite_problem,
    unreachable_inside,
    world_placements,
)
from holomj.layout.desk_grid_groups import (
    BOARD_CATEGORIES,
    MIN_INSTANCES_IN_ROWS,
    GridGroup,
    Station,
    grid_groups,
    index_of,
    is_grid_kind,
    kind_of,
    seats_fit,
)
from holomj.layout.desk_grid_shapes import FreeFloor, Shape, candidate_shapes, rank_shapes
from holomj.layout.room_problem import PreparedRoom, RoomProblem
from holomj.layout.solve import LayoutResult
from holomj.spec.plan import PlanRelation, PlanRoom

__all__ = ["front_lookers", "grid_groups", "is_grid_kind", "solve_desk_grid"]

BLOCK_PREFIX = "desk grid "
MAX_ATTEMPTS = 3  # one-block shapes solved before two blocks are tried
MAX_TWO_BLOCK_ATTEMPTS = 2


@dataclass(frozen=True)
class GridContext:
    """What an attempt needs besides the shapes: the room prepared, the opening the plan has
    the desks face, the board's width (None: no board), the defining priority (such an object
    left out fails the attempt), the priority from which an object left out is reported
    (``left_out``: the attempt stands only if independent placement leaves it out too), the
    room's free floor for the blocks and the footprint (m²) of the other objects."""

    prep: PreparedRoom
    facing: str | None
    board_width: float | None
    defining_priority: int
    keep_priority: int
    floor: FreeFloor
    others_m2: float


def _attempt(
    problem: RoomProblem,
    group: GridGroup,
    parts: Sequence[tuple[Sequence[Station], Shape]],
    solve: Callable[[RoomProblem], LayoutResult],
    ctx: GridContext,
) -> tuple[LayoutResult | None, Any]:
    """Solve ``problem`` with each part (stations and shape) as one block, split the blocks
    and check the result; the layout and the record's fields (``left_out``: the objects of
    at least the keep priority the layout left out), or None and why not."""
    ids = composite_ids(problem, BLOCK_PREFIX, len(parts))
    owner = {
        p.id: ids[n] for n, (stations, _) in enumerate(parts) for s in stations for p in s.pieces
    }
    composite = composite_problem(
        problem, group, [(b, shape) for b, (_, shape) in zip(ids, parts)], owner
    )
    solved = solve(composite)
    failure = composite_failure(problem, solved, ids, ctx.defining_priority)
    if failure is not None:
        what, item, why = failure
        if what == "composite":
            return None, f"the layout left out the block ({why})"
        return None, f"{item} did not fit beside the grid ({why})"
    by_id = {o.id: o for o in problem.objects}
    placements = {i: p for i, p in solved.placements.items() if i not in ids}
    blocks_out = []
    looker = None
    for n, (block, (stations, shape)) in enumerate(zip(ids, parts)):
        p = solved.placements[block]
        k = geo.yaw_index(p.yaw_deg)
        ks = [k, (k + 2) % 4] if shape.symmetric else [k]
        choice = choose_front(ctx.prep, (p.x, p.y), ks, ctx.facing, ctx.board_width)
        board = ctx.board_width is not None and n == 0
        pairs = assign_slots(group, shape, stations, board)
        local = block_pieces(group, shape, pairs)
        placements.update(world_placements(group, local, (p.x, p.y), choice.k))
        if board and pairs and pairs[0][0].front:
            looker = pairs[0][0].front[0].id
        blocks_out.append(block_record(group, shape, p, choice, pairs))
    members = group.members & set(placements)
    checks = check_split(problem, placements, members)
    if not checks.ok:
        problems = checks.problems("the grid blocks the way between the doors")
        return None, "the split grid breaks a hard rule: " + "; ".join(problems[:3])
    cut = unreachable_inside(ctx.prep, placements, [solved.placements[b] for b in ids])
    if cut > 0:
        return None, f"{cut:.2f} m² of the grid's aisles are out of reach"
    left_out = sorted(
        u.id for u in solved.unplaced if u.id in by_id and by_id[u.id].priority >= ctx.keep_priority
    )
    fields: dict[str, Any] = {"blocks": blocks_out, "looker": looker, "left_out": left_out}
    return split_result(problem, solved, placements, checks, ids), fields


def _facing(relations: Sequence[PlanRelation], group: GridGroup) -> str | None:
    """The opening the prompt has the group's desks (or seats) face, if any."""
    names = {group.name} | {kind_of(p.id) for s in group.stations for p in (*s.front, *s.back)}
    for rel in relations:
        if rel.subject in names and rel.kind in ("facing_window", "facing_door"):
            return rel.kind.split("_", 1)[1]
    return None


def board_width(plan_room: PlanRoom | None) -> float | None:
    """The widest board of the room to face (None: the room has none)."""
    if plan_room is None:
        return None
    widths = [
        (obj.size[0] if obj.size else BOARD_WIDTH_M)
        for obj in plan_room.objects
        if obj.placement == "wall" and obj.category in BOARD_CATEGORIES and obj.above is None
    ]
    return max(widths) if widths else None


class _GridSearch:
    """The search for a grid of one group: the shapes tried, each failure noted in the
    record's ``tried``, and the spare, the laid grid that left the fewest objects out (it may
    still stand)."""

    def __init__(
        self,
        problem: RoomProblem,
        group: GridGroup,
        solve: Callable[[RoomProblem], LayoutResult],
        ctx: GridContext,
        record: dict[str, Any],
    ) -> None:
        self.problem = problem
        self.group = group
        self.solve = solve
        self.ctx = ctx
        self.record = record
        self.spare: tuple[LayoutResult, dict[str, Any]] | None = None

    def laid(self, result: LayoutResult | None, outcome: Any, label: str) -> bool:
        """Whether the attempt laid the grid with nothing left out; else note why not."""
        if result is not None and not outcome["left_out"]:
            return True
        if result is not None:
            if self.spare is None or len(outcome["left_out"]) < len(self.spare[1]["left_out"]):
                self.spare = (result, outcome)
            outcome = "the layout left out " + ", ".join(outcome["left_out"])
        self.record["tried"].append({"shape": label, "outcome": outcome})
        return False

    def tried(self, parts: Sequence[tuple[Sequence[Station], Shape]], label: str) -> Any:
        """Solve with ``parts`` as blocks: the layout and the record's fields when the grid is
        laid with nothing left out, else None (the attempt noted under ``label``)."""
        result, outcome = _attempt(self.problem, self.group, parts, self.solve, self.ctx)
        if self.laid(result, outcome, label) and result is not None:
            return result, outcome
        return None

    def one_block(self) -> tuple[LayoutResult, Any] | None:
        """The group laid as one block, in the best ranked shape that lays (at most
        :data:`MAX_ATTEMPTS` solves), or None."""
        group, ctx = self.group, self.ctx
        candidates = candidate_shapes(group, len(group.stations))
        ranked = rank_shapes(group, candidates, ctx.floor, ctx.others_m2)
        tried_shapes: set[tuple[int, int, int, str, bool]] = set()
        attempts = 0
        for _, shape, _ in ranked:
            key = (shape.rows, shape.columns, shape.pair, shape.aisles.name, shape.ends)
            if key in tried_shapes:
                continue
            tried_shapes.add(key)
            attempts += 1
            laid = self.tried([(group.stations, shape)], shape.label())
            if laid is not None:
                return laid
            if attempts >= MAX_ATTEMPTS:
                break
        if not ranked:
            self.record["tried"].append(
                {
                    "shape": "one block",
                    "outcome": "no shape of one block fits the room's free floor",
                }
            )
        return None

    def two_blocks(self) -> tuple[LayoutResult, Any] | None:
        """The group laid as two blocks of half the stations each (at most
        :data:`MAX_TWO_BLOCK_ATTEMPTS` solves), or None (also when it has too few stations)."""
        group, ctx = self.group, self.ctx
        n = len(group.stations)
        if n < 2 * MIN_INSTANCES_IN_ROWS:
            return None
        half = math.ceil(n / 2)
        parts = (group.stations[:half], group.stations[half:])
        candidates = candidate_shapes(group, half)
        ranked = rank_shapes(group, candidates, ctx.floor, ctx.others_m2, copies=2)
        attempts = 0
        for _, shape, _ in ranked:
            rest = replace(shape, count=len(parts[1]))
            if rest.rows > 1 and (rest.rows - 1) * rest.columns >= rest.count:
                continue
            attempts += 1
            laid = self.tried(
                [(parts[0], shape), (parts[1], rest)], f"two blocks of {shape.label()}"
            )
            if laid is not None:
                return laid
            if attempts >= MAX_TWO_BLOCK_ATTEMPTS:
                break
        return None


def solve_desk_grid(
    problem: RoomProblem,
    categories: Mapping[str, str],
    *,
    solve: Callable[[RoomProblem], LayoutResult],
    plan_room: PlanRoom | None = None,
    defining_priority: int = 100,
    keep_priority: int = 10,
) -> tuple[LayoutResult, dict[str, Any] | None]:
    """Lay out ``problem`` with its largest grid group in rows (see the module docstring);
    ``solve`` solves a layout problem (the room's solver), ``categories`` maps instances to
    library categories, ``plan_room`` gives the rows asked, the room's relations and boards.
    Returns the layout and the record (None when the room has no grid group). An object of at
    least ``defining_priority`` left out makes a shape fail; a shape that leaves out an object
    of at least ``keep_priority`` (one the plan asks for) stands only if independent placement
    leaves it out as well."""
    groups = grid_groups(problem, categories, plan_room)
    if not groups:
        return solve(problem), None
    group = groups[0]
    record: dict[str, Any] = {
        "group": group.name,
        "category": group.category,
        "desks": len(group.stations),
        "seats": sum(len(s.front) + len(s.back) for s in group.stations),
        "rows_asked": group.rows_asked,
        "rows": None,
        "columns": None,
        "front_wall": None,
        "blocks": [],
        "tried": [],
        "fallback": None,
    }
    misfit = seats_fit(group)
    if misfit is not None:
        record["fallback"] = f"{misfit}; the desks are laid out one by one"
        return solve(problem), record
    prep = PreparedRoom(problem)
    relations = plan_room.relations if plan_room is not None else ()
    tall = any(group.height > w.sill_height for w in problem.windows)
    others = 0.0
    for obj in problem.objects:
        if obj.id not in group.members:
            w, d, _ = problem.object_size_m(obj)
            others += w * d
    ctx = GridContext(
        prep,
        _facing(relations, group),
        board_width(plan_room),
        defining_priority,
        keep_priority,
        FreeFloor(prep, tall),
        others,
    )
    trials = _GridSearch(problem, group, solve, ctx, record)
    laid = trials.one_block() or trials.two_blocks()
    if laid is not None:
        return laid[0], _finish(record, laid[1])
    alone = solve(problem)
    if trials.spare is not None:
        kept = {o.id for o in problem.objects if o.priority >= keep_priority}
        lost = {u.id for u in alone.unplaced if u.id in kept}
        if set(trials.spare[1]["left_out"]) <= lost:  # placed one by one, they are left out too
            return trials.spare[0], _finish(record, trials.spare[1])
    record["fallback"] = (
        "; ".join(f"{t['shape']}: {t['outcome']}" for t in record["tried"])
        or "no grid fits the room"
    ) + "; the desks are laid out one by one"
    return alone, record


def _finish(record: dict[str, Any], fields: Mapping[str, Any]) -> dict[str, Any]:
    """The record of a grid that was laid: rows, columns and front wall of the first block
    (``tried`` keeps the shapes that gave way before it; ``fallback`` stays None)."""
    blocks = list(fields["blocks"])
    out = dict(record)
    out["blocks"] = blocks
    out["rows"] = blocks[0]["rows"]
    out["columns"] = blocks[0]["columns"]
    out["block_count"] = len(blocks)
    out["front_wall"] = blocks[0]["front_wall"]
    out["looker"] = fields.get("looker")
    out["left_out"] = list(fields.get("left_out", []))
    return out


def front_lookers(plan_room: PlanRoom, record: Mapping[str, Any] | None) -> PlanRoom:
    """``plan_room`` with its boards (whiteboard, TV, projector screen) hung where the grid's
    front-row seat looks (its ``faced_by``), when a grid was laid and the board is not hung
    above something or faced by another object."""
    if not record or not record.get("looker") or not record.get("blocks"):
        return plan_room
    looker = kind_of(str(record["looker"]))
    if index_of(str(record["looker"])) != 0:
        return plan_room
    ours = {looker, str(record.get("group"))}
    floor = {o.name for o in plan_room.objects if o.placement == "floor"}
    if looker not in floor:
        return plan_room
    objects = []
    for obj in plan_room.objects:
        if (
            obj.placement == "wall"
            and obj.category in BOARD_CATEGORIES
            and obj.above is None
            and (obj.faced_by is None or obj.faced_by in ours)
        ):
            obj = obj.model_copy(update={"faced_by": looker})
        objects.append(obj)
    return plan_room.model_copy(update={"objects": objects})
