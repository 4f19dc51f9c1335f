"""Building blocks of procedural assets: materials, meshes, colliders, surfaces and boxes.

Every part knows its visual triangle mesh, its MuJoCo colliders, its axis-aligned bounds and,
when asked, the support surface on its top. Round parts live in :mod:`.round_parts`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Any, ClassVar, Literal, Protocol

import numpy as np

Vec3 = tuple[float, float, float]
Vec4 = tuple[float, float, float, float]
Rect = tuple[float, float, float, float]  # xmin, xmax, ymin, ymax
Axis = Literal["x", "y", "z"]

EDGE_MARGIN = 0.02  # support surfaces are eroded by this much from the part's edges

_QUAT_FOR_AXIS: dict[str, Vec4] = {
    "z": (1.0, 0.0, 0.0, 0.0),
    "x": (math.sqrt(0.5), 0.0, math.sqrt(0.5), 0.0),  # local z -> world x
    "y": (math.sqrt(0.5), -math.sqrt(0.5), 0.0, 0.0),  # local z -> world y
}
_BOX_FACES = np.array(
    [
        [0, 2, 1], [0, 3, 2], [4, 5, 6], [4, 6, 7], [0, 1, 5], [0, 5, 4],
        [1, 2, 6], [1, 6, 5], [2, 3, 7], [2, 7, 6], [3, 0, 4], [3, 4, 7],
    ],
    dtype=np.int64,
)  # fmt: skip


@dataclass(frozen=True)
class RecipeMaterial:
    """A named colour; every material becomes one visual mesh file of the asset.

    ``pattern`` chooses the procedural texture the colour tints (see
    :mod:`asset_pipeline.procedural.textures`): None infers it from the label and name words
    (oak -> wood, linen -> fabric, ...), ``"plain"`` keeps the material untextured, and a
    pattern name (``"wood"``, ``"leather"``, ...) forces that pattern.
    """

    name: str
    rgba: Vec4
    specular: float = 0.3
    shininess: float = 0.3
    label: str = ""
    pattern: str | None = None

    @property
    def words(self) -> str:
        """How a description names this material (``label`` or the name with spaces)."""
        return self.label or self.name.replace("_", " ")


@dataclass(frozen=True)
class Mesh:
    """A triangle mesh: float vertices (n, 3) and 0-based triangle indices (m, 3).

    A textured mesh also has texture coordinates ``uv`` (k, 2) and, per triangle corner, the
    index of its texture coordinate ``uv_faces`` (m, 3) (a vertex shared by faces projected
    differently has several).
    """

    vertices: np.ndarray
    faces: np.ndarray
    uv: np.ndarray | None = None
    uv_faces: np.ndarray | None = None

    def translated(self, offset: Vec3) -> Mesh:
        """This mesh moved by ``offset`` (texture coordinates stay)."""
        return replace(self, vertices=self.vertices + np.asarray(offset, dtype=float))


@dataclass(frozen=True)
class Collider:
    """A MuJoCo collider: a primitive, ``size`` in half-sizes as MuJoCo takes them, or a convex
    hull (``kind="mesh"``) of ``vertices`` given relative to ``pos`` (its bounding-box centre).
    """

    kind: Literal["box", "cylinder", "sphere", "mesh"]
    size: tuple[float, ...]
    pos: Vec3
    axis: Axis = "z"
    vertices: tuple[Vec3, ...] = ()

    @property
    def quat(self) -> Vec4:
        """Orientation taking the primitive's local z onto ``axis``."""
        return _QUAT_FOR_AXIS[self.axis]

    @property
    def volume(self) -> float:
        """Volume in m^3, as MuJoCo computes it for the primitive (or the hull)."""
        if self.kind == "box":
            return 8.0 * self.size[0] * self.size[1] * self.size[2]
        if self.kind == "cylinder":
            return 2.0 * math.pi * self.size[0] ** 2 * self.size[1]
        if self.kind == "mesh":
            return hull_volume(np.asarray(self.vertices, dtype=float))
        return 4.0 / 3.0 * math.pi * self.size[0] ** 3

    def half_extents(self) -> Vec3:
        """Half extents of the axis-aligned bounding box (about ``pos``)."""
        if self.kind == "box":
            return (self.size[0], self.size[1], self.size[2])
        if self.kind == "sphere":
            return (self.size[0],) * 3
        if self.kind == "mesh":
            hx, hy, hz = np.abs(np.asarray(self.vertices, dtype=float)).max(axis=0)
            return (float(hx), float(hy), float(hz))
        radius, half = self.size
        return axis_extents(radius, half, self.axis)

    def translated(self, offset: Vec3) -> Collider:
        """This collider moved by ``offset``."""
        return replace(self, pos=add3(self.pos, offset))


