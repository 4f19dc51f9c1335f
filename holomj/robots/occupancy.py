"""A floor occupancy grid of a compiled scene: rooms, obstacles, door swing zones.

Every cell of a regular grid over the rooms is labelled with the room its centre lies in (or
none), and marked *blocked* when any collision geom that reaches into the height band
``z_band`` touches the cell's square: walls, door frames, furniture, props, a robot. A geom is
rasterised through the convex hull of its outline (see :mod:`holomj.robots.shapes`) grown by the
cell's half-width, so thin geoms still block the cells they cross. Door leaves are kept apart:
``leaves`` marks the closed leaves and ``swing`` every cell a leaf sweeps through its hinge range,
so navigation can walk through doors while a robot is never placed where a door would hit it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import mujoco
import numpy as np
import shapely
from scipy import ndimage

from holomj.mjcf import names
from holomj.robots import shapes
from holomj.spec.scene import SceneSpec
from holomj.spec.walls import room_polygon

DEFAULT_CELL_M = 0.05
DEFAULT_Z_BAND = (0.02, 2.0)
_SWING_STEP_RAD = math.radians(5.0)
_MARGIN_M = 0.5


@dataclass
class FloorGrid:
    """Rasters of shape ``(ny, nx)``; row ``r`` and column ``c`` cover the square with lower-left
    corner ``origin + (c, r) * cell``."""

    origin: tuple[float, float]
    cell: float
    room_ids: list[str]
    room_index: np.ndarray  # int16, -1 outside every room
    blocked: np.ndarray  # bool: obstacles other than door leaves
    leaves: np.ndarray  # bool: closed door leaves
    swing: np.ndarray  # bool: swept by door leaves over their hinge ranges

    @property
    def shape(self) -> tuple[int, int]:
        """(rows, columns)."""
        return self.room_index.shape

    @property
    def inside(self) -> np.ndarray:
        """Cells whose centre lies in a room."""
        return self.room_index >= 0

    def centres(self) -> tuple[np.ndarray, np.ndarray]:
        """World x and y of every cell centre, each of shape ``(ny, nx)``."""
        ny, nx = self.shape
        xs = self.origin[0] + (np.arange(nx) + 0.5) * self.cell
        ys = self.origin[1] + (np.arange(ny) + 0.5) * self.cell
        return np.meshgrid(xs, ys)

    def cell_of(self, x: float, y: float) -> tuple[int, int]:
        """(row, column) of the cell holding world point (x, y), clipped to the grid."""
        ny, nx = self.shape
        col = int(np.clip(math.floor((x - self.origin[0]) / self.cell), 0, nx - 1))
        row = int(np.clip(math.floor((y - self.origin[1]) / self.cell), 0, ny - 1))
        return row, col

    def clearance(self, obstacles: np.ndarray) -> np.ndarray:
        """Metres from each cell to the nearest cell of ``obstacles`` or outside the rooms,
        minus half a cell (an obstacle may lie anywhere in its cell); negative on them."""
        solid = obstacles | ~self.inside
        if not solid.any():
            return np.full(self.shape, np.inf)
        distance = ndimage.distance_transform_edt(~solid) * self.cell
        return np.where(solid, -self.cell / 2, distance - self.cell / 2)


def build_floor_grid(
    model: mujoco.MjModel,
    scene: SceneSpec,
    *,
    cell: float = DEFAULT_CELL_M,
    z_band: tuple[float, float] = DEFAULT_Z_BAND,
    skip_bodies: set[int] | None = None,
) -> FloorGrid:
    """Rasterise the floor of ``scene`` and the colliders of ``model`` at its initial pose.

    ``skip_bodies``: bodies whose geoms (and their descendants') are left out.
    """
    polygons = [room_polygon(room.polygon) for room in scene.rooms]
    xs = [p for poly in polygons for p in poly.bounds[::2]]
    ys = [p for poly in polygons for p in poly.bounds[1::2]]
    origin = (
        math.floor((min(xs) - _MARGIN_M) / cell) * cell,
        math.floor((min(ys) - _MARGIN_M) / cell) * cell,
    )
    nx = math.ceil((max(xs) + _MARGIN_M - origin[0]) / cell)
    ny = math.ceil((max(ys) + _MARGIN_M - origin[1]) / cell)
    empty = np.zeros((ny, nx), dtype=bool)
    grid = FloorGrid(
        origin=(round(origin[0], 9), round(origin[1], 9)),
        cell=cell,
        room_ids=[room.id for room in scene.rooms],
        room_index=np.full((ny, nx), -1, dtype=np.int16),
        blocked=empty.copy(),
        leaves=empty.copy(),
        swing=empty.copy(),
    )
    cx, cy = grid.centres()
    for index, poly in enumerate(polygons):
        grid.room_index[shapely.contains_xy(poly, cx, cy)] = index
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    leaf_bodies = door_leaf_bodies(model, scene)
    skipped = _subtrees(model, set(skip_bodies or ()))
    for geom in shapes.collider_ids(model):
        body = int(model.geom_bodyid[geom])
        if body in skipped:
            continue
        points = shapes.world_points(model, data, geom)
        if points[:, 2].max() <= z_band[0] or points[:, 2].min() >= z_band[1]:
            continue
        target = grid.leaves if body in leaf_bodies else grid.blocked
        _mark_hull(grid, target, points[:, :2])
        if body in leaf_bodies:
            _mark_swing(grid, model, data, body, points[:, :2])
    return grid


def door_leaf_bodies(model: mujoco.MjModel, scene: SceneSpec) -> set[int]:
    """Body ids of the hinged door leaves of ``scene`` in ``model``."""
    found = set()
    for door in scene.doors:
        for index in range(2):
            try:
                found.add(int(model.body(names.door_leaf_body(door.id, index)).id))
            except KeyError:
                break
    return found


def _subtrees(model: mujoco.MjModel, roots: set[int]) -> set[int]:
    if not roots:
        return set()
    inside = set(roots)
    for body in range(1, model.nbody):  # parents come before children
        if int(model.body_parentid[body]) in inside:
            inside.add(body)
    return inside


def _mark_hull(grid: FloorGrid, target: np.ndarray, points: np.ndarray) -> None:
    """Mark every cell whose square meets the convex hull of ``points`` (x, y)."""
    half = grid.cell / 2
    grown = np.vstack([points + [dx, dy] for dx in (-half, half) for dy in (-half, half)])
    hull = shapely.MultiPoint(grown).convex_hull
    x0, y0, x1, y1 = hull.bounds
    ny, nx = grid.shape
    c0 = max(0, math.floor((x0 - grid.origin[0]) / grid.cell))
    c1 = min(nx, math.ceil((x1 - grid.origin[0]) / grid.cell) + 1)
    r0 = max(0, math.floor((y0 - grid.origin[1]) / grid.cell))
    r1 = min(ny, math.ceil((y1 - grid.origin[1]) / grid.cell) + 1)
    if c0 >= c1 or r0 >= r1:
        return
    xs = grid.origin[0] + (np.arange(c0, c1) + 0.5) * grid.cell
    ys = grid.origin[1] + (np.arange(r0, r1) + 0.5) * grid.cell
    gx, gy = np.meshgrid(xs, ys)
    target[r0:r1, c0:c1] |= shapely.intersects_xy(hull, gx, gy)


def _mark_swing(
    grid: FloorGrid, model: mujoco.MjModel, data: mujoco.MjData, body: int, points: np.ndarray
) -> None:
    """Mark the cells a door leaf sweeps over its hinge's range (about the hinge anchor)."""
    joint = int(model.body_jntadr[body])
    if joint < 0 or model.body_jntnum[body] != 1:
        return
    axis = data.xaxis[joint]
    if abs(axis[2]) < 0.99:
        return
    anchor = data.xanchor[joint][:2]
    lo, hi = model.jnt_range[joint] if model.jnt_limited[joint] else (-math.pi, math.pi)
    current = float(data.qpos[model.jnt_qposadr[joint]] - model.qpos0[model.jnt_qposadr[joint]])
    steps = max(2, math.ceil((hi - lo) / _SWING_STEP_RAD) + 1)
    sign = 1.0 if axis[2] > 0 else -1.0
    for angle in np.linspace(lo, hi, steps):
        turn = sign * (angle - current)
        c, s = math.cos(turn), math.sin(turn)
        rotated = (points - anchor) @ np.array([[c, s], [-s, c]]) + anchor
        _mark_hull(grid, grid.swing, rotated)
