"""Nursery pieces and soft seating: changing tables, toy boxes, ottomans, benches, chaise
longues, bean bags and pet beds."""

from __future__ import annotations

from asset_pipeline.procedural.home_kit import (
    HANDLES,
    PROUD,
    ROUND,
    SAGE_TOY,
    SOOT,
)
from asset_pipeline.procedural.kit import (
    BEIGE_FABRIC,
    BLACK_LEATHER,
    BLACK_METAL,
    BLUE_FABRIC,
    BRASS,
    FABRICS,
    GREEN_FABRIC,
    LEATHER,
    LINEN,
    PINE,
    RUG_BEIGE,
    RUG_RED,
    SAGE_LACQUER,
    TOY_BLUE,
    TOYS,
    WHITE_LACQUER,
    WOODS,
    Rng,
    block,
    chance,
    clamp,
    drawer_fronts,
    pick,
    round_legs,
    square_legs,
    uniform,
)
from asset_pipeline.procedural.parts import Part, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.round_parts import Cylinder, Lathe


# --- nursery pieces and soft seating --------------------------------------------------------------
@category(
    "changing_table",
    "furniture",
    size=(0.55, 0.9, 0.95),
    low=(0.45, 0.7, 0.85),
    high=(0.7, 1.2, 1.05),
    mass=30.0,
    friction=0.7,
    description="a {body} baby changing table with a {pad} changing pad and {storage}",
    variants=(None, (0.5, 0.8, 0.9), (0.65, 1.1, 1.0)),
)
def changing_table(size: Vec3, rng: Rng) -> Design:
    """A changing table: side panels, open shelves or drawers (surfaces on the shelves), a
    top with low guard rails at the back and sides and a padded mat between them."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    body = pick(rng, (WHITE_LACQUER, *WOODS, SAGE_LACQUER))
    pad = pick(rng, (LINEN, BLUE_FABRIC, GREEN_FABRIC, BEIGE_FABRIC))
    t = 0.02
    rail_h = uniform(rng, 0.08, 0.1)
    top_z = h - rail_h
    parts: list[Part] = [
        block((-hd, hd), (-hw, -hw + t), (0.0, h), body),
        block((-hd, hd), (hw - t, hw), (0.0, h), body),
        block((-hd, -hd + t), (-hw + t, hw - t), (0.0, h), body),
        block((-hd + t, hd), (-hw + t, hw - t), (top_z - t, top_z), body),
        block(
            (-hd + t + 0.005, hd - 0.005),
            (-hw + t + 0.005, hw - t - 0.005),
            (top_z, top_z + 0.05),
            pad,
            surface=True,
        ),
    ]
    storage = pick(rng, ("shelves", "drawers", "mixed"))
    kick = 0.05
    span = top_z - t - kick
    if storage == "drawers":
        parts.append(block((-hd + t, hd - PROUD), (-hw + t, hw - t), (kick, top_z - t), body))
        parts += drawer_fronts(
            hd - PROUD, (-hw + t, hw - t), (kick, top_z - t), 3, 1, body, pick(rng, HANDLES), 0.004
        )
        parts.append(block((-hd + t, hd - 0.02), (-hw + t, hw - t), (0.0, kick), body))
        text = "three drawers"
    else:
        levels = 3 if storage == "shelves" else 2
        for i in range(levels):
            z = kick + i * span / levels
            parts.append(block((-hd + t, hd), (-hw + t, hw - t), (z - t, z), body, surface=True))
        if storage == "mixed":
            z0 = kick + 2 * span / 3
            parts.append(block((-hd + t, hd - PROUD), (-hw + t, hw - t), (z0, top_z - t), body))
            parts += drawer_fronts(
                hd - PROUD, (-hw + t, hw - t), (z0, top_z - t), 1, 2, body, pick(rng, HANDLES)
            )
        text = "open shelves" if storage == "shelves" else "two drawers above open shelves"
    return Design(tuple(parts), {"body": body.words, "pad": pad.words, "storage": text})


@category(
    "toy_box",
    "furniture",
    size=(0.45, 0.8, 0.5),
    low=(0.3, 0.5, 0.35),
    high=(0.6, 1.1, 0.65),
    mass=12.0,
    friction=0.7,
    description="a {body} toy box with a {lid} lid{detail}",
    variants=(None, (0.4, 0.65, 0.45), (0.55, 1.0, 0.6)),
)
def toy_box(size: Vec3, rng: Rng) -> Design:
    """A toy chest: a box on a plinth or feet, a lid (a surface) overhanging it slightly,
    handle grips on the ends and a painted panel on the front."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    body = pick(rng, (*TOYS, WHITE_LACQUER, PINE, SAGE_TOY))
    lid = pick(rng, (*TOYS, WHITE_LACQUER, PINE))
    lid_t = uniform(rng, 0.025, 0.04)
    o = 0.015
    style = pick(rng, ("plinth", "feet", "cushion"))
    base_h = 0.04
    parts: list[Part] = []
    if style == "feet":
        parts += square_legs(d - 2 * o, w - 2 * o, base_h, 0.05, body)
    else:
        parts.append(block((-hd + o + 0.01, hd - o - 0.01), (-hw + o, hw - o), (0.0, base_h), body))
    top = h - lid_t - (0.05 if style == "cushion" else 0.0)
    parts.append(block((-hd + o, hd - o), (-hw + o, hw - o), (base_h, top), body))
    parts.append(block((-hd, hd), (-hw, hw), (top, top + lid_t), lid, surface=style != "cushion"))
    if style == "cushion":
        parts.append(
            block(
                (-hd + 0.01, hd - 0.01),
                (-hw + 0.01, hw - 0.01),
                (h - 0.05, h),
                pick(rng, FABRICS),
                surface=True,
            )
        )
    accent = pick(rng, [m for m in (*TOYS, WHITE_LACQUER) if m is not body])
    zc = 0.5 * (base_h + top)
    hz = 0.3 * (top - base_h)
    parts.append(
        block(
            (hd - o, hd - o + 0.004),
            (-0.35 * w, 0.35 * w),
            (zc - hz, zc + hz),
            accent,
            collide=False,
        )
    )
    for sign in (-1.0, 1.0):
        y = sorted((sign * (hw - o), sign * (hw - o + 0.004)))
        parts.append(
            block(
                (-0.12 * d, 0.12 * d), (y[0], y[1]), (top - 0.09, top - 0.05), SOOT, collide=False
            )
        )
    words = {
        "body": body.words,
        "lid": lid.words,
        "detail": {"feet": " on short feet", "cushion": " with a seat cushion on top"}.get(
            style, f" and a {accent.words} front panel"
        ),
    }
    return Design(tuple(parts), words)


