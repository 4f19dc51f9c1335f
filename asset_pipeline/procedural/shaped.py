"""Shapes a category's own generator does not make: oval tables (an elliptic top on a
pedestal), round mirrors (a framed disc) and L-shaped desks (a top along the back with a return
wing reaching the front, on five legs), and the size a shaped asset gets."""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, replace

import numpy as np

from asset_pipeline.procedural.appliances import MIRROR
from asset_pipeline.procedural.kit import (
    BLACK_METAL,
    BRASS,
    CASE_FINISHES,
    OAK,
    WALNUT,
    WHITE_LACQUER,
    chance,
    pick,
    uniform,
)
from asset_pipeline.procedural.parts import (
    EDGE_MARGIN,
    Box,
    Collider,
    Mesh,
    Part,
    RecipeMaterial,
    RecipeSurface,
    Vec3,
    add3,
)
from asset_pipeline.procedural.registry import CategoryInfo
from asset_pipeline.procedural.roles import Tagged, tagged
from asset_pipeline.procedural.round_parts import INSCRIBED, SEGMENTS, Cylinder

TABLES = ("coffee_table", "side_table", "dining_table")
TABLE_SHAPES = ("round", "oval", "square")
SHAPED = {
    "coffee_table": TABLE_SHAPES,
    "side_table": TABLE_SHAPES,
    "dining_table": TABLE_SHAPES,
    "stool": ("round", "square"),
    "mirror": ("round",),
    "desk": ("l-shaped",),
}


@dataclass(frozen=True)
class EllipticSlab:
    """A vertical prism over an ellipse (semi-axes ``a`` along X, ``b`` along Y).

    Its visual is a 24-gon with vertices on the ellipse (and on both axes, so the bounding box
    is exact); its colliders are five boxes inside the inscribed ellipse; its top may be a
    support surface (the inscribed ellipse eroded by the edge margin).
    """

    center: Vec3
    a: float
    b: float
    half_height: float
    material: RecipeMaterial
    surface: bool = False

    def mesh(self) -> Mesh | None:
        disc = Cylinder((0.0, 0.0, 0.0), self.a, self.half_height, self.material).mesh()
        assert disc is not None
        vertices = disc.vertices * np.array([1.0, self.b / self.a, 1.0])
        return Mesh(vertices, disc.faces).translated(self.center)

    def colliders(self) -> list[Collider]:
        a, b = self.a * INSCRIBED, self.b * INSCRIBED
        out = []
        edges = (0.0, 0.45, 0.75, 0.92)
        for lo, hi in zip(edges, edges[1:], strict=False):
            half_y = b * math.sqrt(1.0 - hi * hi)
            if lo == 0.0:
                out.append(Collider("box", (hi * a, half_y, self.half_height), self.center))
                continue
            for sign in (-1.0, 1.0):
                cx = sign * 0.5 * (lo + hi) * a
                size = (0.5 * (hi - lo) * a, half_y, self.half_height)
                out.append(Collider("box", size, add3(self.center, (cx, 0.0, 0.0))))
        return out

    def bounds(self) -> tuple[Vec3, Vec3] | None:
        cx, cy, cz = self.center
        h = self.half_height
        return (cx - self.a, cy - self.b, cz - h), (cx + self.a, cy + self.b, cz + h)

    def surfaces(self) -> list[RecipeSurface]:
        if not self.surface:
            return []

        a = self.a * INSCRIBED - EDGE_MARGIN
        b = self.b * INSCRIBED - EDGE_MARGIN
        cx, cy, cz = self.center
        polygon = tuple(
            (
                cx + a * math.cos(2.0 * math.pi * k / SEGMENTS),
                cy + b * math.sin(2.0 * math.pi * k / SEGMENTS),
            )
            for k in range(SEGMENTS)
        )
        return [RecipeSurface(cz + self.half_height, polygon)]

    def translated(self, offset: Vec3) -> EllipticSlab:
        return replace(self, center=add3(self.center, offset))


