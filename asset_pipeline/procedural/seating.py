"""Seating: sofas, armchairs, dining and office chairs, stools."""

from __future__ import annotations

from asset_pipeline.procedural.furniture import (
    WHITE_CHAIR,
)
from asset_pipeline.procedural.kit import (
    BLACK_METAL,
    FABRICS,
    LEATHER,
    WOODS,
    Rng,
    block,
    chance,
    clamp,
    pick,
    round_legs,
    square_legs,
    uniform,
)
from asset_pipeline.procedural.parts import Part, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.roles import tagged
from asset_pipeline.procedural.round_parts import Cylinder


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
        seat_cushion = block(
            (-hd + back_d, hd - 0.02),
            (y0, y0 + inner / seats),
            (seat_z, seat_top),
            fabric,
            surface=True,
        )
        parts += tagged("cushions", [seat_cushion])
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
