"""Generators of shop fittings: clothes racks, gondolas, counters, cases (front +X).

Every generator fills exactly ``[-d/2, d/2] x [-w/2, w/2] x [0, h]`` (x = depth, y = width).
"""

from __future__ import annotations

from asset_pipeline.procedural.kit import (
    ALUMINIUM,
    BLACK_LEATHER,
    BLACK_METAL,
    BLACK_PLASTIC,
    BRASS,
    CHROME,
    CLEAR_GLASS,
    FABRICS,
    GREY_LAMINATE,
    LINEN,
    OAK,
    STEEL,
    WALNUT,
    WHITE_LACQUER,
    WHITE_PLASTIC,
    WOODS,
    Rng,
    block,
    clamp,
    pick,
    uniform,
)
from asset_pipeline.procedural.leisure_kit import (
    BLUE_PAINT,
    RED_PAINT,
    RUBBER,
    YELLOW_PAINT,
    rod,
)
from asset_pipeline.procedural.parts import Part, RecipeMaterial, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.work_kit import (
    NUMBER_WORDS,
    OFFICE_GREY,
)

# --- shops ------------------------------------------------------------------------------------
GARMENTS = (
    *FABRICS,
    LINEN,
    BLACK_LEATHER,
    RecipeMaterial("denim", (0.22, 0.32, 0.50, 1.0), 0.05, 0.1, "denim"),
)


@category(
    "clothes_rack",
    "furniture",
    size=(0.5, 1.5, 1.6),
    low=(0.4, 0.9, 1.2),
    high=(0.7, 2.0, 1.9),
    mass=18.0,
    friction=0.7,
    description="a {metal} clothes rack on casters with {count} garments on hangers",
    variants=(None, (0.55, 1.8, 1.7), (0.45, 1.0, 1.4)),
)
def clothes_rack(size: Vec3, rng: Rng) -> Design:
    """Two feet along X at the ends, two uprights, a top rail along Y and hanging garments."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    metal = pick(rng, (CHROME, BLACK_METAL, BRASS))
    post = 0.03
    rail_z = h - 0.03
    parts: list[Part] = []
    for y in ((-hw, -hw + post), (hw - post, hw)):
        parts.append(block((-hd, hd), y, (0.03, 0.06), metal))
        parts.append(block((-0.5 * post, 0.5 * post), y, (0.06, h), metal))
        for x in (-hd + 0.03, hd - 0.03):
            yc = 0.5 * (y[0] + y[1])
            parts.append(block((x - 0.03, x + 0.03), (yc - 0.015, yc + 0.015), (0.0, 0.03), RUBBER))
    parts.append(rod("y", -hw + post, hw - post, 0.0, rail_z, 0.014, metal))
    span = w - 2 * post - 0.08
    count = int(clamp(span // uniform(rng, 0.07, 0.12), 3, 20))
    pitch = span / count
    for k in range(count):
        yc = -hw + post + 0.04 + (k + 0.5) * pitch
        t = clamp(uniform(rng, 0.03, 0.05), 0.02, 0.8 * pitch)
        length = clamp(uniform(rng, 0.6, 1.0), 0.4, rail_z - 0.3)
        gw = min(uniform(rng, 0.38, 0.46), d - 0.02)
        parts.append(block((-0.005, 0.005), (yc - 0.003, yc + 0.003), (rail_z - 0.05, h), metal))
        parts.append(
            block(
                (-0.5 * gw, 0.5 * gw),
                (yc - 0.004, yc + 0.004),
                (rail_z - 0.08, rail_z - 0.05),
                metal,
            )
        )
        parts.append(
            block(
                (-0.5 * gw, 0.5 * gw),
                (yc - 0.5 * t, yc + 0.5 * t),
                (rail_z - 0.08 - length, rail_z - 0.08),
                pick(rng, GARMENTS),
            )
        )
    return Design(tuple(parts), {"metal": metal.words, "count": str(count)})


@category(
    "shelving_gondola",
    "furniture",
    size=(0.9, 1.2, 1.6),
    low=(0.6, 0.9, 1.2),
    high=(1.1, 2.0, 2.2),
    mass=80.0,
    friction=0.7,
    description="a double-sided {finish} shop shelving gondola with {levels} shelves on each "
    "side and price strips",
    variants=(None, (0.9, 1.8, 1.8), (0.7, 1.0, 1.4)),
)
def shelving_gondola(size: Vec3, rng: Rng) -> Design:
    """A central pegboard spine with uprights at the ends, base decks and shelves on both
    sides (every shelf a surface), price strips on the shelf fronts."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, (WHITE_LACQUER, OFFICE_GREY, BLACK_METAL))
    strip = pick(rng, (YELLOW_PAINT, WHITE_PLASTIC, RED_PAINT))
    spine = 0.03
    post = 0.04
    base_z = 0.12
    levels = int(clamp(round((h - 0.45) / 0.38), 2, 5))
    pitch = (h - 0.25 - base_z) / levels
    parts: list[Part] = [
        block((-0.5 * spine, 0.5 * spine), (-hw, hw), (0.0, h), finish),
    ]
    for sign in (-1.0, 1.0):
        x = tuple(sorted((sign * 0.5 * spine, sign * hd)))
        parts.append(block(x, (-hw + post, hw - post), (0.0, base_z), finish, surface=True))
        for k in range(1, levels + 1):
            z = base_z + k * pitch
            depth = (hd - 0.5 * spine) * (0.85 if k == levels else 1.0)
            xs = tuple(sorted((sign * 0.5 * spine, sign * (0.5 * spine + depth))))
            parts.append(block(xs, (-hw + post, hw - post), (z - 0.025, z), finish, surface=True))
            xf = tuple(sorted((sign * (0.5 * spine + depth), sign * (0.5 * spine + depth - 0.01))))
            parts.append(block(xf, (-hw + post, hw - post), (z - 0.06, z), strip))
    for y in ((-hw, -hw + post), (hw - post, hw)):
        parts.append(block((-0.06, 0.06), y, (base_z, h), finish))
    return Design(tuple(parts), {"finish": finish.words, "levels": NUMBER_WORDS[levels]})


