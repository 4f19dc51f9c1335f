"""Generators of leisure wall decor: dartboards, neon signs, menu boards, panels.

Every generator fills exactly ``[-d/2, d/2] x [-w/2, w/2] x [0, h]`` (x = depth, y = width).
"""

from __future__ import annotations

from asset_pipeline.procedural.kit import (
    ALUMINIUM,
    ASH,
    BLACK_METAL,
    BLACK_PLASTIC,
    CHARCOAL_FABRIC,
    FABRICS,
    OAK,
    WALNUT,
    WHITE_PLASTIC,
    WOODS,
    Rng,
    block,
    chance,
    clamp,
    pick,
    uniform,
)
from asset_pipeline.procedural.leisure_kit import (
    CHALK_BLACK,
    CHALK_WHITE,
    GREEN_PAINT,
    RED_PAINT,
    SISAL,
    frame_rect,
    rod,
)
from asset_pipeline.procedural.parts import Part, RecipeMaterial, Vec3
from asset_pipeline.procedural.registry import Design, category

GLOW_PINK = RecipeMaterial("glow_pink", (1.00, 0.30, 0.70, 1.0), 1.0, 1.0, "pink")
GLOW_BLUE = RecipeMaterial("glow_blue", (0.30, 0.75, 1.00, 1.0), 1.0, 1.0, "blue")
GLOW_GREEN = RecipeMaterial("glow_green", (0.40, 1.00, 0.45, 1.0), 1.0, 1.0, "green")
GLOW_ORANGE = RecipeMaterial("glow_orange", (1.00, 0.55, 0.15, 1.0), 1.0, 1.0, "orange")
ACRYLIC = RecipeMaterial("acrylic", (0.90, 0.92, 0.94, 0.35), 0.9, 0.9, "clear acrylic")
CORK = RecipeMaterial("cork", (0.70, 0.52, 0.34, 1.0), 0.05, 0.1, "cork")
NEONS = (GLOW_PINK, GLOW_BLUE, GLOW_GREEN, GLOW_ORANGE)


# --- wall decor ------------------------------------------------------------------------------
@category(
    "dartboard",
    "furniture",
    size=(0.05, 0.5, 0.5),
    low=(0.03, 0.35, 0.35),
    high=(0.12, 0.8, 0.8),
    mass=5.0,
    placement=("wall",),
    description="a bristle dartboard on a {back} backboard",
    variants=(None, (0.06, 0.6, 0.6), (0.04, 0.45, 0.5)),
)
def dartboard(size: Vec3, rng: Rng) -> Design:
    """A square backboard at -X and a round board with coloured rings facing +X."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    back = pick(rng, (CORK, WALNUT, BLACK_PLASTIC, OAK))
    board_t = clamp(0.6 * d, 0.015, 0.04)
    xb = hd - board_t
    f = 0.025  # a cabinet-style surround, as deep as the board
    radius = min(0.5 * min(w, h) - f - 0.005, 0.23)
    zc = 0.5 * h
    parts: list[Part] = [
        block((-hd, xb), (-hw, hw), (0.0, h), back),
        rod("x", xb, hd - 0.002, 0.0, zc, radius, BLACK_PLASTIC),
        *frame_rect((xb, hd), (-hw, hw), (0.0, h), f, back),
    ]
    rings = (
        (0.75, RED_PAINT),
        (0.7, SISAL),
        (0.45, GREEN_PAINT),
        (0.41, SISAL),
        (0.08, GREEN_PAINT),
        (0.035, RED_PAINT),
    )
    for k, (fraction, mat) in enumerate(rings):
        x0 = hd - 0.002 + 0.0003 * k
        parts.append(rod("x", x0, x0 + 0.0003, 0.0, zc, fraction * radius, mat, collide=False))
    return Design(tuple(parts), {"back": back.words})


_SEGMENTS = {  # seven-segment letters: a top, b top right, c bottom right, d bottom, e f g
    "O": "abcdef", "P": "abefg", "E": "adefg", "N": "abcef", "C": "adef", "A": "abcefg",
    "F": "aefg", "B": "cdefg", "R": "eg", "U": "bcdef", "H": "bcefg", "L": "def",
}  # fmt: skip
_WORDS = ("OPEN", "CAFE", "BAR", "PUB", "HELLO", "FUN")


def _letter(
    ch: str,
    x: tuple[float, float],
    y0: float,
    lw: float,
    z0: float,
    lh: float,
    t: float,
    mat: RecipeMaterial,
) -> list[Part]:
    """The strokes of a seven-segment letter in the plane slab ``x``."""
    zm, z1 = z0 + 0.5 * lh, z0 + lh
    y1 = y0 + lw
    bars = {
        "a": ((y0, y1), (z1 - t, z1)), "d": ((y0, y1), (z0, z0 + t)),
        "g": ((y0, y1), (zm - 0.5 * t, zm + 0.5 * t)),
        "b": ((y1 - t, y1), (zm, z1)), "c": ((y1 - t, y1), (z0, zm)),
        "f": ((y0, y0 + t), (zm, z1)), "e": ((y0, y0 + t), (z0, zm)),
    }  # fmt: skip
    segs = _SEGMENTS.get(ch, "adg")
    return [block(x, bars[s][0], bars[s][1], mat) for s in segs]


@category(
    "neon_sign",
    "furniture",
    size=(0.05, 0.8, 0.4),
    low=(0.03, 0.3, 0.2),
    high=(0.12, 1.6, 0.9),
    mass=4.0,
    placement=("wall",),
    description='a glowing {colour} neon sign reading "{text}" on a {panel} panel',
    variants=(None, (0.06, 1.2, 0.5), (0.04, 0.5, 0.3)),
)
def neon_sign(size: Vec3, rng: Rng) -> Design:
    """A backing panel at -X with neon-tube letters standing proud of it towards +X."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    colour = pick(rng, NEONS)
    panel = pick(rng, (ACRYLIC, BLACK_PLASTIC))
    fits = [word for word in _WORDS if w / len(word) >= 0.9 * h * 0.45] or ["BAR"]
    text = pick(rng, fits)
    panel_t = clamp(0.4 * d, 0.01, 0.03)
    xt = (-hd + panel_t, hd)
    n = len(text)
    margin = 0.05 * w
    pitch = (w - 2 * margin) / n
    lw = 0.75 * pitch
    lh = h - 2 * clamp(0.12 * h, 0.03, 0.1)
    lw = min(lw, 0.7 * lh)
    t = clamp(0.1 * lh, 0.01, 0.025)
    rail = 0.015  # mounting rails as deep as the sign keep the letters off whatever is below
    parts: list[Part] = [
        block((-hd, -hd + panel_t), (-hw, hw), (0.0, h), panel),
        block((-hd + panel_t, hd), (-hw, hw), (0.0, rail), panel),
        block((-hd + panel_t, hd), (-hw, hw), (h - rail, h), panel),
    ]
    start = -0.5 * (n * pitch) + 0.5 * (pitch - lw)
    for k, ch in enumerate(text):
        parts += _letter(ch, xt, start + k * pitch, lw, 0.5 * (h - lh), lh, t, colour)
    return Design(tuple(parts), {"colour": colour.words, "text": text, "panel": panel.words})


