"""The support surfaces of an articulated asset (step 8 of
:mod:`asset_pipeline.articulated_import`): outer ones, and interior ones behind the joints of
the parts in front of them, with their free height at the closed pose."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from asset_pipeline.articulated_bodies import (
    Built,
    body_label,
    joint_name,
    rounded,
)
from asset_pipeline.surfaces import _first_hits, support_surfaces

MIN_CLEARANCE_M = 0.05


FRONT_MARGIN_M = 0.05  # a part "in front" of a surface reaches this close to its front edge


def asset_surfaces(built: list[Built], warnings: list[str]) -> tuple[list[dict], list[dict]]:
    """Outer surfaces of the carcass and interior surfaces (see the module docstring)."""
    triangles = np.concatenate([np.asarray(b.repaired.physics.triangles) for b in built])
    boxes = {b.body.name: np.asarray(b.repaired.physics.bounds) for b in built}
    carcass = built[0]
    own = np.asarray(carcass.repaired.physics.triangles)
    outer, interior = [], []
    joints = {b.body.name: b.body for b in built[1:]}
    for surface in support_surfaces(carcass.repaired.physics):
        record = _surface(surface)
        clear = _clearance(surface, triangles)
        covered = math.isfinite(_clearance(surface, own))
        polygon = np.asarray(surface.polygon)
        (_x0, y0), (x1, y1) = polygon.min(axis=0), polygon.max(axis=0)
        top = surface.height + (min(clear, 1.0) if math.isfinite(clear) else 1.0)
        front = [
            name
            for name, body in joints.items()
            if body.parent is None
            and boxes[name][0, 1] < y1
            and boxes[name][1, 1] > y0
            and boxes[name][0, 2] < top
            and boxes[name][1, 2] > surface.height
            and boxes[name][1, 0] >= x1 - FRONT_MARGIN_M
        ]
        if not (covered and front):
            outer.append(record)
            continue
        if clear < MIN_CLEARANCE_M:
            warnings.append(
                f"interior surface at z = {surface.height:.3f} m left out: {clear:.3f} m free above"
            )
            continue
        behind = [joint_name(joints[name]) for name in front]
        interior.append(
            record | {"part": None, "behind": behind, "clearance_m": rounded(min(clear, 10.0))}
        )
    for b in built[1:]:
        chain = [joint_name(b.body)]
        parent = b.body.parent
        while parent is not None:
            chain.insert(0, joint_name(joints[parent]))
            parent = joints[parent].parent
        for surface in support_surfaces(b.repaired.physics):
            clear = _clearance(surface, triangles)
            if not math.isfinite(clear):
                warnings.append(
                    f"{body_label(b.body)}: its upward surface at z = {surface.height:.3f} m is "
                    "outside (nothing above it when closed): not recorded"
                )
                continue
            if clear < MIN_CLEARANCE_M:
                continue
            interior.append(
                _surface(surface)
                | {"part": b.body.name, "behind": chain, "clearance_m": rounded(min(clear, 10.0))}
            )
    interior.sort(key=lambda s: (s["part"] or "", s["height"], s["polygon"]))
    return outer, interior


def _surface(surface: Any) -> dict:
    return {
        "height": surface.height,
        "polygon": [list(p) for p in surface.polygon],
        "area_m2": surface.area,
    }


def _clearance(surface: Any, triangles: np.ndarray, samples: int = 15) -> float:
    """The smallest free height above ``surface`` to any of ``triangles`` (inf: none above)."""
    polygon = np.asarray(surface.polygon)
    (x0, y0), (x1, y1) = polygon.min(axis=0), polygon.max(axis=0)
    lo, hi = triangles[:, :, :2].min(axis=1), triangles[:, :, :2].max(axis=1)
    near = (hi[:, 0] >= x0) & (lo[:, 0] <= x1) & (hi[:, 1] >= y0) & (lo[:, 1] <= y1)
    tri = triangles[near]
    if len(tri) == 0:
        return math.inf
    from shapely import contains_xy
    from shapely.geometry import Polygon

    gx, gy = np.meshgrid(np.linspace(x0, x1, samples), np.linspace(y0, y1, samples))
    points = np.column_stack([gx.ravel(), gy.ravel()])
    shape = Polygon(polygon).buffer(1e-6)
    points = points[contains_xy(shape, points[:, 0], points[:, 1])]
    if len(points) == 0:
        return math.inf
    cross = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    nz = cross[:, 2] / np.maximum(np.linalg.norm(cross, axis=1), 1e-12)
    hit_z, _ = _first_hits(points, tri, nz, surface.height + 0.001)
    return float(hit_z.min() - surface.height)
