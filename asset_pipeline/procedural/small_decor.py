"""Generators of small decor: globes, frames, clocks, boxes, trophies.

Small items stand on furniture (placement ``object``, issue 15). Sizes follow the knowledge
base (``objects.json``, whose (width, depth, height) is (y, x, z) here); fronts face +X.
"""

from __future__ import annotations

from asset_pipeline.procedural.kit import (
    BLACK_LEATHER,
    BLACK_METAL,
    BLACK_PLASTIC,
    BRASS,
    CHROME,
    FABRICS,
    GILT,
    PAPER,
    SCREEN,
    WHITE_PLASTIC,
    WOODS,
    Rng,
    block,
    chance,
    clamp,
    pick,
)
from asset_pipeline.procedural.parts import Part, RecipeMaterial, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.round_parts import Lathe, Sphere
from asset_pipeline.procedural.small_kit import (
    CREAM_ENAMEL,
    DIAL,
    GOLD,
    MINT_ENAMEL,
    OBJECT,
    RED_ENAMEL,
    ROUND,
    SILVER,
    cyl_x,
    cyl_y,
    cyl_z,
    deco,
)

OCEAN = RecipeMaterial("ocean", (0.22, 0.44, 0.70, 1.0), 0.4, 0.4, "blue")
PARCHMENT = RecipeMaterial("parchment", (0.86, 0.76, 0.55, 1.0), 0.3, 0.3, "antique")
PHOTO = RecipeMaterial("photo", (0.45, 0.58, 0.66, 1.0), 0.6, 0.6)
MARBLE = RecipeMaterial("marble", (0.90, 0.90, 0.88, 1.0), 0.6, 0.6, "white marble")


@category(
    "globe",
    "object",
    size=(0.3, 0.3, 0.45),
    low=(0.18, 0.18, 0.25),
    high=(0.45, 0.45, 0.65),
    mass=1.5,
    placement=OBJECT,
    yx_ratio=ROUND,
    zx_ratio=(1.35, 2.0),
    description="an {finish} desk globe on a {stand} stand",
    variants=(None, (0.22, 0.22, 0.34)),
)
def globe(size: Vec3, rng: Rng) -> Design:
    """A desk globe: round base, stem, the sphere and its axis pin."""
    d, _, h = size
    r = 0.5 * d
    finish = pick(rng, (OCEAN, PARCHMENT))
    stand = pick(rng, (*WOODS[:2], BRASS, BLACK_METAL))
    pin = 0.015
    cz = h - pin - r
    base_r = 0.32 * d
    parts: list[Part] = [
        cyl_z(0.0, 0.0, 0.0, 0.02, base_r, stand),
        cyl_z(0.0, 0.0, 0.02, cz - 0.95 * r, 0.012, stand),
        Sphere((0.0, 0.0, cz), r, finish, rings=8),
        cyl_z(0.0, 0.0, cz + 0.95 * r, h, 0.004, stand),
    ]
    words = "ocean blue" if finish is OCEAN else "antique"
    return Design(tuple(parts), {"finish": words, "stand": stand.words})


@category(
    "picture_frame",
    "object",
    size=(0.08, 0.2, 0.25),
    low=(0.04, 0.1, 0.1),
    high=(0.14, 0.45, 0.5),
    mass=0.6,
    placement=OBJECT,
    zx_ratio=(1.0, 6.0),
    description="a {frame} picture frame standing on its base",
    variants=(None, (0.07, 0.25, 0.2)),
)
def picture_frame(size: Vec3, rng: Rng) -> Design:
    """A standing photo frame on a flat plinth, the photo facing +X, a strut behind."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    frame = pick(rng, (*WOODS, BLACK_METAL, GILT, SILVER))
    ph = clamp(0.05 * h, 0.008, 0.015)
    ft = clamp(0.25 * d, 0.012, 0.025)
    border = clamp(0.1 * min(w, h), 0.01, 0.03)
    parts: list[Part] = [
        block((-hd, hd), (-hw, hw), (0.0, ph), frame),
        block((-0.5 * ft, 0.5 * ft), (-hw, hw), (ph, h), frame),
        deco((0.5 * ft, 0.5 * ft + 0.001), (-hw + border, hw - border), (ph + border, h - border),
             PHOTO),
        block((-hd + 0.005, -0.5 * ft), (-0.01, 0.01), (ph, ph + 0.4 * (h - ph)), frame),
    ]  # fmt: skip
    return Design(tuple(parts), {"frame": frame.words})


@category(
    "alarm_clock",
    "object",
    size=(0.07, 0.12, 0.1),
    low=(0.04, 0.07, 0.06),
    high=(0.12, 0.2, 0.16),
    mass=0.35,
    placement=OBJECT,
    yx_ratio=(1.2, 2.2),
    zx_ratio=(0.9, 2.2),
    description="a {finish} {style} alarm clock",
    variants=(None, (0.06, 0.1, 0.09)),
)
def alarm_clock(size: Vec3, rng: Rng) -> Design:
    """A twin-bell clock (round body on feet, bells on a bridge) or a boxy digital clock."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, (RED_ENAMEL, CHROME, BLACK_METAL, MINT_ENAMEL, CREAM_ENAMEL))
    if chance(rng, 0.6):
        foot_h = 0.08 * h
        rb = min(0.32 * (h - foot_h), 0.45 * w, 0.5 * h)
        cz = foot_h + rb
        bell_r = min(0.22 * w, 0.3 * rb + 0.005)
        bell_z = cz + 0.8 * rb
        by = hw - bell_r
        parts: list[Part] = [
            block((-0.3 * d, 0.3 * d), (-0.6 * rb, -0.4 * rb), (0.0, cz), BLACK_METAL),
            block((-0.3 * d, 0.3 * d), (0.4 * rb, 0.6 * rb), (0.0, cz), BLACK_METAL),
            block((-hd, hd), (-0.6 * rb, 0.6 * rb), (0.0, foot_h), BLACK_METAL),
            cyl_x(-0.3 * d, 0.3 * d, 0.0, cz, rb, finish),
            cyl_x(0.3 * d, 0.3 * d + 0.001, 0.0, cz, 0.85 * rb, DIAL, collide=False),
            cyl_z(0.0, 0.0, cz + 0.9 * rb, bell_z, 0.004, BLACK_METAL, collide=False),
            cyl_y(-by, by, 0.0, bell_z, 0.003, BLACK_METAL, collide=False),
        ]
        for sign in (-1.0, 1.0):
            parts.append(
                Lathe((0.0, sign * by, bell_z), ((bell_r, 0.0), (0.6 * bell_r, h - bell_z)),
                      finish, collide=False)
            )  # fmt: skip
        style = "twin-bell"
    else:
        parts = [
            block((-hd, hd - 0.002), (-hw, hw), (0.0, h), finish),
            deco((hd - 0.002, hd), (-hw + 0.01, hw - 0.01), (0.3 * h, h - 0.012), SCREEN),
        ]
        style = "digital"
    return Design(tuple(parts), {"finish": finish.words, "style": style})


