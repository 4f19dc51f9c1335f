"""Generators of health-care furniture (front +X).

Every generator fills exactly ``[-d/2, d/2] x [-w/2, w/2] x [0, h]`` (x = depth, y = width).
"""

from __future__ import annotations

import numpy as np

from asset_pipeline.procedural.kit import (
    BLACK_LEATHER,
    BLACK_METAL,
    CHROME,
    LINEN,
    OAK,
    PAPER,
    STEEL,
    Rng,
    block,
    chance,
    clamp,
    drawer_fronts,
    pick,
    uniform,
)
from asset_pipeline.procedural.leisure_kit import (
    RUBBER,
    rod,
    tilted,
    tilted_bounds,
)
from asset_pipeline.procedural.parts import Part, RecipeMaterial, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.work_kit import (
    LAB_WHITE,
    OFFICE_GREY,
    PUTTY,
)

MINT = RecipeMaterial("mint_vinyl", (0.55, 0.78, 0.72, 1.0), 0.4, 0.5, "mint green vinyl")


# --- health -----------------------------------------------------------------------------------
@category(
    "hospital_bed",
    "furniture",
    size=(2.2, 1.0, 1.0),
    low=(2.0, 0.85, 0.8),
    high=(2.4, 1.2, 1.2),
    mass=130.0,
    friction=0.8,
    description="an adjustable hospital bed with a {frame} frame, side rails, {back} and casters",
    variants=(None, (2.3, 1.05, 1.05), (2.1, 0.9, 0.9)),
)
def hospital_bed(size: Vec3, rng: Rng) -> Design:
    """A base frame on casters, a lift column, a mattress platform, head and foot boards,
    half-length side rails; the head section may be raised (a tilted slab)."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    frame = pick(
        rng,
        (
            LAB_WHITE,
            OFFICE_GREY,
            RecipeMaterial("bed_blue", (0.45, 0.60, 0.78, 1.0), 0.4, 0.4, "pale blue"),
        ),
    )
    board = pick(rng, (frame, OAK, PUTTY))
    rail = 0.04
    board_t = 0.05
    plat_z = clamp(uniform(rng, 0.45, 0.55), 0.4, h - 0.35)
    mat_t = 0.14
    top = plat_z + mat_t
    xi = (-hd + board_t, hd - board_t)
    yi = (-hw + rail + 0.01, hw - rail - 0.01)
    raised = chance(rng, 0.5)
    parts: list[Part] = [
        block((-hd + 0.1, hd - 0.1), (-hw + 0.1, hw - 0.1), (0.1, 0.16), frame),
        block((-0.3, 0.3), (-0.15, 0.15), (0.16, plat_z - 0.05), BLACK_METAL),
        block((xi[0], xi[1]), (yi[0], yi[1]), (plat_z - 0.05, plat_z), frame),
        block((-hd, -hd + board_t), (-hw + 0.02, hw - 0.02), (0.15, h), board),
        block((hd - board_t, hd), (-hw + 0.02, hw - 0.02), (0.15, min(top + 0.2, h)), board),
    ]
    for x in (-hd + 0.15, hd - 0.15):
        for y in (-hw + 0.15, hw - 0.15):
            parts.append(block((x - 0.03, x + 0.03), (y - 0.03, y + 0.03), (0.06, 0.1), STEEL))
            parts.append(rod("x", x - 0.05, x + 0.05, y, 0.05, 0.05, RUBBER))
    hinge = xi[0] + 0.7
    if raised:
        angle = np.radians(uniform(rng, 25.0, 35.0))
        length = 0.65
        hx, hz = tilted_bounds(length, mat_t, angle)
        cx = hinge - hx
        parts.append(tilted((cx, 0.0, plat_z + hz), length, yi[1] - yi[0], mat_t, -angle, LINEN))
        parts.append(
            block(
                (hinge, xi[1]),
                yi,
                (plat_z, top),
                LINEN,
                surface=(hinge + 0.05, xi[1], yi[0], yi[1]),
            )
        )
    else:
        parts.append(block(xi, yi, (plat_z, top), LINEN, surface=(xi[0] + 0.45, xi[1], *yi)))
        parts.append(block((xi[0] + 0.05, xi[0] + 0.4), (-0.25, 0.25), (top, top + 0.1), LINEN))
    for rail_y in ((-hw, -hw + rail), (hw - rail, hw)):
        parts += frame_rect_y(
            (xi[0] + 0.1, xi[0] + 1.0), rail_y, (plat_z, min(top + 0.3, h - 0.02)), 0.03, frame
        )
    words = {"frame": frame.words, "back": "a raised backrest" if raised else "a pillow"}
    return Design(tuple(parts), words)


def frame_rect_y(
    x: tuple[float, float],
    y: tuple[float, float],
    z: tuple[float, float],
    t: float,
    m: RecipeMaterial,
) -> list[Part]:
    """Four bars outlining the rectangle ``x`` x ``z`` in the plane slab ``y`` (a side rail)."""
    (x0, x1), (z0, z1) = x, z
    return [
        block((x0, x1), y, (z1 - t, z1), m),
        block((x0, x0 + t), y, (z0, z1 - t), m),
        block((x1 - t, x1), y, (z0, z1 - t), m),
        block((x0 + t, x1 - t), y, (0.5 * (z0 + z1) - 0.5 * t, 0.5 * (z0 + z1) + 0.5 * t), m),
    ]


@category(
    "examination_table",
    "furniture",
    size=(1.9, 0.7, 0.8),
    low=(1.7, 0.55, 0.7),
    high=(2.1, 0.85, 1.0),
    mass=80.0,
    friction=0.8,
    description="a padded {cover} medical examination table on a {base} cabinet base with "
    "drawers, a step and a paper roll",
    variants=(None, (2.0, 0.75, 0.85), (1.8, 0.6, 0.75)),
)
def examination_table(size: Vec3, rng: Rng) -> Design:
    """A cabinet base with drawers at the foot end (+X), a step, a flat pad covered by paper
    (a surface), a raised back section at -X and a paper roll at the head."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    cover = pick(
        rng,
        (
            MINT,
            BLACK_LEATHER,
            RecipeMaterial("exam_blue", (0.25, 0.40, 0.60, 1.0), 0.4, 0.5, "blue vinyl"),
            PUTTY,
        ),
    )
    base = pick(rng, (LAB_WHITE, OAK, OFFICE_GREY))
    pad = 0.07
    back_h = clamp(uniform(rng, 0.18, 0.25), 0.1, 0.25)
    top = h - back_h
    step = 0.22
    face = hd - step
    roll_r = 0.06
    parts: list[Part] = [
        block((-hd + 0.1, face - 0.036), (-hw + 0.02, hw - 0.02), (0.0, top - pad), base),
        block((face - 0.036, hd), (-hw + 0.05, hw - 0.05), (0.0, 0.22), base),
        block((face - 0.036, hd - 0.02), (-hw + 0.05, hw - 0.05), (0.22, 0.26), cover),
        block((-hd + 0.1, hd), (-hw, hw), (top - pad, top - 0.002), cover),
        block(
            (-hd + 0.6, hd - 0.02), (-0.45 * w, 0.45 * w), (top - 0.002, top), PAPER, surface=True
        ),
    ]
    parts += drawer_fronts(
        face - 0.036, (-hw + 0.05, hw - 0.05), (0.27, top - pad - 0.01), 2, 1, base, CHROME
    )
    parts.append(block((-hd + 0.1, -hd + 0.6), (-hw, hw), (top, h), cover))
    parts.append(rod("y", -hw + 0.04, hw - 0.04, -hd + roll_r, top - pad - roll_r, roll_r, PAPER))
    parts.append(
        block(
            (-hd + 0.08, -hd + 0.1),
            (-hw + 0.02, hw - 0.02),
            (top - pad - 2 * roll_r, top - pad),
            CHROME,
        )
    )
    return Design(tuple(parts), {"cover": cover.words, "base": base.words})
