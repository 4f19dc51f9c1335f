"""Feasible tasks proposed from a scene's ``objects.json`` and ``navmap.json`` records.

- open / close: every articulated part with a handle between :data:`HANDLE_HEIGHT_M` (each
  object's first part first); a close task starts with the part open (``start``);
- pick-and-place: free objects standing in the open (not inside closed storage), no heavier
  than :data:`GRASP_MASS_KG` and no larger than :data:`GRASP_SIZE_M`, each to another
  receptacle surface in its room whose free area (surface area less the footprints of the
  objects resting on it) holds it with room to spare;
- rearrange: two pick-and-place goals with distinct objects and receptacles;
- navigate: every room the navigation map marks reachable but the robot's own, and every piece
  of furniture with a surface in a reachable room farther than :data:`NAVIGATE_RADIUS_M` from
  the robot (the base within that radius of it, facing it).

Kinds are taken in turn so a small ``limit`` still gets a mix; the choice is deterministic.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from typing import Any, Literal

from holomj.spec import tasks as spec

HANDLE_HEIGHT_M = (0.05, 1.9)
GRASP_MASS_KG = 2.0
GRASP_SIZE_M = 0.3
ON_TOP_TOL_M = 0.03
FREE_AREA_FACTOR = 2.0  # a receptacle needs this many times the object's footprint free
OPEN_FRACTION = 0.5
CLOSED_FRACTION = 0.05
CLOSE_START = 0.8
NAVIGATE_RADIUS_M = 1.0
# (kind, fraction, start) of the two tasks proposed for a part
_OPEN_CLOSE: tuple[tuple[Literal["open", "close"], float, float | None], ...] = (
    ("open", OPEN_FRACTION, None),
    ("close", CLOSED_FRACTION, CLOSE_START),
)


def propose_tasks(
    objects: dict[str, Any], navmap: dict[str, Any] | None, limit: int
) -> spec.TaskSet:
    """At most ``limit`` feasible tasks for the scene of ``objects`` (its ``objects.json``)
    and ``navmap`` (its ``navmap.json``; None: no navigation tasks)."""
    kinds = [
        list(_articulation_tasks(objects)),
        list(_place_tasks(objects)),
        list(_navigate_tasks(objects, navmap)),
    ]
    places = [t for t in kinds[1] if isinstance(t, spec.PickPlaceTask)]
    kinds.append(list(_rearrange_tasks(places)))
    chosen: list[spec.Task] = []
    while len(chosen) < limit and any(kinds):
        for tasks in kinds:
            if tasks and len(chosen) < limit:
                chosen.append(tasks.pop(0))
    return spec.TaskSet(scene=str(objects.get("scene", "")), tasks=chosen)


def _articulation_tasks(objects: dict[str, Any]) -> Iterator[spec.Task]:
    low, high = HANDLE_HEIGHT_M
    handled = [
        (obj, [j for j in obj.get("joints", []) if _handle_between(j, low, high)])
        for obj in objects.get("objects", [])
    ]
    depth = max((len(joints) for _, joints in handled), default=0)
    for index in range(depth):  # every object's first part, then every second one, ...
        for obj, joints in handled:
            if index >= len(joints):
                continue
            joint = joints[index]
            what = f"the {joint['part']} of the {obj['category'] or obj['id']}"
            for kind, fraction, start in _OPEN_CLOSE:
                yield spec.ArticulationTask(
                    kind=kind,
                    id=f"{kind}-{_slug(joint['name'])}",
                    description=f"{kind} {what}",
                    object=obj["id"],
                    joint=joint["name"],
                    fraction=fraction,
                    start=start,
                )


def _handle_between(joint: dict[str, Any], low: float, high: float) -> bool:
    handle = joint.get("handle")
    return handle is not None and low <= handle["position"][2] <= high


def graspable(obj: dict[str, Any]) -> bool:
    """Whether an object is free, light and small enough for a hand to pick up."""
    if obj.get("static") or obj.get("joints") or obj.get("proxy"):
        return False
    low, high = obj["aabb"]["min"], obj["aabb"]["max"]
    size = max(high[i] - low[i] for i in range(3))
    return bool(obj["mass_kg"] <= GRASP_MASS_KG and size <= GRASP_SIZE_M)


def on_top(objects: dict[str, Any], obj: dict[str, Any]) -> bool:
    """Whether an object stands on the floor or on a top surface of its support (not inside a
    closed cabinet or fridge, where a hand would first have to open a door)."""
    support = {o["id"]: o for o in objects.get("objects", [])}.get(obj.get("support") or "")
    if support is None:
        return True
    bottom = obj["aabb"]["min"][2]
    return any(abs(bottom - s["height"]) <= ON_TOP_TOL_M for s in support.get("surfaces", []))


def free_area(objects: dict[str, Any], receptacle: dict[str, Any]) -> float:
    """A receptacle's surface area less the footprints of the objects resting on it."""
    used = sum(
        _footprint(o) for o in objects.get("objects", []) if o.get("support") == receptacle["id"]
    )
    return float(sum(s["area_m2"] for s in receptacle.get("surfaces", []))) - used


