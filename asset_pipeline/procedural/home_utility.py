"""Generators of home utility and hallway pieces: radiators, bins, stands, mirrors (front +X).

Sizes are bounding boxes (x = depth, y = width, z = height); fronts face +X. Like every
asset they have their lowest point at z = 0 and stand upright on a flat bottom.
"""

from __future__ import annotations

from asset_pipeline.procedural.home_kit import (
    DARK_GREY,
    ROUND,
    WICKER,
    upright_rod,
)
from asset_pipeline.procedural.kit import (
    BLACK_METAL,
    BLACK_PLASTIC,
    BLUE_FABRIC,
    BRASS,
    CERAMIC_BLACK,
    CERAMIC_BLUE,
    CHARCOAL_FABRIC,
    CHROME,
    GREEN_FABRIC,
    LEATHER,
    PORCELAIN,
    RUG_RED,
    STEEL,
    WHITE_LACQUER,
    WHITE_PLASTIC,
    WOODS,
    Rng,
    block,
    chance,
    clamp,
    count_word,
    pick,
    uniform,
)
from asset_pipeline.procedural.parts import Part, RecipeMaterial, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.round_parts import Cylinder, Lathe

MAHOGANY = RecipeMaterial("mahogany", (0.45, 0.20, 0.12, 1.0), 0.3, 0.4, "mahogany")


@category(
    "radiator",
    "furniture",
    size=(0.12, 1.0, 0.6),
    low=(0.06, 0.4, 0.3),
    high=(0.2, 2.0, 1.0),
    mass=25.0,
    friction=0.8,
    description="a {finish} {kind} radiator on two feet with a {valve} valve",
    variants=(None, (0.1, 0.6, 0.5), (0.15, 1.4, 0.7)),
)
def radiator(size: Vec3, rng: Rng) -> Design:
    """A radiator standing on two feet: double panels with vertical flutes and a top grille,
    or columns joined by headers, and a valve at one end."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, (WHITE_LACQUER, WHITE_LACQUER, DARK_GREY, CHROME))
    valve = pick(rng, (CHROME, BRASS))
    foot = clamp(0.12 * h, 0.05, 0.12)
    parts: list[Part] = []
    for yc in (-hw + 0.12 * w, hw - 0.12 * w):
        parts.append(block((-hd, hd), (yc - 0.02, yc + 0.02), (0.0, foot + 0.02), finish))
    vy = (hw - 0.05, hw)
    parts.append(block((-0.015, 0.015), vy, (foot - 0.03, foot), valve))
    body_y = (-hw, hw - 0.05)
    kind = pick(rng, ("panel", "column"))
    if kind == "panel":
        pt = clamp(0.3 * d, 0.015, 0.04)
        for x in ((-hd + 0.005, -hd + 0.005 + pt), (hd - 0.005 - pt, hd - 0.005)):
            parts.append(block(x, body_y, (foot, h - 0.005), finish))
        parts.append(block((-hd + 0.005 + pt, hd - 0.005 - pt), body_y, (h - 0.02, h), finish))
        n = int((body_y[1] - body_y[0]) / 0.05)
        for i in range(n):
            y = body_y[0] + (i + 0.5) * (body_y[1] - body_y[0]) / n
            parts.append(
                block(
                    (hd - 0.005, hd),
                    (y - 0.008, y + 0.008),
                    (foot + 0.03, h - 0.03),
                    finish,
                    collide=False,
                )
            )
    else:
        n = int(clamp((body_y[1] - body_y[0]) / 0.07, 3, 22))
        pitch = (body_y[1] - body_y[0]) / n
        for i in range(n):
            y = body_y[0] + i * pitch
            parts.append(
                block((-hd + 0.01, hd - 0.01), (y + 0.008, y + pitch - 0.008), (foot, h), finish)
            )
        for z in ((foot, foot + 0.04), (h - 0.04, h)):
            parts.append(block((-0.02, 0.02), body_y, z, finish))
    words = {"finish": finish.words, "kind": kind, "valve": valve.words}
    return Design(tuple(parts), words)


@category(
    "trash_bin",
    "furniture",
    size=(0.4, 0.4, 0.75),
    low=(0.2, 0.2, 0.3),
    high=(0.5, 0.55, 0.85),
    mass=4.0,
    friction=0.7,
    description="a {finish} {kind}",
    variants=(None, (0.3, 0.3, 0.4), (0.35, 0.45, 0.7)),
)
def trash_bin(size: Vec3, rng: Rng) -> Design:
    """A bin: a round tapered pedal bin, an open round wastebasket, or a rectangular bin
    with a lid and a foot pedal at +X."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, (STEEL, WHITE_PLASTIC, BLACK_PLASTIC, CERAMIC_BLUE, CHROME))
    if abs(d - w) < 1e-3 and chance(rng, 0.6):
        r = hd
        if chance(rng, 0.6):
            parts: list[Part] = [
                Lathe((0.0, 0.0, 0.0), ((0.82 * r, 0.0), (r, h - 0.03)), finish),
                Lathe(
                    (0.0, 0.0, h - 0.03),
                    ((r, 0.0), (0.9 * r, 0.03)),
                    BLACK_PLASTIC if finish is not BLACK_PLASTIC else CHROME,
                ),
                block((0.7 * r, 0.995 * r), (-0.04, 0.04), (0.02, 0.035), BLACK_PLASTIC),
            ]
            return Design(
                tuple(parts), {"finish": finish.words, "kind": "round pedal bin with a lid"}
            )
        parts = [Lathe((0.0, 0.0, 0.0), ((0.8 * r, 0.0), (r, h)), finish, hollow=(0.006, 0.01))]
        return Design(tuple(parts), {"finish": finish.words, "kind": "round open wastebasket"})
    pedal = 0.03
    parts = [
        block((-hd, hd - pedal), (-hw, hw), (0.0, h - 0.03), finish),
        block(
            (-hd, hd - pedal + 0.005),
            (-hw, hw),
            (h - 0.03, h),
            BLACK_PLASTIC if finish is not BLACK_PLASTIC else STEEL,
        ),
        block((hd - pedal, hd), (-0.3 * hw, 0.3 * hw), (0.01, 0.03), BLACK_PLASTIC),
    ]
    return Design(
        tuple(parts), {"finish": finish.words, "kind": "rectangular pedal bin with a lid"}
    )


