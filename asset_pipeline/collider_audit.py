"""Collider-vs-visual audit: how far an asset's visual surface reaches outside its colliders.

A robot touches an asset's colliders, while a camera sees its visual meshes; where the visual
surface sticks out of every collider, hands and objects pass into what looks solid. The gap of
an asset is the largest distance from a point of its visual surface to the union of its
collider geoms (boxes, cylinders, spheres, capsules and convex hull meshes).

It is measured exactly at every visual vertex; a triangle whose corners all lie within the
current gap of one single collider cannot raise it (distance to a convex shape is convex, so it
peaks at a corner), and every other triangle is split at its edge midpoints until it is bounded
so or shorter than :data:`SAMPLE_STEP`. The result is exact to within about half a step.

    gap = collider_gap(meshes, meta.collision, hulls)
    gap.distance_m, gap.point        # worst distance and where on the visual surface it is
"""

from __future__ import annotations

import functools
import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Protocol

import numpy as np

from holomj.spec.assets import AssetMeta

SAMPLE_STEP = 0.002  # triangles are split down to this size where a bound is not enough
GAP_LIMIT_M = 0.005  # what a generated asset may leave uncovered
_IDENTITY = np.eye(3)
_NEGLIGIBLE_M = 1e-4  # triangles bounded this close to a collider are not sampled


@dataclass(frozen=True)
class ColliderGap:
    """The result of an audit: the worst distance and the visual point where it occurs."""

    distance_m: float
    point: tuple[float, float, float]
    samples: int  # points measured


def _times(points: np.ndarray, matrix: np.ndarray) -> np.ndarray:
    """``points @ matrix`` for (n, 3) points, without BLAS (whose threads make these small
    products slow on a busy machine)."""
    return (
        points[:, 0:1] * matrix[0][None, :]
        + points[:, 1:2] * matrix[1][None, :]
        + points[:, 2:3] * matrix[2][None, :]
    )


def _rotation(quat: Sequence[float]) -> np.ndarray:
    """The 3x3 rotation matrix of a (w, x, y, z) quaternion (normalised first)."""
    w, x, y, z = np.asarray(quat, dtype=float) / np.linalg.norm(quat)
    return np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
        ]
    )


def _primitive_distance(local: np.ndarray, kind: str, size: Sequence[float]) -> np.ndarray:
    """Distance from points (in the primitive's own frame) to the solid primitive, 0 inside."""
    if kind == "box":
        excess = np.maximum(np.abs(local) - np.asarray(size[:3], dtype=float), 0.0)
        return np.linalg.norm(excess, axis=1)
    if kind == "sphere":
        return np.maximum(np.linalg.norm(local, axis=1) - size[0], 0.0)
    if kind == "cylinder":
        radial = np.maximum(np.hypot(local[:, 0], local[:, 1]) - size[0], 0.0)
        axial = np.maximum(np.abs(local[:, 2]) - size[1], 0.0)
        return np.hypot(radial, axial)
    if kind == "capsule":
        z = np.clip(local[:, 2], -size[1], size[1])
        return np.maximum(
            np.hypot(np.hypot(local[:, 0], local[:, 1]), local[:, 2] - z) - size[0], 0
        )
    raise ValueError(f"unknown collider kind {kind!r}")


