"""Pure 2-D geometry of floor layouts: footprints, walls, door and window zones, rasters, paths.

Conventions (DESIGN.md): metres, world x/y, yaw counter-clockwise in degrees, an object's front
faces +X at yaw 0. Floor objects turn in quarter turns: the yaw index ``k`` (0..3) stands for
``90 * k`` degrees. ``width`` is an object's left-right size and ``depth`` its front-back size.

The constraint predicates here are the *definition* of each constraint's meaning: the greedy
solver scores candidates with them and the post-check of every solution evaluates them; the CP-SAT
model encodes the same tests conservatively on its integer grid.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TypeVar

import numpy as np
import shapely
from shapely.geometry import LineString, Polygon, box
from shapely.geometry.polygon import orient

FRONT: tuple[tuple[int, int], ...] = ((1, 0), (0, 1), (-1, 0), (0, -1))
EPS = 1e-6
Pose = tuple[int, int, int]  # a pose on the layout grid: x and y in grid units, yaw index
CellRect = tuple[int, int, int, int]  # cells (i0, j0, i1, j1), the ends excluded
Coordinate = TypeVar("Coordinate", float, np.ndarray)  # one value, or an array of them
ADJACENT_GAP_M = 0.45  # 'adjacent to': footprints at most this far apart
# How far a furnished room's layout polygon lies inside its wall surfaces (beyond half the wall
# thickness): furniture laid out against it never touches a wall.
LAYOUT_MARGIN_M = 0.03


def yaw_index(yaw_deg: float) -> int:
    """The quarter turn (0..3) nearest to ``yaw_deg``."""
    return round(yaw_deg / 90.0) % 4


def half_extents(width: float, depth: float, k: int) -> tuple[float, float]:
    """Half sizes along world x and y of a footprint turned by ``k`` quarter turns."""
    return (depth / 2, width / 2) if k % 2 == 0 else (width / 2, depth / 2)


def footprint(x: float, y: float, k: int, width: float, depth: float) -> tuple[float, ...]:
    """``(xmin, ymin, xmax, ymax)`` of a footprint centred at ``(x, y)``."""
    hx, hy = half_extents(width, depth, k)
    return (x - hx, y - hy, x + hx, y + hy)


def rect_gaps(a: Sequence[float], b: Sequence[float]) -> tuple[float, float]:
    """Signed gaps along x and y between two axis-aligned rectangles (negative: overlapping)."""
    gx = max(a[0] - b[2], b[0] - a[2])
    gy = max(a[1] - b[3], b[1] - a[3])
    return gx, gy


# --------------------------------------------------------------------------- walls and openings


@dataclass(frozen=True)
class WallSegment:
    """One edge of the room polygon, walked counter-clockwise (the room lies on its left)."""

    a: tuple[float, float]
    b: tuple[float, float]

    @property
    def length(self) -> float:
        """Length in metres."""
        return math.dist(self.a, self.b)

    @property
    def tangent(self) -> tuple[float, float]:
        """Unit vector from ``a`` to ``b``."""
        n = self.length
        return ((self.b[0] - self.a[0]) / n, (self.b[1] - self.a[1]) / n)

    @property
    def inward(self) -> tuple[float, float]:
        """Unit normal pointing into the room."""
        tx, ty = self.tangent
        return (-ty, tx)

    @property
    def facing_k(self) -> int | None:
        """The yaw index of an object whose back is against this wall (None: wall not axial)."""
        nx, ny = self.inward
        for k, (fx, fy) in enumerate(FRONT):
            if abs(nx - fx) < 1e-6 and abs(ny - fy) < 1e-6:
                return k
        return None

    def locate(self, point: Sequence[Coordinate]) -> tuple[Coordinate, Coordinate]:
        """Distance along the wall from ``a`` and distance into the room from the wall line (of
        one point, or of arrays of x and y)."""
        tx, ty = self.tangent
        px, py = point[0] - self.a[0], point[1] - self.a[1]
        return px * tx + py * ty, -px * ty + py * tx


def room_walls(polygon: Sequence[Sequence[float]]) -> list[WallSegment]:
    """The room's edges, counter-clockwise, skipping zero-length ones."""
    coords = list(orient(Polygon(polygon), sign=1.0).exterior.coords)[:-1]
    walls = []
    for i in range(len(coords)):
        a, b = coords[i], coords[(i + 1) % len(coords)]
        if math.dist(a, b) > 1e-9:
            walls.append(WallSegment((float(a[0]), float(a[1])), (float(b[0]), float(b[1]))))
    return walls


