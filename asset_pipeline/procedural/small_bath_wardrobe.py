"""Generators of small bathroom and wardrobe items.

Small items stand on furniture (placement ``object``, issue 15). Sizes follow the knowledge
base (``objects.json``, whose (width, depth, height) is (y, x, z) here); fronts face +X.
"""

from __future__ import annotations

from asset_pipeline.procedural.kit import (
    BLACK_LEATHER,
    BLACK_PLASTIC,
    CERAMICS,
    CHROME,
    CLEAR_GLASS,
    FABRICS,
    LEATHER,
    LINEN,
    PORCELAIN,
    SPACE_GREY,
    WHITE_PLASTIC,
    WOODS,
    Rng,
    block,
    clamp,
    pick,
)
from asset_pipeline.procedural.parts import Part, RecipeMaterial, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.round_parts import Lathe
from asset_pipeline.procedural.small_kit import (
    GOLD,
    NYLON_RED,
    OBJECT,
    RED_ENAMEL,
    RED_PLASTIC,
    ROUND,
    RUBBER,
    cyl_y,
    cyl_z,
    deco,
    handle_arch,
)

SOAP = RecipeMaterial("soap", (0.75, 0.86, 0.70, 0.8), 0.8, 0.8)
NYLON_NAVY = RecipeMaterial("nylon_navy", (0.13, 0.17, 0.30, 1.0), 0.2, 0.2, "navy")
NYLON_GREEN = RecipeMaterial("nylon_green", (0.24, 0.38, 0.26, 1.0), 0.2, 0.2, "olive green")
NYLON_GREY = RecipeMaterial("nylon_grey", (0.38, 0.39, 0.41, 1.0), 0.2, 0.2, "grey")
SUEDE = RecipeMaterial("suede", (0.62, 0.46, 0.30, 1.0), 0.05, 0.1, "tan suede")
CANVAS_WHITE = RecipeMaterial("canvas_white", (0.93, 0.93, 0.91, 1.0), 0.1, 0.1, "white canvas")
AMBER_BOTTLE = RecipeMaterial("amber_bottle", (0.55, 0.30, 0.08, 1.0), 0.8, 0.8, "amber glass")
NYLONS = (NYLON_NAVY, NYLON_RED, NYLON_GREEN, NYLON_GREY)


# --- bathroom and wardrobe ------------------------------------------------------------------
@category(
    "soap_dispenser",
    "object",
    size=(0.08, 0.08, 0.18),
    low=(0.05, 0.05, 0.1),
    high=(0.12, 0.12, 0.26),
    mass=0.45,
    placement=OBJECT,
    yx_ratio=ROUND,
    zx_ratio=(1.3, 4.5),
    description="a {body} pump soap dispenser",
    variants=(None, (0.07, 0.07, 0.15)),
)
def soap_dispenser(size: Vec3, rng: Rng) -> Design:
    """A pump bottle: body, collar, pump stem and a head with a spout towards +X."""
    d, _, h = size
    r = 0.5 * d
    body = pick(rng, (CLEAR_GLASS, PORCELAIN, CERAMICS[1], AMBER_BOTTLE))
    pump = pick(rng, (CHROME, BLACK_PLASTIC, WHITE_PLASTIC))
    body_h = 0.72 * h
    parts: list[Part] = [
        Lathe((0.0, 0.0, 0.0), ((r, 0.0), (r, 0.85 * body_h), (0.5 * r, body_h)), body),
        cyl_z(0.0, 0.0, body_h, body_h + 0.015, 0.4 * r, pump),
        cyl_z(0.0, 0.0, body_h + 0.015, h - 0.015, 0.005, pump),
        block((-0.012, 0.9 * r), (-0.008, 0.008), (h - 0.015, h), pump),
    ]
    if body is CLEAR_GLASS:
        parts.append(cyl_z(0.0, 0.0, 0.004, 0.6 * body_h, 0.9 * r, SOAP, collide=False))
    return Design(tuple(parts), {"body": body.words})


@category(
    "towel",
    "object",
    size=(0.2, 0.3, 0.08),
    low=(0.12, 0.15, 0.02),
    high=(0.4, 0.6, 0.2),
    mass=0.5,
    friction=0.9,
    placement=OBJECT,
    description="a folded {colour} towel",
    variants=(None, (0.15, 0.25, 0.05)),
)
def towel(size: Vec3, rng: Rng) -> Design:
    """A folded towel: stacked folds, alternately set back, with a stripe across the top."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    colour = pick(rng, (*FABRICS, LINEN))
    n = int(clamp(round(h / 0.02), 2, 6))
    layer = (h - 0.0008) / n
    parts: list[Part] = []
    for i in range(n):
        back = 0.004 if i % 2 else 0.0
        parts.append(block((-hd, hd), (-hw + back, hw - 0.004 + back), (i * layer, (i + 1) * layer),
                           colour))  # fmt: skip
    top = n * layer
    stripe = LINEN if colour is not LINEN else FABRICS[1]
    for y in (-0.3 * w, 0.3 * w):
        parts.append(deco((-hd, hd), (y - 0.01, y + 0.01), (top, h), stripe))
    return Design(tuple(parts), {"colour": colour.words})


@category(
    "hair_dryer",
    "object",
    size=(0.1, 0.25, 0.25),
    low=(0.07, 0.16, 0.16),
    high=(0.14, 0.35, 0.35),
    mass=0.6,
    placement=OBJECT,
    description="a {finish} hair dryer standing on its handle",
    variants=(None, (0.09, 0.22, 0.22)),
)
def hair_dryer(size: Vec3, rng: Rng) -> Design:
    """A hair dryer: the barrel along Y (nozzle +Y) over an upright handle with a wide foot."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, (BLACK_PLASTIC, WHITE_PLASTIC, RED_PLASTIC, SPACE_GREY))
    rb = min(0.5 * d, 0.2 * h)
    bz = h - rb
    nozzle = 0.2 * w
    parts: list[Part] = [
        block((-hd, hd), (-0.17 * w, 0.08 * w), (0.0, 0.04 * h), finish),
        block((-0.35 * d, 0.35 * d), (-0.12 * w, 0.04 * w), (0.04 * h, bz), finish),
        cyl_y(-hw, hw - nozzle, 0.0, bz, rb, finish),
        cyl_y(hw - nozzle, hw, 0.0, bz, 0.65 * rb, BLACK_PLASTIC),
        cyl_y(-hw, -hw + 0.002, 0.0, bz, 0.8 * rb, SPACE_GREY, collide=False),
    ]
    return Design(tuple(parts), {"finish": finish.words})


