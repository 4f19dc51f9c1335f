"""Choose where a robot stands: a free floor spot reachable from the entrance, facing the room.

A cell is a candidate when a disc of the robot's footprint radius plus ``clearance`` around it
holds no obstacle, wall, door leaf or door swing zone, and an agent can walk there from the
entrance (see :mod:`holomj.robots.reach`). Candidates are scored for open space (clearance,
capped) and for being near their room's centre; the spot is drawn with ``rng`` among those
within ``SCORE_BAND`` of the best, so a seed picks one of several equally good spots. The robot
turns its reach direction (``Footprint.front_deg``) towards the furniture of its room, or the
room's centre when the room is empty.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from holomj.errors import InputError
from holomj.robots.occupancy import FloorGrid
from holomj.robots.reach import Reach
from holomj.spec.robot import Footprint
from holomj.spec.scene import SceneSpec
from holomj.spec.walls import room_polygon

DEFAULT_CLEARANCE_M = 0.1
SCORE_BAND = 0.05
OPEN_CAP_M = 0.6  # clearance beyond the robot's needs that still counts as "more open"
CENTRE_WEIGHT = 0.5
MIN_TARGET_DISTANCE_M = 0.3


@dataclass(frozen=True)
class Spot:
    """A robot base pose on the floor: position, yaw (degrees, about +Z) and room."""

    x: float
    y: float
    yaw_deg: float
    room: str
    clearance_m: float


def choose_spot(
    grid: FloorGrid,
    reach: Reach,
    scene: SceneSpec,
    footprint: Footprint,
    rng: np.random.Generator,
    *,
    clearance: float = DEFAULT_CLEARANCE_M,
    room: str | None = None,
) -> Spot:
    """A deterministic (for a given ``rng`` state) free, reachable spot for the robot.

    Raises :class:`~holomj.errors.InputError` when no spot is free.
    """
    needed = footprint.radius_m + clearance
    free = grid.clearance(grid.blocked | grid.leaves | grid.swing)
    candidates = (free >= needed) & reach.reachable
    if room is not None:
        if room not in grid.room_ids:
            raise InputError(
                f"unknown room {room!r}", where="robot room", fix=f"use {', '.join(grid.room_ids)}"
            )
        candidates &= grid.room_index == grid.room_ids.index(room)
    if not candidates.any():
        raise InputError(
            f"no free floor spot for the robot: it needs a disc of {needed:.2f} m radius "
            f"(footprint {footprint.radius_m:.2f} m + clearance {clearance:.2f} m) clear of "
            "furniture, walls and door swings, reachable from the entrance",
            where="--robot",
            fix="use a smaller robot, a roomier scene or less clearance",
        )
    rows, cols = np.nonzero(candidates)
    cx, cy = grid.centres()
    xs, ys = cx[rows, cols], cy[rows, cols]
    rooms = grid.room_index[rows, cols]
    score = np.minimum(free[rows, cols] - needed, OPEN_CAP_M) / OPEN_CAP_M
    centres = [room_polygon(r.polygon) for r in scene.rooms]
    for index in np.unique(rooms):
        poly = centres[int(index)]
        pick = rooms == index
        centre = poly.centroid
        spread = math.sqrt(poly.area)
        score[pick] -= CENTRE_WEIGHT * np.hypot(xs[pick] - centre.x, ys[pick] - centre.y) / spread
    best = np.flatnonzero(score >= score.max() - SCORE_BAND)
    choice = int(best[int(rng.integers(best.size))])
    x, y = float(xs[choice]), float(ys[choice])
    room_id = grid.room_ids[int(rooms[choice])]
    target = _facing_target(scene, room_id, x, y)
    yaw = 0.0
    if target is not None:
        yaw = math.degrees(math.atan2(target[1] - y, target[0] - x)) - footprint.front_deg
    yaw = (yaw + 180.0) % 360.0 - 180.0
    return Spot(
        x=round(x, 4),
        y=round(y, 4),
        yaw_deg=round(yaw, 2),
        room=room_id,
        clearance_m=round(float(free[rows[choice], cols[choice]]) - footprint.radius_m, 4),
    )


def _facing_target(
    scene: SceneSpec, room_id: str, x: float, y: float
) -> tuple[float, float] | None:
    """The centroid of the room's floor-standing objects, else the room's centre."""
    objects = [o for o in scene.objects if o.room == room_id and o.support is None]
    if objects:
        tx = sum(o.position[0] for o in objects) / len(objects)
        ty = sum(o.position[1] for o in objects) / len(objects)
        if math.hypot(tx - x, ty - y) >= MIN_TARGET_DISTANCE_M:
            return tx, ty
    centre = room_polygon(scene.room(room_id).polygon).centroid
    if math.hypot(centre.x - x, centre.y - y) >= MIN_TARGET_DISTANCE_M:
        return centre.x, centre.y
    return None
