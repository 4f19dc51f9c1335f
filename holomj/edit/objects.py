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

import numpy as np
from shapely.geometry import Polygon

from holomj.edit.describe import Described, describe
from holomj.edit.floor import (
    FLOOR_Z_M,
    Blocker,
    RoomFloor,
    Wish,
    footprint,
    in_room,
    object_size,
    object_yaw,
    room_at,
)
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
from holomj.errors import HolomjError
from holomj.layout.constraints import PHRASES, RELATION_WEIGHT, normalize_phrase
from holomj.layout.furniture_rules import FIXED_CATEGORIES, WALL_KINDS, object_id
from holomj.layout.geometry import LAYOUT_MARGIN_M
from holomj.layout.wall_objects import FloorItem, WallObjectRequest, place_wall_objects
from holomj.library.store import AssetLibrary
from holomj.plan.knowledge import knowledge_base
from holomj.spec.edit import AddOp, EditRelation, MoveOp, RemoveOp, ReplaceOp
from holomj.spec.plan import instance_name
from holomj.spec.scene import SceneObject, SceneSpec

# Edit relation kinds -> layout constraint kinds (several: all of them).
CONSTRAINTS: dict[str, tuple[str, ...]] = {
    "corner": ("corner",),
    "wall": ("edge",),
    "middle": ("middle",),
    "under_window": ("under_window",),
    "by_window": ("by_window",),
    "by_door": ("by_door",),
    "facing_window": ("facing_window",),
    "facing_door": ("facing_door",),
    "adjacent_to": ("adjacent_to",),
    "near": ("near",),
    "in_front_of": ("in_front_of",),
    "behind": ("behind",),
    "facing": ("face_to",),
    "across_from": ("face_to",),
    "around": ("adjacent_to", "face_to"),
}
CEILING_GAP_M = 0.05
CEILING_STEP_M = 0.1
MOVE_SEARCH_M = 1.0  # a replaced object that does not fit in place goes this far at most


# --------------------------------------------------------------------------- what things are


def kind_of(obj: SceneObject, library: AssetLibrary) -> str:
    """``floor``, ``wall``, ``ceiling`` or ``object`` (a small object on a receptacle)."""
    if obj.support is not None:
        return "object"
    if obj.position[2] < FLOOR_Z_M:
        return "floor"
    meta = library.get(obj.asset).meta if obj.asset in library else None
    placement = meta.placement if meta is not None else []
    if "ceiling" in placement and "wall" not in placement:
        return "ceiling"
    if "wall" in placement:
        return "wall"
    return "ceiling" if "ceiling" in placement else "wall"


def category_of(obj: SceneObject, library: AssetLibrary) -> str:
    """The library category of an object's asset."""
    return library.get(obj.asset).meta.category if obj.asset in library else obj.asset


def room_of(scene: SceneSpec, obj: SceneObject) -> str:
    """The room an object is in (its ``room``, else where it stands)."""
    if obj.room is not None:
        return obj.room
    found = room_at(scene, obj.position[0], obj.position[1])
    if found is None:
        raise Refused(f"{obj.id} is in no room")
    return found


def _room_id(scene: SceneSpec, room: str | None) -> str | None:
    if room is None:
        return None
    if room not in {r.id for r in scene.rooms}:
        from holomj.errors import closest_names

        near = closest_names(room, [r.id for r in scene.rooms])
        raise Refused(f"unknown room {room!r}" + (f"; did you mean {near}?" if near else ""))
    return room


def _target_room(scene: SceneSpec, relations: Sequence[EditRelation]) -> str | None:
    for rel in relations:
        if rel.target is not None:
            return room_of(scene, find(scene, rel.target))
    return None


