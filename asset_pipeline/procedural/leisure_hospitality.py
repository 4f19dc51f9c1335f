"""Generators of salon and hospitality pieces (front +X).

Every generator fills exactly ``[-d/2, d/2] x [-w/2, w/2] x [0, h]`` (x = depth, y = width).
"""

from __future__ import annotations

import numpy as np

from asset_pipeline.procedural.kit import (
    BLACK_METAL,
    BLACK_PLASTIC,
    BRASS,
    CHROME,
    CLEAR_GLASS,
    PIANO_BLACK,
    PORCELAIN,
    STEEL,
    WALNUT,
    WHITE_LACQUER,
    WOODS,
    Rng,
    block,
    clamp,
    drawer_fronts,
    pick,
    uniform,
)
from asset_pipeline.procedural.leisure_kit import (
    BLUE_PAINT,
    MARQUEE,
    NUMBER_WORDS,
    RED_PAINT,
    UPHOLSTERY,
    YELLOW_PAINT,
    cyl,
    rod,
    tilted,
)
from asset_pipeline.procedural.parts import Part, RecipeMaterial, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.round_parts import Lathe

POPCORN = RecipeMaterial("popcorn", (0.98, 0.90, 0.62, 1.0), 0.1, 0.1)


# --- salon and hospitality -------------------------------------------------------------------
@category(
    "salon_chair",
    "furniture",
    size=(0.75, 0.65, 1.05),
    low=(0.6, 0.55, 0.9),
    high=(0.9, 0.8, 1.25),
    mass=45.0,
    friction=0.9,
    description="a hydraulic hair salon chair in {cover} on a {metal} round base with a footrest",
    variants=(None, (0.8, 0.7, 1.15), (0.65, 0.6, 0.95)),
)
def salon_chair(size: Vec3, rng: Rng) -> Design:
    """A round base, a hydraulic column, seat, arms at +-Y, back at -X, footrest at +X."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    cover = pick(rng, UPHOLSTERY)
    metal = pick(rng, (CHROME, BLACK_METAL))
    base_r = clamp(uniform(rng, 0.26, 0.3), 0.2, min(hw, hd - 0.05) - 0.01)
    seat_z = clamp(uniform(rng, 0.52, 0.58), 0.45, h - 0.35)
    back_t = 0.1
    arm_w = 0.08
    cx = -0.05
    parts: list[Part] = [
        cyl(cx, 0.0, 0.0, 0.04, base_r, metal),
        cyl(cx, 0.0, 0.04, seat_z - 0.18, 0.05, metal),
        block(
            (cx - 0.2, cx + 0.2), (-hw + arm_w, hw - arm_w), (seat_z - 0.18, seat_z - 0.1), metal
        ),
        block((-hd + back_t, hd - 0.14), (-hw + arm_w, hw - arm_w), (seat_z - 0.1, seat_z), cover),
        block((-hd, -hd + back_t), (-hw + 0.02, hw - 0.02), (seat_z - 0.1, h), cover),
    ]
    arm_z = seat_z + clamp(uniform(rng, 0.16, 0.22), 0.12, h - seat_z - 0.1)
    for y in ((-hw, -hw + arm_w), (hw - arm_w, hw)):
        parts.append(block((-hd + back_t, hd - 0.18), y, (seat_z - 0.1, arm_z), cover))
        parts.append(block((-hd + back_t, hd - 0.15), y, (arm_z, arm_z + 0.03), metal))
    parts.append(block((cx + 0.18, hd - 0.05), (-0.025, 0.025), (0.12, 0.16), metal))
    parts.append(block((hd - 0.08, hd), (-0.2, 0.2), (0.1, 0.16), metal))
    return Design(tuple(parts), {"cover": cover.words, "metal": metal.words})


@category(
    "styling_station",
    "furniture",
    size=(0.5, 1.0, 0.8),
    low=(0.35, 0.6, 0.7),
    high=(0.65, 1.5, 1.0),
    mass=40.0,
    description="a {finish} salon styling station with {drawers} drawers and a {metal} dryer "
    "holder",
    variants=(None, (0.55, 1.2, 0.85), (0.4, 0.8, 0.75)),
)
def styling_station(size: Vec3, rng: Rng) -> Design:
    """A counter cabinet (top surface) with drawers on +X and a dryer holster on one side."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, (WHITE_LACQUER, PIANO_BLACK, *WOODS[:2]))
    metal = pick(rng, (CHROME, BLACK_METAL, BRASS))
    holder = 0.08
    top_t = 0.03
    face = hd - 0.036
    cols = 2 if w > 0.9 else 1
    rows = int(rng.integers(2, 4))
    parts: list[Part] = [
        block((-hd, hd), (-hw + holder, hw), (h - top_t, h), finish, surface=True),
        block((-hd, face), (-hw + holder, hw), (0.06, h - top_t), finish),
        block(
            (-hd + 0.02, face - 0.02), (-hw + holder + 0.02, hw - 0.02), (0.0, 0.06), BLACK_PLASTIC
        ),
        block((-0.05, 0.05), (-hw + 0.05, -hw + holder), (h - 0.25, h - 0.2), metal),
        cyl(0.0, -hw + 0.04, h - 0.25, h - 0.12, 0.04, metal),
        block((-0.05, 0.05), (-hw + 0.05, -hw + holder), (h - 0.12, h - 0.1), metal),
    ]
    parts[4] = Lathe(
        (0.0, -hw + 0.04, h - 0.25), ((0.035, 0.0), (0.04, 0.13)), metal, hollow=(0.004, 0.01)
    )
    parts += drawer_fronts(
        face, (-hw + holder, hw), (0.07, h - top_t - 0.01), rows, cols, finish, metal
    )
    return Design(
        tuple(parts),
        {"finish": finish.words, "metal": metal.words, "drawers": NUMBER_WORDS[rows * cols]},
    )


