"""Home tables and chests: console tables, vanity tables and trunks."""

from __future__ import annotations

from asset_pipeline.procedural.furniture import WHITE_CHAIR
from asset_pipeline.procedural.home_kit import (
    HANDLES,
    MARBLE,
    PROUD,
)
from asset_pipeline.procedural.kit import (
    BLACK_LEATHER,
    BLACK_METAL,
    BRASS,
    CASE_FINISHES,
    CHROME,
    LEATHER,
    NAVY_LACQUER,
    WOODS,
    Rng,
    block,
    chance,
    clamp,
    count_word,
    drawer_fronts,
    pick,
    square_legs,
    uniform,
)
from asset_pipeline.procedural.parts import Part, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.roles import fronts as tag_fronts
from asset_pipeline.procedural.roles import tagged


# --- home tables and chests -----------------------------------------------------------------------
@category(
    "console_table",
    "furniture",
    size=(0.35, 1.2, 0.8),
    low=(0.25, 0.7, 0.7),
    high=(0.5, 1.8, 0.95),
    mass=15.0,
    friction=0.6,
    description="a narrow {top} console table on {legs}{extra}",
    variants=(None, (0.3, 0.9, 0.75), (0.45, 1.6, 0.85)),
)
def console_table(size: Vec3, rng: Rng) -> Design:
    """A hall table: a top (a surface) on four legs or two panel ends, maybe an apron with
    drawers or a lower shelf (a surface)."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    top = pick(rng, (*CASE_FINISHES, MARBLE))
    leg_mat = (
        top if top is not MARBLE and chance(rng, 0.6) else pick(rng, (*WOODS, BLACK_METAL, BRASS))
    )
    t = uniform(rng, 0.025, 0.04)
    legs = pick(rng, ("square legs", "panel ends"))
    parts: list[Part] = tagged("top", [block((-hd, hd), (-hw, hw), (h - t, h), top, surface=True)])
    side = 0.04
    if legs == "square legs":
        parts += tagged("legs", square_legs(d, w, h - t, side, leg_mat, inset=0.015))
        y_in = hw - 0.015 - side
    else:
        for y in ((-hw + 0.02, -hw + 0.02 + side), (hw - 0.02 - side, hw - 0.02)):
            parts += tagged("legs", [block((-hd + 0.015, hd - 0.015), y, (0.0, h - t), leg_mat)])
        y_in = hw - 0.02 - side
    extra = pick(rng, ("drawers", "shelf", "both"))
    if extra in ("shelf", "both"):
        shelf = block((-hd + 0.02, hd - 0.02), (-y_in, y_in), (0.12, 0.14), leg_mat, surface=True)
        parts += tagged("shelves", [shelf])
    if extra in ("drawers", "both"):
        apron = (h - t - 0.12, h - t)
        fx = hd - 0.015 - PROUD
        apron_mat = top if top is not MARBLE else leg_mat
        parts += tagged("body", [block((-hd + 0.02, fx), (-y_in, y_in), apron, apron_mat)])
        cols = 1 if w < 1.0 else 2
        made = drawer_fronts(
            fx, (-y_in, y_in), apron, 1, cols, leg_mat, pick(rng, HANDLES), style="knob"
        )
        parts += tag_fronts(made, "knob")
    text = {
        "drawers": " with drawers in the apron",
        "shelf": " with a lower shelf",
        "both": " with apron drawers and a lower shelf",
    }[extra]
    words = {
        "top": top.words,
        "legs": legs if leg_mat is top else f"{leg_mat.words} {legs}",
        "extra": text,
    }
    return Design(tuple(parts), words)


@category(
    "vanity_table",
    "furniture",
    size=(0.45, 1.0, 0.76),
    low=(0.35, 0.7, 0.7),
    high=(0.6, 1.4, 0.82),
    mass=25.0,
    friction=0.6,
    description="a {body} dressing table with {drawers} drawers and {legs}",
    variants=(None, (0.4, 0.8, 0.75), (0.5, 1.2, 0.78)),
)
def vanity_table(size: Vec3, rng: Rng) -> Design:
    """A dressing table: a top (a surface) on legs with a drawer apron, or on one or two
    drawer pedestals around a knee space."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    body = pick(rng, (*CASE_FINISHES, WHITE_CHAIR))
    handle = pick(rng, HANDLES)
    t = uniform(rng, 0.02, 0.03)
    fx = hd - PROUD
    parts: list[Part] = tagged("top", [block((-hd, hd), (-hw, hw), (h - t, h), body, surface=True)])
    style = pick(rng, ("legs", "two pedestals", "one pedestal"))
    if style == "legs":
        parts += tagged("legs", square_legs(d, w, h - t, 0.04, body, inset=0.01))
        apron = (h - t - 0.14, h - t)
        parts += tagged("body", [block((-hd + 0.05, fx), (-hw + 0.05, hw - 0.05), apron, body)])
        made = drawer_fronts(fx, (-hw + 0.05, hw - 0.05), apron, 1, 3, body, handle, style="knob")
        parts += tag_fronts(made, "knob")
        count, legs = 3, "slender legs"
    else:
        ped = clamp(0.3 * w, 0.3, 0.4)
        sides = (-1.0, 1.0) if style == "two pedestals" else (1.0,)
        rows = 3
        for sign in sides:
            y = sorted((sign * hw, sign * (hw - ped)))
            parts += tagged("body", [block((-hd + 0.01, fx), (y[0], y[1]), (0.0, h - t), body)])
            made = drawer_fronts(fx, (y[0], y[1]), (0.05, h - t - 0.005), rows, 1, body, handle)
            parts += tag_fronts(made)
        if style == "one pedestal":
            panel = block((-hd + 0.01, hd - 0.01), (-hw, -hw + 0.03), (0.0, h - t), body)
            parts += tagged("legs", [panel])
        count = rows * len(sides)
        legs = "two drawer pedestals" if len(sides) == 2 else "a drawer pedestal"
    return Design(tuple(parts), {"body": body.words, "drawers": count_word(count), "legs": legs})


