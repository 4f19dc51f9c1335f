"""Generators of home wall pieces: curtains, blinds, clocks, sconces, hooks (back at -X).

Wall pieces (placement ``wall``) have their back at -X; like every asset they have their lowest
point at z = 0 and stand upright on a flat bottom.
"""

from __future__ import annotations

from asset_pipeline.procedural.appliances import BLACK_APPLIANCE
from asset_pipeline.procedural.home_kit import (
    CLOCK_FACE,
    DRUM_GLASS,
    FABRIC_SHADES,
    IVORY_FACE,
    OPAL_GLASS,
    SAGE_TOY,
)
from asset_pipeline.procedural.kit import (
    ALUMINIUM,
    BLACK_METAL,
    BLACK_PLASTIC,
    BLUE_FABRIC,
    BRASS,
    CANVAS_WARM,
    CHARCOAL_FABRIC,
    CHROME,
    FABRICS,
    GILT,
    GREEN_FABRIC,
    GREY_FABRIC,
    LINEN,
    MUSTARD_FABRIC,
    NAVY_LACQUER,
    PAPER,
    RUG_BEIGE,
    RUG_BLUE,
    RUG_BORDER,
    RUG_RED,
    RUST_FABRIC,
    STEEL,
    TOY_BLUE,
    TOY_RED,
    TOY_YELLOW,
    WAX,
    WHITE_LACQUER,
    WHITE_PLASTIC,
    WHITE_SHADE,
    WOODS,
    Rng,
    block,
    chance,
    clamp,
    count_word,
    pick,
    uniform,
)
from asset_pipeline.procedural.parts import Box, Material, Part, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.round_parts import Cylinder, Lathe

WALL = ("wall",)
CORK = Material("cork", (0.70, 0.53, 0.35, 1.0), 0.05, 0.1, "cork")
CURTAIN_FABRICS = (*FABRICS, LINEN, RUG_RED, CANVAS_WARM)


# === wall pieces (back at -X) =================================================================
def _pleated_panel(
    y: tuple[float, float], z: tuple[float, float], xc: float, depth: float, fabric: Material
) -> list[Part]:
    """A pleated curtain panel ``depth`` deep centred on ``xc``: pleats alternate front and
    back (drawn only) around one collider in the slab they all share."""
    amp, t = 0.38 * depth, 0.62 * depth
    count = max(3, round((y[1] - y[0]) / 0.09))
    pitch = (y[1] - y[0]) / count
    parts: list[Part] = []
    for i in range(count):
        off = 0.5 * amp if i % 2 else -0.5 * amp
        parts.append(
            block(
                (xc + off - 0.5 * t, xc + off + 0.5 * t),
                (y[0] + i * pitch, y[0] + (i + 1) * pitch),
                z,
                fabric,
                collide=False,
            )
        )
    core = 0.5 * (t - amp) - 1e-4
    parts.append(
        Box(
            (xc, 0.5 * (y[0] + y[1]), 0.5 * (z[0] + z[1])),
            (core, 0.5 * (y[1] - y[0]), 0.5 * (z[1] - z[0])),
            fabric,
            visual=False,
        )
    )
    return parts


