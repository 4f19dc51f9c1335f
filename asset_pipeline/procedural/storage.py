"""Generators of storage furniture and kitchen and bathroom fixtures (front +X)."""

from __future__ import annotations

import numpy as np

from asset_pipeline.procedural.kit import (
    BLACK_METAL,
    BRASS,
    CASE_FINISHES,
    CHROME,
    FRONT_T,
    GREY_LAMINATE,
    HANDLE_D,
    OAK,
    PAINTED,
    PORCELAIN,
    STEEL,
    WALNUT,
    WHITE_LACQUER,
    WOODS,
    block,
    chance,
    clamp,
    drawer_fronts,
    pick,
    square_legs,
    uniform,
)
from asset_pipeline.procedural.parts import Material, Part, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.roles import fronts as tag_fronts
from asset_pipeline.procedural.roles import tagged
from asset_pipeline.procedural.round_parts import Cylinder, Lathe

Rng = np.random.Generator
PROUD = FRONT_T + HANDLE_D  # fronts and handles stand this far in front of a carcass
STONE = Material("stone_top", (0.85, 0.84, 0.80, 1.0), 0.5, 0.6, "pale stone")
DARK_STONE = Material("dark_stone", (0.20, 0.20, 0.21, 1.0), 0.5, 0.6, "dark stone")
WORKTOPS = (GREY_LAMINATE, STONE, DARK_STONE, OAK, WALNUT)
HANDLES = (BLACK_METAL, CHROME, BRASS)
_COUNT = {1: "one", 2: "two", 3: "three", 4: "four", 5: "five", 6: "six", 7: "seven", 8: "eight"}


def _case(
    size: Vec3,
    rng: Rng,
    *,
    body: Material,
    top: Material,
    top_t: float,
    overhang: float,
    base: str,
    fronts: list[tuple[tuple[float, float], int, int, str]],
    handle: Material,
) -> list[Part]:
    """A carcass with a top board (a surface) and rows of fronts.

    ``fronts`` lists (z fraction range of the front area, rows, columns, handle style).
    ``base``: ``plinth``, ``legs`` or ``none``. The top overhangs the fronts by ``overhang``.
    """
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    face = hd - overhang - PROUD
    base_h = {"none": 0.0, "plinth": uniform(rng, 0.06, 0.1), "legs": uniform(rng, 0.08, 0.15)}[
        base
    ]
    parts: list[Part] = []
    if base == "plinth":
        plinth = block(
            (-hd, face - 0.04),
            (-hw, hw),
            (0.0, base_h),
            BLACK_METAL if chance(rng, 0.3) else body,
        )
        parts += tagged("base", [plinth])
    elif base == "legs":
        legs = square_legs(face + hd, w, base_h, 0.04, pick(rng, (BLACK_METAL, *WOODS)), inset=0.02)
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
            body,
            handle,
            style=style,
        )
        parts += tag_fronts(made, style)
    return parts


@category(
    "wardrobe",
    "furniture",
    size=(0.6, 1.2, 2.0),
    low=(0.45, 0.5, 1.5),
    high=(0.7, 2.4, 2.4),
    mass=80.0,
    friction=0.6,
    description="a tall {body} wardrobe with {doors} doors{drawers}",
    variants=(None, (0.58, 1.8, 2.1)),
)
def wardrobe(size: Vec3, rng: Rng) -> Design:
    """A wardrobe: a row of doors, optionally above a row of drawers; the top is a surface."""
    w = size[1]
    doors = 1 if w < 0.7 else (2 if w < 1.4 else (3 if w < 2.0 else 4))
    drawers = chance(rng, 0.4)
    fronts = (
        [((0.2, 1.0), 1, doors, "door"), ((0.0, 0.2), 1, doors, "bar")]
        if drawers
        else [((0.0, 1.0), 1, doors, "door")]
    )
    body = pick(rng, CASE_FINISHES)
    parts = _case(
        size,
        rng,
        body=body,
        top=body,
        top_t=0.025,
        overhang=0.0,
        base=pick(rng, ("plinth", "legs", "none")),
        fronts=fronts,
        handle=pick(rng, HANDLES),
    )
    words = {
        "body": body.words,
        "doors": _COUNT[doors],
        "drawers": " above drawers" if drawers else "",
    }
    return Design(tuple(parts), words)


