"""Generators of home cabinets, sideboards, console tables and trunks (front +X).

Sizes are bounding boxes (x = depth, y = width, z = height); fronts face +X. Like every
asset they have their lowest point at z = 0 and stand upright on a flat bottom.
"""

from __future__ import annotations

from asset_pipeline.procedural.furniture import WHITE_CHAIR
from asset_pipeline.procedural.home_kit import (
    DARK_GREY,
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
    CLEAR_GLASS,
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
from asset_pipeline.procedural.parts import Material, Part, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.roles import fronts as tag_fronts
from asset_pipeline.procedural.roles import tagged
from asset_pipeline.procedural.storage import STONE


def _cabinet(
    size: Vec3,
    rng: Rng,
    *,
    body: Material,
    top: Material,
    top_t: float,
    base: str,
    fronts: list[tuple[tuple[float, float], int, int, str]],
    handle: Material,
    overhang: float = 0.0,
    front_mat: Material | None = None,
) -> list[Part]:
    """A carcass with a top board (a surface), a base and rows of fronts facing +X.

    ``fronts`` lists (z fraction range of the front area, rows, columns, handle style);
    ``base`` is ``plinth``, ``legs`` or ``none``.
    """
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    face = hd - overhang - PROUD
    base_h = {"none": 0.0, "plinth": uniform(rng, 0.05, 0.1), "legs": uniform(rng, 0.1, 0.18)}[base]
    parts: list[Part] = []
    if base == "plinth":
        parts += tagged("base", [block((-hd, face - 0.04), (-hw, hw), (0.0, base_h), body)])
    elif base == "legs":
        legs = square_legs(face + hd, w, base_h, 0.04, pick(rng, (BLACK_METAL, *WOODS)), 0.02)
        parts += tagged("legs", (leg.translated((0.5 * (face - hd), 0.0, 0.0)) for leg in legs))
    parts += tagged("body", [block((-hd, face), (-hw, hw), (base_h, h - top_t), body)])
    parts += tagged("top", [block((-hd, hd), (-hw, hw), (h - top_t, h), top, surface=True)])
    z0, z1 = base_h + 0.005, h - top_t - 0.005
    for (f0, f1), rows, cols, style in fronts:
        made = drawer_fronts(
            face,
            (-hw + 0.002, hw - 0.002),
            (z0 + f0 * (z1 - z0), z0 + f1 * (z1 - z0)),
            rows,
            cols,
            front_mat or body,
            handle,
            style=style,
        )
        parts += tag_fronts(made, style)
    return parts


# === cabinets, tables and racks ===============================================================
@category(
    "sideboard",
    "furniture",
    size=(0.45, 1.6, 0.85),
    low=(0.35, 0.9, 0.65),
    high=(0.6, 2.4, 1.0),
    mass=55.0,
    friction=0.6,
    description="a long low {body} sideboard with {doors} doors{drawers} and a {top} top",
    variants=(None, (0.42, 1.2, 0.8), (0.5, 2.0, 0.9)),
)
def sideboard(size: Vec3, rng: Rng) -> Design:
    """A sideboard: a row of doors, maybe under a row of drawers; the top is a surface."""
    cols = int(clamp(round(size[1] / 0.45), 2, 5))
    body = pick(rng, CASE_FINISHES)
    top = body if chance(rng, 0.6) else pick(rng, (*WOODS, STONE, MARBLE))
    drawers = chance(rng, 0.5)
    fronts = (
        [((0.0, 0.75), 1, cols, "door"), ((0.75, 1.0), 1, cols, "bar")]
        if drawers
        else [((0.0, 1.0), 1, cols, "door")]
    )
    parts = _cabinet(
        size,
        rng,
        body=body,
        top=top,
        top_t=uniform(rng, 0.025, 0.04),
        base=pick(rng, ("legs", "plinth")),
        fronts=fronts,
        handle=pick(rng, HANDLES),
    )
    words = {
        "body": body.words,
        "doors": count_word(cols),
        "drawers": " under a row of drawers" if drawers else "",
        "top": top.words,
    }
    return Design(tuple(parts), words)


@category(
    "tall_cabinet",
    "furniture",
    size=(0.45, 0.8, 2.0),
    low=(0.3, 0.4, 1.5),
    high=(0.65, 1.2, 2.4),
    mass=60.0,
    friction=0.6,
    description="a tall {body} storage cabinet with {doors} door{s}{drawers}",
    variants=(None, (0.4, 0.6, 1.8), (0.6, 1.0, 2.2)),
)
def tall_cabinet(size: Vec3, rng: Rng) -> Design:
    """A tall cupboard: one or two full-height doors, maybe over drawers; top a surface."""
    doors = 1 if size[1] < 0.55 else 2
    body = pick(rng, (*CASE_FINISHES, DARK_GREY))
    drawers = chance(rng, 0.4)
    fronts = (
        [((0.2, 1.0), 1, doors, "door"), ((0.0, 0.2), 2, 1, "bar")]
        if drawers
        else [((0.0, 1.0), 1, doors, "door")]
    )
    parts = _cabinet(
        size,
        rng,
        body=body,
        top=body,
        top_t=0.025,
        base=pick(rng, ("plinth", "legs", "none")),
        fronts=fronts,
        handle=pick(rng, HANDLES),
    )
    words = {
        "body": body.words,
        "doors": count_word(doors),
        "s": "s" if doors > 1 else "",
        "drawers": " over two drawers" if drawers else "",
    }
    return Design(tuple(parts), words)


@category(
    "display_cabinet",
    "furniture",
    size=(0.4, 0.9, 1.8),
    low=(0.3, 0.5, 1.4),
    high=(0.55, 1.4, 2.2),
    mass=55.0,
    friction=0.6,
    description="a tall {body} display cabinet with glass doors and {levels} glass shelves{base}",
    variants=(None, (0.35, 0.7, 1.6), (0.45, 1.2, 2.0)),
)
def display_cabinet(size: Vec3, rng: Rng) -> Design:
    """A vitrine: a carcass with glass shelves (surfaces) behind framed glass doors, maybe
    over a closed cupboard; the top is a surface."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    body = pick(rng, (*CASE_FINISHES, BLACK_METAL))
    t, door_t = 0.02, 0.022
    face = hd - door_t
    base_h = uniform(rng, 0.06, 0.1)
    cupboard = chance(rng, 0.5)
    glass_z0 = base_h + (uniform(rng, 0.5, 0.7) if cupboard else 0.0)
    parts: list[Part] = [
        block((-hd, face), (-hw, hw), (0.0, base_h), body),
        block((-hd, hd), (-hw, hw), (h - t, h), body, surface=True),
        block((-hd, face), (-hw, -hw + t), (base_h, h - t), body),
        block((-hd, face), (hw - t, hw), (base_h, h - t), body),
        block((-hd, -hd + 0.012), (-hw + t, hw - t), (base_h, h - t), body),
    ]
    if cupboard:
        fc = hd - PROUD
        parts.append(block((-hd + 0.012, fc), (-hw + t, hw - t), (base_h, glass_z0), body))
        parts += drawer_fronts(
            fc,
            (-hw + t, hw - t),
            (base_h, glass_z0),
            1,
            2 if w > 0.6 else 1,
            body,
            pick(rng, HANDLES),
            style="door",
        )
    else:
        parts.append(
            block((-hd + 0.012, face), (-hw + t, hw - t), (base_h, base_h + t), body, surface=True)
        )
    z0 = glass_z0 + (t if not cupboard else 0.0)
    levels = max(2, round((h - t - z0) / 0.35))
    pitch = (h - t - z0) / levels
    for i in range(1, levels):
        z = z0 + i * pitch
        parts.append(
            block(
                (-hd + 0.012, face - 0.005),
                (-hw + t, hw - t),
                (z - 0.008, z),
                CLEAR_GLASS,
                surface=True,
            )
        )
    doors = 2 if w > 0.6 else 1
    dw = w / doors
    f = 0.035
    for j in range(doors):
        y0, y1 = -hw + j * dw, -hw + (j + 1) * dw
        z0d, z1d = glass_z0, h - t
        parts += [
            block((face, hd), (y0, y1), (z0d, z0d + f), body),
            block((face, hd), (y0, y1), (z1d - f, z1d), body),
            block((face, hd), (y0, y0 + f), (z0d + f, z1d - f), body),
            block((face, hd), (y1 - f, y1), (z0d + f, z1d - f), body),
            block((face + 0.006, hd - 0.006), (y0 + f, y1 - f), (z0d + f, z1d - f), CLEAR_GLASS),
        ]
    words = {
        "body": body.words,
        "levels": count_word(levels - 1 + (0 if cupboard else 1)),
        "base": " over a closed cupboard" if cupboard else "",
    }
    return Design(tuple(parts), words)


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
