"""Where a round robot can go: free floor, the share of it reachable from the entrance.

Free floor = room cells not blocked (navmap.json's obstacles; without a navmap, room polygons
minus walls and furniture footprints rasterised on a 5 cm grid). A robot of radius 0.2 m fits
where the nearest blocked cell is at least 0.2 m + half a cell away; ``share`` is the fitting
cells connected to the entrance (the door named by navmap.json, else a door with one room) over
all fitting cells, and ``coverage`` the free floor its body sweeps from there over all free
floor. Per room: the share of that room's fitting cells reached.

A pocket of fitting cells that lies wholly inside one floor object's footprint (the open inside
of a squat rack's frame, a playpen, a walk-in shower's tray) is that object's interior, not floor
the furniture cut off: it is left out of the fitting cells and reported as ``interior_m2``.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from typing import Any

import numpy as np
import shapely
from scipy import ndimage
from shapely.ops import unary_union

from holomj.evaluation.folder import MeasuredFolder

ROBOT_RADIUS_M = 0.2
GRID_M = 0.05
NAVMAP_FREE = ("door", "narrow", "reachable", "unreachable")
ENTRANCE_PROBE_M = 0.4  # the robot starts this far inside the entrance door
ENTRANCE_SNAP_M = 1.5  # ... or at the nearest fitting cell within this distance


def _decode(rle: Any, total: int) -> np.ndarray:
    runs = json.loads(rle) if isinstance(rle, str) else rle
    values = np.concatenate([np.full(int(n), int(v), dtype=np.int32) for v, n in runs])
    if values.size != total:
        raise ValueError(f"run lengths give {values.size} cells, shape needs {total}")
    return values


def grid_from_navmap(nav: dict[str, Any]) -> tuple[np.ndarray, np.ndarray, tuple, float]:
    """(free mask, room-label grid, origin, cell) from navmap.json."""
    ny, nx = nav["shape"]
    codes = _decode(nav["cells"], ny * nx).reshape(ny, nx)
    names = nav.get("codes", {})
    free_codes = [names[k] for k in NAVMAP_FREE if k in names]
    free = np.isin(codes, free_codes)
    if "room_cells" in nav:
        rooms = _decode(nav["room_cells"], ny * nx).reshape(ny, nx)
    else:
        rooms = np.where(free, 0, -1)
    door = names.get("door")
    inside = (rooms >= 0) & ~(codes == door if door is not None else False)
    return free, np.where(inside, rooms, -1), tuple(nav["origin"]), float(nav["cell_m"])


def grid_from_polygons(scene: MeasuredFolder) -> tuple[np.ndarray, np.ndarray, tuple, float]:
    """(free mask, room-label grid, origin, cell) rasterised from rooms, walls and furniture."""
    union = unary_union([r.poly for r in scene.rooms])
    x0, y0, x1, y1 = union.bounds
    origin = (x0 - 0.5, y0 - 0.5)
    nx = math.ceil((x1 - x0 + 1.0) / GRID_M)
    ny = math.ceil((y1 - y0 + 1.0) / GRID_M)
    xs = origin[0] + (np.arange(nx) + 0.5) * GRID_M
    ys = origin[1] + (np.arange(ny) + 0.5) * GRID_M
    gx, gy = np.meshgrid(xs, ys)
    shared = [
        a.poly.exterior.intersection(b.poly.exterior)
        for i, a in enumerate(scene.rooms)
        for b in scene.rooms[i + 1 :]
    ]
    walls = unary_union([g for g in shared if g.length > 0]).buffer(
        scene.wall_t / 2, cap_style="flat"
    )
    gaps = [d.segment.buffer(scene.wall_t, cap_style="flat") for d in scene.doors]
    walls = walls.difference(unary_union(gaps)) if gaps else walls
    furniture = [
        o.fp for o in scene.objects if o.support is None and o.zmin < 2.0 and o.zmax > 0.02
    ]
    free_geom = union.union(unary_union(gaps) if gaps else union).difference(walls)
    if furniture:
        free_geom = free_geom.difference(unary_union(furniture))
    free = shapely.contains_xy(free_geom, gx, gy)
    rooms = np.full((ny, nx), -1, dtype=np.int32)
    for i, r in enumerate(scene.rooms):
        rooms[shapely.contains_xy(r.poly, gx, gy)] = i
    return free, rooms, origin, GRID_M


def entrance(scene: MeasuredFolder) -> tuple[tuple[float, float], tuple[float, float]] | None:
    """The entrance point and the normal into the house."""
    nav = scene.navmap or {}
    ent = nav.get("entrance") or {}
    door = None
    if ent.get("door"):
        door = next((d for d in scene.doors if d.id == ent["door"]), None)
    if door is None:
        door = next((d for d in scene.doors if len(d.rooms) == 1), None)
    if door is None:
        door = scene.doors[0] if scene.doors else None
    if door is None or not door.normals:
        return None
    return door.point, next(iter(door.normals.values()))


@dataclass
class ReachGrid:
    """The robot's reach on a grid: which cells its centre fits in, which of them it reaches
    from the entrance, and which free floor its body sweeps from there."""

    method: str
    radius: float
    origin: tuple[float, float]
    cell: float
    free: np.ndarray
    rooms: np.ndarray
    fits: np.ndarray
    reach: np.ndarray
    swept: np.ndarray
    room_names: list[str]
    entrance_found: bool
    interior: np.ndarray | None = None  # pockets inside one object's footprint (not floor)

    def centres(self) -> tuple[np.ndarray, np.ndarray]:
        """World x and y of every cell's centre."""
        ny, nx = self.free.shape
        xs = self.origin[0] + (np.arange(nx) + 0.5) * self.cell
        ys = self.origin[1] + (np.arange(ny) + 0.5) * self.cell
        return np.meshgrid(xs, ys)


