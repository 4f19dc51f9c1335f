"""Generators of music and art equipment: drums, pianos, speakers, easels (front +X).

Every generator fills exactly ``[-d/2, d/2] x [-w/2, w/2] x [0, h]`` (x = depth, y = width).
"""

from __future__ import annotations

from asset_pipeline.procedural.kit import (
    ASH,
    BLACK_LEATHER,
    BLACK_METAL,
    BLACK_PLASTIC,
    BRASS,
    CHROME,
    IVORY,
    LEATHER,
    LINEN,
    OAK,
    PIANO_BLACK,
    PINE,
    WALNUT,
    WHITE_LACQUER,
    Rng,
    block,
    chance,
    clamp,
    pick,
    uniform,
)
from asset_pipeline.procedural.leisure_kit import (
    NUMBER_WORDS,
    RUBBER,
    SISAL,
    cyl,
    rod,
    strut,
)
from asset_pipeline.procedural.parts import Part, RecipeMaterial, Vec3
from asset_pipeline.procedural.registry import Design, category

GRILLE = RecipeMaterial("grille_cloth", (0.12, 0.12, 0.13, 1.0), 0.05, 0.1, "black grille")
TOLEX = RecipeMaterial("tolex", (0.09, 0.09, 0.09, 1.0), 0.3, 0.3, "black tolex")
CREAM_TOLEX = RecipeMaterial("cream_tolex", (0.88, 0.82, 0.68, 1.0), 0.3, 0.3, "cream tolex")
DRUM_WRAPS = (
    RecipeMaterial("drum_red", (0.62, 0.08, 0.10, 1.0), 0.8, 0.8, "red sparkle"),
    RecipeMaterial("drum_blue", (0.10, 0.22, 0.55, 1.0), 0.8, 0.8, "blue"),
    RecipeMaterial("drum_black", (0.05, 0.05, 0.06, 1.0), 0.8, 0.8, "black"),
    RecipeMaterial("drum_white", (0.92, 0.92, 0.90, 1.0), 0.8, 0.8, "white pearl"),
)
DRUM_HEAD = RecipeMaterial("drum_head", (0.93, 0.92, 0.86, 1.0), 0.2, 0.2)
CYMBAL = RecipeMaterial("cymbal", (0.80, 0.64, 0.28, 1.0), 0.9, 0.9, "bronze")


# --- music -----------------------------------------------------------------------------------
def _stand(x: float, y: float, z_top: float, base_r: float, metal: RecipeMaterial) -> list[Part]:
    """A drum or cymbal stand: a flat round foot and a thin post up to ``z_top``."""
    return [cyl(x, y, 0.0, 0.02, base_r, metal), cyl(x, y, 0.02, z_top, 0.012, metal)]