class _Hull:
    """A convex hull prepared for distance queries: its planes, triangles and vertices."""

    def __init__(self, vertices: np.ndarray) -> None:
        from scipy.spatial import ConvexHull

        hull = ConvexHull(np.asarray(vertices, dtype=float))
        self.normals, self.offsets = hull.equations[:, :3], hull.equations[:, 3]
        self.triangles = hull.points[hull.simplices]
        self.vertices = hull.points[hull.vertices]

    def signed(self, points: np.ndarray) -> np.ndarray:
        """Signed distance of every point to every face plane ((n, faces); > 0 in front)."""
        return _times(points, self.normals.T) + self.offsets

    def lower(self, points: np.ndarray) -> np.ndarray:
        """A lower bound of the distance (the largest plane distance; 0 inside)."""
        return np.maximum(np.max(self.signed(points), axis=1), 0.0)

    def upper(self, points: np.ndarray) -> np.ndarray:
        """An upper bound of the distance (to the nearest hull vertex; 0 inside)."""
        inside = self.lower(points) <= 1e-12
        nearest = np.sqrt(
            np.min(np.sum((points[:, None, :] - self.vertices[None, :, :]) ** 2, axis=2), axis=1)
        )
        return np.where(inside, 0.0, nearest)

    def distance(self, points: np.ndarray) -> np.ndarray:
        """Exact distance from points to the solid hull (0 inside).

        The nearest point of a convex solid to an outside point lies on a face that faces the
        point, so only (point, face) pairs with the point in front of the face are measured.
        """
        signed = self.signed(points)
        result = np.zeros(len(points))
        rows, faces = np.nonzero(signed > 1e-12)
        if len(rows) == 0:
            return result
        tri = self.triangles[faces]
        pair = _point_triangle_pairs(points[rows], tri[:, 0], tri[:, 1], tri[:, 2])
        best = np.full(len(points), np.inf)
        np.minimum.at(best, rows, pair)
        outside = np.isfinite(best)
        result[outside] = best[outside]
        return result


def hull_distance(points: np.ndarray, hull_vertices: np.ndarray) -> np.ndarray:
    """Exact distance from points to the convex hull of ``hull_vertices`` (0 inside)."""
    return _Hull(hull_vertices).distance(np.asarray(points, dtype=float).reshape(-1, 3))


def _point_triangle_pairs(p: np.ndarray, a: np.ndarray, b: np.ndarray, c: np.ndarray) -> np.ndarray:
    """Distance from each point ``p[k]`` to the triangle ``(a[k], b[k], c[k])`` (all (K, 3)):
    to its plane where the foot falls inside it, else to its nearest edge."""
    normal = np.cross(b - a, c - a)
    length = np.linalg.norm(normal, axis=1, keepdims=True)
    unit = normal / np.where(length > 0, length, 1.0)
    height = np.sum((p - a) * unit, axis=1)
    foot = p - height[:, None] * unit
    inside = length[:, 0] > 0
    for u, v in ((a, b), (b, c), (c, a)):
        inside &= np.sum(np.cross(v - u, foot - u) * normal, axis=1) >= 0
    best = np.where(inside, np.abs(height), np.inf)
    for u, v in ((a, b), (b, c), (c, a)):
        edge = v - u
        denom = np.maximum(np.sum(edge * edge, axis=1), 1e-30)
        t = np.clip(np.sum((p - u) * edge, axis=1) / denom, 0.0, 1.0)
        best = np.minimum(best, np.linalg.norm(p - (u + t[:, None] * edge), axis=1))
    return best


@functools.lru_cache(maxsize=256)
def _cached_hull(vertices: tuple[tuple[float, float, float], ...]) -> _Hull:
    return _Hull(np.asarray(vertices, dtype=float))


class ColliderShape(Protocol):
    """What the audit needs of a collider (a :class:`CollisionPart` or a procedural collider)."""

    @property
    def kind(self) -> str: ...
    @property
    def size(self) -> tuple[float, ...]: ...
    @property
    def pos(self) -> tuple[float, float, float]: ...
    @property
    def quat(self) -> tuple[float, float, float, float]: ...


