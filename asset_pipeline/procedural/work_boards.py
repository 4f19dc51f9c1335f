"""Generators of work wall boards: chalkboards, screens, tool walls, eye charts.

Every generator fills exactly ``[-d/2, d/2] x [-w/2, w/2] x [0, h]`` (x = depth, y = width).
"""

from __future__ import annotations

from asset_pipeline.procedural.kit import (
    ALUMINIUM,
    BLACK_METAL,
    BLACK_PLASTIC,
    OAK,
    PAPER,
    PINE,
    STEEL,
    WALNUT,
    WHITE_PLASTIC,
    WHITEBOARD,
    WOODS,
    Rng,
    block,
    chance,
    clamp,
    pick,
    uniform,
)
from asset_pipeline.procedural.leisure_kit import (
    BLUE_PAINT,
    CHALK_BLACK,
    CHALK_WHITE,
    GREEN_PAINT,
    RED_PAINT,
    YELLOW_PAINT,
    frame_rect,
)
from asset_pipeline.procedural.parts import Part, RecipeMaterial, Vec3
from asset_pipeline.procedural.registry import Design, category

PEGBOARD = RecipeMaterial("pegboard", (0.62, 0.47, 0.30, 1.0), 0.1, 0.1, "brown pegboard")
WHITE_PEGBOARD = RecipeMaterial(
    "white_pegboard", (0.92, 0.92, 0.90, 1.0), 0.1, 0.1, "white pegboard"
)


# --- wall boards ------------------------------------------------------------------------------
@category(
    "chalkboard",
    "furniture",
    size=(0.04, 1.2, 0.9),
    low=(0.02, 0.6, 0.5),
    high=(0.1, 3.0, 1.4),
    mass=10.0,
    placement=("wall",),
    description="a {board} chalkboard in a {frame} frame with a chalk tray and writing on it",
    variants=(None, (0.04, 2.4, 1.2), (0.03, 0.8, 0.6)),
)
def chalkboard(size: Vec3, rng: Rng) -> Design:
    """A slate face in a frame as deep as the board; a chalk tray at the bottom; chalk lines."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    board = pick(
        rng,
        (CHALK_BLACK, RecipeMaterial("slate_green", (0.16, 0.28, 0.22, 1.0), 0.05, 0.1, "green")),
    )
    frame = pick(rng, (OAK, WALNUT, PINE, ALUMINIUM))
    f = clamp(0.04 * min(w, h), 0.02, 0.05)
    parts: list[Part] = [
        block((-hd, hd - 0.008), (-hw + f, hw - f), (f, h - f), board),
        *frame_rect((-hd, hd), (-hw, hw), (0.0, h), f, frame),
    ]
    lines = int(clamp((h - 2 * f - 0.15) // 0.08, 1, 10))
    for i in range(lines):
        z = h - f - 0.08 - i * 0.08
        length = (w - 2 * f - 0.1) * uniform(rng, 0.3, 0.8)
        y0 = -hw + f + 0.05
        parts.append(
            block(
                (hd - 0.008, hd - 0.007),
                (y0, y0 + length),
                (z - 0.012, z),
                CHALK_WHITE,
                collide=False,
            )
        )
    parts.append(block((hd - 0.004, hd), (-0.3 * w, 0.3 * w), (f, f + 0.012), frame))
    return Design(tuple(parts), {"board": board.words, "frame": frame.words})


@category(
    "projector_screen",
    "furniture",
    size=(0.08, 2.0, 1.5),
    low=(0.05, 1.2, 1.0),
    high=(0.15, 3.2, 2.2),
    mass=12.0,
    placement=("wall",),
    description="a white projection screen {style}",
    variants=(None, (0.1, 3.0, 1.8), (0.06, 1.5, 1.2)),
)
def projector_screen(size: Vec3, rng: Rng) -> Design:
    """A roll-down screen under its housing with a weighted bottom bar, or a fixed frame."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    rolled = chance(rng, 0.5)
    if rolled:
        case = pick(rng, (WHITE_PLASTIC, BLACK_METAL, ALUMINIUM))
        ch = clamp(0.08 * h, 0.08, 0.12)
        parts: list[Part] = [
            block((-hd, hd), (-hw, hw), (h - ch, h), case),
            block((-0.003, 0.003), (-hw + 0.05, hw - 0.05), (0.03, h - ch), WHITEBOARD),
            block((-0.003, 0.003), (-hw + 0.05, hw - 0.05), (h - ch - 0.15, h - ch), BLACK_PLASTIC),
            block((-hd, hd), (-hw + 0.04, hw - 0.04), (0.0, 0.03), case),
        ]
        return Design(tuple(parts), {"style": f"that rolls down from a {case.words} housing"})
    frame = pick(rng, (BLACK_PLASTIC, BLACK_METAL))
    f = clamp(0.05 * min(w, h), 0.05, 0.1)
    parts = [
        block((-hd, hd - 0.01), (-hw + f, hw - f), (f, h - f), WHITEBOARD),
        *frame_rect((-hd, hd), (-hw, hw), (0.0, h), f, frame),
    ]
    return Design(tuple(parts), {"style": "in a fixed black velvet frame"})


