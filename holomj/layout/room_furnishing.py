"""Furniture of one room: retrieve an asset per instance, solve the floor layout, hang wall objects.

The layout solver works on the room polygon *inset* by half an interior wall plus a margin
(``LAYOUT_MARGIN_M``): interior walls are centred on the room edge, so furniture laid out against
the raw edge would sit inside the wall. Doors and windows are projected onto the inset outline.
The layout uses each retrieved asset's real footprint (width = the asset's y extent, depth = its
x extent: assets face +X), so what the solver sees is what the simulator gets.

Floor objects of the categories that are bolted down or plumbed in in real homes
(``FIXED_CATEGORIES``: counters, base cabinets, the cooker, sanitary ware) are static fixtures;
all other furniture, tall or not (wardrobes, bookshelves, fridges, pianos), gets a free joint, so
validation puts it to the test. Wall objects are always static. Everything that could not be
retrieved or placed is reported with the reason; nothing is dropped silently.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace
from typing import Any, Protocol

import numpy as np
from shapely import affinity
from shapely.geometry import Point, Polygon, box

from holomj.errors import HolomjError
from holomj.layout.counter_runs import (
    ISLAND_CATEGORY,
    run_modules,
    run_windows,
    solve_counter_run,
)
from holomj.layout.desk_grid import front_lookers, solve_desk_grid
from holomj.layout.geometry import LAYOUT_MARGIN_M
from holomj.layout.relation_constraints import relation_constraints, relation_verdicts
from holomj.layout.relation_room import make_room_for_relations
from holomj.layout.room_problem import (
    LayoutDoor,
    LayoutObject,
    LayoutSettings,
    LayoutWindow,
    RoomProblem,
)
from holomj.layout.rugs import Anchor, lay_rugs
from holomj.layout.solve import LayoutResult, Placement, solve_room
from holomj.layout.wall_objects import (
    ABOVE_GAP_M,
    OPENING_MARGIN_M,
    FloorItem,
    WallObjectRequest,
    place_wall_objects,
)
from holomj.layout.window_moves import raise_sill, relocate_window
from holomj.library.store import AssetLibrary
from holomj.seeds import stage_rng
from holomj.spec.decor import DECOR_CATEGORIES
from holomj.spec.plan import PlanObject, PlanRoom, PlanSmallObject, instance_name
from holomj.spec.scene import Door, Room, SceneObject, Window
from holomj.spec.walls import Wall

DEFINING_PRIORITY = 100  # a room's defining furniture outweighs every optional object
REQUESTED_PRIORITY = 10
# The layout keeps a walkway this wide (radius) between every two doors of a room: 5 cm more than
# the navigation map's agent, so that its finer grid and real collider boxes still find the path.
WALKER_RADIUS_M = 0.3
DOOR_CLEARANCE_M = 1.0  # floor kept free in front of a door, on the room's side
FIXED_CATEGORIES = frozenset(
    {
        "kitchen_counter",
        "sink_counter",
        "stove",
        "base_cabinet",
        "toilet",
        "bathtub",
        "shower_tray",
        "washbasin",
    }
)
# Library category -> wall-object kind of holomj.layout.wall_objects (default heights).
WALL_KINDS = {
    "painting": "painting",
    "mirror": "mirror",
    "clock": "clock",
    "whiteboard": "whiteboard",
    "kitchen_cabinet": "wall_cabinet",
    "wall_cabinet": "wall_cabinet",
    "shelf": "shelf",
    "television": "television",
    "wall_television": "television",
    # Window dressings hang at the room's windows (holomj.layout.window_dressing).
    "curtains": "curtains",
    "blinds": "blinds",
}


class Pick(Protocol):
    """One retrieved asset (what :class:`holomj.retrieval.assets.ScoredAsset` offers)."""

    asset_id: str


class AssetChooser(Protocol):
    """Chooses one asset per instance of a planned object."""

    def choose(
        self,
        description: str,
        *,
        quantity: int,
        variance: str,
        rng: np.random.Generator,
        size: tuple[float, float, float] | None = None,
        placement: str = "floor",
        category: str | None = None,
    ) -> Sequence[Pick]:
        """One pick per instance."""
        ...


@dataclass(frozen=True)
class RoomContext:
    """What a room's furnishing needs to know about the house around it."""

    walls: Sequence[Wall]
    doors: Sequence[Door]
    windows: Sequence[Window]
    wall_height: float
    wall_thickness: float