class ColliderSet:
    """An asset's colliders prepared for distance queries (in the asset frame).

    ``hulls`` maps the index of each ``mesh`` collider to its vertices (in the collider's own
    frame, as its file stores them); without an entry, the collider's own ``vertices`` are
    used (procedural colliders carry them), and a mesh collider with neither is an error.
    """

    def __init__(
        self, collision: Sequence[ColliderShape], hulls: Mapping[int, np.ndarray] | None = None
    ) -> None:
        if not collision:
            raise ValueError("an asset without colliders has no collider gap")
        self.parts = list(collision)
        self._identity = [tuple(part.quat) == (1.0, 0.0, 0.0, 0.0) for part in self.parts]
        self._rotations = [
            _IDENTITY if same else _rotation(part.quat)
            for part, same in zip(self.parts, self._identity, strict=True)
        ]
        self._hulls: dict[int, _Hull] = {}
        for k, part in enumerate(self.parts):
            if part.kind == "mesh":
                given = hulls.get(k) if hulls is not None else None
                own = getattr(part, "vertices", None)
                if given is not None:
                    self._hulls[k] = _Hull(np.asarray(given, dtype=float))
                elif own:
                    self._hulls[k] = _cached_hull(tuple(own))
                else:
                    raise ValueError(f"mesh collider {k} has no hull vertices")

    def _local(self, k: int, points: np.ndarray) -> np.ndarray:
        local = points - np.asarray(self.parts[k].pos, dtype=float)
        return local if self._identity[k] else _times(local, self._rotations[k])

    def table(self, points: np.ndarray) -> np.ndarray:
        """Per point and collider, an upper bound of their distance ((n, m) array) whose minimum
        over the colliders is the exact distance to their union.

        Primitives are exact. A hull is measured exactly where its lower bound (largest plane
        distance) does not rule it out as the nearest collider; elsewhere it gets the distance
        to its nearest vertex (an upper bound, enough for a one-collider triangle bound).
        """
        points = np.asarray(points, dtype=float).reshape(-1, 3)
        result = np.empty((len(points), len(self.parts)))
        hulls = []
        for k, part in enumerate(self.parts):
            local = self._local(k, points)
            if part.kind == "mesh":
                hull = self._hulls[k]
                hulls.append((k, local, hull.lower(local)))
                result[:, k] = hull.upper(local)
            else:
                result[:, k] = _primitive_distance(local, part.kind, part.size)
        union = result.min(axis=1)
        for k, local, lower in hulls:
            rows = np.flatnonzero((lower < union) & (result[:, k] > 0.0))
            if len(rows):
                result[rows, k] = self._hulls[k].distance(local[rows])
                union[rows] = np.minimum(union[rows], result[rows, k])
        return result

    def outside(self, points: np.ndarray) -> np.ndarray:
        """Distance from every point to the union of the colliders (0 inside any of them).

        Primitives are measured first; a hull is measured exactly only for the points its
        lower bound does not already rule out.
        """
        points = np.asarray(points, dtype=float).reshape(-1, 3)
        best = np.full(len(points), np.inf)
        hulls = []
        for k, part in enumerate(self.parts):
            if part.kind == "mesh":
                hulls.append(k)
                continue
            todo = np.flatnonzero(best > 0.0)
            distance = _primitive_distance(self._local(k, points[todo]), part.kind, part.size)
            best[todo] = np.minimum(best[todo], distance)
        lower: dict[int, tuple[np.ndarray, np.ndarray]] = {}
        for k in hulls:
            todo = np.flatnonzero(best > 0.0)
            bound = self._hulls[k].lower(self._local(k, points[todo]))
            best[todo[bound <= 1e-12]] = 0.0
            lower[k] = (todo, bound)
        for k in hulls:
            todo, bound = lower[k]
            keep = (bound < best[todo]) & (best[todo] > 0.0)
            rows = todo[keep]
            if len(rows):
                distance = self._hulls[k].distance(self._local(k, points[rows]))
                best[rows] = np.minimum(best[rows], distance)
        return best


def outside_distance(
    points: np.ndarray,
    collision: Sequence[ColliderShape],
    hulls: Mapping[int, np.ndarray] | None = None,
) -> np.ndarray:
    """Distance from each point to the union of the colliders (0 inside any of them)."""
    return ColliderSet(collision, hulls).outside(points)


def collider_gap(
    meshes: Iterable[tuple[np.ndarray, np.ndarray]],
    collision: Sequence[ColliderShape],
    hulls: Mapping[int, np.ndarray] | None = None,
    step: float = SAMPLE_STEP,
    stop_above: float = math.inf,
) -> ColliderGap:
    """The largest distance from the visual surface ``meshes`` ((vertices, faces) pairs, in the
    asset frame) to the union of ``collision`` (see :func:`mesh_gaps`)."""
    gaps, point, count = mesh_gaps(meshes, collision, hulls, step, stop_above)
    return ColliderGap(float(gaps.max()), point, count)


