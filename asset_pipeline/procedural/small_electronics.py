"""Generators of small lab, office and home electronics.

Small items stand on furniture (placement ``object``, issue 15). Sizes follow the knowledge
base (``objects.json``, whose (width, depth, height) is (y, x, z) here); fronts face +X.
"""

from __future__ import annotations

from asset_pipeline.procedural.kit import (
    ALUMINIUM,
    BLACK_METAL,
    BLACK_PLASTIC,
    CHROME,
    PAPER,
    SCREEN,
    SPACE_GREY,
    WHITE_PLASTIC,
    Rng,
    block,
    clamp,
    pick,
)
from asset_pipeline.procedural.parts import Part, RecipeMaterial, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.small_kit import (
    GREY_PLASTIC,
    LED,
    OBJECT,
    RUBBER,
    cyl_y,
    cyl_z,
    deco,
)

VINYL = RecipeMaterial("vinyl", (0.03, 0.03, 0.03, 1.0), 0.8, 0.8)
LABEL = RecipeMaterial("label", (0.85, 0.25, 0.15, 1.0), 0.3, 0.3)


# --- lab and office electronics ------------------------------------------------------------
@category(
    "microscope",
    "object",
    size=(0.3, 0.2, 0.4),
    low=(0.2, 0.13, 0.26),
    high=(0.45, 0.3, 0.6),
    mass=5.0,
    placement=OBJECT,
    description="a {body} laboratory microscope",
    variants=(None, (0.25, 0.17, 0.34)),
)
def microscope(size: Vec3, rng: Rng) -> Design:
    """A microscope: base, rear arm, stage, objective turret and eyepiece tube (front +X)."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    body = pick(rng, (WHITE_PLASTIC, BLACK_METAL, GREY_PLASTIC))
    trim = BLACK_METAL if body is not BLACK_METAL else CHROME
    bh = clamp(0.1 * h, 0.02, 0.05)
    arm = (-hd + 0.08 * d, -hd + 0.32 * d)
    head_x = -hd + 0.55 * d
    tube_r = clamp(0.08 * w, 0.008, 0.02)
    obj_r = clamp(0.1 * w, 0.01, 0.025)
    parts: list[Part] = [
        block((-hd, hd), (-0.45 * w, 0.45 * w), (0.0, bh), body),
        block(arm, (-0.2 * w, 0.2 * w), (bh, 0.84 * h), body),
        block((arm[0], head_x + 0.08 * d), (-0.25 * w, 0.25 * w), (0.7 * h, 0.84 * h), body),
        block((arm[1], hd - 0.08 * d), (-0.4 * w, 0.4 * w), (0.38 * h, 0.42 * h), trim),
        cyl_z(head_x, 0.0, 0.55 * h, 0.7 * h, obj_r, trim),
        cyl_z(head_x - 0.04 * d, 0.0, 0.84 * h, h, tube_r, trim),
        cyl_y(-hw, hw, -hd + 0.2 * d, 0.25 * h, clamp(0.06 * h, 0.012, 0.03), trim),
        cyl_z(head_x, 0.0, bh, bh + 0.02, clamp(0.06 * w, 0.008, 0.015), CHROME),
    ]
    return Design(tuple(parts), {"body": body.words})


@category(
    "cash_register",
    "object",
    size=(0.4, 0.4, 0.3),
    low=(0.26, 0.26, 0.16),
    high=(0.55, 0.55, 0.42),
    mass=8.0,
    placement=OBJECT,
    description="a {body} cash register with a cash drawer",
    variants=(None, (0.34, 0.36, 0.24)),
)
def cash_register(size: Vec3, rng: Rng) -> Design:
    """A cash register: cash drawer, keyboard deck, a customer display on a post at -X."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    body = pick(rng, (BLACK_PLASTIC, WHITE_PLASTIC, GREY_PLASTIC))
    front = 0.006
    parts: list[Part] = [
        block((-hd, hd - front), (-hw, hw), (0.0, 0.35 * h), body),
        block((hd - front, hd), (-0.4 * w, 0.4 * w), (0.04 * h, 0.31 * h), GREY_PLASTIC),
        block((-hd, hd - 0.12 * d), (-0.45 * w, 0.45 * w), (0.35 * h, 0.52 * h), body),
        block((-hd, -hd + 0.14 * d), (-0.1 * w, 0.1 * w), (0.52 * h, 0.82 * h), body),
        block((-hd, -hd + 0.2 * d), (-0.3 * w, 0.3 * w), (0.82 * h, h), body),
        deco((-hd + 0.2 * d, -hd + 0.2 * d + 0.001), (-0.26 * w, 0.26 * w), (0.85 * h, 0.97 * h),
             SCREEN),
    ]  # fmt: skip
    keys = BLACK_PLASTIC if body is not BLACK_PLASTIC else SPACE_GREY
    x0, x1 = -hd + 0.25 * d, hd - 0.16 * d
    for i in range(4):
        for j in range(5):
            kx = x0 + (i + 0.5) * (x1 - x0) / 4
            ky = -0.35 * w + (j + 0.5) * 0.7 * w / 5
            parts.append(
                deco((kx - 0.012, kx + 0.012), (ky - 0.012, ky + 0.012), (0.52 * h, 0.53 * h), keys)
            )
    return Design(tuple(parts), {"body": body.words})


