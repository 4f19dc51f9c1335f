"""Generators of beds, sofas, chairs, tables and desks (depth along X, width along Y, front +X).

Every generator takes the bounding box ``(d, w, h)`` and a style generator and fills exactly
``[-d/2, d/2] x [-w/2, w/2] x [0, h]``.
"""

from __future__ import annotations

from asset_pipeline.procedural.kit import (
    BLACK_LEATHER,
    BLACK_METAL,
    BRASS,
    CASE_FINISHES,
    CHROME,
    FABRICS,
    GREY_FABRIC,
    LEATHER,
    LINEN,
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
from asset_pipeline.procedural.parts import Material, Part, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.roles import fronts, tagged
from asset_pipeline.procedural.round_parts import Cylinder

WHITE_CHAIR = Material("white_chair", (0.93, 0.92, 0.90, 1.0), 0.3, 0.4, "white painted")


# --- beds ------------------------------------------------------------------------------------
@category(
    "bed",
    "furniture",
    size=(2.1, 1.6, 1.0),
    low=(1.8, 0.8, 0.7),
    high=(2.4, 2.2, 1.4),
    mass=60.0,
    description="a {width} bed with a {frame} frame, a {headboard} headboard and {pillows}",
    variants=(None, (2.05, 0.95, 0.9)),
)
def bed(size: Vec3, rng: Rng) -> Design:
    """A bed: headboard at -X, frame on legs, mattress (a surface past the pillows), pillows."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    frame = pick(rng, WOODS)
    headboard = frame if chance(rng, 0.5) else pick(rng, FABRICS)
    hb_t = uniform(rng, 0.04, 0.08)
    mattress_top = min(uniform(rng, 0.5, 0.6), h - 0.15)
    thickness = uniform(rng, 0.18, 0.26)
    frame_top = mattress_top - thickness
    leg_h = min(uniform(rng, 0.06, 0.16), frame_top - 0.08)
    x0 = -hd + hb_t
    parts: list[Part] = tagged("headboard", [block((-hd, x0), (-hw, hw), (0.0, h), headboard)])
    foot_t = uniform(rng, 0.03, 0.05) if chance(rng, 0.5) else 0.0
    x1 = hd - foot_t
    if foot_t:
        parts += tagged("frame", [block((x1, hd), (-hw, hw), (0.0, mattress_top - 0.06), frame)])
    parts += tagged(
        "legs",
        (
            p.translated((x0 + 0.5 * (x1 - x0), 0.0, 0.0))
            for p in square_legs(x1 - x0, w, leg_h, 0.07, frame)
        ),
    )
    parts += tagged("frame", [block((x0, x1), (-hw, hw), (leg_h, frame_top), frame)])
    pillow_front = x0 + uniform(rng, 0.36, 0.46)
    bedding: list[Part] = []
    bedding.append(
        block(
            (x0 + 0.01, x1 - 0.01),
            (-hw + 0.02, hw - 0.02),
            (frame_top, mattress_top),
            LINEN,
            surface=(pillow_front + 0.02, x1, -hw, hw),
        )
    )
    pillows = 1 if w < 1.2 else 2
    span = (w - 0.16) / pillows
    pillow_h = min(uniform(rng, 0.1, 0.14), h - mattress_top - 0.01)
    for i in range(pillows):
        y0 = -hw + 0.08 + i * span
        bedding.append(
            block(
                (x0 + 0.05, pillow_front),
                (y0 + 0.02, y0 + span - 0.02),
                (mattress_top, mattress_top + pillow_h),
                LINEN,
            )
        )
    parts += tagged("bedding", bedding)
    words = {
        "width": "single" if w < 1.2 else ("double" if w < 1.7 else "king-size"),
        "frame": frame.words,
        "headboard": headboard.words + (" upholstered" if headboard in FABRICS else ""),
        "pillows": "one pillow" if pillows == 1 else "two pillows",
    }
    return Design(tuple(parts), words)


@category(
    "bunk_bed",
    "furniture",
    size=(2.05, 1.0, 1.65),
    low=(1.9, 0.8, 1.4),
    high=(2.2, 1.4, 1.9),
    mass=70.0,
    description="a {frame} bunk bed with two mattresses, guard rails and a ladder",
    variants=(None, (2.0, 0.95, 1.55)),
)
def bunk_bed(size: Vec3, rng: Rng) -> Design:
    """Two bunks between four corner posts; rails around the top bunk, a ladder on +Y."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    frame = pick(rng, WOODS + (BLACK_METAL,))
    post = uniform(rng, 0.05, 0.07)
    rail_t = 0.025
    parts: list[Part] = []
    for x in ((-hd, -hd + post), (hd - post, hd)):
        for y in ((-hw, -hw + post), (hw - post, hw)):
            parts.append(block(x, y, (0.0, h), frame))
    xi = (-hd + post, hd - post)
    mattress_t = uniform(rng, 0.12, 0.16)
    lower_frame = (0.12, 0.22)
    upper_top = h - uniform(rng, 0.2, 0.26)  # top of the upper mattress
    upper_frame = (upper_top - mattress_t - 0.1, upper_top - mattress_t)
    ladder_x = (hd - post - 0.42, hd - post)
    for z0, z1 in (lower_frame, upper_frame):
        parts.append(block(xi, (-hw, hw), (z0, z1), frame))
    # lower mattress: clear of the ladder on +Y
    parts.append(
        block(
            (xi[0] + 0.01, xi[1] - 0.01),
            (-hw + 0.02, hw - 0.04),
            (lower_frame[1], lower_frame[1] + mattress_t),
            LINEN,
            surface=True,
        )
    )
    parts.append(
        block(
            (xi[0] + 0.01, xi[1] - 0.01),
            (-hw + rail_t + 0.01, hw - rail_t - 0.01),
            (upper_frame[1], upper_top),
            LINEN,
            surface=True,
        )
    )
    rail_z = (upper_frame[1], h - 0.02)
    parts.append(block(xi, (-hw, -hw + rail_t), rail_z, frame))
    parts.append(block((xi[0], ladder_x[0]), (hw - rail_t, hw), rail_z, frame))
    for x in ((ladder_x[0], ladder_x[0] + 0.03),):
        parts.append(block(x, (hw - rail_t, hw), (0.0, upper_frame[0]), frame))
    rungs = int((upper_frame[0] - 0.25) // 0.25) + 1
    for i in range(rungs):
        z = 0.3 + i * (upper_frame[0] - 0.3) / rungs
        parts.append(
            block((ladder_x[0] + 0.03, ladder_x[1]), (hw - rail_t, hw), (z, z + 0.03), frame)
        )
    return Design(tuple(parts), {"frame": frame.words})


# --- seating ---------------------------------------------------------------------------------
def _upholstered(size: Vec3, rng: Rng, seats: int) -> tuple[list[Part], dict[str, str]]:
    """A sofa or an armchair: base, back at -X, two arms, ``seats`` seat cushions (surfaces)."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    fabric = pick(rng, FABRICS + (LEATHER,))
    legs = pick(rng, ("metal legs", "wooden legs", "plinth"))
    base_z = uniform(rng, 0.08, 0.16) if legs != "plinth" else uniform(rng, 0.04, 0.08)
    seat_top = uniform(rng, 0.4, 0.46)
    cushion = uniform(rng, 0.1, 0.14)
    seat_z = seat_top - cushion
    arm_w = clamp(uniform(rng, 0.1, 0.2), 0.08, 0.15 * w)
    back_d = clamp(uniform(rng, 0.16, 0.24), 0.12, 0.3 * d)
    arm_top = min(seat_top + uniform(rng, 0.14, 0.26), h - 0.05)
    rolled = chance(rng, 0.4)
    parts: list[Part] = []
    if legs == "metal legs":
        parts += tagged("legs", round_legs(d, w, base_z, 0.022, BLACK_METAL, inset=0.06))
    elif legs == "wooden legs":
        parts += tagged("legs", square_legs(d, w, base_z, 0.045, pick(rng, WOODS), inset=0.03))
    else:
        plinth = block(
            (-hd + 0.03, hd - 0.03), (-hw + 0.03, hw - 0.03), (0.0, base_z), pick(rng, WOODS)
        )
        parts += tagged("base", [plinth])
    parts += tagged("body", [block((-hd, hd), (-hw, hw), (base_z, seat_z), fabric)])
    parts += tagged("back", [block((-hd, -hd + back_d), (-hw, hw), (seat_z, h), fabric)])
    arms: list[Part] = []
    for sign in (-1.0, 1.0):
        y = sorted((sign * hw, sign * (hw - arm_w)))
        if rolled:
            r = 0.5 * arm_w
            arms.append(block((-hd + back_d, hd), (y[0], y[1]), (seat_z, arm_top - r), fabric))
            arms.append(
                Cylinder(
                    (0.5 * back_d, 0.5 * (y[0] + y[1]), arm_top - r),
                    r,
                    0.5 * (d - back_d),
                    fabric,
                    axis="x",
                )
            )
        else:
            arms.append(block((-hd + back_d, hd), (y[0], y[1]), (seat_z, arm_top), fabric))
    parts += tagged("arms", arms)
    inner = w - 2 * arm_w
    for i in range(seats):
        y0 = -hw + arm_w + i * inner / seats
        cushion = block(
            (-hd + back_d, hd - 0.02),
            (y0, y0 + inner / seats),
            (seat_z, seat_top),
            fabric,
            surface=True,
        )
        parts += tagged("cushions", [cushion])
    words = {
        "fabric": fabric.words if fabric is not LEATHER else "brown leather",
        "legs": {"plinth": "a low wooden plinth", "metal legs": "black metal legs"}.get(
            legs, "wooden legs"
        ),
        "arms": "rolled" if rolled else "square",
        "seats": {1: "one", 2: "two", 3: "three", 4: "four"}[seats],
    }
    return parts, words


@category(
    "sofa",
    "furniture",
    size=(0.9, 2.0, 0.85),
    low=(0.7, 1.2, 0.65),
    high=(1.1, 3.2, 1.05),
    mass=50.0,
    friction=0.9,
    description="a {fabric} {seats}-seat sofa with {arms} arms on {legs}",
    variants=(None, (0.85, 1.6, 0.8)),
)
def sofa(size: Vec3, rng: Rng) -> Design:
    """A sofa with one seat cushion per ~65 cm of inner width."""
    seats = int(clamp(round((size[1] - 0.3) / 0.65), 1, 4))
    parts, words = _upholstered(size, rng, seats)
    return Design(tuple(parts), words)


@category(
    "armchair",
    "furniture",
    size=(0.85, 0.85, 0.9),
    low=(0.65, 0.6, 0.7),
    high=(1.0, 1.1, 1.1),
    mass=25.0,
    friction=0.9,
    description="a {fabric} upholstered armchair with {arms} arms on {legs}",
    variants=(None, (0.8, 0.75, 0.95)),
)
def armchair(size: Vec3, rng: Rng) -> Design:
    """An armchair: a one-seat sofa."""
    parts, words = _upholstered(size, rng, 1)
    return Design(tuple(parts), words)


@category(
    "dining_chair",
    "furniture",
    size=(0.45, 0.45, 0.9),
    low=(0.4, 0.38, 0.75),
    high=(0.6, 0.6, 1.1),
    mass=5.0,
    friction=0.6,
    description="a {wood} dining chair with a {back} back{cushion}",
    variants=(None, (0.5, 0.46, 0.95)),
)
def dining_chair(size: Vec3, rng: Rng) -> Design:
    """A wooden chair; its rear legs rise into the back posts at -X."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    wood = pick(rng, WOODS + (WHITE_CHAIR,))
    leg = uniform(rng, 0.032, 0.045)
    seat_top = uniform(rng, 0.44, 0.48)
    seat_t = uniform(rng, 0.025, 0.04)
    cushion = pick(rng, FABRICS) if chance(rng, 0.4) else None
    cushion_t = 0.03 if cushion else 0.0
    seat_bottom = seat_top - seat_t - cushion_t
    parts: list[Part] = []
    for y in ((-hw, -hw + leg), (hw - leg, hw)):
        parts += tagged("legs", [block((hd - leg, hd), y, (0.0, seat_bottom), wood)])
        parts += tagged("legs", [block((-hd, -hd + leg), y, (0.0, h), wood)])
    seat_top_board = seat_bottom + seat_t
    board = block(
        (-hd, hd),
        (-hw, hw),
        (seat_bottom, seat_top_board),
        wood,
        surface=False if cushion else (-hd + leg, hd, -hw, hw),
    )
    parts += tagged("seat", [board])
    if cushion:
        pad = block(
            (-hd + leg + 0.01, hd - 0.01),
            (-hw + 0.02, hw - 0.02),
            (seat_top_board, seat_top),
            cushion,
            surface=True,
        )
        parts += tagged("cushions", [pad])
    back = pick(rng, ("slatted", "solid", "ladder"))
    x_back = (-hd + 0.006, -hd + leg - 0.006)
    y_in = (-hw + leg, hw - leg)
    back_low = seat_top + 0.12
    backrest: list[Part] = []
    if back == "solid":
        backrest.append(block(x_back, y_in, (back_low, h - 0.02), wood))
    elif back == "slatted":
        backrest.append(block(x_back, y_in, (h - 0.08, h - 0.02), wood))
        slats = 3 if w < 0.5 else 4
        pitch = (y_in[1] - y_in[0]) / (slats + 1)
        for i in range(1, slats + 1):
            yc = y_in[0] + i * pitch
            backrest.append(block(x_back, (yc - 0.012, yc + 0.012), (back_low, h - 0.08), wood))
    else:
        rails = 3
        pitch = (h - 0.02 - back_low) / rails
        for i in range(rails):
            z1 = h - 0.02 - i * pitch
            backrest.append(block(x_back, y_in, (z1 - 0.05, z1), wood))
    parts += tagged("back", backrest)
    words = {
        "wood": wood.words,
        "back": back,
        "cushion": f" and a {cushion.words} seat cushion" if cushion else "",
    }
    return Design(tuple(parts), words)


@category(
    "office_chair",
    "furniture",
    size=(0.62, 0.6, 1.0),
    low=(0.5, 0.5, 0.85),
    high=(0.75, 0.75, 1.3),
    mass=12.0,
    friction=0.7,
    description="a {fabric} office chair with a {metal} column{arms} on a cross base",
    variants=(None, (0.66, 0.66, 1.15)),
)
def office_chair(size: Vec3, rng: Rng) -> Design:
    """A static office chair: cross base, gas column, padded seat, backrest at -X."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    fabric = pick(rng, (GREY_FABRIC, BLACK_LEATHER, *FABRICS[1:3]))
    metal = pick(rng, (CHROME, BLACK_METAL))
    back_t = uniform(rng, 0.05, 0.08)
    gap = 0.02
    sx = (-hd + back_t + gap, hd)
    cx = 0.5 * (sx[0] + sx[1])
    seat_top = uniform(rng, 0.46, 0.52)
    seat_t = uniform(rng, 0.07, 0.1)
    arms = chance(rng, 0.5)
    arm_w = 0.05 if arms else 0.0
    seat_y = (-hw + arm_w + (0.01 if arms else 0.0), hw - arm_w - (0.01 if arms else 0.0))
    reach = 0.5 * (sx[1] - sx[0])
    parts: list[Part] = [
        *tagged(
            "base",
            [
                block((cx - reach, cx + reach), (-0.03, 0.03), (0.0, 0.04), BLACK_METAL),
                block(
                    (cx - 0.03, cx + 0.03),
                    (-min(hw, reach + 0.05), min(hw, reach + 0.05)),
                    (0.0, 0.04),
                    BLACK_METAL,
                ),
            ],
        ),
        *tagged(
            "pole",
            [
                Cylinder(
                    (cx, 0.0, 0.5 * (0.04 + seat_top - seat_t)),
                    0.025,
                    0.5 * (seat_top - seat_t - 0.04),
                    metal,
                )
            ],
        ),
        *tagged("seat", [block(sx, seat_y, (seat_top - seat_t, seat_top), fabric, surface=True)]),
        *tagged(
            "frame",
            [
                block(
                    (-hd + back_t, sx[0] + 0.015),
                    (-0.03, 0.03),
                    (seat_top - seat_t, seat_top + 0.15),
                    BLACK_METAL,
                )
            ],
        ),
        *tagged(
            "back",
            [
                block(
                    (-hd, -hd + back_t),
                    (-min(hw, 0.5 * w - 0.02), min(hw, 0.5 * w - 0.02)),
                    (seat_top + 0.12, h),
                    fabric,
                )
            ],
        ),
    ]
    if arms:
        arm_top = seat_top + uniform(rng, 0.18, 0.24)
        for y in ((-hw, -hw + arm_w), (hw - arm_w, hw)):
            ym = 0.5 * (y[0] + y[1])
            post = block(
                (cx - 0.02, cx + 0.02),
                (ym - 0.012, ym + 0.012),
                (seat_top - seat_t, arm_top - 0.03),
                BLACK_METAL,
            )
            pad = block((cx - 0.14, cx + 0.12), y, (arm_top - 0.03, arm_top), BLACK_METAL)
            parts += tagged("arms", [post, pad])
    words = {"fabric": fabric.words, "metal": metal.words, "arms": " and armrests" if arms else ""}
    return Design(tuple(parts), words)


@category(
    "stool",
    "furniture",
    size=(0.34, 0.34, 0.46),
    low=(0.28, 0.28, 0.4),
    high=(0.5, 0.5, 0.85),
    mass=3.0,
    friction=0.6,
    description="a {shape} {wood} stool with four legs{footrest}",
    variants=(None, (0.38, 0.38, 0.75)),
)
def stool(size: Vec3, rng: Rng) -> Design:
    """A stool: four legs, a square or (for a square footprint) round seat, a footrest if tall."""
    d, w, h = size
    wood = pick(rng, WOODS + (BLACK_METAL,))
    seat_t = uniform(rng, 0.025, 0.04)
    leg_top = h - seat_t
    round_seat = abs(d - w) < 1e-3 and chance(rng, 0.6)
    parts: list[Part] = []
    if round_seat:
        r = 0.5 * d
        inset = 0.45 * r
        parts += tagged("legs", round_legs(d, w, leg_top, 0.016, wood, inset=inset))
        seat = Cylinder((0.0, 0.0, h - 0.5 * seat_t), r, 0.5 * seat_t, wood, surface=True)
        parts += tagged("seat", [seat])
        reach = 0.5 * d - inset
    else:
        inset = uniform(rng, 0.02, 0.05)
        parts += tagged("legs", square_legs(d, w, leg_top, 0.032, wood, inset=inset))
        seat = block((-0.5 * d, 0.5 * d), (-0.5 * w, 0.5 * w), (leg_top, h), wood, surface=True)
        parts += tagged("seat", [seat])
        reach = 0.5 * d - inset - 0.016
    footrest = h > 0.6
    if footrest:
        z = 0.3 * h
        for sign in (-1.0, 1.0):
            y = sign * (0.5 * w - inset - (0.0 if round_seat else 0.016))
            rest = block((-reach, reach), (y - 0.01, y + 0.01), (z, z + 0.02), wood)
            parts += tagged("frame", [rest])
    words = {
        "shape": "round" if round_seat else "square",
        "wood": wood.words,
        "footrest": " and footrests" if footrest else "",
    }
    return Design(tuple(parts), words)


# --- tables and desks ------------------------------------------------------------------------
def _table(
    size: Vec3, rng: Rng, *, shelf_chance: float, allow_round: bool
) -> tuple[list[Part], dict[str, str]]:
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    top_mat = pick(rng, CASE_FINISHES)
    leg_mat = top_mat if chance(rng, 0.6) else pick(rng, (BLACK_METAL, *WOODS))
    t = uniform(rng, 0.02, 0.045)
    parts: list[Part] = []
    if allow_round and abs(d - w) < 1e-3 and chance(rng, 0.6):
        r = hd
        base_r = min(0.6 * r, 0.3)
        foot = Cylinder((0.0, 0.0, 0.02), base_r, 0.02, leg_mat)
        column = Cylinder((0.0, 0.0, 0.5 * (h - t + 0.04)), 0.05, 0.5 * (h - t - 0.04), leg_mat)
        parts += tagged("base", [foot, column])
        top = Cylinder((0.0, 0.0, h - 0.5 * t), r, 0.5 * t, top_mat, surface=True)
        parts += tagged("top", [top])
        return parts, {"top": top_mat.words, "shape": "round", "legs": "a pedestal", "shelf": ""}
    legs = pick(rng, ("square legs", "round legs", "panel legs"))
    inset = uniform(rng, 0.0, min(0.06, 0.1 * d))
    side = clamp(uniform(rng, 0.035, 0.07), 0.03, 0.12 * min(d, w))
    leg_h = h - t
    if legs == "square legs":
        parts += tagged("legs", square_legs(d, w, leg_h, side, leg_mat, inset=inset))
    elif legs == "round legs":
        supports = round_legs(d, w, leg_h, 0.5 * side, leg_mat, inset=inset + 0.5 * side)
        parts += tagged("legs", supports)
    else:
        for y in ((-hw + inset, -hw + inset + side), (hw - inset - side, hw - inset)):
            parts += tagged("legs", [block((-hd + inset, hd - inset), y, (0.0, leg_h), leg_mat)])
    parts += tagged("top", [block((-hd, hd), (-hw, hw), (leg_h, h), top_mat, surface=True)])
    shelf = chance(rng, shelf_chance) and h > 0.3
    if shelf:
        x_in = hd - inset - (side if legs == "square legs" else 0.0) - 0.002
        y_in = hw - inset - side - 0.002
        z = min(0.12, 0.3 * h)
        board = block((-x_in, x_in), (-y_in, y_in), (z - 0.02, z), top_mat, surface=True)
        parts += tagged("shelves", [board])
    return parts, {
        "top": top_mat.words,
        "shape": "square" if abs(d - w) < 1e-3 else "rectangular",
        "legs": legs if leg_mat is top_mat else f"{leg_mat.words} {legs}",
        "shelf": " and a lower shelf" if shelf else "",
    }


@category(
    "coffee_table",
    "furniture",
    size=(0.6, 1.1, 0.42),
    low=(0.4, 0.4, 0.3),
    high=(1.0, 1.6, 0.55),
    mass=15.0,
    friction=0.6,
    description="a low {shape} {top} coffee table on {legs}{shelf}",
    variants=(None, (0.8, 0.8, 0.4)),
)
def coffee_table(size: Vec3, rng: Rng) -> Design:
    """A low table, often with a lower shelf."""
    parts, words = _table(size, rng, shelf_chance=0.5, allow_round=True)
    return Design(tuple(parts), words)


@category(
    "side_table",
    "furniture",
    size=(0.45, 0.45, 0.55),
    low=(0.3, 0.3, 0.4),
    high=(0.7, 0.7, 0.8),
    mass=6.0,
    friction=0.6,
    description="a small {shape} {top} side table on {legs}{shelf}",
    variants=(None, (0.4, 0.5, 0.6)),
)
def side_table(size: Vec3, rng: Rng) -> Design:
    """A small table beside a sofa or a bed."""
    parts, words = _table(size, rng, shelf_chance=0.3, allow_round=True)
    return Design(tuple(parts), words)


@category(
    "dining_table",
    "furniture",
    size=(0.9, 1.6, 0.75),
    low=(0.7, 0.7, 0.7),
    high=(1.2, 2.6, 0.8),
    mass=35.0,
    friction=0.6,
    description="a {shape} {top} dining table on {legs}",
    variants=(None, (1.1, 1.1, 0.75)),
)
def dining_table(size: Vec3, rng: Rng) -> Design:
    """A dining table: four legs, panel legs, or (square footprint) a round pedestal table."""
    parts, words = _table(size, rng, shelf_chance=0.0, allow_round=True)
    return Design(tuple(parts), words)


@category(
    "desk",
    "furniture",
    size=(0.7, 1.4, 0.75),
    low=(0.5, 0.8, 0.7),
    high=(0.9, 2.0, 0.8),
    mass=30.0,
    friction=0.6,
    description="a {top} desk {style}",
    variants=(None, (0.6, 1.2, 0.75)),
)
def desk(size: Vec3, rng: Rng) -> Design:
    """A desk on legs or with a drawer pedestal on its right (+Y) and panel legs."""
    d, w, h = size
    if chance(rng, 0.4):
        parts, words = _table(size, rng, shelf_chance=0.0, allow_round=False)
        return Design(tuple(parts), {"top": words["top"], "style": f"on {words['legs']}"})
    hd, hw = 0.5 * d, 0.5 * w
    mat = pick(rng, CASE_FINISHES)
    handle = pick(rng, (BLACK_METAL, CHROME, BRASS))
    t = uniform(rng, 0.025, 0.04)
    drawers = int(rng.integers(2, 5))
    ped_w = clamp(uniform(rng, 0.38, 0.45), 0.3, 0.35 * w)
    face = hd - 0.05 - 0.036
    parts: list[Part] = [
        *tagged("top", [block((-hd, hd), (-hw, hw), (h - t, h), mat, surface=True)]),
        *tagged(
            "body", [block((-hd + 0.02, face), (hw - 0.02 - ped_w, hw - 0.02), (0.0, h - t), mat)]
        ),
        *tagged(
            "legs", [block((-hd + 0.02, hd - 0.05), (-hw + 0.02, -hw + 0.05), (0.0, h - t), mat)]
        ),
    ]
    parts += fronts(
        drawer_fronts(
            face, (hw - 0.02 - ped_w, hw - 0.02), (0.02, h - t - 0.01), drawers, 1, mat, handle
        )
    )
    return Design(tuple(parts), {"top": mat.words, "style": f"with a {drawers}-drawer pedestal"})
