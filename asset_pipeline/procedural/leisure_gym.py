"""Generators of gym equipment (front +X).

Every generator fills exactly ``[-d/2, d/2] x [-w/2, w/2] x [0, h]`` (x = depth, y = width).
"""

from __future__ import annotations

from asset_pipeline.procedural.kit import (
    ALUMINIUM,
    BLACK_LEATHER,
    BLACK_METAL,
    BLACK_PLASTIC,
    CHARCOAL_FABRIC,
    CHROME,
    LEATHER,
    OAK,
    SCREEN,
    SPACE_GREY,
    STEEL,
    WALNUT,
    WHITE_LACQUER,
    WHITE_PLASTIC,
    Rng,
    block,
    chance,
    clamp,
    pick,
    uniform,
)
from asset_pipeline.procedural.leisure_kit import (
    BLUE_PAINT,
    RED_PAINT,
    RUBBER,
    UPHOLSTERY,
    cyl,
    rod,
)
from asset_pipeline.procedural.parts import Part, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.round_parts import Lathe

GYM_PAINTS = (BLACK_METAL, SPACE_GREY, RED_PAINT, WHITE_LACQUER)


# --- gym -------------------------------------------------------------------------------------
@category(
    "treadmill",
    "furniture",
    size=(1.95, 0.85, 1.4),
    low=(1.5, 0.65, 1.1),
    high=(2.3, 1.05, 1.65),
    mass=90.0,
    friction=0.8,
    description="a {frame} motorised treadmill with a {belt} running belt, handrails and a console",
    variants=(None, (2.1, 0.95, 1.5), (1.7, 0.75, 1.3)),
)
def treadmill(size: Vec3, rng: Rng) -> Design:
    """A treadmill: deck on the floor, motor hood and console uprights at +X, handrails."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    frame = pick(rng, (BLACK_METAL, SPACE_GREY, ALUMINIUM))
    accent = pick(rng, (RED_PAINT, BLUE_PAINT, BLACK_PLASTIC))
    hood = uniform(rng, 0.28, 0.36)
    deck_h = uniform(rng, 0.16, 0.22)
    belt_w = clamp(uniform(rng, 0.5, 0.6), 0.4, w - 0.2)
    rail = 0.5 * (w - belt_w) - 0.04
    x_hood = hd - hood
    up = 0.05
    console_h = clamp(uniform(rng, 0.16, 0.22), 0.12, 0.3)
    parts: list[Part] = [
        block((-hd, x_hood), (-0.5 * belt_w, 0.5 * belt_w), (0.0, deck_h - 0.01), BLACK_PLASTIC),
        block(
            (-hd + 0.06, x_hood - 0.04),
            (-0.5 * belt_w + 0.02, 0.5 * belt_w - 0.02),
            (deck_h - 0.01, deck_h),
            RUBBER,
        ),
        block((x_hood, hd), (-hw + 0.04, hw - 0.04), (0.0, deck_h + 0.08), accent),
    ]
    for sign in (-1.0, 1.0):
        y_in, y_out = sign * 0.5 * belt_w, sign * (0.5 * belt_w + rail)
        parts.append(block((-hd, x_hood), tuple(sorted((y_in, y_out))), (0.0, deck_h), frame))
        y_post = tuple(sorted((sign * hw, sign * (hw - up))))
        parts.append(
            block((x_hood + 0.02, x_hood + 0.02 + up), y_post, (0.0, h - console_h), frame)
        )
        arm_z = h - console_h - uniform(rng, 0.12, 0.2)
        parts.append(block((x_hood - 0.45, x_hood + 0.02), y_post, (arm_z - 0.04, arm_z), frame))
    parts.append(block((x_hood - 0.08, hd - 0.02), (-hw, hw), (h - console_h, h), frame))
    parts.append(
        block(
            (x_hood - 0.085, x_hood - 0.08),
            (-0.3 * w, 0.3 * w),
            (h - console_h + 0.03, h - 0.03),
            SCREEN,
            collide=False,
        )
    )
    return Design(tuple(parts), {"frame": frame.words, "belt": "black rubber"})


@category(
    "exercise_bike",
    "furniture",
    size=(1.1, 0.55, 1.3),
    low=(0.9, 0.45, 1.1),
    high=(1.4, 0.7, 1.5),
    mass=40.0,
    description="a {frame} stationary exercise bike with a {seat} saddle and a front flywheel",
    variants=(None, (1.2, 0.6, 1.35), (1.0, 0.5, 1.2)),
)
def exercise_bike(size: Vec3, rng: Rng) -> Design:
    """Two floor stabilisers, a frame beam, a flywheel at +X, seat post at -X, handlebars."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    frame = pick(rng, (BLACK_METAL, WHITE_LACQUER, SPACE_GREY))
    seat = pick(rng, (BLACK_LEATHER, CHARCOAL_FABRIC, LEATHER))
    wheel = pick(rng, (CHROME, RED_PAINT, BLACK_PLASTIC))
    fw_r = clamp(uniform(rng, 0.2, 0.26), 0.15, 0.25 * h)
    x_front, x_back = hd - 0.06, -hd + 0.06
    seat_z = clamp(uniform(rng, 0.78, 0.9), 0.6, h - 0.3)
    parts: list[Part] = [
        block((hd - 0.12, hd), (-hw, hw), (0.0, 0.06), frame),
        block((-hd, -hd + 0.12), (-hw, hw), (0.0, 0.06), frame),
        block((x_back, x_front), (-0.03, 0.03), (0.06, 0.12), frame),
        rod("y", -0.045, 0.045, x_front - fw_r - 0.02, 0.12 + fw_r, fw_r, wheel),
        block((x_front - 0.1, x_front - 0.05), (-0.05, -0.045), (0.12, 0.16 + 2 * fw_r), frame),
        block((x_front - 0.1, x_front - 0.05), (0.045, 0.05), (0.12, 0.16 + 2 * fw_r), frame),
        block((x_front - 0.08, x_front - 0.02), (-0.03, 0.03), (0.12 + 2 * fw_r, h - 0.1), frame),
        block(
            (x_front - 0.22, x_front), (-min(hw, 0.24), min(hw, 0.24)), (h - 0.14, h - 0.1), frame
        ),
        block((x_front - 0.1, x_front), (-0.08, 0.08), (h - 0.1, h), BLACK_PLASTIC),
        block((x_back + 0.2, x_back + 0.26), (-0.025, 0.025), (0.12, seat_z - 0.05), frame),
        block((x_back + 0.12, x_back + 0.38), (-0.09, 0.09), (seat_z - 0.05, seat_z), seat),
    ]
    crank_x = x_back + 0.5 * (x_front - x_back) - 0.02
    for sign in (-1.0, 1.0):
        y = tuple(sorted((sign * 0.03, sign * 0.06)))
        parts.append(block((crank_x - 0.02, crank_x + 0.02), y, (0.12, 0.36), BLACK_METAL))
        y_p = tuple(sorted((sign * 0.06, sign * 0.16)))
        parts.append(block((crank_x - 0.06, crank_x + 0.06), y_p, (0.14, 0.17), BLACK_PLASTIC))
    return Design(tuple(parts), {"frame": frame.words, "seat": seat.words})


