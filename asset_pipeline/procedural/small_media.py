"""Handheld and home electronics: phones, tablets, desk phones, radios, game consoles, record
players and headphones."""

from __future__ import annotations

from asset_pipeline.procedural.kit import (
    ALUMINIUM,
    BLACK_PLASTIC,
    CHROME,
    SCREEN,
    SPACE_GREY,
    WHITE_PLASTIC,
    WOODS,
    Rng,
    block,
    clamp,
    pick,
)
from asset_pipeline.procedural.parts import Part, RecipeMaterial, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.small_electronics import (
    LABEL,
    VINYL,
)
from asset_pipeline.procedural.small_kit import (
    CREAM_ENAMEL,
    DIAL,
    GOLD,
    GREY_PLASTIC,
    LED,
    NYLON_RED,
    OBJECT,
    RED_ENAMEL,
    cyl_x,
    cyl_y,
    cyl_z,
    deco,
    handle_arch,
)


# --- handheld and home electronics ----------------------------------------------------------------
def _slab_device(size: Vec3, rng: Rng, finishes: tuple[RecipeMaterial, ...]) -> Design:
    """A phone or tablet lying screen up: a slab, the screen inset on top."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, finishes)
    bezel = clamp(0.04 * min(d, w), 0.003, 0.012)
    parts: list[Part] = [
        block((-hd, hd), (-hw, hw), (0.0, h - 0.0005), finish),
        deco((-hd + bezel, hd - bezel), (-hw + bezel, hw - bezel), (h - 0.0005, h), SCREEN),
    ]
    return Design(tuple(parts), {"finish": finish.words})


@category(
    "phone",
    "object",
    size=(0.155, 0.075, 0.01),
    low=(0.11, 0.055, 0.006),
    high=(0.19, 0.095, 0.015),
    mass=0.2,
    placement=OBJECT,
    description="a {finish} smartphone lying flat",
    variants=(None, (0.14, 0.068, 0.008)),
)
def phone(size: Vec3, rng: Rng) -> Design:
    """A smartphone lying screen up."""
    return _slab_device(size, rng, (BLACK_PLASTIC, SPACE_GREY, ALUMINIUM, GOLD))


@category(
    "tablet",
    "object",
    size=(0.17, 0.25, 0.01),
    low=(0.12, 0.18, 0.006),
    high=(0.26, 0.34, 0.015),
    mass=0.5,
    placement=OBJECT,
    description="a {finish} tablet computer",
    variants=(None, (0.15, 0.21, 0.008)),
)
def tablet(size: Vec3, rng: Rng) -> Design:
    """A tablet lying screen up."""
    return _slab_device(size, rng, (BLACK_PLASTIC, SPACE_GREY, ALUMINIUM))


@category(
    "desk_phone",
    "object",
    size=(0.2, 0.2, 0.1),
    low=(0.14, 0.14, 0.06),
    high=(0.28, 0.3, 0.14),
    mass=1.0,
    placement=OBJECT,
    description="a {finish} office desk phone",
    variants=(None, (0.18, 0.22, 0.09)),
)
def desk_phone(size: Vec3, rng: Rng) -> Design:
    """A desk phone: base with a keypad at +X, a raised cradle at -X holding the handset."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, (BLACK_PLASTIC, GREY_PLASTIC, WHITE_PLASTIC))
    keys = SPACE_GREY if finish is BLACK_PLASTIC else BLACK_PLASTIC
    hx = (-hd + 0.05 * d, -0.05 * d)
    parts: list[Part] = [
        block((-hd, hd), (-hw, hw), (0.0, 0.4 * h), finish),
        block((-hd, 0.0), (-0.45 * w, 0.45 * w), (0.4 * h, 0.65 * h), finish),
        block(hx, (-0.45 * w, -0.3 * w), (0.65 * h, h), finish),
        block(hx, (0.3 * w, 0.45 * w), (0.65 * h, h), finish),
        block((hx[0] + 0.01, hx[1] - 0.01), (-0.3 * w, 0.3 * w), (0.82 * h, h), finish),
        deco((0.05 * d, 0.2 * d), (0.05 * w, 0.4 * w), (0.4 * h, 0.4 * h + 0.001), SCREEN),
    ]
    for i in range(4):
        for j in range(3):
            kx = 0.25 * d + i * 0.055 * d
            ky = -0.38 * w + j * 0.13 * w
            parts.append(
                deco((kx, kx + 0.04 * d), (ky, ky + 0.09 * w), (0.4 * h, 0.4 * h + 0.003), keys)
            )
    return Design(tuple(parts), {"finish": finish.words})


