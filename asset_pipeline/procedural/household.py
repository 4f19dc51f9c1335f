"""Small household objects: fruit, toys, a remote, cookware, candles and a small plant."""

from __future__ import annotations

from asset_pipeline.procedural.kit import (
    APPLE_GREEN,
    APPLE_RED,
    BLACK_METAL,
    BLACK_PLASTIC,
    CERAMICS,
    CHROME,
    DARK_FOLIAGE,
    FOLIAGE,
    ORANGE_PEEL,
    RED_WAX,
    SOIL,
    SPACE_GREY,
    STEEL,
    STEM,
    TERRACOTTA,
    TOYS,
    WAX,
    WHITE_PLASTIC,
    WICK,
    WOODS,
    Rng,
    block,
    chance,
    clamp,
    pick,
    uniform,
)
from asset_pipeline.procedural.objects import (
    OBJECT,
    ROUND,
)
from asset_pipeline.procedural.parts import Part, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.round_parts import Cylinder, Lathe, Sphere


# --- fruit, toys, cookware, candles and plants ----------------------------------------------------
def _fruit(size: Vec3, rng: Rng, skin, stem: bool) -> list[Part]:
    d, _, h = size
    r = 0.5 * d
    stem_h = 0.008 if stem else 0.0
    body = h - stem_h
    cut = 2.0 * r - body  # flattened base
    parts: list[Part] = [Sphere((0.0, 0.0, r - cut), r, skin, cut=0.0)]
    if stem:
        parts.append(
            Cylinder(
                (0.0, 0.0, body + 0.5 * stem_h - 0.002),
                0.003,
                0.5 * stem_h + 0.002,
                STEM,
                collide=False,
            )
        )
    return parts


@category(
    "apple",
    "object",
    size=(0.08, 0.08, 0.083),
    low=(0.06, 0.06, 0.05),
    high=(0.1, 0.1, 0.11),
    mass=0.18,
    friction=0.7,
    placement=OBJECT,
    yx_ratio=ROUND,
    zx_ratio=(0.9, 1.05),
    description="a {skin} apple",
    variants=(None, (0.072, 0.072, 0.07)),
)
def apple(size: Vec3, rng: Rng) -> Design:
    """An apple: a sphere flattened at its base, with a stem."""
    skin = pick(rng, (APPLE_RED, APPLE_GREEN))
    return Design(tuple(_fruit(size, rng, skin, stem=True)), {"skin": skin.words})


@category(
    "orange",
    "object",
    size=(0.075, 0.075, 0.072),
    low=(0.055, 0.055, 0.05),
    high=(0.1, 0.1, 0.1),
    mass=0.2,
    friction=0.7,
    placement=OBJECT,
    yx_ratio=ROUND,
    zx_ratio=(0.9, 0.98),
    description="an orange",
)
def orange(size: Vec3, rng: Rng) -> Design:
    """An orange: a sphere slightly flattened at its base."""
    return Design(tuple(_fruit(size, rng, ORANGE_PEEL, stem=False)), {})


@category(
    "toy_block",
    "object",
    size=(0.05, 0.05, 0.05),
    low=(0.02, 0.02, 0.02),
    high=(0.12, 0.12, 0.12),
    mass=0.06,
    friction=0.6,
    placement=OBJECT,
    description="a {colour} wooden toy block",
    variants=(None, (0.08, 0.04, 0.04)),
)
def toy_block(size: Vec3, rng: Rng) -> Design:
    """A painted wooden block; its top is a surface when it is big enough."""
    d, w, h = size
    colour = pick(rng, TOYS)
    top = min(d, w) > 0.055
    part = block((-0.5 * d, 0.5 * d), (-0.5 * w, 0.5 * w), (0.0, h), colour, surface=top)
    return Design((part,), {"colour": colour.words})


@category(
    "toy_ball",
    "object",
    size=(0.1, 0.1, 0.097),
    low=(0.04, 0.04, 0.037),
    high=(0.25, 0.25, 0.245),
    mass=0.15,
    friction=0.8,
    placement=OBJECT,
    yx_ratio=ROUND,
    zx_ratio=(0.94, 0.98),
    description="a {colour} soft toy ball",
)
def toy_ball(size: Vec3, rng: Rng) -> Design:
    """A soft ball, slightly squashed flat where it rests so that it does not roll away."""
    d, _, h = size
    r = 0.5 * d
    colour = pick(rng, TOYS)
    return Design((Sphere((0.0, 0.0, h - r), r, colour, cut=0.0),), {"colour": colour.words})


