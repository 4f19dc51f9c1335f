"""Generators of small desk and office items.

Small items stand on furniture (placement ``object``, issue 15). Sizes follow the knowledge
base (``objects.json``, whose (width, depth, height) is (y, x, z) here); fronts face +X.
"""

from __future__ import annotations

import numpy as np

from asset_pipeline.procedural.kit import (
    BLACK_METAL,
    BLACK_PLASTIC,
    CERAMICS,
    CHROME,
    COVERS,
    PAPER,
    WOODS,
    Rng,
    block,
    clamp,
    pick,
    uniform,
)
from asset_pipeline.procedural.parts import Part, RecipeMaterial, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.round_parts import Lathe
from asset_pipeline.procedural.small_kit import (
    BLUE_PLASTIC,
    GREY_PLASTIC,
    OBJECT,
    RED_PLASTIC,
    ROUND,
    cyl_y,
    deco,
)

RED_PEN = RecipeMaterial("red_pen", (0.80, 0.10, 0.10, 1.0), 0.5, 0.5)
BLUE_PEN = RecipeMaterial("blue_pen", (0.10, 0.20, 0.70, 1.0), 0.5, 0.5)
PENCIL = RecipeMaterial("pencil", (0.95, 0.75, 0.15, 1.0), 0.3, 0.3)
BRIGHT_PAPER = RecipeMaterial("bright_paper", (0.99, 0.99, 0.99, 1.0), 0.05, 0.1, "white")
RECYCLED = RecipeMaterial("recycled_paper", (0.88, 0.85, 0.76, 1.0), 0.05, 0.1, "recycled")


# --- desk and office -----------------------------------------------------------------------
@category(
    "pen_holder",
    "object",
    size=(0.08, 0.08, 0.1),
    low=(0.05, 0.05, 0.07),
    high=(0.12, 0.12, 0.16),
    mass=0.3,
    placement=OBJECT,
    yx_ratio=ROUND,
    description="a {material} cup of pens and pencils",
    variants=(None, (0.07, 0.07, 0.12)),
)
def pen_holder(size: Vec3, rng: Rng) -> Design:
    """A desk tidy: an open cup with pens and pencils standing in it."""
    d, _, h = size
    r = 0.5 * d
    material = pick(rng, (BLACK_METAL, *CERAMICS[:3], WOODS[1]))
    cup_h = 0.65 * h
    parts: list[Part] = [
        Lathe((0.0, 0.0, 0.0), ((r, 0.0), (r, cup_h)), material, hollow=(0.003, 0.006)),
    ]
    pens = (RED_PEN, BLUE_PEN, BLACK_PLASTIC, PENCIL)
    for i, pen in enumerate(pens):
        angle = 2 * np.pi * i / len(pens) + 0.4
        pr = 0.45 * (r - 0.003)
        top = h if i == 0 else cup_h + uniform(rng, 0.5, 0.95) * (h - cup_h)
        x, y = pr * float(np.cos(angle)), pr * float(np.sin(angle))
        parts.append(deco((x - 0.0035, x + 0.0035), (y - 0.0035, y + 0.0035), (0.006, top), pen))
    return Design(tuple(parts), {"material": material.words})


@category(
    "stapler",
    "object",
    size=(0.05, 0.16, 0.06),
    low=(0.03, 0.1, 0.035),
    high=(0.08, 0.25, 0.09),
    mass=0.35,
    placement=OBJECT,
    description="a {finish} desk stapler",
    variants=(None, (0.04, 0.13, 0.05)),
)
def stapler(size: Vec3, rng: Rng) -> Design:
    """A stapler along Y: base, hinge at -Y, a top arm over the base."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, (BLACK_PLASTIC, RED_PLASTIC, BLUE_PLASTIC, CHROME))
    parts: list[Part] = [
        block((-hd, hd), (-hw, hw), (0.0, 0.25 * h), BLACK_PLASTIC),
        block((-0.3 * d, 0.3 * d), (-hw, -hw + 0.15 * w), (0.25 * h, 0.6 * h), CHROME),
        block((-0.4 * d, 0.4 * d), (-hw, hw - 0.03 * w), (0.6 * h, h), finish),
    ]
    return Design(tuple(parts), {"finish": finish.words})


@category(
    "binder",
    "object",
    size=(0.06, 0.3, 0.32),
    low=(0.025, 0.2, 0.2),
    high=(0.1, 0.4, 0.4),
    mass=0.6,
    placement=OBJECT,
    description="a {cover} ring binder standing upright",
    variants=(None, (0.04, 0.28, 0.3)),
)
def binder(size: Vec3, rng: Rng) -> Design:
    """A ring binder on its bottom edge: covers facing +-X, the spine at -Y, paper inside."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    cover = pick(rng, (*COVERS, GREY_PLASTIC))
    c = 0.003
    parts: list[Part] = [
        block((-hd, -hd + c), (-hw + 0.001, hw), (0.0, h), cover),
        block((hd - c, hd), (-hw + 0.001, hw), (0.0, h), cover),
        block((-hd + c, hd - c), (-hw + 0.001, -hw + 0.001 + c), (0.0, h), cover),
        block((-hd + c, hd - c), (-hw + c + 0.001, hw - 0.01), (0.01, h - 0.01), PAPER),
        deco((-0.3 * d, 0.3 * d), (-hw, -hw + 0.001), (0.55 * h, 0.8 * h), PAPER),
        cyl_y(-hw, -hw + 0.001, 0.0, 0.2 * h, clamp(0.25 * d, 0.006, 0.015), BLACK_PLASTIC,
              collide=False),
    ]  # fmt: skip
    return Design(tuple(parts), {"cover": cover.words})


@category(
    "paper_stack",
    "object",
    size=(0.21, 0.3, 0.05),
    low=(0.14, 0.2, 0.005),
    high=(0.32, 0.45, 0.15),
    mass=2.5,
    placement=OBJECT,
    description="a stack of {paper} paper",
    variants=(None, (0.21, 0.3, 0.02)),
)
def paper_stack(size: Vec3, rng: Rng) -> Design:
    """A stack of sheets, slightly out of line; the top is a surface."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    paper = pick(rng, (PAPER, BRIGHT_PAPER, RECYCLED))
    split = 0.5 * h
    parts: list[Part] = [
        block((-hd + 0.003, hd), (-hw, hw - 0.004), (0.0, split), paper),
        block((-hd, hd - 0.003), (-hw + 0.004, hw), (split, h), paper, surface=True),
    ]
    return Design(tuple(parts), {"paper": paper.words})