@dataclass
class RoomFurniture:
    """The furnished room: scene objects, receptacles for small objects, and the record."""

    room_id: str
    objects: list[SceneObject] = field(default_factory=list)
    receptacles: list[tuple[str, PlanObject]] = field(default_factory=list)
    picks: list[dict[str, Any]] = field(default_factory=list)
    unplaced: list[dict[str, str]] = field(default_factory=list)
    layout: dict[str, Any] = field(default_factory=dict)
    warnings: list[str] = field(default_factory=list)
    windows: list[Window] = field(default_factory=list)  # the room's windows, after any move
    changes: list[str] = field(default_factory=list)  # what the plan changed to fit, and why
    relations: list[dict[str, Any]] = field(default_factory=list)  # the prompt's, judged


def object_id(room_id: str, instance: str) -> str:
    """Scene id of a plan instance: ``("living_room", "coffee table-0")`` ->
    ``living_room.coffee_table_0``."""
    stem = re.sub(r"[^a-z0-9]+", "_", instance.lower()).strip("_")
    return f"{room_id}.{stem}"


def description_of(obj: PlanObject) -> str:
    """The text retrieval matches: the description, else the name."""
    return obj.description.strip() or obj.name


@dataclass
class RoomAssets:
    """The assets retrieved for a room's floor and wall instances (instance name -> asset id)."""

    room_id: str
    floor: dict[str, str] = field(default_factory=dict)
    wall: dict[str, str] = field(default_factory=dict)
    ceiling: dict[str, str] = field(default_factory=dict)
    picks: list[dict[str, Any]] = field(default_factory=list)
    failed: list[dict[str, str]] = field(default_factory=list)


def retrieve_room(
    plan_room: PlanRoom, library: AssetLibrary, chooser: AssetChooser, seed: int
) -> RoomAssets:
    """One asset per floor and wall instance of ``plan_room``; failures are recorded."""
    out = RoomAssets(plan_room.id)
    rng = stage_rng(seed, "retrieve", plan_room.id)
    out.floor = _retrieve(plan_room, "floor", chooser, rng, out)
    out.wall = _retrieve(plan_room, "wall", chooser, rng, out)
    out.ceiling = _retrieve(plan_room, "ceiling", chooser, rng, out)
    return out


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
    runs: list[tuple[LayoutResult, dict[str, Any]]] = []  # each layout's counter run, if any

    def plain(problem: RoomProblem) -> LayoutResult:
        return solve_room(
            problem,
            solver="cpsat",
            time_limit_s=time_limit_s,
            rng=stage_rng(seed, "layout", room.id),
        )

    grid_log: list[dict[str, Any] | None] = []  # the desk grid of each gridded solve
    grids: list[tuple[LayoutResult, dict[str, Any] | None]] = []

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
        problem = _problem(plan_room, room, context, room_windows, room_assets, library)
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
            runs.append((result, run))
        grids.append((result, grid_log[-1] if grid_log else None))  # the last solve is used
        return result

    result = solve(windows)
    windows, result = _make_room_for_defining(
        plan_room, room, context, assets.floor, library, windows, result, solve, out
    )
    result = _make_room_for_relations(plan_room, assets, metas, windows, result, solve, out)
    out.layout = _layout_record(result)
    run = next((record for solved, record in runs if solved is result), None)
    if run is not None:
        out.layout["counter_run"] = run
        windows, notes = run_windows(windows, run)
        out.changes.extend(f"{room.id}: {note}" for note in notes)
    grid = next((record for solved, record in grids if solved is result), None)
    if grid is not None:
        out.layout["desk_grid"] = grid
    out.windows = windows
    out.relations = relation_verdicts(plan_room, result.constraints)
    out.warnings.extend(result.warnings)
    by_name = {o.name: o for o in plan_room.objects}
    for item in result.unplaced:
        out.unplaced.append({"object": item.id, "stage": "layout", "reason": item.reason})
    floor_items: list[FloorItem] = []
    placed_of: dict[str, int] = {}  # plan object -> its instances placed so far
    for instance, placement in result.placements.items():
        asset_id = assets.floor[instance]
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
    _lay_rugs(plan_room, room, context, assets.floor, result, library, out)
    hung_for = front_lookers(plan_room, grid)  # boards hang where the front row looks
    _hang(hung_for, room, context, windows, assets.wall, floor_items, library, seed, out)
    _stand_unhung_tvs(plan_room, room, out, library)
    _hang_from_ceiling(plan_room, room, context, assets.ceiling, floor_items, library, out)
    return out


