"""Objects: ``add``, ``remove``, ``move`` and ``replace``.

A floor object is placed by :class:`holomj.edit.floor.RoomFloor` among the room's other objects,
which stay where they are; a wall object is hung by
:func:`holomj.layout.wall_objects.place_wall_objects` (the room's other objects, wall objects
included, keep it clear); a ceiling object hangs with its
top at the ceiling, above its target or at the wished-for spot. Small objects resting on a moved
object move along with it (the same turn and shift), those on a removed one are removed with it,
those on a replaced one are dropped again on the new one (or removed, when they find no place),
and every such consequence is reported.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

from holomj.edit.choice import choose_asset
from holomj.edit.describe import Described, describe
from holomj.edit.floor import RoomFloor
from holomj.edit.footprints import object_size, object_yaw, room_at
from holomj.edit.lookup import floor_ids, kind_of, new_id, pick_room, room_of
from holomj.edit.placing import ceiling_spot, hang_from_ceiling, hang_on_wall, place_on_floor
from holomj.edit.small import drop
from holomj.edit.state import (
    Change,
    EditContext,
    Refused,
    check_size,
    find,
    resting_on,
    with_objects,
)
from holomj.edit.wishes import default_wishes, described_wishes, wishes_of
from holomj.layout.furniture_rules import FIXED_CATEGORIES
from holomj.spec.assets import AssetMeta
from holomj.spec.edit import AddOp, MoveOp, RemoveOp, ReplaceOp
from holomj.spec.scene import SceneObject, SceneSpec

MOVE_SEARCH_M = 1.0  # a replaced object that does not fit in place goes this far at most


# --------------------------------------------------------------------------- add


def add(scene: SceneSpec, op: AddOp, ctx: EditContext, index: int) -> Change:
    """``add``: see :class:`holomj.spec.edit.AddOp`."""
    room_id = pick_room(scene, op.room, op.relations, op.position)
    if op.size is not None:
        check_size(op.size, "size")
    asked = describe(op.description, scene.room(room_id).type, ctx.seed)
    placement = op.placement or asked.placement
    if placement == "object":
        raise Refused(
            f"{op.description!r} is a small object: use add_on with a receptacle id"
            + (f" (it would go on a {asked.holder})" if asked.holder else "")
        )
    size = op.size or asked.size
    if size is not None:
        check_size(size, "size")
    library = ctx.library
    on_floor = floor_ids(scene, library)
    notes = list(asked.notes)
    wishes = wishes_of(scene, room_id, op.relations, on_floor)
    more, above = described_wishes(scene, room_id, asked, library, on_floor, notes)
    wishes += more
    above = next((r.target for r in op.relations if r.kind == "above"), above)
    oid = new_id(scene, room_id, asked.name, op.id)
    asset_id, meta, pick = _asset_for(ctx, asked, op, size, placement, ("add", index))
    details: dict[str, Any] = {"room": room_id, "name": asked.name, "placement": placement, **pick}
    if placement == "floor":
        if not wishes and op.position is None:
            wishes = default_wishes(scene, room_id, asked.name, library, on_floor)
        obj, verdicts = place_on_floor(scene, oid, asset_id, room_id, op, wishes, ctx)
        details["relations"] = verdicts
    elif placement == "wall":
        obj = hang_on_wall(scene, oid, asset_id, room_id, above, library, ctx, index)
    else:
        obj = hang_from_ceiling(scene, oid, asset_id, room_id, op.position, above, library)
    if meta.proxy:
        obj = obj.model_copy(update={"proxy": True})
    return Change(
        with_objects(scene, [*scene.objects, obj]), added=[oid], notes=notes, details=details
    )


# --------------------------------------------------------------------------- remove


def remove(scene: SceneSpec, op: RemoveOp, ctx: EditContext, index: int) -> Change:
    """``remove``: the object and everything resting on it."""
    find(scene, op.id)
    riders = [o.id for o in resting_on(scene, op.id)]
    gone = {op.id, *riders}
    notes = [f"removed with it (they rested on it): {', '.join(riders)}"] if riders else []
    kept = [o for o in scene.objects if o.id not in gone]
    return Change(with_objects(scene, kept), removed=[op.id, *riders], notes=notes)


# --------------------------------------------------------------------------- move


def carried(
    scene: SceneSpec, obj: SceneObject, x: float, y: float, yaw_deg: float, room_id: str
) -> dict[str, SceneObject]:
    """``obj`` at ``(x, y)`` turned to ``yaw_deg``, and what rests on it moved along (the same
    turn about its origin, the same shift), by id."""
    x0, y0, z0 = obj.position
    turn = yaw_deg - object_yaw(obj)
    c, s = math.cos(math.radians(turn)), math.sin(math.radians(turn))
    out = {
        obj.id: obj.model_copy(
            update={
                "position": (round(x, 4), round(y, 4), z0),
                "yaw_deg": round(yaw_deg % 360.0, 4),
                "quat": None,
                "room": room_id,
            }
        )
    }
    half = math.radians(turn) / 2
    qz = (math.cos(half), 0.0, 0.0, math.sin(half))
    for rider in resting_on(scene, obj.id):
        px, py, pz = rider.position
        dx, dy = px - x0, py - y0
        update: dict[str, Any] = {
            "position": (round(x + c * dx - s * dy, 6), round(y + s * dx + c * dy, 6), pz),
            "yaw_deg": round((rider.yaw_deg + turn) % 360.0, 4),
            "room": room_id,
        }
        if rider.quat is not None:
            update["quat"] = _quat_mul(qz, rider.quat)
        out[rider.id] = rider.model_copy(update=update)
    return out


def _quat_mul(a: Sequence[float], b: Sequence[float]) -> tuple[float, float, float, float]:
    w1, x1, y1, z1 = a
    w2, x2, y2, z2 = b
    return (
        w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2,
        w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
        w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2,
        w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2,
    )


def _replace_objects(scene: SceneSpec, updated: dict[str, SceneObject]) -> SceneSpec:
    return with_objects(scene, [updated.get(o.id, o) for o in scene.objects])


def move(scene: SceneSpec, op: MoveOp, ctx: EditContext, index: int) -> Change:
    """``move`` to a pose or to where relations hold (small objects: see
    :func:`holomj.edit.small.move_onto`)."""
    from holomj.edit.small import move_onto

    if op.on is not None:
        return move_onto(scene, op, ctx, index)
    obj = find(scene, op.id)
    library = ctx.library
    kind = kind_of(obj, library)
    if kind == "object":
        raise Refused(f"{op.id} is a small object on {obj.support}: move it with 'on'")
    if kind == "wall":
        raise Refused(f"{op.id} hangs on a wall: remove it and add it again where it should be")
    room_id = room_of(scene, obj)
    riders = frozenset(o.id for o in resting_on(scene, op.id))
    depth, width, height = object_size(obj, library)
    yaw = op.yaw_deg if op.yaw_deg is not None else object_yaw(obj)
    details: dict[str, Any] = {}
    if kind == "ceiling":
        if op.relations:
            raise Refused(f"{op.id} hangs from the ceiling: give a position")
        at = op.position or obj.position
        target_room = room_at(scene, at[0], at[1])
        if target_room is None:
            raise Refused(f"position ({at[0]:g}, {at[1]:g}) is outside every room")
        x, y, _ = ceiling_spot(
            scene, target_room, (depth, width, height), library, at=at,
            exclude=frozenset({op.id}),
        )  # fmt: skip
        if math.hypot(x - at[0], y - at[1]) > 1e-6:
            raise Refused(f"the ceiling at ({at[0]:g}, {at[1]:g}) is taken")
        room_id = target_room
    elif op.relations:
        floor = RoomFloor(scene, room_id, library, exclude=riders | {op.id}, blockers=ctx.blockers)
        wishes = wishes_of(scene, room_id, op.relations, floor_ids(scene, library) - {op.id})
        if any(r.kind == "above" for r in op.relations):
            raise Refused("'above' is for wall and ceiling objects")
        spot = floor.place((width, depth, height), wishes, yaw_deg=op.yaw_deg)
        x, y, yaw = spot.x, spot.y, spot.yaw_deg
        details["relations"] = spot.verdicts
    else:
        at = op.position or obj.position
        x, y = at[0], at[1]
        target_room = room_at(scene, x, y)
        if target_room is None:
            raise Refused(f"position ({x:g}, {y:g}) is outside every room")
        room_id = target_room
        floor = RoomFloor(scene, room_id, library, exclude=riders | {op.id}, blockers=ctx.blockers)
        problems = floor.problems(x, y, yaw, (width, depth, height))
        if problems:
            raise Refused(f"cannot stand at ({x:g}, {y:g}) with yaw {yaw:g}: {'; '.join(problems)}")
    updated = carried(scene, obj, x, y, yaw, room_id)
    notes = []
    if riders:
        notes.append(f"moved along with it (they rest on it): {', '.join(sorted(riders))}")
    why = {
        oid: f"operation {index}: move" if oid == op.id else f"operation {index}: rests on {op.id}"
        for oid in updated
    }
    return Change(
        _replace_objects(scene, updated),
        moved=list(updated),
        notes=notes,
        details={**details, "position": [round(x, 4), round(y, 4)], "yaw_deg": round(yaw % 360, 4)},
        why=why,
    )


# --------------------------------------------------------------------------- replace


def replace(scene: SceneSpec, op: ReplaceOp, ctx: EditContext, index: int) -> Change:
    """``replace``: a new asset for the description, in the same place (see
    :class:`holomj.spec.edit.ReplaceOp`)."""
    obj = find(scene, op.id)
    library = ctx.library
    kind = kind_of(obj, library)
    if kind == "object":
        raise Refused(f"{op.id} is a small object: remove it and add_on a new one")
    if op.size is not None:
        check_size(op.size, "size")
    room_id = room_of(scene, obj)
    asked = describe(op.description, scene.room(room_id).type, ctx.seed)
    size = op.size or asked.size
    asset_id, meta, pick = _asset_for(ctx, asked, op, size, kind, ("replace", index))
    depth, width, height = meta.size
    x, y, z = obj.position
    yaw = object_yaw(obj)
    riders = resting_on(scene, op.id)
    rider_ids = frozenset(o.id for o in riders)
    notes: list[str] = []
    details: dict[str, Any] = {"from_asset": obj.asset, **pick}
    if kind == "floor":
        floor = RoomFloor(
            scene, room_id, library, exclude=rider_ids | {op.id}, blockers=ctx.blockers
        )
        problems = floor.problems(x, y, yaw, (width, depth, height))
        if problems:
            spot = floor.place(
                (width, depth, height), [], yaw_deg=yaw, near=(x, y), within=MOVE_SEARCH_M
            )
            notes.append(
                f"the new {asked.name} does not fit where {op.id} stood ({problems[0]}); it "
                f"stands {math.hypot(spot.x - x, spot.y - y):.2f} m away"
            )
            x, y = spot.x, spot.y
    elif kind == "ceiling":
        x, y, z = ceiling_spot(
            scene, room_id, meta.size, library, at=(x, y), exclude=frozenset({op.id})
        )
    else:  # a wall object keeps its back on the wall: its centre moves by the change in depth
        shift = (depth - object_size(obj, library)[0]) / 2
        x += math.cos(math.radians(yaw)) * shift
        y += math.sin(math.radians(yaw)) * shift
    new = obj.model_copy(
        update={
            "asset": asset_id,
            "position": (round(x, 4), round(y, 4), z),
            "scale": 1.0,
            "static": obj.static if kind != "floor" else meta.category in FIXED_CATEGORIES,
            "proxy": True if meta.proxy else None,
        }
    )
    if asset_id == obj.asset:
        notes.append(f"retrieval chose the asset {op.id} already had ({asset_id})")
    kept = [new if o.id == op.id else o for o in scene.objects if o.id not in rider_ids]
    new_scene = with_objects(scene, kept)
    change = Change(new_scene, changed=[op.id], notes=notes, details=details)
    if kind == "floor" and (x, y) != (obj.position[0], obj.position[1]):
        change.moved.append(op.id)
        change.why[op.id] = f"operation {index}: replaced, did not fit in place"
    if riders:
        _drop_again(change, riders, op.id, ctx, index)
    return change


def _drop_again(
    change: Change, riders: list[SceneObject], holder: str, ctx: EditContext, index: int
) -> None:
    """The small objects of a replaced receptacle dropped on the new one (keeping their ids);
    those that find no place are removed, and the change says so."""
    direct = [o for o in riders if o.support == holder]
    try:
        scene, placed, _ = drop(
            change.scene, ctx, holder, [o.asset for o in direct],
            rng_key=("replace", index, "drop"), ids=[o.id for o in direct],
        )  # fmt: skip
    except Refused:
        scene, placed = change.scene, []
    change.scene = scene
    lost = [o.id for o in riders if o.id not in placed]
    if placed:
        change.moved.extend(placed)
        change.notes.append(f"dropped again on the new {holder}: {', '.join(placed)}")
        change.why.update({p: f"operation {index}: dropped again on {holder}" for p in placed})
    if lost:
        change.removed.extend(lost)
        change.notes.append(f"removed (no place on the new {holder}): {', '.join(lost)}")


def _asset_for(
    ctx: EditContext,
    asked: Described,
    op: AddOp | ReplaceOp,
    size: tuple[float, float, float] | None,
    placement: str,
    key: tuple[object, ...],
) -> tuple[str, AssetMeta, dict[str, Any]]:
    """The asset an ``add`` or ``replace`` asks for (its attributes and category hint)."""
    return choose_asset(
        ctx,
        asked,
        attributes=op.attributes,
        category=op.category or asked.category,
        size=size,
        placement=placement,
        key=key,
    )
