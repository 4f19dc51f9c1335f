"""Home decor: framed paintings and mirrors, floor lamps, potted plants and rugs."""

from __future__ import annotations

from asset_pipeline.procedural.appliances import (
    MIRROR,
)
from asset_pipeline.procedural.kit import (
    BARK,
    BLACK_METAL,
    BRASS,
    CANVAS,
    CANVAS_WARM,
    CERAMIC_BLACK,
    CHROME,
    CONCRETE,
    DARK_FOLIAGE,
    FOLIAGE,
    GILT,
    LAMP_SHADE,
    RUG_BEIGE,
    RUG_BLUE,
    RUG_BORDER,
    RUG_DARK_BORDER,
    RUG_GREY,
    RUG_RED,
    SOIL,
    TERRACOTTA,
    WHITE_LACQUER,
    WHITE_SHADE,
    WOODS,
    Rng,
    block,
    chance,
    clamp,
    pick,
    uniform,
)
from asset_pipeline.procedural.parts import Box, Part, RecipeMaterial, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.roles import tagged
from asset_pipeline.procedural.round_parts import Cylinder, Lathe, Sphere


# --- framed pictures, lamps, plants and rugs ------------------------------------------------------
def _framed(size: Vec3, rng: Rng, face: RecipeMaterial) -> tuple[list[Part], str]:
    d, w, h = size
    hw = 0.5 * w
    frame = pick(rng, (GILT, BLACK_METAL, *WOODS[:2], WHITE_LACQUER))
    f = clamp(uniform(rng, 0.02, 0.06), 0.01, 0.15 * min(w, h))
    x0, x1 = -0.5 * d, 0.5 * d
    parts: list[Part] = [
        block((x0, x1 - 0.01), (-hw + f, hw - f), (f, h - f), face),
        *tagged(
            "frame",
            [
                block((x0, x1), (-hw, hw), (0.0, f), frame),
                block((x0, x1), (-hw, hw), (h - f, h), frame),
                block((x0, x1), (-hw, -hw + f), (f, h - f), frame),
                block((x0, x1), (hw - f, hw), (f, h - f), frame),
            ],
        ),
    ]
    return parts, frame.words


@category(
    "painting",
    "furniture",
    size=(0.03, 0.8, 0.6),
    low=(0.015, 0.2, 0.2),
    high=(0.08, 1.6, 1.2),
    mass=3.0,
    placement=("wall",),
    description="a framed {subject} painting with a {frame} frame",
    variants=(None, (0.03, 0.5, 0.7)),
)
def painting(size: Vec3, rng: Rng) -> Design:
    """A framed canvas for a wall; the canvas faces +X."""
    canvas = pick(rng, (CANVAS, CANVAS_WARM))
    parts, frame = _framed(size, rng, canvas)
    subject = "seascape" if canvas is CANVAS else "abstract"
    return Design(tuple(parts), {"subject": subject, "frame": frame})


@category(
    "mirror",
    "furniture",
    size=(0.03, 0.6, 0.9),
    low=(0.015, 0.3, 0.3),
    high=(0.08, 1.6, 2.0),
    mass=6.0,
    placement=("wall",),
    description="a wall mirror with a {frame} frame",
    variants=(None, (0.03, 1.0, 0.7)),
)
def mirror(size: Vec3, rng: Rng) -> Design:
    """A framed wall mirror; the glass faces +X."""
    parts, frame = _framed(size, rng, MIRROR)
    return Design(tuple(parts), {"frame": frame})


@category(
    "floor_lamp",
    "furniture",
    size=(0.4, 0.4, 1.65),
    low=(0.25, 0.25, 1.2),
    high=(0.6, 0.6, 1.9),
    mass=6.0,
    friction=0.7,
    yx_ratio=(1.0, 1.0),
    description="a {metal} floor lamp with a {shade} {shape} shade",
    variants=(None, (0.5, 0.5, 1.5)),
)
def floor_lamp(size: Vec3, rng: Rng) -> Design:
    """A floor lamp: heavy round base, thin pole, a fabric shade as wide as the lamp."""
    d, _, h = size
    r = 0.5 * d
    metal = pick(rng, (BLACK_METAL, BRASS, CHROME))
    shade_mat = pick(rng, (LAMP_SHADE, WHITE_SHADE))
    cone = chance(rng, 0.6)
    shade_h = clamp(uniform(rng, 0.22, 0.35), 0.15, 0.25 * h)
    base_r = clamp(uniform(rng, 0.55, 0.8) * r, 0.11, r)
    top_r = r * (uniform(rng, 0.55, 0.75) if cone else 1.0)
    parts: list[Part] = [
        *tagged("base", [Cylinder((0.0, 0.0, 0.015), base_r, 0.015, metal)]),
        *tagged(
            "pole",
            [
                Cylinder(
                    (0.0, 0.0, 0.5 * (h - shade_h + 0.03)), 0.012, 0.5 * (h - shade_h - 0.03), metal
                )
            ],
        ),
        *tagged("shade", [Lathe((0.0, 0.0, h - shade_h), ((r, 0.0), (top_r, shade_h)), shade_mat)]),
    ]
    return Design(
        tuple(parts),
        {"metal": metal.words, "shade": shade_mat.words, "shape": "conical" if cone else "drum"},
    )