@category(
    "drum_kit",
    "furniture",
    size=(1.2, 1.5, 1.2),
    low=(0.9, 1.1, 1.0),
    high=(1.6, 2.0, 1.5),
    mass=35.0,
    description="a five-piece {wrap} drum kit with {cymbals} cymbals, a hi-hat and a throne",
    variants=(None, (1.3, 1.7, 1.3), (1.0, 1.3, 1.1)),
)
def drum_kit(size: Vec3, rng: Rng) -> Design:
    """Bass drum facing +X with two rack toms, snare, floor tom, hi-hat, cymbals on stands
    and the drummer's throne at -X."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    wrap = pick(rng, DRUM_WRAPS)
    metal = pick(rng, (CHROME, BLACK_METAL))
    bass_r = clamp(uniform(rng, 0.25, 0.29), 0.2, 0.3)
    bass_x = (hd - 0.4, hd)
    bx = 0.5 * (bass_x[0] + bass_x[1])
    parts: list[Part] = [
        rod("x", bass_x[0], bass_x[1] - 0.01, 0.0, bass_r, bass_r, wrap),
        rod("x", bass_x[1] - 0.01, bass_x[1], 0.0, bass_r, bass_r - 0.01, DRUM_HEAD),
        block((bass_x[0] + 0.05, bass_x[1] - 0.05), (-0.1, 0.1), (0.0, 0.03), metal),
    ]
    tom_z = 2 * bass_r + 0.12
    for sign in (-1.0, 1.0):
        parts.append(cyl(bx - 0.05, sign * 0.14, 2 * bass_r, tom_z - 0.1, 0.01, metal))
        parts.append(cyl(bx - 0.05, sign * 0.14, tom_z - 0.1, tom_z + 0.12, 0.11, wrap))
    # snare (left, -Y) and floor tom (right, +Y) near the throne
    sx, sy = bx - 0.5, -0.3
    parts += _stand(sx, sy, 0.55, 0.14, metal)
    parts.append(cyl(sx, sy, 0.55, 0.68, 0.17, wrap))
    parts.append(cyl(sx, sy, 0.68, 0.685, 0.165, DRUM_HEAD))
    ft_r = 0.2
    parts.append(cyl(bx - 0.45, min(0.35, hw - ft_r - 0.05), 0.1, 0.6, ft_r, wrap))
    parts.append(
        block(
            (bx - 0.47, bx - 0.43),
            (min(0.35, hw - ft_r - 0.05) - 0.02, min(0.35, hw - ft_r - 0.05) + 0.02),
            (0.0, 0.1),
            metal,
        )
    )
    # throne
    tx = -hd + 0.2
    parts += _stand(tx, 0.0, 0.5, 0.2, metal)
    parts.append(cyl(tx, 0.0, 0.5, 0.58, 0.17, BLACK_LEATHER))
    # hi-hat on the far left, crash and ride reaching the edges and the top
    cymbal_r = clamp(0.2 * w, 0.18, 0.26)
    hh_y = -hw + 0.18
    parts += _stand(bx - 0.55, hh_y, 0.9, 0.15, metal)
    parts.append(cyl(bx - 0.55, hh_y, 0.9, 0.91, 0.18, CYMBAL))
    parts.append(cyl(bx - 0.55, hh_y, 0.93, 0.94, 0.18, CYMBAL))
    cymbals = 2 if chance(rng, 0.5) else 1
    spots = [(bx - 0.15, -hw + cymbal_r, h), (bx - 0.1, hw - cymbal_r, h - 0.1)][:cymbals]
    for x, y, z in spots:
        parts += _stand(x, y, z - 0.01, 0.16, metal)
        parts.append(cyl(x, y, z - 0.01, z, cymbal_r, CYMBAL))
    if cymbals == 1:
        parts.append(block((bx - 0.1, bx - 0.06), (hw - 0.04, hw), (0.0, 0.8), metal))
    words = {"wrap": wrap.words, "cymbals": NUMBER_WORDS[cymbals + 1]}
    return Design(tuple(parts), words)


@category(
    "digital_piano",
    "furniture",
    size=(0.4, 1.35, 0.9),
    low=(0.3, 1.1, 0.75),
    high=(0.55, 1.6, 1.1),
    mass=45.0,
    description="a {finish} 88-key digital piano on {stand}",
    variants=(None, (0.45, 1.4, 0.95), (0.35, 1.3, 0.85)),
)
def digital_piano(size: Vec3, rng: Rng) -> Design:
    """A keyboard case with ivory and black keys, a music rest and a cabinet or leg stand."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, (PIANO_BLACK, WHITE_LACQUER, WALNUT, OAK))
    cabinet = chance(rng, 0.6)
    key_z = clamp(uniform(rng, 0.72, 0.76), 0.6, h - 0.12)
    case_z = key_z - 0.1
    key_d = 0.15
    parts: list[Part] = [
        block((-hd, hd - key_d - 0.01), (-hw, hw), (case_z, key_z + 0.05), finish),
        block((hd - key_d - 0.01, hd), (-hw, -hw + 0.04), (case_z, key_z + 0.03), finish),
        block((hd - key_d - 0.01, hd), (hw - 0.04, hw), (case_z, key_z + 0.03), finish),
        block((hd - key_d - 0.01, hd), (-hw + 0.04, hw - 0.04), (case_z, key_z - 0.02), finish),
        block((hd - key_d, hd), (-hw + 0.04, hw - 0.04), (key_z - 0.02, key_z), IVORY),
        block((hd - key_d, hd - 0.06), (-hw + 0.05, hw - 0.05), (key_z, key_z + 0.01), PIANO_BLACK),
        block((-hd + 0.03, -hd + 0.06), (-hw + 0.1, hw - 0.1), (key_z + 0.05, h), finish),
    ]
    if cabinet:
        for y in ((-hw, -hw + 0.04), (hw - 0.04, hw)):
            parts.append(block((-hd, hd - 0.02), y, (0.0, case_z), finish))
        parts.append(block((-hd, -hd + 0.02), (-hw + 0.04, hw - 0.04), (0.1, case_z), finish))
        parts.append(block((-hd + 0.05, hd - 0.12), (-0.15, 0.15), (0.03, 0.07), BRASS))
        stand = "a matching cabinet stand with pedals"
    else:
        for y in ((-hw + 0.08, -hw + 0.12), (hw - 0.12, hw - 0.08)):
            parts.append(block((-hd, hd), y, (0.0, 0.04), BLACK_METAL))
            parts.append(block((-0.02, 0.02), y, (0.04, case_z), BLACK_METAL))
        parts.append(block((-hd, hd), (-hw, -hw + 0.01), (case_z - 0.001, case_z), BLACK_METAL))
        stand = "a black metal leg stand"
    return Design(tuple(parts), {"finish": finish.words, "stand": stand})