def hull_collider(points: np.ndarray) -> Collider:
    """A convex-hull collider through ``points`` (n, 3) in the asset frame; its ``pos`` is the
    centre of their bounding box. The points must span a volume."""
    points = np.asarray(points, dtype=float).reshape(-1, 3)
    centre = 0.5 * (points.min(axis=0) + points.max(axis=0))
    relative = points - centre
    pos: Vec3 = (float(centre[0]), float(centre[1]), float(centre[2]))
    vertices = tuple((float(x), float(y), float(z)) for x, y, z in relative)
    return Collider("mesh", (), pos, vertices=vertices)


def hull_volume(points: np.ndarray) -> float:
    """Volume of the convex hull of ``points`` (n, 3)."""
    from scipy.spatial import ConvexHull

    return float(ConvexHull(np.asarray(points, dtype=float)).volume)


@dataclass(frozen=True)
class RecipeSurface:
    """An upward support surface: its height and its (already eroded) polygon."""

    height: float
    polygon: tuple[tuple[float, float], ...]

    def translated(self, offset: Vec3) -> RecipeSurface:
        """This surface moved by ``offset``."""
        dx, dy, dz = offset
        return RecipeSurface(self.height + dz, tuple((x + dx, y + dy) for x, y in self.polygon))


class Part(Protocol):
    """What an asset is made of (parts are frozen dataclasses, so the material is read-only and
    ``dataclasses.replace`` makes a changed copy)."""

    __dataclass_fields__: ClassVar[dict[str, Any]]

    @property
    def material(self) -> RecipeMaterial:
        """The part's material."""

    def mesh(self) -> Mesh | None:
        """The visual mesh, or None for a collider-only part."""

    def colliders(self) -> list[Collider]:
        """The part's colliders (possibly none)."""

    def bounds(self) -> tuple[Vec3, Vec3] | None:
        """Low and high corners of the visual mesh, or None for a collider-only part."""

    def surfaces(self) -> list[RecipeSurface]:
        """Support surfaces on the part's top."""

    def translated(self, offset: Vec3) -> Part:
        """This part moved by ``offset``."""


@dataclass(frozen=True)
class Box:
    """An axis-aligned box given by its centre and half-sizes.

    ``surface`` makes the top a support surface: ``True`` for the whole top, or a rectangle
    (xmin, xmax, ymin, ymax) to clip it to, e.g. to leave out the pillows on a bed.
    """

    center: Vec3
    half: Vec3
    material: RecipeMaterial
    visual: bool = True
    collide: bool = True
    surface: bool | Rect = False

    def mesh(self) -> Mesh | None:
        if not self.visual:
            return None
        c, h = np.asarray(self.center), np.asarray(self.half)
        signs = np.array(
            [[-1, -1, -1], [1, -1, -1], [1, 1, -1], [-1, 1, -1],
             [-1, -1, 1], [1, -1, 1], [1, 1, 1], [-1, 1, 1]],
            dtype=float,
        )  # fmt: skip
        return Mesh(c + signs * h, _BOX_FACES.copy())

    def colliders(self) -> list[Collider]:
        return [Collider("box", self.half, self.center)] if self.collide else []

    def bounds(self) -> tuple[Vec3, Vec3] | None:
        if not self.visual:
            return None
        return sub3(self.center, self.half), add3(self.center, self.half)

    def surfaces(self) -> list[RecipeSurface]:
        if self.surface is False:
            return []
        (cx, cy, cz), (hx, hy, hz) = self.center, self.half
        rect = (cx - hx, cx + hx, cy - hy, cy + hy)
        if self.surface is not True:
            clip = self.surface
            rect = (
                max(rect[0], clip[0]),
                min(rect[1], clip[1]),
                max(rect[2], clip[2]),
                min(rect[3], clip[3]),
            )
        x0, x1, y0, y1 = (
            rect[0] + EDGE_MARGIN,
            rect[1] - EDGE_MARGIN,
            rect[2] + EDGE_MARGIN,
            rect[3] - EDGE_MARGIN,
        )
        if x1 <= x0 or y1 <= y0:
            raise ValueError(f"support surface of {self} vanishes after erosion")
        return [RecipeSurface(cz + hz, ((x0, y0), (x1, y0), (x1, y1), (x0, y1)))]

    def translated(self, offset: Vec3) -> Box:
        return replace(self, center=add3(self.center, offset))


def axis_extents(radius: float, half: float, axis: Axis) -> Vec3:
    """Half extents of the bounding box of a cylinder along ``axis``."""
    return {"x": (half, radius, radius), "y": (radius, half, radius), "z": (radius, radius, half)}[
        axis
    ]


def add3(a: Vec3, b: Vec3) -> Vec3:
    """a + b."""
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def sub3(a: Vec3, b: Vec3) -> Vec3:
    """a - b."""
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])