def wall_of(point: Sequence[float], walls: Sequence[WallSegment]) -> tuple[WallSegment, float]:
    """The wall nearest to ``point`` and the distance along it."""
    best: tuple[float, WallSegment, float] | None = None
    for wall in walls:
        along, off = wall.locate(point)
        clamped = min(max(along, 0.0), wall.length)
        dist = math.hypot(along - clamped, off)
        if best is None or dist < best[0]:
            best = (dist, wall, along)
    assert best is not None  # a room has walls
    return best[1], best[2]


def _wall_rect(wall: WallSegment, along: float, width: float, depth: float) -> Polygon:
    """A rectangle on the room side of ``wall``: ``width`` along it centred at ``along``."""
    (ax, ay), (tx, ty), (nx, ny) = wall.a, wall.tangent, wall.inward
    pts = []
    for s, d in (
        (along - width / 2, 0.0),
        (along + width / 2, 0.0),
        (along + width / 2, depth),
        (along - width / 2, depth),
    ):
        pts.append((ax + tx * s + nx * d, ay + ty * s + ny * d))
    return Polygon(pts)


def door_keepout(
    position: Sequence[float],
    width: float,
    swing: str,
    walls: Sequence[WallSegment],
    clearance: float,
) -> Polygon:
    """The zone kept free in front of a door: its width, as deep as the leaf or ``clearance``."""
    wall, along = wall_of(position, walls)
    depth = max(clearance, width if swing == "in" else 0.0)
    return _wall_rect(wall, along, width, depth)


def door_swing(
    position: Sequence[float], width: float, swing: str, hinge: str, walls: Sequence[WallSegment]
) -> Polygon | None:
    """The quarter disc swept by the leaf of a door that swings into the room (else None)."""
    if swing != "in":
        return None
    wall, along = wall_of(position, walls)
    (ax, ay), (tx, ty), (nx, ny) = wall.a, wall.tangent, wall.inward
    # Seen from inside the room looking at the wall, "left" is along +tangent (CCW walls).
    side = 1.0 if hinge == "left" else -1.0
    hinge_s = along + side * width / 2
    hx, hy = ax + tx * hinge_s, ay + ty * hinge_s
    pts = [(hx, hy)]
    for i in range(17):
        angle = (math.pi / 2) * i / 16
        # From pointing at the door's other jamb (-side * tangent) to pointing into the room.
        ux = -side * tx * math.cos(angle) + nx * math.sin(angle)
        uy = -side * ty * math.cos(angle) + ny * math.sin(angle)
        pts.append((hx + width * ux, hy + width * uy))
    return Polygon(pts)


def window_zone(
    position: Sequence[float], width: float, walls: Sequence[WallSegment], clearance: float
) -> Polygon:
    """The zone in front of a window that tall objects keep free."""
    wall, along = wall_of(position, walls)
    return _wall_rect(wall, along, width, max(clearance, 1e-3))


# --------------------------------------------------------------------------- rasters


