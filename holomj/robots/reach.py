"""Where an agent of a given radius can walk from the entrance, through the doors.

The entrance is the first exterior door of the scene (a door naming one room); a scene without
one is entered in its first room. Walkable cells are those with at least ``agent_radius`` of
clearance from obstacles and walls (door leaves do not count: doors open); reachable cells are
the walkable cells 4-connected to the cells just inside the entrance.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy import ndimage

from holomj.robots.occupancy import FloorGrid
from holomj.spec.scene import SceneSpec

DEFAULT_AGENT_RADIUS_M = 0.25
ENTRANCE_REACH_M = 0.6  # cells this far inside an exterior door (beyond its half-width) seed
_FOUR = ndimage.generate_binary_structure(2, 1)


@dataclass(frozen=True)
class Entrance:
    """Where walking starts: an exterior door (with its centre) or, lacking one, a room."""

    room: str
    door: str | None
    position: tuple[float, float] | None


@dataclass
class Reach:
    """Walkable and reachable cells of a grid for one agent radius."""

    grid: FloorGrid
    agent_radius: float
    entrance: Entrance
    walkable: np.ndarray  # bool (ny, nx)
    reachable: np.ndarray  # bool (ny, nx)

    def room_stats(self) -> dict[str, dict[str, float | bool]]:
        """Per room: floor, walkable and reachable area (m²) and whether it is reachable."""
        area = self.grid.cell**2
        stats: dict[str, dict[str, float | bool]] = {}
        for index, room in enumerate(self.grid.room_ids):
            inside = self.grid.room_index == index
            reach = int(np.count_nonzero(inside & self.reachable))
            stats[room] = {
                "reachable": reach > 0,
                "reachable_area_m2": round(reach * area, 4),
                "walkable_area_m2": round(int(np.count_nonzero(inside & self.walkable)) * area, 4),
                "floor_area_m2": round(int(np.count_nonzero(inside)) * area, 4),
            }
        return stats


def find_entrance(scene: SceneSpec) -> Entrance:
    """The first exterior door, else the first room."""
    for door in scene.doors:
        if len(door.rooms) == 1:
            return Entrance(door.rooms[0], door.id, (door.position[0], door.position[1]))
    return Entrance(scene.rooms[0].id, None, None)


def compute_reach(
    grid: FloorGrid, scene: SceneSpec, agent_radius: float = DEFAULT_AGENT_RADIUS_M
) -> Reach:
    """Walkable cells for ``agent_radius`` and those reachable from the entrance."""
    walkable = grid.inside & (grid.clearance(grid.blocked) >= agent_radius)
    entrance = find_entrance(scene)
    seeds = _seeds(grid, scene, entrance, walkable)
    labels, _ = ndimage.label(walkable, structure=_FOUR)
    hit = np.unique(labels[seeds & walkable])
    hit = hit[hit > 0]
    reachable = np.isin(labels, hit) if hit.size else np.zeros_like(walkable)
    return Reach(grid, agent_radius, entrance, walkable, reachable)


def _seeds(
    grid: FloorGrid, scene: SceneSpec, entrance: Entrance, walkable: np.ndarray
) -> np.ndarray:
    room = grid.room_ids.index(entrance.room)
    in_room = grid.room_index == room
    if entrance.position is None:
        labels, count = ndimage.label(walkable & in_room, structure=_FOUR)
        if count == 0:
            return np.zeros_like(walkable)
        sizes = np.bincount(labels.ravel())[1:]
        return labels == int(np.argmax(sizes)) + 1
    door = next(d for d in scene.doors if d.id == entrance.door)
    cx, cy = grid.centres()
    reach = door.effective_width / 2 + ENTRANCE_REACH_M
    near = np.hypot(cx - entrance.position[0], cy - entrance.position[1]) <= reach
    return near & in_room & walkable


def cells_in_disc(grid: FloorGrid, x: float, y: float, radius: float) -> np.ndarray:
    """Cells whose centre lies within ``radius`` of (x, y)."""
    cx, cy = grid.centres()
    return np.hypot(cx - x, cy - y) <= radius + 1e-9


def nearest_reachable(reach: Reach, x: float, y: float) -> float:
    """Distance from (x, y) to the nearest reachable cell centre (inf when there is none)."""
    if not reach.reachable.any():
        return math.inf
    cx, cy = reach.grid.centres()
    return float(np.min(np.hypot(cx[reach.reachable] - x, cy[reach.reachable] - y)))
