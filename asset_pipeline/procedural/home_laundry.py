"""Generators of laundry and kitchen appliances and laundry aids (front +X).

Sizes are bounding boxes (x = depth, y = width, z = height); fronts face +X. Like every
asset they have their lowest point at z = 0 and stand upright on a flat bottom.
"""

from __future__ import annotations

from asset_pipeline.procedural.appliances import BLACK_APPLIANCE, OVEN_GLASS
from asset_pipeline.procedural.home_kit import (
    DARK_GREY,
    DRUM_GLASS,
    SOOT,
    WICKER,
)
from asset_pipeline.procedural.kit import (
    BLACK_METAL,
    BLACK_PLASTIC,
    BLUE_FABRIC,
    CHROME,
    FABRICS,
    GREEN_FABRIC,
    GREY_FABRIC,
    LINEN,
    OAK,
    RUG_RED,
    SCREEN,
    STEEL,
    WHITE_LACQUER,
    WHITE_PLASTIC,
    Rng,
    block,
    chance,
    clamp,
    pick,
    square_legs,
    uniform,
)
from asset_pipeline.procedural.parts import Part, RecipeMaterial, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.round_parts import Cylinder, Lathe

SEAGRASS = RecipeMaterial("seagrass", (0.62, 0.60, 0.42, 1.0), 0.05, 0.1, "woven seagrass")


# === laundry, kitchen appliances and utility ==================================================
def _laundry(size: Vec3, rng: Rng, dryer: bool) -> tuple[list[Part], dict[str, str]]:
    """A front-loading washer or dryer: a cabinet on feet (its top a surface), a control
    panel with a dial, a round door (a ring with a glass or solid centre) at +X."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, (WHITE_LACQUER, WHITE_LACQUER, STEEL, DARK_GREY))
    ring = pick(rng, (CHROME, DARK_GREY, WHITE_PLASTIC, BLACK_PLASTIC))
    face = hd - 0.045
    feet = 0.02
    parts: list[Part] = [
        *square_legs(d - 0.06, w - 0.06, feet, 0.04, BLACK_PLASTIC),
        block((-hd, face), (-hw, hw), (feet, h), finish, surface=True),
    ]
    panel = (h - 0.11, h - 0.01)
    zc = feet + 0.45 * (panel[0] - feet)
    radius = clamp(uniform(rng, 0.36, 0.42) * w, 0.15, 0.5 * (panel[0] - feet) - 0.01)
    parts.append(Cylinder((face + 0.015, 0.0, zc), radius, 0.015, ring, axis="x"))
    centre = pick(rng, (OVEN_GLASS, DRUM_GLASS)) if not dryer or chance(rng, 0.5) else finish
    parts.append(Cylinder((face + 0.0375, 0.0, zc), 0.72 * radius, 0.0075, centre, axis="x"))
    parts.append(
        block(
            (face + 0.03, face + 0.045),
            (radius - 0.02, radius + 0.01),
            (zc - 0.05, zc + 0.05),
            ring,
        )
    )
    dial_y = 0.25 * w
    parts.append(Cylinder((face + 0.01, dial_y, 0.5 * sum(panel)), 0.03, 0.01, ring, axis="x"))
    parts.append(
        block(
            (face, face + 0.003),
            (-0.05, 0.12),
            (panel[0] + 0.03, panel[1] - 0.03),
            SCREEN,
            collide=False,
        )
    )
    if not dryer:
        parts.append(
            block(
                (face, face + 0.012),
                (-hw + 0.03, -hw + 0.2),
                (panel[0] + 0.01, panel[1] - 0.01),
                finish,
            )
        )
    else:
        parts.append(
            block(
                (face, face + 0.004),
                (-hw + 0.05, hw - 0.05),
                (feet + 0.02, feet + 0.06),
                BLACK_PLASTIC,
                collide=False,
            )
        )
    words = {
        "finish": finish.words,
        "ring": ring.words,
        "door": "glass" if centre is not finish else "solid",
    }
    return parts, words


@category(
    "washing_machine",
    "furniture",
    size=(0.6, 0.6, 0.85),
    low=(0.5, 0.5, 0.8),
    high=(0.7, 0.7, 0.9),
    mass=70.0,
    friction=0.8,
    description="a {finish} front-loading washing machine with a {ring} door ring around a "
    "{door} porthole and a detergent drawer",
    variants=(None, (0.55, 0.6, 0.85), (0.65, 0.6, 0.88)),
)
def washing_machine(size: Vec3, rng: Rng) -> Design:
    """A front-loading washing machine (its top is a surface)."""
    parts, words = _laundry(size, rng, dryer=False)
    return Design(tuple(parts), words)


@category(
    "dryer",
    "furniture",
    size=(0.6, 0.6, 0.85),
    low=(0.5, 0.5, 0.8),
    high=(0.7, 0.7, 0.9),
    mass=40.0,
    friction=0.8,
    description="a {finish} front-loading tumble dryer with a {ring} door ring around a "
    "{door} door",
    variants=(None, (0.6, 0.6, 0.82), (0.65, 0.6, 0.88)),
)
def dryer(size: Vec3, rng: Rng) -> Design:
    """A tumble dryer (its top is a surface)."""
    parts, words = _laundry(size, rng, dryer=True)
    return Design(tuple(parts), words)


@category(
    "dishwasher",
    "furniture",
    size=(0.6, 0.6, 0.85),
    low=(0.55, 0.45, 0.8),
    high=(0.7, 0.65, 0.9),
    mass=45.0,
    friction=0.8,
    description="a built-in {finish} dishwasher with a {handle} handle and a control strip",
    variants=(None, (0.58, 0.45, 0.82), (0.62, 0.6, 0.88)),
)
def dishwasher(size: Vec3, rng: Rng) -> Design:
    """A built-in dishwasher: a tub (its top a surface), a full-height door with a control
    strip and a handle, and a recessed toe kick."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, (STEEL, WHITE_LACQUER, BLACK_APPLIANCE, OAK))
    handle = pick(rng, (CHROME, BLACK_METAL, STEEL))
    face = hd - 0.025 - 0.03
    kick = 0.1
    parts: list[Part] = [
        block((-hd, face - 0.05), (-hw, hw), (0.0, kick), BLACK_PLASTIC),
        block((-hd, face), (-hw, hw), (kick, h), finish, surface=True),
        block((face, face + 0.025), (-hw + 0.003, hw - 0.003), (kick, h - 0.003), finish),
        block(
            (face + 0.025, face + 0.027),
            (-hw + 0.02, hw - 0.02),
            (h - 0.07, h - 0.02),
            SCREEN,
            collide=False,
        ),
        block((face + 0.025, hd), (-0.3 * w, 0.3 * w), (h - 0.12, h - 0.1), handle),
    ]
    words = {"finish": "wood-panelled" if finish is OAK else finish.words, "handle": handle.words}
    return Design(tuple(parts), words)


