"""Make decomposition output simulation-ready: capped, inside the visual mesh, no slivers.

For each raw hull, in order:

1. clip its points to the visual mesh's bounding box;
2. cap its vertices at :data:`HULL_VERTEX_CAP` (farthest-point subset of the hull vertices, then
   the hull of that subset, which lies inside the original);
3. move vertices that stick out of the visual mesh by more than :data:`DEVIATION_TOL_M` to
   their closest point on its surface (or, failing that, toward the hull's vertex centroid by
   bisection on the outward deviation of :class:`~asset_pipeline.proximity.MeshProximity`),
   and take the hull again;
4. a hull with volume below :data:`SLIVER_VOLUME_M3` or a principal extent below
   :data:`SLIVER_EXTENT_M` (MuJoCo cannot give it a volume) becomes a box along its principal
   axes, or is dropped when another collider covers it or it is under 1 mm³.

Vertices are rounded as the OBJ writer writes them before volumes are taken, so the recorded
``volume_m3`` matches the file.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
import trimesh
from scipy.spatial import ConvexHull, QhullError
from scipy.spatial.transform import Rotation

from asset_pipeline.objfile import obj_bytes, rounded
from asset_pipeline.proximity import MeshProximity

HULL_VERTEX_CAP = 64
DEVIATION_TOL_M = 0.003
SLIVER_VOLUME_M3 = 1e-7
SLIVER_EXTENT_M = 0.001
TINY_VOLUME_M3 = 1e-9


@dataclass(frozen=True)
class HullCollider:
    """A convex hull (vertices, outward faces) or a box (half sizes, pos, quat wxyz)."""

    kind: str
    volume: float
    vertices: np.ndarray | None = None
    faces: np.ndarray | None = None
    size: tuple[float, float, float] | None = None
    pos: tuple[float, float, float] = (0.0, 0.0, 0.0)
    quat: tuple[float, float, float, float] = (1.0, 0.0, 0.0, 0.0)

    @property
    def hull(self) -> tuple[np.ndarray, np.ndarray]:
        """A mesh collider's (vertices, faces); a ValueError for a box."""
        if self.vertices is None or self.faces is None:
            raise ValueError(f"a {self.kind} collider has no hull")
        return self.vertices, self.faces

    @property
    def box(self) -> tuple[float, float, float]:
        """A box collider's half sizes; a ValueError for a hull."""
        if self.size is None:
            raise ValueError(f"a {self.kind} collider has no box size")
        return self.size

    def points(self) -> np.ndarray:
        """Hull vertices, or the eight box corners."""
        if self.kind == "mesh":
            return self.hull[0]
        signs = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)])
        rot = Rotation.from_quat([*self.quat[1:], self.quat[0]]).as_matrix()
        return (signs * np.asarray(self.size)) @ rot.T + np.asarray(self.pos)


@dataclass(frozen=True)
class HullSet:
    colliders: list[HullCollider]
    maxhullvert: int
    quality: dict

    @property
    def volume(self) -> float:
        """The colliders' total volume (m³)."""
        return sum(c.volume for c in self.colliders)


def collision_records(
    colliders: list[HullCollider], files: dict[str, bytes], prefix: str = ""
) -> list[dict[str, Any]]:
    """The ``collision`` records of ``colliders``; each hull's OBJ goes into ``files`` as
    ``{prefix}hull_KK.obj`` (K: the collider's index)."""
    collision: list[dict[str, Any]] = []
    for k, collider in enumerate(colliders):
        if collider.kind == "mesh":
            name = f"{prefix}hull_{k:02d}.obj"
            files[name] = obj_bytes(*collider.hull)
            collision.append({"kind": "mesh", "mesh": name, "volume_m3": collider.volume})
        else:
            collision.append(
                {
                    "kind": "box",
                    "size": list(collider.box),
                    "pos": list(collider.pos),
                    "quat": list(collider.quat),
                    "volume_m3": collider.volume,
                }
            )
    return collision


