"""Small geometry helpers for building MJCF: orientations, look-at, polygon slabs."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import shapely
from shapely.geometry import Polygon
from shapely.geometry.polygon import orient

Quat = tuple[float, float, float, float]


def yaw_quat(yaw_rad: float) -> Quat:
    """Quaternion (w, x, y, z) of a rotation by ``yaw_rad`` about +Z."""
    return (math.cos(yaw_rad / 2), 0.0, 0.0, math.sin(yaw_rad / 2))


def quat_from_axes(x_axis: np.ndarray, y_axis: np.ndarray, z_axis: np.ndarray) -> Quat:
    """Quaternion of the rotation whose columns are the given orthonormal axes."""
    import mujoco

    mat = np.column_stack([x_axis, y_axis, z_axis]).astype(np.float64)
    quat = np.zeros(4)
    mujoco.mju_mat2Quat(quat, mat.reshape(-1))
    if quat[0] < 0:
        quat = -quat
    w, x, y, z = (_clean(float(q)) for q in quat)
    return (w, x, y, z)


def look_at_quat(position: Sequence[float], target: Sequence[float]) -> Quat:
    """Orientation of a camera (looking down its -Z, +Y up) at ``position`` facing ``target``."""
    forward = np.asarray(target, dtype=float) - np.asarray(position, dtype=float)
    forward /= np.linalg.norm(forward)
    z_axis = -forward
    up = np.array([0.0, 0.0, 1.0])
    if abs(float(np.dot(up, z_axis))) > 0.999:
        up = np.array([0.0, 1.0, 0.0])
    x_axis = np.cross(up, z_axis)
    x_axis /= np.linalg.norm(x_axis)
    y_axis = np.cross(z_axis, x_axis)
    return quat_from_axes(x_axis, y_axis, z_axis)


def _clean(value: float) -> float:
    """Round away float noise so generated XML is stable and readable."""
    rounded = round(value, 9)
    return 0.0 if rounded == 0 else rounded


def clean(values: Sequence[float] | np.ndarray) -> list[float]:
    """:func:`_clean` for every value."""
    return [_clean(float(v)) for v in values]


@dataclass(frozen=True)
class SlabMesh:
    """A triangulated prism: vertices (n, 3), faces (m, 3) and per-vertex texture coordinates."""

    vertices: np.ndarray
    faces: np.ndarray
    texcoords: np.ndarray


def polygon_slab(
    points: Sequence[Sequence[float]], bottom: float, top: float, tile_m: float = 1.0
) -> SlabMesh:
    """A closed slab over a simple polygon (any shape) between ``bottom`` and ``top``.

    Faces point outwards. Texture coordinates tile the texture every ``tile_m`` metres in x/y.
    """
    polygon = orient(Polygon(points), sign=1.0)
    ring = [tuple(p) for p in list(polygon.exterior.coords)[:-1]]
    index = {p: i for i, p in enumerate(ring)}
    n = len(ring)
    faces: list[tuple[int, int, int]] = []
    for tri in shapely.constrained_delaunay_triangles(polygon).geoms:
        a, b, c = (index[tuple(p)] for p in list(orient(tri, sign=1.0).exterior.coords)[:3])
        faces.append((n + a, n + b, n + c))  # top, counter-clockwise seen from above
        faces.append((a, c, b))  # bottom, facing down
    for i in range(n):
        j = (i + 1) % n
        faces.append((i, j, n + j))
        faces.append((i, n + j, n + i))
    xy = np.asarray(ring, dtype=float)
    vertices = np.vstack(
        [np.column_stack([xy, np.full(n, bottom)]), np.column_stack([xy, np.full(n, top)])]
    )
    texcoords = np.vstack([xy, xy]) / tile_m
    return SlabMesh(vertices=vertices, faces=np.asarray(faces, dtype=int), texcoords=texcoords)
