"""Generators of small lab, workshop and garden items.

Small items stand on furniture (placement ``object``, issue 15). Sizes follow the knowledge
base (``objects.json``, whose (width, depth, height) is (y, x, z) here); fronts face +X.
"""

from __future__ import annotations

from asset_pipeline.procedural.kit import (
    BLACK_METAL,
    BLACK_PLASTIC,
    CHROME,
    CLEAR_GLASS,
    STEEL,
    TOYS,
    WHITE_PLASTIC,
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
    BLUE_METAL,
    BLUE_PLASTIC,
    CREAM_ENAMEL,
    GREEN_METAL,
    MINT_ENAMEL,
    NYLON_RED,
    OBJECT,
    RED_ENAMEL,
    ROUND,
    cyl_y,
    cyl_z,
    deco,
    handle_arch,
)

RED_METAL = RecipeMaterial("red_metal", (0.72, 0.12, 0.10, 1.0), 0.5, 0.5, "red metal")
GALVANISED = RecipeMaterial("galvanised", (0.66, 0.68, 0.68, 1.0), 0.5, 0.5, "galvanised steel")
COPPER = RecipeMaterial("copper", (0.72, 0.42, 0.26, 1.0), 0.8, 0.8)
BLUE_LIQUID = RecipeMaterial("blue_liquid", (0.25, 0.45, 0.85, 0.8), 0.8, 0.8)
GREEN_LIQUID = RecipeMaterial("green_liquid", (0.30, 0.75, 0.35, 0.8), 0.8, 0.8)
DRILL_YELLOW = RecipeMaterial("drill_yellow", (0.95, 0.72, 0.10, 1.0), 0.3, 0.3, "yellow")
PAINT_COLOURS = (
    RecipeMaterial("paint_white", (0.95, 0.95, 0.93, 1.0), 0.3, 0.3, "white"),
    RecipeMaterial("paint_blue", (0.20, 0.38, 0.70, 1.0), 0.3, 0.3, "blue"),
    RecipeMaterial("paint_yellow", (0.95, 0.78, 0.20, 1.0), 0.3, 0.3, "yellow"),
    RecipeMaterial("paint_green", (0.30, 0.60, 0.36, 1.0), 0.3, 0.3, "green"),
)


# --- lab, workshop and garden ----------------------------------------------------------------
@category(
    "beaker",
    "object",
    size=(0.08, 0.08, 0.12),
    low=(0.04, 0.04, 0.05),
    high=(0.15, 0.15, 0.25),
    mass=0.15,
    placement=OBJECT,
    yx_ratio=ROUND,
    description="a glass laboratory beaker of {liquid} liquid",
    variants=(None, (0.06, 0.06, 0.09)),
)
def beaker(size: Vec3, rng: Rng) -> Design:
    """A straight glass beaker, part filled."""
    d, _, h = size
    r = 0.5 * d
    liquid = pick(rng, (BLUE_LIQUID, GREEN_LIQUID, CLEAR_GLASS))
    parts: list[Part] = [
        Lathe((0.0, 0.0, 0.0), ((r, 0.0), (r, h)), CLEAR_GLASS, hollow=(0.002, 0.004)),
        cyl_z(0.0, 0.0, 0.004, uniform(rng, 0.3, 0.7) * h, r - 0.0025, liquid, collide=False),
    ]
    words = {BLUE_LIQUID: "blue", GREEN_LIQUID: "green"}.get(liquid, "clear")
    return Design(tuple(parts), {"liquid": words})