def _pick_room(
    scene: SceneSpec,
    room: str | None,
    relations: Sequence[EditRelation],
    position: Sequence[float] | None,
) -> str:
    """The room an added object goes to (see :class:`holomj.spec.edit.AddOp`)."""
    chosen = _room_id(scene, room) or _target_room(scene, relations)
    if chosen is None and position is not None:
        chosen = room_at(scene, position[0], position[1])
        if chosen is None:
            raise Refused(f"position ({position[0]:g}, {position[1]:g}) is outside every room")
    if chosen is None:
        if len(scene.rooms) != 1:
            rooms = ", ".join(r.id for r in scene.rooms)
            raise Refused(f"say which room: the scene has {len(scene.rooms)} ({rooms})")
        chosen = scene.rooms[0].id
    return chosen


# --------------------------------------------------------------------------- wishes


def wishes_of(
    scene: SceneSpec, room_id: str, relations: Sequence[EditRelation], floor_ids: set[str]
) -> list[Wish]:
    """Layout wishes of explicit relations (targets: object ids of the room)."""
    out = []
    for rel in relations:
        if rel.kind == "above":
            continue
        if rel.target is not None:
            target = find(scene, rel.target)
            if room_of(scene, target) != room_id:
                raise Refused(f"{rel.target} is not in room {room_id!r}")
            if rel.target not in floor_ids:
                raise Refused(f"{rel.target} is not an object the layout can relate to")
        for kind in CONSTRAINTS[rel.kind]:
            source = f"{rel.kind} {rel.target or ''}".strip()
            out.append(Wish(kind, rel.target, RELATION_WEIGHT, source))
    return out


def _match(
    scene: SceneSpec, room_id: str, name: str, library: AssetLibrary, floor_ids: set[str]
) -> str | None:
    """The object of the room a plan name means: one of the kind's category, else one whose id
    names it."""
    kb = knowledge_base()
    category = kb.objects[name].category if name in kb.objects else name.replace(" ", "_")
    stem = name.replace(" ", "_")
    candidates = [o for o in scene.objects if o.id in floor_ids and in_room(scene, o, room_id)]
    for obj in candidates:
        if category_of(obj, library) == category:
            return obj.id
    for obj in candidates:
        if stem in obj.id.rsplit(".", 1)[-1]:
            return obj.id
    return None


def described_wishes(
    scene: SceneSpec,
    room_id: str,
    asked: Described,
    library: AssetLibrary,
    floor_ids: set[str],
    notes: list[str],
) -> tuple[list[Wish], str | None]:
    """Wishes from the relations the description's words gave (targets matched to the room's
    objects), and the target of an ``above``; relations that name nothing here are noted."""
    out: list[Wish] = []
    above = None
    for kind, target in asked.relations:
        if kind in ("on", "ceiling"):
            continue
        target_id = None
        if target is not None:
            target_id = _match(scene, room_id, target, library, floor_ids)
            if target_id is None:
                notes.append(f"'{kind} {target}': no {target} in {room_id}; not used")
                continue
        if kind == "above":
            above = target_id
            continue
        if kind not in CONSTRAINTS:
            notes.append(f"'{kind}' cannot be used for one object; not used")
            continue
        source = f"{kind} {target or ''}".strip()
        out.extend(Wish(k, target_id, RELATION_WEIGHT, source) for k in CONSTRAINTS[kind])
    return out, above


def default_wishes(
    scene: SceneSpec, room_id: str, name: str, library: AssetLibrary, floor_ids: set[str]
) -> list[Wish]:
    """The kind's default layout lines (``armchair | near, coffee table | face to, coffee
    table``) with weight 1, over the room's objects; floor objects without any stand against a
    wall."""
    kb = knowledge_base()
    lines = kb.objects[name].constraints if name in kb.objects else [f"{name} | edge"]
    out: list[Wish] = []
    for line in lines:
        for part in line.split("|")[1:]:
            phrase, _, target = (s.strip() for s in part.partition(","))
            kinds = PHRASES.get(normalize_phrase(phrase), ())
            target_id = None
            if target:
                target_id = _match(scene, room_id, target.rsplit("-", 1)[0], library, floor_ids)
                if target_id is None:
                    continue
            out.extend(Wish(k, target_id, 1.0, f"default: {part.strip()}") for k in kinds)
    return out or [Wish("edge", None, 1.0, "default: against a wall")]