def _place_tasks(objects: dict[str, Any]) -> Iterator[spec.Task]:
    records = objects.get("objects", [])
    receptacles = [o for o in records if o.get("surfaces")]
    for item in (o for o in records if graspable(o) and on_top(objects, o)):
        need = FREE_AREA_FACTOR * _footprint(item)
        for receptacle in receptacles:
            if receptacle["id"] in (item["id"], item.get("support")):
                continue
            if receptacle["room"] != item["room"] or free_area(objects, receptacle) < need:
                continue
            largest = max(receptacle["surfaces"], key=lambda s: s["area_m2"])
            yield spec.PickPlaceTask(
                id=f"place-{_slug(item['id'])}-on-{_slug(receptacle['id'])}",
                description=(
                    f"put the {item['category'] or item['id']} on the "
                    f"{receptacle['category'] or receptacle['id']}"
                ),
                goal=spec.PlaceGoal(
                    object=item["id"], receptacle=receptacle["id"], surface=largest["index"]
                ),
            )
            break


def _rearrange_tasks(places: list[spec.PickPlaceTask]) -> Iterator[spec.Task]:
    for first, second in zip(places, places[1:], strict=False):
        a, b = first.goal, second.goal
        if a.object == b.object:
            continue
        yield spec.RearrangeTask(
            id=f"rearrange-{_slug(a.object)}-{_slug(b.object)}",
            description=f"{first.description}, and {second.description}",
            goals=[a, b],
        )


def _navigate_tasks(objects: dict[str, Any], navmap: dict[str, Any] | None) -> Iterator[spec.Task]:
    if navmap is None or objects.get("robot") is None:
        return
    rooms = navmap.get("rooms", {})
    robot = objects["robot"]
    for room in objects.get("rooms", []):
        if room["id"] != robot.get("room") and _reachable(rooms, room["id"]):
            yield spec.NavigateTask(
                id=f"go-to-{_slug(room['id'])}",
                description=f"go to the {room['type']}",
                room=room["id"],
            )
    for obj in objects.get("objects", []):
        far = math.dist(obj["position"][:2], robot["position"][:2]) > NAVIGATE_RADIUS_M
        if far and obj.get("surfaces") and not graspable(obj) and _reachable(rooms, obj["room"]):
            yield spec.NavigateTask(
                id=f"go-to-{_slug(obj['id'])}",
                description=f"go to the {obj['category'] or obj['id']}",
                object=obj["id"],
                radius_m=NAVIGATE_RADIUS_M,
            )


def _reachable(rooms: dict[str, Any], room: str) -> bool:
    return bool(rooms.get(room, {}).get("reachable"))


def _footprint(obj: dict[str, Any]) -> float:
    low, high = obj["aabb"]["min"], obj["aabb"]["max"]
    return float((high[0] - low[0]) * (high[1] - low[1]))


def _slug(name: str) -> str:
    return "".join(c if c.isalnum() or c in "_.-" else "-" for c in name)