def _paired(room_id: str, instance: str, target: str, counts: dict[str, int]) -> str:
    """The floor instance of ``target`` that wall or ceiling instance ``instance`` is hung for:
    mirror k for salon chair k, mobile k above crib k (beyond the targets' count, round again)."""
    index = int(instance.rsplit("-", 1)[1]) if instance.rsplit("-", 1)[-1].isdigit() else 0
    return object_id(room_id, instance_name(target, index % max(1, counts.get(target, 1))))


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
    priorities = _priorities(plan_room)
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


# a top a TV without its own stand stands on (a counter, a sideboard): its height, least area
TV_HOST_HEIGHTS_M = (0.4, 1.2)
TV_HOST_AREA_M2 = 0.25


def _stand_unhung_tvs(
    plan_room: PlanRoom, room: Room, out: RoomFurniture, library: AssetLibrary
) -> None:
    """A TV that could not hang (over its stand: a window or door took that wall; without a
    stand: no wall had room) stands on its stand instead, or on the roomiest top of the room's
    furniture at a TV's height (a counter, a sideboard): it joins that receptacle's small
    objects, dropped and settled with them."""
    above = {o.name: o.above for o in plan_room.objects if o.placement == "wall" and o.above}
    placed = {o.id for o in out.objects}
    kept = []
    for item in out.unplaced:
        name = str(item.get("object", "")).rsplit("-", 1)[0]
        if item.get("stage") != "wall" or name != "television":
            kept.append(item)
            continue
        stand = above.get(name)
        oid = object_id(room.id, instance_name(stand, 0)) if stand is not None else ""
        if oid not in placed:
            oid = _tv_host(out, library)
        if not oid:
            kept.append(item)
            continue
        tv = PlanSmallObject(
            name="television",
            description="a flat-screen television on feet",
            category="television",
            variance="same",
        )
        index = next((i for i, (rid, _) in enumerate(out.receptacles) if rid == oid), None)
        if index is not None:
            holder = out.receptacles[index][1]
        else:
            holder = _plan_object_of(plan_room, room.id, oid)
        others = [s for s in holder.on_top if s.category != "television"]
        entry = (oid, holder.model_copy(update={"on_top": [tv, *others]}))
        if index is None:
            out.receptacles.append(entry)
        else:
            out.receptacles[index] = entry
        reason = item.get("reason", "no wall for it")
        out.changes.append(f"{room.id}: {item['object']}: {reason}; it stands on {oid} instead")
    out.unplaced = kept


