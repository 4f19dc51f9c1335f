"""Generators of appliances, instruments, wall decor, lamps, floor plants and rugs (front +X)."""

from __future__ import annotations

from asset_pipeline.procedural.kit import (
    ALUMINIUM,
    BLACK_METAL,
    CHROME,
    IVORY,
    PIANO_BLACK,
    SCREEN,
    STEEL,
    WALNUT,
    WHITE_LACQUER,
    WHITEBOARD,
    Rng,
    block,
    chance,
    clamp,
    pick,
    uniform,
)
from asset_pipeline.procedural.parts import Part, RecipeMaterial, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.round_parts import Cylinder

MIRROR = RecipeMaterial("mirror_glass", (0.78, 0.84, 0.86, 1.0), 1.0, 1.0, "mirror")
BLACK_APPLIANCE = RecipeMaterial("black_appliance", (0.10, 0.10, 0.11, 1.0), 0.7, 0.7, "black")
OVEN_GLASS = RecipeMaterial("oven_glass", (0.05, 0.05, 0.06, 1.0), 0.9, 0.9, "dark glass")
APPLIANCE_FINISHES = (WHITE_LACQUER, STEEL, BLACK_APPLIANCE)
_NUM = {1: "one", 2: "two", 3: "three", 4: "four", 6: "six"}


@category(
    "fridge",
    "furniture",
    size=(0.7, 0.7, 1.8),
    low=(0.55, 0.5, 0.8),
    high=(0.85, 1.0, 2.1),
    mass=70.0,
    friction=0.5,
    description="a {finish} {layout} with {metal} handles",
    variants=(None, (0.75, 0.9, 1.8)),
)
def fridge(size: Vec3, rng: Rng) -> Design:
    """A fridge: cabinet, doors on +X with vertical handles; the top is a surface."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, APPLIANCE_FINISHES)
    metal = pick(rng, (CHROME, BLACK_METAL, STEEL))
    door_t, handle_d = 0.03, 0.035
    face = hd - door_t - handle_d
    parts: list[Part] = [block((-hd, face), (-hw, hw), (0.0, h), finish, surface=True)]
    if h < 1.0:
        layout, doors = "under-counter fridge", [((0.02, h - 0.02), (-hw, hw))]
    elif w >= 0.85 and chance(rng, 0.6):
        layout = "side-by-side fridge-freezer"
        doors = [((0.02, h - 0.02), (-hw, -0.003)), ((0.02, h - 0.02), (0.003, hw))]
    else:
        split = uniform(rng, 0.3, 0.38) * h
        layout = "fridge-freezer"
        doors = [((0.02, split - 0.004), (-hw, hw)), ((split + 0.004, h - 0.02), (-hw, hw))]
    for (z0, z1), (y0, y1) in doors:
        parts.append(block((face, face + door_t), (y0 + 0.004, y1 - 0.004), (z0, z1), finish))
        yh = y1 - 0.06 if y0 < -0.01 and y1 > 0.01 else (y1 - 0.04 if y1 < 0 else y0 + 0.04)
        zc, half = 0.5 * (z0 + z1), min(0.22, 0.3 * (z1 - z0))
        parts.append(
            block((face + door_t, hd), (yh - 0.012, yh + 0.012), (zc - half, zc + half), metal)
        )
    return Design(tuple(parts), {"finish": finish.words, "layout": layout, "metal": metal.words})


@category(
    "stove",
    "furniture",
    size=(0.65, 0.6, 0.95),
    low=(0.55, 0.5, 0.85),
    high=(0.75, 0.9, 1.1),
    mass=55.0,
    friction=0.6,
    description="a {finish} freestanding cooker with {burners} burners, an oven{back}",
    variants=(None, (0.62, 0.9, 0.92)),
)
def stove(size: Vec3, rng: Rng) -> Design:
    """A cooker: oven body, door with a window and handle, burners on top (each a surface)."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, APPLIANCE_FINISHES)
    burner_h = 0.012
    back = chance(rng, 0.5) and h - burner_h > 0.93
    top_z = uniform(rng, 0.85, 0.92) if back else h - burner_h
    top_z = min(top_z, h - burner_h)
    door_t, handle_d = 0.025, 0.04
    face = hd - door_t - handle_d
    parts: list[Part] = [
        block((-hd, face), (-hw, hw), (0.0, top_z - 0.02), finish),
        block((-hd, face + door_t), (-hw, hw), (top_z - 0.02, top_z), BLACK_APPLIANCE),
        block((face, face + door_t), (-hw + 0.01, hw - 0.01), (0.1, top_z - 0.14), finish),
        block(
            (face + door_t, face + door_t + 0.002),
            (-hw + 0.08, hw - 0.08),
            (0.2, top_z - 0.26),
            OVEN_GLASS,
            collide=False,
        ),
        Cylinder((hd - 0.012, 0.0, top_z - 0.18), 0.012, hw - 0.08, STEEL, axis="y"),
    ]
    x_front = face + door_t
    back_d = 0.04 if back else 0.0
    if back:
        parts.append(block((-hd, -hd + back_d), (-hw, hw), (top_z, h), finish))
    cols = 3 if w >= 0.85 else 2
    cell_x = (x_front - (-hd + back_d)) / 2
    cell_y = w / cols
    radius = min(0.5 * cell_x, 0.5 * cell_y) - 0.02
    radius = clamp(radius * uniform(rng, 0.8, 1.0), 0.05, 0.11)
    for i in range(2):
        for j in range(cols):
            x = -hd + back_d + (i + 0.5) * cell_x
            y = -hw + (j + 0.5) * cell_y
            parts.append(
                Cylinder(
                    (x, y, top_z + 0.5 * burner_h),
                    radius,
                    0.5 * burner_h,
                    BLACK_METAL,
                    surface=True,
                )
            )
    knobs = cols * 2
    for k in range(knobs):
        y = -hw + (k + 0.5) * w / knobs
        parts.append(Cylinder((face + 0.01, y, top_z - 0.07), 0.018, 0.01, BLACK_METAL, axis="x"))
    words = {
        "finish": finish.words,
        "burners": _NUM[2 * cols],
        "back": " and a backguard" if back else "",
    }
    return Design(tuple(parts), words)


