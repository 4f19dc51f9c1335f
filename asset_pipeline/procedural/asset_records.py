"""What both assemblies (rigid and articulated) share: the metadata records of a collider (with a
hull's OBJ file) and of a support surface, their rounding, and the checks that the colliders stay
inside the asset and that every support surface has free height above it."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from asset_pipeline.procedural.obj_writer import obj_bytes, rounded
from asset_pipeline.procedural.parts import (
    Collider,
    Mesh,
    Part,
    RecipeSurface,
)
from holomj.spec.assets import CollisionPart, SupportSurface

SOURCE = "holomj procedural"


LICENSE = "Apache-2.0"


DECIMALS = 6  # metadata numbers (OBJ vertices use 5)


CLEARANCE = 0.05  # free height required above every support surface


PROUD = 1e-3  # parts standing less than this above a surface (tape, a screen) do not block it


def check_inside(asset_id: str, colliders: list[Collider], low: np.ndarray, high: np.ndarray):
    tol = 2e-5
    for collider in colliders:
        half = np.asarray(collider.half_extents())
        pos = np.asarray(collider.pos)
        if np.any(pos - half < low - tol) or np.any(pos + half > high + tol):
            raise ValueError(f"{asset_id}: collider {collider} sticks out of the visual bounds")


def _part_boxes(part: Part) -> list[tuple[np.ndarray, np.ndarray]]:
    boxes = []
    bounds = part.bounds()
    if bounds is not None:
        boxes.append((np.asarray(bounds[0]), np.asarray(bounds[1])))
    for c in part.colliders():
        half = np.asarray(c.half_extents())
        boxes.append((np.asarray(c.pos) - half, np.asarray(c.pos) + half))
    return boxes


def check_clearance(asset_id: str, parts: Sequence[Part]) -> None:
    boxes = [box for part in parts for box in _part_boxes(part)]
    for part in parts:
        for surface in part.surfaces():
            xy = np.asarray(surface.polygon)
            (x0, y0), (x1, y1) = xy.min(axis=0), xy.max(axis=0)
            h = surface.height
            for low, high in boxes:
                if (
                    high[2] > h + PROUD
                    and low[2] < h + CLEARANCE
                    and low[0] < x1 - 1e-6
                    and high[0] > x0 + 1e-6
                    and low[1] < y1 - 1e-6
                    and high[1] > y0 + 1e-6
                ):
                    raise ValueError(
                        f"{asset_id}: the surface at z = {h:.3f} has a part within "
                        f"{CLEARANCE} m above it ({np.round(low, 3)}..{np.round(high, 3)})"
                    )


def collision_record(
    collider: Collider, hull_name: str
) -> tuple[CollisionPart, tuple[bytes, np.ndarray] | None]:
    """The metadata of a collider, and for a hull its OBJ file and its vertices as written."""
    px, py, pz = collider.pos
    qw, qx, qy, qz = collider.quat
    pos = (meta_round(px), meta_round(py), meta_round(pz))
    quat = (meta_round(qw), meta_round(qx), meta_round(qy), meta_round(qz))
    if collider.kind == "mesh":
        vertices, faces = _hull_mesh(np.asarray(collider.vertices, dtype=float))
        mesh = rounded(Mesh(vertices, faces))
        data = obj_bytes(mesh, comment=f"convex collider ({SOURCE}, {LICENSE})")
        written = tuple((float(x), float(y), float(z)) for x, y, z in mesh.vertices)
        rounded_collider = Collider("mesh", (), collider.pos, vertices=written)
        part = CollisionPart(
            kind="mesh",
            mesh=hull_name,
            size=tuple(
                meta_round(v) for v in rounded_collider.half_extents()
            ),  # as MuJoCo sizes it
            pos=pos,
            quat=(1.0, 0.0, 0.0, 0.0),
            volume_m3=float(f"{rounded_collider.volume:.9g}"),
        )
        return part, (data, mesh.vertices)
    size = tuple(meta_round(v) for v in collider.size)
    rounded_collider = Collider(collider.kind, size, collider.pos, collider.axis)
    part = CollisionPart(
        kind=collider.kind,
        size=size,
        pos=pos,
        quat=quat,
        volume_m3=float(f"{rounded_collider.volume:.9g}"),
    )
    return part, None


def _hull_mesh(points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The convex hull of ``points``: its vertices (in input order) and outward triangles."""
    from scipy.spatial import ConvexHull

    hull = ConvexHull(points)
    used = np.sort(hull.vertices)
    index = np.full(len(points), -1, dtype=np.int64)
    index[used] = np.arange(len(used))
    faces = hull.simplices.copy()
    centre = points[used].mean(axis=0)
    tri = points[faces]
    normal = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    flip = np.einsum("fk,fk->f", normal, tri[:, 0] - centre) < 0
    faces[flip] = faces[flip][:, [0, 2, 1]]
    return points[used], index[faces]


def surface_record(surface: RecipeSurface) -> SupportSurface:
    polygon = [(meta_round(x), meta_round(y)) for x, y in surface.polygon]
    area = 0.0
    for (x0, y0), (x1, y1) in zip(polygon, polygon[1:] + polygon[:1], strict=True):
        area += x0 * y1 - x1 * y0
    return SupportSurface(
        height=meta_round(surface.height), polygon=polygon, area_m2=meta_round(0.5 * area)
    )


def meta_round(value: float) -> float:
    """Round a metadata number; never ``-0.0``."""
    return round(float(value), DECIMALS) + 0.0
