"""Generators of games, toys and small sport items.

Small items stand on furniture (placement ``object``, issue 15). Sizes follow the knowledge
base (``objects.json``, whose (width, depth, height) is (y, x, z) here); fronts face +X.
"""

from __future__ import annotations

from asset_pipeline.procedural.kit import (
    CARDBOARD,
    CHROME,
    COVERS,
    PAPER,
    SCREEN,
    TOYS,
    WOODS,
    Rng,
    block,
    clamp,
    pick,
)
from asset_pipeline.procedural.parts import Part, RecipeMaterial, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.round_parts import Sphere
from asset_pipeline.procedural.small_kit import (
    BLUE_METAL,
    CAST_IRON,
    GREEN_METAL,
    NYLON_RED,
    OBJECT,
    RED_ENAMEL,
    ROUND,
    RUBBER,
    cyl_x,
    cyl_y,
    cyl_z,
    deco,
)

PLUSH_BROWN = RecipeMaterial("plush_brown", (0.50, 0.33, 0.19, 1.0), 0.0, 0.05, "brown")
PLUSH_HONEY = RecipeMaterial("plush_honey", (0.80, 0.60, 0.34, 1.0), 0.0, 0.05, "honey")
PLUSH_CREAM = RecipeMaterial("plush_cream", (0.92, 0.87, 0.77, 1.0), 0.0, 0.05, "cream")
CHESS_DARK = RecipeMaterial("chess_dark", (0.25, 0.16, 0.10, 1.0), 0.4, 0.4)
CHESS_LIGHT = RecipeMaterial("chess_light", (0.90, 0.82, 0.64, 1.0), 0.4, 0.4)


# --- games, toys, sport --------------------------------------------------------------------
@category(
    "board_game",
    "object",
    size=(0.27, 0.4, 0.07),
    low=(0.18, 0.25, 0.03),
    high=(0.45, 0.55, 0.1),
    mass=1.0,
    placement=OBJECT,
    description="a boxed board game with a {colour} lid",
    variants=(None, (0.26, 0.26, 0.06)),
)
def board_game(size: Vec3, rng: Rng) -> Design:
    """A game box: the base and its lid (a surface), a printed panel on the lid."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    colour = pick(rng, (*COVERS, *TOYS))
    parts: list[Part] = [
        block((-hd + 0.002, hd - 0.002), (-hw + 0.002, hw - 0.002), (0.0, 0.3 * h), CARDBOARD),
        block((-hd, hd), (-hw, hw), (0.3 * h, h - 0.0008), colour, surface=True),
        deco((-0.3 * d, 0.3 * d), (-0.35 * w, 0.35 * w), (h - 0.0008, h), PAPER),
    ]
    return Design(tuple(parts), {"colour": colour.words})


@category(
    "chess_set",
    "object",
    size=(0.4, 0.4, 0.1),
    low=(0.25, 0.25, 0.05),
    high=(0.55, 0.55, 0.14),
    mass=1.8,
    placement=OBJECT,
    yx_ratio=ROUND,
    description="a {wood} chess set with its pieces",
    variants=(None, (0.3, 0.3, 0.08)),
)
def chess_set(size: Vec3, rng: Rng) -> Design:
    """A chess board with 32 pieces on their starting squares."""
    d, _, h = size
    hd = 0.5 * d
    wood = pick(rng, WOODS)
    bt = clamp(0.2 * h, 0.012, 0.025)
    border = 0.05 * d
    sq = (d - 2 * border) / 8
    parts: list[Part] = [block((-hd, hd), (-hd, hd), (0.0, bt), wood)]
    for i in range(8):
        for j in range(8):
            if (i + j) % 2 == 0:
                x, y = -hd + border + i * sq, -hd + border + j * sq
                parts.append(deco((x, x + sq), (y, y + sq), (bt, bt + 0.0005), CHESS_DARK))
    pr = 0.3 * sq
    tall = h - bt
    for i, material in ((0, CHESS_LIGHT), (1, CHESS_LIGHT), (6, CHESS_DARK), (7, CHESS_DARK)):
        x = -hd + border + (i + 0.5) * sq
        for j in range(8):
            y = -hd + border + (j + 0.5) * sq
            pawn = i in (1, 6)
            ph = 0.5 * tall if pawn else (tall if j in (3, 4) else 0.75 * tall)
            half = (0.7 if pawn else 0.85) * pr
            parts.append(deco((x - half, x + half), (y - half, y + half), (bt, bt + ph), material))
    return Design(tuple(parts), {"wood": wood.words})


@category(
    "toy_car",
    "object",
    size=(0.07, 0.15, 0.06),
    low=(0.04, 0.08, 0.03),
    high=(0.12, 0.3, 0.12),
    mass=0.15,
    placement=OBJECT,
    yx_ratio=(1.5, 3.0),
    zx_ratio=(0.5, 1.2),
    description="a {colour} toy car",
    variants=(None, (0.06, 0.12, 0.05)),
)
def toy_car(size: Vec3, rng: Rng) -> Design:
    """A toy car along Y: four wheels, a body and a cabin with windows."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    colour = pick(rng, TOYS)
    rw = min(0.3 * h, 0.14 * w)
    wt = 0.18 * d
    body = (0.6 * rw, 0.6 * h)
    parts: list[Part] = [
        block((-hd + wt, hd - wt), (-hw, hw), body, colour),
        block((-hd + wt, hd - wt), (-0.28 * w, 0.15 * w), (body[1], h), colour),
        deco((hd - wt, hd - wt + 0.001), (-0.24 * w, 0.11 * w), (body[1] + 0.004, h - 0.004),
             SCREEN),
    ]  # fmt: skip
    for y in (-hw + 0.04 * w + rw, hw - 0.04 * w - rw):
        for x0, x1 in ((-hd, -hd + wt), (hd - wt, hd)):
            parts.append(cyl_x(x0, x1, y, rw, rw, RUBBER))
    return Design(tuple(parts), {"colour": colour.words})