@category(
    "ottoman",
    "furniture",
    size=(0.6, 0.6, 0.42),
    low=(0.4, 0.4, 0.3),
    high=(1.0, 1.2, 0.5),
    mass=8.0,
    friction=0.9,
    description="a {shape} {fabric} upholstered ottoman{base}",
    variants=(None, (0.45, 0.45, 0.4), (0.7, 0.9, 0.42)),
)
def ottoman(size: Vec3, rng: Rng) -> Design:
    """An ottoman: a padded box on legs or a plinth, or (square footprint) a round pouf; the
    padded top is a surface."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    fabric = pick(rng, (*FABRICS, LEATHER, BLACK_LEATHER))
    if abs(d - w) < 1e-3 and chance(rng, 0.4):
        band = pick(rng, (BRASS, BLACK_METAL, fabric))
        parts: list[Part] = [
            Cylinder((0.0, 0.0, 0.015), 0.45 * d, 0.015, band),
            Cylinder((0.0, 0.0, 0.5 * (h + 0.03)), hd, 0.5 * (h - 0.03), fabric, surface=True),
        ]
        return Design(tuple(parts), {"shape": "round", "fabric": fabric.words, "base": ""})
    base = pick(rng, ("legs", "plinth", "skirt"))
    base_h = {"legs": uniform(rng, 0.06, 0.14), "plinth": 0.04, "skirt": 0.0}[base]
    parts = []
    if base == "legs":
        parts += round_legs(d, w, base_h, 0.018, pick(rng, (*WOODS, BRASS, BLACK_METAL)), 0.05)
    elif base == "plinth":
        parts.append(
            block((-hd + 0.03, hd - 0.03), (-hw + 0.03, hw - 0.03), (0.0, base_h), pick(rng, WOODS))
        )
    top_t = uniform(rng, 0.06, 0.1)
    parts.append(block((-hd, hd), (-hw, hw), (base_h, h - top_t), fabric))
    parts.append(block((-hd, hd), (-hw, hw), (h - top_t, h), fabric, surface=True))
    words = {
        "shape": "square" if abs(d - w) < 1e-3 else "rectangular",
        "fabric": fabric.words,
        "base": {"legs": " on short legs", "plinth": " on a wooden plinth"}.get(base, ""),
    }
    return Design(tuple(parts), words)


@category(
    "bench",
    "furniture",
    size=(0.4, 1.2, 0.46),
    low=(0.28, 0.7, 0.38),
    high=(0.55, 2.2, 0.55),
    mass=12.0,
    friction=0.7,
    description="a {wood} bench {style}",
    variants=(None, (0.35, 0.9, 0.45), (0.4, 1.8, 0.46)),
)
def bench(size: Vec3, rng: Rng) -> Design:
    """A bench: a seat board (a surface) on four legs, on two panel ends, over a lower
    shelf (a surface), or with an upholstered pad (a surface)."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    wood = pick(rng, (*WOODS, WHITE_LACQUER, BLACK_METAL))
    style = pick(rng, ("legs", "panels", "shelf", "pad"))
    pad = pick(rng, FABRICS) if style == "pad" else None
    top = h - (0.05 if pad else 0.0)
    t = uniform(rng, 0.03, 0.045)
    parts: list[Part] = [block((-hd, hd), (-hw, hw), (top - t, top), wood, surface=pad is None)]
    if style == "legs" or style == "pad":
        parts += square_legs(d, w, top - t, 0.045, wood, inset=0.03)
        parts.append(block((-0.02, 0.02), (-hw + 0.075, hw - 0.075), (0.12, 0.16), wood))
    else:
        pt = 0.035
        for y in ((-hw + 0.04, -hw + 0.04 + pt), (hw - 0.04 - pt, hw - 0.04)):
            parts.append(block((-hd + 0.02, hd - 0.02), y, (0.0, top - t), wood))
        if style == "shelf":
            y_in = hw - 0.04 - pt
            parts.append(
                block((-hd + 0.02, hd - 0.02), (-y_in, y_in), (0.1, 0.12), wood, surface=True)
            )
    if pad:
        parts.append(
            block((-hd + 0.01, hd - 0.01), (-hw + 0.01, hw - 0.01), (top, h), pad, surface=True)
        )
    words = {
        "wood": wood.words,
        "style": {
            "legs": "on four square legs",
            "panels": "on two solid panel ends",
            "shelf": "with a lower shelf for shoes",
            "pad": f"with a {pad.words if pad else ''} seat pad",
        }[style],
    }
    return Design(tuple(parts), words)