@category(
    "trunk",
    "furniture",
    size=(0.5, 1.0, 0.5),
    low=(0.35, 0.6, 0.3),
    high=(0.7, 1.4, 0.7),
    mass=20.0,
    friction=0.7,
    description="a {body} storage trunk with {metal} corners, {straps}and end handles",
    variants=(None, (0.45, 0.8, 0.45), (0.6, 1.2, 0.6)),
)
def trunk(size: Vec3, rng: Rng) -> Design:
    """A chest: body, a lid (a surface), metal corner caps, a lock plate, optional straps on
    the front and handles on both ends."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    body = pick(rng, (*WOODS, LEATHER, NAVY_LACQUER, BLACK_LEATHER))
    metal = pick(rng, (BRASS, BLACK_METAL, CHROME))
    hnd = 0.025
    lid_t = clamp(uniform(rng, 0.18, 0.25) * h, 0.06, 0.14)
    yb = hw - hnd
    feet = chance(rng, 0.4)
    base = 0.03 if feet else 0.0
    parts: list[Part] = []
    if feet:
        parts += square_legs(d - 0.01, 2 * yb - 0.01, base, 0.05, metal)
    parts.append(block((-hd, hd - 0.004), (-yb, yb), (base, h - lid_t - 0.004), body))
    parts.append(block((-hd, hd - 0.004), (-yb, yb), (h - lid_t, h), body, surface=True))
    parts.append(
        block((-hd, hd - 0.004), (-yb + 0.004, yb - 0.004), (h - lid_t - 0.004, h - lid_t), metal)
    )
    c = 0.04
    for y in ((-yb, -yb + c), (yb - c, yb)):
        for z in ((base, base + c), (h - lid_t - 0.004, h - lid_t - 0.004 + c)):
            parts.append(block((hd - 0.004, hd), y, z, metal, collide=False))
    zl = h - lid_t
    parts.append(
        block((hd - 0.004, hd), (-0.04, 0.04), (zl - 0.06, zl + 0.03), metal, collide=False)
    )
    straps = chance(rng, 0.5)
    if straps:
        strap = LEATHER if body is not LEATHER else BLACK_LEATHER
        for yc in (-0.3 * w, 0.3 * w):
            parts.append(
                block(
                    (hd - 0.003, hd),
                    (yc - 0.025, yc + 0.025),
                    (base, h - 0.01),
                    strap,
                    collide=False,
                )
            )
    zc = 0.5 * (base + zl)
    for y in ((-hw, -yb), (yb, hw)):
        parts.append(block((-0.08, 0.08), y, (zc - 0.015, zc + 0.015), metal))
    words = {
        "body": body.words,
        "metal": metal.words,
        "straps": "two leather straps " if straps else "",
    }
    return Design(tuple(parts), words)