def _tv_host(out: RoomFurniture, library: AssetLibrary) -> str:
    """The placed floor object with the roomiest top at a TV's height, if any ("" if none)."""
    best, best_area = "", TV_HOST_AREA_M2
    low, high = TV_HOST_HEIGHTS_M
    for obj in out.objects:
        meta = library.get(obj.asset).meta
        area = max((s.area_m2 for s in meta.surfaces if low <= s.height <= high), default=0.0)
        if area > best_area:
            best, best_area = obj.id, area
    return best


def _plan_object_of(plan_room: PlanRoom, room_id: str, oid: str) -> PlanObject:
    """The plan object a placed scene object is an instance of."""
    for obj in plan_room.objects:
        for instance in obj.instances():
            if object_id(room_id, instance) == oid:
                return obj
    raise KeyError(oid)


def _hang_from_ceiling(
    plan_room: PlanRoom,
    room: Room,
    context: RoomContext,
    assets: dict[str, str],
    floor_items: list[FloorItem],
    library: AssetLibrary,
    out: RoomFurniture,
) -> None:
    """Ceiling objects (pendants, chandeliers, fans) hang with their top at the ceiling: over
    the floor object they are ``above`` (a dining table), else spread along the room's long
    axis through its centre. Static, like the ceiling."""
    centres = {f.id: f.footprint.centroid for f in floor_items}
    polygon = Polygon(room.polygon)
    minx, miny, maxx, maxy = polygon.bounds
    centre = (
        polygon.centroid if polygon.centroid.within(polygon) else polygon.representative_point()
    )
    counts = {o.name: o.quantity for o in plan_room.objects if o.placement == "floor"}
    for obj in plan_room.objects:
        if obj.placement != "ceiling":
            continue
        instances = [i for i in obj.instances() if i in assets]
        for k, instance in enumerate(instances):
            meta = library.get(assets[instance]).meta
            target = _paired(room.id, instance, obj.above, counts) if obj.above else None
            if target in centres:
                x, y = centres[target].x, centres[target].y
            else:
                f = (k + 1) / (len(instances) + 1)
                if maxx - minx >= maxy - miny:
                    x, y = minx + f * (maxx - minx), centre.y
                else:
                    x, y = centre.x, miny + f * (maxy - miny)
            z = max(context.wall_height - meta.size[2], 0.0)
            out.objects.append(
                SceneObject(
                    id=object_id(room.id, instance),
                    asset=assets[instance],
                    position=(round(x, 4), round(y, 4), round(z, 4)),
                    static=True,
                    room=room.id,
                )
            )


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
    result, missing = best, set()
    heights = {i: library.get(a).meta.size[2] for i, a in floor_assets.items()}
    doors = [d for d in context.doors if room.id in d.rooms]
    names = ", ".join(sorted(defining - missing))
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
        trial = solve([*kept, raised]) if raised is not None else None
        if raised is not None and trial is not None and not defining - set(trial.placements):
            kept.append(raised)
            result = trial
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


def _retrieve(
    plan_room: PlanRoom,
    placement: str,
    chooser: AssetChooser,
    rng: np.random.Generator,
    out: RoomAssets,
) -> dict[str, str]:
    """Instance name -> asset id for the room's objects of one placement."""
    chosen: dict[str, str] = {}
    for obj in plan_room.objects:
        if obj.placement != placement:
            continue
        try:
            picks = chooser.choose(
                description_of(obj),
                quantity=obj.quantity,
                variance=obj.variance,
                rng=rng,
                size=obj.size,
                placement=placement,
                category=obj.category,
            )
        except HolomjError as err:
            for instance in obj.instances():
                out.failed.append(
                    {"object": instance, "stage": "retrieve", "reason": err.one_line()}
                )
            continue
        for instance, pick in zip(obj.instances(), picks):
            chosen[instance] = pick.asset_id
            record = {"room": plan_room.id, "instance": instance, "asset": pick.asset_id}
            for key in ("category", "score", "visual", "text", "size"):
                value = getattr(pick, key, None)
                if value is not None:
                    record[key] = round(value, 4) if isinstance(value, float) else value
            record.update(on_demand_record(pick))
            out.picks.append(record)
    return chosen