@category(
    "tool_wall",
    "furniture",
    size=(0.1, 2.0, 1.2),
    low=(0.05, 1.0, 0.6),
    high=(0.2, 3.0, 2.0),
    mass=25.0,
    placement=("wall",),
    description="a {board} tool wall hung with {count} hand tools",
    variants=(None, (0.12, 2.4, 1.5), (0.08, 1.2, 0.8)),
)
def tool_wall(size: Vec3, rng: Rng) -> Design:
    """A framed pegboard at -X and hand tools (hammers, wrenches, screwdrivers, saws) on it."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    board = pick(
        rng,
        (
            PEGBOARD,
            WHITE_PEGBOARD,
            RecipeMaterial("peg_grey", (0.35, 0.36, 0.38, 1.0), 0.3, 0.3, "grey steel pegboard"),
        ),
    )
    f = 0.03
    x0 = -hd + f
    parts: list[Part] = [
        block((-hd, x0), (-hw, hw), (0.0, h), board),
        *frame_rect((x0, hd), (-hw, hw), (0.0, h), f, WOODS[0]),
    ]
    tx = (x0 + 0.005, min(hd - 0.005, x0 + 0.06))
    cols = max(2, int((w - 2 * f) // 0.22))
    rows = max(1, int((h - 2 * f) // 0.4))
    cw, rh = (w - 2 * f) / cols, (h - 2 * f) / rows
    count = 0
    for i in range(rows):
        for j in range(cols):
            yc = -hw + f + (j + 0.5) * cw
            z0, z1 = f + i * rh + 0.04, f + (i + 1) * rh - 0.04
            kind = int(rng.integers(0, 4))
            handle = pick(rng, (RED_PAINT, BLUE_PAINT, YELLOW_PAINT, BLACK_PLASTIC))
            if kind == 0:  # hammer: handle and head
                parts.append(block(tx, (yc - 0.015, yc + 0.015), (z0, z1 - 0.04), handle))
                parts.append(block(tx, (yc - 0.06, yc + 0.06), (z1 - 0.04, z1), STEEL))
            elif kind == 1:  # wrench set
                for k in range(3):
                    y = yc - 0.06 + 0.06 * k
                    parts.append(block(tx, (y - 0.01, y + 0.01), (z0 + 0.03 * k, z1), STEEL))
            elif kind == 2:  # screwdrivers
                for k in range(3):
                    y = yc - 0.05 + 0.05 * k
                    parts.append(
                        block(tx, (y - 0.003, y + 0.003), (z0, z0 + 0.5 * (z1 - z0)), STEEL)
                    )
                    parts.append(
                        block(tx, (y - 0.012, y + 0.012), (z0 + 0.5 * (z1 - z0), z1), handle)
                    )
            else:  # saw
                parts.append(block(tx, (yc - 0.07, yc + 0.07), (z0, z1 - 0.06), STEEL))
                parts.append(block(tx, (yc - 0.05, yc + 0.05), (z1 - 0.06, z1), handle))
            count += 1
    return Design(tuple(parts), {"board": board.words, "count": str(count)})


@category(
    "eye_chart",
    "furniture",
    size=(0.02, 0.3, 0.6),
    low=(0.01, 0.2, 0.4),
    high=(0.06, 0.6, 1.2),
    mass=0.8,
    placement=("wall",),
    description="a {kind} eye test chart with rows of shrinking letters",
    variants=(None, (0.05, 0.35, 0.7), (0.015, 0.25, 0.5)),
)
def eye_chart(size: Vec3, rng: Rng) -> Design:
    """A white board with rows of black letter blocks, each row smaller, and red/green bars."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    lightbox = chance(rng, 0.5)
    case = pick(rng, (WHITE_PLASTIC, ALUMINIUM)) if lightbox else WHITE_PLASTIC
    parts: list[Part] = [block((-hd, hd - 0.001), (-hw, hw), (0.0, h), case)]
    if lightbox:
        parts.append(
            block(
                (hd - 0.0012, hd - 0.001),
                (-hw + 0.015, hw - 0.015),
                (0.015, h - 0.015),
                PAPER,
                collide=False,
            )
        )
    x = (hd - 0.001, hd)
    z = h - 0.04
    size_l = 0.14 * w * 0.6 / 0.3 if w < 0.3 else 0.084 * w / 0.3
    rows = 0
    n = 1
    while z - size_l > 0.1 and rows < 9:
        gap = 0.3 * size_l
        total = n * size_l + (n - 1) * gap
        if total > w - 0.04:
            break
        y0 = -0.5 * total
        for k in range(n):
            parts.append(
                block(
                    x,
                    (y0 + k * (size_l + gap), y0 + k * (size_l + gap) + size_l),
                    (z - size_l, z),
                    BLACK_PLASTIC,
                    collide=False,
                )
            )
        z -= size_l + 0.5 * size_l + 0.01
        size_l *= 0.75
        n += 1
        rows += 1
    parts.append(block(x, (-0.3 * w, 0.0), (0.03, 0.06), RED_PAINT, collide=False))
    parts.append(block(x, (0.0, 0.3 * w), (0.03, 0.06), GREEN_PAINT, collide=False))
    return Design(tuple(parts), {"kind": "backlit" if lightbox else "printed"})