@category(
    "shoe",
    "object",
    size=(0.11, 0.3, 0.12),
    low=(0.07, 0.18, 0.06),
    high=(0.16, 0.38, 0.3),
    mass=0.45,
    placement=("floor", "object"),
    description="a {material} {kind}",
    variants=(None, (0.1, 0.27, 0.1)),
)
def shoe(size: Vec3, rng: Rng) -> Design:
    """A shoe along Y (toe +Y): sole, heel counter and toe box, the opening on top."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    material = pick(rng, (LEATHER, BLACK_LEATHER, SUEDE, CANVAS_WHITE))
    sole = pick(rng, (RUBBER, WHITE_PLASTIC, WOODS[1]))
    sh = clamp(0.12 * h, 0.01, 0.025)
    kind = "boot" if h > 0.18 else ("sneaker" if material is CANVAS_WHITE else "shoe")
    toe_h = min(0.55 * h, sh + 0.06)
    parts: list[Part] = [
        block((-hd, hd), (-hw, hw), (0.0, sh), sole),
        block((-0.44 * d, 0.44 * d), (-hw + 0.01, 0.1 * w), (sh, h - 0.001), material),
        block((-0.42 * d, 0.42 * d), (0.1 * w, hw - 0.02 * w), (sh, toe_h), material),
        deco((-0.3 * d, 0.3 * d), (-hw + 0.04 * w, 0.05 * w), (h - 0.001, h), BLACK_LEATHER),
    ]
    return Design(tuple(parts), {"material": material.words, "kind": kind})


@category(
    "handbag",
    "object",
    size=(0.14, 0.32, 0.25),
    low=(0.08, 0.2, 0.15),
    high=(0.22, 0.45, 0.4),
    mass=0.8,
    placement=OBJECT,
    description="a {material} handbag",
    variants=(None, (0.12, 0.28, 0.22)),
)
def handbag(size: Vec3, rng: Rng) -> Design:
    """A handbag: a tapered body, a flap with a clasp on +X, two handles on top."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    material = pick(rng, (LEATHER, BLACK_LEATHER, SUEDE, RED_ENAMEL))
    body_h = 0.62 * h
    face = hd - 0.004
    parts: list[Part] = [
        block((-hd, face), (-hw, hw), (0.0, 0.7 * body_h), material),
        block((-0.85 * hd, 0.85 * face), (-0.9 * hw, 0.9 * hw), (0.7 * body_h, body_h), material),
        block((face, hd), (-0.6 * hw, 0.6 * hw), (0.35 * body_h, 0.7 * body_h), material),
        block((face, hd), (-0.05 * w, 0.05 * w), (0.3 * body_h, 0.4 * body_h), GOLD),
        *handle_arch((-0.3 * w, -0.1 * w), (body_h, h), 0.01, material),
        *handle_arch((0.1 * w, 0.3 * w), (body_h, h), 0.01, material),
    ]
    return Design(tuple(parts), {"material": material.words})


@category(
    "backpack",
    "object",
    size=(0.18, 0.3, 0.42),
    low=(0.1, 0.2, 0.25),
    high=(0.3, 0.4, 0.55),
    mass=1.2,
    placement=("floor", "object"),
    description="a {colour} backpack",
    variants=(None, (0.16, 0.28, 0.38)),
)
def backpack(size: Vec3, rng: Rng) -> Design:
    """A backpack standing up: main compartment, front pocket (+X), straps at -X, top loop."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    colour = pick(rng, NYLONS)
    trim = BLACK_PLASTIC
    strap = 0.012
    pocket = 0.3 * d
    body_h = 0.93 * h
    parts: list[Part] = [
        block((-hd + strap, hd - pocket), (-hw, hw), (0.0, body_h), colour),
        block((hd - pocket, hd), (-0.38 * w, 0.38 * w), (0.06 * h, 0.5 * h), colour),
        deco((hd - pocket, hd), (-0.3 * w, 0.3 * w), (0.5 * h - 0.004, 0.5 * h), trim),
        *handle_arch((-0.12 * w, 0.12 * w), (body_h, h), 0.008, trim),
    ]
    for y in (-0.25 * w, 0.2 * w):
        parts.append(deco((-hd, -hd + strap), (y, y + 0.05 * w), (0.12 * h, 0.9 * h), trim))
    return Design(tuple(parts), {"colour": colour.words})
