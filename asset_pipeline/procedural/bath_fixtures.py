"""Kitchen and bathroom fixtures: sink counters, washbasins, toilets, bathtubs, shower trays."""

from __future__ import annotations

from asset_pipeline.procedural.kit import (
    BLACK_METAL,
    BRASS,
    CHROME,
    OAK,
    PAINTED,
    PORCELAIN,
    STEEL,
    WHITE_LACQUER,
    WOODS,
    block,
    chance,
    clamp,
    drawer_fronts,
    pick,
    uniform,
)
from asset_pipeline.procedural.parts import Part, RecipeMaterial, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.round_parts import Cylinder, Lathe
from asset_pipeline.procedural.storage import (
    DARK_STONE,
    HANDLES,
    PROUD,
    STONE,
    WORKTOPS,
    Rng,
)


# --- kitchen and bathroom fixtures -----------------------------------------------------------
def _faucet(
    x_back: float, y: float, z: float, height: float, reach: float, metal: RecipeMaterial
) -> list[Part]:
    """A faucet standing at (x_back, y) on height z: a column and a spout reaching +X."""
    r = 0.015
    return [
        Cylinder((x_back + r, y, z + 0.5 * height), r, 0.5 * height, metal),
        block(
            (x_back + 2 * r, x_back + 2 * r + reach),
            (y - 0.012, y + 0.012),
            (z + height - 0.03, z + height),
            metal,
        ),
    ]


@category(
    "sink_counter",
    "furniture",
    size=(0.62, 1.2, 1.1),
    low=(0.55, 0.6, 0.95),
    high=(0.75, 2.4, 1.25),
    mass=55.0,
    friction=0.6,
    description=(
        "a {body} kitchen sink unit with a {basin} basin, a {top} worktop and a {metal} faucet"
    ),
    variants=(None, (0.62, 1.8, 1.15)),
)
def sink_counter(size: Vec3, rng: Rng) -> Design:
    """A base unit whose worktop holds a basin and a faucet; the worktop beside it is a surface."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    faucet_h = uniform(rng, max(0.12, h - 0.95), min(0.3, h - 0.85))
    top_z = h - faucet_h
    body = pick(rng, (*PAINTED, OAK))
    top = pick(rng, WORKTOPS)
    metal = pick(rng, (CHROME, STEEL, BLACK_METAL))
    basin_mat = pick(rng, (STEEL, PORCELAIN))
    overhang = 0.02
    face = hd - overhang - PROUD
    plinth = 0.08
    cols = max(2, round(w / 0.5))
    bw = clamp(uniform(rng, 0.4, 0.6), 0.3, w - 0.3)
    by = uniform(rng, -0.5 * (w - bw) + 0.15, 0.5 * (w - bw) - 0.15)
    bx = (-hd + 0.12, hd - 0.08)
    yb = (by - 0.5 * bw, by + 0.5 * bw)
    t = 0.04
    parts: list[Part] = [
        block((-hd, face - 0.04), (-hw, hw), (0.0, plinth), BLACK_METAL),
        block((-hd, face), (-hw, hw), (plinth, top_z - t), body),
        block((-hd, hd), (-hw, yb[0]), (top_z - t, top_z), top, surface=True),
        block((-hd, hd), (yb[1], hw), (top_z - t, top_z), top, surface=True),
        block((-hd, bx[0]), yb, (top_z - t, top_z), top),
        block((bx[1], hd), yb, (top_z - t, top_z), top),
        block(bx, yb, (top_z - 0.2, top_z - 0.185), basin_mat),
        block(bx, (yb[0], yb[0] + 0.01), (top_z - 0.185, top_z - 0.005), basin_mat),
        block(bx, (yb[1] - 0.01, yb[1]), (top_z - 0.185, top_z - 0.005), basin_mat),
    ]
    parts += _faucet(-hd + 0.03, by, top_z, faucet_h, 0.12, metal)
    parts += drawer_fronts(
        face,
        (-hw + 0.002, hw - 0.002),
        (plinth + 0.005, top_z - t - 0.005),
        1,
        cols,
        body,
        pick(rng, HANDLES),
        style="door",
    )
    words = {"body": body.words, "basin": basin_mat.words, "top": top.words, "metal": metal.words}
    return Design(tuple(parts), words)


@category(
    "washbasin",
    "furniture",
    size=(0.45, 0.55, 1.0),
    low=(0.35, 0.4, 0.85),
    high=(0.6, 0.75, 1.15),
    mass=20.0,
    friction=0.6,
    description="a {porcelain} pedestal washbasin with a {metal} tap",
    variants=(None, (0.4, 0.5, 0.95)),
)
def washbasin(size: Vec3, rng: Rng) -> Design:
    """A pedestal sink: a column, a rectangular basin with a back ledge (surfaces), a tap."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    porcelain = PORCELAIN
    metal = pick(rng, (CHROME, BRASS, BLACK_METAL))
    tap_h = uniform(rng, 0.12, min(0.2, h - 0.78))
    rim = h - tap_h
    basin_h = uniform(rng, 0.14, 0.2)
    wall = 0.025
    ledge = uniform(rng, 0.08, 0.11)
    z0 = rim - basin_h
    pr = min(0.25 * w, 0.3 * d, 0.14)
    px = 0.0
    parts: list[Part] = [
        Lathe((px, 0.0, 0.0), ((pr * 1.2, 0.0), (pr * 0.8, 0.25 * z0), (pr * 0.8, z0)), porcelain),
        block((-hd + ledge, hd), (-hw, hw), (z0, z0 + 0.03), porcelain),
        block((hd - wall, hd), (-hw, hw), (z0 + 0.03, rim), porcelain),
        block((-hd + ledge, hd - wall), (-hw, -hw + wall), (z0 + 0.03, rim), porcelain),
        block((-hd + ledge, hd - wall), (hw - wall, hw), (z0 + 0.03, rim), porcelain),
        block((-hd, -hd + ledge), (-0.04, 0.04), (z0, rim), porcelain),
    ]
    side_w = hw - 0.04
    for y in ((-hw, -0.04), (0.04, hw)):
        parts.append(block((-hd, -hd + ledge), y, (z0, rim), porcelain, surface=side_w > 0.09))
    parts += _faucet(-hd + 0.5 * ledge - 0.015, 0.0, rim, tap_h, 0.08, metal)
    return Design(tuple(parts), {"porcelain": "white porcelain", "metal": metal.words})


