"""Generators of small kitchen appliances.

Small items stand on furniture (placement ``object``, issue 15). Sizes follow the knowledge
base (``objects.json``, whose (width, depth, height) is (y, x, z) here); fronts face +X.
"""

from __future__ import annotations

from asset_pipeline.procedural.kit import (
    BLACK_METAL,
    BLACK_PLASTIC,
    CERAMICS,
    CHROME,
    CLEAR_GLASS,
    PORCELAIN,
    SCREEN,
    SPACE_GREY,
    STEEL,
    WHITE_PLASTIC,
    Rng,
    block,
    clamp,
    pick,
)
from asset_pipeline.procedural.parts import Part, RecipeMaterial, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.round_parts import Lathe
from asset_pipeline.procedural.small_kit import (
    CAST_IRON,
    CREAM_ENAMEL,
    LED,
    MINT_ENAMEL,
    OBJECT,
    RED_ENAMEL,
    ROUND,
    cyl_y,
    cyl_z,
    deco,
)


def loop_handle(
    x: tuple[float, float],
    r: float,
    reach: float,
    z: tuple[float, float],
    t: float,
    m: RecipeMaterial,
) -> list[Part]:
    """A mug-like handle on +Y of a round body of radius ``r``, reaching ``reach`` beyond it."""
    y0, y1 = 0.75 * r, r + reach
    z0, z1 = z
    return [
        block(x, (y0, y1), (z1 - t, z1), m),
        block(x, (y0, y1), (z0, z0 + t), m),
        block(x, (y1 - t, y1), (z0 + t, z1 - t), m),
    ]


# --- kitchen appliances --------------------------------------------------------------------
@category(
    "microwave",
    "object",
    size=(0.38, 0.5, 0.3),
    low=(0.28, 0.38, 0.2),
    high=(0.5, 0.7, 0.42),
    mass=12.0,
    placement=OBJECT,
    description="a {finish} countertop microwave oven",
    variants=(None, (0.34, 0.45, 0.26)),
)
def microwave(size: Vec3, rng: Rng) -> Design:
    """A microwave: cabinet, door with a dark window and handle, control panel (front +X)."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, (WHITE_PLASTIC, BLACK_PLASTIC, STEEL))
    face = hd - 0.03
    split = hw - 0.27 * w
    parts: list[Part] = [
        block((-hd, face), (-hw, hw), (0.0, h), finish),
        block((face, hd - 0.015), (-hw + 0.005, split), (0.03 * h, 0.97 * h), finish),
        deco((hd - 0.015, hd - 0.014), (-hw + 0.04, split - 0.05), (0.15 * h, 0.85 * h), SCREEN),
        block((hd - 0.015, hd), (split - 0.035, split - 0.015), (0.2 * h, 0.8 * h), finish),
        block((face, hd - 0.016), (split + 0.005, hw - 0.005), (0.03 * h, 0.97 * h), SPACE_GREY),
        deco((hd - 0.016, hd - 0.015), (split + 0.02, hw - 0.02), (0.75 * h, 0.88 * h), LED),
    ]
    for i in range(3):
        z = 0.2 * h + i * 0.15 * h
        parts.append(
            deco((hd - 0.016, hd - 0.015), (split + 0.02, hw - 0.02), (z, z + 0.08 * h), SCREEN)
        )
    return Design(tuple(parts), {"finish": finish.words})


@category(
    "toaster",
    "object",
    size=(0.18, 0.3, 0.2),
    low=(0.12, 0.2, 0.14),
    high=(0.3, 0.45, 0.3),
    mass=1.8,
    placement=OBJECT,
    description="a {finish} two-slot toaster",
    variants=(None, (0.16, 0.27, 0.19)),
)
def toaster(size: Vec3, rng: Rng) -> Design:
    """A toaster: body with two slots on top, a lever on +Y and a browning knob on -Y."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, (CHROME, WHITE_PLASTIC, CREAM_ENAMEL, RED_ENAMEL, BLACK_PLASTIC))
    side = 0.012
    y = (-hw + side, hw - side)
    top = 0.9 * h
    slot = clamp(0.15 * d, 0.015, 0.035)
    wall = (d - 2 * slot) / 3
    parts: list[Part] = [block((-hd, hd), y, (0.0, top), finish)]
    for i in range(3):
        x0 = -hd + i * (wall + slot)
        parts.append(block((x0, x0 + wall), y, (top, h), finish))
    parts.append(block((-hd + wall, hd - wall), (y[0], y[0] + 0.02), (top, h), finish))
    parts.append(block((-hd + wall, hd - wall), (y[1] - 0.02, y[1]), (top, h), finish))
    for i in range(2):
        x0 = -hd + wall + i * (wall + slot)
        parts.append(deco((x0, x0 + slot), (y[0] + 0.02, y[1] - 0.02), (top, top + 0.002),
                          BLACK_METAL))  # fmt: skip
    parts.append(block((-0.015, 0.015), (hw - side, hw), (0.45 * h, 0.52 * h), BLACK_PLASTIC))
    parts.append(cyl_y(-hw, -hw + side, 0.0, 0.3 * h, 0.012, BLACK_PLASTIC))
    return Design(tuple(parts), {"finish": finish.words})


