"""Generators of office furniture and equipment (front +X).

Every generator fills exactly ``[-d/2, d/2] x [-w/2, w/2] x [0, h]`` (x = depth, y = width).
"""

from __future__ import annotations

from asset_pipeline.procedural.kit import (
    BLACK_METAL,
    BLACK_PLASTIC,
    BRASS,
    CHROME,
    SCREEN,
    SPACE_GREY,
    STEEL,
    WHITE_PLASTIC,
    Rng,
    block,
    chance,
    clamp,
    drawer_fronts,
    pick,
    uniform,
)
from asset_pipeline.procedural.leisure_kit import (
    BLUE_PAINT,
    GREEN_PAINT,
    RED_PAINT,
    YELLOW_PAINT,
    cyl,
    frame_rect,
    rod,
)
from asset_pipeline.procedural.parts import Part, RecipeMaterial, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.round_parts import Lathe
from asset_pipeline.procedural.work_kit import (
    LAB_WHITE,
    METAL_HANDLES,
    NUMBER_WORDS,
    OFFICE_GREY,
    PUTTY,
)

LED_GREEN = RecipeMaterial("led_green", (0.2, 1.0, 0.3, 1.0), 1.0, 1.0)
LED_BLUE = RecipeMaterial("led_blue", (0.2, 0.5, 1.0, 1.0), 1.0, 1.0)
WATER = RecipeMaterial("water_bottle", (0.55, 0.75, 0.95, 0.55), 0.9, 0.9, "blue")
STEELS = (OFFICE_GREY, PUTTY, BLACK_METAL, BLUE_PAINT, LAB_WHITE)


# --- office -----------------------------------------------------------------------------------
@category(
    "filing_cabinet",
    "furniture",
    size=(0.62, 0.47, 1.32),
    low=(0.45, 0.38, 0.6),
    high=(0.75, 0.9, 1.5),
    mass=45.0,
    friction=0.6,
    description="a {finish} metal filing cabinet with {drawers} drawers, label holders and "
    "{handle} handles",
    variants=(None, (0.62, 0.47, 0.72), (0.6, 0.8, 1.05)),
)
def filing_cabinet(size: Vec3, rng: Rng) -> Design:
    """A steel carcass with one drawer per ~30 cm of height (two columns when wide); the top
    is a surface."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, STEELS)
    handle = pick(rng, METAL_HANDLES)
    face = hd - 0.036
    rows = int(clamp(round((h - 0.05) / 0.31), 2, 5))
    cols = 2 if w > 0.7 else 1
    parts: list[Part] = [block((-hd, face), (-hw, hw), (0.0, h), finish, surface=True)]
    parts += drawer_fronts(face, (-hw, hw), (0.04, h - 0.01), rows, cols, finish, handle)
    pitch = (h - 0.05) / rows
    for i in range(rows):
        for j in range(cols):
            yc = -hw + (j + 0.5) * w / cols
            z = 0.04 + (i + 1) * pitch - 0.05
            parts.append(
                block((face + 0.018, face + 0.022), (yc - 0.04, yc + 0.04), (z - 0.02, z), CHROME)
            )
    return Design(
        tuple(parts),
        {
            "finish": finish.words,
            "handle": handle.words,
            "drawers": NUMBER_WORDS.get(rows * cols, str(rows * cols)),
        },
    )


@category(
    "locker",
    "furniture",
    size=(0.45, 0.38, 1.8),
    low=(0.35, 0.3, 1.5),
    high=(0.6, 1.2, 2.1),
    mass=35.0,
    friction=0.6,
    description="a tall {finish} steel locker with {doors} doors, vents and {latch} latches",
    variants=(None, (0.5, 0.9, 1.8), (0.45, 0.6, 1.85)),
)
def locker(size: Vec3, rng: Rng) -> Design:
    """A carcass on a plinth; a grid of doors (columns of ~30-40 cm, one or two tiers), each
    with vent slots near its top and a latch."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, (*STEELS, RED_PAINT, GREEN_PAINT, YELLOW_PAINT))
    latch = pick(rng, METAL_HANDLES)
    door_t = 0.015
    face = hd - door_t - 0.012
    plinth = 0.08
    cols = max(1, round(w / 0.35))
    tiers = 2 if chance(rng, 0.4) else 1
    parts: list[Part] = [
        block((-hd, face), (-hw, hw), (plinth, h), finish, surface=True),
        block((-hd + 0.02, face - 0.02), (-hw + 0.01, hw - 0.01), (0.0, plinth), BLACK_METAL),
    ]
    cw = w / cols
    th = (h - plinth) / tiers
    for i in range(tiers):
        for j in range(cols):
            y0, z0 = -hw + j * cw, plinth + i * th
            parts.append(
                block(
                    (face, face + door_t),
                    (y0 + 0.004, y0 + cw - 0.004),
                    (z0 + 0.004, z0 + th - 0.004),
                    finish,
                )
            )
            for k in range(4):
                z = z0 + th - 0.08 - k * 0.025
                parts.append(
                    block(
                        (face + door_t, face + door_t + 0.001),
                        (y0 + 0.25 * cw, y0 + 0.75 * cw),
                        (z - 0.008, z),
                        BLACK_METAL,
                        collide=False,
                    )
                )
            zc = z0 + 0.5 * th
            parts.append(
                block(
                    (face + door_t, hd),
                    (y0 + cw - 0.06, y0 + cw - 0.04),
                    (zc - 0.06, zc + 0.06),
                    latch,
                )
            )
    return Design(
        tuple(parts),
        {
            "finish": finish.words,
            "latch": latch.words,
            "doors": NUMBER_WORDS.get(cols * tiers, str(cols * tiers)),
        },
    )


