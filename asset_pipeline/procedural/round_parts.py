"""Round parts: cylinders, surfaces of revolution (lathes) and spheres.

Round parts are drawn as polygons with :data:`SEGMENTS` sides whose vertices lie on the true
radius (vertices on the +-X and +-Y axes, so the bounding box is exact). No collider ever sticks
out of the visual mesh, and every collider covers its visual within :data:`COVER_TOLERANCE`:
a straight piece is a cylinder of the inscribed radius where that leaves little enough
uncovered, and otherwise (a steep taper such as a lamp shade or a basin, a wide disc) the convex
hull of the visual polygon rings themselves, which is exact.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass, replace

import numpy as np

from asset_pipeline.procedural.parts import (
    EDGE_MARGIN,
    Axis,
    Collider,
    Mesh,
    RecipeMaterial,
    RecipeSurface,
    Vec3,
    add3,
    axis_extents,
    hull_collider,
    sub3,
)

SEGMENTS = 24  # sides of round parts; a multiple of 4
INSCRIBED = math.cos(math.pi / SEGMENTS)  # inscribed / circumscribed radius of the polygon
COVER_TOLERANCE = 0.0025  # how much of a round visual a primitive collider may leave uncovered


def _unit_circle() -> tuple[np.ndarray, np.ndarray]:
    """Cosines and sines of the :data:`SEGMENTS` polygon angles, axis directions exact."""
    angles = np.arange(SEGMENTS) * (2.0 * math.pi / SEGMENTS)
    cos, sin = np.cos(angles), np.sin(angles)
    cos[np.abs(cos) < 1e-12] = 0.0
    sin[np.abs(sin) < 1e-12] = 0.0
    return cos, sin


def ring_points(rings: list[tuple[float, float]], base: Vec3) -> np.ndarray:
    """The visual polygon vertices of rings (radius, height) about a vertical axis through
    ``base`` (a ring of radius 0 is its centre point): exactly the vertices
    :func:`lathe_mesh` draws for them."""
    cos, sin = _unit_circle()
    points = []
    for r, z in rings:
        if r <= 1e-12:
            points.append(np.array([[0.0, 0.0, z]]))
        else:
            points.append(np.stack([r * cos, r * sin, np.full(SEGMENTS, z)], axis=1))
    return np.concatenate(points) + np.asarray(base, dtype=float)


@dataclass(frozen=True)
class Lathe:
    """A surface of revolution about a vertical axis through ``base`` (its bottom centre).

    ``outer`` lists (radius, height above base) from bottom to top, heights non-decreasing.
    With ``hollow=(wall, floor)`` the top is open: an inner wall ``wall`` thick runs down to
    a floor at height ``floor`` (a mug, a bowl, a pot). The colliders are stacked cylinders,
    one per profile segment, with the segment's smaller radius, inscribed.
    """

    base: Vec3
    outer: tuple[tuple[float, float], ...]
    material: RecipeMaterial
    hollow: tuple[float, float] | None = None
    visual: bool = True
    collide: bool = True
    surface: bool = False

    def profile(self) -> list[tuple[float, float]]:
        """The closed meridian profile, counter-clockwise in the (r, z) half plane."""
        outer = list(self.outer)
        points = [(0.0, outer[0][1]), *outer]
        if self.hollow is None:
            points.append((0.0, outer[-1][1]))
        else:
            wall, floor = self.hollow
            r_top, z_top = outer[-1]
            points += [(r_top - wall, z_top), (_radius_at(outer, floor) - wall, floor)]
            points.append((0.0, floor))
        return points

    def mesh(self) -> Mesh | None:
        if not self.visual:
            return None
        return lathe_mesh(self.profile()).translated(self.base)

    def colliders(self) -> list[Collider]:
        if not self.collide:
            return []
        result = []
        for (r0, z0), (r1, z1) in itertools.pairwise(self.outer):
            if z1 - z0 <= 1e-9 or max(r0, r1) <= 1e-12:
                continue
            radius = min(r0, r1) * INSCRIBED
            if max(r0, r1) - radius <= COVER_TOLERANCE:
                center = add3(self.base, (0.0, 0.0, 0.5 * (z0 + z1)))
                result.append(Collider("cylinder", (radius, 0.5 * (z1 - z0)), center))
            else:  # a taper: the frustum's own hull
                result.append(hull_collider(ring_points([(r0, z0), (r1, z1)], self.base)))
        return result

    def bounds(self) -> tuple[Vec3, Vec3] | None:
        if not self.visual:
            return None
        r = max(r for r, _ in self.outer)
        bx, by, bz = self.base
        low = (bx - r, by - r, bz + self.outer[0][1])
        return low, (bx + r, by + r, bz + self.outer[-1][1])

    def surfaces(self) -> list[RecipeSurface]:
        if not self.surface:
            return []
        r_top, z_top = self.outer[-1]
        radius = r_top * INSCRIBED - EDGE_MARGIN
        return [RecipeSurface(self.base[2] + z_top, circle(self.base[0], self.base[1], radius))]

    def translated(self, offset: Vec3) -> Lathe:
        return replace(self, base=add3(self.base, offset))


@dataclass(frozen=True)
class Cylinder:
    """A cylinder given by its centre, radius and half-length along ``axis``."""

    center: Vec3
    radius: float
    half_length: float
    material: RecipeMaterial
    axis: Axis = "z"
    visual: bool = True
    collide: bool = True
    surface: bool = False

    def mesh(self) -> Mesh | None:
        if not self.visual:
            return None
        h = self.half_length
        local = lathe_mesh([(0.0, -h), (self.radius, -h), (self.radius, h), (0.0, h)])
        vertices = local.vertices
        if self.axis == "x":
            vertices = np.stack([vertices[:, 2], vertices[:, 1], -vertices[:, 0]], axis=1)
        elif self.axis == "y":
            vertices = np.stack([vertices[:, 0], vertices[:, 2], -vertices[:, 1]], axis=1)
        return Mesh(vertices, local.faces).translated(self.center)

    def colliders(self) -> list[Collider]:
        if not self.collide:
            return []
        if self.visual and self.radius * (1.0 - INSCRIBED) > COVER_TOLERANCE:
            mesh = self.mesh()
            assert mesh is not None
            return [hull_collider(mesh.vertices)]  # a wide disc: the prism itself
        radius = self.radius * INSCRIBED if self.visual else self.radius
        return [Collider("cylinder", (radius, self.half_length), self.center, self.axis)]

    def bounds(self) -> tuple[Vec3, Vec3] | None:
        if not self.visual:
            return None
        ext = axis_extents(self.radius, self.half_length, self.axis)
        return sub3(self.center, ext), add3(self.center, ext)

    def surfaces(self) -> list[RecipeSurface]:
        if not self.surface:
            return []
        if self.axis != "z":
            raise ValueError("only an upright cylinder has a flat top")
        radius = self.radius * INSCRIBED - EDGE_MARGIN
        cx, cy, cz = self.center
        return [RecipeSurface(cz + self.half_length, circle(cx, cy, radius))]

    def translated(self, offset: Vec3) -> Cylinder:
        return replace(self, center=add3(self.center, offset))


@dataclass(frozen=True)
class Sphere:
    """A sphere, optionally cut flat at height ``cut`` (an absolute z below the centre).

    Its collider is the inscribed sphere (kept above the cut); a cut sphere also gets a short
    inscribed cylinder at its flat base so that it rests without rolling. Where the cut keeps
    that sphere well inside the visual (a ball cut near its equator), the collider is the
    convex hull of the visual mesh itself instead.
    """

    center: Vec3
    radius: float
    material: RecipeMaterial
    cut: float | None = None
    rings: int = 10
    visual: bool = True
    collide: bool = True

    def _start_angle(self) -> float:
        if self.cut is None:
            return 0.0
        return math.acos((self.center[2] - self.cut) / self.radius)

    def _angles(self) -> list[float]:
        """Polar angles of the profile rings, from the bottom; the equator is always one."""
        start, half = self._start_angle(), math.pi / 2.0
        below = max(1, math.ceil((half - start) / (math.pi / self.rings) - 1e-9))
        above = max(1, self.rings // 2)
        lower = [start + (half - start) * i / below for i in range(below)]
        return lower + [half + half * i / above for i in range(above + 1)]

    def _cut_radius(self) -> float:
        return self.radius * math.sin(self._start_angle())

    def mesh(self) -> Mesh | None:
        if not self.visual:
            return None
        points = [(self.radius * math.sin(a), -self.radius * math.cos(a)) for a in self._angles()]
        points[-1] = (0.0, self.radius)
        profile = [(0.0, points[0][1]), *points] if self.cut is not None else points
        profile[0] = (0.0, profile[0][1])
        return lathe_mesh(profile).translated(self.center)

    def colliders(self) -> list[Collider]:
        if not self.collide:
            return []
        angles = self._angles()
        step = max(b - a for a, b in itertools.pairwise(angles))
        radius = self.radius * INSCRIBED * math.cos(step / 2.0)
        result = [Collider("sphere", (radius,), self.center)]
        if self.cut is not None:
            limited = min(radius, self.center[2] - self.cut)
            if self.visual and radius - limited > COVER_TOLERANCE:
                mesh = self.mesh()  # the cut keeps an inscribed sphere far from the equator
                assert mesh is not None
                return [hull_collider(mesh.vertices)]
            base_r = self._cut_radius() * INSCRIBED
            half = 0.1 * self.radius
            center = (self.center[0], self.center[1], self.cut + half)
            result = [
                Collider("sphere", (limited,), self.center),
                Collider("cylinder", (base_r, half), center),
            ]
        return result

    def bounds(self) -> tuple[Vec3, Vec3] | None:
        if not self.visual:
            return None
        r = self.radius
        low = sub3(self.center, (r, r, r))
        if self.cut is not None:
            low = (low[0], low[1], self.cut)
        return low, add3(self.center, (r, r, r))

    def surfaces(self) -> list[RecipeSurface]:
        return []

    def translated(self, offset: Vec3) -> Sphere:
        cut = None if self.cut is None else self.cut + offset[2]
        return replace(self, center=add3(self.center, offset), cut=cut)


def lathe_mesh(profile: list[tuple[float, float]]) -> Mesh:
    """Revolve a closed (r, z) profile (counter-clockwise, ends on the axis) about +Z.

    Points with r = 0 become single pole vertices; every other point a ring of
    :data:`SEGMENTS` vertices starting on +X. Triangles face outward.
    """
    cos, sin = _unit_circle()  # axis directions snapped so that bounds are exact
    vertices: list[np.ndarray] = []
    rings: list[list[int] | int] = []
    count = 0
    for r, z in profile:
        if r <= 1e-12:
            vertices.append(np.array([[0.0, 0.0, z]]))
            rings.append(count)
            count += 1
        else:
            vertices.append(np.stack([r * cos, r * sin, np.full(SEGMENTS, z)], axis=1))
            rings.append(list(range(count, count + SEGMENTS)))
            count += SEGMENTS
    faces: list[tuple[int, int, int]] = []
    for lower, upper in itertools.pairwise(rings):
        for k in range(SEGMENTS):
            k1 = (k + 1) % SEGMENTS
            if isinstance(lower, int) and isinstance(upper, int):
                raise ValueError("two consecutive profile points on the axis")
            if isinstance(lower, int):
                assert isinstance(upper, list)
                faces.append((lower, upper[k1], upper[k]))
            elif isinstance(upper, int):
                faces.append((lower[k], lower[k1], upper))
            else:
                faces.append((lower[k], lower[k1], upper[k1]))
                faces.append((lower[k], upper[k1], upper[k]))
    return Mesh(np.concatenate(vertices), np.array(faces, dtype=np.int64))


def circle(cx: float, cy: float, radius: float) -> tuple[tuple[float, float], ...]:
    """A counter-clockwise polygon with :data:`SEGMENTS` vertices on a circle."""
    if radius <= 0.0:
        raise ValueError("support surface vanishes after erosion")
    return tuple(
        (
            cx + radius * math.cos(2.0 * math.pi * k / SEGMENTS),
            cy + radius * math.sin(2.0 * math.pi * k / SEGMENTS),
        )
        for k in range(SEGMENTS)
    )


def _radius_at(outer: list[tuple[float, float]], z: float) -> float:
    """Radius of the outer profile at height ``z`` (linear between points)."""
    for (r0, z0), (r1, z1) in itertools.pairwise(outer):
        if z0 <= z <= z1 and z1 > z0:
            return r0 + (r1 - r0) * (z - z0) / (z1 - z0)
    raise ValueError(f"height {z} is outside the profile")