@category(
    "test_tube_rack",
    "object",
    size=(0.08, 0.2, 0.12),
    low=(0.05, 0.12, 0.08),
    high=(0.14, 0.35, 0.2),
    mass=0.4,
    placement=OBJECT,
    description="a {frame} rack of test tubes",
    variants=(None, (0.07, 0.16, 0.14)),
)
def test_tube_rack(size: Vec3, rng: Rng) -> Design:
    """A rack: base plate, end posts, a top plate and a row of stoppered tubes."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    frame = pick(rng, (WHITE_PLASTIC, *WOODS[:2], BLUE_PLASTIC))
    t = 0.01
    top = 0.55 * h
    parts: list[Part] = [
        block((-hd, hd), (-hw, hw), (0.0, t), frame),
        block((-hd, hd), (-hw, -hw + t), (t, top), frame),
        block((-hd, hd), (hw - t, hw), (t, top), frame),
        block((-hd, hd), (-hw + t, hw - t), (top - t, top), frame),
    ]
    tr = clamp(0.12 * d, 0.006, 0.012)
    n = int(clamp((w - 2 * t) // (2 * tr + 0.008), 2, 5))
    for i in range(n):
        y = -hw + t + (i + 0.5) * (w - 2 * t) / n
        z1 = h if i == 0 else h - uniform(rng, 0.0, 0.2) * (h - top)
        parts.append(cyl_z(0.0, y, t, z1 - 0.01, tr, CLEAR_GLASS, collide=False))
        parts.append(deco((-0.7 * tr, 0.7 * tr), (y - 0.7 * tr, y + 0.7 * tr), (z1 - 0.01, z1),
                          pick(rng, TOYS)))  # fmt: skip
    return Design(tuple(parts), {"frame": frame.words})


@category(
    "toolbox",
    "object",
    size=(0.22, 0.5, 0.25),
    low=(0.14, 0.3, 0.12),
    high=(0.35, 0.7, 0.4),
    mass=4.5,
    placement=("floor", "object"),
    description="a {finish} toolbox",
    variants=(None, (0.2, 0.4, 0.2)),
)
def toolbox(size: Vec3, rng: Rng) -> Design:
    """A toolbox: body, a lid with latches and a carrying handle on top."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, (RED_METAL, BLUE_METAL, GREEN_METAL, BLACK_PLASTIC))
    face = hd - 0.004
    parts: list[Part] = [
        block((-hd, face), (-hw, hw), (0.0, 0.6 * h), finish),
        block((-hd, face), (-hw, hw), (0.6 * h, 0.72 * h), finish),
        *handle_arch((-0.3 * w, 0.3 * w), (0.72 * h, h), clamp(0.05 * h, 0.01, 0.018),
                     BLACK_PLASTIC),
    ]  # fmt: skip
    for y in (-0.3 * w, 0.3 * w):
        parts.append(block((face, hd), (y - 0.02, y + 0.02), (0.52 * h, 0.68 * h), CHROME))
    return Design(tuple(parts), {"finish": finish.words})