@category(
    "curtains",
    "furniture",
    size=(0.1, 1.4, 2.4),
    low=(0.05, 0.6, 1.0),
    high=(0.25, 3.5, 3.0),
    mass=6.0,
    friction=0.8,
    placement=WALL,
    description="{layout} of long pleated {fabric} curtains on a {metal} rod{sheer}",
    variants=(None, (0.1, 2.2, 2.5), (0.08, 1.0, 1.6)),
)
def curtains(size: Vec3, rng: Rng) -> Design:
    """Curtains: a rod with end finials on two wall brackets, and one or two pleated panels
    hanging from it to the floor (open to the sides or drawn), maybe a sheer behind."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    fabric = pick(rng, CURTAIN_FABRICS)
    metal = pick(rng, (BLACK_METAL, BRASS, CHROME, *WOODS[:2]))
    rr = clamp(0.15 * d, 0.008, 0.016)
    fin = 2.0 * rr + 0.006
    panel_d = clamp(0.55 * d, 0.025, 0.07)
    xc = hd - max(0.5 * panel_d, 0.5 * fin)
    rod_z = h - 0.5 * fin
    parts: list[Part] = [
        Cylinder((xc, 0.0, rod_z), rr, hw - fin, metal, axis="y"),
        block((xc - 0.5 * fin, xc + 0.5 * fin), (-hw, -hw + fin), (h - fin, h), metal),
        block((xc - 0.5 * fin, xc + 0.5 * fin), (hw - fin, hw), (h - fin, h), metal),
    ]
    for yc in (-hw + fin + 0.06, hw - fin - 0.06):
        parts.append(block((-hd, xc), (yc - 0.01, yc + 0.01), (rod_z - 0.01, rod_z + 0.01), metal))
    z = (0.0, h - fin - 0.005)
    span = (-hw + fin, hw - fin)
    layout = pick(rng, ("open", "drawn", "single"))
    if layout == "open":
        pw = uniform(rng, 0.28, 0.4) * (span[1] - span[0])
        panels = [(span[0], span[0] + pw), (span[1] - pw, span[1])]
        text = "a pair"
    elif layout == "drawn":
        panels = [(span[0], -0.005), (0.005, span[1])]
        text = "a drawn pair"
    else:
        panels = [(span[0], span[1])]
        text = "a single panel"
    for y in panels:
        parts += _pleated_panel(y, z, xc, panel_d, fabric)
    sheer = fabric is not LINEN and chance(rng, 0.4) and xc - 0.5 * panel_d - 0.012 > -hd + 0.002
    if sheer:
        xs = xc - 0.5 * panel_d - 0.008
        parts.append(block((xs - 0.003, xs + 0.003), span, z, WHITE_SHADE))
    words = {
        "layout": text,
        "fabric": fabric.words,
        "metal": metal.words,
        "sheer": " over a white sheer" if sheer else "",
    }
    return Design(tuple(parts), words)


@category(
    "blinds",
    "furniture",
    size=(0.05, 1.2, 1.5),
    low=(0.02, 0.4, 0.5),
    high=(0.12, 2.5, 2.5),
    mass=4.0,
    friction=0.8,
    placement=WALL,
    description="{colour} {kind} window blinds under a headrail",
    variants=(None, (0.05, 0.8, 1.2), (0.06, 1.8, 2.0)),
)
def blinds(size: Vec3, rng: Rng) -> Design:
    """Window blinds hanging from a headrail to a bottom rail: venetian slats on ladder tapes,
    a flat roller blind, or a roman blind folded at the bottom."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    kind = pick(rng, ("venetian", "roller", "roman"))
    colour = (
        pick(rng, (WHITE_PLASTIC, *WOODS[:3], ALUMINIUM))
        if kind == "venetian"
        else pick(rng, (LINEN, *FABRICS))
    )
    rail = WHITE_PLASTIC if colour is not WHITE_PLASTIC else ALUMINIUM
    hr = clamp(0.03 + 0.01 * h, 0.03, 0.06)
    parts: list[Part] = [block((-hd, hd), (-hw, hw), (h - hr, h), rail)]
    y_in = (-hw + 0.01, hw - 0.01)
    bar = clamp(0.5 * d, 0.01, 0.03)
    parts.append(
        block((-0.5 * bar, 0.5 * bar), y_in, (0.0, 0.02), rail if kind != "venetian" else colour)
    )
    if kind == "venetian":
        pitch = max(0.05, (h - hr - 0.02) / 30)
        count = int((h - hr - 0.04) / pitch)
        sx = min(0.5 * d - 0.002, 0.025)
        for i in range(count):
            z = 0.03 + (i + 0.5) * pitch
            parts.append(block((-sx, sx), y_in, (z, z + 0.004), colour, collide=False))
        for yc in (-0.35 * w, 0.0, 0.35 * w):
            parts.append(block((-0.003, 0.003), (yc - 0.006, yc + 0.006), (0.02, h - hr), LINEN))
    else:
        parts.append(block((-0.002, 0.002), y_in, (0.02, h - hr), colour))
        if kind == "roman":
            for i in range(3):
                z = 0.02 + i * 0.06
                parts.append(
                    block((-0.5 * bar, 0.5 * bar), y_in, (z, z + 0.05), colour, collide=False)
                )
    parts.append(
        block(
            (hd - 0.002, hd),
            (hw - 0.04, hw - 0.03),
            (0.3 * h, h - hr),
            WHITE_PLASTIC,
            collide=False,
        )
    )
    return Design(tuple(parts), {"colour": colour.words, "kind": kind})


