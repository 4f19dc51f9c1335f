"""Wall fittings: towel rails, coat hooks, range hoods, tapestries and pin boards."""

from __future__ import annotations

from asset_pipeline.procedural.appliances import BLACK_APPLIANCE
from asset_pipeline.procedural.home_kit import (
    DRUM_GLASS,
    SAGE_TOY,
)
from asset_pipeline.procedural.home_wall import (
    CORK,
    WALL,
)
from asset_pipeline.procedural.kit import (
    ALUMINIUM,
    BLACK_METAL,
    BLACK_PLASTIC,
    BLUE_FABRIC,
    BRASS,
    CHARCOAL_FABRIC,
    CHROME,
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
    WHITE_LACQUER,
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
from asset_pipeline.procedural.parts import Part, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.round_parts import Cylinder


# --- towel rails, hooks, hoods and hangings -------------------------------------------------------
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
        for rail in ((0.0, 0.025), (h - 0.04, h - 0.015)):
            parts.append(block((-hd, xc - 0.5 * ts), (y[0] + 0.005, y[1] - 0.005), rail, metal))
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