@category(
    "dresser",
    "furniture",
    size=(0.5, 1.2, 0.85),
    low=(0.35, 0.5, 0.6),
    high=(0.65, 2.0, 1.3),
    mass=50.0,
    friction=0.6,
    description="a {body} chest of {count} drawers with {handle} handles",
    variants=(None, (0.45, 0.8, 1.1)),
)
def dresser(size: Vec3, rng: Rng) -> Design:
    """A chest of drawers in one or two columns; the top is a surface."""
    _, w, h = size
    rows = int(clamp(int(rng.integers(3, 6)), 2, max(2, int((h - 0.15) / 0.14))))
    cols = 1 if w < 0.8 else (2 if w < 1.6 else 3)
    if cols == 2 and w < 1.0 and chance(rng, 0.5):
        cols = 1
    body = pick(rng, CASE_FINISHES)
    top = body if chance(rng, 0.6) else pick(rng, WOODS)
    handle = pick(rng, HANDLES)
    parts = _case(
        size,
        rng,
        body=body,
        top=top,
        top_t=uniform(rng, 0.02, 0.035),
        overhang=0.0,
        base=pick(rng, ("plinth", "legs")),
        fronts=[((0.0, 1.0), rows, cols, pick(rng, ("bar", "knob")))],
        handle=handle,
    )
    words = {
        "body": body.words,
        "count": _COUNT.get(rows * cols, str(rows * cols)),
        "handle": handle.words,
    }
    return Design(tuple(parts), words)


@category(
    "nightstand",
    "furniture",
    size=(0.4, 0.45, 0.55),
    low=(0.3, 0.3, 0.4),
    high=(0.55, 0.65, 0.75),
    mass=12.0,
    friction=0.6,
    description="a {body} nightstand with {count} drawer{s} and a {top} top",
    variants=(None, (0.38, 0.5, 0.6)),
)
def nightstand(size: Vec3, rng: Rng) -> Design:
    """A bedside cabinet with one to three drawers; the top is a surface."""
    rows = int(rng.integers(1, 4))
    body = pick(rng, CASE_FINISHES)
    top = body if chance(rng, 0.5) else pick(rng, WOODS)
    parts = _case(
        size,
        rng,
        body=body,
        top=top,
        top_t=uniform(rng, 0.02, 0.03),
        overhang=0.0,
        base=pick(rng, ("plinth", "legs", "none")),
        fronts=[((0.0, 1.0), rows, 1, pick(rng, ("bar", "knob")))],
        handle=pick(rng, HANDLES),
    )
    words = {
        "body": body.words,
        "count": _COUNT[rows],
        "s": "s" if rows > 1 else "",
        "top": top.words,
    }
    return Design(tuple(parts), words)


@category(
    "tv_stand",
    "furniture",
    size=(0.45, 1.6, 0.5),
    low=(0.3, 0.8, 0.35),
    high=(0.6, 2.4, 0.7),
    mass=30.0,
    friction=0.6,
    description="a long low {body} tv stand with {count} {kind}",
    variants=(None, (0.4, 1.2, 0.55)),
)
def tv_stand(size: Vec3, rng: Rng) -> Design:
    """A low media cabinet with doors or drawers; the top is a surface."""
    cols = int(clamp(round(size[1] / 0.55), 2, 4))
    kind = pick(rng, ("doors", "drawers"))
    body = pick(rng, CASE_FINISHES)
    parts = _case(
        size,
        rng,
        body=body,
        top=body,
        top_t=uniform(rng, 0.025, 0.04),
        overhang=0.0,
        base=pick(rng, ("legs", "plinth")),
        fronts=[((0.0, 1.0), 1, cols, "door" if kind == "doors" else "bar")],
        handle=pick(rng, HANDLES),
    )
    return Design(tuple(parts), {"body": body.words, "count": _COUNT[cols], "kind": kind})