@category(
    "water_cooler",
    "furniture",
    size=(0.32, 0.32, 1.1),
    low=(0.28, 0.28, 0.9),
    high=(0.45, 0.45, 1.4),
    mass=20.0,
    friction=0.7,
    description="a {finish} bottled water cooler with hot and cold taps and a {water} water "
    "bottle on top",
    variants=(None, (0.34, 0.34, 1.2), (0.3, 0.3, 1.0)),
)
def water_cooler(size: Vec3, rng: Rng) -> Design:
    """A cabinet with a recessed tap bay on +X (two taps, a drip tray) and an upturned water
    bottle on top."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, (WHITE_PLASTIC, OFFICE_GREY, BLACK_PLASTIC, STEEL))
    bottle_h = clamp(uniform(rng, 0.4, 0.45), 0.3, 0.45 * h)
    body_h = h - bottle_h
    br = min(hd, hw) - 0.02
    bay = (body_h - 0.3, body_h - 0.1)
    parts: list[Part] = [
        block((-hd, hd - 0.06), (-hw, hw), (0.0, body_h), finish),
        block((hd - 0.06, hd), (-hw, hw), (0.0, bay[0]), finish),
        block((hd - 0.06, hd), (-hw, hw), (bay[1], body_h), finish),
        block((hd - 0.06, hd), (-hw, -hw + 0.04), (bay[0], bay[1]), finish),
        block((hd - 0.06, hd), (hw - 0.04, hw), (bay[0], bay[1]), finish),
        block(
            (hd - 0.06, hd - 0.005), (-hw + 0.04, hw - 0.04), (bay[0], bay[0] + 0.02), BLACK_PLASTIC
        ),
        block((hd - 0.05, hd - 0.02), (-0.07, -0.04), (bay[1] - 0.05, bay[1]), RED_PAINT),
        block((hd - 0.05, hd - 0.02), (0.04, 0.07), (bay[1] - 0.05, bay[1]), BLUE_PAINT),
        Lathe(
            (0.0, 0.0, body_h),
            ((0.04, 0.0), (0.04, 0.04), (br, 0.1), (br, bottle_h - 0.05), (0.8 * br, bottle_h)),
            WATER,
        ),
    ]
    return Design(tuple(parts), {"finish": finish.words, "water": "blue"})


@category(
    "server_rack",
    "furniture",
    size=(1.07, 0.6, 2.0),
    low=(0.8, 0.5, 1.6),
    high=(1.2, 0.8, 2.3),
    mass=350.0,
    friction=0.7,
    description="a {finish} 42U server rack with a perforated door frame and {servers} servers "
    "with blinking lights",
    variants=(None, (1.2, 0.8, 2.0), (1.0, 0.6, 1.8)),
)
def server_rack(size: Vec3, rng: Rng) -> Design:
    """A cabinet on a plinth; behind an open door frame on +X, rack servers with LEDs."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, (BLACK_METAL, SPACE_GREY, OFFICE_GREY))
    plinth = 0.08
    face = hd - 0.03
    parts: list[Part] = [
        block((-hd, face), (-hw, hw), (plinth, h), finish),
        block((-hd + 0.03, hd - 0.03), (-hw + 0.03, hw - 0.03), (0.0, plinth), BLACK_METAL),
        *frame_rect((face, hd), (-hw, hw), (plinth, h), 0.04, finish),
    ]
    u = 0.0445
    z = plinth + 0.06
    servers = 0
    while z + 2 * u < h - 0.1:
        size_u = int(rng.integers(1, 4))
        zt = min(z + size_u * u, h - 0.1)
        if chance(rng, 0.8):
            parts.append(
                block(
                    (face - 0.002, face),
                    (-hw + 0.06, hw - 0.06),
                    (z + 0.002, zt - 0.002),
                    pick(rng, (BLACK_PLASTIC, SPACE_GREY, STEEL)),
                    collide=False,
                )
            )
            led = pick(rng, (LED_GREEN, LED_BLUE))
            for k in range(2):
                y = hw - 0.1 - 0.03 * k
                parts.append(
                    block(
                        (face, face + 0.003),
                        (y - 0.006, y + 0.006),
                        (0.5 * (z + zt) - 0.004, 0.5 * (z + zt) + 0.004),
                        led,
                        collide=False,
                    )
                )
            servers += 1
        z = zt
    return Design(tuple(parts), {"finish": finish.words, "servers": str(servers)})