@category(
    "speaker",
    "furniture",
    size=(0.3, 0.3, 1.0),
    low=(0.2, 0.18, 0.6),
    high=(0.5, 0.45, 1.4),
    mass=22.0,
    description="a {finish} floor-standing speaker with {drivers} drivers{grille}",
    variants=(None, (0.35, 0.25, 1.1), (0.25, 0.2, 0.8)),
)
def speaker(size: Vec3, rng: Rng) -> Design:
    """A tower cabinet on a plinth; a tweeter and woofers on the +X baffle."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, (PIANO_BLACK, WALNUT, WHITE_LACQUER, OAK))
    grille = chance(rng, 0.4)
    plinth = 0.04
    face = hd - 0.012
    parts: list[Part] = [
        block((-hd, hd), (-hw, hw), (0.0, plinth), BLACK_PLASTIC),
        block((-hd, face), (-hw + 0.01, hw - 0.01), (plinth, h), finish),
    ]
    r_w = clamp(0.38 * w, 0.05, 0.1)
    woofers = int(clamp((h - 0.35) // (2 * r_w + 0.05), 1, 3))
    z = h - 0.1
    parts.append(rod("x", face, face + 0.008, 0.0, z, 0.025, BLACK_PLASTIC))
    for k in range(woofers):
        zc = z - 0.08 - r_w - k * (2 * r_w + 0.04)
        parts.append(rod("x", face, face + 0.01, 0.0, zc, r_w, GRILLE))
    if grille:
        parts.append(
            block(
                (face + 0.01, hd),
                (-hw + 0.01, hw - 0.01),
                (plinth + 0.02, h - 0.02),
                GRILLE,
                collide=False,
            )
        )
    else:
        parts.append(block((face, hd), (-0.01, 0.01), (plinth + 0.02, plinth + 0.05), BRASS))
    words = {
        "finish": finish.words,
        "drivers": NUMBER_WORDS[woofers + 1],
        "grille": " behind a fabric grille" if grille else "",
    }
    return Design(tuple(parts), words)


@category(
    "guitar_amplifier",
    "furniture",
    size=(0.3, 0.6, 0.5),
    low=(0.2, 0.35, 0.3),
    high=(0.45, 0.8, 0.75),
    mass=20.0,
    description="a {covering} guitar combo amplifier with a {grille} grille and a carry handle",
    variants=(None, (0.28, 0.5, 0.42), (0.35, 0.7, 0.6)),
)
def guitar_amplifier(size: Vec3, rng: Rng) -> Design:
    """A covered cabinet with a speaker grille on +X, a control strip and a top handle."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    covering = pick(rng, (TOLEX, CREAM_TOLEX, LEATHER))
    grille = pick(rng, (GRILLE, SISAL, LINEN))
    handle = 0.03
    top = h - handle
    panel = clamp(0.18 * top, 0.05, 0.1)
    parts: list[Part] = [
        block((-hd, hd - 0.01), (-hw, hw), (0.02, top), covering),
        block((hd - 0.01, hd), (-hw + 0.02, hw - 0.02), (0.04, top - panel - 0.01), grille),
        block((hd - 0.01, hd), (-hw + 0.02, hw - 0.02), (top - panel, top - 0.01), CHROME),
        block((-0.06, 0.06), (-0.12, 0.12), (top, top + 0.01), BLACK_LEATHER),
        block((-0.03, 0.03), (-0.1, 0.1), (top + 0.01, h), BLACK_LEATHER),
    ]
    for x in ((-hd + 0.02, -hd + 0.06), (hd - 0.07, hd - 0.03)):
        for y in ((-hw + 0.02, -hw + 0.06), (hw - 0.06, hw - 0.02)):
            parts.append(block(x, y, (0.0, 0.02), RUBBER))
    knobs = int(clamp((w - 0.12) // 0.06, 3, 8))
    for k in range(knobs):
        yk = -hw + 0.08 + k * (w - 0.16) / max(1, knobs - 1)
        zc = top - 0.5 * panel - 0.005
        parts.append(
            block(
                (hd - 0.011, hd - 0.01),
                (yk - 0.01, yk + 0.01),
                (zc - 0.01, zc + 0.01),
                BLACK_PLASTIC,
                collide=False,
            )
        )
    return Design(tuple(parts), {"covering": covering.words, "grille": grille.words})


# --- art -------------------------------------------------------------------------------------
@category(
    "easel",
    "furniture",
    size=(0.6, 0.6, 1.7),
    low=(0.45, 0.45, 1.3),
    high=(0.9, 0.9, 2.1),
    mass=6.0,
    description="a {wood} A-frame painting easel holding a {canvas} canvas on its ledge",
    variants=(None, (0.7, 0.65, 1.85), (0.5, 0.5, 1.45)),
)
def easel(size: Vec3, rng: Rng) -> Design:
    """Two front legs meeting at the top (an A), a rear leg slanting back to -X, a canvas
    ledge across the front legs and a canvas standing on it."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    wood = pick(rng, (PINE, OAK, WALNUT, ASH))
    canvas = pick(
        rng,
        (
            LINEN,
            WHITE_LACQUER,
            RecipeMaterial("canvas_blue", (0.45, 0.6, 0.78, 1.0), 0.05, 0.1, "half-painted"),
        ),
    )
    s = 0.035
    foot = 0.012
    lean = clamp(uniform(rng, 0.1, 0.16), 0.08, 0.3 * d)  # the front legs lean back this much
    xf = hd - 0.5 * s  # front feet's centre line

    def x_leg(z: float) -> float:
        return xf - lean * z / h

    ledge_z = clamp(uniform(rng, 0.42, 0.48) * h, 0.55, 0.9)
    parts: list[Part] = []
    for sign in (-1.0, 1.0):
        y_foot = sign * (hw - 0.5 * s)
        y_span = tuple(sorted((y_foot - 0.5 * s, y_foot + 0.5 * s)))
        parts.append(block((hd - s, hd), y_span, (0.0, foot), wood))
        parts.append(strut((xf, y_foot, foot), (x_leg(h), sign * 0.04, h), s, wood))
    # rear leg from the back foot up to just behind the front legs' top
    top_r = h - 0.15
    xr_top = x_leg(top_r) - s
    parts.append(block((-hd, -hd + s), (-0.5 * s, 0.5 * s), (0.0, foot), wood))
    parts.append(strut((-hd + 0.5 * s, 0.0, foot), (xr_top, 0.0, top_r), s, wood))
    parts.append(
        block((xr_top - 0.5 * s, x_leg(top_r)), (-0.05, 0.05), (top_r - 0.04, top_r), wood)
    )
    # ledge across the front legs, a lip at its front and the canvas standing on it
    xl = x_leg(ledge_z) + 0.5 * s
    ledge_d = min(0.08, hd - xl)
    parts.append(
        block((xl - s, xl + ledge_d), (-hw + 0.06, hw - 0.06), (ledge_z - 0.03, ledge_z), wood)
    )
    parts.append(
        block(
            (xl + ledge_d - 0.012, xl + ledge_d),
            (-hw + 0.06, hw - 0.06),
            (ledge_z, ledge_z + 0.025),
            wood,
        )
    )
    cz1 = min(h - 0.1, ledge_z + clamp(uniform(rng, 0.5, 0.7), 0.3, 0.9))
    cw = clamp(uniform(rng, 0.7, 0.9) * (w - 0.2), 0.25, w - 0.1)
    parts.append(block((xl + 0.004, xl + 0.024), (-0.5 * cw, 0.5 * cw), (ledge_z, cz1), canvas))
    xc = x_leg(cz1) + 0.5 * s
    parts.append(block((xc - s, xc + 0.03), (-0.04, 0.04), (cz1, cz1 + 0.04), wood))
    return Design(tuple(parts), {"wood": wood.words, "canvas": canvas.words})
