"""Generators of game tables and arcade machines (front +X).

Every generator fills exactly ``[-d/2, d/2] x [-w/2, w/2] x [0, h]`` (x = depth, y = width).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from asset_pipeline.procedural.kit import (
    BLACK_METAL,
    BLACK_PLASTIC,
    CHROME,
    CLEAR_GLASS,
    PIANO_BLACK,
    SPACE_GREY,
    WALNUT,
    WHITE_LACQUER,
    WHITE_PLASTIC,
    WOODS,
    Rng,
    block,
    chance,
    clamp,
    pick,
    square_legs,
    uniform,
)
from asset_pipeline.procedural.leisure_kit import (
    BLUE_PAINT,
    GREEN_PAINT,
    LIT_SCREEN,
    MARQUEE,
    RED_PAINT,
    YELLOW_PAINT,
    cyl,
    rod,
    tilted,
)
from asset_pipeline.procedural.parts import Part, RecipeMaterial, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.round_parts import Sphere

# --- local palette ---------------------------------------------------------------------------
FELT_GREEN = RecipeMaterial("felt_green", (0.10, 0.42, 0.22, 1.0), 0.02, 0.05, "green")
FELT_BLUE = RecipeMaterial("felt_blue", (0.12, 0.28, 0.55, 1.0), 0.02, 0.05, "blue")
FELT_RED = RecipeMaterial("felt_red", (0.50, 0.10, 0.14, 1.0), 0.02, 0.05, "wine red")
TT_BLUE = RecipeMaterial("tt_blue", (0.10, 0.22, 0.45, 1.0), 0.2, 0.3, "blue")
TT_GREEN = RecipeMaterial("tt_green", (0.08, 0.33, 0.22, 1.0), 0.2, 0.3, "green")
LINE_WHITE = RecipeMaterial("line_white", (0.97, 0.97, 0.97, 1.0), 0.2, 0.3, "white")
NET_MESH = RecipeMaterial("net_mesh", (0.15, 0.15, 0.16, 0.85), 0.1, 0.1, "black")


# --- game tables -----------------------------------------------------------------------------
@category(
    "pool_table",
    "furniture",
    size=(2.5, 1.4, 0.8),
    low=(2.0, 1.1, 0.74),
    high=(3.0, 1.7, 0.86),
    mass=300.0,
    friction=0.8,
    description="a {wood} pool table with {felt} felt, cushioned rails and six pockets on {legs}",
    variants=(None, (2.1, 1.2, 0.8), (2.8, 1.55, 0.82)),
)
def pool_table(size: Vec3, rng: Rng) -> Design:
    """Legs, an apron, a slate bed with a felt top (the surface), cushioned rails and pockets
    as black blocks at the four corners and the middle of the long sides."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    wood = pick(rng, (*WOODS[:2], PIANO_BLACK, WHITE_LACQUER))
    felt = pick(rng, (FELT_GREEN, FELT_BLUE, FELT_RED))
    c = clamp(uniform(rng, 0.12, 0.15), 0.1, 0.12 * w)
    cushion = 0.045
    felt_top = h - 0.035
    apron_z = h - clamp(uniform(rng, 0.2, 0.26), 0.15, 0.3)
    six = d > 2.3 and chance(rng, 0.5)
    leg = clamp(uniform(rng, 0.12, 0.16), 0.1, 0.2)
    parts: list[Part] = [*square_legs(d - 0.3, w - 0.3, apron_z, leg, wood)]
    if six:
        for y in ((-0.5 * w + 0.15, -0.5 * w + 0.15 + leg), (0.5 * w - 0.15 - leg, 0.5 * w - 0.15)):
            parts.append(block((-0.5 * leg, 0.5 * leg), y, (0.0, apron_z), wood))
    parts += [
        block((-hd + 0.03, hd - 0.03), (-hw + 0.03, hw - 0.03), (apron_z, felt_top - 0.04), wood),
        block(
            (-hd + c, hd - c), (-hw + c, hw - c), (felt_top - 0.04, felt_top), felt, surface=True
        ),
    ]
    z_rail = (felt_top - 0.04, h)
    p = 0.07  # half length of a middle pocket
    for sign in (-1.0, 1.0):
        y_wood = tuple(sorted((sign * hw, sign * (hw - c + cushion))))
        y_cush = tuple(sorted((sign * (hw - c + cushion), sign * (hw - c))))
        for x in ((-hd + c, -p), (p, hd - c)):
            parts.append(block(x, y_wood, z_rail, wood))
            parts.append(block(x, y_cush, (felt_top, h - 0.012), felt))
        parts.append(
            block((-p, p), tuple(sorted((sign * hw, sign * (hw - c)))), z_rail, PIANO_BLACK)
        )
        x_wood = tuple(sorted((sign * hd, sign * (hd - c + cushion))))
        x_cush = tuple(sorted((sign * (hd - c + cushion), sign * (hd - c))))
        parts.append(block(x_wood, (-hw + c, hw - c), z_rail, wood))
        parts.append(block(x_cush, (-hw + c, hw - c), (felt_top, h - 0.012), felt))
        for sy in (-1.0, 1.0):
            xs = tuple(sorted((sign * hd, sign * (hd - c))))
            ys = tuple(sorted((sy * hw, sy * (hw - c))))
            parts.append(block(xs, ys, z_rail, PIANO_BLACK))
    words = {"wood": wood.words, "felt": felt.words, "legs": "six legs" if six else "four legs"}
    return Design(tuple(parts), words)