@category(
    "umbrella_stand",
    "furniture",
    size=(0.25, 0.25, 0.55),
    low=(0.18, 0.18, 0.4),
    high=(0.35, 0.35, 0.7),
    mass=3.0,
    friction=0.7,
    yx_ratio=(0.8, 1.25),
    description="a {finish} umbrella stand holding {count} folded umbrella{s}",
    variants=(None, (0.22, 0.22, 0.45), (0.3, 0.3, 0.65)),
)
def umbrella_stand(size: Vec3, rng: Rng) -> Design:
    """A hollow stand (round or square) with folded umbrellas whose crook handles stand out
    of the top."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, (CERAMIC_BLUE, CERAMIC_BLACK, BRASS, BLACK_METAL, PORCELAIN, WICKER))
    body_h = h - uniform(rng, 0.08, 0.12)
    parts: list[Part] = []
    if abs(d - w) < 1e-3 and chance(rng, 0.6):
        parts.append(
            Lathe((0.0, 0.0, 0.0), ((0.9 * hd, 0.0), (hd, body_h)), finish, hollow=(0.008, 0.015))
        )
        reach = 0.45 * hd
    else:
        t = 0.01
        parts += [
            block((-hd, hd), (-hw, hw), (0.0, 0.015), finish),
            block((-hd, -hd + t), (-hw, hw), (0.015, body_h), finish),
            block((hd - t, hd), (-hw, hw), (0.015, body_h), finish),
            block((-hd + t, hd - t), (-hw, -hw + t), (0.015, body_h), finish),
            block((-hd + t, hd - t), (hw - t, hw), (0.015, body_h), finish),
        ]
        reach = 0.5 * min(d, w) - 0.05
    count = int(rng.integers(1, 4))
    spots = ((0.0, -reach * 0.6), (0.0, reach * 0.6), (reach * 0.6, 0.0))[:count]
    for k, (x, y) in enumerate(spots):
        fabric = pick(rng, (BLUE_FABRIC, CHARCOAL_FABRIC, RUG_RED, GREEN_FABRIC))
        top = h - 0.015 - 0.01 * k
        parts.append(
            block((x - 0.02, x + 0.02), (y - 0.02, y + 0.02), (0.015, body_h - 0.05), fabric)
        )
        parts.append(
            block(
                (x - 0.006, x + 0.006), (y - 0.006, y + 0.006), (body_h - 0.05, top), BLACK_PLASTIC
            )
        )
        parts.append(
            block(
                (x - 0.006, x + 0.006),
                (y - 0.006, y + 0.05 if y <= 0 else y + 0.006),
                (top, top + 0.015),
                LEATHER,
            )
        )
    return Design(
        tuple(parts),
        {"finish": finish.words, "count": count_word(count), "s": "s" if count > 1 else ""},
    )


@category(
    "coat_rack",
    "furniture",
    size=(0.5, 0.5, 1.8),
    low=(0.35, 0.35, 1.5),
    high=(0.7, 0.7, 2.0),
    mass=6.0,
    friction=0.7,
    yx_ratio=ROUND,
    description="a freestanding {material} coat rack with {hooks} hooks on {base}",
    variants=(None, (0.4, 0.4, 1.7), (0.6, 0.6, 1.9)),
)
def coat_rack(size: Vec3, rng: Rng) -> Design:
    """A coat stand: a pole on a cross of feet or a heavy disc, hooks near the top."""
    d, _, h = size
    r = 0.5 * d
    mat = pick(rng, (*WOODS, BLACK_METAL, CHROME))
    base = pick(rng, ("cross feet", "a round base"))
    parts: list[Part] = [
        upright_rod(0.0, h - 0.03, 0.022, mat),
        upright_rod(h - 0.03, h, 0.03, mat),
    ]
    if base == "cross feet":
        parts.append(block((-r, r), (-0.025, 0.025), (0.0, 0.04), mat))
        parts.append(block((-0.025, 0.025), (-r, r), (0.0, 0.04), mat))
    else:
        parts.append(
            Cylinder((0.0, 0.0, 0.0125), r, 0.0125, BLACK_METAL if mat is not CHROME else CHROME)
        )
    reach = min(0.6 * r, 0.2)
    tiers = (h - 0.12, h - 0.35) if chance(rng, 0.5) else (h - 0.12,)
    hooks = 0
    for z in tiers:
        for ax, sign in (("x", 1.0), ("x", -1.0), ("y", 1.0), ("y", -1.0)):
            a = sorted((sign * 0.02, sign * reach))
            b = sorted((sign * (reach - 0.015), sign * reach))
            if ax == "x":
                parts.append(block((a[0], a[1]), (-0.008, 0.008), (z - 0.012, z), mat))
                parts.append(block((b[0], b[1]), (-0.008, 0.008), (z, z + 0.05), mat))
            else:
                parts.append(block((-0.008, 0.008), (a[0], a[1]), (z - 0.012, z), mat))
                parts.append(block((-0.008, 0.008), (b[0], b[1]), (z, z + 0.05), mat))
            hooks += 1
    return Design(tuple(parts), {"material": mat.words, "hooks": count_word(hooks), "base": base})