@category(
    "teddy_bear",
    "object",
    size=(0.2, 0.25, 0.3),
    low=(0.12, 0.15, 0.16),
    high=(0.4, 0.5, 0.6),
    mass=0.4,
    placement=OBJECT,
    yx_ratio=(0.9, 1.6),
    zx_ratio=(1.1, 2.0),
    description="a {plush} plush teddy bear sitting up",
    variants=(None, (0.16, 0.2, 0.24)),
)
def teddy_bear(size: Vec3, rng: Rng) -> Design:
    """A sitting teddy: a round body, legs forward (+X), arms to the sides, head and ears."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    plush = pick(rng, (PLUSH_BROWN, PLUSH_HONEY, PLUSH_CREAM))
    rb = min(0.4 * d, 0.4 * w, 0.3 * h)
    bx = -hd + rb
    bz = 0.92 * rb
    rh = 0.75 * rb
    hz = h - rh
    rl = 0.3 * rb
    ra = 0.25 * rb
    parts: list[Part] = [
        Sphere((bx, 0.0, bz), rb, plush, cut=0.0, rings=6),
        cyl_z(bx, 0.0, bz, hz, 0.45 * rb, plush),
        Sphere((bx, 0.0, hz), rh, plush, rings=6),
        cyl_x(bx + 0.7 * rh, bx + 1.1 * rh, 0.0, hz - 0.15 * rh, 0.3 * rh, PLUSH_CREAM,
              collide=False),
    ]  # fmt: skip
    for sign in (-1.0, 1.0):
        parts.append(cyl_x(bx, hd, sign * 0.5 * rb, rl, rl, plush))
        arm = sorted((sign * 0.5 * rb, sign * hw))
        parts.append(cyl_y(arm[0], arm[1], bx + 0.2 * rb, bz + 0.3 * rb, ra, plush))
        parts.append(cyl_x(bx - 0.08 * rh, bx + 0.08 * rh, sign * 0.7 * rh, hz + 0.7 * rh,
                           0.3 * rh, plush, collide=False))  # fmt: skip
    return Design(tuple(parts), {"plush": plush.words})


@category(
    "dumbbell",
    "object",
    size=(0.12, 0.3, 0.12),
    low=(0.07, 0.2, 0.07),
    high=(0.2, 0.45, 0.2),
    mass=5.0,
    placement=("floor", "object"),
    description="a {coating} dumbbell",
    variants=(None, (0.1, 0.26, 0.1)),
)
def dumbbell(size: Vec3, rng: Rng) -> Design:
    """A dumbbell lying along Y: two square heads and a knurled handle."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    coating = pick(rng, (RUBBER, CAST_IRON, CHROME, NYLON_RED))
    head = clamp(0.2 * w, 0.04, 0.1)
    hr = 0.15 * min(d, h)
    parts: list[Part] = [
        block((-hd, hd), (-hw, -hw + head), (0.0, h), coating),
        block((-hd, hd), (hw - head, hw), (0.0, h), coating),
        cyl_y(-hw + head, hw - head, 0.0, 0.5 * h, hr, CHROME),
    ]
    return Design(tuple(parts), {"coating": coating.words})


@category(
    "kettlebell",
    "object",
    size=(0.15, 0.2, 0.25),
    low=(0.1, 0.12, 0.14),
    high=(0.25, 0.32, 0.4),
    mass=12.0,
    placement=("floor", "object"),
    yx_ratio=(1.0, 1.6),
    zx_ratio=(1.25, 2.2),
    description="a {finish} kettlebell",
    variants=(None, (0.13, 0.17, 0.21)),
)
def kettlebell(size: Vec3, rng: Rng) -> Design:
    """A kettlebell: a ball flattened at its base and a handle arch over it."""
    d, w, h = size
    hw = 0.5 * w
    finish = pick(rng, (CAST_IRON, RED_ENAMEL, BLUE_METAL, GREEN_METAL))
    r = 0.5 * d
    cut = 0.15 * r
    cz = r - cut
    t = clamp(0.12 * r, 0.01, 0.02)
    lug_z = cz + 0.5 * r
    parts: list[Part] = [Sphere((0.0, 0.0, cz), r, finish, cut=0.0)]
    for sign in (-1.0, 1.0):
        ys = sorted((sign * 0.55 * r, sign * hw))
        parts.append(block((-t, t), ys, (lug_z, lug_z + 2 * t), finish))
        post = sorted((sign * hw, sign * (hw - 2 * t)))
        parts.append(block((-t, t), post, (lug_z + 2 * t, h - 2 * t), finish))
    parts.append(block((-t, t), (-hw, hw), (h - 2 * t, h), finish))
    return Design(tuple(parts), {"finish": finish.words})