@category(
    "wall_clock",
    "furniture",
    size=(0.05, 0.35, 0.35),
    low=(0.03, 0.2, 0.2),
    high=(0.1, 0.7, 0.7),
    mass=1.5,
    friction=0.7,
    placement=WALL,
    description="a {shape} wall clock with a {face} face and a {rim} {frame}",
    variants=(None, (0.04, 0.25, 0.25), (0.06, 0.4, 0.55)),
)
def wall_clock(size: Vec3, rng: Rng) -> Design:
    """A wall clock facing +X: a round rim and dial (when width = height) or a square or
    rectangular case, hour marks and hands drawn on the face."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    rim = pick(rng, (BLACK_METAL, *WOODS[:2], BRASS, WHITE_PLASTIC, CHROME))
    face = pick(
        rng, (CLOCK_FACE, IVORY_FACE, BLACK_PLASTIC if rim is not BLACK_METAL else CLOCK_FACE)
    )
    ink = BLACK_METAL if face is not BLACK_PLASTIC else WHITE_PLASTIC
    zc = 0.5 * h
    fx = hd - 0.004
    if abs(w - h) < 1e-3 and chance(rng, 0.7):
        r = hw
        parts: list[Part] = [
            Cylinder((-0.004, 0.0, zc), r, hd - 0.004, rim, axis="x"),
            Cylinder((fx - 0.001, 0.0, zc), 0.88 * r, 0.002, face, axis="x", collide=False),
        ]
        shape, radius, frame = "round", 0.88 * r, "rim"
    else:
        f = clamp(0.08 * min(w, h), 0.015, 0.04)
        parts = [
            block((-hd, hd - 0.008), (-hw, hw), (0.0, h), rim),
            block((hd - 0.008, fx - 0.0), (-hw + f, hw - f), (f, h - f), face, collide=False),
        ]
        radius = 0.5 * min(w, h) - f
        shape, frame = ("square" if abs(w - h) < 1e-3 else "rectangular"), "case"
        zc = h - f - radius if h > w else zc
    for dy, dz in ((0.0, 1.0), (1.0, 0.0), (0.0, -1.0), (-1.0, 0.0)):
        yc, z = 0.8 * radius * dy, zc + 0.8 * radius * dz
        parts.append(
            block(
                (fx, fx + 0.001),
                (yc - 0.006, yc + 0.006),
                (z - 0.006, z + 0.006),
                ink,
                collide=False,
            )
        )
    parts.append(
        block(
            (fx + 0.001, fx + 0.003), (-0.004, 0.004), (zc, zc + 0.5 * radius), ink, collide=False
        )
    )
    parts.append(
        block((fx + 0.003, hd), (0.0, 0.7 * radius), (zc - 0.003, zc + 0.003), ink, collide=False)
    )
    if shape != "round" and h > w + 0.08:
        parts.append(
            block(
                (fx, fx + 0.002), (-0.005, 0.005), (0.06, zc - radius - 0.01), BRASS, collide=False
            )
        )
        frame = "pendulum case"
    return Design(
        tuple(parts), {"shape": shape, "face": face.words, "rim": rim.words, "frame": frame}
    )


@category(
    "wall_sconce",
    "furniture",
    size=(0.2, 0.15, 0.3),
    low=(0.1, 0.08, 0.15),
    high=(0.35, 0.4, 0.6),
    mass=1.5,
    friction=0.7,
    placement=WALL,
    description="a {metal} wall sconce with a {shade}",
    variants=(None, (0.15, 0.12, 0.25), (0.25, 0.2, 0.4)),
)
def wall_sconce(size: Vec3, rng: Rng) -> Design:
    """A wall light: a backplate on the wall, an arm out to a cup, and a shade or a candle
    bulb on the cup rising to the top."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    metal = pick(rng, (BRASS, BLACK_METAL, CHROME, GILT))
    bp = 0.015
    r = min(hw, 0.5 * (d - bp) - 0.005)
    xc = hd - r
    parts: list[Part] = [block((-hd, -hd + bp), (-hw, hw), (0.0, clamp(0.6 * h, 0.1, h)), metal)]
    cup_r = clamp(0.35 * r, 0.02, 0.04)
    cup_h = 0.03
    parts.append(block((-hd + bp, xc), (-0.01, 0.01), (0.0, 0.02), metal))
    parts.append(Cylinder((xc, 0.0, 0.5 * cup_h), cup_r, 0.5 * cup_h, metal))
    kind = pick(rng, ("fabric drum", "glass tulip", "candle"))
    if kind == "candle":
        parts.append(
            Cylinder((xc, 0.0, 0.5 * (cup_h + h - 0.03)), 0.014, 0.5 * (h - 0.03 - cup_h), WAX)
        )
        parts.append(Cylinder((xc, 0.0, h - 0.015), 0.012, 0.015, OPAL_GLASS))
        parts.append(Cylinder((xc, 0.0, cup_h + 0.004), r, 0.004, metal))
        shade = "candle-style bulb on a drip plate"
    elif kind == "fabric drum":
        sh = clamp(0.5 * h, 0.08, 0.25)
        parts.append(
            Cylinder((xc, 0.0, 0.5 * (cup_h + h - sh)), 0.008, 0.5 * (h - sh - cup_h), metal)
        )
        mat = pick(rng, FABRIC_SHADES)
        parts.append(Lathe((xc, 0.0, h - sh), ((r, 0.0), (0.85 * r, sh)), mat))
        shade = f"{mat.words} fabric shade"
    else:
        sh = h - cup_h
        parts.append(
            Lathe((xc, 0.0, cup_h), ((0.4 * r, 0.0), (0.7 * r, 0.4 * sh), (r, sh)), OPAL_GLASS)
        )
        shade = "opal glass tulip shade"
    return Design(tuple(parts), {"metal": metal.words, "shade": shade})


