"""Lookups into an ``objects.json`` record (:mod:`holomj.formats.objects_json`) for task checks.

Unknown ids give an :class:`~holomj.errors.InputError` that lists what the scene has, so a task
written against the wrong scene is refused with the reason rather than judged false forever.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import mujoco
import numpy as np

from holomj.errors import InputError


class SceneObjects:
    """An ``objects.json`` record with lookups by object id and joint name."""

    def __init__(self, record: dict[str, Any]) -> None:
        self.record = record
        self.objects: dict[str, dict[str, Any]] = {o["id"]: o for o in record.get("objects", [])}
        self.rooms: dict[str, dict[str, Any]] = {r["id"]: r for r in record.get("rooms", [])}
        self.robot: dict[str, Any] | None = record.get("robot")

    def object(self, object_id: str) -> dict[str, Any]:
        """The record of object ``object_id``."""
        try:
            return self.objects[object_id]
        except KeyError:
            raise InputError(
                f"the scene has no object {object_id!r}",
                fix=f"use one of: {_listing(self.objects)}",
            ) from None

    def joint(self, object_id: str, joint: str) -> dict[str, Any]:
        """The joint record ``joint`` of articulated object ``object_id``."""
        joints = {j["name"]: j for j in self.object(object_id).get("joints", [])}
        try:
            return joints[joint]
        except KeyError:
            raise InputError(
                f"object {object_id!r} has no joint {joint!r}",
                fix=f"use one of: {_listing(joints) or '(none: it is not articulated)'}",
            ) from None

    def room(self, room_id: str) -> dict[str, Any]:
        """The record of room ``room_id``."""
        try:
            return self.rooms[room_id]
        except KeyError:
            raise InputError(
                f"the scene has no room {room_id!r}", fix=f"use one of: {_listing(self.rooms)}"
            ) from None

    def robot_base(self) -> str:
        """The body name of the robot's base."""
        if self.robot is None:
            raise InputError(
                "the scene has no robot", fix="attach one with 'holomj add-robot OUT panda|jaco'"
            )
        return str(self.robot["base_body"])


def _listing(names: Any, most: int = 12) -> str:
    ordered = sorted(names)
    more = f", ... ({len(ordered) - most} more)" if len(ordered) > most else ""
    return ", ".join(ordered[:most]) + more


def subtree(model: mujoco.MjModel, root: int) -> set[int]:
    """Body ``root`` and every body below it."""
    bodies = {root}
    for body in range(root + 1, model.nbody):
        if int(model.body_parentid[body]) in bodies:
            bodies.add(body)
    return bodies


def body_id(model: mujoco.MjModel, name: str) -> int:
    """The id of body ``name``; a FormatError-free InputError when the model lacks it."""
    body = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, name)
    if body < 0:
        raise InputError(
            f"the model has no body {name!r}", fix="check that objects.json is the scene's own"
        )
    return int(body)


def inside_polygon(x: float, y: float, polygon: Sequence[Sequence[float]]) -> bool:
    """Whether point (x, y) lies inside ``polygon`` (a list of [x, y], even-odd rule)."""
    inside = False
    count = len(polygon)
    for i in range(count):
        x1, y1 = polygon[i][0], polygon[i][1]
        x2, y2 = polygon[(i + 1) % count][0], polygon[(i + 1) % count][1]
        if (y1 > y) != (y2 > y) and x < x1 + (y - y1) * (x2 - x1) / (y2 - y1):
            inside = not inside
    return inside


def polygon_distance(x: float, y: float, polygon: Sequence[Sequence[float]]) -> float:
    """Distance from (x, y) to ``polygon`` (0 inside)."""
    if inside_polygon(x, y, polygon):
        return 0.0
    point = np.array([x, y])
    best = np.inf
    for i in range(len(polygon)):
        a = np.asarray(polygon[i][:2], dtype=float)
        b = np.asarray(polygon[(i + 1) % len(polygon)][:2], dtype=float)
        ab = b - a
        t = float(np.clip(np.dot(point - a, ab) / max(float(np.dot(ab, ab)), 1e-12), 0.0, 1.0))
        best = min(best, float(np.linalg.norm(point - (a + t * ab))))
    return float(best)
