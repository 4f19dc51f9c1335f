"""Articulated kitchen counters: base units under one worktop, and the sink unit (front +X).

The modules of a kitchen's counter run (:mod:`holomj.layout.counter_runs`) besides the cooker,
the dishwasher and the plain base cabinet: their sizes, placements and variants are the rigid
ones' (:mod:`asset_pipeline.procedural.storage`), so a library swaps one for the other. The
worktop is the outer surface (small objects go on top as before); the cupboard floors, shelves
and drawer bottoms behind the fronts are interior surfaces.
"""

from __future__ import annotations

from asset_pipeline.procedural.articulated.cabinets import LINER, doors_under_drawers, shell
from asset_pipeline.procedural.articulated.kit import (
    FRONT_T,
    GAP,
    PANEL,
    PROUD,
    carcass,
    door_pair,
    floor_surface,
    joint_names,
)
from asset_pipeline.procedural.articulated.registry import articulated
from asset_pipeline.procedural.home_kit import HANDLES
from asset_pipeline.procedural.kit import (
    BLACK_METAL,
    CHROME,
    OAK,
    PAINTED,
    PORCELAIN,
    STEEL,
    Rng,
    block,
    chance,
    clamp,
    count_word,
    pick,
    uniform,
)
from asset_pipeline.procedural.parts import Part, RecipeMaterial, Vec3
from asset_pipeline.procedural.registry import Design
from asset_pipeline.procedural.roles import tagged
from asset_pipeline.procedural.round_parts import Cylinder
from asset_pipeline.procedural.storage import WORKTOPS

WORKTOP_T = 0.04
MODULE_W = 0.5  # one door (and one drawer) per this much width, as the rigid counters


def _columns(width: float, least: int = 1) -> int:
    return max(least, round(width / MODULE_W))


@articulated(
    "kitchen_counter",
    "furniture",
    size=(0.62, 1.2, 0.9),
    low=(0.55, 0.3, 0.85),
    high=(0.75, 3.0, 0.95),
    mass=60.0,
    description="a {body} kitchen counter with a {top} worktop over {doors} hinged door{s}"
    "{drawers}",
    variants=(None, (0.62, 2.4, 0.92)),
)
def kitchen_counter(size: Vec3, rng: Rng) -> Design:
    """A run of base units under one overhanging worktop: a door per half metre, maybe under a
    row of drawers, a shelf behind the doors."""
    body = pick(rng, (*PAINTED, OAK))
    top = pick(rng, WORKTOPS)
    cols = _columns(size[1])
    drawer_h = uniform(rng, 0.13, 0.17) if chance(rng, 0.5) else None
    sh = shell(size, rng, body, top, WORKTOP_T, "plinth", overhang=uniform(rng, 0.015, 0.03))
    z1 = sh.fronts_z[1]
    made, _ = doors_under_drawers(
        sh, rng, body, body, pick(rng, HANDLES), cols, drawer_h, z1 - (drawer_h or 0.0) - 0.1
    )
    words = {
        "body": body.words,
        "top": top.words,
        "doors": count_word(cols),
        "s": "s" if cols > 1 else "",
        "drawers": " under a row of drawers" if drawer_h else "",
    }
    return Design(tuple(sh.parts + made), words)


def _faucet(x_back: float, y: float, z: float, height: float, metal: RecipeMaterial) -> list[Part]:
    """A faucet standing at (x_back, y) on height z: a column and a spout reaching +X."""
    r = 0.015
    return [
        Cylinder((x_back + r, y, z + 0.5 * height), r, 0.5 * height, metal),
        block(
            (x_back + 2 * r, x_back + 2 * r + 0.12),
            (y - 0.012, y + 0.012),
            (z + height - 0.03, z + height),
            metal,
        ),
    ]


@articulated(
    "sink_counter",
    "furniture",
    size=(0.62, 1.2, 1.1),
    low=(0.55, 0.6, 0.95),
    high=(0.75, 2.4, 1.25),
    mass=55.0,
    description="a {body} kitchen sink unit with a {basin} basin in a {top} worktop, a {metal} "
    "faucet and {doors} hinged doors below",
    variants=(None, (0.62, 1.8, 1.15)),
)
def sink_counter(size: Vec3, rng: Rng) -> Design:
    """A base unit whose worktop holds a basin and a faucet (the worktop beside the basin is
    the outer surface); doors below open on the cupboard under the sink (its floor an interior
    surface; no shelf, the basin hangs into it)."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    faucet_h = uniform(rng, max(0.12, h - 0.95), min(0.3, h - 0.85))
    top_z = h - faucet_h
    body = pick(rng, (*PAINTED, OAK))
    top = pick(rng, WORKTOPS)
    metal = pick(rng, (CHROME, STEEL, BLACK_METAL))
    basin_mat = pick(rng, (STEEL, PORCELAIN))
    handle = pick(rng, HANDLES)
    overhang = 0.02
    face = hd - PROUD
    plinth = 0.08
    t = WORKTOP_T
    parts: list[Part] = tagged("base", [block((-hd, face - 0.04), (-hw, hw), (0.0, plinth), body)])
    panels, cavity = carcass((-hd, face), (-hw, hw), (plinth, top_z - t), body, top=False)
    parts += tagged("body", panels)
    # The worktop around the basin; the strips beside it are the outer surfaces.
    front = face + GAP + FRONT_T + overhang
    bw = clamp(uniform(rng, 0.4, 0.6), 0.3, w - 0.3)
    by = uniform(rng, -0.5 * (w - bw) + 0.15, 0.5 * (w - bw) - 0.15)
    bx = (cavity.x0 + 0.1, face - 0.02)
    yb = (by - 0.5 * bw, by + 0.5 * bw)
    zt = (top_z - t, top_z)
    parts += tagged(
        "top",
        [
            block((-hd, front), (-hw, yb[0]), zt, top, surface=True),
            block((-hd, front), (yb[1], hw), zt, top, surface=True),
            block((-hd, bx[0]), yb, zt, top),
            block((bx[1], front), yb, zt, top),
        ],
    )
    wall, deep = 0.01, 0.2
    basin_z = (top_z - deep, top_z - t - 0.002)
    parts += tagged(
        "body",
        [
            block(bx, yb, (basin_z[0], basin_z[0] + 0.015), basin_mat),
            block(bx, (yb[0], yb[0] + wall), (basin_z[0] + 0.015, basin_z[1]), basin_mat),
            block(bx, (yb[1] - wall, yb[1]), (basin_z[0] + 0.015, basin_z[1]), basin_mat),
            block((bx[0], bx[0] + wall), (yb[0] + wall, yb[1] - wall), basin_z, basin_mat),
            block((bx[1] - wall, bx[1]), (yb[0] + wall, yb[1] - wall), basin_z, basin_mat),
        ],
    )
    parts += _faucet(-hd + 0.03, by, top_z, faucet_h, metal)
    doors = _columns(w, least=2)
    z_doors = (plinth + 0.003, top_z - t - 0.003)
    made, links = door_pair(
        "door",
        face,
        (cavity.y0 - PANEL + 0.002, cavity.y1 + PANEL - 0.002),
        z_doors,
        doors,
        body,
        handle,
        z_doors[1] - 0.1,
        rng,
    )
    parts += made + floor_surface(cavity, LINER, joint_names(links))
    words = {
        "body": body.words,
        "basin": basin_mat.words,
        "top": top.words,
        "metal": metal.words,
        "doors": count_word(doors),
    }
    return Design(tuple(parts), words)
