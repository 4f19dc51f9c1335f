"""Generators of the hearth, seating and nursery pieces of a home (front +X).

Sizes are bounding boxes (x = depth, y = width, z = height); fronts face +X. Like every
asset they have their lowest point at z = 0 and stand upright on a flat bottom.
"""

from __future__ import annotations

import math

from asset_pipeline.procedural.furniture import WHITE_CHAIR
from asset_pipeline.procedural.home_kit import (
    BRICK,
    MARBLE,
    SOOT,
)
from asset_pipeline.procedural.kit import (
    BARK,
    CONCRETE,
    FABRICS,
    LINEN,
    SAGE_LACQUER,
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
from asset_pipeline.procedural.parts import Part, RecipeMaterial, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.storage import DARK_STONE, STONE

SANDSTONE = RecipeMaterial("sandstone", (0.80, 0.70, 0.55, 1.0), 0.1, 0.1, "sandstone")
SLATE = RecipeMaterial("slate", (0.22, 0.23, 0.25, 1.0), 0.3, 0.3, "slate")
STONES = (BRICK, MARBLE, SANDSTONE, WHITE_LACQUER, CONCRETE)


# === hearth and seating =======================================================================
@category(
    "fireplace",
    "furniture",
    size=(0.5, 1.5, 1.1),
    low=(0.3, 0.9, 0.8),
    high=(0.7, 2.2, 1.5),
    mass=120.0,
    friction=0.8,
    description="a {surround} fireplace with a {mantel} mantel shelf, an open firebox "
    "and a {hearth} hearth{style}",
    variants=(None, (0.55, 1.8, 1.2), (0.4, 1.2, 1.0)),
)
def fireplace(size: Vec3, rng: Rng) -> Design:
    """A fireplace surround against the wall (-X): a hearth slab projecting at +X (a
    surface), two jambs and a frieze around an open firebox (no collider inside it, sooty
    lining at its back) and a mantel shelf on top (a surface)."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    surround = pick(rng, STONES)
    mantel = pick(rng, WOODS) if chance(rng, 0.5) else surround
    hearth = pick(rng, (SLATE, DARK_STONE, MARBLE, STONE))
    hearth_t = uniform(rng, 0.03, 0.06)
    proj = clamp(uniform(rng, 0.25, 0.35) * d, 0.1, 0.25)
    face = hd - proj
    back_t = clamp(0.15 * d, 0.04, 0.08)
    lining = 0.02
    shelf_t = uniform(rng, 0.04, 0.07)
    over = min(uniform(rng, 0.03, 0.07), proj - 0.02)
    body_top = h - shelf_t
    opening_w = clamp(uniform(rng, 0.45, 0.6) * w, 0.4, w - 0.3)
    opening_h = clamp(uniform(rng, 0.5, 0.6) * (body_top - hearth_t), 0.35, body_top - 0.2)
    ow, top = 0.5 * opening_w, hearth_t + opening_h
    x_in = -hd + back_t
    parts: list[Part] = [
        block((-hd, hd), (-hw, hw), (0.0, hearth_t), hearth, surface=(face, hd, -hw, hw)),
        block((-hd, x_in), (-hw, hw), (hearth_t, body_top), surround),
        block((x_in, face), (-hw, -ow), (hearth_t, body_top), surround),
        block((x_in, face), (ow, hw), (hearth_t, body_top), surround),
        block((x_in, face), (-ow, ow), (top, body_top), surround),
        block((x_in, x_in + lining), (-ow, ow), (hearth_t, top), SOOT),
        block((-hd, face + over), (-hw, hw), (body_top, h), mantel, surface=True),
    ]
    style = pick(rng, ("classic", "modern", "rustic"))
    if style == "classic":
        pw = clamp(0.35 * (hw - ow), 0.05, 0.15)
        for sign in (-1.0, 1.0):
            y = sorted((sign * (hw - 0.02), sign * (hw - 0.02 - pw)))
            parts.append(block((face, face + 0.015), (y[0], y[1]), (hearth_t, body_top), mantel))
    elif style == "rustic":
        parts.append(block((face, face + 0.015), (-ow - 0.04, ow + 0.04), (top, top + 0.1), BARK))
    words = {
        "surround": surround.words,
        "mantel": mantel.words,
        "hearth": hearth.words,
        "style": {"classic": " framed by pilasters", "rustic": " under a rough beam lintel"}.get(
            style, ""
        ),
    }
    return Design(tuple(parts), words)


@category(
    "rocking_chair",
    "furniture",
    size=(0.9, 0.65, 1.05),
    low=(0.7, 0.5, 0.85),
    high=(1.1, 0.8, 1.2),
    mass=12.0,
    friction=0.7,
    description="a {wood} rocking chair with a {back} back{arms}{cushion} on curved rockers",
    variants=(None, (0.8, 0.58, 0.95), (1.0, 0.7, 1.1)),
)
def rocking_chair(size: Vec3, rng: Rng) -> Design:
    """A rocking chair: two rockers along X (a flat middle under the chair, stepped ends
    curving up like an arc), legs, seat, a back at -X, optional arms and cushion."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    wood = pick(rng, (*WOODS, WHITE_CHAIR))
    rt, rh, ls = 0.028, 0.04, 0.035
    seat_d = clamp(uniform(rng, 0.46, 0.56) * d, 0.38, 0.52)
    xb, xf = -0.5 * seat_d, 0.5 * seat_d
    flat = xf + 0.02
    radius = uniform(rng, 1.0, 1.4)
    parts: list[Part] = []
    steps = 4
    for sign in (-1.0, 1.0):
        y = sorted((sign * hw, sign * (hw - rt)))
        parts.append(block((-flat, flat), (y[0], y[1]), (0.0, rh), wood))
        span = (hd - flat) / steps
        for i in range(steps):
            xa, xe = flat + i * span, flat + (i + 1) * span
            lift = radius - math.sqrt(radius**2 - (xa + 0.5 * span) ** 2)
            for x in ((xa, xe), (-xe, -xa)):
                parts.append(block(x, (y[0], y[1]), (lift, lift + rh), wood))
    seat_top = uniform(rng, 0.42, 0.47)
    seat_t = 0.03
    cushion = pick(rng, FABRICS) if chance(rng, 0.5) else None
    cushion_t = 0.04 if cushion else 0.0
    seat_z = seat_top - seat_t - cushion_t
    arms = chance(rng, 0.7)
    arm_z = seat_top + uniform(rng, 0.18, 0.24)
    for ys in ((-hw, -hw + ls), (hw - ls, hw)):
        parts.append(block((xf - ls, xf), ys, (rh, arm_z if arms else seat_z), wood))
        parts.append(block((xb, xb + ls), ys, (rh, h), wood))
    parts.append(block((xb, xf), (-hw, hw), (seat_z, seat_z + seat_t), wood))
    yi = hw - ls
    if cushion:
        parts.append(
            block(
                (xb + ls + 0.005, xf - 0.005),
                (-yi + 0.005, yi - 0.005),
                (seat_z + seat_t, seat_top),
                cushion,
                surface=True,
            )
        )
    else:
        parts[-1] = block(
            (xb, xf), (-hw, hw), (seat_z, seat_z + seat_t), wood, surface=(xb + ls, xf, -yi, yi)
        )
    if arms:
        for ys in ((-hw, -hw + ls + 0.01), (hw - ls - 0.01, hw)):
            parts.append(block((xb + ls, xf), ys, (arm_z - 0.03, arm_z), wood))
    back = pick(rng, ("spindle", "slat", "upholstered"))
    xr = (xb + 0.005, xb + ls - 0.005)
    low, top_rail = seat_top + 0.1, h - 0.07
    parts.append(block(xr, (-yi, yi), (top_rail, h - 0.01), wood))
    if back == "upholstered":
        parts.append(block(xr, (-yi, yi), (low, top_rail), cushion or pick(rng, FABRICS)))
    else:
        count, half = (5, 0.009) if back == "spindle" else (3, 0.03)
        pitch = 2.0 * yi / (count + 1)
        for i in range(1, count + 1):
            yc = -yi + i * pitch
            parts.append(block(xr, (yc - half, yc + half), (low, top_rail), wood))
    words = {
        "wood": wood.words,
        "back": back,
        "arms": " and arms" if arms else "",
        "cushion": f", a {cushion.words} seat cushion" if cushion else "",
    }
    return Design(tuple(parts), words)


@category(
    "crib",
    "furniture",
    size=(0.7, 1.3, 1.0),
    low=(0.55, 1.0, 0.8),
    high=(0.85, 1.5, 1.15),
    mass=25.0,
    friction=0.7,
    description="a {wood} baby crib with slatted sides{ends} and a mattress{drawer}",
    variants=(None, (0.65, 1.2, 0.9), (0.78, 1.45, 1.05)),
)
def crib(size: Vec3, rng: Rng) -> Design:
    """A crib: four corner posts, slatted long sides (±X) between rails, solid or slatted
    ends (±Y), a mattress on a base board (a surface), maybe a drawer below."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    wood = pick(rng, (*WOODS, WHITE_LACQUER, SAGE_LACQUER))
    ps, rail, slat = 0.045, 0.04, 0.012
    base_z = uniform(rng, 0.25, 0.35)
    mat_t = uniform(rng, 0.09, 0.12)
    parts: list[Part] = []
    for x in ((-hd, -hd + ps), (hd - ps, hd)):
        for y in ((-hw, -hw + ps), (hw - ps, hw)):
            parts.append(block(x, y, (0.0, h), wood))
    xi, yi = (-hd + ps, hd - ps), (-hw + ps, hw - ps)
    parts.append(block(xi, yi, (base_z - 0.02, base_z), wood))
    parts.append(
        block(
            (xi[0] + 0.005, xi[1] - 0.005),
            (yi[0] + 0.005, yi[1] - 0.005),
            (base_z, base_z + mat_t),
            pick(rng, (LINEN, WHITE_SHADE)),
            surface=True,
        )
    )
    low = base_z - 0.02 - rail

    def slats(axis: str, centre: float, span: tuple[float, float]) -> None:
        count = max(2, int((span[1] - span[0]) / 0.085))
        pitch = (span[1] - span[0]) / count
        for i in range(count):
            c = span[0] + (i + 0.5) * pitch
            a, b = (centre - slat, centre + slat), (c - 0.0125, c + 0.0125)
            x, y = (a, b) if axis == "x" else (b, a)
            parts.append(block(x, y, (low + rail, h - rail), wood))

    for cx in (-hd + 0.5 * ps, hd - 0.5 * ps):
        x = (cx - 0.015, cx + 0.015)
        parts.append(block(x, yi, (low, low + rail), wood))
        parts.append(block(x, yi, (h - rail, h), wood))
        slats("x", cx, yi)
    solid = chance(rng, 0.5)
    for cy in (-hw + 0.5 * ps, hw - 0.5 * ps):
        y = (cy - 0.015, cy + 0.015)
        if solid:
            parts.append(block(xi, y, (low, h - 0.02), wood))
        else:
            parts.append(block(xi, y, (low, low + rail), wood))
            parts.append(block(xi, y, (h - rail, h), wood))
            slats("y", cy, xi)
    drawer = low > 0.22 and chance(rng, 0.5)
    if drawer:
        parts.append(block(xi, yi, (0.04, low - 0.01), wood))
    words = {
        "wood": wood.words,
        "ends": " and solid end panels" if solid else " and ends",
        "drawer": " over a storage drawer" if drawer else "",
    }
    return Design(tuple(parts), words)