def _kitchen_base(size: Vec3, rng: Rng, worktop: bool) -> tuple[list[Part], dict[str, str]]:
    w = size[1]
    cols = max(1, round(w / 0.5))
    body = pick(rng, (*PAINTED, OAK))
    top = pick(rng, WORKTOPS) if worktop else body
    drawer_row = chance(rng, 0.5) and size[2] > 0.6
    fronts = (
        [((0.0, 0.78), 1, cols, "door"), ((0.78, 1.0), 1, cols, "bar")]
        if drawer_row
        else [((0.0, 1.0), 1, cols, "door")]
    )
    parts = _case(
        size,
        rng,
        body=body,
        top=top,
        top_t=0.04 if worktop else 0.02,
        overhang=uniform(rng, 0.015, 0.03) if worktop else 0.0,
        base="plinth",
        fronts=fronts,
        handle=pick(rng, HANDLES),
    )
    return parts, {
        "body": body.words,
        "top": top.words,
        "doors": _COUNT.get(cols, str(cols)),
        "drawers": " under a row of drawers" if drawer_row else "",
    }


@category(
    "kitchen_counter",
    "furniture",
    size=(0.62, 1.2, 0.9),
    low=(0.55, 0.3, 0.85),
    high=(0.75, 3.0, 0.95),
    mass=60.0,
    friction=0.6,
    description="a {body} kitchen counter with a {top} worktop and {doors} door(s){drawers}",
    variants=(None, (0.62, 2.4, 0.92)),
)
def kitchen_counter(size: Vec3, rng: Rng) -> Design:
    """A run of kitchen base units under one worktop (a surface)."""
    parts, words = _kitchen_base(size, rng, worktop=True)
    return Design(tuple(parts), words)


@category(
    "base_cabinet",
    "furniture",
    size=(0.58, 0.6, 0.88),
    low=(0.35, 0.3, 0.5),
    high=(0.7, 1.2, 0.95),
    mass=28.0,
    friction=0.6,
    description="a {body} base cabinet with {doors} door(s){drawers}",
    variants=(None, (0.45, 0.9, 0.8)),
)
def base_cabinet(size: Vec3, rng: Rng) -> Design:
    """A single floor cabinet with a flush top (a surface)."""
    parts, words = _kitchen_base(size, rng, worktop=False)
    return Design(tuple(parts), words)


def _wall_unit(
    size: Vec3, rng: Rng, bodies: tuple[Material, ...]
) -> tuple[list[Part], dict[str, str]]:
    cols = 1 if size[1] < 0.55 else (2 if size[1] < 1.1 else 3)
    body = pick(rng, bodies)
    parts = _case(
        size,
        rng,
        body=body,
        top=body,
        top_t=0.02,
        overhang=0.0,
        base="none",
        fronts=[((0.0, 1.0), 1, cols, "door")],
        handle=pick(rng, HANDLES),
    )
    return parts, {"body": body.words, "doors": _COUNT[cols], "s": "s" if cols > 1 else ""}


@category(
    "kitchen_cabinet",
    "furniture",
    size=(0.35, 0.8, 0.7),
    low=(0.25, 0.3, 0.3),
    high=(0.45, 1.5, 1.0),
    mass=18.0,
    friction=0.6,
    placement=("wall",),
    description="a {body} wall-mounted kitchen cabinet with {doors} door{s}",
    variants=(None, (0.33, 0.6, 0.9)),
)
def kitchen_cabinet(size: Vec3, rng: Rng) -> Design:
    """A kitchen wall unit (hangs on a wall; its bottom is z = 0 of the asset)."""
    parts, words = _wall_unit(size, rng, (*PAINTED, OAK))
    return Design(tuple(parts), words)


@category(
    "wall_cabinet",
    "furniture",
    size=(0.2, 0.6, 0.7),
    low=(0.12, 0.3, 0.3),
    high=(0.45, 1.5, 1.2),
    mass=10.0,
    friction=0.6,
    placement=("wall",),
    description="a {body} wall cabinet with {doors} door{s}",
    variants=(None, (0.3, 1.0, 0.5)),
)
def wall_cabinet(size: Vec3, rng: Rng) -> Design:
    """A wall-mounted cabinet (bathroom, hall, utility room)."""
    parts, words = _wall_unit(size, rng, CASE_FINISHES)
    return Design(tuple(parts), words)