@category(
    "kettle",
    "object",
    size=(0.16, 0.22, 0.25),
    low=(0.12, 0.15, 0.16),
    high=(0.24, 0.34, 0.35),
    mass=1.0,
    placement=OBJECT,
    yx_ratio=(1.2, 1.6),
    description="a {finish} electric kettle on its base",
    variants=(None, (0.15, 0.21, 0.22)),
)
def kettle(size: Vec3, rng: Rng) -> Design:
    """An electric kettle (diameter x) on a power base, with its handle on +Y."""
    d, w, h = size
    r = 0.5 * d
    finish = pick(rng, (STEEL, WHITE_PLASTIC, CREAM_ENAMEL, BLACK_PLASTIC, MINT_ENAMEL))
    base_h = 0.06 * h
    knob = 0.015
    lid_h = 0.015
    body_h = h - base_h - lid_h - knob
    parts: list[Part] = [
        cyl_z(0.0, 0.0, 0.0, base_h, r, BLACK_PLASTIC),
        Lathe((0.0, 0.0, base_h), ((0.92 * r, 0.0), (r, 0.35 * body_h), (0.75 * r, body_h)),
              finish),
        cyl_z(0.0, 0.0, h - knob - lid_h, h - knob, 0.7 * r, BLACK_PLASTIC),
        cyl_z(0.0, 0.0, h - knob, h, 0.015, BLACK_PLASTIC),
        *loop_handle((-0.008, 0.008), r, w - d, (base_h + 0.2 * body_h, base_h + 0.85 * body_h),
                     clamp(0.25 * (w - d), 0.008, 0.015), BLACK_PLASTIC),
    ]  # fmt: skip
    return Design(tuple(parts), {"finish": finish.words})


@category(
    "teapot",
    "object",
    size=(0.15, 0.25, 0.15),
    low=(0.1, 0.16, 0.09),
    high=(0.24, 0.4, 0.25),
    mass=0.9,
    placement=OBJECT,
    yx_ratio=(1.4, 2.0),
    description="a {ceramic} teapot",
    variants=(None, (0.13, 0.21, 0.14)),
)
def teapot(size: Vec3, rng: Rng) -> Design:
    """A teapot (body diameter x): spout towards -Y, handle on +Y, lid with a knob."""
    d, w, h = size
    r = 0.5 * d
    ceramic = pick(rng, (PORCELAIN, *CERAMICS, CAST_IRON))
    reach = w - d
    handle = 0.45 * reach
    spout = reach - handle
    knob = 0.015
    body_h = h - knob - 0.01
    t = clamp(0.2 * handle, 0.007, 0.012)
    parts: list[Part] = [
        Lathe((0.0, 0.0, 0.0), ((0.7 * r, 0.0), (r, 0.45 * body_h), (0.7 * r, body_h)), ceramic),
        cyl_z(0.0, 0.0, body_h, body_h + 0.01, 0.5 * r, ceramic),
        cyl_z(0.0, 0.0, body_h + 0.01, h, 0.012, ceramic),
        *loop_handle((-0.007, 0.007), r, handle, (0.25 * body_h, 0.85 * body_h), t, ceramic),
    ]
    # The spout climbs in three steps from the belly to the rim height.
    sr = clamp(0.12 * r, 0.007, 0.013)
    y_in = -0.7 * r
    for i in range(3):
        y1 = -r - i * spout / 3
        y0 = -r - (i + 1) * spout / 3
        z0 = 0.25 * body_h + i * 0.2 * body_h
        parts.append(block((-sr, sr), (y0, y1 if i else y_in), (z0, z0 + 0.25 * body_h), ceramic))
    return Design(tuple(parts), {"ceramic": ceramic.words})