@category(
    "printer",
    "object",
    size=(0.4, 0.45, 0.3),
    low=(0.25, 0.3, 0.12),
    high=(0.6, 0.65, 0.45),
    mass=8.0,
    placement=OBJECT,
    description="a {body} desktop printer",
    variants=(None, (0.32, 0.4, 0.18)),
)
def printer(size: Vec3, rng: Rng) -> Design:
    """A printer: body, scanner lid, control panel and a paper output tray at +X."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    body = pick(rng, (WHITE_PLASTIC, BLACK_PLASTIC, GREY_PLASTIC))
    lid = SPACE_GREY if body is not SPACE_GREY else BLACK_PLASTIC
    tray = 0.08 * d
    parts: list[Part] = [
        block((-hd, hd - tray), (-hw, hw), (0.0, 0.85 * h), body),
        block((-hd, 0.25 * d), (-hw, hw), (0.85 * h, h), lid),
        block((0.25 * d, hd - tray), (-hw, hw), (0.85 * h, 0.9 * h), body),
        deco((0.3 * d, hd - tray - 0.01), (0.1 * w, 0.4 * w), (0.9 * h, 0.905 * h), SCREEN),
        block((hd - tray, hd), (-0.35 * w, 0.35 * w), (0.3 * h, 0.33 * h), body),
        deco((hd - tray - 0.02, hd - 0.005), (-0.3 * w, 0.3 * w), (0.33 * h, 0.335 * h), PAPER),
    ]
    return Design(tuple(parts), {"body": body.words})


@category(
    "monitor",
    "object",
    size=(0.2, 0.55, 0.45),
    low=(0.12, 0.35, 0.28),
    high=(0.3, 0.9, 0.7),
    mass=4.5,
    placement=OBJECT,
    description="a {finish} flat computer monitor on a stand",
    variants=(None, (0.18, 0.62, 0.42)),
)
def monitor(size: Vec3, rng: Rng) -> Design:
    """A monitor: a flat foot, a neck behind the panel, the screen facing +X."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, (BLACK_PLASTIC, SPACE_GREY, ALUMINIUM, WHITE_PLASTIC))
    t = clamp(0.12 * d, 0.012, 0.035)
    nt = clamp(0.15 * d, 0.015, 0.03)
    bw = clamp(0.2 * w, 0.08, hw)
    zb = clamp(0.2 * h, 0.06, 0.18)
    bezel = 0.01
    parts: list[Part] = [
        block((-hd, hd), (-bw, bw), (0.0, 0.015), finish),
        block((-0.5 * t - nt, -0.5 * t), (-0.03, 0.03), (0.015, 0.7 * h), finish),
        block((-0.5 * t, 0.5 * t), (-hw, hw), (zb, h), finish),
        deco((0.5 * t, 0.5 * t + 0.001), (-hw + bezel, hw - bezel), (zb + 0.02, h - bezel),
             SCREEN),
    ]  # fmt: skip
    return Design(tuple(parts), {"finish": finish.words})