@category(
    "ironing_board",
    "furniture",
    size=(0.35, 1.2, 0.9),
    low=(0.3, 0.9, 0.75),
    high=(0.45, 1.5, 1.0),
    mass=7.0,
    friction=0.7,
    description="a folding ironing board with a {cover} cover on {metal} legs",
    variants=(None, (0.32, 1.0, 0.8), (0.42, 1.4, 0.95)),
)
def ironing_board(size: Vec3, rng: Rng) -> Design:
    """An ironing board: a covered board (a surface) tapering to a nose at -Y, an iron rest
    at +Y, on two leg frames (a post on a foot bar along X)."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    cover = pick(rng, (BLUE_FABRIC, GREY_FABRIC, RUG_RED, LINEN, GREEN_FABRIC))
    metal = pick(rng, (CHROME, BLACK_METAL, WHITE_PLASTIC))
    bt = 0.03
    rest = 0.14
    y_end = hw - rest
    nose = 0.25 * w
    parts: list[Part] = [
        block((-hd, hd), (-hw + nose, y_end), (h - bt, h), cover, surface=True),
        block((-hd + 0.005, hd - 0.005), (y_end, hw), (h - bt, h - bt + 0.01), metal),
    ]
    steps = 3
    for i in range(steps):
        y0 = -hw + nose * i / steps
        half = hd * (0.45 + 0.55 * (i + 1) / (steps + 1))
        parts.append(block((-half, half), (y0, y0 + nose / steps), (h - bt, h), cover))
    for yc in (-0.28 * w, 0.28 * w):
        parts.append(block((-hd + 0.01, hd - 0.01), (yc - 0.015, yc + 0.015), (0.0, 0.025), metal))
        parts.append(block((-0.0125, 0.0125), (yc - 0.0125, yc + 0.0125), (0.025, h - bt), metal))
    return Design(tuple(parts), {"cover": cover.words, "metal": metal.words})


@category(
    "laundry_basket",
    "furniture",
    size=(0.35, 0.45, 0.55),
    low=(0.28, 0.3, 0.35),
    high=(0.5, 0.65, 0.7),
    mass=1.5,
    friction=0.8,
    description="a {material} laundry basket{lid}",
    variants=(None, (0.4, 0.4, 0.5), (0.45, 0.6, 0.6)),
)
def laundry_basket(size: Vec3, rng: Rng) -> Design:
    """A laundry basket: an open or lidded woven box with hand grips, maybe clothes inside;
    a square footprint may give a round tapered basket."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    mat = pick(rng, (WICKER, SEAGRASS, WHITE_PLASTIC, GREY_FABRIC))
    lid = chance(rng, 0.4)
    if abs(d - w) < 1e-3 and chance(rng, 0.5):
        r = hd
        parts: list[Part] = [
            Lathe((0.0, 0.0, 0.0), ((0.85 * r, 0.0), (r, h)), mat, hollow=(0.01, 0.015))
        ]
        if lid:
            parts[0] = Lathe((0.0, 0.0, 0.0), ((0.85 * r, 0.0), (r, h)), mat)
        return Design(tuple(parts), {"material": mat.words, "lid": " with a lid" if lid else ""})
    t = 0.012
    top = h - (0.03 if lid else 0.0)
    parts = [
        block((-hd, hd), (-hw, hw), (0.0, 0.015), mat),
        block((-hd, -hd + t), (-hw, hw), (0.015, top), mat),
        block((hd - t, hd), (-hw, hw), (0.015, top), mat),
        block((-hd + t, hd - t), (-hw, -hw + t), (0.015, top), mat),
        block((-hd + t, hd - t), (hw - t, hw), (0.015, top), mat),
    ]
    for sign in (-1.0, 1.0):
        y = sorted((sign * hw, sign * (hw - t - 0.001)))
        parts.append(
            block((-0.06, 0.06), (y[0], y[1]), (top - 0.08, top - 0.05), SOOT, collide=False)
        )
    if lid:
        parts.append(block((-hd, hd), (-hw, hw), (top, h), mat))
    elif chance(rng, 0.6):
        parts.append(
            block((-hd + t, hd - t), (-hw + t, hw - t), (0.015, 0.6 * top), pick(rng, FABRICS))
        )
    return Design(tuple(parts), {"material": mat.words, "lid": " with a lid" if lid else ""})