@category(
    "chaise_longue",
    "furniture",
    size=(0.7, 1.6, 0.85),
    low=(0.55, 1.3, 0.65),
    high=(0.9, 2.0, 1.0),
    mass=35.0,
    friction=0.9,
    description="a {fabric} chaise longue with a raised sloping back{rail} on {legs}",
    variants=(None, (0.65, 1.45, 0.8), (0.85, 1.9, 0.9)),
)
def chaise_longue(size: Vec3, rng: Rng) -> Design:
    """A chaise longue: a long seat along Y (a surface) and a backrest at -Y rising in
    steps (a sloping back), on legs or a plinth, maybe a low back rail along -X."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    fabric = pick(rng, (*FABRICS, LEATHER))
    legs = pick(rng, ("wooden legs", "metal legs", "a plinth"))
    base_h = 0.04 if legs == "a plinth" else uniform(rng, 0.1, 0.16)
    parts: list[Part] = []
    if legs == "wooden legs":
        parts += square_legs(d, w, base_h, 0.045, pick(rng, WOODS), inset=0.03)
    elif legs == "metal legs":
        parts += round_legs(d, w, base_h, 0.018, BLACK_METAL, inset=0.05)
    else:
        parts.append(
            block((-hd + 0.03, hd - 0.03), (-hw + 0.03, hw - 0.03), (0.0, base_h), pick(rng, WOODS))
        )
    seat_top = uniform(rng, 0.4, 0.46)
    cushion = 0.1
    seat_z = seat_top - cushion
    parts.append(block((-hd, hd), (-hw, hw), (base_h, seat_z), fabric))
    back_len = clamp(uniform(rng, 0.35, 0.45) * w, 0.45, 0.8)
    steps = 5
    for i in range(steps):
        y0 = -hw + i * back_len / steps
        ztop = h - i * (h - seat_top - 0.1) / steps
        parts.append(block((-hd, hd), (y0, y0 + back_len / steps), (seat_z, ztop), fabric))
    rail = chance(rng, 0.5)
    x0 = -hd + (0.1 if rail else 0.0)
    if rail:
        parts.append(block((-hd, x0), (-hw + back_len, hw), (seat_z, seat_top + 0.18), fabric))
    parts.append(block((x0, hd), (-hw + back_len, hw), (seat_z, seat_top), fabric, surface=True))
    words = {
        "fabric": fabric.words,
        "rail": " and a low side rail" if rail else "",
        "legs": legs,
    }
    return Design(tuple(parts), words)


@category(
    "bean_bag",
    "furniture",
    size=(0.9, 0.9, 0.7),
    low=(0.6, 0.6, 0.45),
    high=(1.3, 1.3, 0.9),
    mass=6.0,
    friction=0.9,
    yx_ratio=ROUND,
    description="a soft {fabric} {shape} bean bag seat",
    variants=(None, (0.75, 0.75, 0.6), (1.1, 1.1, 0.8)),
)
def bean_bag(size: Vec3, rng: Rng) -> Design:
    """A bean bag: a slumped surface of revolution with a flat bottom."""
    d, _, h = size
    r = 0.5 * d
    fabric = pick(rng, (*FABRICS, BLACK_LEATHER, RUG_RED, TOY_BLUE))
    shape = pick(rng, ("teardrop", "round", "pear"))
    profile = {
        "teardrop": ((0.7, 0.0), (0.95, 0.15), (1.0, 0.35), (0.85, 0.65), (0.5, 0.9), (0.25, 1.0)),
        "round": ((0.75, 0.0), (0.97, 0.2), (1.0, 0.45), (0.9, 0.75), (0.55, 1.0)),
        "pear": ((0.8, 0.0), (1.0, 0.25), (0.92, 0.5), (0.6, 0.8), (0.35, 1.0)),
    }[shape]
    outer = tuple((f * r, z * h) for f, z in profile)
    return Design(
        (Lathe((0.0, 0.0, 0.0), outer, fabric),), {"fabric": fabric.words, "shape": shape}
    )


@category(
    "pet_bed",
    "furniture",
    size=(0.6, 0.8, 0.2),
    low=(0.4, 0.5, 0.1),
    high=(0.9, 1.2, 0.3),
    mass=2.5,
    friction=0.9,
    description="a cushioned {fabric} pet bed with {rim}",
    variants=(None, (0.5, 0.6, 0.18), (0.8, 0.8, 0.22)),
)
def pet_bed(size: Vec3, rng: Rng) -> Design:
    """A pet bed: a cushion with a bolster rim (lower at the front +X); a square footprint
    may give a round donut bed."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    fabric = pick(rng, (*FABRICS, RUG_BEIGE, LINEN))
    inner = pick(rng, (LINEN, BEIGE_FABRIC, fabric))
    if abs(d - w) < 1e-3 and chance(rng, 0.5):
        r = hd
        outer = ((0.9 * r, 0.0), (r, 0.45 * h), (0.93 * r, h))
        parts: list[Part] = [
            Lathe((0.0, 0.0, 0.0), outer, fabric, hollow=(0.25 * r, 0.35 * h)),
            Cylinder((0.0, 0.0, 0.35 * h + 0.005), 0.65 * r, 0.005, inner, collide=False),
        ]
        return Design(tuple(parts), {"fabric": fabric.words, "rim": "a round donut rim"})
    b = clamp(0.15 * min(d, w), 0.06, 0.14)
    base_t = clamp(0.35 * h, 0.04, 0.08)
    front = clamp(0.6 * h, base_t + 0.02, h)
    parts = [
        block((-hd, hd), (-hw, hw), (0.0, base_t), fabric),
        block((-hd + b, hd - b), (-hw + b, hw - b), (base_t, base_t + 0.02), inner, surface=True),
        block((-hd, -hd + b), (-hw, hw), (base_t, h), fabric),
        block((hd - b, hd), (-hw + b, hw - b), (base_t, front), fabric),
        block((-hd + b, hd), (-hw, -hw + b), (base_t, h), fabric),
        block((-hd + b, hd), (hw - b, hw), (base_t, h), fabric),
    ]
    return Design(tuple(parts), {"fabric": fabric.words, "rim": "a bolster rim"})
