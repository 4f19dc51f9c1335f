"""Generators of small objects that rest on furniture (placement ``object``).

Round objects (``yx_ratio=(1, 1)``) take x = y = diameter.
"""

from __future__ import annotations

from asset_pipeline.procedural.kit import (
    ALUMINIUM,
    AMBER_GLASS,
    BLACK_METAL,
    BLACK_PLASTIC,
    BRASS,
    CARDBOARD,
    CERAMICS,
    CHROME,
    CLEAR_GLASS,
    COVERS,
    GREEN_GLASS,
    LAMP_SHADE,
    PAPER,
    PORCELAIN,
    SCREEN,
    SPACE_GREY,
    TAPE,
    WHITE_PLASTIC,
    WHITE_SHADE,
    Rng,
    block,
    chance,
    clamp,
    pick,
    uniform,
)
from asset_pipeline.procedural.parts import Part, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.roles import tagged
from asset_pipeline.procedural.round_parts import Cylinder, Lathe

OBJECT = ("object",)
ROUND = (1.0, 1.0)


@category(
    "book",
    "object",
    size=(0.23, 0.16, 0.03),
    low=(0.1, 0.08, 0.008),
    high=(0.35, 0.28, 0.08),
    mass=0.5,
    friction=0.6,
    placement=OBJECT,
    description="a {cover} {binding} book lying flat",
    variants=(None, (0.2, 0.13, 0.02)),
)
def book(size: Vec3, rng: Rng) -> Design:
    """A book lying flat, spine at -Y; its top cover is a surface (books stack)."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    cover = pick(rng, COVERS)
    hard = chance(rng, 0.6)
    c = min(0.003 if hard else 0.001, 0.15 * h)
    parts: list[Part] = [
        block((-hd, hd), (-hw, hw), (0.0, c), cover),
        block((-hd, hd), (-hw, hw), (h - c, h), cover, surface=w > 0.06),
        block((-hd, hd), (-hw, -hw + c), (c, h - c), cover),
        block((-hd + c, hd - c), (-hw + c, hw - c), (c, h - c), PAPER),
    ]
    return Design(
        tuple(parts), {"cover": cover.words, "binding": "hardback" if hard else "paperback"}
    )


@category(
    "cardboard_box",
    "object",
    size=(0.4, 0.3, 0.25),
    low=(0.1, 0.1, 0.06),
    high=(0.8, 0.8, 0.7),
    mass=0.8,
    friction=0.7,
    placement=("floor", "object"),
    description="a closed {material} box sealed with tape",
    variants=(None, (0.3, 0.3, 0.3)),
)
def cardboard_box(size: Vec3, rng: Rng) -> Design:
    """A closed, taped carton; its top is a surface."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    tape_w = clamp(0.15 * w, 0.02, 0.05)
    parts: list[Part] = [
        block((-hd, hd), (-hw, hw), (0.0, h - 0.0005), CARDBOARD, surface=True),
        block((-hd, hd), (-0.5 * tape_w, 0.5 * tape_w), (h - 0.0005, h), TAPE, collide=False),
    ]
    return Design(tuple(parts), {"material": CARDBOARD.words})


@category(
    "mug",
    "object",
    size=(0.082, 0.112, 0.095),
    low=(0.06, 0.075, 0.07),
    high=(0.11, 0.16, 0.13),
    mass=0.3,
    friction=0.6,
    placement=OBJECT,
    yx_ratio=(1.2, 1.45),
    description="a {ceramic} mug with a {handle} handle",
    variants=(None, (0.09, 0.12, 0.11)),
)
def mug(size: Vec3, rng: Rng) -> Design:
    """A mug (diameter x) with a handle on +Y reaching to the width y."""
    d, w, h = size
    r = 0.5 * d
    ceramic = pick(rng, CERAMICS)
    taper = uniform(rng, 0.9, 1.0) if chance(rng, 0.4) else 1.0
    reach = w - d  # handle beyond the body
    t = clamp(uniform(rng, 0.008, 0.012), 0.006, 0.3 * reach)
    y0, y1 = r - 0.004, r + reach
    z0, z1 = 0.22 * h, 0.82 * h
    parts: list[Part] = [
        Lathe((0.0, 0.0, 0.0), ((r * taper, 0.0), (r, h)), ceramic, hollow=(0.005, 0.008)),
        block((-0.006, 0.006), (y0, y1), (z1 - t, z1), ceramic),
        block((-0.006, 0.006), (y0, y1), (z0, z0 + t), ceramic),
        block((-0.006, 0.006), (y1 - t, y1), (z0 + t, z1 - t), ceramic),
    ]
    return Design(
        tuple(parts), {"ceramic": ceramic.words, "handle": "square" if t > 0.01 else "slim"}
    )