@category(
    "foosball_table",
    "furniture",
    size=(1.4, 0.75, 0.9),
    low=(1.15, 0.6, 0.8),
    high=(1.6, 1.0, 1.0),
    mass=70.0,
    description="a {body} foosball table with eight chrome rods and {team} players",
    variants=(None, (1.5, 0.85, 0.92), (1.2, 0.65, 0.85)),
)
def foosball_table(size: Vec3, rng: Rng) -> Design:
    """A cabinet on legs with a green field inside; eight rods cross Y with handles outside."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    body = pick(rng, (*WOODS[:2], BLACK_METAL, BLUE_PAINT))
    team = pick(rng, (RED_PAINT, BLUE_PAINT, YELLOW_PAINT))
    handle = 0.12
    cw = hw - handle  # half width of the cabinet
    box_z = h - clamp(uniform(rng, 0.2, 0.24), 0.16, 0.3)
    field_z = box_z + 0.04
    wall = 0.03
    rod_z = h - 0.06
    parts: list[Part] = [
        *square_legs(d - 0.06, 2 * cw - 0.06, box_z, 0.08, body),
        block((-hd, hd), (-cw, cw), (box_z, field_z), body),
        block(
            (-hd + wall, hd - wall), (-cw + wall, cw - wall), (field_z, field_z + 0.01), FELT_GREEN
        ),
        block((-hd, -hd + wall), (-cw, cw), (field_z, h), body),
        block((hd - wall, hd), (-cw, cw), (field_z, h), body),
        block((-hd + wall, hd - wall), (-cw, -cw + wall), (field_z, h), body),
        block((-hd + wall, hd - wall), (cw - wall, cw), (field_z, h), body),
    ]
    pitch = (d - 2 * wall) / 8
    for i in range(8):
        x = -hd + wall + (i + 0.5) * pitch
        side = -1.0 if i in (0, 1, 3, 5) else 1.0  # handles alternate sides
        a0, a1 = (-hw, cw - 0.005) if side < 0 else (-cw + 0.005, hw)
        parts.append(rod("y", a0, a1, x, rod_z, 0.008, CHROME))
        hy = (-hw, -hw + 0.09) if side < 0 else (hw - 0.09, hw)
        parts.append(rod("y", hy[0], hy[1], x, rod_z, 0.018, BLACK_PLASTIC))
        men = (1, 2, 5, 3, 3, 5, 2, 1)[i]
        mat = team if i % 2 == 0 else WHITE_PLASTIC
        for j in range(men):
            y = -cw + wall + (j + 0.5) * (2 * cw - 2 * wall) / men
            parts.append(
                block(
                    (x - 0.012, x + 0.012),
                    (y - 0.015, y + 0.015),
                    (field_z + 0.025, rod_z + 0.03),
                    mat,
                )
            )
    return Design(tuple(parts), {"body": body.words, "team": f"{team.words} and white"})


@category(
    "table_tennis_table",
    "furniture",
    size=(2.74, 1.525, 0.76),
    low=(2.2, 1.2, 0.7),
    high=(2.9, 1.65, 0.95),
    mass=100.0,
    friction=0.7,
    description="a {top} table tennis table with white lines {net}",
    variants=(None, (2.74, 1.525, 0.9125), (2.5, 1.4, 0.9)),
)
def table_tennis_table(size: Vec3, rng: Rng) -> Design:
    """A thin top on an undercarriage; with room for it (h >= 0.86 m) a net 15 cm high across
    the middle (then the top is at h - 0.15), else the net is taken down (top at h)."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    top = pick(rng, (TT_BLUE, TT_GREEN, BLACK_PLASTIC))
    legs = pick(rng, (BLACK_METAL, SPACE_GREY, BLUE_PAINT))
    net = h >= 0.86
    net_h = min(0.1525, h - 0.7) if net else 0.0
    top_z = h - net_h
    t = 0.025
    line = 0.02
    parts: list[Part] = [
        block((-hd, 0.0), (-hw, hw), (top_z - t, top_z), top, surface=True),
        block((0.0, hd), (-hw, hw), (top_z - t, top_z), top, surface=True),
        block((-hd + 0.2, hd - 0.2), (-hw + 0.15, hw - 0.15), (top_z - t - 0.06, top_z - t), legs),
    ]
    for x in (-hd + 0.35, hd - 0.45):
        parts.append(block((x, x + 0.1), (-hw + 0.2, hw - 0.2), (0.0, 0.05), legs))
        for y in (-hw + 0.25, hw - 0.3):
            parts.append(
                block((x + 0.025, x + 0.075), (y, y + 0.05), (0.05, top_z - t - 0.06), legs)
            )
    for xs in ((-hd, hd),):
        for ys in ((-hw, -hw + line), (hw - line, hw)):
            parts.append(block(xs, ys, (top_z, top_z + 0.0005), LINE_WHITE, collide=False))
    for xs in ((-hd, -hd + line), (hd - line, hd)):
        parts.append(
            block(xs, (-hw + line, hw - line), (top_z, top_z + 0.0005), LINE_WHITE, collide=False)
        )
    parts.append(
        block(
            (-hd + line, hd - line),
            (-0.0015, 0.0015),
            (top_z, top_z + 0.0005),
            LINE_WHITE,
            collide=False,
        )
    )
    if net:
        parts.append(block((-0.004, 0.004), (-hw, hw), (top_z + 0.01, h), NET_MESH, collide=False))
        for ys in ((-hw, -hw + 0.02), (hw - 0.02, hw)):
            parts.append(block((-0.012, 0.012), ys, (top_z, h), BLACK_METAL))
    words = {"top": top.words, "net": "and a net" if net else "with its net taken down"}
    return Design(tuple(parts), words)