@category(
    "weight_bench",
    "furniture",
    size=(1.3, 0.6, 0.45),
    low=(1.1, 0.45, 0.4),
    high=(1.6, 0.75, 0.55),
    mass=25.0,
    description="an adjustable weight bench with {pad} pads on a {frame} frame",
    variants=(None, (1.4, 0.65, 0.48), (1.2, 0.5, 0.43)),
)
def weight_bench(size: Vec3, rng: Rng) -> Design:
    """Two floor feet across Y, a spine beam, a seat pad and a longer back pad."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    frame = pick(rng, GYM_PAINTS)
    pad = pick(rng, UPHOLSTERY)
    pad_t = uniform(rng, 0.06, 0.08)
    pad_w = clamp(uniform(rng, 0.26, 0.3), 0.24, w - 0.1)
    split = hd - uniform(rng, 0.38, 0.45)
    gap = 0.03 if chance(rng, 0.7) else 0.0
    z_pad = h - pad_t
    parts: list[Part] = [
        block((hd - 0.08, hd), (-hw, hw), (0.0, 0.06), frame),
        block((-hd, -hd + 0.08), (-hw, hw), (0.0, 0.06), frame),
        block((-hd + 0.1, hd - 0.1), (-0.04, 0.04), (0.06, 0.14), frame),
        block((hd - 0.1, hd - 0.04), (-0.035, 0.035), (0.06, z_pad - 0.03), frame),
        block((-hd + 0.04, -hd + 0.1), (-0.035, 0.035), (0.06, z_pad - 0.03), frame),
        block((-0.05, 0.05), (-0.035, 0.035), (0.14, z_pad - 0.03), frame),
        block((-hd + 0.02, hd - 0.02), (-0.06, 0.06), (z_pad - 0.03, z_pad), frame),
        block((split + 0.5 * gap, hd), (-0.5 * pad_w, 0.5 * pad_w), (z_pad, h), pad),
        block((-hd, split - 0.5 * gap), (-0.5 * pad_w, 0.5 * pad_w), (z_pad, h), pad),
    ]
    return Design(tuple(parts), {"pad": pad.words, "frame": frame.words})


@category(
    "dumbbell_rack",
    "furniture",
    size=(0.5, 1.2, 0.8),
    low=(0.35, 0.7, 0.55),
    high=(0.7, 1.8, 1.0),
    mass=35.0,
    description="a two-tier {frame} dumbbell rack with {trays} trays",
    variants=(None, (0.55, 1.5, 0.85), (0.4, 0.9, 0.7)),
)
def dumbbell_rack(size: Vec3, rng: Rng) -> Design:
    """Two end frames and two stepped trays: the upper at the back (-X), the lower in front."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    frame = pick(rng, GYM_PAINTS)
    tray = pick(rng, (BLACK_PLASTIC, frame, STEEL))
    post = 0.05
    split = uniform(rng, -0.05, 0.05) * d
    low_z = clamp(uniform(rng, 0.5, 0.6) * h, 0.3, h - 0.15)
    t = 0.04
    parts: list[Part] = []
    for y in ((-hw, -hw + post), (hw - post, hw)):
        parts.append(block((-hd, hd), y, (0.0, 0.05), frame))
        parts.append(block((-hd + 0.02, -hd + 0.02 + post), y, (0.05, h), frame))
        parts.append(block((hd - 0.02 - post, hd - 0.02), y, (0.05, low_z), frame))
        parts.append(block((-hd + 0.02 + post, split), y, (h - t - 0.05, h - t), frame))
    yin = (-hw + post, hw - post)
    parts.append(block((-hd, split), yin, (h - t, h), tray, surface=True))
    parts.append(block((split + 0.005, hd), yin, (low_z - t, low_z), tray, surface=True))
    parts.append(block((-hd + 0.02, -hd + 0.02 + post), yin, (0.05, 0.12), frame))
    return Design(tuple(parts), {"frame": frame.words, "trays": tray.words})