def on_demand_record(pick: Any) -> dict[str, Any]:
    """What a pick says about the attributes asked and honoured, and how (library match,
    synthesised, proxy...); empty for a pick that does not say (a plain ranking)."""
    if getattr(pick, "attributes_asked", None) is None:
        return {}
    record = {
        "attributes_asked": pick.attributes_asked,
        "attributes_honoured": pick.attributes_honoured or {},
        "how": pick.how,
        "proxy": bool(pick.proxy),
    }
    if getattr(pick, "attributes_how", None) is not None:  # per part: "brass on the handles"
        record["attributes_how"] = pick.attributes_how
    return record


def _hung_above(
    plan_room: PlanRoom, wall_assets: dict[str, str], library: AssetLibrary
) -> dict[str, float]:
    """Plan name of a floor object -> (width, height) of the wall objects hung above it (the
    widest and the tallest)."""
    out: dict[str, tuple[float, float]] = {}
    for obj in plan_room.objects:
        if obj.placement != "wall" or obj.above is None:
            continue
        for instance in obj.instances():
            if instance in wall_assets:
                _, width, height = library.get(wall_assets[instance]).meta.size
                old_w, old_h = out.get(obj.above, (0.0, 0.0))
                out[obj.above] = (max(old_w, width), max(old_h, height))
    return out


def _priorities(plan_room: PlanRoom) -> dict[str, int]:
    """Layout priority per instance: defining furniture 100, requested objects 10, others 1."""
    out = {}
    for obj in plan_room.objects:
        priority = DEFINING_PRIORITY if obj.defining else REQUESTED_PRIORITY if obj.requested else 1
        for instance in obj.instances():
            out[instance] = priority
    return out


def _problem(
    plan_room: PlanRoom,
    room: Room,
    context: RoomContext,
    room_windows: Sequence[Window],
    room_assets: RoomAssets,
    library: AssetLibrary,
) -> RoomProblem:
    """The layout problem of the room's floor objects. A floor object that a wall object hangs
    above (a TV stand under its TV) counts as tall as both together and as wide as the wider,
    so that the wall above it stays free of windows."""
    assets = room_assets.floor
    hung = _hung_above(plan_room, room_assets.wall, library)
    inset = context.wall_thickness / 2 + LAYOUT_MARGIN_M
    polygon = Polygon(room.polygon).buffer(-inset, join_style="mitre")
    ring = polygon.exterior

    def on_ring(xy: Sequence[float]) -> tuple[float, float]:
        point = ring.interpolate(ring.project(Point(xy)))
        return (round(point.x, 6), round(point.y, 6))

    doors = []
    for door in context.doors:
        if room.id not in door.rooms:
            continue
        swing = "none"
        if door.kind == "doorway":
            swing = "in" if (door.opens_into or door.rooms[0]) == room.id else "out"
        doors.append(
            LayoutDoor(
                id=door.id,
                position=on_ring(door.position),
                width=door.effective_width,
                swing=swing,
                hinge=door.hinge_side,
            )
        )
    windows = [
        LayoutWindow(
            id=w.id,
            position=on_ring(w.position),
            width=w.width,
            sill_height=w.base_height,
            height=w.height,
        )
        for w in room_windows
    ]
    priorities = _priorities(plan_room)
    objects = []
    for instance, asset_id in assets.items():
        if _is_decor(library, asset_id):
            continue  # laid after the layout (holomj.layout.rugs)
        depth, width, height = library.get(asset_id).meta.size
        above = hung.get(instance.rsplit("-", 1)[0])
        if above is not None:
            # the wall object's span keeps its frame margin from window frames too
            width = max(width, above[0] + 2 * OPENING_MARGIN_M)
            height = height + ABOVE_GAP_M + above[1]
        objects.append(
            LayoutObject(
                id=instance,
                width=width,
                depth=depth,
                height=height,
                priority=priorities.get(instance, 1),
            )
        )
    coords = [(round(x, 6), round(y, 6)) for x, y in list(ring.coords)[:-1]]
    return RoomProblem(
        room_id=room.id,
        polygon=coords,
        size_unit="m",
        doors=doors,
        windows=windows,
        objects=objects,
        constraints=relation_constraints(plan_room, [o.id for o in objects]),
        constraints_text="\n".join(plan_room.constraints) or None,
        settings=LayoutSettings(walker_radius_m=WALKER_RADIUS_M, door_clearance_m=DOOR_CLEARANCE_M),
    )