@category(
    "remote",
    "object",
    size=(0.18, 0.05, 0.022),
    low=(0.12, 0.035, 0.012),
    high=(0.25, 0.07, 0.035),
    mass=0.12,
    friction=0.7,
    placement=OBJECT,
    description="a {colour} tv remote control",
)
def remote(size: Vec3, rng: Rng) -> Design:
    """A remote control lying flat, buttons on top."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    body = pick(rng, (BLACK_PLASTIC, SPACE_GREY, WHITE_PLASTIC))
    top = h - 0.0008
    parts: list[Part] = [block((-hd, hd), (-hw, hw), (0.0, top), body)]
    keys = BLACK_PLASTIC if body is not BLACK_PLASTIC else SPACE_GREY
    for i in range(4):
        x = -hd + 0.03 + i * (d - 0.06) / 3
        parts.append(
            block((x - 0.008, x + 0.008), (-0.3 * w, 0.3 * w), (top, h), keys, collide=False)
        )
    return Design(tuple(parts), {"colour": body.words})


@category(
    "pot",
    "object",
    size=(0.22, 0.3, 0.14),
    low=(0.14, 0.17, 0.07),
    high=(0.32, 0.46, 0.25),
    mass=1.5,
    friction=0.6,
    placement=OBJECT,
    yx_ratio=(1.15, 1.45),
    description="a {metal} cooking pot with two handles{lid}",
    variants=(None, (0.18, 0.24, 0.1)),
)
def pot(size: Vec3, rng: Rng) -> Design:
    """A cooking pot (diameter x) with handles on +-Y, maybe with a lid."""
    d, w, h = size
    r = 0.5 * d
    metal = pick(rng, (STEEL, BLACK_METAL, CHROME))
    reach = 0.5 * (w - d)
    lid = chance(rng, 0.5)
    knob = 0.02 if lid else 0.0
    body_h = h - knob - (0.006 if lid else 0.0)
    parts: list[Part] = [
        Lathe((0.0, 0.0, 0.0), ((r, 0.0), (r, body_h)), metal, hollow=(0.004, 0.006))
    ]
    hz = body_h - 0.02
    for sign in (-1.0, 1.0):
        y = sorted((sign * (r - 0.004), sign * (r + reach)))
        parts.append(block((-0.025, 0.025), (y[0], y[1]), (hz - 0.012, hz), BLACK_METAL))
    if lid:
        parts.append(Cylinder((0.0, 0.0, body_h + 0.003), r, 0.003, metal))
        parts.append(
            Cylinder((0.0, 0.0, body_h + 0.006 + 0.5 * knob), 0.015, 0.5 * knob, BLACK_METAL)
        )
    return Design(tuple(parts), {"metal": metal.words, "lid": " and a lid" if lid else ""})


@category(
    "pan",
    "object",
    size=(0.26, 0.48, 0.05),
    low=(0.16, 0.28, 0.03),
    high=(0.32, 0.66, 0.08),
    mass=1.2,
    friction=0.6,
    placement=OBJECT,
    yx_ratio=(1.6, 2.1),
    description="a {metal} frying pan with a {handle} handle",
)
def pan(size: Vec3, rng: Rng) -> Design:
    """A frying pan (diameter x) with a long handle on +Y."""
    d, w, h = size
    r = 0.5 * d
    metal = pick(rng, (BLACK_METAL, STEEL))
    handle = pick(rng, (BLACK_PLASTIC, *WOODS[:2], STEEL))
    profile = ((0.85 * r, 0.0), (r, h))
    parts: list[Part] = [
        Lathe((0.0, 0.0, 0.0), profile, metal, hollow=(0.003, 0.004)),
        block((-0.014, 0.014), (r - 0.006, w - r), (h - 0.02, h - 0.004), handle),
    ]
    return Design(tuple(parts), {"metal": metal.words, "handle": handle.words})


@category(
    "candle",
    "object",
    size=(0.07, 0.07, 0.12),
    low=(0.02, 0.02, 0.05),
    high=(0.12, 0.12, 0.3),
    mass=0.4,
    friction=0.6,
    placement=OBJECT,
    yx_ratio=ROUND,
    zx_ratio=(0.5, 10.0),
    description="a {wax} pillar candle",
    variants=(None, (0.025, 0.025, 0.25)),
)
def candle(size: Vec3, rng: Rng) -> Design:
    """A pillar candle with its wick."""
    d, _, h = size
    wax = pick(rng, (WAX, RED_WAX))
    wick_h = 0.01
    parts: list[Part] = [
        Cylinder((0.0, 0.0, 0.5 * (h - wick_h)), 0.5 * d, 0.5 * (h - wick_h), wax),
        Cylinder(
            (0.0, 0.0, h - 0.5 * wick_h - 0.001), 0.0015, 0.5 * wick_h + 0.001, WICK, collide=False
        ),
    ]
    return Design(tuple(parts), {"wax": wax.words})


@category(
    "small_plant",
    "object",
    size=(0.18, 0.18, 0.28),
    low=(0.1, 0.1, 0.14),
    high=(0.35, 0.35, 0.6),
    mass=1.5,
    friction=0.7,
    placement=OBJECT,
    yx_ratio=ROUND,
    zx_ratio=(1.1, 2.5),
    description="a small {leaves} houseplant in a {pot} pot",
    variants=(None, (0.14, 0.14, 0.2)),
)
def small_plant(size: Vec3, rng: Rng) -> Design:
    """A small plant for shelves and tables: a pot and a round crown as wide as the plant."""
    d, _, h = size
    crown = 0.5 * d
    pot_mat = pick(rng, (TERRACOTTA, *CERAMICS[:3]))
    leaves = pick(rng, (FOLIAGE, DARK_FOLIAGE))
    pot_h = h - uniform(rng, 1.3, 1.65) * crown
    pot_r = clamp(uniform(rng, 0.55, 0.75) * crown, 0.03, crown)
    parts: list[Part] = [
        Lathe(
            (0.0, 0.0, 0.0), ((0.8 * pot_r, 0.0), (pot_r, pot_h)), pot_mat, hollow=(0.006, 0.012)
        ),
        Cylinder((0.0, 0.0, pot_h - 0.012), pot_r - 0.01, 0.004, SOIL, collide=False),
        Sphere((0.0, 0.0, h - crown), crown, leaves),
    ]
    return Design(tuple(parts), {"leaves": leaves.words, "pot": pot_mat.words})