@category(
    "power_drill",
    "object",
    size=(0.08, 0.25, 0.25),
    low=(0.05, 0.16, 0.16),
    high=(0.12, 0.35, 0.35),
    mass=1.6,
    placement=OBJECT,
    description="a {finish} cordless power drill standing on its battery",
    variants=(None, (0.07, 0.22, 0.22)),
)
def power_drill(size: Vec3, rng: Rng) -> Design:
    """A cordless drill: battery pack foot, grip, motor barrel along Y and the chuck at +Y."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, (NYLON_RED, DRILL_YELLOW, GREEN_METAL, BLUE_PLASTIC))
    bat_h = 0.2 * h
    rb = min(0.5 * d, 0.16 * h)
    bz = h - rb
    chuck = 0.22 * w
    parts: list[Part] = [
        block((-hd, hd), (-hw, 0.1 * w), (0.0, bat_h), BLACK_PLASTIC),
        block((-0.35 * d, 0.35 * d), (-0.3 * w, -0.05 * w), (bat_h, bz), finish),
        cyl_y(-hw, hw - chuck, 0.0, bz, rb, finish),
        cyl_y(hw - chuck, hw - 0.08 * w, 0.0, bz, 0.6 * rb, BLACK_METAL),
        cyl_y(hw - 0.08 * w, hw, 0.0, bz, 0.12 * rb, STEEL),
    ]
    return Design(tuple(parts), {"finish": finish.words})


@category(
    "paint_can",
    "object",
    size=(0.17, 0.17, 0.19),
    low=(0.08, 0.08, 0.08),
    high=(0.3, 0.3, 0.35),
    mass=4.0,
    placement=("floor", "object"),
    yx_ratio=ROUND,
    description="a can of {colour} paint",
    variants=(None, (0.12, 0.12, 0.13)),
)
def paint_can(size: Vec3, rng: Rng) -> Design:
    """A paint tin: a metal can with a coloured label band and a lid rim."""
    d, _, h = size
    r = 0.5 * d
    colour = pick(rng, PAINT_COLOURS)
    parts: list[Part] = [
        cyl_z(0.0, 0.0, 0.0, 0.15 * h, 0.98 * r, GALVANISED),
        cyl_z(0.0, 0.0, 0.15 * h, 0.85 * h, r, colour),
        cyl_z(0.0, 0.0, 0.85 * h, h - 0.004, 0.98 * r, GALVANISED),
        cyl_z(0.0, 0.0, h - 0.004, h, 0.85 * r, GALVANISED),
    ]
    return Design(tuple(parts), {"colour": colour.words})


@category(
    "sewing_machine",
    "object",
    size=(0.2, 0.42, 0.3),
    low=(0.14, 0.3, 0.2),
    high=(0.3, 0.55, 0.4),
    mass=7.5,
    placement=OBJECT,
    description="a {finish} sewing machine",
    variants=(None, (0.18, 0.38, 0.28)),
)
def sewing_machine(size: Vec3, rng: Rng) -> Design:
    """A sewing machine: bed, pillar at +Y, arm over the bed, needle head at -Y, handwheel."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, (WHITE_PLASTIC, CREAM_ENAMEL, BLACK_METAL, MINT_ENAMEL))
    bed = 0.25 * h
    x = (-0.4 * d, 0.3 * d)
    wheel_r = min(0.4 * d, 0.15 * h)
    parts: list[Part] = [
        block((-hd, hd), (-hw, hw), (0.0, bed), finish),
        block(x, (hw - 0.3 * w, hw - 0.06 * w), (bed, h), finish),
        block(x, (-hw + 0.04 * w, hw - 0.3 * w), (0.72 * h, h), finish),
        block(x, (-hw + 0.04 * w, -hw + 0.18 * w), (0.5 * h, 0.72 * h), finish),
        cyl_z(0.0, -hw + 0.11 * w, bed + 0.01, 0.5 * h, 0.003, CHROME, collide=False),
        cyl_y(hw - 0.06 * w, hw, -0.05 * d, 0.75 * h, wheel_r, CHROME),
        deco((-0.2 * d, 0.2 * d), (-0.2 * w, 0.1 * w), (bed, bed + 0.002), CHROME),
    ]
    return Design(tuple(parts), {"finish": finish.words})


@category(
    "watering_can",
    "object",
    size=(0.15, 0.45, 0.3),
    low=(0.1, 0.28, 0.16),
    high=(0.25, 0.6, 0.45),
    mass=0.9,
    placement=("floor", "object"),
    yx_ratio=(2.0, 4.0),
    zx_ratio=(1.2, 3.0),
    description="a {finish} watering can",
    variants=(None, (0.13, 0.36, 0.24)),
)
def watering_can(size: Vec3, rng: Rng) -> Design:
    """A watering can: a round body at +Y, a spout rising to -Y with a rose, a top handle."""
    d, w, h = size
    hw = 0.5 * w
    finish = pick(rng, (GALVANISED, GREEN_METAL, COPPER, RED_ENAMEL))
    r = 0.5 * d
    by = hw - r
    body_h = 0.6 * h
    t = 0.012
    parts: list[Part] = [
        cyl_z(0.0, by, 0.0, body_h, r, finish),
        *handle_arch((by - 0.6 * r, by + 0.6 * r), (body_h, h), t, finish),
    ]
    # Spout: four rising steps from the body's foot towards -Y, then the rose.
    y_start, y_end = by - 0.9 * r, -hw + 0.02
    steps = 4
    for i in range(steps):
        y1 = y_start - i * (y_start - y_end) / steps
        y0 = y_start - (i + 1) * (y_start - y_end) / steps
        z0 = 0.15 * h + i * (0.6 * h / steps)
        parts.append(block((-0.008, 0.008), (y0, y1), (z0, z0 + 0.6 * h / steps + 0.01), finish))
    z_rose = 0.15 * h + 0.6 * h + 0.01
    rose_r = min(0.3 * d, 0.025)
    parts.append(cyl_y(-hw, -hw + 0.02, 0.0, z_rose - rose_r, rose_r, finish))
    return Design(tuple(parts), {"finish": finish.words})