@category(
    "menu_board",
    "furniture",
    size=(0.04, 1.0, 0.7),
    low=(0.02, 0.5, 0.4),
    high=(0.1, 2.0, 1.2),
    mass=6.0,
    placement=("wall",),
    description="a {board} menu board with a {frame} frame, a title and {columns} of dishes "
    "and prices",
    variants=(None, (0.04, 1.5, 0.9), (0.03, 0.6, 0.8)),
)
def menu_board(size: Vec3, rng: Rng) -> Design:
    """A framed board with a title bar and lines of menu items and prices (flush strokes)."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    board, ink = pick(
        rng,
        (
            (CHALK_BLACK, CHALK_WHITE),
            (WHITE_PLASTIC, BLACK_PLASTIC),
            (
                RecipeMaterial("menu_green", (0.14, 0.26, 0.2, 1.0), 0.05, 0.1, "dark green"),
                CHALK_WHITE,
            ),
        ),
    )
    frame = pick(rng, (*WOODS[:2], BLACK_METAL, ALUMINIUM))
    f = clamp(0.04 * min(w, h), 0.015, 0.05)
    xf = (hd - 0.003, hd - 0.002)
    parts: list[Part] = [
        block((-hd, hd - 0.003), (-hw + f, hw - f), (f, h - f), board),
        *frame_rect((-hd, hd), (-hw, hw), (0.0, h), f, frame),
    ]
    title_h = 0.12 * h
    parts.append(
        block(xf, (-0.3 * w, 0.3 * w), (h - f - 0.04 - title_h, h - f - 0.04), ink, collide=False)
    )
    columns = 2 if w >= 0.8 else 1
    col_w = (w - 2 * f - 0.06 * (columns + 1)) / columns
    lines = int(clamp((h - 2 * f - title_h - 0.1) // 0.06, 2, 12))
    for c in range(columns):
        y0 = -hw + f + 0.06 + c * (col_w + 0.06)
        for i in range(lines):
            z = h - f - title_h - 0.1 - i * 0.06
            item = col_w * uniform(rng, 0.45, 0.7)
            parts.append(block(xf, (y0, y0 + item), (z - 0.015, z), ink, collide=False))
            parts.append(
                block(
                    xf, (y0 + col_w - 0.12 * col_w, y0 + col_w), (z - 0.015, z), ink, collide=False
                )
            )
    words = {
        "board": board.words,
        "frame": frame.words,
        "columns": "two columns" if columns == 2 else "a column",
    }
    return Design(tuple(parts), words)


@category(
    "acoustic_panel",
    "furniture",
    size=(0.05, 0.6, 1.2),
    low=(0.025, 0.3, 0.3),
    high=(0.12, 1.2, 2.4),
    mass=2.5,
    placement=("wall",),
    description="a {fabric} acoustic panel{style}",
    variants=(None, (0.05, 1.2, 0.6), (0.04, 0.6, 0.6)),
)
def acoustic_panel(size: Vec3, rng: Rng) -> Design:
    """A fabric-wrapped absorber: plain with a bevelled face, or wooden slats over felt."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    fabric = pick(rng, (*FABRICS, CHARCOAL_FABRIC))
    slats = chance(rng, 0.4)
    if slats:
        wood = pick(rng, (OAK, WALNUT, ASH))
        back = 0.5 * d
        parts: list[Part] = [block((-hd, -hd + back), (-hw, hw), (0.0, h), fabric)]
        n = max(3, int(w // 0.045))
        pitch = w / n
        for k in range(n):
            y = -hw + k * pitch
            parts.append(block((-hd + back, hd), (y + 0.004, y + pitch - 0.004), (0.0, h), wood))
        return Design(
            tuple(parts), {"fabric": fabric.words, "style": f" with {wood.words} slats over felt"}
        )
    bevel = clamp(0.2 * d, 0.005, 0.015)
    parts = [
        block((-hd, hd - bevel), (-hw, hw), (0.0, h), fabric),
        block((hd - bevel, hd), (-hw + bevel, hw - bevel), (bevel, h - bevel), fabric),
    ]
    return Design(tuple(parts), {"fabric": fabric.words, "style": " with bevelled edges"})
