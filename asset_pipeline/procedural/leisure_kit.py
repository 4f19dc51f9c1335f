"""Shared palette and slanted-part builders of the leisure generators (``leisure_*.py``).

Every generator fills exactly ``[-d/2, d/2] x [-w/2, w/2] x [0, h]`` (x = depth, y = width).
Slanted pieces (tripod legs, easel legs, tilted backrests) are :class:`Slab` parts: a sheared
or rotated box whose colliders are axis-aligned boxes inscribed in slices of it.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from asset_pipeline.procedural.kit import (
    BLACK_LEATHER,
    FABRICS,
    LEATHER,
    block,
)
from asset_pipeline.procedural.parts import (
    Axis,
    Collider,
    Mesh,
    Part,
    RecipeMaterial,
    RecipeSurface,
    Vec3,
    add3,
)
from asset_pipeline.procedural.round_parts import Cylinder

RUBBER = RecipeMaterial("rubber", (0.05, 0.05, 0.05, 1.0), 0.1, 0.1, "black rubber")
RED_PAINT = RecipeMaterial("red_paint", (0.72, 0.10, 0.10, 1.0), 0.5, 0.5, "red")
YELLOW_PAINT = RecipeMaterial("yellow_paint", (0.92, 0.74, 0.12, 1.0), 0.5, 0.5, "yellow")
BLUE_PAINT = RecipeMaterial("blue_paint", (0.12, 0.30, 0.62, 1.0), 0.5, 0.5, "blue")
GREEN_PAINT = RecipeMaterial("green_paint", (0.16, 0.45, 0.28, 1.0), 0.5, 0.5, "green")
LIT_SCREEN = RecipeMaterial("lit_screen", (0.25, 0.55, 0.95, 1.0), 0.9, 0.9, "glowing")
MARQUEE = RecipeMaterial("marquee", (0.98, 0.80, 0.30, 1.0), 0.9, 0.9, "lit")
SISAL = RecipeMaterial("sisal", (0.90, 0.84, 0.66, 1.0), 0.05, 0.1, "sisal")
CHALK_BLACK = RecipeMaterial("chalk_black", (0.10, 0.11, 0.10, 1.0), 0.05, 0.1, "black chalkboard")
CHALK_WHITE = RecipeMaterial("chalk_white", (0.93, 0.93, 0.90, 1.0), 0.05, 0.1, "chalk")
UPHOLSTERY = (
    BLACK_LEATHER,
    LEATHER,
    *FABRICS[4:6],
    RecipeMaterial("red_vinyl", (0.60, 0.08, 0.10, 1.0), 0.4, 0.5, "red vinyl"),
)
NUMBER_WORDS = {1: "one", 2: "two", 3: "three", 4: "four", 5: "five", 6: "six", 7: "seven"}

_SIGNS = np.array(
    [[-1, -1, -1], [1, -1, -1], [1, 1, -1], [-1, 1, -1],
     [-1, -1, 1], [1, -1, 1], [1, 1, 1], [-1, 1, 1]],
    dtype=float,
)  # fmt: skip
_FACES = np.array(
    [
        [0, 2, 1], [0, 3, 2], [4, 5, 6], [4, 6, 7], [0, 1, 5], [0, 5, 4],
        [1, 2, 6], [1, 6, 5], [2, 3, 7], [2, 7, 6], [3, 0, 4], [3, 4, 7],
    ],
    dtype=np.int64,
)  # fmt: skip


# --- slanted parts ---------------------------------------------------------------------------
@dataclass(frozen=True)
class Slab:
    """A parallelepiped: ``center`` plus three half-edge vectors ``axes`` (right-handed).

    Its colliders are axis-aligned boxes, one per slice of the slab along ``axes[along]``,
    each the largest box of the slice's proportions that fits inside the slab.
    """

    center: Vec3
    axes: tuple[Vec3, Vec3, Vec3]
    material: RecipeMaterial
    slices: int = 8
    along: int = 2
    collide: bool = True

    def _corners(self) -> np.ndarray:
        return np.asarray(self.center) + _SIGNS @ np.asarray(self.axes, dtype=float)

    def mesh(self) -> Mesh | None:
        return Mesh(self._corners(), _FACES.copy())

    def colliders(self) -> list[Collider]:
        if not self.collide:
            return []
        axes = np.asarray(self.axes, dtype=float)
        centre = np.asarray(self.center)
        inverse = np.linalg.inv(axes.T)
        result = []
        n = self.slices
        for k in range(n):
            mid = -1.0 + (2 * k + 1) / n
            p = centre + mid * axes[self.along]
            sub = axes.copy()
            sub[self.along] = sub[self.along] / n
            ext = np.abs(sub).sum(axis=0)
            low, high = 0.0, 1.0
            for _ in range(30):
                lam = 0.5 * (low + high)
                corners = p + _SIGNS * (lam * ext) - centre
                if np.abs(corners @ inverse.T).max() <= 1.0 - 1e-9:
                    low = lam
                else:
                    high = lam
            half = low * ext
            if half.min() > 2e-4:
                result.append(Collider("box", tuple(float(v) for v in half), tuple(p.tolist())))
        return result

    def bounds(self) -> tuple[Vec3, Vec3] | None:
        v = self._corners()
        lo, hi = v.min(axis=0), v.max(axis=0)
        return (float(lo[0]), float(lo[1]), float(lo[2])), (
            float(hi[0]),
            float(hi[1]),
            float(hi[2]),
        )

    def surfaces(self) -> list[RecipeSurface]:
        return []

    def translated(self, offset: Vec3) -> Slab:
        return replace(self, center=add3(self.center, offset))


def strut(foot: Vec3, top: Vec3, side: float, material: RecipeMaterial, slices: int = 10) -> Slab:
    """A slanted leg of square ``side`` cross-section from ``foot`` up to ``top``."""
    cx, cy, cz = (0.5 * (a + b) for a, b in zip(foot, top))
    ax, ay, az = (0.5 * (b - a) for a, b in zip(foot, top))
    s = 0.5 * side
    return Slab((cx, cy, cz), ((s, 0.0, 0.0), (0.0, s, 0.0), (ax, ay, az)), material, slices=slices)


def tilted(
    center: Vec3, length: float, width: float, thick: float, angle: float, material: RecipeMaterial
) -> Slab:
    """A board ``length`` along X tilted by ``angle`` (radians; +X end up), ``width`` in Y."""
    ca, sa = np.cos(angle), np.sin(angle)
    axes = (
        (0.5 * length * ca, 0.0, 0.5 * length * sa),
        (0.0, 0.5 * width, 0.0),
        (-0.5 * thick * sa, 0.0, 0.5 * thick * ca),
    )
    return Slab(center, axes, material, slices=8, along=0)


def tilted_bounds(length: float, thick: float, angle: float) -> tuple[float, float]:
    """Half extents in X and Z of a board from :func:`tilted`."""
    ca, sa = np.cos(angle), np.sin(angle)
    return 0.5 * (length * ca + thick * sa), 0.5 * (length * sa + thick * ca)


def cyl(
    x: float, y: float, z0: float, z1: float, r: float, material: RecipeMaterial, **kw
) -> Cylinder:
    """An upright cylinder from ``z0`` to ``z1``."""
    return Cylinder((x, y, 0.5 * (z0 + z1)), r, 0.5 * (z1 - z0), material, **kw)


def rod(
    axis: Axis,
    a0: float,
    a1: float,
    p: float,
    q: float,
    r: float,
    material: RecipeMaterial,
    **kw: Any,
) -> Cylinder:
    """A horizontal cylinder along ``axis`` ('x' or 'y') from ``a0`` to ``a1``; (p, q) are the
    other horizontal coordinate and z."""
    mid = 0.5 * (a0 + a1)
    center = (mid, p, q) if axis == "x" else (p, mid, q)
    return Cylinder(center, r, 0.5 * (a1 - a0), material, axis=axis, **kw)


def frame_rect(
    x: tuple[float, float],
    y: tuple[float, float],
    z: tuple[float, float],
    t: float,
    m: RecipeMaterial,
) -> list[Part]:
    """Four bars outlining the rectangle ``y`` x ``z`` in the plane slab ``x`` (a door frame)."""
    (y0, y1), (z0, z1) = y, z
    return [
        block(x, (y0, y1), (z0, z0 + t), m),
        block(x, (y0, y1), (z1 - t, z1), m),
        block(x, (y0, y0 + t), (z0 + t, z1 - t), m),
        block(x, (y1 - t, y1), (z0 + t, z1 - t), m),
    ]