@category(
    "desktop_computer",
    "object",
    size=(0.45, 0.2, 0.42),
    low=(0.3, 0.14, 0.28),
    high=(0.6, 0.3, 0.6),
    mass=9.0,
    placement=("floor", "object"),
    description="a {finish} desktop computer tower",
    variants=(None, (0.4, 0.18, 0.36)),
)
def desktop_computer(size: Vec3, rng: Rng) -> Design:
    """A tower case on four feet; the front panel faces +X."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, (BLACK_PLASTIC, SPACE_GREY, WHITE_PLASTIC, ALUMINIUM))
    panel = BLACK_PLASTIC if finish is not BLACK_PLASTIC else SPACE_GREY
    foot = 0.012
    fx = (-hd + 0.01, -hd + 0.05), (hd - 0.062, hd - 0.022)
    fy = (-hw + 0.01, -hw + 0.04), (hw - 0.04, hw - 0.01)
    parts: list[Part] = [block(x, y, (0.0, foot), RUBBER) for x in fx for y in fy]
    parts += [
        block((-hd, hd - 0.012), (-hw, hw), (foot, h), finish),
        block((hd - 0.012, hd - 0.002), (-hw, hw), (foot, h), panel),
        deco((hd - 0.002, hd), (-0.1 * w, 0.1 * w), (h - 0.05, h - 0.038), LED),
        deco((hd - 0.002, hd), (-0.3 * w, 0.3 * w), (h - 0.12, h - 0.1), SPACE_GREY),
    ]
    return Design(tuple(parts), {"finish": finish.words})


@category(
    "computer_keyboard",
    "object",
    size=(0.14, 0.44, 0.03),
    low=(0.1, 0.28, 0.015),
    high=(0.22, 0.55, 0.05),
    mass=0.8,
    placement=OBJECT,
    description="a {finish} computer keyboard",
    variants=(None, (0.12, 0.36, 0.025)),
)
def computer_keyboard(size: Vec3, rng: Rng) -> Design:
    """A keyboard: a flat case with five rows of keys (visual) on top."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, (BLACK_PLASTIC, WHITE_PLASTIC, SPACE_GREY))
    keys = WHITE_PLASTIC if finish is SPACE_GREY else finish
    keys = GREY_PLASTIC if keys is WHITE_PLASTIC and finish is WHITE_PLASTIC else keys
    case_h = 0.6 * h
    parts: list[Part] = [block((-hd, hd), (-hw, hw), (0.0, case_h), finish)]
    # Five rows of key clusters (a long space bar in the front row).
    rows, groups = 5, max(3, round((w - 0.02) / 0.08))
    pitch_x, pitch_y = (d - 0.02) / rows, (w - 0.02) / groups
    for i in range(rows):
        x = -hd + 0.01 + i * pitch_x
        if i == rows - 1:
            spans = [(-0.25 * w, 0.15 * w)]
        else:
            spans = [
                (-hw + 0.01 + j * pitch_y, -hw + 0.01 + (j + 1) * pitch_y) for j in range(groups)
            ]
        for y0, y1 in spans:
            parts.append(deco((x + 0.002, x + pitch_x - 0.002), (y0 + 0.003, y1 - 0.003),
                              (case_h, h), keys))  # fmt: skip
    return Design(tuple(parts), {"finish": finish.words})


@category(
    "computer_mouse",
    "object",
    size=(0.12, 0.07, 0.04),
    low=(0.08, 0.05, 0.025),
    high=(0.15, 0.1, 0.055),
    mass=0.1,
    placement=OBJECT,
    description="a {finish} computer mouse",
    variants=(None, (0.1, 0.06, 0.035)),
)
def computer_mouse(size: Vec3, rng: Rng) -> Design:
    """A mouse: stepped shell (buttons to +X) with a scroll wheel."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, (BLACK_PLASTIC, WHITE_PLASTIC, SPACE_GREY))
    wheel_r = clamp(0.2 * h, 0.004, 0.008)
    parts: list[Part] = [
        block((-hd, hd), (-hw, hw), (0.0, 0.45 * h), finish),
        block((-hd + 0.08 * d, hd - 0.04 * d), (-0.4 * w, 0.4 * w), (0.45 * h, 0.8 * h), finish),
        block((-hd + 0.2 * d, hd - 0.15 * d), (-0.28 * w, 0.28 * w), (0.8 * h, h), finish),
        cyl_y(-0.004, 0.004, hd - 0.3 * d, h - wheel_r, wheel_r, RUBBER, collide=False),
    ]  # fmt: skip
    return Design(tuple(parts), {"finish": finish.words})