# --------------------------------------------------------------------------- retrieval


def retrieve(
    ctx: EditContext,
    asked: Described,
    *,
    attributes: Sequence[str],
    category: str | None,
    size: tuple[float, float, float] | None,
    placement: str,
    key: tuple[object, ...],
) -> tuple[str, dict[str, Any]]:
    """One asset for the described object: its id and the pick's record."""
    text = " ".join([asked.description, *attributes])
    try:
        pick = ctx.retriever.choose(
            text,
            quantity=1,
            variance="same",
            rng=ctx.rng(*key),
            size=size,
            placement=placement,
            category=category,
        )[0]
    except HolomjError as err:
        raise Refused(f"no asset for {asked.description!r}: {err.one_line()}") from None
    record: dict[str, Any] = {"asset": pick.asset_id, "query": text}
    for name in ("category", "score", "how", "proxy", "attributes_asked", "attributes_honoured"):
        value = getattr(pick, name, None)
        if value is not None:
            record[name] = round(value, 4) if isinstance(value, float) else value
    return pick.asset_id, record


def new_id(scene: SceneSpec, room_id: str, name: str, wanted: str | None) -> str:
    """``wanted`` when free (refused when taken), else ``<room>.<name>_<n>`` with the first
    free ``n``."""
    taken = {o.id for o in scene.objects}
    if wanted is not None:
        if wanted in taken:
            raise Refused(f"id {wanted!r} is taken")
        return wanted
    n = 0
    while object_id(room_id, instance_name(name, n)) in taken:
        n += 1
    return object_id(room_id, instance_name(name, n))


def _floor_ids(scene: SceneSpec, library: AssetLibrary) -> set[str]:
    return {o.id for o in scene.objects if o.support is None}


# --------------------------------------------------------------------------- add


def add(scene: SceneSpec, op: AddOp, ctx: EditContext, index: int) -> Change:
    """``add``: see :class:`holomj.spec.edit.AddOp`."""
    room_id = _pick_room(scene, op.room, op.relations, op.position)
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
    floor_ids = _floor_ids(scene, library)
    notes = list(asked.notes)
    wishes = wishes_of(scene, room_id, op.relations, floor_ids)
    more, above = described_wishes(scene, room_id, asked, library, floor_ids, notes)
    wishes += more
    above = next((r.target for r in op.relations if r.kind == "above"), above)
    oid = new_id(scene, room_id, asked.name, op.id)
    asset_id, pick = retrieve(
        ctx,
        asked,
        attributes=op.attributes,
        category=op.category or asked.category,
        size=size,
        placement=placement,
        key=("add", index),
    )
    library = ctx.library
    meta = library.get(asset_id).meta
    check_size(meta.size, f"asset {asset_id}")
    details: dict[str, Any] = {"room": room_id, "name": asked.name, "placement": placement, **pick}
    if placement == "floor":
        if not wishes and op.position is None:
            wishes = default_wishes(scene, room_id, asked.name, library, floor_ids)
        obj, verdicts = _place_floor(scene, oid, asset_id, room_id, op, wishes, ctx)
        details["relations"] = verdicts
    elif placement == "wall":
        obj = _hang_on_wall(scene, oid, asset_id, room_id, above, library, ctx, index)
    else:
        obj = _hang_from_ceiling(scene, oid, asset_id, room_id, op.position, above, library)
    if meta.proxy:
        obj = obj.model_copy(update={"proxy": True})
    return Change(
        with_objects(scene, [*scene.objects, obj]), added=[oid], notes=notes, details=details
    )


def _place_floor(
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


def _hang_on_wall(
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


def _hang_from_ceiling(
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
        wishes = wishes_of(scene, room_id, op.relations, _floor_ids(scene, library) - {op.id})
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
    asset_id, pick = retrieve(
        ctx,
        asked,
        attributes=op.attributes,
        category=op.category or asked.category,
        size=size,
        placement=kind,
        key=("replace", index),
    )
    library = ctx.library
    meta = library.get(asset_id).meta
    check_size(meta.size, f"asset {asset_id}")
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