def postprocess(
    raw_hulls: list[np.ndarray],
    mesh: trimesh.Trimesh,
    proximity: MeshProximity,
    watertight: bool,
    tol: float = DEVIATION_TOL_M,
) -> HullSet:
    """Turn raw hull point sets into colliders; see the module docstring."""
    lo, hi = mesh.bounds
    hulls: list[HullCollider] = []
    slivers: list[np.ndarray] = []
    capped = pulled = 0
    for raw in raw_hulls:
        points = _hull_vertices(np.clip(raw, lo, hi))
        if points is None:
            slivers.append(np.clip(raw, lo, hi))
            continue
        if len(points) > HULL_VERTEX_CAP:
            capped += 1
            points = _hull_vertices(_farthest_points(points, HULL_VERTEX_CAP))
        if points is not None:
            points, moved = _pull_inside(points, proximity, tol)
            pulled += int(moved)
        collider = _mesh_collider(points) if points is not None else None
        if collider is None or _is_sliver(collider.hull[0], collider.volume):
            slivers.append(points if points is not None else raw)
            continue
        hulls.append(collider)
    boxes: list[HullCollider] = []
    dropped = 0
    for points in slivers:
        box = _box_collider(points)
        if _covered(points, hulls) or (box.volume < TINY_VOLUME_M3 and (hulls or boxes)):
            dropped += 1
            continue
        boxes.append(box)
    colliders = hulls + boxes
    if not colliders:
        colliders = [_box_collider(np.asarray(mesh.vertices))]
    all_points = np.concatenate([c.points() for c in colliders])
    deviation = float(proximity.outward_deviation(all_points, exact_above=tol).max())
    hull_volume = sum(c.volume for c in colliders)
    mesh_volume = float(mesh.volume) if watertight else 0.0
    if watertight and mesh_volume > 0:
        reference, ref_volume = "mesh", mesh_volume
    else:
        reference, ref_volume = "convex_hull", _hull_volume(np.asarray(mesh.vertices))
    max_vertices = max((len(c.hull[0]) for c in hulls), default=4)
    quality = {
        "hull_count": len(colliders),
        "mesh_hulls": len(hulls),
        "box_colliders": len(boxes),
        "slivers_dropped": dropped,
        "hulls_capped": capped,
        "hulls_pulled_inside": pulled,
        "max_vertices_per_hull": max_vertices,
        "hull_volume_m3": hull_volume,
        "reference_volume_m3": ref_volume,
        "volume_reference": reference,
        "volume_ratio": hull_volume / ref_volume if ref_volume > 0 else None,
        "max_outward_deviation_m": deviation,
        "deviation_tolerance_m": tol,
        "deviation_measure": "largest distance of a collider vertex outside the visual mesh "
        "(inside: winding number >= 0.5); vertices within the tolerance of the surface count "
        "with their full distance (an upper bound)",
    }
    return HullSet(colliders=colliders, maxhullvert=max(4, max_vertices), quality=quality)


def _hull_vertices(points: np.ndarray) -> np.ndarray | None:
    """The convex hull's vertices (in index order), or None when the points are flat."""
    points = np.asarray(points, dtype=np.float64)
    if len(points) < 4:
        return None
    try:
        hull = ConvexHull(points)
    except (QhullError, ValueError):
        return None
    return points[np.sort(hull.vertices)]


def _hull_volume(points: np.ndarray) -> float:
    try:
        return float(ConvexHull(points).volume)
    except (QhullError, ValueError):
        return 0.0  # flat


def _farthest_points(points: np.ndarray, count: int) -> np.ndarray:
    """A deterministic farthest-point subset, starting from the point farthest from the mean."""
    chosen = [int(np.argmax(np.linalg.norm(points - points.mean(axis=0), axis=1)))]
    nearest = np.linalg.norm(points - points[chosen[0]], axis=1)
    while len(chosen) < count:
        nxt = int(np.argmax(nearest))
        chosen.append(nxt)
        nearest = np.minimum(nearest, np.linalg.norm(points - points[nxt], axis=1))
    return points[np.sort(chosen)]