def oval_table(size: Vec3, rng: np.random.Generator) -> tuple[list[Part], dict[str, str]]:
    """An oval table: an elliptic top on a central pedestal with a round foot."""

    d, w, h = size
    top = pick(rng, CASE_FINISHES)
    leg = top if chance(rng, 0.6) else BLACK_METAL
    t = uniform(rng, 0.025, 0.045)
    foot_r = min(0.6 * min(d, w) / 2.0, 0.32)
    parts: list[Part] = [
        *tagged(
            "base",
            [
                Cylinder((0.0, 0.0, 0.02), foot_r, 0.02, leg),
                Cylinder((0.0, 0.0, 0.5 * (h - t + 0.04)), 0.055, 0.5 * (h - t - 0.04), leg),
            ],
        ),
        *tagged(
            "top",
            [EllipticSlab((0.0, 0.0, h - 0.5 * t), 0.5 * d, 0.5 * w, 0.5 * t, top, surface=True)],
        ),
    ]
    legs = "a pedestal" if leg is top else f"a {leg.words} pedestal"
    return parts, {"top": top.words, "shape": "oval", "legs": legs, "shelf": ""}


def round_mirror(size: Vec3, rng: np.random.Generator) -> tuple[list[Part], dict[str, str]]:
    """A round wall mirror: a framed disc facing +X (x = thickness, y = z = diameter)."""

    d, diameter, _ = size
    r = 0.5 * diameter
    frame = pick(rng, (BLACK_METAL, BRASS, OAK, WALNUT, WHITE_LACQUER))
    back = 0.7 * d
    glass = d - back
    rim = min(0.06, 0.12 * r)
    parts: list[Part] = [
        Tagged(Cylinder((-0.5 * d + 0.5 * back, 0.0, r), r, 0.5 * back, frame, axis="x"), "frame"),
        Cylinder((0.5 * d - 0.5 * glass, 0.0, r), r - rim, 0.5 * glass, MIRROR, axis="x"),
    ]
    return parts, {"frame": frame.words}


def l_desk(size: Vec3, rng: np.random.Generator) -> tuple[list[Part], dict[str, str]]:
    """An L-shaped corner desk: a top along the back (-X) and a return wing on its +Y end
    reaching the front, both support surfaces, on square legs at the L's five outer corners."""

    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    top = pick(rng, CASE_FINISHES)
    leg = top if chance(rng, 0.5) else BLACK_METAL
    t = uniform(rng, 0.025, 0.04)
    main = min(max(0.6 * d, 0.45), d - 0.25)  # depth of the top along the back
    wing = min(max(0.35 * w, 0.45), 0.6 * w)  # width of the return
    side = 0.05
    x_main = -hd + main
    y_wing = hw - wing
    parts: list[Part] = [
        *tagged("top", [Box((0.5 * (x_main - hd), 0.0, h - 0.5 * t), (0.5 * main, hw, 0.5 * t),
                            top, surface=True)]),
        *tagged("top", [Box((0.5 * (x_main + hd), 0.5 * (y_wing + hw), h - 0.5 * t),
                            (0.5 * (hd - x_main), 0.5 * wing, 0.5 * t), top, surface=True)]),
    ]  # fmt: skip
    corners = ((-hd, -hw), (x_main - side, -hw), (-hd, hw - side), (hd - side, hw - side),
               (hd - side, y_wing))  # fmt: skip
    half = (0.5 * side, 0.5 * side, 0.5 * (h - t))
    legs = [Box((x + half[0], y + half[1], half[2]), half, leg) for x, y in corners]
    parts += tagged("legs", legs)
    legs_words = "" if leg is top else f" on {leg.words} legs"
    words = {
        "top": top.words,
        "shape": "l-shaped",
        "style": f"with an l-shaped corner return{legs_words}",
    }
    return parts, words


def shaped_size(info: CategoryInfo, shape: str | None, size: Vec3) -> Vec3:
    """The size a shaped asset gets: square footprints for round and square tables (the smaller
    side), a round mirror as wide as tall (the smaller of the two), an L-shaped desk as deep as
    a desk may be (so that its return reaches forward)."""
    d, w, h = size
    if shape is None or shape not in SHAPED.get(info.name, ()):
        return size
    if info.name == "mirror":
        side = min(w, h)
        return (d, side, side)
    if shape == "l-shaped":
        return (info.size_max[0], w, h)
    if shape in ("round", "square"):
        side = min(d, w)
        return (side, side, h)
    return size


ShapeBuilder = Callable[[Vec3, np.random.Generator], tuple[list[Part], dict[str, str]]]


def shape_builder(category: str, shape: str) -> ShapeBuilder | None:
    """The builder of this module making ``category`` in ``shape`` (one of its
    :data:`SHAPED`), or None where the category's own generator makes that shape."""
    if category == "mirror":
        return round_mirror
    return {"oval": oval_table, "l-shaped": l_desk}.get(shape)
