"""Generators of studio, lecture and craft furniture (front +X).

Every generator fills exactly ``[-d/2, d/2] x [-w/2, w/2] x [0, h]`` (x = depth, y = width).
"""

from __future__ import annotations

import numpy as np

from asset_pipeline.procedural.kit import (
    ALUMINIUM,
    BLACK_METAL,
    BLACK_PLASTIC,
    GREY_LAMINATE,
    OAK,
    PINE,
    SPACE_GREY,
    STEEL,
    WALNUT,
    WHITE_LACQUER,
    WHITE_PLASTIC,
    WHITEBOARD,
    Rng,
    block,
    chance,
    clamp,
    drawer_fronts,
    pick,
    square_legs,
    uniform,
)
from asset_pipeline.procedural.leisure_kit import (
    tilted,
    tilted_bounds,
)
from asset_pipeline.procedural.parts import Part, RecipeMaterial, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.work_kit import (
    METAL_HANDLES,
    NUMBER_WORDS,
)


# --- studio, lecture and craft ----------------------------------------------------------------
@category(
    "mixing_desk",
    "furniture",
    size=(0.8, 1.5, 0.9),
    low=(0.6, 1.0, 0.8),
    high=(1.1, 2.4, 1.1),
    mass=90.0,
    friction=0.7,
    description="a {finish} recording studio desk with a {channels}-channel mixing console, "
    "a monitor bridge and rack bays",
    variants=(None, (0.9, 2.0, 0.95), (0.7, 1.2, 0.85)),
)
def mixing_desk(size: Vec3, rng: Rng) -> Design:
    """A desk top (surfaces beside the console), rack bays under it at both ends, a stepped
    console with fader strips in the middle and a bridge shelf (a surface) at the back."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, (WALNUT, BLACK_METAL, OAK, SPACE_GREY))
    desk_z = h - clamp(uniform(rng, 0.14, 0.2), 0.12, 0.25)
    t = 0.04
    bridge_d = clamp(0.28 * d, 0.18, 0.3)
    xb = -hd + bridge_d
    cw = clamp(0.55 * w, 0.5, w - 0.4)
    bay = 0.5 * (w - cw)
    parts: list[Part] = [
        block((-hd, xb), (-hw, hw), (h - 0.03, h), finish, surface=True),
        block((-hd, -hd + 0.04), (-hw, -hw + 0.04), (desk_z, h - 0.03), finish),
        block((-hd, -hd + 0.04), (hw - 0.04, hw), (desk_z, h - 0.03), finish),
    ]
    for sign in (-1.0, 1.0):
        y = tuple(sorted((sign * hw, sign * (hw - bay))))
        parts.append(
            block(
                (-hd, hd),
                y,
                (desk_z - t, desk_z),
                finish,
                surface=(xb + 0.01, hd, -hw + 0.05, hw - 0.05),
            )
        )
        parts.append(block((-hd + 0.05, hd - 0.05), y, (0.0, desk_z - t), finish))
        for k in range(3):
            z = 0.1 + k * 0.15
            parts.append(
                block(
                    (hd - 0.0505, hd - 0.05),
                    (y[0] + 0.03, y[1] - 0.03),
                    (z, z + 0.12),
                    BLACK_PLASTIC,
                    collide=False,
                )
            )
    yc = (-hw + bay, hw - bay)
    parts.append(block((-hd + 0.05, hd), yc, (desk_z - t, desk_z), finish))
    parts.append(block((xb + 0.02, hd - 0.02), yc, (desk_z, desk_z + 0.05), BLACK_PLASTIC))
    parts.append(block((xb + 0.02, xb + 0.3), yc, (desk_z + 0.05, desk_z + 0.09), BLACK_PLASTIC))
    channels = int(clamp((cw - 0.04) // 0.035, 8, 48))
    pitch = (cw - 0.04) / channels
    for k in range(channels):
        yk = yc[0] + 0.02 + (k + 0.5) * pitch
        parts.append(
            block(
                (xb + 0.32, hd - 0.06),
                (yk - 0.003, yk + 0.003),
                (desk_z + 0.05, desk_z + 0.051),
                STEEL,
                collide=False,
            )
        )
        parts.append(
            block(
                (xb + 0.05, xb + 0.28),
                (yk - 0.005, yk + 0.005),
                (desk_z + 0.09, desk_z + 0.091),
                WHITE_PLASTIC,
                collide=False,
            )
        )
    return Design(tuple(parts), {"finish": finish.words, "channels": str(channels)})


@category(
    "lectern",
    "furniture",
    size=(0.5, 0.6, 1.15),
    low=(0.4, 0.45, 1.0),
    high=(0.7, 0.9, 1.3),
    mass=30.0,
    friction=0.7,
    description="a {wood} lectern with a sloped reading top, a book ledge and {body}",
    variants=(None, (0.55, 0.7, 1.2), (0.45, 0.5, 1.1)),
)
def lectern(size: Vec3, rng: Rng) -> Design:
    """A plinth, a column or panelled body, a reading top sloping down towards the speaker
    (-X) with a ledge, and a shelf inside the open back."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    wood = pick(rng, (OAK, WALNUT, PINE, WHITE_LACQUER))
    panelled = chance(rng, 0.6)
    angle = np.radians(uniform(rng, 12.0, 20.0))
    t = 0.03
    _, hz = tilted_bounds(d - 0.02, t, angle)
    top_c = (0.01, 0.0, h - hz)
    z_low = h - 2 * hz
    parts: list[Part] = [
        block((-hd, hd), (-hw, hw), (0.0, 0.06), wood),
        tilted(top_c, d - 0.02, w, t, angle, wood),
        block((-hd, -hd + 0.03), (-hw + 0.02, hw - 0.02), (z_low - 0.02, z_low + 0.04), wood),
    ]
    inner = (-hd + 0.04, hd - 0.04)
    if panelled:
        parts.append(block((hd - 0.06, hd - 0.03), (-hw + 0.04, hw - 0.04), (0.06, z_low), wood))
        for y in ((-hw + 0.04, -hw + 0.07), (hw - 0.07, hw - 0.04)):
            parts.append(block(inner, y, (0.06, z_low), wood))
        parts.append(
            block((inner[0], hd - 0.06), (-hw + 0.07, hw - 0.07), (0.45, 0.47), wood, surface=True)
        )
        parts.append(block((hd - 0.03, hd - 0.02), (-0.3 * w, 0.3 * w), (0.3, z_low - 0.15), wood))
        body = "a panelled body"
    else:
        parts.append(block((-0.08, 0.08), (-0.08, 0.08), (0.06, z_low), wood))
        parts.append(
            block(
                (-0.5 * d + 0.1, 0.5 * d - 0.1),
                (-0.5 * w + 0.1, 0.5 * w - 0.1),
                (z_low - 0.03, z_low),
                wood,
            )
        )
        body = "a single column"
    return Design(tuple(parts), {"wood": wood.words, "body": body})