@category(
    "towel_rail",
    "furniture",
    size=(0.1, 0.6, 0.8),
    low=(0.05, 0.3, 0.3),
    high=(0.2, 1.2, 1.8),
    mass=6.0,
    friction=0.7,
    placement=WALL,
    description="a {metal} heated towel rail with {bars} bars{towel}",
    variants=(None, (0.08, 0.5, 0.6), (0.12, 0.6, 1.2)),
)
def towel_rail(size: Vec3, rng: Rng) -> Design:
    """A ladder towel radiator: two side tubes, horizontal bars, brackets to the wall at the
    top and at the floor, maybe a folded towel over one bar."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    metal = pick(rng, (CHROME, WHITE_LACQUER, BLACK_METAL, BRASS))
    ts = 0.03
    xc = hd - 0.5 * ts
    parts: list[Part] = []
    for y in ((-hw, -hw + ts), (hw - ts, hw)):
        parts.append(block((xc - 0.5 * ts, xc + 0.5 * ts), y, (0.0, h), metal))
        for z in ((0.0, 0.025), (h - 0.04, h - 0.015)):
            parts.append(block((-hd, xc - 0.5 * ts), (y[0] + 0.005, y[1] - 0.005), z, metal))
    bars = int(clamp(round((h - 0.06) / 0.08), 2, 20))
    pitch = (h - 0.06) / bars
    for i in range(bars):
        z = 0.05 + i * pitch
        parts.append(block((xc - 0.01, xc + 0.01), (-hw + ts, hw - ts), (z, z + 0.02), metal))
    towel = chance(rng, 0.5) and bars >= 3
    text = ""
    if towel:
        fabric = pick(rng, (LINEN, BLUE_FABRIC, GREY_FABRIC, RUST_FABRIC))
        z_top = 0.05 + (bars - 1) * pitch + 0.02
        zb = max(0.04, z_top - 0.35)
        tx = min(xc + 0.02, hd - 0.002)
        parts.append(block((xc - 0.02, tx), (-0.35 * w, 0.35 * w), (zb, z_top + 0.008), fabric))
        text = f" and a {fabric.words} towel"
    return Design(
        tuple(parts),
        {"metal": metal.words, "bars": count_word(bars) if bars <= 8 else str(bars), "towel": text},
    )


@category(
    "coat_hooks",
    "furniture",
    size=(0.08, 0.6, 0.15),
    low=(0.04, 0.3, 0.08),
    high=(0.15, 1.5, 0.3),
    mass=1.2,
    friction=0.7,
    placement=WALL,
    description="a {board} rail of {count} {metal} coat hooks",
    variants=(None, (0.07, 0.4, 0.12), (0.1, 1.0, 0.2)),
)
def coat_hooks(size: Vec3, rng: Rng) -> Design:
    """A hook rail: a board on the wall and a row of upturned hooks along its lower edge."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    board = pick(rng, (*WOODS, WHITE_LACQUER, NAVY_LACQUER))
    metal = pick(rng, (BLACK_METAL, BRASS, CHROME))
    bt = clamp(0.25 * d, 0.015, 0.025)
    count = int(clamp(round(w / 0.15), 2, 8))
    parts: list[Part] = [block((-hd, -hd + bt), (-hw, hw), (0.0, h), board)]
    pitch = w / count
    double = chance(rng, 0.4) and h >= 0.1
    for i in range(count):
        yc = -hw + (i + 0.5) * pitch
        parts.append(block((-hd + bt, hd - 0.012), (yc - 0.008, yc + 0.008), (0.0, 0.014), metal))
        parts.append(
            block(
                (hd - 0.012, hd),
                (yc - 0.008, yc + 0.008),
                (0.0, clamp(0.35 * h, 0.03, 0.06)),
                metal,
            )
        )
        if double:
            parts.append(
                block((-hd + bt, 0.0), (yc - 0.006, yc + 0.006), (0.5 * h, 0.5 * h + 0.012), metal)
            )
    return Design(
        tuple(parts), {"board": board.words, "count": count_word(count), "metal": metal.words}
    )