@category(
    "air_hockey_table",
    "furniture",
    size=(2.1, 1.2, 0.8),
    low=(1.6, 0.9, 0.75),
    high=(2.5, 1.4, 0.9),
    mass=120.0,
    description="a {body} air hockey table with a white playfield and goal slots at both ends",
    variants=(None, (2.3, 1.3, 0.82), (1.8, 1.0, 0.78)),
)
def air_hockey_table(size: Vec3, rng: Rng) -> Design:
    """A cabinet on legs; rails around a white playfield (a surface) with goal slots in the
    end rails."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    body = pick(rng, (BLACK_METAL, BLUE_PAINT, RED_PAINT, WALNUT))
    rail = pick(rng, (BLACK_PLASTIC, CHROME, YELLOW_PAINT))
    field_z = h - 0.04
    box_z = h - clamp(uniform(rng, 0.22, 0.3), 0.18, 0.3)
    r = 0.07
    goal = clamp(0.2 * w, 0.15, 0.3)
    parts: list[Part] = [
        *square_legs(d - 0.2, w - 0.2, box_z, 0.1, body),
        block((-hd, hd), (-hw, hw), (box_z, field_z - 0.01), body),
        block(
            (-hd + r, hd - r),
            (-hw + r, hw - r),
            (field_z - 0.01, field_z),
            WHITE_PLASTIC,
            surface=True,
        ),
        block((-hd + r, hd - r), (-hw, -hw + r), (field_z - 0.01, h), rail),
        block((-hd + r, hd - r), (hw - r, hw), (field_z - 0.01, h), rail),
        block(
            (-0.004, 0.004),
            (-hw + r, hw - r),
            (field_z, field_z + 0.0005),
            RED_PAINT,
            collide=False,
        ),
    ]
    for sign in (-1.0, 1.0):
        x = tuple(sorted((sign * hd, sign * (hd - r))))
        parts.append(block(x, (-hw, -0.5 * goal), (field_z - 0.01, h), rail))
        parts.append(block(x, (0.5 * goal, hw), (field_z - 0.01, h), rail))
        parts.append(
            block(x, (-0.5 * goal, 0.5 * goal), (field_z - 0.04, field_z - 0.01), BLACK_PLASTIC)
        )
    return Design(tuple(parts), {"body": body.words})


# --- arcade ----------------------------------------------------------------------------------
@category(
    "arcade_cabinet",
    "furniture",
    size=(0.8, 0.7, 1.8),
    low=(0.6, 0.55, 1.6),
    high=(1.0, 0.9, 2.0),
    mass=110.0,
    description="an upright {side} arcade cabinet with a glowing screen, a lit marquee and "
    "{players}",
    variants=(None, (0.85, 0.8, 1.85), (0.7, 0.6, 1.7)),
)
def arcade_cabinet(size: Vec3, rng: Rng) -> Design:
    """Side panels, a lower body, a control panel overhanging at +X, screen and marquee."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    side = pick(rng, (BLACK_PLASTIC, RED_PAINT, BLUE_PAINT, YELLOW_PAINT, WALNUT))
    trim = pick(rng, (BLACK_PLASTIC, CHROME))
    panel_d = clamp(uniform(rng, 0.22, 0.28), 0.15, 0.35 * d)
    x_face = hd - panel_d
    panel_z = clamp(uniform(rng, 0.88, 0.96), 0.8, h - 0.6)
    st = 0.02
    marquee = clamp(uniform(rng, 0.18, 0.24), 0.12, 0.25)
    parts: list[Part] = [
        block((-hd, hd), (-hw, -hw + st), (0.0, panel_z - 0.02), side),
        block((-hd, hd), (hw - st, hw), (0.0, panel_z - 0.02), side),
        block((-hd, x_face), (-hw, -hw + st), (panel_z - 0.02, h), side),
        block((-hd, x_face), (hw - st, hw), (panel_z - 0.02, h), side),
        block((-hd, x_face), (-hw + st, hw - st), (0.0, h), BLACK_PLASTIC),
        block((x_face, hd - 0.02), (-hw + st, hw - st), (0.05, panel_z - 0.1), trim),
        block((x_face, hd), (-hw + st, hw - st), (panel_z - 0.1, panel_z), side),
        block(
            (x_face, x_face + 0.002),
            (-hw + 0.05, hw - 0.05),
            (panel_z + 0.12, h - marquee - 0.04),
            LIT_SCREEN,
            collide=False,
        ),
        block(
            (x_face, x_face + 0.002),
            (-hw + st, hw - st),
            (h - marquee, h - 0.02),
            MARQUEE,
            collide=False,
        ),
        block((x_face + 0.002, x_face + 0.05), (-hw + st, hw - st), (h - 0.02, h), side),
        block((hd - 0.021, hd - 0.02), (-0.08, 0.08), (0.2, 0.4), BLACK_METAL, collide=False),
    ]
    two = w > 0.65 and chance(rng, 0.6)
    sticks = (-0.25 * w, 0.25 * w) if two else (0.0,)
    for y in sticks:
        xj = x_face + 0.5 * panel_d
        parts.append(cyl(xj, y - 0.06, panel_z, panel_z + 0.06, 0.008, BLACK_METAL))
        parts.append(Sphere((xj, y - 0.06, panel_z + 0.07), 0.018, RED_PAINT))
        for k in range(3):
            parts.append(
                cyl(
                    xj - 0.03 + 0.03 * k,
                    y + 0.06,
                    panel_z,
                    panel_z + 0.01,
                    0.012,
                    pick(rng, (RED_PAINT, BLUE_PAINT, YELLOW_PAINT, GREEN_PAINT)),
                )
            )
    words = {"side": side.words, "players": "two joysticks" if two else "a joystick and buttons"}
    return Design(tuple(parts), words)