@category(
    "drafting_table",
    "furniture",
    size=(0.8, 1.2, 0.95),
    low=(0.6, 0.9, 0.8),
    high=(1.0, 1.6, 1.15),
    mass=35.0,
    friction=0.7,
    description="an adjustable drafting table with a {board} board {tilt} on a {frame} "
    "trestle frame with a pencil ledge and a lower shelf",
    variants=(None, (0.9, 1.5, 1.0), (0.7, 1.0, 0.9)),
)
def drafting_table(size: Vec3, rng: Rng) -> Design:
    """Two trestle ends, a stretcher, a lower shelf (a surface) and a board: flat (a surface)
    or tilted up at the back (-X)."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    board = pick(
        rng,
        (
            WHITEBOARD,
            RecipeMaterial("drafting_green", (0.55, 0.70, 0.55, 1.0), 0.1, 0.1, "green vinyl"),
            ASH_LOCAL,
        ),
    )
    frame = pick(rng, (BLACK_METAL, OAK, ALUMINIUM))
    t = 0.03
    tilt = chance(rng, 0.4)
    post = 0.05
    angle = np.radians(uniform(rng, 10.0, 20.0))
    length = d - 0.03
    hx, hz = tilted_bounds(length, t, angle)
    low_z = h - 2 * hz
    under = low_z - 0.06 if tilt else h - t
    parts: list[Part] = []
    for y in ((-hw + 0.03, -hw + 0.03 + post), (hw - 0.03 - post, hw - 0.03)):
        parts.append(block((-hd, hd), y, (0.0, 0.05), frame))
        parts.append(block((-0.5 * post, 0.5 * post), y, (0.05, under), frame))
        parts.append(block((-hd + 0.05, hd - 0.05), y, (under - 0.04, under), frame))
    parts.append(block((-0.02, 0.02), (-hw + 0.08, hw - 0.08), (0.3, 0.34), frame))
    parts.append(
        block((-hd + 0.05, -0.03), (-hw + 0.08, hw - 0.08), (0.13, 0.15), frame, surface=True)
    )
    if tilt:
        top_c = (-hd + 0.03 + hx, 0.0, h - hz)
        parts.append(tilted(top_c, length, w, t, -angle, board))
        parts.append(block((hd - 0.03, hd), (-hw, hw), (low_z - 0.03, low_z + 0.02), frame))
        parts.append(block((-0.05, 0.05), (-hw + 0.08, hw - 0.08), (under, low_z), frame))
    else:
        parts.append(block((-hd, hd - 0.03), (-hw, hw), (h - t, h), board, surface=True))
        parts.append(block((hd - 0.03, hd), (-hw, hw), (h - t - 0.03, h), frame))
    words = {
        "board": board.words,
        "frame": frame.words,
        "tilt": "tilted up" if tilt else "set flat",
    }
    return Design(tuple(parts), words)


ASH_LOCAL = RecipeMaterial("maple_board", (0.88, 0.78, 0.60, 1.0), 0.15, 0.2, "maple")


@category(
    "sewing_table",
    "furniture",
    size=(0.6, 1.2, 0.76),
    low=(0.45, 0.8, 0.7),
    high=(0.75, 1.6, 0.85),
    mass=30.0,
    friction=0.7,
    description="a {top} sewing table with a drop-in machine platform and a {drawers}-drawer "
    "pedestal",
    variants=(None, (0.65, 1.4, 0.76), (0.5, 1.0, 0.74)),
)
def sewing_table(size: Vec3, rng: Rng) -> Design:
    """A top (a surface) with a flush machine platform, legs at -Y and a drawer pedestal at +Y."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    top = pick(rng, (WHITE_LACQUER, OAK, WALNUT, GREY_LAMINATE))
    handle = pick(rng, METAL_HANDLES)
    t = 0.03
    ped = clamp(0.35 * w, 0.3, 0.45)
    face = hd - 0.036
    n = int(rng.integers(2, 4))
    parts: list[Part] = [
        block((-hd, hd), (-hw, hw), (h - t, h), top, surface=True),
        block(
            (-0.3 * d, 0.3 * d),
            (-hw + 0.1, -hw + 0.1 + min(0.45, 0.4 * w)),
            (h - 0.0005, h),
            GREY_LAMINATE,
            collide=False,
        ),
        block((-hd, face), (hw - ped, hw), (0.0, h - t), top),
        *[p for p in square_legs(d, w, h - t, 0.045, top) if p.center[1] - p.half[1] < 0.0],
        block((-hd + 0.02, -hd + 0.04), (-hw + 0.045, hw - ped), (0.1, h - t - 0.08), top),
    ]
    parts += drawer_fronts(face, (hw - ped, hw), (0.02, h - t - 0.01), n, 1, top, handle)
    return Design(tuple(parts), {"top": top.words, "drawers": NUMBER_WORDS[n]})
