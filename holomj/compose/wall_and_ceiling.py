"""Everything of a room that is not on its floor: wall objects hung (over the floor object they
belong to, facing the one that looks at them), a TV that found no wall stood on a top instead,
and ceiling objects hung over their floor object or along the room's long axis. Wall and
ceiling objects are static."""

from __future__ import annotations

from collections.abc import Sequence

from shapely.geometry import Polygon

from holomj.compose.room_context import RoomContext, RoomFurniture
from holomj.layout.furniture_rules import WALL_KINDS, object_id
from holomj.layout.wall_objects import FloorItem, WallObjectRequest, place_wall_objects
from holomj.library.store import AssetLibrary
from holomj.seeds import stage_rng
from holomj.spec.plan import PlanObject, PlanRoom, PlanSmallObject, instance_name
from holomj.spec.scene import Room, SceneObject, Window


def paired(room_id: str, instance: str, target: str, counts: dict[str, int]) -> str:
    """The floor instance of ``target`` that wall or ceiling instance ``instance`` is hung for:
    mirror k for salon chair k, mobile k above crib k (beyond the targets' count, round again)."""
    index = int(instance.rsplit("-", 1)[1]) if instance.rsplit("-", 1)[-1].isdigit() else 0
    return object_id(room_id, instance_name(target, index % max(1, counts.get(target, 1))))


def hang_wall_objects(
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
                above=paired(room.id, instance, target, counts) if target else None,
                faced_by=paired(room.id, instance, looker, counts) if looker else None,
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


# a top a TV without its own stand stands on (a counter, a sideboard): its height, least area
TV_HOST_HEIGHTS_M = (0.4, 1.2)
TV_HOST_AREA_M2 = 0.25


def stand_unhung_tvs(
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


def hang_from_ceiling(
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
            target = paired(room.id, instance, obj.above, counts) if obj.above else None
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
