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

import re
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any, Protocol

import numpy as np
from shapely import affinity
from shapely.geometry import Point, Polygon, box

from holomj.errors import HolomjError
from holomj.layout.room_problem import (
    LayoutDoor,
    LayoutObject,
    LayoutSettings,
    LayoutWindow,
    RoomProblem,
)
from holomj.layout.solve import LayoutResult, Placement, solve_room
from holomj.layout.wall_objects import FloorItem, WallObjectRequest, place_wall_objects
from holomj.library.store import AssetLibrary
from holomj.seeds import stage_rng
from holomj.spec.plan import PlanObject, PlanRoom, instance_name
from holomj.spec.scene import Door, Room, SceneObject, Window
from holomj.spec.walls import Wall

LAYOUT_MARGIN_M = 0.03  # beyond half the interior wall thickness
# The layout keeps a walkway this wide (radius) between every two doors of a room: 5 cm more than
# the navigation map's agent, so that its finer grid and real collider boxes still find the path.
WALKER_RADIUS_M = 0.3
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
    objects."""
    out = RoomFurniture(room.id, picks=list(assets.picks), unplaced=list(assets.failed))
    problem = _problem(plan_room, room, context, assets.floor, library)
    result = solve_room(
        problem,
        solver="cpsat",
        time_limit_s=time_limit_s,
        rng=stage_rng(seed, "layout", room.id),
    )
    out.layout = _layout_record(result)
    out.warnings.extend(result.warnings)
    by_name = {o.name: o for o in plan_room.objects}
    for item in result.unplaced:
        out.unplaced.append({"object": item.id, "stage": "layout", "reason": item.reason})
    floor_items: list[FloorItem] = []
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
        floor_items.append(FloorItem(oid, _footprint(placement), meta.size[2]))
        plan_obj = by_name[instance.rsplit("-", 1)[0]]
        if plan_obj.on_top:
            out.receptacles.append((oid, plan_obj))
    _hang(plan_room, room, context, assets.wall, floor_items, library, seed, out)
    return out


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
            out.picks.append(record)
    return chosen


def _problem(
    plan_room: PlanRoom,
    room: Room,
    context: RoomContext,
    assets: dict[str, str],
    library: AssetLibrary,
) -> RoomProblem:
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
        for w in context.windows
        if room.id in w.rooms
    ]
    objects = []
    for instance, asset_id in assets.items():
        depth, width, height = library.get(asset_id).meta.size
        objects.append(LayoutObject(id=instance, width=width, depth=depth, height=height))
    coords = [(round(x, 6), round(y, 6)) for x, y in list(ring.coords)[:-1]]
    return RoomProblem(
        room_id=room.id,
        polygon=coords,
        size_unit="m",
        doors=doors,
        windows=windows,
        objects=objects,
        constraints_text="\n".join(plan_room.constraints) or None,
        settings=LayoutSettings(walker_radius_m=WALKER_RADIUS_M),
    )


def _footprint(p: Placement) -> Polygon:
    rect = box(-p.depth / 2, -p.width / 2, p.depth / 2, p.width / 2)
    return affinity.translate(affinity.rotate(rect, p.yaw_deg, origin=(0, 0)), p.x, p.y)


def _hang(
    plan_room: PlanRoom,
    room: Room,
    context: RoomContext,
    assets: dict[str, str],
    floor_items: list[FloorItem],
    library: AssetLibrary,
    seed: int,
    out: RoomFurniture,
) -> None:
    above = {o.name: o.above for o in plan_room.objects if o.placement == "wall"}
    requests = []
    asset_of = {object_id(room.id, instance): a for instance, a in assets.items()}
    for instance, asset_id in assets.items():
        meta = library.get(asset_id).meta
        depth, width, height = meta.size
        target = above.get(instance.rsplit("-", 1)[0])
        requests.append(
            WallObjectRequest(
                id=object_id(room.id, instance),
                size=(width, depth, height),
                kind=WALL_KINDS.get(meta.category, "other"),
                above=object_id(room.id, instance_name(target, 0)) if target else None,
            )
        )
    if not requests:
        return
    placed, unplaced = place_wall_objects(
        room,
        context.walls,
        context.doors,
        context.windows,
        floor_items,
        requests,
        stage_rng(seed, "wall_objects", room.id),
        wall_height=context.wall_height,
        wall_thickness=context.wall_thickness,
    )
    for p in placed:
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
    }