@dataclass(frozen=True)
class Raster:
    """A grid of square cells over a bounding box; cell ``(i, j)`` spans
    ``[x0 + i*cell, x0 + (i+1)*cell] x [y0 + j*cell, y0 + (j+1)*cell]``."""

    x0: float
    y0: float
    cell: float
    nx: int
    ny: int

    @classmethod
    def around(cls, polygon: Polygon, cell: float) -> Raster:
        """A raster whose cells lie on multiples of ``cell`` and cover ``polygon``."""
        minx, miny, maxx, maxy = polygon.bounds
        i0, j0 = math.floor(minx / cell + 1e-9), math.floor(miny / cell + 1e-9)
        i1, j1 = math.ceil(maxx / cell - 1e-9), math.ceil(maxy / cell - 1e-9)
        return cls(i0 * cell, j0 * cell, cell, max(i1 - i0, 1), max(j1 - j0, 1))

    def _cell_boxes(
        self, a0: int = 0, a1: int | None = None, b0: int = 0, b1: int | None = None
    ) -> np.ndarray:
        a1 = self.nx if a1 is None else a1
        b1 = self.ny if b1 is None else b1
        i, j = np.meshgrid(np.arange(a0, a1), np.arange(b0, b1), indexing="ij")
        x = self.x0 + i * self.cell
        y = self.y0 + j * self.cell
        return shapely.box(x, y, x + self.cell, y + self.cell)

    def centres(self) -> tuple[np.ndarray, np.ndarray]:
        """Cell centre coordinates, arrays of shape ``(nx, ny)``."""
        i, j = np.meshgrid(np.arange(self.nx), np.arange(self.ny), indexing="ij")
        return self.x0 + (i + 0.5) * self.cell, self.y0 + (j + 0.5) * self.cell

    def covered(self, polygon: Polygon) -> np.ndarray:
        """Boolean mask of cells lying entirely inside ``polygon``."""
        # A cell is inside when its centre is, and the boundary does not cross the cell.
        xs, ys = self.centres()
        shapely.prepare(polygon)
        inside = np.asarray(shapely.contains_xy(polygon, xs, ys), dtype=bool)
        boundary = polygon.boundary
        near = self._window(boundary.bounds, pad=1)
        if near is not None:
            (a0, a1), (b0, b1) = near
            sub = self._cell_boxes(a0, a1, b0, b1)
            crossing = np.asarray(shapely.intersects(sub, boundary), dtype=bool)
            covered_sub = np.asarray(
                shapely.covered_by(sub[crossing], polygon.buffer(1e-9)), dtype=bool
            )
            block = inside[a0:a1, b0:b1]
            block[crossing] = covered_sub
            inside[a0:a1, b0:b1] = block
        return inside

    def touched(self, polygon: Polygon) -> np.ndarray:
        """Boolean mask of cells whose interior meets ``polygon``'s interior (positive area)."""
        hit = np.zeros((self.nx, self.ny), dtype=bool)
        near = self._window(polygon.bounds, pad=1)
        if near is None:
            return hit
        (a0, a1), (b0, b1) = near
        boxes = self._cell_boxes(a0, a1, b0, b1)
        sub = np.asarray(shapely.intersects(boxes, polygon), dtype=bool)
        if sub.any():
            areas = shapely.area(shapely.intersection(boxes[sub], polygon))
            sub[sub] = areas > 1e-6 * self.cell * self.cell
        hit[a0:a1, b0:b1] = sub
        return hit

    def _window(
        self, bounds: tuple[float, ...], pad: int
    ) -> tuple[tuple[int, int], tuple[int, int]] | None:
        """Cell index ranges covering ``bounds`` (plus ``pad`` cells), or None if outside."""
        minx, miny, maxx, maxy = bounds
        a0 = max(math.floor((minx - self.x0) / self.cell) - pad, 0)
        b0 = max(math.floor((miny - self.y0) / self.cell) - pad, 0)
        a1 = min(math.ceil((maxx - self.x0) / self.cell) + pad, self.nx)
        b1 = min(math.ceil((maxy - self.y0) / self.cell) + pad, self.ny)
        if a0 >= a1 or b0 >= b1:
            return None
        return (a0, a1), (b0, b1)


