"""Vending and slot machines, massage tables and telescopes."""

from __future__ import annotations

import numpy as np

from asset_pipeline.procedural.kit import (
    ALUMINIUM,
    BLACK_LEATHER,
    BLACK_METAL,
    BLACK_PLASTIC,
    BRASS,
    CHROME,
    CLEAR_GLASS,
    FABRICS,
    OAK,
    PIANO_BLACK,
    SCREEN,
    STEEL,
    WHITE_LACQUER,
    WHITE_PLASTIC,
    WOODS,
    Rng,
    block,
    chance,
    clamp,
    pick,
    square_legs,
    uniform,
)
from asset_pipeline.procedural.leisure_kit import (
    BLUE_PAINT,
    GREEN_PAINT,
    LIT_SCREEN,
    MARQUEE,
    NUMBER_WORDS,
    RED_PAINT,
    RUBBER,
    YELLOW_PAINT,
    cyl,
    rod,
    strut,
)
from asset_pipeline.procedural.parts import Part, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.round_parts import Sphere


# --- machines, massage tables and telescopes ------------------------------------------------------
@category(
    "vending_machine",
    "furniture",
    size=(0.8, 0.9, 1.83),
    low=(0.6, 0.6, 1.6),
    high=(1.0, 1.3, 2.0),
    mass=300.0,
    friction=0.7,
    description="a {finish} snack and drinks vending machine with a glass front, {rows} rows "
    "of products and a keypad",
    variants=(None, (0.85, 1.1, 1.9), (0.7, 0.75, 1.75)),
)
def vending_machine(size: Vec3, rng: Rng) -> Design:
    """A cabinet with a glass window onto product spirals, a keypad column and a pickup bin."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, (BLACK_PLASTIC, RED_PAINT, BLUE_PAINT, STEEL))
    pad_w = clamp(0.25 * w, 0.18, 0.3)
    recess = 0.08
    face = hd - recess
    win_y = (-hw + 0.04, hw - pad_w)
    z_win = (0.35, h - 0.15)
    rows = int(clamp((z_win[1] - z_win[0]) // 0.22, 4, 7))
    parts: list[Part] = [
        block((-hd, face), (-hw, hw), (0.0, h), finish),
        block((face, hd), (hw - pad_w, hw), (0.0, h), finish),
        block((face, hd), (-hw, -hw + 0.04), (0.0, h), finish),
        block((face, hd), (-hw + 0.04, hw - pad_w), (0.0, z_win[0]), finish),
        block((face, hd), (-hw + 0.04, hw - pad_w), (z_win[1], h), finish),
        block((hd - 0.006, hd), win_y, z_win, CLEAR_GLASS),
        block(
            (hd - 0.001, hd),
            (win_y[0] + 0.05, win_y[1] - 0.05),
            (0.1, 0.25),
            BLACK_PLASTIC,
            collide=False,
        ),
        block((hd - 0.001, hd), (hw - pad_w + 0.04, hw - 0.04), (1.0, 1.25), SCREEN, collide=False),
        block(
            (hd - 0.001, hd), (hw - pad_w + 0.06, hw - 0.06), (0.85, 0.95), CHROME, collide=False
        ),
    ]
    pitch = (z_win[1] - z_win[0]) / rows
    cols = max(3, int((win_y[1] - win_y[0]) // 0.11))
    cw = (win_y[1] - win_y[0]) / cols
    colours = (RED_PAINT, YELLOW_PAINT, BLUE_PAINT, GREEN_PAINT, WHITE_PLASTIC)
    for i in range(rows):
        z = z_win[0] + i * pitch
        parts.append(block((face, hd - 0.006), win_y, (z, z + 0.01), STEEL, collide=False))
        for j in range(cols):
            y = win_y[0] + j * cw
            parts.append(
                block(
                    (face + 0.01, hd - 0.02),
                    (y + 0.015, y + cw - 0.015),
                    (z + 0.01, z + 0.6 * pitch),
                    pick(rng, colours),
                    collide=False,
                )
            )
    return Design(tuple(parts), {"finish": finish.words, "rows": NUMBER_WORDS[rows]})


@category(
    "slot_machine",
    "furniture",
    size=(0.7, 0.6, 1.8),
    low=(0.5, 0.45, 1.5),
    high=(0.9, 0.8, 2.0),
    mass=110.0,
    description="a {finish} casino slot machine with three reels, a button deck, a lit topper "
    "and {lever}",
    variants=(None, (0.75, 0.65, 1.9), (0.6, 0.5, 1.6)),
)
def slot_machine(size: Vec3, rng: Rng) -> Design:
    """A base cabinet, a reel cabinet with a button deck on +X, a topper and maybe a lever."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, (RED_PAINT, BLUE_PAINT, PIANO_BLACK, CHROME))
    lever = chance(rng, 0.6)
    lw = 0.06 if lever else 0.0
    bw = hw - 0.5 * lw  # half width of the body (the lever sticks out at +Y)
    deck_z = clamp(uniform(rng, 0.8, 0.9), 0.7, h - 0.7)
    deck_d = 0.15
    face = hd - deck_d
    reel_z = (deck_z + 0.1, deck_z + 0.1 + clamp(0.3 * (h - deck_z), 0.2, 0.35))
    parts: list[Part] = [
        block((-hd, hd - 0.05), (-bw, bw), (0.0, deck_z - 0.1), finish),
        block((-hd, hd), (-bw, bw), (deck_z - 0.1, deck_z), BLACK_PLASTIC),
        block((-hd, face), (-bw, bw), (deck_z, h), finish),
        block(
            (face, face + 0.002),
            (-bw + 0.05, bw - 0.05),
            (reel_z[1] + 0.05, h - 0.15),
            LIT_SCREEN,
            collide=False,
        ),
        block(
            (face, face + 0.002),
            (-bw + 0.03, bw - 0.03),
            (h - 0.12, h - 0.02),
            MARQUEE,
            collide=False,
        ),
    ]
    rw = (2 * bw - 0.12) / 3
    for k in range(3):
        y = -bw + 0.06 + k * rw
        parts.append(
            block(
                (face, face + 0.002),
                (y + 0.01, y + rw - 0.01),
                reel_z,
                WHITE_PLASTIC,
                collide=False,
            )
        )
    for k in range(4):
        y = -bw + 0.08 + k * (2 * bw - 0.16) / 3
        parts.append(
            block(
                (face + 0.05, face + 0.08),
                (y - 0.02, y + 0.02),
                (deck_z, deck_z + 0.01),
                pick(rng, (RED_PAINT, YELLOW_PAINT, GREEN_PAINT)),
            )
        )
    if lever:
        xl = -hd + 0.5 * d - 0.1
        parts.append(
            block((xl - 0.04, xl + 0.04), (bw, bw + 0.03), (deck_z + 0.1, deck_z + 0.2), CHROME)
        )
        parts.append(
            block(
                (xl - 0.012, xl + 0.012),
                (bw + 0.02, bw + lw - 0.02),
                (deck_z + 0.14, deck_z + 0.5),
                CHROME,
            )
        )
        parts.append(Sphere((xl, bw + lw - 0.03, deck_z + 0.53), 0.03, RED_PAINT))
    words = {"finish": finish.words, "lever": "a pull lever" if lever else "a push button"}
    return Design(tuple(parts), words)


