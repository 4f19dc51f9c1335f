"""Support surfaces and footprints in world coordinates, and sampling poses on them.

An asset's :class:`~holomj.spec.assets.SupportSurface` lives in the asset frame; here it is
scaled and moved to the receptacle's pose in the scene. The interior surfaces of an articulated
asset (:class:`~holomj.spec.assets.InteriorSurface`: shelves behind doors, drawer bottoms) are
placed the same way, at the closed pose (:func:`world_interior_surfaces`). Receptacles are
assumed to stand upright: only the yaw of their orientation is used (the surfaces of a tilted
table are not supports).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from shapely import affinity
from shapely.geometry import Point, Polygon
from shapely.geometry.polygon import orient
from shapely.prepared import prep

from holomj.spec.assets import AssetMeta
from holomj.spec.scene import SceneObject


@dataclass(frozen=True)
class WorldSurface:
    """A support surface of a receptacle at its pose in the scene."""

    index: int  # position in the asset's ``surfaces`` list (``articulation.interior`` inside)
    height: float  # world z of the surface
    polygon: Polygon  # world x/y
    clearance: float  # free height above it up to the next surface of the same asset (inf: none)
    interior: bool = False  # inside the asset (behind a door, in a drawer)
    part: str | None = None  # the moving part it lies on (None: the carcass)

    @property
    def area(self) -> float:
        """Area in m²."""
        return float(self.polygon.area)


def object_yaw(obj: SceneObject) -> float:
    """The yaw of an object in radians (from its quaternion when it has one)."""
    if obj.quat is None:
        return math.radians(obj.yaw_deg)
    w, x, y, z = obj.quat
    return math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))


def world_surfaces(obj: SceneObject, meta: AssetMeta) -> list[WorldSurface]:
    """The receptacle's support surfaces, scaled and placed at the object's pose."""
    sz = obj.scale3[2]
    pz = obj.position[2]
    heights = sorted(s.height * sz for s in meta.surfaces)
    surfaces = []
    for index, surface in enumerate(meta.surfaces):
        poly = _placed_outline(obj, surface.polygon)
        if poly is None:
            continue
        height = surface.height * sz
        above = [h for h in heights if h > height + 1e-6]
        clearance = (min(above) - height) if above else math.inf
        surfaces.append(WorldSurface(index, pz + height, poly, clearance))
    return surfaces


def world_interior_surfaces(obj: SceneObject, meta: AssetMeta) -> list[WorldSurface]:
    """The interior surfaces of an articulated receptacle at the object's pose, its parts
    closed; their clearance is the free height inside (``clearance_m``). Empty for a rigid
    asset."""
    if meta.articulation is None:
        return []
    sz = obj.scale3[2]
    pz = obj.position[2]
    surfaces = []
    for index, surface in enumerate(meta.articulation.interior):
        poly = _placed_outline(obj, surface.polygon)
        if poly is None:
            continue
        clearance = surface.clearance_m * sz if surface.clearance_m is not None else math.inf
        surfaces.append(
            WorldSurface(
                index, pz + surface.height * sz, poly, clearance, interior=True, part=surface.part
            )
        )
    return surfaces


def _placed_outline(obj: SceneObject, outline: Sequence[Sequence[float]]) -> Polygon | None:
    """A surface outline in the asset frame scaled, turned and moved to the object's pose
    (counter-clockwise); None when it is empty or falls apart."""
    sx, sy, _ = obj.scale3
    poly = Polygon([(x * sx, y * sy) for x, y in outline])
    if not poly.is_valid:
        poly = poly.buffer(0)
    if poly.is_empty or poly.geom_type != "Polygon":
        return None
    poly = affinity.rotate(poly, object_yaw(obj), origin=(0.0, 0.0), use_radians=True)
    return orient(affinity.translate(poly, obj.position[0], obj.position[1]), 1.0)


def footprint(meta: AssetMeta, scale: tuple[float, float, float]) -> tuple[float, float]:
    """Half-extents (x, y) of an asset's footprint rectangle at a scale."""
    return meta.size[0] * scale[0] / 2.0, meta.size[1] * scale[1] / 2.0


def footprint_polygon(half: tuple[float, float], x: float, y: float, yaw: float) -> Polygon:
    """The footprint rectangle centred at (x, y) turned by ``yaw`` radians."""
    hx, hy = half
    c, s = math.cos(yaw), math.sin(yaw)
    corners = [(-hx, -hy), (hx, -hy), (hx, hy), (-hx, hy)]
    return Polygon([(x + c * a - s * b, y + s * a + c * b) for a, b in corners])


@dataclass
class SurfaceSampler:
    """Samples footprint-centred points with a yaw such that the footprint lies on a surface.

    The centre is drawn uniformly from the surface eroded by the footprint's inner radius (a
    necessary condition), then the turned footprint rectangle must lie inside the surface; up to
    ``tries`` draws per call.
    """

    surface: WorldSurface
    half: tuple[float, float]
    tries: int = 64

    def __post_init__(self) -> None:
        inner = min(self.half)
        self._region = self.surface.polygon.buffer(-inner, join_style="mitre")
        self._prepared = prep(self.surface.polygon)
        self._bounds = self._region.bounds if not self._region.is_empty else None
        self._prepared_region = prep(self._region) if not self._region.is_empty else None

    @property
    def feasible(self) -> bool:
        """False when no footprint centre can possibly fit."""
        return self._bounds is not None and self._region.area > 1e-8

    def sample(self, rng: np.random.Generator) -> tuple[float, float, float] | None:
        """(x, y, yaw) with the footprint inside the surface, or None after ``tries`` draws."""
        if not self.feasible or self._bounds is None or self._prepared_region is None:
            return None
        x0, y0, x1, y1 = self._bounds
        for _ in range(self.tries):
            x = float(rng.uniform(x0, x1))
            y = float(rng.uniform(y0, y1))
            yaw = float(rng.uniform(-math.pi, math.pi))
            if not self._prepared_region.contains(Point(x, y)):
                continue
            if self._prepared.contains(footprint_polygon(self.half, x, y, yaw)):
                return x, y, yaw
        return None
