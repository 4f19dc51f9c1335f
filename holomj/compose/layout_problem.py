"""The layout problem of a room's floor objects (:class:`holomj.layout.room_problem.RoomProblem`)
from its plan, its retrieved assets and the house around it.

The solver works on the room polygon *inset* by half an interior wall plus a margin
(``LAYOUT_MARGIN_M``): interior walls are centred on the room edge, so furniture laid out against
the raw edge would sit inside the wall. Doors and windows are projected onto the inset outline.
The layout uses each retrieved asset's real footprint (width = the asset's y extent, depth = its
x extent: assets face +X), so what the solver sees is what the simulator gets.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Literal

from shapely.geometry import Point, Polygon

from holomj.compose.room_assets import RoomAssets
from holomj.compose.room_context import RoomContext
from holomj.layout.furniture_rules import DOOR_CLEARANCE_M, WALKER_RADIUS_M
from holomj.layout.geometry import LAYOUT_MARGIN_M
from holomj.layout.relation_constraints import relation_constraints
from holomj.layout.room_problem import (
    LayoutDoor,
    LayoutObject,
    LayoutSettings,
    LayoutWindow,
    RoomProblem,
)
from holomj.layout.wall_objects import ABOVE_GAP_M, OPENING_MARGIN_M
from holomj.library.store import AssetLibrary
from holomj.spec.decor import DECOR_CATEGORIES
from holomj.spec.plan import PlanRoom
from holomj.spec.scene import Room, Window

DEFINING_PRIORITY = 100  # a room's defining furniture outweighs every optional object
REQUESTED_PRIORITY = 10


def _hung_above(
    plan_room: PlanRoom, wall_assets: dict[str, str], library: AssetLibrary
) -> dict[str, tuple[float, float]]:
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


def instance_priorities(plan_room: PlanRoom) -> dict[str, int]:
    """Layout priority per instance: defining furniture 100, requested objects 10, others 1."""
    out = {}
    for obj in plan_room.objects:
        priority = DEFINING_PRIORITY if obj.defining else REQUESTED_PRIORITY if obj.requested else 1
        for instance in obj.instances():
            out[instance] = priority
    return out


def layout_problem(
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
        swing: Literal["in", "out", "none"] = "none"
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
    priorities = instance_priorities(plan_room)
    objects = []
    for instance, asset_id in assets.items():
        if is_decor(library, asset_id):
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


def is_decor(library: AssetLibrary, asset_id: str) -> bool:
    return library.get(asset_id).meta.category in DECOR_CATEGORIES