@category(
    "cup",
    "object",
    size=(0.075, 0.075, 0.1),
    low=(0.05, 0.05, 0.06),
    high=(0.1, 0.1, 0.16),
    mass=0.22,
    friction=0.6,
    placement=OBJECT,
    yx_ratio=ROUND,
    description="a {material} tumbler",
)
def cup(size: Vec3, rng: Rng) -> Design:
    """A tapered drinking glass or beaker."""
    d, _, h = size
    r = 0.5 * d
    material = pick(rng, (CLEAR_GLASS, *CERAMICS[:3], WHITE_PLASTIC))
    parts: list[Part] = [
        Lathe(
            (0.0, 0.0, 0.0),
            ((r * uniform(rng, 0.72, 0.9), 0.0), (r, h)),
            material,
            hollow=(0.003, 0.006),
        )
    ]
    return Design(tuple(parts), {"material": material.words})


@category(
    "bowl",
    "object",
    size=(0.16, 0.16, 0.065),
    low=(0.1, 0.1, 0.04),
    high=(0.32, 0.32, 0.14),
    mass=0.35,
    friction=0.6,
    placement=OBJECT,
    yx_ratio=ROUND,
    description="a {ceramic} bowl",
    variants=(None, (0.24, 0.24, 0.09)),
)
def bowl(size: Vec3, rng: Rng) -> Design:
    """A flared bowl on a foot."""
    d, _, h = size
    r = 0.5 * d
    ceramic = pick(rng, CERAMICS)
    foot = uniform(rng, 0.5, 0.62) * r
    profile = ((foot, 0.0), (uniform(rng, 0.7, 0.8) * r, 0.3 * h), (r, h))
    return Design(
        (Lathe((0.0, 0.0, 0.0), profile, ceramic, hollow=(0.004, 0.006)),),
        {"ceramic": ceramic.words},
    )


@category(
    "plate",
    "object",
    size=(0.26, 0.26, 0.02),
    low=(0.15, 0.15, 0.012),
    high=(0.34, 0.34, 0.035),
    mass=0.45,
    friction=0.6,
    placement=OBJECT,
    yx_ratio=ROUND,
    description="a round {ceramic} plate",
    variants=(None, (0.2, 0.2, 0.018)),
)
def plate(size: Vec3, rng: Rng) -> Design:
    """A plate with a shallow well."""
    d, _, h = size
    r = 0.5 * d
    ceramic = pick(rng, (PORCELAIN, *CERAMICS))
    foot = uniform(rng, 0.55, 0.62) * r
    profile = ((foot, 0.0), (foot + 0.1 * r, 0.4 * h), (r, h))
    return Design(
        (Lathe((0.0, 0.0, 0.0), profile, ceramic, hollow=(0.004, 0.006)),),
        {"ceramic": ceramic.words},
    )


@category(
    "bottle",
    "object",
    size=(0.072, 0.072, 0.3),
    low=(0.05, 0.05, 0.15),
    high=(0.11, 0.11, 0.38),
    mass=1.2,
    friction=0.5,
    placement=OBJECT,
    yx_ratio=ROUND,
    zx_ratio=(2.0, 7.0),
    description="a {glass} bottle",
    variants=(None, (0.065, 0.065, 0.22)),
)
def bottle(size: Vec3, rng: Rng) -> Design:
    """A bottle: body, shoulder, neck, lip."""
    d, _, h = size
    r = 0.5 * d
    glass = pick(rng, (GREEN_GLASS, AMBER_GLASS, CLEAR_GLASS))
    body = uniform(rng, 0.55, 0.7) * h
    neck_r = clamp(0.3 * r, 0.009, 0.5 * r)
    profile = (
        (r, 0.0),
        (r, body),
        (neck_r, body + 0.6 * (h - body) * uniform(rng, 0.5, 1.0)),
        (neck_r, h - 0.01),
        (neck_r * 1.15, h),
    )
    return Design((Lathe((0.0, 0.0, 0.0), profile, glass),), {"glass": glass.words})