def _counter(
    size: Vec3, rng: Rng, top: RecipeMaterial, body: RecipeMaterial, staff_shelves: bool
) -> tuple[list[Part], float]:
    """A counter: top (a surface) overhanging the customer side (+X), a plinth, a front panel
    and, on the staff side (-X), open shelves (surfaces) or a closed back."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    t = 0.04
    over = 0.05
    plinth = 0.1
    parts: list[Part] = [
        block((-hd, hd), (-hw, hw), (h - t, h), top, surface=True),
        block((hd - over - 0.03, hd - over), (-hw, hw), (plinth, h - t), body),
        block(
            (-hd + 0.05, hd - over - 0.05), (-hw + 0.02, hw - 0.02), (0.0, plinth), BLACK_PLASTIC
        ),
        block((-hd, -hd + 0.03), (-hw, hw), (plinth, h - t), body)
        if not staff_shelves
        else block((-hd, hd - over - 0.03), (-hw, -hw + 0.03), (plinth, h - t), body),
        block((-hd, hd - over - 0.03), (hw - 0.03, hw), (plinth, h - t), body),
    ]
    inner_x = (-hd, hd - over - 0.03)
    if staff_shelves:
        parts.append(
            block(inner_x, (-hw + 0.03, hw - 0.03), (plinth - 0.02, plinth), body, surface=True)
        )
        z = plinth + 0.5 * (h - t - plinth)
        parts.append(block(inner_x, (-hw + 0.03, hw - 0.03), (z - 0.02, z), body, surface=True))
    else:
        parts.append(
            block((inner_x[0] + 0.03, inner_x[1]), (-hw + 0.03, -hw + 0.06), (plinth, h - t), body)
        )
        parts.append(
            block((-hd + 0.03, hd - over - 0.03), (-hw, hw), (plinth - 0.02, plinth), body)
        )
    return parts, h - t


@category(
    "checkout_counter",
    "furniture",
    size=(0.8, 1.8, 0.9),
    low=(0.6, 1.2, 0.8),
    high=(1.0, 2.6, 1.05),
    mass=120.0,
    friction=0.7,
    description="a {body} checkout counter with a conveyor belt, a glass scanner plate and a "
    "{top} bagging area",
    variants=(None, (0.9, 2.2, 0.9), (0.7, 1.4, 0.85)),
)
def checkout_counter(size: Vec3, rng: Rng) -> Design:
    """A counter whose top is a black belt (-Y), a glass scanner plate and a bagging shelf."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    body = pick(rng, (WHITE_LACQUER, OFFICE_GREY, WALNUT, BLUE_PAINT))
    top = pick(rng, (STEEL, GREY_LAMINATE))
    parts, _ = _counter(size, rng, top, body, staff_shelves=False)
    belt_y = (-hw + 0.04, -hw + 0.55 * w)
    scan_y = (belt_y[1] + 0.03, belt_y[1] + 0.03 + min(0.3, 0.15 * w))
    parts.append(block((-hd + 0.08, hd - 0.08), belt_y, (h - 0.0005, h), RUBBER, collide=False))
    parts.append(
        block((-hd + 0.15, hd - 0.15), scan_y, (h - 0.0005, h), CLEAR_GLASS, collide=False)
    )
    parts.append(
        block(
            (-hd + 0.02, hd - 0.02),
            (belt_y[0] - 0.02, belt_y[0]),
            (h - 0.0005, h),
            BLACK_METAL,
            collide=False,
        )
    )
    return Design(tuple(parts), {"body": body.words, "top": top.words})


