"""Tasks named in words ("open the fridge, then put the mug in the sink") read against a scene.

The text is split into clauses at commas, semicolons, "then" and "and"; each clause is one of

- ``open|close [the] THING``: the first part with a handle of the first object whose category
  names THING (a close task starts with the part open);
- ``put|place|move [the] THING on|in|onto|into [the] PLACE``: a pick-and-place task, THING
  graspable, PLACE an object with receptacle surfaces;
- ``go to|navigate to [the] THING``: a navigation task to a room (by id or type) or an object.

THING matches an object whose category equals it (spaces as underscores) or has it as one of its
words ("sink" finds ``sink_counter``); objects in the robot's room come first. A clause that
names nothing the scene has, or asks something infeasible (opening what has no handle, picking
up a counter), is an InputError saying which clause and why.
"""

from __future__ import annotations

import re
from typing import Any

from holomj.errors import InputError
from holomj.spec import tasks as spec
from holomj.tasks.propose import CLOSE_START, CLOSED_FRACTION, OPEN_FRACTION, graspable

_SPLIT = re.compile(r"\s*(?:[,;.]|\bthen\b|\band\b)\s*", re.IGNORECASE)
_ARTICLES = re.compile(r"\b(?:the|a|an|some)\b\s*", re.IGNORECASE)
_PLACE = re.compile(r"^(?:put|place|move)\s+(.+?)\s+(?:on|in|onto|into|inside)\s+(.+)$")
_GO = re.compile(r"^(?:go|navigate|drive|walk)\s+(?:to\s+)?(.+)$")
_OPEN = re.compile(r"^(open|close|shut)\s+(.+)$")


def tasks_from_words(text: str, objects: dict[str, Any]) -> spec.TaskSet:
    """The tasks ``text`` names, on the scene of ``objects`` (its ``objects.json``)."""
    clauses = [c.strip() for c in _SPLIT.split(text) if c and c.strip()]
    if not clauses:
        raise InputError("no task in the words", fix='write e.g. "open the fridge"')
    found: list[spec.Task] = []
    for number, clause in enumerate(clauses):
        found.append(_task(clause, number, objects))
    return spec.TaskSet(scene=str(objects.get("scene", "")), tasks=found)


def _task(clause: str, number: int, objects: dict[str, Any]) -> spec.Task:
    words = _ARTICLES.sub("", clause.lower()).strip()
    if match := _PLACE.match(words):
        item, place = _find(match[1], objects, clause), _find(match[2], objects, clause)
        if not graspable(item):
            raise _refuse(clause, f"the {match[1]} is too big, too heavy or fixed to pick up")
        if not place.get("surfaces"):
            raise _refuse(clause, f"the {match[2]} has no surface to put things on")
        largest = max(place["surfaces"], key=lambda s: s["area_m2"])
        goal = spec.PlaceGoal(object=item["id"], receptacle=place["id"], surface=largest["index"])
        return spec.PickPlaceTask(id=f"task-{number}", description=clause, goal=goal)
    if match := _OPEN.match(words):
        thing = _find(match[2], objects, clause)
        joints = [j for j in thing.get("joints", []) if j.get("handle") is not None]
        if not joints:
            raise _refuse(clause, f"the {match[2]} has no door, drawer or lid with a handle")
        opening = match[1] == "open"
        return spec.ArticulationTask(
            kind="open" if opening else "close",
            id=f"task-{number}",
            description=clause,
            object=thing["id"],
            joint=joints[0]["name"],
            fraction=OPEN_FRACTION if opening else CLOSED_FRACTION,
            start=None if opening else CLOSE_START,
        )
    if match := _GO.match(words):
        if objects.get("robot") is None:
            raise _refuse(clause, "the scene has no robot")
        room = _room(match[1], objects)
        if room is not None:
            return spec.NavigateTask(id=f"task-{number}", description=clause, room=room)
        target = _find(match[1], objects, clause)
        return spec.NavigateTask(id=f"task-{number}", description=clause, object=target["id"])
    raise _refuse(clause, "not a task holomj knows", "start it with open, close, put or go to")


def _find(name: str, objects: dict[str, Any], clause: str) -> dict[str, Any]:
    """The object ``name`` names (see the module docstring)."""
    key = "_".join(name.split())
    robot_room = (objects.get("robot") or {}).get("room")
    records = sorted(objects.get("objects", []), key=lambda o: o.get("room") != robot_room)
    for exact in (True, False):
        for obj in records:
            category = (obj.get("category") or "").lower()
            if obj["id"].lower() == key or category == key:
                return obj
            if not exact and key in category.split("_"):
                return obj
    known = sorted({o.get("category") or o["id"] for o in records})
    raise _refuse(clause, f"the scene has no {name}", f"name one of: {', '.join(known)}")


def _room(name: str, objects: dict[str, Any]) -> str | None:
    key = "_".join(name.split())
    for room in objects.get("rooms", []):
        if key in (room["id"].lower(), str(room.get("type", "")).lower()):
            return str(room["id"])
    return None


def _refuse(clause: str, why: str, fix: str = "ask for something the scene allows") -> InputError:
    return InputError(why, where=f"task {clause!r}", fix=fix)