@category(
    "coffee_machine",
    "object",
    size=(0.4, 0.3, 0.4),
    low=(0.25, 0.18, 0.26),
    high=(0.55, 0.45, 0.55),
    mass=9.0,
    placement=OBJECT,
    description="a {finish} espresso machine",
    variants=(None, (0.34, 0.26, 0.36)),
)
def coffee_machine(size: Vec3, rng: Rng) -> Design:
    """An espresso machine: base with drip tray, rear tower, a head over the tray (+X)."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, (STEEL, BLACK_PLASTIC, RED_ENAMEL, CREAM_ENAMEL))
    base_h = 0.08 * h
    gx = hd - 0.22 * d
    head_z = 0.72 * h
    cup_h = min(0.07, 0.3 * h)
    gr = clamp(0.1 * min(d, w), 0.02, 0.04)
    parts: list[Part] = [
        block((-hd, hd), (-hw, hw), (0.0, base_h), finish),
        deco((-hd + 0.55 * d, hd - 0.02), (-0.4 * w, 0.4 * w), (base_h, base_h + 0.002), CHROME),
        block((-hd, -hd + 0.55 * d), (-hw, hw), (base_h, h), finish),
        block((-hd + 0.55 * d, hd - 0.04 * d), (-hw, hw), (head_z, h), finish),
        cyl_z(gx, 0.0, head_z - 0.06 * h, head_z, gr, CHROME),
        block((gx, hd), (-0.012, 0.012), (head_z - 0.055 * h, head_z - 0.035 * h), BLACK_PLASTIC),
        Lathe((gx, 0.0, base_h + 0.002), ((0.022, 0.0), (0.03, cup_h)), PORCELAIN,
              hollow=(0.003, 0.006), collide=False),
        cyl_z(hd - 0.1 * d, 0.38 * w, 0.25 * h, head_z, 0.004, CHROME, collide=False),
    ]  # fmt: skip
    return Design(tuple(parts), {"finish": finish.words})


@category(
    "blender",
    "object",
    size=(0.18, 0.18, 0.4),
    low=(0.12, 0.12, 0.26),
    high=(0.26, 0.26, 0.55),
    mass=3.5,
    placement=OBJECT,
    yx_ratio=ROUND,
    zx_ratio=(1.4, 3.5),
    description="a {finish} countertop blender",
    variants=(None, (0.16, 0.16, 0.36)),
)
def blender(size: Vec3, rng: Rng) -> Design:
    """A blender: square motor base with a dial, a flared glass jar and a lid."""
    d, _, h = size
    hd = 0.5 * d
    finish = pick(rng, (BLACK_PLASTIC, WHITE_PLASTIC, STEEL, RED_ENAMEL))
    base_h = 0.32 * h
    jar_top = h - 0.025
    parts: list[Part] = [
        block((-hd, hd - 0.006), (-hd, hd), (0.0, base_h), finish),
        block((hd - 0.006, hd), (-0.03, 0.03), (0.35 * base_h, 0.65 * base_h), CHROME),
        Lathe((0.0, 0.0, base_h), ((0.5 * hd, 0.0), (0.88 * hd, jar_top - base_h)), CLEAR_GLASS,
              hollow=(0.004, 0.012)),
        cyl_z(0.0, 0.0, jar_top, h, 0.9 * hd, BLACK_PLASTIC),
    ]  # fmt: skip
    return Design(tuple(parts), {"finish": finish.words})


@category(
    "stand_mixer",
    "object",
    size=(0.25, 0.35, 0.35),
    low=(0.18, 0.26, 0.26),
    high=(0.34, 0.45, 0.45),
    mass=10.0,
    placement=OBJECT,
    description="a {finish} stand mixer with a steel bowl",
    variants=(None, (0.22, 0.32, 0.33)),
)
def stand_mixer(size: Vec3, rng: Rng) -> Design:
    """A tilt-head stand mixer: base, column at +Y, head over a steel bowl at -Y."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, (RED_ENAMEL, CREAM_ENAMEL, MINT_ENAMEL, WHITE_PLASTIC, BLACK_PLASTIC))
    base_h = 0.08 * h
    head_r = min(0.45 * d, 0.16 * h)
    head_z = h - head_r
    col = (hw - 0.3 * w, hw - 0.02 * w)
    bowl_r = min(0.45 * d, 0.3 * w)
    bowl_y = -hw + 0.02 + bowl_r
    bowl_h = min(0.45 * h, head_z - head_r - base_h - 0.01)
    parts: list[Part] = [
        block((-hd, hd), (-hw, hw), (0.0, base_h), finish),
        block((-0.35 * d, 0.35 * d), col, (base_h, head_z), finish),
        cyl_y(-hw + 0.12 * w, hw, 0.0, head_z, head_r, finish),
        cyl_z(0.0, -hw + 0.12 * w, head_z - 0.4 * head_r, head_z, 0.4 * head_r, finish),
        Lathe((0.0, bowl_y, base_h), ((0.55 * bowl_r, 0.0), (bowl_r, bowl_h)), STEEL,
              hollow=(0.003, 0.01)),
        cyl_z(0.0, bowl_y, base_h + 0.3 * bowl_h, head_z - head_r, 0.006, CHROME,
              collide=False),
    ]  # fmt: skip
    return Design(tuple(parts), {"finish": finish.words})