def mesh_gaps(
    meshes: Iterable[tuple[np.ndarray, np.ndarray]],
    collision: Sequence[ColliderShape],
    hulls: Mapping[int, np.ndarray] | None = None,
    step: float = SAMPLE_STEP,
    stop_above: float = math.inf,
) -> tuple[np.ndarray, tuple[float, float, float], int]:
    """The gap of each of ``meshes`` to the union of ``collision``, the point where the largest
    one occurs, and the number of points measured.

    Two bounds close a triangle: distance to one convex collider is a convex function, so over
    a triangle it peaks at a corner (a triangle whose corners all lie within d of one collider
    lies within d of it everywhere); and distance to the union is 1-Lipschitz, so no point of a
    triangle is further than its farthest corner plus ``longest edge / sqrt(3)``. A triangle
    neither bound keeps within its mesh's gap found so far (plus ``step / 2``) is split in four
    at its edge midpoints, measured exactly, until it is no longer than ``step``: the work goes
    to the seams between colliders and to what sticks out, and each gap is exact to within
    ``step / 2``. A mesh whose gap exceeds ``stop_above`` is not searched further (enough to
    know that it does).
    """
    colliders = ColliderSet(collision, hulls)
    vertex_list, face_list, owner_list, offset = [], [], [], 0
    for index, (vertices, faces) in enumerate(meshes):
        vertices = np.asarray(vertices, dtype=float).reshape(-1, 3)
        faces = np.asarray(faces, dtype=np.int64).reshape(-1, 3)
        vertex_list.append(vertices)
        face_list.append(faces + offset)
        owner_list.append(np.full(len(vertices), index, dtype=np.int64))
        offset += len(vertices)
    if not vertex_list:
        raise ValueError("no visual mesh to audit")
    vertices, faces = np.concatenate(vertex_list), np.concatenate(face_list)
    vertex_owner = np.concatenate(owner_list)
    table = colliders.table(vertices)
    union = table.min(axis=1)
    gaps = np.zeros(len(vertex_list))
    np.maximum.at(gaps, vertex_owner, union)
    worst = int(np.argmax(union))
    gap, point = float(union[worst]), vertices[worst]
    count = len(vertices)
    owner = vertex_owner[faces[:, 0]]
    corners, distances = vertices[faces], table[faces]  # (k, 3, 3) and (k, 3, m)
    slack = 0.5 * step
    while len(corners):
        single = distances.max(axis=1).min(axis=1)  # best single collider per triangle
        edges = corners - np.roll(corners, -1, axis=1)
        longest = np.sqrt(np.max(np.sum(edges * edges, axis=2), axis=1))
        lipschitz = distances.min(axis=2).max(axis=1) + longest / math.sqrt(3.0)
        bound = np.minimum(single, lipschitz)
        known = gaps[owner]
        split = (
            (bound > np.maximum(known + slack, _NEGLIGIBLE_M))
            & (longest > step)
            & (known <= stop_above)
        )
        corners, distances, owner = corners[split], distances[split], owner[split]
        if not len(corners):
            break
        mids = 0.5 * (corners + np.roll(corners, -1, axis=1))  # ab, bc, ca
        mid_table = colliders.table(mids.reshape(-1, 3)).reshape(len(mids), 3, -1)
        count += 3 * len(mids)
        mid_union = mid_table.min(axis=2)
        np.maximum.at(gaps, owner, mid_union.max(axis=1))
        k = int(np.argmax(mid_union))
        if mid_union.reshape(-1)[k] > gap:
            gap, point = float(mid_union.reshape(-1)[k]), mids.reshape(-1, 3)[k]
        a, b, c = corners[:, 0], corners[:, 1], corners[:, 2]
        ab, bc, ca = mids[:, 0], mids[:, 1], mids[:, 2]
        da, db, dc = distances[:, 0], distances[:, 1], distances[:, 2]
        dab, dbc, dca = mid_table[:, 0], mid_table[:, 1], mid_table[:, 2]
        corners = np.concatenate(
            [
                np.stack([a, ab, ca], axis=1),
                np.stack([ab, b, bc], axis=1),
                np.stack([ca, bc, c], axis=1),
                np.stack([ab, bc, ca], axis=1),
            ]
        )
        distances = np.concatenate(
            [
                np.stack([da, dab, dca], axis=1),
                np.stack([dab, db, dbc], axis=1),
                np.stack([dca, dbc, dc], axis=1),
                np.stack([dab, dbc, dca], axis=1),
            ]
        )
        owner = np.tile(owner, 4)
    x, y, z = (float(v) for v in point)
    return gaps, (x, y, z), count


