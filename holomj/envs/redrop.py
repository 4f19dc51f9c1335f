"""Small objects moved a little at each reset, so episodes of one scene differ.

Every graspable object standing in the open (:func:`holomj.tasks.propose.graspable`,
:func:`holomj.tasks.propose.on_top`) on a surface of its support is shifted by up to
``radius_m`` in x and y and turned by a random yaw about its own centre, lifted by
:data:`LIFT_M` so that it drops back onto the surface in the first steps; a shift that would take
its centre off the surface (or onto another object's spot) is drawn again, up to
:data:`TRIES` times, else the object stays where the validated scene has it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import mujoco
import numpy as np

from holomj.tasks.propose import graspable, on_top
from holomj.tasks.scene_objects import inside_polygon

LIFT_M = 0.003
TRIES = 8
MIN_GAP_M = 0.08  # between the centres of two moved objects


@dataclass(frozen=True)
class Droppable:
    """A free object that can be moved on its support surface."""

    qpos_adr: int
    polygon: list[list[float]]


def droppable_objects(model: mujoco.MjModel, record: dict[str, Any]) -> list[Droppable]:
    """The objects of ``record`` (``objects.json``) a reset may move."""
    objects = {o["id"]: o for o in record.get("objects", [])}
    found = []
    for obj in objects.values():
        support = objects.get(obj.get("support") or "")
        if support is None or obj.get("joint") is None:
            continue
        if not (graspable(obj) and on_top(record, obj)):
            continue
        bottom = obj["aabb"]["min"][2]
        surface = min(support["surfaces"], key=lambda s: abs(s["height"] - bottom))
        joint = model.joint(obj["joint"]).id
        found.append(Droppable(int(model.jnt_qposadr[joint]), surface["polygon"]))
    return found


def redrop(
    data: mujoco.MjData, objects: list[Droppable], radius_m: float, rng: np.random.Generator
) -> None:
    """Move ``objects`` in ``data`` (at the validated scene's pose) as the module says."""
    placed: list[np.ndarray] = []
    for obj in objects:
        adr = obj.qpos_adr
        home = data.qpos[adr : adr + 2].copy()
        for _ in range(TRIES):
            spot = home + rng.uniform(-radius_m, radius_m, size=2)
            free = all(np.linalg.norm(spot - other) >= MIN_GAP_M for other in placed)
            if free and inside_polygon(float(spot[0]), float(spot[1]), obj.polygon):
                data.qpos[adr : adr + 2] = spot
                data.qpos[adr + 2] += LIFT_M
                data.qpos[adr + 3 : adr + 7] = _turned(data.qpos[adr + 3 : adr + 7], rng)
                break
        placed.append(data.qpos[adr : adr + 2].copy())


def _turned(quat: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """``quat`` turned by a random yaw about the world z axis."""
    half = rng.uniform(-math.pi, math.pi) / 2.0
    yaw = np.array([math.cos(half), 0.0, 0.0, math.sin(half)])
    out = np.zeros(4)
    mujoco.mju_mulQuat(out, yaw, np.asarray(quat, dtype=float))
    return out
