"""Hanging decor: paper lanterns and hanging plants."""

from __future__ import annotations

import math

from asset_pipeline.procedural.home_ceiling import (
    CEILING,
    ceiling_canopy,
)
from asset_pipeline.procedural.home_kit import (
    RICE_PAPER,
    ROUND,
    WICKER,
    upright_rod,
)
from asset_pipeline.procedural.kit import (
    BARK,
    BLACK_METAL,
    BLACK_PLASTIC,
    BRASS,
    CANVAS_WARM,
    CERAMIC_BLUE,
    CONCRETE,
    DARK_FOLIAGE,
    FOLIAGE,
    LAMP_SHADE,
    LINEN,
    PORCELAIN,
    TERRACOTTA,
    TOY_RED,
    WHITE_LACQUER,
    WHITE_PLASTIC,
    Rng,
    block,
    clamp,
    pick,
    uniform,
)
from asset_pipeline.procedural.parts import Part, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.round_parts import Cylinder, Lathe


# --- paper lanterns and hanging plants ------------------------------------------------------------
@category(
    "paper_lantern",
    "furniture",
    size=(0.5, 0.5, 0.5),
    low=(0.25, 0.25, 0.3),
    high=(0.8, 0.8, 1.2),
    mass=0.4,
    friction=0.7,
    placement=CEILING,
    yx_ratio=ROUND,
    zx_ratio=(0.7, 3.0),
    description="a {shape} {paper} paper lantern light on a {cord} cord",
    variants=(None, (0.35, 0.35, 0.6), (0.7, 0.7, 0.9)),
)
def paper_lantern(size: Vec3, rng: Rng) -> Design:
    """A paper lantern: a globe, an oval or a ribbed drum of paper (a surface of revolution
    with small openings top and bottom) hanging on a cord from a ceiling hook."""
    d, _, h = size
    r = 0.5 * d
    paper = pick(rng, (RICE_PAPER, RICE_PAPER, LAMP_SHADE, CANVAS_WARM, TOY_RED))
    cord = pick(rng, (WHITE_PLASTIC, BLACK_PLASTIC))
    shape = pick(rng, ("globe", "oval", "drum"))
    bh = min(h - 0.05, {"globe": 0.95, "oval": 1.3, "drum": 1.1}[shape] * d)
    n = 6
    points = []
    for i in range(n + 1):
        u = -1.0 + 2.0 * i / n
        f = (1.0 - (u / 1.06) ** 8) ** 0.5 if shape == "drum" else (1.0 - (u / 1.08) ** 2) ** 0.5
        points.append((f * r, 0.5 * (u + 1.0) * bh))
    parts: list[Part] = [
        Lathe((0.0, 0.0, 0.0), tuple(points), paper),
        upright_rod(bh - 0.005, h - 0.015, 0.004, cord),
        ceiling_canopy(h, 0.03, cord if cord is BLACK_PLASTIC else WHITE_LACQUER, 0.015),
    ]
    words = {
        "shape": {"globe": "round globe", "oval": "tall oval", "drum": "ribbed drum"}[shape],
        "paper": paper.words.replace(" paper", ""),
        "cord": cord.words,
    }
    return Design(tuple(parts), words)


@category(
    "hanging_plant",
    "furniture",
    size=(0.4, 0.4, 0.6),
    low=(0.25, 0.25, 0.35),
    high=(0.7, 0.7, 1.2),
    mass=3.0,
    friction=0.8,
    placement=CEILING,
    yx_ratio=ROUND,
    description="a trailing {leaves} plant in a hanging {pot} pot on {hanger}",
    variants=(None, (0.35, 0.35, 0.8), (0.55, 0.55, 0.9)),
)
def hanging_plant(size: Vec3, rng: Rng) -> Design:
    """A hanging planter: a pot (the flat bottom), a mound of foliage as wide as the box,
    trailing vines down its sides, and cords up to a ring and a ceiling hook."""
    d, _, h = size
    r = 0.5 * d
    pot = pick(rng, (TERRACOTTA, PORCELAIN, CERAMIC_BLUE, WICKER, CONCRETE))
    leaves = pick(rng, (FOLIAGE, DARK_FOLIAGE))
    pr = clamp(0.45 * r, 0.07, 0.16)
    ph = clamp(0.9 * pr, 0.08, 0.16)
    fh = clamp(0.35 * h, 0.12, 0.3)
    fh = min(fh, h - ph - 0.1)
    ring_z = ph + fh + 0.03
    hanger = pick(rng, ("cords", "a chain"))
    parts: list[Part] = [
        Lathe((0.0, 0.0, 0.0), ((0.75 * pr, 0.0), (pr, ph)), pot),
        Lathe(
            (0.0, 0.0, ph - 0.01),
            ((0.9 * pr, 0.0), (r, 0.4 * fh), (0.75 * r, 0.75 * fh), (0.3 * r, fh)),
            leaves,
        ),
        Cylinder((0.0, 0.0, ring_z), 0.03, 0.006, BRASS if hanger == "a chain" else BARK),
        upright_rod(
            ring_z + 0.006, h - 0.012, 0.004, BLACK_METAL if hanger == "a chain" else LINEN
        ),
        ceiling_canopy(h, 0.025, WHITE_LACQUER, 0.012),
    ]
    for dx, dy in ((1.0, 0.0), (-1.0, 0.0), (0.0, 1.0), (0.0, -1.0)):
        x, y = 0.7 * pr * dx, 0.7 * pr * dy
        parts.append(
            block(
                (x - 0.003, x + 0.003),
                (y - 0.003, y + 0.003),
                (ph + 0.3 * fh, ring_z - 0.006),
                LINEN,
                collide=False,
            )
        )
    vines = int(rng.integers(3, 7))
    for k in range(vines):
        ang = 2.0 * math.pi * (k + 0.5) / vines
        x, y = 0.8 * r * math.cos(ang), 0.8 * r * math.sin(ang)
        z0 = uniform(rng, 0.02, 0.4 * ph + 0.02)
        parts.append(
            block(
                (x - 0.012, x + 0.012),
                (y - 0.012, y + 0.012),
                (z0, ph + 0.3 * fh),
                leaves,
                collide=False,
            )
        )
    return Design(tuple(parts), {"leaves": leaves.words, "pot": pot.words, "hanger": hanger})
