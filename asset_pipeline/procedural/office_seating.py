"""Office chairs and stools."""

from __future__ import annotations

from asset_pipeline.procedural.kit import (
    BLACK_LEATHER,
    BLACK_METAL,
    CHROME,
    FABRICS,
    GREY_FABRIC,
    WOODS,
    Rng,
    block,
    chance,
    pick,
    round_legs,
    square_legs,
    uniform,
)
from asset_pipeline.procedural.parts import Part, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.roles import tagged
from asset_pipeline.procedural.round_parts import Cylinder


# --- office chairs and stools ---------------------------------------------------------------------
@category(
    "office_chair",
    "furniture",
    size=(0.62, 0.6, 1.0),
    low=(0.5, 0.5, 0.85),
    high=(0.75, 0.75, 1.3),
    mass=12.0,
    friction=0.7,
    description="a {fabric} office chair with a {metal} column{arms} on a cross base",
    variants=(None, (0.66, 0.66, 1.15)),
)
def office_chair(size: Vec3, rng: Rng) -> Design:
    """A static office chair: cross base, gas column, padded seat, backrest at -X."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    fabric = pick(rng, (GREY_FABRIC, BLACK_LEATHER, *FABRICS[1:3]))
    metal = pick(rng, (CHROME, BLACK_METAL))
    back_t = uniform(rng, 0.05, 0.08)
    gap = 0.02
    sx = (-hd + back_t + gap, hd)
    cx = 0.5 * (sx[0] + sx[1])
    seat_top = uniform(rng, 0.46, 0.52)
    seat_t = uniform(rng, 0.07, 0.1)
    arms = chance(rng, 0.5)
    arm_w = 0.05 if arms else 0.0
    seat_y = (-hw + arm_w + (0.01 if arms else 0.0), hw - arm_w - (0.01 if arms else 0.0))
    reach = 0.5 * (sx[1] - sx[0])
    parts: list[Part] = [
        *tagged(
            "base",
            [
                block((cx - reach, cx + reach), (-0.03, 0.03), (0.0, 0.04), BLACK_METAL),
                block(
                    (cx - 0.03, cx + 0.03),
                    (-min(hw, reach + 0.05), min(hw, reach + 0.05)),
                    (0.0, 0.04),
                    BLACK_METAL,
                ),
            ],
        ),
        *tagged(
            "pole",
            [
                Cylinder(
                    (cx, 0.0, 0.5 * (0.04 + seat_top - seat_t)),
                    0.025,
                    0.5 * (seat_top - seat_t - 0.04),
                    metal,
                )
            ],
        ),
        *tagged("seat", [block(sx, seat_y, (seat_top - seat_t, seat_top), fabric, surface=True)]),
        *tagged(
            "frame",
            [
                block(
                    (-hd + back_t, sx[0] + 0.015),
                    (-0.03, 0.03),
                    (seat_top - seat_t, seat_top + 0.15),
                    BLACK_METAL,
                )
            ],
        ),
        *tagged(
            "back",
            [
                block(
                    (-hd, -hd + back_t),
                    (-min(hw, 0.5 * w - 0.02), min(hw, 0.5 * w - 0.02)),
                    (seat_top + 0.12, h),
                    fabric,
                )
            ],
        ),
    ]
    if arms:
        arm_top = seat_top + uniform(rng, 0.18, 0.24)
        for y in ((-hw, -hw + arm_w), (hw - arm_w, hw)):
            ym = 0.5 * (y[0] + y[1])
            post = block(
                (cx - 0.02, cx + 0.02),
                (ym - 0.012, ym + 0.012),
                (seat_top - seat_t, arm_top - 0.03),
                BLACK_METAL,
            )
            pad = block((cx - 0.14, cx + 0.12), y, (arm_top - 0.03, arm_top), BLACK_METAL)
            parts += tagged("arms", [post, pad])
    words = {"fabric": fabric.words, "metal": metal.words, "arms": " and armrests" if arms else ""}
    return Design(tuple(parts), words)


@category(
    "stool",
    "furniture",
    size=(0.34, 0.34, 0.46),
    low=(0.28, 0.28, 0.4),
    high=(0.5, 0.5, 0.85),
    mass=3.0,
    friction=0.6,
    description="a {shape} {wood} stool with four legs{footrest}",
    variants=(None, (0.38, 0.38, 0.75)),
)
def stool(size: Vec3, rng: Rng) -> Design:
    """A stool: four legs, a square or (for a square footprint) round seat, a footrest if tall."""
    d, w, h = size
    wood = pick(rng, WOODS + (BLACK_METAL,))
    seat_t = uniform(rng, 0.025, 0.04)
    leg_top = h - seat_t
    round_seat = abs(d - w) < 1e-3 and chance(rng, 0.6)
    parts: list[Part] = []
    if round_seat:
        r = 0.5 * d
        inset = 0.45 * r
        parts += tagged("legs", round_legs(d, w, leg_top, 0.016, wood, inset=inset))
        seat: Part = Cylinder((0.0, 0.0, h - 0.5 * seat_t), r, 0.5 * seat_t, wood, surface=True)
        parts += tagged("seat", [seat])
        reach = 0.5 * d - inset
    else:
        inset = uniform(rng, 0.02, 0.05)
        parts += tagged("legs", square_legs(d, w, leg_top, 0.032, wood, inset=inset))
        seat = block((-0.5 * d, 0.5 * d), (-0.5 * w, 0.5 * w), (leg_top, h), wood, surface=True)
        parts += tagged("seat", [seat])
        reach = 0.5 * d - inset - 0.016
    footrest = h > 0.6
    if footrest:
        z = 0.3 * h
        for sign in (-1.0, 1.0):
            y = sign * (0.5 * w - inset - (0.0 if round_seat else 0.016))
            rest = block((-reach, reach), (y - 0.01, y + 0.01), (z, z + 0.02), wood)
            parts += tagged("frame", [rest])
    words = {
        "shape": "round" if round_seat else "square",
        "wood": wood.words,
        "footrest": " and footrests" if footrest else "",
    }
    return Design(tuple(parts), words)
