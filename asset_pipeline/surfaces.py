"""Receptacle surfaces: where small objects may rest on an asset, at every level.

1. Faces whose normal is within :data:`NORMAL_TOL_DEG` of +Z and whose centroid is at least
   :data:`MIN_HEIGHT_M` up (the floor-contact bottom is never a surface) are grouped by height:
   sorted, and split wherever two consecutive heights differ by more than :data:`HEIGHT_GAP_M`.
2. Each group's triangles are projected to the XY plane and unioned (shapely).
3. Free space: points on a grid over the polygon cast a ray straight up from just above the
   group's top. A point is blocked when the ray hits the mesh within :data:`CLEARANCE_M`
   (a shelf board right above, a lamp standing on the table), or when its first hit is an
   upward-facing face (the point is inside solid geometry, e.g. under a side panel). Blocked
   grid cells are cut out.
4. The rest is eroded by :data:`ERODE_M` (objects keep clear of edges and obstacles), split into
   hole-free parts (a cut through each hole), and parts of at least :data:`MIN_AREA_M2` are kept.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import shapely
import trimesh
from shapely.geometry import MultiPolygon, Polygon
from shapely.geometry import box as shapely_box
from shapely.geometry.polygon import orient

NORMAL_TOL_DEG = 10.0
MIN_HEIGHT_M = 0.01
HEIGHT_GAP_M = 0.01
RAY_START_M = 0.001
CLEARANCE_M = 0.05
ERODE_M = 0.02
MIN_AREA_M2 = 0.01
MAX_SAMPLES = 4000
SIMPLIFY_M = 0.002


@dataclass(frozen=True)
class Surface:
    height: float
    polygon: list[tuple[float, float]]
    area: float


def support_surfaces(mesh: trimesh.Trimesh) -> list[Surface]:
    """Support surfaces of ``mesh`` (asset frame), by height, then largest first."""
    if len(mesh.faces) == 0:
        return []
    tri = np.asarray(mesh.triangles, dtype=np.float64)
    cross = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    norm = np.linalg.norm(cross, axis=1)
    with np.errstate(invalid="ignore", divide="ignore"):
        nz = np.where(norm > 0, cross[:, 2] / norm, 0.0)
    z = tri[:, :, 2].mean(axis=1)
    upward = (nz >= math.cos(math.radians(NORMAL_TOL_DEG))) & (z >= MIN_HEIGHT_M)
    faces = np.flatnonzero(upward)
    if len(faces) == 0:
        return []
    faces = faces[np.argsort(z[faces], kind="stable")]
    splits = np.flatnonzero(np.diff(z[faces]) > HEIGHT_GAP_M) + 1
    out: list[Surface] = []
    for group in np.split(faces, splits):
        out.extend(_group_surfaces(tri, nz, norm, z, group))
    return sorted(out, key=lambda s: (s.height, -s.area, s.polygon))


def _group_surfaces(
    tri: np.ndarray, nz: np.ndarray, norm: np.ndarray, z: np.ndarray, group: np.ndarray
) -> list[Surface]:
    area = norm[group] / 2
    height = float(np.average(z[group], weights=area)) if area.sum() > 0 else float(z[group][0])
    rings = np.concatenate([tri[group][:, :, :2], tri[group][:, :1, :2]], axis=1)
    polys = shapely.polygons(rings)
    polys = polys[shapely.area(polys) > 1e-12]
    if len(polys) == 0:
        return []
    region = shapely.union_all(polys)
    if region.buffer(-ERODE_M).area < MIN_AREA_M2:
        return []
    top = float(tri[group][:, :, 2].max()) + RAY_START_M
    blockers = np.ones(len(tri), dtype=bool)
    blockers[group] = False
    blockers &= (tri[:, :, 2].max(axis=1) > top) & (np.abs(nz) > 1e-6)
    free = _free_region(region, tri[blockers], nz[blockers], top, height)
    parts = []
    for part in _polygons(free.buffer(-ERODE_M, join_style="mitre")):
        for piece in _without_holes(part):
            piece = piece.simplify(SIMPLIFY_M)
            if isinstance(piece, Polygon) and piece.area >= MIN_AREA_M2:
                parts.append(piece)
    return [_surface(height, p) for p in parts]


def _free_region(region, tri: np.ndarray, nz: np.ndarray, start: float, height: float):
    """``region`` minus the grid cells whose upward ray is blocked."""
    minx, miny, maxx, maxy = region.bounds
    if len(tri):
        lo, hi = tri[:, :, :2].min(axis=1), tri[:, :, :2].max(axis=1)
        near = (hi[:, 0] >= minx) & (lo[:, 0] <= maxx) & (hi[:, 1] >= miny) & (lo[:, 1] <= maxy)
        tri, nz = tri[near], nz[near]
    if len(tri) == 0:
        return region
    step = max(0.01, math.sqrt(region.area / MAX_SAMPLES))
    xs = np.arange(minx + step / 2, maxx, step)
    ys = np.arange(miny + step / 2, maxy, step)
    gx, gy = np.meshgrid(xs, ys)
    points = np.column_stack([gx.ravel(), gy.ravel()])
    points = points[shapely.contains_xy(region.buffer(step), points[:, 0], points[:, 1])]
    if len(points) == 0:
        return region
    hit_z, hit_up = _first_hits(points, tri, nz, start)
    blocked = (hit_z - height < CLEARANCE_M) | (np.isfinite(hit_z) & hit_up)
    if not blocked.any():
        return region
    half = step / 2 + 1e-6
    cells = shapely.box(
        points[blocked, 0] - half,
        points[blocked, 1] - half,
        points[blocked, 0] + half,
        points[blocked, 1] + half,
    )
    return region.difference(shapely.union_all(cells))


def _first_hits(
    points: np.ndarray, tri: np.ndarray, nz: np.ndarray, start: float, chunk: int = 256
) -> tuple[np.ndarray, np.ndarray]:
    """Height of the first face above ``start`` over each point, and whether it faces up."""
    a, b, c = tri[:, 0], tri[:, 1], tri[:, 2]
    v0, v1 = (b - a)[:, :2], (c - a)[:, :2]
    den = v0[:, 0] * v1[:, 1] - v1[:, 0] * v0[:, 1]
    ok = np.abs(den) > 1e-14
    a, v0, v1, den, nz = a[ok], v0[ok], v1[ok], den[ok], nz[ok]
    dz0, dz1 = (b - tri[:, 0])[ok, 2], (c - tri[:, 0])[ok, 2]
    hit_z = np.full(len(points), np.inf)
    hit_up = np.zeros(len(points), dtype=bool)
    eps = 1e-9
    for s in range(0, len(points), chunk):
        p = points[s : s + chunk]
        dx = p[:, None, 0] - a[None, :, 0]
        dy = p[:, None, 1] - a[None, :, 1]
        u = (dx * v1[None, :, 1] - v1[None, :, 0] * dy) / den
        v = (v0[None, :, 0] * dy - dx * v0[None, :, 1]) / den
        inside = (u >= -eps) & (v >= -eps) & (u + v <= 1 + eps)
        zz = a[None, :, 2] + u * dz0 + v * dz1
        zz = np.where(inside & (zz > start), zz, np.inf)
        first = np.argmin(zz, axis=1)
        rows = np.arange(len(p))
        hit_z[s : s + chunk] = zz[rows, first]
        hit_up[s : s + chunk] = nz[first] > 0
    return hit_z, hit_up


def _polygons(geometry) -> list[Polygon]:
    if isinstance(geometry, Polygon):
        return [] if geometry.is_empty else [geometry]
    if isinstance(geometry, MultiPolygon):
        return [g for g in geometry.geoms if not g.is_empty]
    if hasattr(geometry, "geoms"):
        return [g for item in geometry.geoms for g in _polygons(item)]
    return []


def _without_holes(polygon: Polygon, limit: int = 64) -> list[Polygon]:
    """Split ``polygon`` into hole-free parts by thin vertical cuts through its holes."""
    done, todo = [], [polygon]
    while todo and limit > 0:
        part = todo.pop()
        if not part.interiors:
            done.append(part)
            continue
        limit -= 1
        x = part.interiors[0].centroid.x
        _, miny, _, maxy = part.bounds
        cut = shapely_box(x - 1e-4, miny - 1.0, x + 1e-4, maxy + 1.0)
        todo.extend(_polygons(part.difference(cut)))
    return done + [Polygon(p.exterior) for p in todo]


def _surface(height: float, polygon: Polygon) -> Surface:
    ring = list(orient(polygon, sign=1.0).exterior.coords)[:-1]
    points = [(round(x, 4) + 0.0, round(y, 4) + 0.0) for x, y in ring]
    return Surface(height=round(height, 4), polygon=points, area=round(Polygon(points).area, 6))