def _is_decor(library: AssetLibrary, asset_id: str) -> bool:
    return library.get(asset_id).meta.category in DECOR_CATEGORIES


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
    rugs = [(i, a) for i, a in assets.items() if _is_decor(library, a)]
    if not rugs:
        return
    anchors = [
        Anchor(p.x, p.y, p.yaw_deg, p.width, p.depth, library.get(assets[i]).meta.category)
        for i, p in result.placements.items()
    ]
    inset = context.wall_thickness / 2 + LAYOUT_MARGIN_M
    polygon = Polygon(room.polygon).buffer(-inset, join_style="mitre")
    sizes = [tuple(library.get(a).meta.size[:2]) for _, a in rugs]
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


def _footprint(p: Placement) -> Polygon:
    rect = box(-p.depth / 2, -p.width / 2, p.depth / 2, p.width / 2)
    return affinity.translate(affinity.rotate(rect, p.yaw_deg, origin=(0, 0)), p.x, p.y)


def _hang(
    plan_room: PlanRoom,
    room: Room,
    context: RoomContext,
    room_windows: Sequence[Window],
    assets: dict[str, str],
    floor_items: list[FloorItem],
    library: AssetLibrary,
    seed: int,
    out: RoomFurniture,
) -> None:
    above = {o.name: o.above for o in plan_room.objects if o.placement == "wall"}
    faced_by = {o.name: o.faced_by for o in plan_room.objects if o.placement == "wall"}
    counts = {o.name: o.quantity for o in plan_room.objects if o.placement == "floor"}
    asked = {o.name for o in plan_room.objects if o.requested}
    requests = []
    asset_of = {object_id(room.id, instance): a for instance, a in assets.items()}
    for instance, asset_id in assets.items():
        meta = library.get(asset_id).meta
        depth, width, height = meta.size
        target = above.get(instance.rsplit("-", 1)[0])
        looker = faced_by.get(instance.rsplit("-", 1)[0])
        requests.append(
            WallObjectRequest(
                id=object_id(room.id, instance),
                size=(width, depth, height),
                kind=WALL_KINDS.get(meta.category, "other"),
                above=_paired(room.id, instance, target, counts) if target else None,
                faced_by=_paired(room.id, instance, looker, counts) if looker else None,
                optional=instance.rsplit("-", 1)[0] not in asked,
            )
        )
    if not requests:
        return
    placed, unplaced = place_wall_objects(
        room,
        context.walls,
        context.doors,
        [*(w for w in context.windows if room.id not in w.rooms), *room_windows],
        floor_items,
        requests,
        stage_rng(seed, "wall_objects", room.id),
        wall_height=context.wall_height,
        wall_thickness=context.wall_thickness,
    )
    for p in placed:
        if p.note:
            out.changes.append(f"{room.id}: {p.id}: {p.note}")
        obj = p.scene_object(asset_of[p.id]).model_copy(
            update={
                "position": tuple(round(v, 4) for v in (p.x, p.y, p.z)),
                "yaw_deg": round(p.yaw_deg, 4),
            }
        )
        out.objects.append(obj)
    instance_of = {object_id(room.id, instance): instance for instance in assets}
    for item in unplaced:
        out.unplaced.append(
            {"object": instance_of[item.id], "stage": "wall", "reason": item.reason}
        )


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
