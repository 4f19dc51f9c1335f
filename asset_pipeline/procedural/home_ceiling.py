"""Generators of home ceiling pieces: pendant lights, chandeliers, fans, lanterns.

Ceiling pieces (placement ``ceiling``) are hung by the layout so that the top of the box
touches the ceiling, so their cord, rod or canopy reaches the top; like every asset they
have their lowest point at z = 0 and stand upright on a flat bottom.
"""

from __future__ import annotations

from asset_pipeline.procedural.home_kit import (
    DRUM_GLASS,
    FABRIC_SHADES,
    OPAL_GLASS,
    ROUND,
    WICKER,
    upright_rod,
)
from asset_pipeline.procedural.kit import (
    BLACK_METAL,
    BLACK_PLASTIC,
    BRASS,
    CERAMIC_GREEN,
    CHROME,
    CLEAR_GLASS,
    GILT,
    LAMP_SHADE,
    METALS,
    WAX,
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

CEILING = ("ceiling",)
CRYSTAL = RecipeMaterial("crystal", (0.90, 0.94, 0.98, 0.7), 1.0, 1.0, "crystal")


def ceiling_canopy(h: float, radius: float, material: RecipeMaterial, t: float = 0.025) -> Cylinder:
    """The ceiling canopy (rose) of a hanging light: a disc whose top is the box's top."""
    return Cylinder((0.0, 0.0, h - 0.5 * t), radius, 0.5 * t, material)


# === ceiling pieces (top at the ceiling, z = 0 their lowest point) =============================
@category(
    "pendant_light",
    "furniture",
    size=(0.4, 0.4, 0.5),
    low=(0.15, 0.15, 0.25),
    high=(0.7, 0.7, 1.5),
    mass=2.0,
    friction=0.7,
    placement=CEILING,
    yx_ratio=ROUND,
    description="a pendant light with a {shade} {shape} shade on a {cord} cord",
    variants=(None, (0.3, 0.3, 0.8), (0.55, 0.55, 0.7)),
)
def pendant_light(size: Vec3, rng: Rng) -> Design:
    """A pendant: a ceiling canopy, a cord and a shade (dome, drum, cone or globe) with a
    flat open bottom."""
    d, _, h = size
    r = 0.5 * d
    shape = pick(rng, ("dome", "drum", "cone", "globe"))
    mat = {
        "dome": pick(rng, (*METALS, CERAMIC_GREEN, WHITE_LACQUER)),
        "drum": pick(rng, FABRIC_SHADES),
        "cone": pick(rng, (BLACK_METAL, BRASS, WICKER, WHITE_LACQUER)),
        "globe": pick(rng, (OPAL_GLASS, CLEAR_GLASS, DRUM_GLASS)),
    }[shape]
    cord = pick(rng, (BLACK_PLASTIC, WHITE_PLASTIC, BRASS))
    sh = clamp(uniform(rng, 0.5, 0.75) * d, 0.1, h - 0.08)
    profile = {
        "dome": ((1.0, 0.0), (0.96, 0.3), (0.8, 0.6), (0.45, 0.88), (0.12, 1.0)),
        "drum": ((1.0, 0.0), (1.0, 1.0)),
        "cone": ((1.0, 0.0), (0.12, 1.0)),
        "globe": ((0.45, 0.0), (0.88, 0.2), (1.0, 0.5), (0.88, 0.8), (0.3, 1.0)),
    }[shape]
    parts: list[Part] = [
        Lathe((0.0, 0.0, 0.0), tuple((f * r, z * sh) for f, z in profile), mat),
        upright_rod(sh - 0.005, h - 0.02, 0.004, cord),
        ceiling_canopy(h, min(0.05, r), cord if cord is not WHITE_PLASTIC else WHITE_LACQUER, 0.02),
    ]
    return Design(tuple(parts), {"shade": mat.words, "shape": shape, "cord": cord.words})


@category(
    "chandelier",
    "furniture",
    size=(0.8, 0.8, 0.7),
    low=(0.4, 0.4, 0.4),
    high=(1.4, 1.4, 1.5),
    mass=12.0,
    friction=0.7,
    placement=CEILING,
    yx_ratio=ROUND,
    description="a {metal} chandelier with {lights} {kind} on {tiers} and {crystal}",
    variants=(None, (1.2, 1.2, 1.1), (0.6, 0.6, 0.55)),
)
def chandelier(size: Vec3, rng: Rng) -> Design:
    """A chandelier: a turned central column on a flat bottom bowl, four arms (one or two
    tiers) ending in cups with candle bulbs or small shades, crystal drops, and a chain up
    to a canopy."""
    d, _, h = size
    r = 0.5 * d
    metal = pick(rng, (BRASS, GILT, BLACK_METAL, CHROME))
    bowl_r = clamp(0.14 * d, 0.06, 0.14)
    bowl_h = clamp(0.1 * h, 0.04, 0.1)
    col_top = clamp(0.55 * h, bowl_h + 0.15, h - 0.08)
    parts: list[Part] = [
        Lathe(
            (0.0, 0.0, 0.0),
            ((0.6 * bowl_r, 0.0), (bowl_r, 0.6 * bowl_h), (0.4 * bowl_r, bowl_h)),
            metal,
        ),
        upright_rod(bowl_h, col_top, clamp(0.03 * d, 0.015, 0.035), metal),
        upright_rod(col_top, h - 0.03, 0.008, metal),
        ceiling_canopy(h, clamp(0.1 * d, 0.05, 0.1), metal, 0.03),
    ]
    kind = pick(rng, ("candle bulbs", "small shades"))
    crystal = chance(rng, 0.6)
    tiers = [(bowl_h + 0.04, r)]
    if h >= 0.55 and chance(rng, 0.5):
        tiers.append((bowl_h + 0.04 + 0.4 * (col_top - bowl_h), 0.6 * r))
    cup_r, cup_h = clamp(0.05 * d, 0.025, 0.05), 0.025
    lights = 0
    for z_arm, reach in tiers:
        tip = reach - cup_r
        cand_h = min(0.12, col_top - z_arm - cup_h - 0.01)
        for ax, sign in (("x", 1.0), ("x", -1.0), ("y", 1.0), ("y", -1.0)):
            a = sorted((0.0, sign * tip))
            c = (sign * tip, 0.0) if ax == "x" else (0.0, sign * tip)
            arm = ((a[0], a[1]), (-0.008, 0.008)) if ax == "x" else ((-0.008, 0.008), (a[0], a[1]))
            parts.append(block(arm[0], arm[1], (z_arm - 0.016, z_arm), metal))
            top = z_arm + cup_h
            if kind == "candle bulbs":
                parts.append(
                    block(
                        (c[0] - cup_r, c[0] + cup_r),
                        (c[1] - cup_r, c[1] + cup_r),
                        (z_arm, top),
                        metal,
                    )
                )
                parts.append(Cylinder((c[0], c[1], top + 0.5 * cand_h), 0.012, 0.5 * cand_h, WAX))
            else:
                parts.append(
                    Lathe(
                        (c[0], c[1], top),
                        ((cup_r, 0.0), (0.7 * cup_r, min(cand_h, 0.08))),
                        LAMP_SHADE,
                    )
                )
            if crystal:
                mid = 0.5 * sign * tip
                xy = (mid, 0.0) if ax == "x" else (0.0, mid)
                parts.append(
                    block(
                        (xy[0] - 0.006, xy[0] + 0.006),
                        (xy[1] - 0.006, xy[1] + 0.006),
                        (z_arm - 0.016 - 0.05, z_arm - 0.016),
                        CRYSTAL,
                        collide=False,
                    )
                )
            lights += 1
    words = {
        "metal": metal.words,
        "lights": count_word(lights),
        "kind": kind,
        "tiers": "two tiers of arms" if len(tiers) == 2 else "four arms",
        "crystal": "hanging crystal drops" if crystal else "a turned central column",
    }
    return Design(tuple(parts), words)


@category(
    "ceiling_fan",
    "furniture",
    size=(1.3, 1.3, 0.4),
    low=(0.8, 0.8, 0.25),
    high=(1.6, 1.6, 0.8),
    mass=7.0,
    friction=0.7,
    placement=CEILING,
    yx_ratio=ROUND,
    description="a ceiling fan with four {blades} blades, a {metal} motor housing{light}",
    variants=(None, (1.1, 1.1, 0.35), (1.5, 1.5, 0.6)),
)
def ceiling_fan(size: Vec3, rng: Rng) -> Design:
    """A ceiling fan: a canopy, a downrod, a motor housing, four blades along ±X and ±Y on
    blade irons, and maybe a light kit bowl under the motor (the flat bottom)."""
    d, _, h = size
    r = 0.5 * d
    blades = pick(rng, (*WOODS, WHITE_LACQUER, BLACK_METAL))
    metal = pick(rng, (BLACK_METAL, CHROME, BRASS, WHITE_LACQUER))
    canopy_t = 0.04
    motor_h = clamp(0.3 * h, 0.07, 0.14)
    light = h - canopy_t - motor_h >= 0.14 and chance(rng, 0.6)
    lk = 0.08 if light else 0.0
    motor_r = clamp(0.08 * d, 0.08, 0.12)
    z_m = lk
    parts: list[Part] = [
        Cylinder((0.0, 0.0, z_m + 0.5 * motor_h), motor_r, 0.5 * motor_h, metal),
        upright_rod(z_m + motor_h, h - canopy_t, 0.013, metal),
        ceiling_canopy(h, 0.07, metal, canopy_t),
    ]
    if light:
        parts.append(
            Lathe(
                (0.0, 0.0, 0.0),
                ((0.5 * motor_r, 0.0), (0.9 * motor_r, 0.5 * lk), (motor_r, lk)),
                OPAL_GLASS,
            )
        )
    zb = z_m + 0.5 * motor_h
    bw = clamp(0.11 * d, 0.1, 0.16)
    for ax, sign in (("x", 1.0), ("x", -1.0), ("y", 1.0), ("y", -1.0)):
        blade = sorted((sign * (motor_r + 0.08), sign * r))
        iron = sorted((sign * (0.7 * motor_r), sign * (motor_r + 0.1)))
        if ax == "x":
            parts.append(
                block((blade[0], blade[1]), (-0.5 * bw, 0.5 * bw), (zb - 0.006, zb + 0.006), blades)
            )
            parts.append(
                block((iron[0], iron[1]), (-0.015, 0.015), (zb + 0.006, zb + 0.014), metal)
            )
        else:
            parts.append(
                block((-0.5 * bw, 0.5 * bw), (blade[0], blade[1]), (zb - 0.006, zb + 0.006), blades)
            )
            parts.append(
                block((-0.015, 0.015), (iron[0], iron[1]), (zb + 0.006, zb + 0.014), metal)
            )
    words = {
        "blades": blades.words,
        "metal": metal.words,
        "light": " and an opal glass light kit" if light else "",
    }
    return Design(tuple(parts), words)


@category(
    "ceiling_light",
    "furniture",
    size=(0.4, 0.4, 0.12),
    low=(0.2, 0.2, 0.06),
    high=(0.7, 0.7, 0.3),
    mass=1.5,
    friction=0.7,
    placement=CEILING,
    yx_ratio=ROUND,
    description="a flush-mounted ceiling light with a {diffuser} {shape}",
    variants=(None, (0.3, 0.3, 0.1), (0.55, 0.55, 0.15)),
)
def ceiling_light(size: Vec3, rng: Rng) -> Design:
    """A flush mount: a base plate at the top and an opal dome, a fabric drum or a flat
    LED panel below it (a flat bottom)."""
    d, _, h = size
    r = 0.5 * d
    shape = pick(rng, ("dome", "drum", "flat panel"))
    trim = pick(rng, (WHITE_LACQUER, CHROME, BRASS, BLACK_METAL))
    plate = 0.015
    if shape == "dome":
        dh = h - plate
        mat = pick(rng, (OPAL_GLASS, CLEAR_GLASS))
        parts: list[Part] = [
            Lathe((0.0, 0.0, 0.0), ((0.45 * r, 0.0), (0.8 * r, 0.45 * dh), (r, dh)), mat),
            Cylinder((0.0, 0.0, h - 0.5 * plate), 0.95 * r, 0.5 * plate, trim),
        ]
    elif shape == "drum":
        mat = pick(rng, FABRIC_SHADES)
        parts = [
            Lathe((0.0, 0.0, 0.0), ((r, 0.0), (r, h - plate)), mat),
            Cylinder((0.0, 0.0, h - 0.5 * plate), 0.9 * r, 0.5 * plate, trim),
        ]
    else:
        mat = OPAL_GLASS
        pt = clamp(0.3 * h, 0.02, 0.04)
        parts = [
            Cylinder((0.0, 0.0, 0.5 * pt), r, 0.5 * pt, mat),
            Cylinder((0.0, 0.0, 0.5 * (pt + h)), 0.6 * r, 0.5 * (h - pt), trim),
        ]
    return Design(tuple(parts), {"diffuser": mat.words, "shape": shape})