def read_obj(path: Path) -> tuple[np.ndarray, np.ndarray]:
    """Vertices and triangles of an OBJ file (polygons fanned; texture/normal indices dropped)."""
    vertices: list[list[float]] = []
    faces: list[list[int]] = []
    for line in path.read_text(encoding="utf-8", errors="replace").splitlines():
        fields = line.split()
        if not fields:
            continue
        if fields[0] == "v":
            vertices.append([float(v) for v in fields[1:4]])
        elif fields[0] == "f":
            ids = [int(f.split("/")[0]) for f in fields[1:]]
            ids = [i - 1 if i > 0 else len(vertices) + i for i in ids]
            faces += [[ids[0], ids[k], ids[k + 1]] for k in range(1, len(ids) - 1)]
    return np.asarray(vertices, dtype=float).reshape(-1, 3), np.asarray(
        faces, dtype=np.int64
    ).reshape(-1, 3)


def _read_mesh(path: Path) -> tuple[np.ndarray, np.ndarray]:
    if path.suffix.lower() == ".obj":
        return read_obj(path)
    import trimesh

    mesh = trimesh.load(path, force="mesh", process=False)
    if not isinstance(mesh, trimesh.Trimesh):  # force="mesh" concatenates a scene into one
        raise ValueError(f"{path}: not a triangle mesh")
    return np.asarray(mesh.vertices, dtype=float), np.asarray(mesh.faces, dtype=np.int64)


def audit_asset_folder(folder: Path, meta: AssetMeta, step: float = SAMPLE_STEP) -> ColliderGap:
    """The collider gap of an asset written to ``folder`` (its meshes read from disk)."""
    meshes = [_read_mesh(folder / part.mesh) for part in meta.visual]
    hulls = {
        k: _read_mesh(folder / part.mesh)[0]
        for k, part in enumerate(meta.collision)
        if part.kind == "mesh" and part.mesh is not None
    }
    return collider_gap(meshes, meta.collision, hulls, step)


def round_gap(distance: float) -> float:
    """A gap as metadata records it: metres, to 0.1 mm, never ``-0.0``."""
    return math.floor(distance * 1e4 + 0.5) / 1e4 + 0.0


def gap_summary(metas: Iterable[AssetMeta], limit: float = GAP_LIMIT_M) -> dict[str, object]:
    """A build summary of recorded gaps: per category its worst asset and gap (millimetres),
    the assets over ``limit``, and how many assets were not measured."""
    worst: dict[str, tuple[float, str]] = {}
    over: list[tuple[float, str]] = []
    unmeasured = 0
    for meta in metas:
        if meta.collider_gap_m is None:
            unmeasured += 1
            continue
        gap = meta.collider_gap_m
        if meta.category not in worst or gap > worst[meta.category][0]:
            worst[meta.category] = (gap, meta.id)
        if gap > limit:
            over.append((gap, meta.id))
    return {
        "limit_mm": limit * 1000.0,
        "worst_mm": max((g for g, _ in worst.values()), default=0.0) * 1000.0,
        "over_limit": {asset: round(gap * 1000.0, 1) for gap, asset in sorted(over, reverse=True)},
        "unmeasured": unmeasured,
        "categories": {
            category: {"asset": asset, "gap_mm": round(gap * 1000.0, 1)}
            for category, (gap, asset) in sorted(worst.items())
        },
    }
