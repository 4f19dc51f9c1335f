"""Plane geometry the metrics share: oriented footprints, angles, directions (metres, degrees,
yaw counter-clockwise about +Z, an asset's front along +X)."""

from __future__ import annotations

import math

from shapely.geometry import LineString, Polygon


def oriented_rect(center: tuple[float, float], sx: float, sy: float, yaw: float) -> Polygon:
    """The ``sx`` x ``sy`` rectangle centred on ``center``, turned by ``yaw`` degrees."""
    c, s = math.cos(math.radians(yaw)), math.sin(math.radians(yaw))
    pts = []
    for dx, dy in ((sx / 2, sy / 2), (-sx / 2, sy / 2), (-sx / 2, -sy / 2), (sx / 2, -sy / 2)):
        pts.append((center[0] + c * dx - s * dy, center[1] + s * dx + c * dy))
    return Polygon(pts)


def angle_deg(u: tuple[float, float], v: tuple[float, float]) -> float:
    """The angle between two plane vectors (180 when either is zero)."""
    nu, nv = math.hypot(*u), math.hypot(*v)
    if nu < 1e-9 or nv < 1e-9:
        return 180.0
    cos = max(-1.0, min(1.0, (u[0] * v[0] + u[1] * v[1]) / (nu * nv)))
    return math.degrees(math.acos(cos))


def direction(line: LineString) -> tuple[float, float]:
    """The unit direction of a segment from its first point to its last."""
    (ax, ay), (bx, by) = line.coords[0], line.coords[-1]
    length = math.hypot(bx - ax, by - ay) or 1.0
    return ((bx - ax) / length, (by - ay) / length)