@category(
    "massage_table",
    "furniture",
    size=(1.9, 0.7, 0.7),
    low=(1.7, 0.55, 0.6),
    high=(2.2, 0.85, 0.85),
    mass=16.0,
    friction=0.9,
    description="a padded {cover} massage table with a face cradle on {wood} legs",
    variants=(None, (2.05, 0.75, 0.75), (1.8, 0.6, 0.65)),
)
def massage_table(size: Vec3, rng: Rng) -> Design:
    """A padded top (a surface) on a wooden apron and four legs, a face cradle at +X."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    cover = pick(rng, (BLACK_LEATHER, *FABRICS[:4], WHITE_LACQUER))
    wood = pick(rng, (*WOODS, ALUMINIUM))
    cradle = 0.28
    xt = hd - cradle  # end of the table top
    pad = 0.06
    top_z = h - 0.06
    parts: list[Part] = [
        *[
            p.translated((-0.5 * cradle, 0.0, 0.0))
            for p in square_legs(d - cradle - 0.1, w - 0.1, top_z - 0.08, 0.05, wood)
        ],
        block((-hd, xt), (-hw, hw), (top_z - 0.08, top_z - pad + 0.0), wood),
        block((-hd, xt), (-hw, hw), (top_z - pad, top_z), cover, surface=True),
        block((xt - 0.05, hd - 0.1), (-0.03, 0.03), (top_z - 0.12, top_z - 0.1), CHROME),
        block((hd - 0.12, hd - 0.08), (-0.03, 0.03), (top_z - 0.1, h - pad), CHROME),
        block((hd - 0.08, hd), (-0.12, 0.12), (h - pad, h), cover),
        block((xt + 0.04, hd - 0.08), (-0.12, -0.06), (h - pad, h), cover),
        block((xt + 0.04, hd - 0.08), (0.06, 0.12), (h - pad, h), cover),
    ]
    return Design(tuple(parts), {"cover": cover.words, "wood": wood.words})


@category(
    "telescope",
    "furniture",
    size=(0.6, 0.6, 1.5),
    low=(0.45, 0.45, 1.1),
    high=(1.1, 1.1, 2.3),
    mass=15.0,
    description="a {tube} telescope on a {tripod} tripod with a finder scope",
    variants=(None, (0.9, 0.8, 1.9), (0.5, 0.5, 1.3)),
)
def telescope(size: Vec3, rng: Rng) -> Design:
    """A horizontal tube (eyepiece at -X) on a mount head over three slanted tripod legs,
    two feet at -X and one at +X, each on a rubber pad."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    tube = pick(rng, (WHITE_LACQUER, BLACK_PLASTIC, BLUE_PAINT, BRASS))
    tripod = pick(rng, (ALUMINIUM, OAK, BLACK_METAL))
    r = clamp(uniform(rng, 0.07, 0.1), 0.05, 0.12 * d)
    mount = 0.12
    head_z = h - 2 * r - mount
    s = 0.035
    f = 0.03  # half size of a foot pad
    spread_x = min(hd, hw) - f
    parts: list[Part] = [
        rod("x", -hd + 0.06, hd - 0.08, 0.0, h - r, r, tube),
        rod("x", hd - 0.08, hd, 0.0, h - r, r, BLACK_PLASTIC),
        rod("x", -hd, -hd + 0.06, 0.0, h - r, 0.025, BLACK_PLASTIC),
        block((-0.07, 0.07), (-0.06, 0.06), (head_z, h - 2 * r), BLACK_METAL),
        cyl(0.0, 0.0, head_z - 0.06, head_z, 0.07, tripod),
    ]
    finder_y = min(r + 0.03, hw - 0.02)
    parts.append(rod("x", -0.15 * d, 0.1 * d, finder_y, h - r, 0.02, BLACK_PLASTIC))
    parts.append(
        block((-0.02, 0.02), (r - 0.01, finder_y), (h - r - 0.01, h - r + 0.01), BLACK_PLASTIC)
    )
    feet = [(-0.5 * spread_x, -(hw - f)), (-0.5 * spread_x, hw - f), (spread_x, 0.0)]
    for fx, fy in feet:
        parts.append(block((fx - f, fx + f), (fy - f, fy + f), (0.0, 0.02), RUBBER))
        top = (0.045 * np.sign(fx) if abs(fx) > 1e-9 else 0.0, 0.045 * np.sign(fy), head_z - 0.05)
        parts.append(strut((fx, fy, 0.02), top, s, tripod))
    words = {"tube": tube.words, "tripod": tripod.words}
    return Design(tuple(parts), words)