@category(
    "squat_rack",
    "furniture",
    size=(1.2, 1.2, 2.2),
    low=(0.9, 1.0, 1.8),
    high=(1.6, 2.2, 2.5),
    mass=120.0,
    description="a {frame} steel squat rack with a barbell{plates} resting on J-hooks",
    variants=(None, (1.4, 1.5, 2.3), (1.0, 1.1, 2.0)),
)
def squat_rack(size: Vec3, rng: Rng) -> Design:
    """Four uprights on floor rails, top cross bars, J-hooks and a barbell across Y."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    frame = pick(rng, GYM_PAINTS)
    s = 0.07
    sleeve = clamp(0.12 * w, 0.1, 0.25)
    fw = hw - sleeve  # half width of the frame
    bar_z = clamp(uniform(rng, 0.55, 0.65) * h, 1.0, h - 0.4)
    plates = chance(rng, 0.5)
    pr = min(clamp(uniform(rng, 0.16, 0.22), 0.1, bar_z - 0.1), 0.3 * d)
    bar_x = hd - (pr if plates else 0.035)
    xf = (bar_x - 0.06 - s, bar_x - 0.06)
    xr = (-hd + 0.05, -hd + 0.05 + s)
    parts: list[Part] = []
    for y in ((-fw, -fw + s), (fw - s, fw)):
        parts.append(block((-hd, hd), y, (0.0, 0.06), frame))
        for x in (xf, xr):
            parts.append(block(x, y, (0.06, h), frame))
        parts.append(block((xr[1], xf[0]), y, (h - s, h), frame))
        parts.append(block((xf[1], bar_x + 0.03), y, (bar_z - 0.05, bar_z), BLACK_PLASTIC))
        parts.append(block((bar_x + 0.02, bar_x + 0.035), y, (bar_z, bar_z + 0.03), BLACK_PLASTIC))
    parts.append(block(xr, (-fw + s, fw - s), (h - s, h), frame))
    parts.append(block(xr, (-fw + s, fw - s), (0.0, 0.06), frame))
    parts.append(rod("y", -hw, hw, bar_x, bar_z + 0.015, 0.015, CHROME))
    if plates:
        for sign in (-1.0, 1.0):
            a0, a1 = sorted((sign * (fw + 0.02), sign * (fw + 0.08)))
            parts.append(rod("y", a0, a1, bar_x, bar_z + 0.015, pr, BLACK_PLASTIC))
    words = {"frame": frame.words, "plates": " loaded with plates" if plates else ""}
    return Design(tuple(parts), words)


@category(
    "punching_bag",
    "furniture",
    size=(0.6, 0.6, 1.7),
    low=(0.45, 0.45, 1.4),
    high=(0.8, 0.8, 2.0),
    mass=110.0,
    friction=0.9,
    yx_ratio=(1.0, 1.0),
    description="a freestanding {bag} punching bag on a weighted {base} base",
    variants=(None, (0.65, 0.65, 1.85), (0.5, 0.5, 1.5)),
)
def punching_bag(size: Vec3, rng: Rng) -> Design:
    """A round water-filled base, a short neck and a tall bag above it."""
    d, _, h = size
    r = 0.5 * d
    base = pick(rng, (BLACK_PLASTIC, RED_PAINT, BLUE_PAINT))
    bag = pick(rng, (BLACK_LEATHER, RED_PAINT, BLUE_PAINT, LEATHER))
    base_h = clamp(uniform(rng, 0.3, 0.38), 0.25, 0.25 * h)
    bag_r = clamp(uniform(rng, 0.16, 0.19), 0.12, 0.6 * r)
    neck = 0.1
    parts: list[Part] = [
        Lathe((0.0, 0.0, 0.0), ((r, 0.0), (r, 0.05), (0.75 * r, base_h)), base),
        cyl(0.0, 0.0, base_h, base_h + neck, 0.06, BLACK_PLASTIC),
        Lathe(
            (0.0, 0.0, base_h + neck),
            (
                (0.8 * bag_r, 0.0),
                (bag_r, 0.06),
                (bag_r, h - base_h - neck - 0.05),
                (0.85 * bag_r, h - base_h - neck),
            ),
            bag,
        ),
    ]
    return Design(tuple(parts), {"bag": bag.words, "base": base.words})


@category(
    "rowing_machine",
    "furniture",
    size=(2.4, 0.55, 0.6),
    low=(2.0, 0.45, 0.5),
    high=(2.7, 0.7, 1.0),
    mass=30.0,
    description="an indoor rowing machine with a {frame} rail, a sliding seat and a {fan}",
    variants=(None, (2.5, 0.6, 0.95), (2.1, 0.5, 0.55)),
)
def rowing_machine(size: Vec3, rng: Rng) -> Design:
    """A long monorail on two feet, a sliding seat, footrests and a flywheel housing at +X."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    frame = pick(rng, (ALUMINIUM, BLACK_METAL, OAK))
    housing = pick(rng, (BLACK_PLASTIC, WHITE_PLASTIC, WALNUT))
    r = clamp(uniform(rng, 0.22, 0.26), 0.18, 0.5 * min(h, 0.6) - 0.03)
    fx = hd - r
    rail_z = clamp(uniform(rng, 0.24, 0.3), 0.2, 0.55 * h)
    monitor = h > r * 2 + 0.25
    parts: list[Part] = [
        block((-hd, -hd + 0.1), (-hw, hw), (0.0, 0.06), frame),
        block((fx - 0.12, fx + 0.12), (-hw, hw), (0.0, 0.06), BLACK_METAL),
        block((-hd + 0.03, -hd + 0.08), (-0.04, 0.04), (0.06, rail_z - 0.05), frame),
        block((-hd + 0.03, fx - 0.1), (-0.05, 0.05), (rail_z - 0.05, rail_z), frame),
        block((fx - 0.35, fx - 0.1), (-0.05, 0.05), (0.06, rail_z), BLACK_METAL),
        rod("y", -0.12, 0.12, fx, 0.06 + r, r, housing),
        block((-0.2, 0.12), (-0.13, 0.13), (rail_z, rail_z + 0.06), BLACK_LEATHER),
        block((fx - 0.45, fx - 0.3), (-hw, -0.05), (rail_z - 0.05, rail_z + 0.05), BLACK_PLASTIC),
        block((fx - 0.45, fx - 0.3), (0.05, hw), (rail_z - 0.05, rail_z + 0.05), BLACK_PLASTIC),
    ]
    top = 0.06 + 2 * r - 0.01
    if monitor:
        parts.append(block((fx - 0.03, fx + 0.03), (-0.02, 0.02), (top, h - 0.12), BLACK_METAL))
        parts.append(block((fx - 0.05, fx + 0.05), (-0.09, 0.09), (h - 0.12, h), BLACK_PLASTIC))
    else:
        parts.append(block((fx - 0.04, fx + 0.04), (-0.04, 0.04), (top, h), BLACK_PLASTIC))
    fan = f"{housing.words} flywheel housing" + (" and a monitor arm" if monitor else "")
    return Design(tuple(parts), {"frame": frame.words, "fan": fan})
