"""What a scene's objects are and where: an object's kind (floor, wall, ceiling, small), its
category and room, the room an added object goes to, and a free id for a new object."""

from __future__ import annotations

from collections.abc import Sequence

from holomj.edit.footprints import FLOOR_Z_M, room_at
from holomj.edit.state import (
    Refused,
    find,
)
from holomj.layout.furniture_rules import object_id
from holomj.library.store import AssetLibrary
from holomj.spec.edit import EditRelation
from holomj.spec.plan import instance_name
from holomj.spec.scene import SceneObject, SceneSpec


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


def pick_room(
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


def floor_ids(scene: SceneSpec, library: AssetLibrary) -> set[str]:
    return {o.id for o in scene.objects if o.support is None}