@category(
    "shop_counter",
    "furniture",
    size=(0.6, 1.6, 0.95),
    low=(0.5, 1.0, 0.85),
    high=(0.8, 2.6, 1.1),
    mass=70.0,
    friction=0.7,
    description="a {body} shop counter with a {top} worktop and open shelves on the staff side",
    variants=(None, (0.7, 2.4, 0.95), (0.55, 1.2, 0.9)),
)
def shop_counter(size: Vec3, rng: Rng) -> Design:
    """A counter with a panelled customer front and open shelves behind (all surfaces)."""
    d, w, _ = size
    hd, hw = 0.5 * d, 0.5 * w
    body = pick(rng, (*WOODS, WHITE_LACQUER, BLACK_METAL))
    top = pick(rng, (OAK, WALNUT, GREY_LAMINATE, WHITE_LACQUER))
    parts, z_top = _counter(size, rng, top, body, staff_shelves=True)
    panels = max(2, round(w / 0.5))
    x = (hd - 0.05, hd - 0.04)
    for k in range(panels):
        y0 = -hw + 0.05 + k * (w - 0.1) / panels
        parts.append(
            block(x, (y0 + 0.02, y0 + (w - 0.1) / panels - 0.02), (0.18, z_top - 0.08), body)
        )
    return Design(tuple(parts), {"body": body.words, "top": top.words})


@category(
    "display_case",
    "furniture",
    size=(0.6, 1.2, 1.0),
    low=(0.45, 0.8, 0.85),
    high=(0.8, 2.0, 1.2),
    mass=80.0,
    friction=0.7,
    description="a glass-topped {frame} display case with a {base} base and a glass shelf",
    variants=(None, (0.6, 1.8, 1.0), (0.5, 0.9, 0.95)),
)
def display_case(size: Vec3, rng: Rng) -> Design:
    """A base cabinet, a glass box (walls, a top that is a surface) with a deck and a glass
    shelf inside (surfaces), metal corner posts."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    frame = pick(rng, (ALUMINIUM, BLACK_METAL, BRASS))
    base = pick(rng, (*WOODS[:2], WHITE_LACQUER, PIANO_BLACK_LOCAL))
    base_z = clamp(uniform(rng, 0.25, 0.4), 0.2, h - 0.5)
    g = 0.01
    post = 0.025
    parts: list[Part] = [
        block((-hd, hd), (-hw, hw), (0.0, base_z), base),
        block(
            (-hd + post, hd - post),
            (-hw + post, hw - post),
            (base_z, base_z + 0.01),
            LINEN,
            surface=True,
        ),
        block((-hd, hd), (-hw, hw), (h - g, h), CLEAR_GLASS, surface=True),
        block((hd - g, hd), (-hw + post, hw - post), (base_z, h - g), CLEAR_GLASS),
        block((-hd, -hd + g), (-hw + post, hw - post), (base_z, h - g), CLEAR_GLASS),
        block((-hd + post, hd - post), (-hw, -hw + g), (base_z, h - g), CLEAR_GLASS),
        block((-hd + post, hd - post), (hw - g, hw), (base_z, h - g), CLEAR_GLASS),
    ]
    for x in ((-hd, -hd + post), (hd - post, hd)):
        for y in ((-hw, -hw + post), (hw - post, hw)):
            parts.append(block(x, y, (base_z, h - g), frame))
    shelf_z = base_z + 0.5 * (h - g - base_z)
    parts.append(
        block(
            (-hd + post, hd - post),
            (-hw + post, hw - post),
            (shelf_z - g, shelf_z),
            CLEAR_GLASS,
            surface=True,
        )
    )
    return Design(tuple(parts), {"frame": frame.words, "base": base.words})


PIANO_BLACK_LOCAL = RecipeMaterial("gloss_black", (0.04, 0.04, 0.04, 1.0), 0.9, 0.9, "gloss black")
