"""Generators of beds, sofas, chairs, tables and desks (depth along X, width along Y, front +X).

Every generator takes the bounding box ``(d, w, h)`` and a style generator and fills exactly
``[-d/2, d/2] x [-w/2, w/2] x [0, h]``.
"""

from __future__ import annotations

from asset_pipeline.procedural.kit import (
    BLACK_METAL,
    FABRICS,
    LINEN,
    WOODS,
    Rng,
    block,
    chance,
    pick,
    square_legs,
    uniform,
)
from asset_pipeline.procedural.parts import Part, RecipeMaterial, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.roles import tagged

WHITE_CHAIR = RecipeMaterial("white_chair", (0.93, 0.92, 0.90, 1.0), 0.3, 0.4, "white painted")


# --- beds ------------------------------------------------------------------------------------
@category(
    "bed",
    "furniture",
    size=(2.1, 1.6, 1.0),
    low=(1.8, 0.8, 0.7),
    high=(2.4, 2.2, 1.4),
    mass=60.0,
    description="a {width} bed with a {frame} frame, a {headboard} headboard and {pillows}",
    variants=(None, (2.05, 0.95, 0.9)),
)
def bed(size: Vec3, rng: Rng) -> Design:
    """A bed: headboard at -X, frame on legs, mattress (a surface past the pillows), pillows."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    frame = pick(rng, WOODS)
    headboard = frame if chance(rng, 0.5) else pick(rng, FABRICS)
    hb_t = uniform(rng, 0.04, 0.08)
    mattress_top = min(uniform(rng, 0.5, 0.6), h - 0.15)
    thickness = uniform(rng, 0.18, 0.26)
    frame_top = mattress_top - thickness
    leg_h = min(uniform(rng, 0.06, 0.16), frame_top - 0.08)
    x0 = -hd + hb_t
    parts: list[Part] = tagged("headboard", [block((-hd, x0), (-hw, hw), (0.0, h), headboard)])
    foot_t = uniform(rng, 0.03, 0.05) if chance(rng, 0.5) else 0.0
    x1 = hd - foot_t
    if foot_t:
        parts += tagged("frame", [block((x1, hd), (-hw, hw), (0.0, mattress_top - 0.06), frame)])
    parts += tagged(
        "legs",
        (
            p.translated((x0 + 0.5 * (x1 - x0), 0.0, 0.0))
            for p in square_legs(x1 - x0, w, leg_h, 0.07, frame)
        ),
    )
    parts += tagged("frame", [block((x0, x1), (-hw, hw), (leg_h, frame_top), frame)])
    pillow_front = x0 + uniform(rng, 0.36, 0.46)
    bedding: list[Part] = []
    bedding.append(
        block(
            (x0 + 0.01, x1 - 0.01),
            (-hw + 0.02, hw - 0.02),
            (frame_top, mattress_top),
            LINEN,
            surface=(pillow_front + 0.02, x1, -hw, hw),
        )
    )
    pillows = 1 if w < 1.2 else 2
    span = (w - 0.16) / pillows
    pillow_h = min(uniform(rng, 0.1, 0.14), h - mattress_top - 0.01)
    for i in range(pillows):
        y0 = -hw + 0.08 + i * span
        bedding.append(
            block(
                (x0 + 0.05, pillow_front),
                (y0 + 0.02, y0 + span - 0.02),
                (mattress_top, mattress_top + pillow_h),
                LINEN,
            )
        )
    parts += tagged("bedding", bedding)
    words = {
        "width": "single" if w < 1.2 else ("double" if w < 1.7 else "king-size"),
        "frame": frame.words,
        "headboard": headboard.words + (" upholstered" if headboard in FABRICS else ""),
        "pillows": "one pillow" if pillows == 1 else "two pillows",
    }
    return Design(tuple(parts), words)


@category(
    "bunk_bed",
    "furniture",
    size=(2.05, 1.0, 1.65),
    low=(1.9, 0.8, 1.4),
    high=(2.2, 1.4, 1.9),
    mass=70.0,
    description="a {frame} bunk bed with two mattresses, guard rails and a ladder",
    variants=(None, (2.0, 0.95, 1.55)),
)
def bunk_bed(size: Vec3, rng: Rng) -> Design:
    """Two bunks between four corner posts; rails around the top bunk, a ladder on +Y."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    frame = pick(rng, WOODS + (BLACK_METAL,))
    post = uniform(rng, 0.05, 0.07)
    rail_t = 0.025
    parts: list[Part] = []
    for x in ((-hd, -hd + post), (hd - post, hd)):
        for y in ((-hw, -hw + post), (hw - post, hw)):
            parts.append(block(x, y, (0.0, h), frame))
    xi = (-hd + post, hd - post)
    mattress_t = uniform(rng, 0.12, 0.16)
    lower_frame = (0.12, 0.22)
    upper_top = h - uniform(rng, 0.2, 0.26)  # top of the upper mattress
    upper_frame = (upper_top - mattress_t - 0.1, upper_top - mattress_t)
    ladder_x = (hd - post - 0.42, hd - post)
    for z0, z1 in (lower_frame, upper_frame):
        parts.append(block(xi, (-hw, hw), (z0, z1), frame))
    # lower mattress: clear of the ladder on +Y
    parts.append(
        block(
            (xi[0] + 0.01, xi[1] - 0.01),
            (-hw + 0.02, hw - 0.04),
            (lower_frame[1], lower_frame[1] + mattress_t),
            LINEN,
            surface=True,
        )
    )
    parts.append(
        block(
            (xi[0] + 0.01, xi[1] - 0.01),
            (-hw + rail_t + 0.01, hw - rail_t - 0.01),
            (upper_frame[1], upper_top),
            LINEN,
            surface=True,
        )
    )
    rail_z = (upper_frame[1], h - 0.02)
    parts.append(block(xi, (-hw, -hw + rail_t), rail_z, frame))
    parts.append(block((xi[0], ladder_x[0]), (hw - rail_t, hw), rail_z, frame))
    for x in ((ladder_x[0], ladder_x[0] + 0.03),):
        parts.append(block(x, (hw - rail_t, hw), (0.0, upper_frame[0]), frame))
    rungs = int((upper_frame[0] - 0.25) // 0.25) + 1
    for i in range(rungs):
        z = 0.3 + i * (upper_frame[0] - 0.3) / rungs
        parts.append(
            block((ladder_x[0] + 0.03, ladder_x[1]), (hw - rail_t, hw), (z, z + 0.03), frame)
        )
    return Design(tuple(parts), {"frame": frame.words})