def merge_cells(mask: np.ndarray) -> list[CellRect]:
    """Cover the true cells of ``mask`` (indexed ``[i, j]``) with disjoint rectangles.

    Returns half-open cell index ranges ``(i0, j0, i1, j1)``: runs along ``j`` in each column,
    merged across neighbouring columns with identical runs.
    """
    rects: list[CellRect] = []
    open_runs: dict[tuple[int, int], int] = {}
    nx = mask.shape[0]
    for i in range(nx + 1):
        runs: set[tuple[int, int]] = set()
        if i < nx:
            col = mask[i]
            j, ny = 0, col.shape[0]
            while j < ny:
                if col[j]:
                    start = j
                    while j < ny and col[j]:
                        j += 1
                    runs.add((start, j))
                else:
                    j += 1
        for run in list(open_runs):
            if run not in runs:
                rects.append((open_runs.pop(run), run[0], i, run[1]))
        for run in runs:
            open_runs.setdefault(run, i)
    return sorted(rects)


class SummedArea:
    """O(1) counts of true cells in any cell rectangle of a mask (vectorised queries)."""

    def __init__(self, mask: np.ndarray) -> None:
        self.shape = mask.shape
        table = np.zeros((mask.shape[0] + 1, mask.shape[1] + 1), dtype=np.int64)
        table[1:, 1:] = np.cumsum(np.cumsum(mask.astype(np.int64), axis=0), axis=1)
        self.table = table

    def count(self, i0: np.ndarray, j0: np.ndarray, i1: np.ndarray, j1: np.ndarray) -> np.ndarray:
        """True cells in ``[i0, i1) x [j0, j1)``; ranges are clipped, cells outside count as
        true (outside the raster is never free)."""
        nx, ny = self.shape
        outside = (i0 < 0) | (j0 < 0) | (i1 > nx) | (j1 > ny)
        a0, b0 = np.clip(i0, 0, nx), np.clip(j0, 0, ny)
        a1, b1 = np.clip(i1, 0, nx), np.clip(j1, 0, ny)
        t = self.table
        inside = t[a1, b1] - t[a0, b1] - t[a1, b0] + t[a0, b0]
        return np.where(outside, 1, 0) + inside


# --------------------------------------------------------------------------- walkable path


@dataclass(frozen=True)
class WalkCheck:
    """Whether a walker of a given radius can go between every two doors."""

    applicable: bool
    ok: bool
    detail: str


def free_walk_mask(
    room: Polygon,
    rects: Sequence[Sequence[float]],
    raster: Raster,
    radius: float,
) -> np.ndarray:
    """Cells whose centre a disc of ``radius`` can occupy: inside the room, clear of ``rects``."""
    xs, ys = raster.centres()
    inner = room.buffer(-radius, join_style="mitre")
    free = (
        np.asarray(shapely.contains_xy(inner, xs, ys), dtype=bool)
        if not inner.is_empty
        else np.zeros(xs.shape, dtype=bool)
    )
    return clear_of(free, xs, ys, rects, radius)


def clear_of(
    free: np.ndarray,
    xs: np.ndarray,
    ys: np.ndarray,
    rects: Sequence[Sequence[float]],
    radius: float,
) -> np.ndarray:
    """``free`` without the cells (centres ``xs``, ``ys``) closer than ``radius`` to a rect
    ``(xmin, ymin, xmax, ymax)`` (a new mask)."""
    free = free.copy()
    for xmin, ymin, xmax, ymax in rects:
        dx = np.maximum(np.maximum(xmin - xs, xs - xmax), 0.0)
        dy = np.maximum(np.maximum(ymin - ys, ys - ymax), 0.0)
        free &= dx * dx + dy * dy >= radius * radius
    return free