def _pull_inside(
    points: np.ndarray, proximity: MeshProximity, tol: float
) -> tuple[np.ndarray | None, bool]:
    """Move vertices deviating more than ``tol`` inside; (hull vertices, moved).

    A deviating vertex goes to its closest point on the surface (feet stay on the floor,
    edges stay on edges); if that is still too far out, it goes toward the vertex centroid
    (bisection).
    """
    deviation = proximity.outward_deviation(points, exact_above=tol)
    bad = deviation > tol
    if not bad.any():
        return points, False
    moved = points.copy()
    moved[bad] = proximity.closest(points[bad])[0]
    still = np.zeros(len(points), dtype=bool)
    still[bad] = proximity.outward_deviation(moved[bad], exact_above=tol) > tol
    if still.any():
        centre = points.mean(axis=0)
        outer = moved[still]
        lo_t, hi_t = np.zeros(len(outer)), np.ones(len(outer))
        for _ in range(12):
            mid = (lo_t + hi_t) / 2
            trial = centre + (outer - centre) * mid[:, None]
            ok = proximity.outward_deviation(trial, exact_above=tol) <= tol
            lo_t = np.where(ok, mid, lo_t)
            hi_t = np.where(ok, hi_t, mid)
        moved[still] = centre + (outer - centre) * lo_t[:, None]
    return _hull_vertices(moved), True


def _mesh_collider(points: np.ndarray) -> HullCollider | None:
    points = rounded(points)
    try:
        hull = ConvexHull(points)
    except (QhullError, ValueError):
        return None
    used = np.sort(hull.vertices)
    index = np.full(len(points), -1)
    index[used] = np.arange(len(used))
    faces = hull.simplices.copy()
    tri = points[faces]
    normal = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    inward = np.einsum("ij,ij->i", normal, hull.equations[:, :3]) < 0
    faces[inward] = faces[inward][:, ::-1]
    order = np.lexsort(np.sort(index[faces], axis=1).T[::-1])
    return HullCollider(
        kind="mesh", volume=float(hull.volume), vertices=points[used], faces=index[faces][order]
    )


def _is_sliver(vertices: np.ndarray, volume: float) -> bool:
    return volume < SLIVER_VOLUME_M3 or _principal_extents(vertices)[0].min() < SLIVER_EXTENT_M


def _principal_extents(points: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(extents, axes as columns, centre) of the principal-axes box of ``points``."""
    centred = points - points.mean(axis=0)
    _, _, vt = np.linalg.svd(centred, full_matrices=False)
    axes = vt.T
    if np.linalg.det(axes) < 0:
        axes[:, 2] *= -1
    local = centred @ axes
    lo, hi = local.min(axis=0), local.max(axis=0)
    centre = points.mean(axis=0) + ((lo + hi) / 2) @ axes.T
    return hi - lo, axes, centre


def _box_collider(points: np.ndarray) -> HullCollider:
    """A box along the principal axes of ``points``, at least 1 mm thick."""
    points = np.asarray(points, dtype=np.float64).reshape(-1, 3)
    if len(points) < 3:
        points = np.vstack([points, points + 1e-4])
    extents, axes, centre = _principal_extents(points)
    half = np.maximum(extents / 2, SLIVER_EXTENT_M / 2)
    xyzw = Rotation.from_matrix(axes).as_quat()
    quat = np.array([xyzw[3], *xyzw[:3]])
    quat = quat if quat[0] >= 0 else -quat
    sx, sy, sz = (round(float(h), 6) for h in half)
    px, py, pz = (round(float(c), 6) for c in centre)
    qw, qx, qy, qz = (round(float(q), 8) for q in quat)
    return HullCollider(
        kind="box",
        volume=float(8 * np.prod((sx, sy, sz))),
        size=(sx, sy, sz),
        pos=(px, py, pz),
        quat=(qw, qx, qy, qz),
    )


def _covered(points: np.ndarray, hulls: list[HullCollider], margin: float = 0.001) -> bool:
    """True when every point lies inside one of ``hulls`` (within ``margin``)."""
    for hull in hulls:
        equations = ConvexHull(hull.vertices).equations
        if (points @ equations[:, :3].T + equations[:, 3] <= margin).all():
            return True
    return False