@category(
    "radio",
    "object",
    size=(0.12, 0.3, 0.18),
    low=(0.07, 0.18, 0.1),
    high=(0.2, 0.45, 0.28),
    mass=1.5,
    placement=OBJECT,
    description="a {finish} radio with a carrying handle",
    variants=(None, (0.1, 0.24, 0.15)),
)
def radio(size: Vec3, rng: Rng) -> Design:
    """A portable radio: cabinet, speaker grille and tuning dial on +X, a handle on top."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, (*WOODS[:2], CREAM_ENAMEL, BLACK_PLASTIC, RED_ENAMEL))
    body_h = 0.78 * h
    face = hd - 0.003
    grille_r = clamp(0.35 * body_h, 0.02, 0.3 * w)
    parts: list[Part] = [
        block((-hd, face), (-hw, hw), (0.0, body_h), finish),
        cyl_x(face, hd, -0.2 * w, 0.5 * body_h, grille_r, SPACE_GREY, collide=False),
        cyl_x(face, hd, 0.3 * w, 0.5 * body_h, clamp(0.15 * body_h, 0.01, 0.1 * w), CHROME,
              collide=False),
        deco((face, hd), (0.12 * w, 0.45 * w), (0.78 * body_h, 0.9 * body_h), DIAL),
        *handle_arch((-0.38 * w, 0.38 * w), (body_h, h), clamp(0.08 * (h - body_h) + 0.006,
                     0.006, 0.012), CHROME),
    ]  # fmt: skip
    return Design(tuple(parts), {"finish": finish.words})


@category(
    "game_console",
    "object",
    size=(0.25, 0.3, 0.08),
    low=(0.15, 0.18, 0.03),
    high=(0.35, 0.45, 0.12),
    mass=3.0,
    placement=OBJECT,
    description="a {finish} video game console",
    variants=(None, (0.2, 0.27, 0.05)),
)
def game_console(size: Vec3, rng: Rng) -> Design:
    """A console lying flat: a case with a contrasting top band, a disc slot and a light."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, (BLACK_PLASTIC, WHITE_PLASTIC, SPACE_GREY))
    band = BLACK_PLASTIC if finish is WHITE_PLASTIC else WHITE_PLASTIC
    face = hd - 0.002
    parts: list[Part] = [
        block((-hd, face), (-hw, hw), (0.0, 0.15 * h), BLACK_PLASTIC),
        block((-hd, face), (-hw, hw), (0.15 * h, 0.7 * h), finish),
        block((-hd, face), (-hw, hw), (0.7 * h, h), band),
        deco((face, hd), (-0.35 * w, 0.15 * w), (0.45 * h, 0.5 * h), BLACK_PLASTIC),
        deco((face, hd), (0.3 * w, 0.34 * w), (0.4 * h, 0.55 * h), LED),
    ]
    return Design(tuple(parts), {"finish": finish.words})


@category(
    "record_player",
    "object",
    size=(0.35, 0.42, 0.13),
    low=(0.25, 0.3, 0.08),
    high=(0.5, 0.55, 0.2),
    mass=5.5,
    placement=OBJECT,
    description="a record player with a {plinth} plinth",
    variants=(None, (0.33, 0.45, 0.11)),
)
def record_player(size: Vec3, rng: Rng) -> Design:
    """A turntable: plinth, platter with a record, and a tonearm on a post at +Y."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    plinth = pick(rng, (*WOODS[:2], BLACK_PLASTIC, ALUMINIUM))
    ph = 0.5 * h
    r = min(0.46 * d, 0.36 * w)
    py = -hw + 0.04 + r
    arm_y = hw - 0.05
    parts: list[Part] = [
        block((-hd, hd), (-hw, hw), (0.0, ph), plinth),
        cyl_z(0.0, py, ph, ph + 0.1 * h, r, CHROME),
        cyl_z(0.0, py, ph + 0.1 * h, ph + 0.1 * h + 0.002, 0.97 * r, VINYL, collide=False),
        cyl_z(0.0, py, ph + 0.1 * h + 0.002, ph + 0.1 * h + 0.003, 0.3 * r, LABEL, collide=False),
        cyl_z(-hd + 0.06, arm_y, ph, h - 0.006, 0.012, CHROME),
        block((-hd + 0.05, -hd + 0.07), (py + 0.6 * r, arm_y), (h - 0.006, h), CHROME),
        cyl_z(hd - 0.04, hw - 0.04, ph, ph + 0.01, 0.015, CHROME, collide=False),
    ]
    return Design(tuple(parts), {"plinth": plinth.words})


@category(
    "headphones",
    "object",
    size=(0.1, 0.18, 0.2),
    low=(0.07, 0.14, 0.14),
    high=(0.16, 0.26, 0.3),
    mass=0.6,
    placement=OBJECT,
    description="a pair of {finish} headphones on a stand",
    variants=(None, (0.09, 0.17, 0.24)),
)
def headphones(size: Vec3, rng: Rng) -> Design:
    """Over-ear headphones hanging on a small stand: base, post, headband and ear cups."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, (BLACK_PLASTIC, WHITE_PLASTIC, SPACE_GREY, NYLON_RED))
    stand = pick(rng, (*WOODS[:2], ALUMINIUM))
    band_t = 0.012
    cup_r = 0.45 * d
    cup_t = clamp(0.15 * w, 0.02, 0.04)
    zc = max(0.3 * h, 0.025 + cup_r)
    parts: list[Part] = [
        block((-hd, hd), (-0.3 * w, 0.3 * w), (0.0, 0.012), stand),
        cyl_z(0.0, 0.0, 0.012, h - band_t, 0.01, stand),
        block((-0.02, 0.02), (-hw + 0.5 * cup_t, hw - 0.5 * cup_t), (h - band_t, h), finish),
    ]
    for sign in (-1.0, 1.0):
        outer = sign * (hw - 0.5 * cup_t)
        bar = sorted((outer, outer - sign * 0.01))
        parts.append(block((-0.01, 0.01), (bar[0], bar[1]), (zc, h - band_t), finish))
        ys = sorted((sign * hw, sign * (hw - cup_t)))
        parts.append(cyl_y(ys[0], ys[1], 0.0, zc, cup_r, finish))
    return Design(tuple(parts), {"finish": finish.words})