@category(
    "potted_plant",
    "furniture",
    size=(0.6, 0.6, 1.25),
    low=(0.3, 0.3, 0.5),
    high=(1.0, 1.0, 2.2),
    mass=12.0,
    friction=0.8,
    yx_ratio=(1.0, 1.0),
    description="a leafy {kind} in a {pot} pot",
    variants=(None, (0.45, 0.45, 0.9)),
)
def potted_plant(size: Vec3, rng: Rng) -> Design:
    """A floor plant: a pot, a trunk and a crown of leaf spheres exactly as wide as the size."""
    d, _, h = size
    r = 0.5 * d
    pot_mat = pick(rng, (TERRACOTTA, CONCRETE, CERAMIC_BLACK, WHITE_LACQUER))
    leaves = pick(rng, (FOLIAGE, DARK_FOLIAGE))
    pot_top_r = clamp(uniform(rng, 0.45, 0.6) * r, 0.1, 0.3)
    pot_h = clamp(uniform(rng, 0.25, 0.35) * h, 0.18, 0.5)
    crown = clamp(uniform(rng, 0.7, 0.9) * r, 0.1, 0.5 * (h - pot_h))
    parts: list[Part] = [
        Lathe(
            (0.0, 0.0, 0.0),
            ((0.8 * pot_top_r, 0.0), (pot_top_r, pot_h)),
            pot_mat,
            hollow=(0.015, 0.04),
        ),
        Cylinder((0.0, 0.0, pot_h - 0.035), pot_top_r - 0.02, 0.015, SOIL, collide=False),
        Cylinder(
            (0.0, 0.0, 0.5 * (pot_h - 0.05 + h - crown)),
            0.02,
            0.5 * (h - crown - pot_h + 0.05),
            BARK,
        ),
        Sphere((0.0, 0.0, h - crown), crown, leaves),
    ]
    side_r = clamp(0.45 * crown, 0.05, r)
    offset = r - side_r
    side_z = max(h - crown - 0.5 * crown, pot_h + side_r + 0.02)
    for x, y in ((offset, 0.0), (-offset, 0.0), (0.0, offset), (0.0, -offset)):
        parts.append(Sphere((x, y, side_z), side_r, leaves))
    kind = "tree" if h > 1.2 else "shrub"
    return Design(tuple(parts), {"kind": kind, "pot": pot_mat.words})


@category(
    "rug",
    "furniture",
    size=(1.6, 2.3, 0.012),
    low=(0.5, 0.5, 0.008),
    high=(3.5, 4.0, 0.025),
    mass=5.0,
    friction=1.0,
    description="a {field} rug with a {border} border",
    variants=(None, (1.2, 1.8, 0.01)),
)
def rug(size: Vec3, rng: Rng) -> Design:
    """A flat rug: one thin box collider, a patterned field and a border drawn on top."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    field = pick(rng, (RUG_RED, RUG_BLUE, RUG_BEIGE, RUG_GREY))
    border = RUG_DARK_BORDER if field in (RUG_BEIGE,) else pick(rng, (RUG_BORDER, RUG_DARK_BORDER))
    b = clamp(uniform(rng, 0.04, 0.1) * min(d, w), 0.03, 0.2)
    parts: list[Part] = [
        Box((0.0, 0.0, 0.5 * h), (hd, hw, 0.5 * h), field, visual=False),
        block((-hd + b, hd - b), (-hw + b, hw - b), (0.0, h), field, collide=False),
        block((-hd, hd), (-hw, -hw + b), (0.0, h), border, collide=False),
        block((-hd, hd), (hw - b, hw), (0.0, h), border, collide=False),
        block((-hd, -hd + b), (-hw + b, hw - b), (0.0, h), border, collide=False),
        block((hd - b, hd), (-hw + b, hw - b), (0.0, h), border, collide=False),
    ]
    return Design(tuple(parts), {"field": field.words, "border": border.words})