@category(
    "pinball_machine",
    "furniture",
    size=(1.4, 0.75, 1.9),
    low=(1.2, 0.6, 1.7),
    high=(1.6, 0.9, 2.1),
    mass=115.0,
    description="a {body} pinball machine with a sloped glass playfield and a lit backbox",
    variants=(None, (1.45, 0.7, 1.95), (1.25, 0.65, 1.8)),
)
def pinball_machine(size: Vec3, rng: Rng) -> Design:
    """A sloped cabinet on four legs (player end +X, lower), a backbox at -X."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    body = pick(rng, (BLACK_PLASTIC, RED_PAINT, BLUE_PAINT, PIANO_BLACK))
    legs = pick(rng, (CHROME, BLACK_METAL))
    box_x = clamp(uniform(rng, 0.18, 0.24), 0.15, 0.25)
    cab_w = w
    front_z, back_z = 0.82, 0.95
    cab_h = 0.32
    parts: list[Part] = []
    for x in ((-hd + 0.02, -hd + 0.1), (hd - 0.1, hd - 0.02)):
        for y in ((-hw + 0.02, -hw + 0.08), (hw - 0.08, hw - 0.02)):
            parts.append(block(x, y, (0.0, front_z - cab_h if x[0] > 0 else back_z - cab_h), legs))
    # the cabinet as a stair of two boxes under a sloped glass top
    parts.append(block((-hd, 0.0), (-0.5 * cab_w, 0.5 * cab_w), (back_z - cab_h, back_z), body))
    parts.append(block((0.0, hd), (-0.5 * cab_w, 0.5 * cab_w), (front_z - cab_h, front_z), body))
    angle = np.arctan2(back_z - front_z, d)
    glass_c = (0.5 * box_x, 0.0, 0.5 * (front_z + back_z) + 0.02)
    glass = tilted(glass_c, d - box_x - 0.004, cab_w - 0.04, 0.01, -angle, CLEAR_GLASS)
    parts.append(replace(glass, collide=False))
    parts.append(block((-hd, -hd + box_x), (-hw, hw), (back_z, h), body))
    parts.append(
        block(
            (-hd + box_x, -hd + box_x + 0.002),
            (-hw + 0.03, hw - 0.03),
            (back_z + 0.08, h - 0.05),
            MARQUEE,
            collide=False,
        )
    )
    parts.append(
        block(
            (hd - 0.001, hd), (-0.08, 0.08), (front_z - 0.25, front_z - 0.08), CHROME, collide=False
        )
    )
    return Design(tuple(parts), {"body": body.words})