def robot_reach(scene: MeasuredFolder, radius: float = ROBOT_RADIUS_M) -> ReachGrid | None:
    """The reach of a robot of ``radius`` in ``scene`` (None when the scene has no rooms)."""
    method = "navmap"
    try:
        if not scene.navmap:
            raise ValueError("no navmap")
        free, rooms, origin, cell = grid_from_navmap(scene.navmap)
    except (KeyError, ValueError, TypeError):
        if not scene.rooms:
            return None
        method = "raster"
        free, rooms, origin, cell = grid_from_polygons(scene)
    clearance = ndimage.distance_transform_edt(free) * cell
    fits = free & (clearance >= radius + cell / 2 - 1e-9)
    labels, _ = ndimage.label(fits)
    interior = object_interiors(scene, labels, origin, cell)
    fits &= ~interior
    start = entrance(scene)
    seed_label = 0
    if start is not None:
        (px, py), (nx_, ny_) = start
        iy, ix = np.nonzero(fits)
        if iy.size:
            cx = origin[0] + (ix + 0.5) * cell
            cy = origin[1] + (iy + 0.5) * cell
            tx, ty = px + nx_ * ENTRANCE_PROBE_M, py + ny_ * ENTRANCE_PROBE_M
            dist = np.hypot(cx - tx, cy - ty)
            k = int(np.argmin(dist))
            if float(dist[k]) <= ENTRANCE_SNAP_M:
                seed_label = int(labels[iy[k], ix[k]])
    reach = labels == seed_label if seed_label else np.zeros_like(fits)
    swept = ndimage.distance_transform_edt(~reach) * cell <= radius + cell / 2
    names = (scene.navmap or {}).get("rooms_index") if method == "navmap" else None
    names = names or [r.id for r in scene.rooms]
    return ReachGrid(
        method=method,
        radius=radius,
        origin=(float(origin[0]), float(origin[1])),
        cell=cell,
        free=free,
        rooms=rooms,
        fits=fits,
        reach=reach,
        swept=swept,
        room_names=list(names),
        entrance_found=bool(seed_label),
        interior=interior,
    )


def object_interiors(
    scene: MeasuredFolder, labels: np.ndarray, origin: tuple, cell: float
) -> np.ndarray:
    """Cells of the labelled pockets that lie wholly inside one floor object's footprint."""
    interior = np.zeros(labels.shape, dtype=bool)
    if not labels.any():
        return interior
    ny, nx = labels.shape
    sizes = np.bincount(labels.ravel())
    for obj in scene.objects:
        if obj.support is not None or obj.zmin >= 2.0 or obj.zmax <= 0.02:
            continue
        x0, y0, x1, y1 = obj.fp.bounds
        c0 = max(0, int((x0 - origin[0]) / cell))
        r0 = max(0, int((y0 - origin[1]) / cell))
        c1 = min(nx, math.ceil((x1 - origin[0]) / cell))
        r1 = min(ny, math.ceil((y1 - origin[1]) / cell))
        window = labels[r0:r1, c0:c1]
        found = np.unique(window[window > 0])
        if not found.size:
            continue
        xs = origin[0] + (np.arange(c0, c1) + 0.5) * cell
        ys = origin[1] + (np.arange(r0, r1) + 0.5) * cell
        gx, gy = np.meshgrid(xs, ys)
        inside = shapely.contains_xy(obj.fp, gx, gy)
        for label in found:
            cells = window == label
            if int(np.count_nonzero(cells)) == int(sizes[label]) and bool(inside[cells].all()):
                interior[r0:r1, c0:c1] |= cells
    return interior


def reachability(scene: MeasuredFolder, radius: float = ROBOT_RADIUS_M) -> dict[str, Any]:
    """Reachable share of the robot's free space (and swept coverage), overall and per room."""
    grid = robot_reach(scene, radius)
    if grid is None:
        return {"share": None, "coverage": None, "method": None, "reason": "no rooms"}
    return reach_summary(grid)


def reach_summary(grid: ReachGrid) -> dict[str, Any]:
    """The numbers of :func:`reachability` for a computed grid."""
    floor = grid.free & (grid.rooms >= 0)
    fit_floor = grid.fits & (grid.rooms >= 0)
    n_fit = int(fit_floor.sum())
    share = float((grid.reach & fit_floor).sum() / n_fit) if n_fit else 0.0
    coverage = float((grid.swept & floor).sum() / floor.sum()) if floor.sum() else 0.0
    per_room = {}
    for i, name in enumerate(grid.room_names):
        mask = fit_floor & (grid.rooms == i)
        total = int(mask.sum())
        per_room[name] = round(float((grid.reach & mask).sum() / total), 4) if total else 0.0
    return {
        "share": round(share, 4),
        "coverage": round(coverage, 4),
        "method": grid.method,
        "robot_radius_m": grid.radius,
        "entrance_found": grid.entrance_found,
        "interior_m2": round(float(grid.interior.sum()) * grid.cell**2, 4)
        if grid.interior is not None
        else 0.0,
        "per_room": per_room,
    }