class WalkChecker:
    """The walkable-path test with the empty-room work done once (rasters, door cells)."""

    def __init__(
        self, room: Polygon, door_zones: Sequence[Polygon], cell: float, radius: float
    ) -> None:
        self.radius = radius
        self.raster = Raster.around(room, cell)
        self.base = free_walk_mask(room, [], self.raster, radius)
        xs, ys = self.raster.centres()
        self.xs, self.ys = xs, ys
        self.zones = [np.asarray(shapely.contains_xy(z, xs, ys), dtype=bool) for z in door_zones]
        self.applicable = len(door_zones) >= 2
        self.reason = "fewer than two doors" if not self.applicable else ""
        if self.applicable:
            from scipy import ndimage

            labels, _ = ndimage.label(self.base)
            if not _doors_connected(labels, [self.base & z for z in self.zones]):
                self.applicable = False
                self.reason = "doors are not connected even in the empty room"

    def check(self, rects: Sequence[Sequence[float]]) -> WalkCheck:
        """Whether the doors stay connected with these footprints in the room."""
        if not self.applicable:
            return WalkCheck(False, True, self.reason)
        from scipy import ndimage

        free = self._free_cells(rects)
        labels, _ = ndimage.label(free)
        if _doors_connected(labels, [free & z for z in self.zones]):
            return WalkCheck(True, True, "every door reaches every other door")
        return WalkCheck(True, False, f"no path {2 * self.radius:.2f} m wide between the doors")

    def blocked_cells(self, rects: Sequence[Sequence[float]]) -> np.ndarray:
        """Cells of the empty room's free space that these footprints make unwalkable."""
        return self.base & ~self._free_cells(rects)

    def _free_cells(self, rects: Sequence[Sequence[float]]) -> np.ndarray:
        """Cells where a walker of ``radius`` fits beside these footprints."""
        return clear_of(self.base, self.xs, self.ys, rects, self.radius)


def _doors_connected(labels: np.ndarray, cells: Sequence[np.ndarray]) -> bool:
    sets = [set(np.unique(labels[c]).tolist()) - {0} for c in cells]
    if any(not s for s in sets):
        return False
    reach = set(sets[0])
    return all(s & reach for s in sets[1:])


# --------------------------------------------------------------------------- constraint predicates


@dataclass(frozen=True)
class LayoutThresholds:
    """The numbers behind the constraint words (metres), see :class:`LayoutSettings`."""

    near: float = 1.5
    far: float = 1.5
    in_front_max_gap: float = 5.0
    align_tolerance: float = 0.05
    edge_tolerance: float = 0.15
    middle_gap: float = 0.5
    footprint_buffer: float = 0.05  # near/far: footprints grown by this per side (Holodeck)

    @property
    def near_raw_gap(self) -> float:
        """'near' as a gap between the unbuffered footprints."""
        return self.near + 2 * self.footprint_buffer

    @property
    def far_raw_gap(self) -> float:
        """'far' as a gap between the unbuffered footprints."""
        return self.far + 2 * self.footprint_buffer