@category(
    "photocopier",
    "furniture",
    size=(0.65, 0.6, 1.15),
    low=(0.5, 0.5, 0.9),
    high=(0.9, 1.1, 1.4),
    mass=90.0,
    friction=0.7,
    description="a {finish} floor-standing office photocopier with {trays} paper trays, an "
    "output tray and a document feeder",
    variants=(None, (0.75, 0.9, 1.2), (0.6, 0.55, 1.0)),
)
def photocopier(size: Vec3, rng: Rng) -> Design:
    """Paper trays in a base cabinet, the print engine, an output bay, the scanner and its
    document feeder on top, a control panel at the front."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, (WHITE_PLASTIC, OFFICE_GREY, PUTTY))
    accent = pick(rng, (BLACK_PLASTIC, SPACE_GREY))
    trays = int(clamp(round((h - 0.6) / 0.13), 2, 4))
    base = 0.08 + trays * 0.13
    bay = (h - 0.3, h - 0.16)
    face = hd - 0.036
    parts: list[Part] = [
        block((-hd + 0.02, face - 0.02), (-hw + 0.02, hw - 0.02), (0.0, 0.06), BLACK_PLASTIC),
        block((-hd, face), (-hw, hw), (0.06, bay[0]), finish),
        *drawer_fronts(face, (-hw, hw), (0.08, base), trays, 1, finish, accent),
        block((face, hd - 0.012), (-hw, hw), (base, bay[0]), finish),
        block((-hd, -hd + 0.2), (-hw, hw), (bay[0], bay[1]), finish),
        block((-hd + 0.2, hd - 0.06), (-hw + 0.05, hw - 0.05), (bay[0], bay[0] + 0.01), accent),
        block((-hd, hd - 0.06), (-hw, hw), (bay[1], h - 0.06), finish),
        block((-hd, hd - 0.12), (-hw + 0.02, hw - 0.02), (h - 0.06, h), accent),
        block((hd - 0.12, hd), (0.1 * w, hw), (h - 0.1, h - 0.04), accent),
        block(
            (hd - 0.1, hd - 0.02),
            (0.1 * w + 0.02, hw - 0.02),
            (h - 0.04, h - 0.039),
            SCREEN,
            collide=False,
        ),
    ]
    return Design(tuple(parts), {"finish": finish.words, "trays": NUMBER_WORDS[trays]})


@category(
    "safe",
    "furniture",
    size=(0.45, 0.45, 0.6),
    low=(0.35, 0.35, 0.4),
    high=(0.7, 0.7, 1.3),
    mass=80.0,
    friction=0.8,
    description="a heavy {finish} steel safe with a {dial} dial, a spoked handle and hinges",
    variants=(None, (0.6, 0.6, 1.2), (0.4, 0.4, 0.5)),
)
def safe(size: Vec3, rng: Rng) -> Design:
    """A steel body (top surface) on four feet, a door on +X with a dial, a handle, hinges."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(
        rng,
        (
            BLACK_METAL,
            OFFICE_GREY,
            GREEN_PAINT,
            RecipeMaterial("safe_red", (0.45, 0.08, 0.08, 1.0), 0.6, 0.6, "oxblood"),
        ),
    )
    dial = pick(rng, (BRASS, CHROME))
    door_t = 0.04
    face = hd - door_t - 0.03
    feet = 0.03
    parts: list[Part] = [
        block((-hd, face), (-hw, hw), (feet, h), finish, surface=True),
        block((face, face + door_t), (-hw + 0.03, hw - 0.03), (feet + 0.03, h - 0.03), finish),
        rod("x", face + door_t, hd, 0.1 * w, feet + 0.6 * (h - feet), 0.035, dial),
        rod(
            "x",
            face + door_t,
            face + door_t + 0.02,
            -0.15 * w,
            feet + 0.45 * (h - feet),
            0.02,
            dial,
        ),
    ]
    zc = feet + 0.45 * (h - feet)
    for k in range(3):
        z = zc + 0.05 * (k - 1)
        parts.append(
            block(
                (face + door_t + 0.005, face + door_t + 0.015),
                (-0.15 * w - 0.06, -0.15 * w + 0.06),
                (z - 0.006, z + 0.006),
                dial,
            )
        )
    for z in (feet + 0.15 * (h - feet), feet + 0.85 * (h - feet)):
        parts.append(cyl(face + 0.01, hw - 0.015, z - 0.04, z + 0.04, 0.015, BLACK_METAL))
    for x in ((-hd + 0.02, -hd + 0.08), (face - 0.08, face - 0.02)):
        for y in ((-hw + 0.02, -hw + 0.08), (hw - 0.08, hw - 0.02)):
            parts.append(block(x, y, (0.0, feet), BLACK_METAL))
    return Design(tuple(parts), {"finish": finish.words, "dial": dial.words})