@category(
    "range_hood",
    "furniture",
    size=(0.5, 0.9, 0.6),
    low=(0.3, 0.5, 0.2),
    high=(0.65, 1.5, 1.2),
    mass=15.0,
    friction=0.6,
    placement=WALL,
    description="a {finish} {kind} range hood with {controls}",
    variants=(None, (0.5, 0.6, 0.5), (0.6, 1.2, 0.9)),
)
def range_hood(size: Vec3, rng: Rng) -> Design:
    """A cooker hood: a canopy over the hob (flat bottom with grease filters) narrowing in
    steps to a chimney against the wall (-X), or a flat visor hood when low."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, (STEEL, STEEL, WHITE_LACQUER, BLACK_APPLIANCE))
    visor = h < 0.3 or chance(rng, 0.25)
    parts: list[Part] = []
    if visor:
        parts.append(block((-hd, hd - 0.01), (-hw, hw), (0.0, h), finish))
        parts.append(
            block((hd - 0.01, hd), (-hw + 0.01, hw - 0.01), (0.0, min(0.06, h)), DRUM_GLASS)
        )
        kind = "slim visor"
    else:
        vh = clamp(0.12 * h, 0.05, 0.1)
        parts.append(block((-hd, hd), (-hw, hw), (0.0, vh), finish))
        cw = clamp(0.3 * w, 0.2, 0.35)
        cd = clamp(0.55 * d, 0.2, 0.3)
        steps = 3
        canopy_top = vh + clamp(0.3 * h, 0.1, 0.25)
        for i in range(steps):
            f = (i + 1) / (steps + 1)
            z0 = vh + i * (canopy_top - vh) / steps
            xf = hd - f * (d - cd)
            yh = hw - f * (hw - 0.5 * cw)
            parts.append(block((-hd, xf), (-yh, yh), (z0, z0 + (canopy_top - vh) / steps), finish))
        parts.append(block((-hd, -hd + cd), (-0.5 * cw, 0.5 * cw), (canopy_top, h), finish))
        kind = "chimney"
    parts.append(
        block(
            (-hd + 0.03, hd - 0.03), (-hw + 0.03, hw - 0.03), (0.0, 0.002), ALUMINIUM, collide=False
        )
    )
    buttons = not visor and chance(rng, 0.5)
    for i in range(4 if buttons else 0):
        y = -0.1 + i * 0.06
        parts.append(
            block((hd - 0.003, hd), (y, y + 0.03), (0.015, 0.03), BLACK_PLASTIC, collide=False)
        )
    controls = "push buttons on the front" if buttons else "touch controls"
    return Design(tuple(parts), {"finish": finish.words, "kind": kind, "controls": controls})


@category(
    "tapestry",
    "furniture",
    size=(0.02, 1.2, 1.5),
    low=(0.008, 0.4, 0.4),
    high=(0.05, 3.0, 3.0),
    mass=3.0,
    friction=0.8,
    placement=WALL,
    description="a woven {field} wall tapestry with a {pattern} pattern on a {rod} hanging rod",
    variants=(None, (0.02, 0.8, 1.0), (0.025, 2.0, 1.4)),
)
def tapestry(size: Vec3, rng: Rng) -> Design:
    """A wall hanging: a woven panel under a hanging rod, a weighted hem batten at the
    bottom and a woven pattern (bands, a medallion or a border) drawn on its face."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    field = pick(rng, (RUG_RED, RUG_BLUE, RUG_BEIGE, MUSTARD_FABRIC, GREEN_FABRIC))
    accent = pick(
        rng,
        [m for m in (RUG_BORDER, CHARCOAL_FABRIC, MUSTARD_FABRIC, RUST_FABRIC) if m is not field],
    )
    rod = pick(rng, (*WOODS[:2], BLACK_METAL, BRASS))
    ft = min(0.006, 0.6 * d)
    m = clamp(0.04 * w, 0.02, 0.08)
    hem = clamp(0.02 * h, 0.015, 0.04)
    parts: list[Part] = [
        Cylinder((0.0, 0.0, h - hd), hd, hw, rod, axis="y"),
        block((-0.5 * ft, 0.5 * ft), (-hw + m, hw - m), (hem, h - hd), field),
        block((-hd, hd), (-hw + m, hw - m), (0.0, hem), accent),
    ]
    fx = (0.5 * ft, min(0.5 * ft + 0.001, hd))
    pattern = pick(rng, ("banded", "medallion", "bordered"))
    y0, y1, z0, z1 = -hw + m, hw - m, hem, h - d
    if pattern == "banded":
        for i in range(1, 5):
            z = z0 + i * (z1 - z0) / 5
            parts.append(
                block(fx, (y0 + 0.02, y1 - 0.02), (z - 0.02, z + 0.02), accent, collide=False)
            )
    elif pattern == "medallion":
        zc, r = 0.5 * (z0 + z1), 0.25 * min(y1 - y0, z1 - z0)
        parts.append(block(fx, (-r, r), (zc - r, zc + r), accent, collide=False))
        parts.append(
            block(fx, (-2 * r, 2 * r), (zc - 0.2 * r, zc + 0.2 * r), accent, collide=False)
        )
    else:
        b = 0.06 * min(y1 - y0, z1 - z0)
        for yy, zz in (
            ((y0 + b, y1 - b), (z0 + b, z0 + 2 * b)),
            ((y0 + b, y1 - b), (z1 - 2 * b, z1 - b)),
            ((y0 + b, y0 + 2 * b), (z0 + 2 * b, z1 - 2 * b)),
            ((y1 - 2 * b, y1 - b), (z0 + 2 * b, z1 - 2 * b)),
        ):
            parts.append(block(fx, yy, zz, accent, collide=False))
    return Design(tuple(parts), {"field": field.words, "pattern": pattern, "rod": rod.words})


