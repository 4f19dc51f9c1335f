"""Where a new object goes: on the floor among the room's other objects, hung on a wall (kept
clear of what stands below) or from the ceiling (its top at the ceiling)."""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
from shapely.geometry import Polygon

from holomj.edit.floor import Blocker, RoomFloor, Wish
from holomj.edit.footprints import footprint, in_room, object_size, object_yaw, room_at
from holomj.edit.lookup import room_of
from holomj.edit.state import (
    EditContext,
    Refused,
    find,
)
from holomj.errors import HolomjError
from holomj.layout.furniture_rules import FIXED_CATEGORIES, WALL_KINDS
from holomj.layout.geometry import LAYOUT_MARGIN_M
from holomj.layout.wall_objects import FloorItem, WallObjectRequest, place_wall_objects
from holomj.library.store import AssetLibrary
from holomj.spec.edit import AddOp
from holomj.spec.scene import SceneObject, SceneSpec

CEILING_GAP_M = 0.05


CEILING_STEP_M = 0.1


def place_on_floor(
    scene: SceneSpec,
    oid: str,
    asset_id: str,
    room_id: str,
    op: AddOp,
    wishes: list[Wish],
    ctx: EditContext,
) -> tuple[SceneObject, list[dict[str, object]]]:
    library = ctx.library
    meta = library.get(asset_id).meta
    depth, width, height = meta.size
    floor = RoomFloor(scene, room_id, library, blockers=ctx.blockers)
    if op.position is not None:
        x, y = op.position[0], op.position[1]
        if room_at(scene, x, y) != room_id:
            raise Refused(f"position ({x:g}, {y:g}) is outside room {room_id!r}")
        yaw = op.yaw_deg if op.yaw_deg is not None else 0.0
        problems = floor.problems(x, y, yaw, (width, depth, height))
        if problems:
            raise Refused(f"cannot stand at ({x:g}, {y:g}): {'; '.join(problems)}")
        verdicts = floor.verdicts(x, y, yaw, (width, depth, height), wishes)
    else:
        spot = floor.place((width, depth, height), wishes, yaw_deg=op.yaw_deg)
        x, y, yaw, verdicts = spot.x, spot.y, spot.yaw_deg, spot.verdicts
    obj = SceneObject(
        id=oid,
        asset=asset_id,
        position=(round(x, 4), round(y, 4), 0.0),
        yaw_deg=round(yaw % 360.0, 4),
        static=meta.category in FIXED_CATEGORIES,
        room=room_id,
    )
    return obj, verdicts


def _things_as_floor_items(
    scene: SceneSpec, room_id: str, library: AssetLibrary
) -> list[FloorItem]:
    """The room's objects (floor and wall) as wall placement sees floor furniture: a wall
    object counts as furniture as high as its top, so nothing new hangs over it."""
    items = []
    for obj in scene.objects:
        if obj.support is not None or not in_room(scene, obj, room_id):
            continue
        depth, width, height = object_size(obj, library)
        yaw = object_yaw(obj)
        rad = math.radians(yaw)
        items.append(
            FloorItem(
                obj.id,
                footprint(obj.position[0], obj.position[1], yaw, width, depth),
                obj.position[2] + height,
                (round(math.cos(rad), 9), round(math.sin(rad), 9)),
            )
        )
    return items


def hang_on_wall(
    scene: SceneSpec,
    oid: str,
    asset_id: str,
    room_id: str,
    above: str | None,
    library: AssetLibrary,
    ctx: EditContext,
    index: int,
) -> SceneObject:
    meta = library.get(asset_id).meta
    depth, width, height = meta.size
    items = _things_as_floor_items(scene, room_id, library)
    if above is not None and above not in {i.id for i in items}:
        raise Refused(f"{above} is not in room {room_id!r}")
    request = WallObjectRequest(
        id=oid,
        size=(width, depth, height),
        kind=WALL_KINDS.get(meta.category, "other"),
        above=above,
    )
    room = scene.room(room_id)
    try:
        placed, unplaced = place_wall_objects(
            room,
            scene.walls,
            scene.doors,
            scene.windows,
            [i for i in items if i.id == above or i.id != oid],
            [request],
            ctx.rng("wall", index),
            wall_height=scene.wall_height,
            wall_thickness=scene.wall_thickness,
        )
    except HolomjError as err:
        raise Refused(err.one_line()) from None
    if not placed:
        reason = unplaced[0].reason if unplaced else "no free wall"
        raise Refused(f"no wall of {room_id!r} takes it: {reason}")
    p = placed[0]
    return p.scene_object(asset_id).model_copy(
        update={
            "position": tuple(round(v, 4) for v in (p.x, p.y, p.z)),
            "yaw_deg": round(p.yaw_deg, 4),
            "room": room_id,
        }
    )


def ceiling_spot(
    scene: SceneSpec,
    room_id: str,
    size: tuple[float, float, float],
    library: AssetLibrary,
    *,
    at: Sequence[float] | None = None,
    above: str | None = None,
    exclude: frozenset[str] = frozenset(),
    blockers: Sequence[Blocker] = (),
) -> tuple[float, float, float]:
    """Where a ceiling object of ``size`` = (x extent, y extent, height) hangs: its top at the
    ceiling, over ``above``, at ``at`` or at the room's centre, else the nearest free spot."""
    room = scene.room(room_id)
    depth, width, height = size
    z = max(scene.wall_height - height, 0.0)
    inset = Polygon(room.polygon).buffer(
        -(scene.wall_thickness / 2 + LAYOUT_MARGIN_M), join_style="mitre"
    )
    if above is not None:
        target = find(scene, above)
        if room_of(scene, target) != room_id:
            raise Refused(f"{above} is not in room {room_id!r}")
        want = (target.position[0], target.position[1])
    elif at is not None:
        want = (at[0], at[1])
        if room_at(scene, want[0], want[1]) != room_id:
            raise Refused(f"position ({want[0]:g}, {want[1]:g}) is outside room {room_id!r}")
    else:
        point = inset.centroid if inset.centroid.within(inset) else inset.representative_point()
        want = (point.x, point.y)
    floor = RoomFloor(scene, room_id, library, exclude=exclude, blockers=blockers)
    others = [t for t in floor.things if t.top > z]
    minx, miny, maxx, maxy = inset.bounds
    xs = np.arange(minx, maxx + 1e-9, CEILING_STEP_M)
    ys = np.arange(miny, maxy + 1e-9, CEILING_STEP_M)
    spots = [(want[0], want[1])] + sorted(
        ((float(x), float(y)) for x in xs for y in ys),
        key=lambda p: (math.hypot(p[0] - want[0], p[1] - want[1]), p),
    )
    for x, y in spots:
        shape = footprint(x, y, 0.0, width, depth)
        if not inset.buffer(1e-7).covers(shape):
            continue
        if all(t.polygon.distance(shape) >= CEILING_GAP_M for t in others):
            return (round(x, 4), round(y, 4), round(z, 4))
    raise Refused(f"no free ceiling in room {room_id!r} for a {width:.2f} x {depth:.2f} m object")


def hang_from_ceiling(
    scene: SceneSpec,
    oid: str,
    asset_id: str,
    room_id: str,
    at: Sequence[float] | None,
    above: str | None,
    library: AssetLibrary,
) -> SceneObject:
    meta = library.get(asset_id).meta
    position = ceiling_spot(scene, room_id, meta.size, library, at=at, above=above)
    return SceneObject(id=oid, asset=asset_id, position=position, static=True, room=room_id)
