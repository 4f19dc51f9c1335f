"""Generators of home cabinets, sideboards, console tables and trunks (front +X).

Sizes are bounding boxes (x = depth, y = width, z = height); fronts face +X. Like every
asset they have their lowest point at z = 0 and stand upright on a flat bottom.
"""

from __future__ import annotations

from asset_pipeline.procedural.home_kit import (
    DARK_GREY,
    HANDLES,
    MARBLE,
    PROUD,
)
from asset_pipeline.procedural.kit import (
    BLACK_METAL,
    CASE_FINISHES,
    CLEAR_GLASS,
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
from asset_pipeline.procedural.parts import Part, RecipeMaterial, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.roles import fronts as tag_fronts
from asset_pipeline.procedural.roles import tagged
from asset_pipeline.procedural.storage import STONE


def _cabinet(
    size: Vec3,
    rng: Rng,
    *,
    body: RecipeMaterial,
    top: RecipeMaterial,
    top_t: float,
    base: str,
    fronts: list[tuple[tuple[float, float], int, int, str]],
    handle: RecipeMaterial,
    overhang: float = 0.0,
    front_mat: RecipeMaterial | None = None,
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