@category(
    "television",
    "furniture",
    size=(0.24, 1.25, 0.8),
    low=(0.12, 0.5, 0.35),
    high=(0.35, 2.0, 1.3),
    mass=14.0,
    friction=0.6,
    placement=("object",),
    description="a {inches}-inch black flat-screen television on {stand}",
    variants=(None, (0.2, 0.9, 0.58)),
)
def television(size: Vec3, rng: Rng) -> Design:
    """A flat-screen TV on a stand; the screen faces +X. Stands on furniture."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    panel_t = uniform(rng, 0.03, min(0.06, 0.5 * d))
    px = (-0.5 * panel_t, 0.5 * panel_t)
    lift = uniform(rng, 0.06, 0.1)
    two_feet = chance(rng, 0.5)
    parts: list[Part] = [
        block(px, (-hw, hw), (lift, h), BLACK_METAL),
        block(
            (px[1], px[1] + 0.002),
            (-hw + 0.015, hw - 0.015),
            (lift + 0.015, h - 0.015),
            SCREEN,
            collide=False,
        ),
    ]
    if two_feet:
        for sign in (-1.0, 1.0):
            y = sign * (hw - 0.12)
            parts.append(block((-hd, hd), (y - 0.03, y + 0.03), (0.0, 0.015), BLACK_METAL))
            parts.append(block(px, (y - 0.015, y + 0.015), (0.015, lift), BLACK_METAL))
    else:
        fw = clamp(0.4 * w, 0.2, 0.5)
        parts.append(block((-hd, hd), (-0.5 * fw, 0.5 * fw), (0.0, 0.02), BLACK_METAL))
        parts.append(block((px[0] - 0.02, px[0]), (-0.04, 0.04), (0.02, lift + 0.1), BLACK_METAL))
    diagonal = ((w - 0.03) ** 2 + (h - lift - 0.03) ** 2) ** 0.5 / 0.0254
    words = {
        "inches": str(int(5 * round(diagonal / 5))),
        "stand": "two feet" if two_feet else "a centre stand",
    }
    return Design(tuple(parts), words)


@category(
    "wall_television",
    "furniture",
    size=(0.08, 1.25, 0.75),
    low=(0.04, 0.5, 0.3),
    high=(0.15, 2.0, 1.2),
    mass=12.0,
    friction=0.6,
    placement=("wall",),
    description="a {inches}-inch black flat-screen television on a wall bracket",
    variants=(None, (0.07, 0.9, 0.53)),
)
def wall_television(size: Vec3, rng: Rng) -> Design:
    """A flat-screen TV for hanging: a bracket against the wall (-X) and the panel in front of
    it, the screen facing +X."""
    d, w, h = size
    x0 = -0.5 * d
    panel_t = uniform(rng, 0.025, min(0.05, 0.6 * d))
    px = (0.5 * d - 0.002 - panel_t, 0.5 * d - 0.002)
    bw, bh = clamp(0.3 * w, 0.15, 0.4), clamp(0.4 * h, 0.12, 0.35)
    zc = 0.5 * h
    parts: list[Part] = [
        block((x0, px[0]), (-0.5 * bw, 0.5 * bw), (zc - 0.5 * bh, zc + 0.5 * bh), BLACK_METAL),
        block(px, (-0.5 * w, 0.5 * w), (0.0, h), BLACK_METAL),
        block(
            (px[1], px[1] + 0.002),
            (-0.5 * w + 0.015, 0.5 * w - 0.015),
            (0.015, h - 0.015),
            SCREEN,
            collide=False,
        ),
    ]
    diagonal = ((w - 0.03) ** 2 + (h - 0.03) ** 2) ** 0.5 / 0.0254
    return Design(tuple(parts), {"inches": str(int(5 * round(diagonal / 5)))})


@category(
    "piano",
    "furniture",
    size=(0.55, 1.5, 1.25),
    low=(0.45, 1.2, 1.0),
    high=(0.7, 1.7, 1.4),
    mass=220.0,
    friction=0.6,
    description="a {finish} upright piano with ivory keys",
    variants=(None,),
)
def piano(size: Vec3, rng: Rng) -> Design:
    """An upright piano with its keyboard at +X (the lid is a surface)."""
    d, w, h = size
    finish = pick(rng, (PIANO_BLACK, WALNUT, WHITE_LACQUER))
    # The reference design (0.55 x 1.5 x 1.25), scaled to the size: boxes stay boxes.
    ref = [
        ((-0.3, 0.0), (-0.75, 0.75), (0.0, 1.25), finish, True),
        ((0.0, 0.25), (-0.75, 0.75), (0.64, 0.72), finish, False),
        ((0.0, 0.25), (-0.75, -0.69), (0.72, 0.8), finish, False),
        ((0.0, 0.25), (0.69, 0.75), (0.72, 0.8), finish, False),
        ((0.0, 0.09), (-0.69, 0.69), (0.72, 0.82), finish, False),
        ((0.09, 0.25), (-0.69, 0.69), (0.72, 0.74), IVORY, False),
        ((0.09, 0.16), (-0.67, 0.67), (0.74, 0.75), PIANO_BLACK, False),
        ((0.19, 0.25), (-0.75, -0.69), (0.0, 0.64), finish, False),
        ((0.19, 0.25), (0.69, 0.75), (0.0, 0.64), finish, False),
    ]
    sx, sy, sz = d / 0.55, w / 1.5, h / 1.25
    parts: list[Part] = [
        block((x0 * sx, x1 * sx), (y0 * sy, y1 * sy), (z0 * sz, z1 * sz), mat, surface=top)
        for (x0, x1), (y0, y1), (z0, z1), mat, top in ref
    ]
    return Design(tuple(parts), {"finish": finish.words})


@category(
    "whiteboard",
    "furniture",
    size=(0.06, 1.2, 0.9),
    low=(0.03, 0.5, 0.4),
    high=(0.1, 2.4, 1.5),
    mass=8.0,
    friction=0.5,
    placement=("wall",),
    description="a wall-mounted whiteboard with an aluminium frame{tray}",
    variants=(None,),
)
def whiteboard(size: Vec3, rng: Rng) -> Design:
    """A whiteboard: backing, white face, frame, and maybe a marker tray at +X."""
    d, w, h = size
    hw, f = 0.5 * w, 0.02
    tray = chance(rng, 0.7)
    back = 0.02 if tray else d
    x0 = -0.5 * d
    parts: list[Part] = [
        block((x0, x0 + back - 0.005), (-hw, hw), (0.0, h), ALUMINIUM),
        block((x0 + back - 0.005, x0 + back), (-hw + f, hw - f), (f, h - f), WHITEBOARD),
        block((x0 + back - 0.005, x0 + back), (-hw, hw), (0.0, f), ALUMINIUM),
        block((x0 + back - 0.005, x0 + back), (-hw, hw), (h - f, h), ALUMINIUM),
        block((x0 + back - 0.005, x0 + back), (-hw, -hw + f), (f, h - f), ALUMINIUM),
        block((x0 + back - 0.005, x0 + back), (hw - f, hw), (f, h - f), ALUMINIUM),
    ]
    if tray:
        parts.append(block((x0 + back, 0.5 * d), (-0.25 * w, 0.25 * w), (f, f + 0.015), ALUMINIUM))
    return Design(tuple(parts), {"tray": " and a marker tray" if tray else ""})