def relation_holds(
    kind: str,
    xa: np.ndarray | float,
    ya: np.ndarray | float,
    ka: int,
    size_a: tuple[float, float],
    xt: np.ndarray | float,
    yt: np.ndarray | float,
    kt: int,
    size_t: tuple[float, float],
    th: LayoutThresholds,
) -> np.ndarray:
    """Whether object A (centre ``xa, ya``, yaw index ``ka``, ``(width, depth)``) stands in
    relation ``kind`` to target T. Vectorised over A's centre and over T's centre.

    * near / far: the Euclidean gap between the footprints, each grown by
      ``footprint_buffer`` per side as Holodeck grows them, is ``<= near`` / ``>= far``;
    * adjacent to: the gap between the footprints is at most ``ADJACENT_GAP_M``;
    * in front of / behind: A's centre lies beyond T's front / back face, within T's width
      sideways, and at most ``in_front_max_gap`` away along T's axis;
    * side of: A's centre lies within T's depth band and beyond T's width (left or right);
      left of / right of: the same, on T's own left / right;
    * center aligned: the centres share an x or a y, strictly closer than ``align_tolerance``:
      Holodeck's test, which is "on the target's front-back axis or on its left-right axis";
    * face to: the ray from A's centre along A's front meets T's footprint;
    * face same as / face opposite to: equal / opposite yaw.
    """
    xa = np.asarray(xa, dtype=float)
    ya = np.asarray(ya, dtype=float)
    dx, dy = xa - xt, ya - yt
    hxa, hya = half_extents(size_a[0], size_a[1], ka)
    hxt, hyt = half_extents(size_t[0], size_t[1], kt)
    if kind in ("near", "far", "adjacent_to"):
        gx = np.maximum(np.abs(dx) - (hxa + hxt), 0.0)
        gy = np.maximum(np.abs(dy) - (hya + hyt), 0.0)
        gap = np.hypot(gx, gy)
        if kind == "adjacent_to":
            return gap <= ADJACENT_GAP_M + EPS
        return gap <= th.near_raw_gap + EPS if kind == "near" else gap >= th.far_raw_gap - EPS
    if kind == "center_aligned":
        return np.minimum(np.abs(dx), np.abs(dy)) < th.align_tolerance - EPS
    if kind == "face_same_as":
        return np.full(np.broadcast(dx, dy).shape, ka == kt)
    if kind == "face_opposite_to":
        return np.full(np.broadcast(dx, dy).shape, ka == (kt + 2) % 4)
    if kind == "face_to":
        fx, fy = FRONT[ka]
        fwd = -(dx * fx + dy * fy)  # T's centre ahead of A's
        lat = -(dx * -fy + dy * fx)
        t_lat = hyt if fx != 0 else hxt
        t_fwd = hxt if fx != 0 else hyt
        return (np.abs(lat) <= t_lat + EPS) & (fwd >= -t_fwd - EPS)
    fx, fy = FRONT[kt]
    along = dx * fx + dy * fy
    lat = dx * -fy + dy * fx
    hd_t, hw_t = size_t[1] / 2, size_t[0] / 2
    a_along = hxa if fx != 0 else hya
    if kind == "in_front_of":
        return (
            (along >= hd_t - EPS)
            & (np.abs(lat) <= hw_t + EPS)
            & (along - hd_t - a_along <= th.in_front_max_gap + EPS)
        )
    if kind == "behind":
        return (
            (along <= -hd_t + EPS)
            & (np.abs(lat) <= hw_t + EPS)
            & (-along - hd_t - a_along <= th.in_front_max_gap + EPS)
        )
    band = np.abs(along) <= hd_t + EPS
    if kind == "side_of":
        return band & (np.abs(lat) >= hw_t - EPS)
    if kind == "left_of":
        return band & (lat >= hw_t - EPS)
    if kind == "right_of":
        return band & (lat <= -hw_t + EPS)
    raise ValueError(f"not a relation: {kind}")


def edge_holds(
    xa: np.ndarray | float,
    ya: np.ndarray | float,
    ka: int,
    size_a: tuple[float, float],
    walls: Sequence[WallSegment],
    tolerance: float,
) -> np.ndarray:
    """'edge': A's back face is within ``tolerance`` of a wall it has its back to.

    The middle of A's back face must lie in front of that wall's span, at most ``tolerance``
    from the wall line (only walls along x or y qualify, as objects turn in quarter turns).
    """
    xa = np.asarray(xa, dtype=float)
    ya = np.asarray(ya, dtype=float)
    fx, fy = FRONT[ka]
    hd = size_a[1] / 2
    bx, by = xa - fx * hd, ya - fy * hd
    result = np.zeros(np.broadcast(xa, ya).shape, dtype=bool)
    for wall in walls:
        if wall.facing_k != ka:
            continue
        along, off = wall.locate((bx, by))
        result |= (
            (along >= -EPS)
            & (along <= wall.length + EPS)
            & (off >= -EPS)
            & (off <= tolerance + EPS)
        )
    return result


def middle_holds(rect: Sequence[float], room: Polygon, gap: float) -> bool:
    """'middle': the footprint keeps at least ``gap`` from every wall."""
    return bool(room.exterior.distance(box(*rect)) >= gap - EPS)


def front_is_clear(
    x: float, y: float, k: int, depth: float, room: Polygon, clearance: float
) -> bool:
    """The segment from the middle of the front face ``clearance`` straight ahead is in the room."""
    fx, fy = FRONT[k]
    sx, sy = x + fx * depth / 2, y + fy * depth / 2
    if clearance <= 0:
        return bool(room.buffer(EPS).contains(shapely.Point(sx, sy)))
    segment = LineString([(sx, sy), (sx + fx * clearance, sy + fy * clearance)])
    return bool(room.buffer(EPS).covers(segment))