# --- open shelving -----------------------------------------------------------------------------
@category(
    "bookshelf",
    "furniture",
    size=(0.3, 0.8, 1.8),
    low=(0.22, 0.4, 0.6),
    high=(0.45, 1.8, 2.4),
    mass=30.0,
    friction=0.6,
    description="a {body} bookshelf with {levels} open shelves{divider}",
    variants=(None, (0.35, 1.2, 2.0)),
)
def bookshelf(size: Vec3, rng: Rng) -> Design:
    """An open bookcase (open side +X) with a back panel; every level and the top are surfaces."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    body = pick(rng, CASE_FINISHES)
    t = uniform(rng, 0.018, 0.03)
    kick = uniform(rng, 0.04, 0.1)
    top_bottom = h - t
    pitch_target = uniform(rng, 0.28, 0.38)
    levels = max(1, round((top_bottom - kick) / pitch_target))
    divider = w > 1.1 and chance(rng, 0.6)
    parts: list[Part] = [
        block((-hd, hd), (-hw, -hw + t), (0.0, top_bottom), body),
        block((-hd, hd), (hw - t, hw), (0.0, top_bottom), body),
        block((-hd, -hd + 0.01), (-hw + t, hw - t), (0.0, top_bottom), body),
        block((hd - t, hd), (-hw + t, hw - t), (0.0, kick - t), body),
        block((-hd, hd), (-hw, hw), (top_bottom, h), body, surface=True),
    ]
    spans = [(-hw + t, hw - t)]
    if divider:
        parts.append(block((-hd + 0.01, hd), (-0.5 * t, 0.5 * t), (kick, top_bottom), body))
        spans = [(-hw + t, -0.5 * t), (0.5 * t, hw - t)]
    pitch = (top_bottom - kick) / levels
    for i in range(levels):
        z = kick + i * pitch
        for y in spans:
            parts.append(block((-hd + 0.01, hd), y, (z - t, z), body, surface=True))
    words = {
        "body": body.words,
        "levels": _COUNT.get(levels + 1, str(levels + 1)),
        "divider": " and a central divider" if divider else "",
    }
    return Design(tuple(parts), words)


@category(
    "shelving_unit",
    "furniture",
    size=(0.4, 0.9, 1.5),
    low=(0.3, 0.6, 0.8),
    high=(0.6, 1.6, 2.2),
    mass=15.0,
    friction=0.5,
    description="an open {post} shelving unit with {levels} {shelf} shelves",
    variants=(None, (0.45, 1.2, 1.8)),
)
def shelving_unit(size: Vec3, rng: Rng) -> Design:
    """Open shelving: four corner posts and evenly spaced shelves (each a surface)."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    post_mat = pick(rng, (STEEL, BLACK_METAL, *WOODS[:2]))
    shelf_mat = pick(rng, (GREY_LAMINATE, WHITE_LACQUER, *WOODS))
    post = uniform(rng, 0.025, 0.04)
    levels = max(3, round((h - 0.15) / uniform(rng, 0.35, 0.5)) + 1)
    parts: list[Part] = []
    for x in ((-hd, -hd + post), (hd - post, hd)):
        for y in ((-hw, -hw + post), (hw - post, hw)):
            parts.append(block(x, y, (0.0, h), post_mat))
    low = uniform(rng, 0.1, 0.18)
    for i in range(levels):
        top = low + i * (h - low) / (levels - 1)
        parts.append(
            block((-hd, hd), (-hw + post, hw - post), (top - 0.02, top), shelf_mat, surface=True)
        )
    words = {
        "post": post_mat.words,
        "levels": _COUNT.get(levels, str(levels)),
        "shelf": shelf_mat.words,
    }
    return Design(tuple(parts), words)


# --- kitchen and bathroom fixtures -----------------------------------------------------------
def _faucet(
    x_back: float, y: float, z: float, height: float, reach: float, metal: Material
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
