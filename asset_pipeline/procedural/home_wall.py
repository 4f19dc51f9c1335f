"""Generators of home wall pieces: curtains, blinds, clocks, sconces, hooks (back at -X).

Wall pieces (placement ``wall``) have their back at -X; like every asset they have their lowest
point at z = 0 and stand upright on a flat bottom.
"""

from __future__ import annotations

from asset_pipeline.procedural.home_kit import (
    CLOCK_FACE,
    FABRIC_SHADES,
    IVORY_FACE,
    OPAL_GLASS,
)
from asset_pipeline.procedural.kit import (
    ALUMINIUM,
    BLACK_METAL,
    BLACK_PLASTIC,
    BRASS,
    CANVAS_WARM,
    CHROME,
    FABRICS,
    GILT,
    LINEN,
    RUG_RED,
    WAX,
    WHITE_PLASTIC,
    WHITE_SHADE,
    WOODS,
    Rng,
    block,
    chance,
    clamp,
    pick,
    uniform,
)
from asset_pipeline.procedural.parts import Box, Part, RecipeMaterial, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.round_parts import Cylinder, Lathe

WALL = ("wall",)
CORK = RecipeMaterial("cork", (0.70, 0.53, 0.35, 1.0), 0.05, 0.1, "cork")
CURTAIN_FABRICS = (*FABRICS, LINEN, RUG_RED, CANVAS_WARM)


# === wall pieces (back at -X) =================================================================
def _pleated_panel(
    y: tuple[float, float], z: tuple[float, float], xc: float, depth: float, fabric: RecipeMaterial
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