@category(
    "vase",
    "object",
    size=(0.15, 0.15, 0.3),
    low=(0.08, 0.08, 0.12),
    high=(0.35, 0.35, 0.7),
    mass=1.0,
    friction=0.6,
    placement=OBJECT,
    yx_ratio=ROUND,
    zx_ratio=(0.8, 5.0),
    description="a {ceramic} {shape} vase",
    variants=(None, (0.12, 0.12, 0.25)),
)
def vase(size: Vec3, rng: Rng) -> Design:
    """A vase: a bulbous body with a narrow neck, or a straight cylinder."""
    d, _, h = size
    r = 0.5 * d
    ceramic = pick(rng, CERAMICS)
    if chance(rng, 0.6):
        neck = uniform(rng, 0.45, 0.6) * r
        profile: tuple[tuple[float, float], ...] = (
            (0.7 * r, 0.0),
            (r, 0.35 * h),
            (0.8 * r, 0.65 * h),
            (neck, 0.88 * h),
            (1.2 * neck, h),
        )
        shape = "bulbous"
    else:
        profile = ((0.85 * r, 0.0), (r, h))
        shape = "tall flared"
    return Design(
        (Lathe((0.0, 0.0, 0.0), profile, ceramic),), {"ceramic": ceramic.words, "shape": shape}
    )


@category(
    "laptop",
    "object",
    size=(0.25, 0.34, 0.23),
    low=(0.2, 0.28, 0.15),
    high=(0.32, 0.42, 0.3),
    mass=1.8,
    friction=0.6,
    placement=OBJECT,
    description="an open {finish} laptop",
    variants=(None, (0.22, 0.3, 0.2)),
)
def laptop(size: Vec3, rng: Rng) -> Design:
    """An open laptop; the screen faces +X, the lid stands upright at -X."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, (ALUMINIUM, SPACE_GREY, BLACK_PLASTIC))
    t = uniform(rng, 0.012, 0.02)
    lid = 0.007
    parts: list[Part] = [
        block((-hd + lid, hd), (-hw, hw), (0.0, t), finish),
        block(
            (-hd + lid + 0.02, hd - 0.08),
            (-hw + 0.02, hw - 0.02),
            (t, t + 0.0008),
            BLACK_PLASTIC,
            collide=False,
        ),
        block((-hd, -hd + lid), (-hw, hw), (0.0, h), finish),
        block(
            (-hd + lid, -hd + lid + 0.0008),
            (-hw + 0.01, hw - 0.01),
            (t + 0.01, h - 0.01),
            SCREEN,
            collide=False,
        ),
    ]
    return Design(tuple(parts), {"finish": finish.words})


@category(
    "desk_lamp",
    "object",
    size=(0.2, 0.16, 0.4),
    low=(0.15, 0.1, 0.28),
    high=(0.35, 0.3, 0.7),
    mass=1.2,
    friction=0.7,
    placement=OBJECT,
    yx_ratio=(0.6, 1.0),
    description="a {metal} desk lamp with a {shade} shade",
    variants=(None, (0.26, 0.2, 0.5)),
)
def desk_lamp(size: Vec3, rng: Rng) -> Design:
    """A desk lamp: round base, upright pole, an arm reaching +X and a downward shade."""
    d, w, h = size
    hd = 0.5 * d
    metal = pick(rng, (BLACK_METAL, BRASS, CHROME))
    shade_mat = pick(rng, (LAMP_SHADE, WHITE_SHADE, metal))
    base_r = 0.5 * w
    bx = -hd + base_r
    shade_r = clamp(min(0.5 * w, 0.5 * d - 0.01), 0.03, 0.09)
    shade_h = clamp(uniform(rng, 0.7, 1.2) * shade_r, 0.04, 0.3 * h)
    sx = hd - shade_r
    arm_z = h - 0.008
    shade_top = arm_z - 0.008
    parts: list[Part] = [
        *tagged("base", [Cylinder((bx, 0.0, 0.012), base_r, 0.012, metal)]),
        *tagged(
            "pole",
            [
                Cylinder((bx, 0.0, 0.5 * (0.024 + h)), 0.008, 0.5 * (h - 0.024), metal),
                Cylinder((0.5 * (bx + sx), 0.0, arm_z), 0.008, 0.5 * (sx - bx), metal, axis="x"),
            ],
        ),
        *tagged(
            "shade",
            [
                Lathe(
                    (sx, 0.0, shade_top - shade_h),
                    ((shade_r, 0.0), (0.4 * shade_r, shade_h)),
                    shade_mat,
                )
            ],
        ),
    ]
    return Design(tuple(parts), {"metal": metal.words, "shade": shade_mat.words})
