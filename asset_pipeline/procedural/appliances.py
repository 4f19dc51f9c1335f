"""Generators of appliances, instruments, wall decor, lamps, floor plants and rugs (front +X)."""

from __future__ import annotations

from asset_pipeline.procedural.kit import (
    ALUMINIUM,
    BARK,
    BLACK_METAL,
    BRASS,
    CANVAS,
    CANVAS_WARM,
    CERAMIC_BLACK,
    CHROME,
    CONCRETE,
    DARK_FOLIAGE,
    FOLIAGE,
    GILT,
    IVORY,
    LAMP_SHADE,
    PIANO_BLACK,
    RUG_BEIGE,
    RUG_BLUE,
    RUG_BORDER,
    RUG_DARK_BORDER,
    RUG_GREY,
    RUG_RED,
    SCREEN,
    SOIL,
    STEEL,
    TERRACOTTA,
    WALNUT,
    WHITE_LACQUER,
    WHITE_SHADE,
    WHITEBOARD,
    WOODS,
    Rng,
    block,
    chance,
    clamp,
    pick,
    uniform,
)
from asset_pipeline.procedural.parts import Box, Material, Part, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.roles import tagged
from asset_pipeline.procedural.round_parts import Cylinder, Lathe, Sphere

MIRROR = Material("mirror_glass", (0.78, 0.84, 0.86, 1.0), 1.0, 1.0, "mirror")
BLACK_APPLIANCE = Material("black_appliance", (0.10, 0.10, 0.11, 1.0), 0.7, 0.7, "black")
OVEN_GLASS = Material("oven_glass", (0.05, 0.05, 0.06, 1.0), 0.9, 0.9, "dark glass")
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


def _framed(size: Vec3, rng: Rng, face: Material) -> tuple[list[Part], str]:
    d, w, h = size
    hw = 0.5 * w
    frame = pick(rng, (GILT, BLACK_METAL, *WOODS[:2], WHITE_LACQUER))
    f = clamp(uniform(rng, 0.02, 0.06), 0.01, 0.15 * min(w, h))
    x0, x1 = -0.5 * d, 0.5 * d
    parts: list[Part] = [
        block((x0, x1 - 0.01), (-hw + f, hw - f), (f, h - f), face),
        *tagged(
            "frame",
            [
                block((x0, x1), (-hw, hw), (0.0, f), frame),
                block((x0, x1), (-hw, hw), (h - f, h), frame),
                block((x0, x1), (-hw, -hw + f), (f, h - f), frame),
                block((x0, x1), (hw - f, hw), (f, h - f), frame),
            ],
        ),
    ]
    return parts, frame.words


@category(
    "painting",
    "furniture",
    size=(0.03, 0.8, 0.6),
    low=(0.015, 0.2, 0.2),
    high=(0.08, 1.6, 1.2),
    mass=3.0,
    placement=("wall",),
    description="a framed {subject} painting with a {frame} frame",
    variants=(None, (0.03, 0.5, 0.7)),
)
def painting(size: Vec3, rng: Rng) -> Design:
    """A framed canvas for a wall; the canvas faces +X."""
    canvas = pick(rng, (CANVAS, CANVAS_WARM))
    parts, frame = _framed(size, rng, canvas)
    subject = "seascape" if canvas is CANVAS else "abstract"
    return Design(tuple(parts), {"subject": subject, "frame": frame})


@category(
    "mirror",
    "furniture",
    size=(0.03, 0.6, 0.9),
    low=(0.015, 0.3, 0.3),
    high=(0.08, 1.6, 2.0),
    mass=6.0,
    placement=("wall",),
    description="a wall mirror with a {frame} frame",
    variants=(None, (0.03, 1.0, 0.7)),
)
def mirror(size: Vec3, rng: Rng) -> Design:
    """A framed wall mirror; the glass faces +X."""
    parts, frame = _framed(size, rng, MIRROR)
    return Design(tuple(parts), {"frame": frame})