@category(
    "jewelry_box",
    "object",
    size=(0.15, 0.25, 0.1),
    low=(0.08, 0.12, 0.05),
    high=(0.25, 0.4, 0.18),
    mass=0.8,
    placement=OBJECT,
    description="a small {wood} jewelry box",
    variants=(None, (0.12, 0.2, 0.08)),
)
def jewelry_box(size: Vec3, rng: Rng) -> Design:
    """A box with a lid, a clasp on +X and an inlay on the lid."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    wood = pick(rng, (*WOODS, BLACK_LEATHER, WHITE_PLASTIC))
    metal = pick(rng, (BRASS, SILVER))
    face = hd - 0.004
    parts: list[Part] = [
        block((-hd, face), (-hw, hw), (0.0, 0.7 * h), wood),
        block((-hd, face), (-hw, hw), (0.7 * h, h - 0.0008), wood, surface=True),
        block((face, hd), (-0.04 * w, 0.04 * w), (0.55 * h, 0.8 * h), metal),
        deco((-0.3 * d, 0.3 * d), (-0.3 * w, 0.3 * w), (h - 0.0008, h), metal),
    ]
    return Design(tuple(parts), {"wood": wood.words})


@category(
    "tissue_box",
    "object",
    size=(0.12, 0.24, 0.09),
    low=(0.1, 0.1, 0.06),
    high=(0.16, 0.3, 0.2),
    mass=0.25,
    placement=OBJECT,
    description="a {colour} box of tissues",
    variants=(None, (0.12, 0.12, 0.13)),
)
def tissue_box(size: Vec3, rng: Rng) -> Design:
    """A tissue box with a tissue plume poking out of the top."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    colour = pick(rng, (*FABRICS[:5], WHITE_PLASTIC))
    plume = 0.02
    parts: list[Part] = [
        block((-hd, hd), (-hw, hw), (0.0, h - plume), colour),
        deco((-0.2 * d, 0.2 * d), (-0.2 * w, 0.2 * w), (h - plume, h), PAPER),
        deco((-0.05 * d, 0.05 * d), (-0.3 * w, 0.3 * w), (h - plume, h - 0.005), PAPER),
    ]
    return Design(tuple(parts), {"colour": colour.words})


@category(
    "trophy",
    "object",
    size=(0.15, 0.15, 0.35),
    low=(0.08, 0.08, 0.15),
    high=(0.3, 0.3, 0.6),
    mass=1.2,
    placement=OBJECT,
    yx_ratio=ROUND,
    zx_ratio=(1.2, 4.0),
    description="a {metal} trophy cup on a {base} base",
    variants=(None, (0.12, 0.12, 0.25)),
)
def trophy(size: Vec3, rng: Rng) -> Design:
    """A trophy: a square plinth, a stem and an open cup with two handles."""
    d, _, h = size
    hd = 0.5 * d
    metal = pick(rng, (GOLD, SILVER, BRASS))
    base = pick(rng, (MARBLE, *WOODS[:2], BLACK_PLASTIC))
    plinth = 0.2 * h
    cup_z = 0.5 * h
    cr = 0.38 * d
    hr = 0.12 * d  # handle loops reach the plinth's width
    parts: list[Part] = [
        block((-hd, hd), (-hd, hd), (0.0, plinth), base),
        cyl_z(0.0, 0.0, plinth, plinth + 0.01, 0.25 * d, metal),
        cyl_z(0.0, 0.0, plinth + 0.01, cup_z, 0.06 * d, metal),
        Lathe((0.0, 0.0, cup_z), ((0.1 * d, 0.0), (cr, h - cup_z)), metal,
              hollow=(0.003, 0.3 * (h - cup_z))),
    ]  # fmt: skip
    for sign in (-1.0, 1.0):
        ys = sorted((sign * 0.75 * cr, sign * (cr + hr)))
        parts.append(block((-0.005, 0.005), ys, (cup_z + 0.35 * (h - cup_z),
                                                  cup_z + 0.85 * (h - cup_z)), metal))  # fmt: skip
    return Design(tuple(parts), {"metal": metal.words, "base": base.words})