@category(
    "toilet",
    "furniture",
    size=(0.68, 0.4, 0.8),
    low=(0.55, 0.35, 0.7),
    high=(0.8, 0.5, 0.9),
    mass=30.0,
    friction=0.6,
    description="a white porcelain toilet with a {seat} seat and a cistern",
    variants=(None, (0.62, 0.38, 0.75)),
)
def toilet(size: Vec3, rng: Rng) -> Design:
    """A toilet: pedestal, round bowl and seat at +X, cistern at -X (its lid is a surface)."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    seat_mat = pick(rng, (WHITE_LACQUER, PORCELAIN, WOODS[0]))
    r = hw
    bx = hd - r
    seat_top = uniform(rng, 0.4, 0.44)
    cd = uniform(rng, 0.16, 0.22)
    rim = seat_top - 0.03
    bowl = ((0.55 * r, 0.0), (0.6 * r, 0.4 * rim), (0.95 * r, rim))
    parts: list[Part] = [
        Lathe((bx, 0.0, 0.0), bowl, PORCELAIN),
        block((-hd + 0.04, bx), (-0.4 * r, 0.4 * r), (0.0, rim), PORCELAIN),
        Cylinder((bx, 0.0, seat_top - 0.015), r, 0.015, seat_mat),
        block((-hd, -hd + cd), (-hw, hw), (seat_top - 0.02, h), PORCELAIN, surface=w > 0.3),
    ]
    return Design(tuple(parts), {"seat": seat_mat.words})


@category(
    "bathtub",
    "furniture",
    size=(0.75, 1.7, 0.55),
    low=(0.65, 1.4, 0.4),
    high=(0.95, 1.9, 0.65),
    mass=50.0,
    friction=0.6,
    description="a white {style} bathtub",
    variants=(None, (0.8, 1.6, 0.6)),
)
def bathtub(size: Vec3, rng: Rng) -> Design:
    """A bathtub long along Y: a floor (its inside is a surface) and four walls; maybe on feet."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    wall = uniform(rng, 0.05, 0.08)
    feet = chance(rng, 0.35)
    z0 = uniform(rng, 0.1, 0.14) if feet else 0.0
    floor_t = 0.1
    parts: list[Part] = []
    if feet:
        metal = pick(rng, (BRASS, CHROME, BLACK_METAL))
        for x in (-hd + 0.12, hd - 0.12):
            for y in (-hw + 0.15, hw - 0.15):
                parts.append(Cylinder((x, y, 0.5 * z0), 0.04, 0.5 * z0, metal))
    parts += [
        block(
            (-hd, hd),
            (-hw, hw),
            (z0, z0 + floor_t),
            PORCELAIN,
            surface=(-hd + wall, hd - wall, -hw + wall, hw - wall),
        ),
        block((hd - wall, hd), (-hw, hw), (z0 + floor_t, h), PORCELAIN),
        block((-hd, -hd + wall), (-hw, hw), (z0 + floor_t, h), PORCELAIN),
        block((-hd + wall, hd - wall), (-hw, -hw + wall), (z0 + floor_t, h), PORCELAIN),
        block((-hd + wall, hd - wall), (hw - wall, hw), (z0 + floor_t, h), PORCELAIN),
    ]
    return Design(tuple(parts), {"style": "freestanding" if feet else "built-in"})


@category(
    "shower_tray",
    "furniture",
    size=(0.9, 0.9, 0.06),
    low=(0.7, 0.7, 0.03),
    high=(1.4, 1.4, 0.15),
    mass=25.0,
    friction=0.7,
    description="a {colour} low shower tray with a raised rim",
    variants=(None, (0.8, 1.2, 0.05)),
)
def shower_tray(size: Vec3, rng: Rng) -> Design:
    """A flat tray: a base slab (its inside is a surface) and a raised rim."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    mat = pick(rng, (PORCELAIN, STONE, DARK_STONE))
    rim_w = uniform(rng, 0.04, 0.06)
    rim_h = min(uniform(rng, 0.01, 0.02), 0.4 * h)
    base = h - rim_h
    parts: list[Part] = [
        block(
            (-hd, hd),
            (-hw, hw),
            (0.0, base),
            mat,
            surface=(-hd + rim_w, hd - rim_w, -hw + rim_w, hw - rim_w),
        ),
        block((hd - rim_w, hd), (-hw, hw), (base, h), mat),
        block((-hd, -hd + rim_w), (-hw, hw), (base, h), mat),
        block((-hd + rim_w, hd - rim_w), (-hw, -hw + rim_w), (base, h), mat),
        block((-hd + rim_w, hd - rim_w), (hw - rim_w, hw), (base, h), mat),
        Cylinder((0.0, 0.0, base + 0.0004), 0.05, 0.0004, STEEL, collide=False),
    ]
    return Design(tuple(parts), {"colour": mat.words})