@category(
    "floor_lamp",
    "furniture",
    size=(0.4, 0.4, 1.65),
    low=(0.25, 0.25, 1.2),
    high=(0.6, 0.6, 1.9),
    mass=6.0,
    friction=0.7,
    yx_ratio=(1.0, 1.0),
    description="a {metal} floor lamp with a {shade} {shape} shade",
    variants=(None, (0.5, 0.5, 1.5)),
)
def floor_lamp(size: Vec3, rng: Rng) -> Design:
    """A floor lamp: heavy round base, thin pole, a fabric shade as wide as the lamp."""
    d, _, h = size
    r = 0.5 * d
    metal = pick(rng, (BLACK_METAL, BRASS, CHROME))
    shade_mat = pick(rng, (LAMP_SHADE, WHITE_SHADE))
    cone = chance(rng, 0.6)
    shade_h = clamp(uniform(rng, 0.22, 0.35), 0.15, 0.25 * h)
    base_r = clamp(uniform(rng, 0.55, 0.8) * r, 0.11, r)
    top_r = r * (uniform(rng, 0.55, 0.75) if cone else 1.0)
    parts: list[Part] = [
        *tagged("base", [Cylinder((0.0, 0.0, 0.015), base_r, 0.015, metal)]),
        *tagged(
            "pole",
            [
                Cylinder(
                    (0.0, 0.0, 0.5 * (h - shade_h + 0.03)), 0.012, 0.5 * (h - shade_h - 0.03), metal
                )
            ],
        ),
        *tagged("shade", [Lathe((0.0, 0.0, h - shade_h), ((r, 0.0), (top_r, shade_h)), shade_mat)]),
    ]
    return Design(
        tuple(parts),
        {"metal": metal.words, "shade": shade_mat.words, "shape": "conical" if cone else "drum"},
    )


@category(
    "potted_plant",
    "furniture",
    size=(0.6, 0.6, 1.25),
    low=(0.3, 0.3, 0.5),
    high=(1.0, 1.0, 2.2),
    mass=12.0,
    friction=0.8,
    yx_ratio=(1.0, 1.0),
    description="a leafy {kind} in a {pot} pot",
    variants=(None, (0.45, 0.45, 0.9)),
)
def potted_plant(size: Vec3, rng: Rng) -> Design:
    """A floor plant: a pot, a trunk and a crown of leaf spheres exactly as wide as the size."""
    d, _, h = size
    r = 0.5 * d
    pot_mat = pick(rng, (TERRACOTTA, CONCRETE, CERAMIC_BLACK, WHITE_LACQUER))
    leaves = pick(rng, (FOLIAGE, DARK_FOLIAGE))
    pot_top_r = clamp(uniform(rng, 0.45, 0.6) * r, 0.1, 0.3)
    pot_h = clamp(uniform(rng, 0.25, 0.35) * h, 0.18, 0.5)
    crown = clamp(uniform(rng, 0.7, 0.9) * r, 0.1, 0.5 * (h - pot_h))
    parts: list[Part] = [
        Lathe(
            (0.0, 0.0, 0.0),
            ((0.8 * pot_top_r, 0.0), (pot_top_r, pot_h)),
            pot_mat,
            hollow=(0.015, 0.04),
        ),
        Cylinder((0.0, 0.0, pot_h - 0.035), pot_top_r - 0.02, 0.015, SOIL, collide=False),
        Cylinder(
            (0.0, 0.0, 0.5 * (pot_h - 0.05 + h - crown)),
            0.02,
            0.5 * (h - crown - pot_h + 0.05),
            BARK,
        ),
        Sphere((0.0, 0.0, h - crown), crown, leaves),
    ]
    side_r = clamp(0.45 * crown, 0.05, r)
    offset = r - side_r
    side_z = max(h - crown - 0.5 * crown, pot_h + side_r + 0.02)
    for x, y in ((offset, 0.0), (-offset, 0.0), (0.0, offset), (0.0, -offset)):
        parts.append(Sphere((x, y, side_z), side_r, leaves))
    kind = "tree" if h > 1.2 else "shrub"
    return Design(tuple(parts), {"kind": kind, "pot": pot_mat.words})


@category(
    "rug",
    "furniture",
    size=(1.6, 2.3, 0.012),
    low=(0.5, 0.5, 0.008),
    high=(3.5, 4.0, 0.025),
    mass=5.0,
    friction=1.0,
    description="a {field} rug with a {border} border",
    variants=(None, (1.2, 1.8, 0.01)),
)
def rug(size: Vec3, rng: Rng) -> Design:
    """A flat rug: one thin box collider, a patterned field and a border drawn on top."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    field = pick(rng, (RUG_RED, RUG_BLUE, RUG_BEIGE, RUG_GREY))
    border = RUG_DARK_BORDER if field in (RUG_BEIGE,) else pick(rng, (RUG_BORDER, RUG_DARK_BORDER))
    b = clamp(uniform(rng, 0.04, 0.1) * min(d, w), 0.03, 0.2)
    parts: list[Part] = [
        Box((0.0, 0.0, 0.5 * h), (hd, hw, 0.5 * h), field, visual=False),
        block((-hd + b, hd - b), (-hw + b, hw - b), (0.0, h), field, collide=False),
        block((-hd, hd), (-hw, -hw + b), (0.0, h), border, collide=False),
        block((-hd, hd), (hw - b, hw), (0.0, h), border, collide=False),
        block((-hd, -hd + b), (-hw + b, hw - b), (0.0, h), border, collide=False),
        block((hd - b, hd), (-hw + b, hw - b), (0.0, h), border, collide=False),
    ]
    return Design(tuple(parts), {"field": field.words, "border": border.words})