@category(
    "shampoo_station",
    "furniture",
    size=(1.2, 0.7, 0.95),
    low=(1.0, 0.55, 0.85),
    high=(1.5, 0.9, 1.1),
    mass=70.0,
    description="a salon backwash unit: a {basin} basin on a cabinet and a reclining {cover} chair",
    variants=(None, (1.3, 0.75, 1.0), (1.1, 0.6, 0.9)),
)
def shampoo_station(size: Vec3, rng: Rng) -> Design:
    """A basin on a cabinet at -X and a chair facing +X whose tilted back leans into it."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    basin = pick(
        rng,
        (
            PORCELAIN,
            RecipeMaterial("basin_black", (0.08, 0.08, 0.09, 1.0), 0.8, 0.8, "black ceramic"),
        ),
    )
    cover = pick(rng, UPHOLSTERY)
    cab = pick(rng, (PIANO_BLACK, WHITE_LACQUER, WALNUT))
    br = clamp(0.45 * w, 0.2, 0.3)
    bowl_h = 0.18
    cab_x = (-hd, -hd + 2 * br + 0.04)
    bx = cab_x[0] + br + 0.02
    seat_z = 0.48
    arm_w = 0.08
    parts: list[Part] = [
        block(cab_x, (-br - 0.02, br + 0.02), (0.0, h - bowl_h), cab),
        Lathe((bx, 0.0, h - bowl_h), ((0.6 * br, 0.0), (br, bowl_h)), basin, hollow=(0.02, 0.06)),
        cyl(cab_x[0] + 0.03, 0.0, h - bowl_h, h - bowl_h + 0.1, 0.015, CHROME),
        block((cab_x[1], hd), (-hw + arm_w, hw - arm_w), (0.0, 0.08), cab),
        block((cab_x[1] + 0.05, hd - 0.05), (-hw + arm_w, hw - arm_w), (0.08, seat_z - 0.1), cab),
        block((cab_x[1] + 0.25, hd), (-hw + arm_w, hw - arm_w), (seat_z - 0.1, seat_z), cover),
    ]
    for y in ((-hw, -hw + arm_w), (hw - arm_w, hw)):
        parts.append(block((cab_x[1] + 0.2, hd - 0.05), y, (0.0, seat_z + 0.2), cover))
    # tilted back from the seat's rear up towards the basin rim
    angle = np.radians(uniform(rng, 40.0, 50.0))
    x0, x1 = cab_x[1] + 0.02, cab_x[1] + 0.25
    z0, z1 = seat_z - 0.1, h - bowl_h - 0.04
    length = float(np.hypot(x1 - x0, z1 - z0))
    angle = float(np.arctan2(z1 - z0, x1 - x0))
    centre = (0.5 * (x0 + x1), 0.0, 0.5 * (z0 + z1))
    parts.append(tilted(centre, length, 2 * (hw - arm_w) - 0.02, 0.1, np.pi - angle, cover))
    return Design(tuple(parts), {"basin": basin.words, "cover": cover.words})


@category(
    "popcorn_machine",
    "furniture",
    size=(0.5, 0.6, 1.6),
    low=(0.4, 0.45, 1.3),
    high=(0.7, 0.9, 1.9),
    mass=45.0,
    description="a {colour} popcorn machine with a glass cabinet full of popcorn on a wheeled cart",
    variants=(None, (0.55, 0.7, 1.7), (0.45, 0.5, 1.4)),
)
def popcorn_machine(size: Vec3, rng: Rng) -> Design:
    """A cart on four wheels, a coloured cabinet, a glass popper with a kettle and a roof."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    colour = pick(rng, (RED_PAINT, YELLOW_PAINT, BLUE_PAINT))
    r = 0.06
    cart_top = clamp(uniform(rng, 0.7, 0.8), 0.6, h - 0.6)
    glass_top = h - clamp(uniform(rng, 0.12, 0.16), 0.1, 0.2)
    post = 0.03
    parts: list[Part] = []
    for x in (-hd + r, hd - r):
        for y in (-hw + 0.04, hw - 0.04):
            parts.append(rod("y", y - 0.02, y + 0.02, x, r, r, BLACK_PLASTIC))
            parts.append(
                block((x - 0.015, x + 0.015), (y - 0.03, y - 0.02), (r, r + 0.06), BLACK_METAL)
            )
    parts.append(block((-hd, hd), (-hw, hw), (2 * r, 2 * r + 0.04), colour))
    parts.append(
        block((-hd + 0.02, hd - 0.02), (-hw + 0.02, hw - 0.02), (2 * r + 0.04, cart_top), colour)
    )
    parts.append(block((-hd, hd), (-hw, hw), (cart_top, cart_top + 0.03), BLACK_METAL))
    z0 = cart_top + 0.03
    for xs in ((-hd, -hd + post), (hd - post, hd)):
        for ys in ((-hw, -hw + post), (hw - post, hw)):
            parts.append(block(xs, ys, (z0, glass_top), colour))
    g = 0.006
    parts += [
        block((hd - g, hd), (-hw + post, hw - post), (z0, glass_top), CLEAR_GLASS),
        block((-hd, -hd + g), (-hw + post, hw - post), (z0, glass_top), CLEAR_GLASS),
        block((-hd + post, hd - post), (-hw, -hw + g), (z0, glass_top), CLEAR_GLASS),
        block((-hd + post, hd - post), (hw - g, hw), (z0, glass_top), CLEAR_GLASS),
        block((-hd + post, hd - post), (-hw + post, hw - post), (z0, z0 + 0.12), POPCORN),
        block((-hd, hd), (-hw, hw), (glass_top, h - 0.04), colour),
        block((-hd + 0.04, hd - 0.04), (-hw + 0.04, hw - 0.04), (h - 0.04, h), MARQUEE),
        cyl(0.0, 0.0, glass_top - 0.06, glass_top, 0.015, STEEL),
        Lathe((0.0, 0.0, glass_top - 0.2), ((0.07, 0.0), (0.11, 0.14)), STEEL),
    ]
    return Design(tuple(parts), {"colour": colour.words})