@category(
    "bulletin_board",
    "furniture",
    size=(0.03, 0.9, 0.6),
    low=(0.015, 0.3, 0.25),
    high=(0.06, 2.0, 1.3),
    mass=3.0,
    friction=0.7,
    placement=WALL,
    description="a cork bulletin board in a {frame} frame with {notes} pinned notes",
    variants=(None, (0.03, 1.5, 1.0), (0.02, 0.6, 0.45)),
)
def bulletin_board(size: Vec3, rng: Rng) -> Design:
    """A pin board: a cork panel in a frame with paper notes pinned on its face (+X)."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    frame = pick(rng, (*WOODS, ALUMINIUM, BLACK_METAL))
    f = clamp(0.04 * min(w, h), 0.012, 0.03)
    cx = hd - 0.004
    parts: list[Part] = [
        block((-hd, cx), (-hw + f, hw - f), (f, h - f), CORK),
        block((-hd, hd), (-hw, hw), (0.0, f), frame),
        block((-hd, hd), (-hw, hw), (h - f, h), frame),
        block((-hd, hd), (-hw, -hw + f), (f, h - f), frame),
        block((-hd, hd), (hw - f, hw), (f, h - f), frame),
    ]
    notes = int(rng.integers(3, 7))
    for _ in range(notes):
        nw = uniform(rng, 0.07, 0.15)
        nh = uniform(rng, 0.07, 0.15)
        yc = uniform(rng, -hw + f + 0.5 * nw + 0.01, hw - f - 0.5 * nw - 0.01)
        zc = uniform(rng, f + 0.5 * nh + 0.01, h - f - 0.5 * nh - 0.01)
        mat = pick(rng, (PAPER, TOY_YELLOW, SAGE_TOY, TOY_BLUE, WHITE_SHADE))
        parts.append(
            block(
                (cx, cx + 0.001),
                (yc - 0.5 * nw, yc + 0.5 * nw),
                (zc - 0.5 * nh, zc + 0.5 * nh),
                mat,
                collide=False,
            )
        )
        parts.append(
            block(
                (cx + 0.001, cx + 0.003),
                (yc - 0.004, yc + 0.004),
                (zc + 0.5 * nh - 0.02, zc + 0.5 * nh - 0.012),
                TOY_RED,
                collide=False,
            )
        )
    return Design(tuple(parts), {"frame": frame.words, "notes": count_word(notes)})
