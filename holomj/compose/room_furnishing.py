"""Furniture of one room: lay out its retrieved floor assets, hang its wall and ceiling objects.

The layout problem (:mod:`holomj.compose.layout_problem`) sees each asset's real footprint.
Floor objects of the categories that are bolted down or plumbed in in real homes
(``FIXED_CATEGORIES``: counters, base cabinets, the cooker, sanitary ware) are static fixtures;
all other furniture, tall or not (wardrobes, bookshelves, fridges, pianos), gets a free joint, so
validation puts it to the test. Wall objects are always static. Everything that could not be
retrieved or placed is reported with the reason; nothing is dropped silently.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace
from typing import Any

from shapely import affinity
from shapely.geometry import Polygon, box

from holomj.compose.layout_problem import (
    DEFINING_PRIORITY,
    REQUESTED_PRIORITY,
    instance_priorities,
    is_decor,
    layout_problem,
)
from holomj.compose.room_assets import RoomAssets
from holomj.compose.room_context import RoomContext, RoomFurniture
from holomj.compose.wall_and_ceiling import (
    hang_from_ceiling,
    hang_wall_objects,
    stand_unhung_tvs,
)
from holomj.layout.counter_runs import (
    ISLAND_CATEGORY,
    run_modules,
    run_windows,
    solve_counter_run,
)
from holomj.layout.desk_grid import front_lookers, solve_desk_grid
from holomj.layout.furniture_rules import FIXED_CATEGORIES, object_id
from holomj.layout.geometry import LAYOUT_MARGIN_M
from holomj.layout.relation_constraints import relation_verdicts
from holomj.layout.relation_room import make_room_for_relations
from holomj.layout.room_problem import RoomProblem
from holomj.layout.rugs import Anchor, lay_rugs
from holomj.layout.solve import LayoutResult, Placement, solve_room
from holomj.layout.wall_objects import FloorItem
from holomj.layout.window_moves import raise_sill, relocate_window
from holomj.library.store import AssetLibrary
from holomj.seeds import stage_rng
from holomj.spec.plan import PlanRoom
from holomj.spec.scene import Room, SceneObject, Window


def furnish_room(
    plan_room: PlanRoom,
    room: Room,
    context: RoomContext,
    assets: RoomAssets,
    library: AssetLibrary,
    seed: int,
    *,
    time_limit_s: float = 1.0,
) -> RoomFurniture:
    """Lay out the retrieved floor ``assets`` of ``plan_room`` in ``room`` and hang its wall
    objects.

    Defining furniture goes first (it outweighs every optional object in the solver). When it
    still does not fit, a window that keeps it out is moved to a free stretch of exterior wall,
    or left out when there is none; ``changes`` says what moved and why. A kitchen's counters,
    sink, cooker and dishwasher make one counter run (:mod:`holomj.layout.counter_runs`; its
    record is ``layout["counter_run"]``), in the shape the plan asks for
    (``counter_run_shape``), if any. Many desks and their seats stand in rows facing one front wall
    (:mod:`holomj.layout.desk_grid`; its record is ``layout["desk_grid"]``), and the room's
    boards hang on that wall."""
    out = RoomFurniture(room.id, picks=list(assets.picks), unplaced=list(assets.failed))
    windows = [w for w in context.windows if room.id in w.rooms]

    metas = {instance: library.get(a).meta for instance, a in assets.floor.items()}
    solve, solves = _room_solver(plan_room, room, context, assets, library, seed, time_limit_s)
    result = solve(windows)
    windows, result = _make_room_for_defining(
        plan_room, room, context, assets.floor, library, windows, result, solve, out
    )
    result = _make_room_for_relations(plan_room, assets, metas, windows, result, solve, out)
    out.layout = _layout_record(result)
    run, grid = solves.records_of(result)
    if run is not None:
        out.layout["counter_run"] = run
        windows, notes = run_windows(windows, run)
        out.changes.extend(f"{room.id}: {note}" for note in notes)
    if grid is not None:
        out.layout["desk_grid"] = grid
    out.windows = windows
    out.relations = relation_verdicts(plan_room, result.constraints)
    out.warnings.extend(result.warnings)
    for item in result.unplaced:
        out.unplaced.append({"object": item.id, "stage": "layout", "reason": item.reason})
    floor_items = _place_floor_objects(plan_room, room, assets.floor, result, library, out)
    _lay_rugs(plan_room, room, context, assets.floor, result, library, out)
    hung_for = front_lookers(plan_room, grid)  # boards hang where the front row looks
    hang_wall_objects(
        hung_for, room, context, windows, assets.wall, floor_items, library, seed, out
    )
    stand_unhung_tvs(plan_room, room, out, library)
    hang_from_ceiling(plan_room, room, context, assets.ceiling, floor_items, library, out)
    return out


@dataclass(frozen=True)
class _Solves:
    """Every layout solved for a room, with the counter run and desk grid each was made with."""

    runs: list[tuple[LayoutResult, dict[str, Any]]] = field(default_factory=list)
    grids: list[tuple[LayoutResult, dict[str, Any] | None]] = field(default_factory=list)

    def records_of(
        self, result: LayoutResult
    ) -> tuple[dict[str, Any] | None, dict[str, Any] | None]:
        """The counter run and desk grid of the solve that gave ``result`` (None: none)."""
        run = next((record for solved, record in self.runs if solved is result), None)
        grid = next((record for solved, record in self.grids if solved is result), None)
        return run, grid


def _room_solver(
    plan_room: PlanRoom,
    room: Room,
    context: RoomContext,
    assets: RoomAssets,
    library: AssetLibrary,
    seed: int,
    time_limit_s: float,
) -> tuple[Callable[..., LayoutResult], _Solves]:
    """``solve(windows, assets=assets)``: the room's layout with those windows and floor assets
    (a counter run, desks in rows, the rest by the solver), and the record of every solve."""
    metas = {instance: library.get(a).meta for instance, a in assets.floor.items()}
    solves = _Solves()

    def plain(problem: RoomProblem) -> LayoutResult:
        return solve_room(
            problem,
            solver="cpsat",
            time_limit_s=time_limit_s,
            rng=stage_rng(seed, "layout", room.id),
        )

    grid_log: list[dict[str, Any] | None] = []  # the desk grid of each gridded solve

    def gridded(problem: RoomProblem) -> LayoutResult:
        # desks and their seats in rows (holomj.layout.desk_grid), inside the counter run
        result, grid = solve_desk_grid(
            problem,
            {i: m.category for i, m in metas.items()},
            solve=plain,
            plan_room=plan_room,
            defining_priority=DEFINING_PRIORITY,
            keep_priority=REQUESTED_PRIORITY,
        )
        grid_log.append(grid)
        return result

    def solve(room_windows: list[Window], room_assets: RoomAssets = assets) -> LayoutResult:
        problem = layout_problem(plan_room, room, context, room_windows, room_assets, library)
        categories = {i: m.category for i, m in metas.items()}
        result, run = solve_counter_run(
            problem,
            run_modules(problem, categories, {i: m.size for i, m in metas.items()}),
            solve=gridded,
            rng=stage_rng(seed, "counter_run", room.id),
            requested=plan_room.counter_run_shape,
            island=next((i for i, c in categories.items() if c == ISLAND_CATEGORY), None),
            defining_priority=DEFINING_PRIORITY,
            windows=room_windows,
            wall_height=context.wall_height,
        )
        if run is not None:
            solves.runs.append((result, run))
        solves.grids.append((result, grid_log[-1] if grid_log else None))
        return result

    return solve, solves


def _place_floor_objects(
    plan_room: PlanRoom,
    room: Room,
    floor_assets: dict[str, str],
    result: LayoutResult,
    library: AssetLibrary,
    out: RoomFurniture,
) -> list[FloorItem]:
    """The scene objects of the layout's placements (added to ``out``, with each one's planned
    small objects as a receptacle), and their footprints for the wall objects."""
    by_name = {o.name: o for o in plan_room.objects}
    floor_items: list[FloorItem] = []
    placed_of: dict[str, int] = {}  # plan object -> its instances placed so far
    for instance, placement in result.placements.items():
        asset_id = floor_assets[instance]
        meta = library.get(asset_id).meta
        oid = object_id(room.id, instance)
        out.objects.append(
            SceneObject(
                id=oid,
                asset=asset_id,
                position=(round(placement.x, 4), round(placement.y, 4), 0.0),
                yaw_deg=round(placement.yaw_deg, 4),
                static=meta.category in FIXED_CATEGORIES,
                room=room.id,
            )
        )
        yaw = math.radians(placement.yaw_deg)
        front = (round(math.cos(yaw), 9), round(math.sin(yaw), 9))
        floor_items.append(FloorItem(oid, _footprint(placement), meta.size[2], front))
        plan_obj = by_name[instance.rsplit("-", 1)[0]]
        nth = placed_of.get(plan_obj.name, 0)
        placed_of[plan_obj.name] = nth + 1
        on_top = [s for s in plan_obj.on_top if s.instances is None or nth < s.instances]
        if on_top:
            out.receptacles.append((oid, plan_obj.model_copy(update={"on_top": on_top})))
    return floor_items


def _make_room_for_relations(
    plan_room: PlanRoom,
    assets: RoomAssets,
    metas: dict[str, Any],
    windows: list[Window],
    result: LayoutResult,
    solve: Callable[[list[Window], RoomAssets], LayoutResult],
    out: RoomFurniture,
) -> LayoutResult:
    """When a prompt relation does not hold, leave optional objects out (the largest first) if
    that makes it hold (:mod:`holomj.layout.relation_room`); the left-out ones are reported."""
    priorities = instance_priorities(plan_room)
    optional = sorted(
        (i for i, p in priorities.items() if p < REQUESTED_PRIORITY and i in metas),
        key=lambda i: (-metas[i].size[0] * metas[i].size[1], i),
    )

    def solve_without(dropped: frozenset[str]) -> LayoutResult:
        floor = {i: a for i, a in assets.floor.items() if i not in dropped}
        return solve(windows, replace(assets, floor=floor))

    made = make_room_for_relations(result, optional, solve_without)
    for instance in made.dropped:
        out.unplaced.append({"object": instance, "stage": "layout", "reason": made.reason})
    return made.result


def _make_room_for_defining(
    plan_room: PlanRoom,
    room: Room,
    context: RoomContext,
    floor_assets: dict[str, str],
    library: AssetLibrary,
    windows: list[Window],
    result: LayoutResult,
    solve: Callable[[list[Window]], LayoutResult],
    out: RoomFurniture,
) -> tuple[list[Window], LayoutResult]:
    """Windows moved (or left out) so that the room's defining furniture fits; see
    :mod:`holomj.layout.window_moves`."""
    defining = {
        instance
        for obj in plan_room.objects
        if obj.defining and obj.placement == "floor"
        for instance in obj.instances()
        if instance in floor_assets
    }
    missing = defining - set(result.placements)
    if not missing or not windows:
        return windows, result
    # Take windows out, widest first, until the defining furniture fits (or none is left).
    kept, removed, best = list(windows), [], None
    for window in sorted(windows, key=lambda w: (-w.width, w.id)):
        kept = [w for w in kept if w.id != window.id]
        removed.append(window)
        trial = solve(kept)
        if not defining - set(trial.placements):
            best = trial
            break
    if best is None:  # even without windows it does not fit: nothing to gain by moving them
        return windows, result
    result = best
    heights = {i: library.get(a).meta.size[2] for i, a in floor_assets.items()}
    doors = [d for d in context.doors if room.id in d.rooms]
    names = ", ".join(sorted(defining))
    for window in removed:
        tall = [
            _footprint(p) for i, p in result.placements.items() if heights[i] > window.base_height
        ]
        moved = relocate_window(
            window, room.id, Polygon(room.polygon), context.walls, doors, kept, tall
        )
        if moved is not None:
            kept.append(moved)
            out.changes.append(
                f"{room.id}: moved window {window.id} from {_xy(window.position)} to "
                f"{_xy(moved.position)} so that the {names} fits"
            )
            continue
        # In place, above the defining furniture: the layout must then keep taller things away.
        tallest = max((heights[i] for i in defining), default=0.0)
        raised = raise_sill(window, tallest, context.wall_height)
        below = solve([*kept, raised]) if raised is not None else None
        if raised is not None and below is not None and not defining - set(below.placements):
            kept.append(raised)
            result = below
            out.changes.append(
                f"{room.id}: raised the sill of window {window.id} from "
                f"{window.base_height:.2f} to {raised.base_height:.2f} m so that the {names} "
                "fits below it (no other stretch of exterior wall was free)"
            )
        else:
            out.changes.append(
                f"{room.id}: left out window {window.id}: the {names} needs its wall, no other "
                "stretch of exterior wall is free and it does not fit below a raised window"
            )
    order = {w.id: i for i, w in enumerate(windows)}
    return sorted(kept, key=lambda w: order[w.id]), result


def _xy(point: Sequence[float]) -> str:
    return f"({point[0]:.2f}, {point[1]:.2f})"


def _lay_rugs(
    plan_room: PlanRoom,
    room: Room,
    context: RoomContext,
    assets: dict[str, str],
    result: LayoutResult,
    library: AssetLibrary,
    out: RoomFurniture,
) -> None:
    """Rugs under the room's main piece (see :mod:`holomj.layout.rugs`)."""
    rugs = [(i, a) for i, a in assets.items() if is_decor(library, a)]
    if not rugs:
        return
    anchors = [
        Anchor(p.x, p.y, p.yaw_deg, p.width, p.depth, library.get(assets[i]).meta.category)
        for i, p in result.placements.items()
    ]
    inset = context.wall_thickness / 2 + LAYOUT_MARGIN_M
    polygon = Polygon(room.polygon).buffer(-inset, join_style="mitre")
    sizes = [_plan_size(library, a) for _, a in rugs]
    for (instance, asset_id), pose in zip(rugs, lay_rugs(polygon, sizes, anchors), strict=True):
        if isinstance(pose, str):
            out.unplaced.append({"object": instance, "stage": "layout", "reason": pose})
            continue
        out.objects.append(
            SceneObject(
                id=object_id(room.id, instance),
                asset=asset_id,
                position=(pose.x, pose.y, 0.0),
                yaw_deg=pose.yaw_deg,
                scale=(pose.scale, pose.scale, 1.0) if pose.scale != 1.0 else 1.0,
                static=True,
                room=room.id,
            )
        )


def _plan_size(library: AssetLibrary, asset_id: str) -> tuple[float, float]:
    """An asset's extent along x and y."""
    size = library.get(asset_id).meta.size
    return (size[0], size[1])


def _footprint(p: Placement) -> Polygon:
    rect = box(-p.depth / 2, -p.width / 2, p.depth / 2, p.width / 2)
    return affinity.translate(affinity.rotate(rect, p.yaw_deg, origin=(0, 0)), p.x, p.y)


def _layout_record(result: LayoutResult) -> dict[str, Any]:
    return {
        "placed": len(result.placements),
        "constraints_satisfied": result.satisfied,
        "constraints_total": result.total,
        "solver": result.solver_used,
        "status": result.solver_status,
        "seconds": round(result.solve_time_s, 3),
        "hard_checks_ok": result.hard_checks.ok,
        "reachable_share": result.reachable_share,
    }
