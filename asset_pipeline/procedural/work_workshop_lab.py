"""Generators of workshop and lab furniture (front +X).

Every generator fills exactly ``[-d/2, d/2] x [-w/2, w/2] x [0, h]`` (x = depth, y = width).
"""

from __future__ import annotations

from asset_pipeline.procedural.kit import (
    BLACK_METAL,
    BLACK_PLASTIC,
    CHROME,
    CLEAR_GLASS,
    OAK,
    PINE,
    SPACE_GREY,
    STEEL,
    Rng,
    block,
    chance,
    clamp,
    drawer_fronts,
    pick,
    square_legs,
    uniform,
)
from asset_pipeline.procedural.leisure_kit import (
    BLUE_PAINT,
    RED_PAINT,
    RUBBER,
    cyl,
    frame_rect,
    rod,
)
from asset_pipeline.procedural.parts import Part, RecipeMaterial, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.work_kit import (
    LAB_WHITE,
    METAL_HANDLES,
    NUMBER_WORDS,
    OFFICE_GREY,
    PUTTY,
)

RESIN = RecipeMaterial("black_resin", (0.07, 0.07, 0.08, 1.0), 0.5, 0.6, "black epoxy resin")
GREY_RESIN = RecipeMaterial("grey_resin", (0.42, 0.44, 0.45, 1.0), 0.5, 0.6, "grey epoxy resin")


# --- workshop ---------------------------------------------------------------------------------
@category(
    "workbench",
    "furniture",
    size=(0.75, 1.8, 0.9),
    low=(0.55, 1.1, 0.8),
    high=(0.95, 2.5, 1.0),
    mass=60.0,
    description="a sturdy workbench with a thick {top} top, {frame} legs, {drawers} and a "
    "lower shelf{vise}",
    variants=(None, (0.6, 1.2, 0.9), (0.85, 2.2, 0.95)),
)
def workbench(size: Vec3, rng: Rng) -> Design:
    """A thick top (a surface), four legs, a lower shelf (a surface), drawers, maybe a vise."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    top = pick(
        rng,
        (
            OAK,
            PINE,
            RecipeMaterial("beech_block", (0.80, 0.62, 0.42, 1.0), 0.2, 0.3, "beech butcher-block"),
        ),
    )
    frame = pick(rng, (top, BLACK_METAL, SPACE_GREY, BLUE_PAINT))
    t = uniform(rng, 0.04, 0.06)
    vise = chance(rng, 0.5)
    vd = 0.06 if vise else 0.0
    xt = (-hd, hd - vd)
    leg = 0.07
    shelf_z = clamp(uniform(rng, 0.12, 0.2), 0.1, 0.25)
    parts: list[Part] = [
        block(xt, (-hw, hw), (h - t, h), top, surface=True),
        *[
            p.translated((-0.5 * vd, 0.0, 0.0))
            for p in square_legs(d - vd, w, h - t, leg, frame, inset=0.03)
        ],
        block(
            (xt[0] + 0.03 + leg, xt[1] - 0.03 - leg),
            (-hw + 0.03, hw - 0.03),
            (shelf_z - 0.025, shelf_z),
            frame if frame is not top else top,
            surface=True,
        ),
    ]
    for x in ((xt[0] + 0.03, xt[0] + 0.03 + leg), (xt[1] - 0.03 - leg, xt[1] - 0.03)):
        parts.append(block(x, (-hw + 0.03, hw - 0.03), (shelf_z - 0.06, shelf_z - 0.025), frame))
    n = int(rng.integers(0, 4))
    if n:
        dw = min(0.5 * w, 0.45 * n)
        face = xt[1] - 0.03 - 0.036
        parts.append(
            block(
                (xt[0] + 0.1, face),
                (hw - 0.05 - dw, hw - 0.05),
                (h - t - 0.18, h - t),
                frame if frame is not top else top,
            )
        )
        parts += drawer_fronts(
            face,
            (hw - 0.05 - dw, hw - 0.05),
            (h - t - 0.18, h - t - 0.005),
            1,
            n,
            frame if frame is not top else top,
            BLACK_METAL,
        )
    if vise:
        vy = -hw + 0.12
        parts.append(block((hd - vd, hd), (vy - 0.09, vy + 0.09), (h - 0.12, h), BLUE_PAINT))
        parts.append(rod("x", hd - vd, hd, vy, h - 0.09, 0.012, STEEL))
    words = {
        "top": top.words,
        "frame": "matching" if frame is top else frame.words,
        "drawers": f"{NUMBER_WORDS[n]} drawers" if n else "an open front",
        "vise": " and a bench vise" if vise else "",
    }
    return Design(tuple(parts), words)


@category(
    "tool_chest",
    "furniture",
    size=(0.45, 0.7, 1.0),
    low=(0.35, 0.5, 0.7),
    high=(0.6, 1.1, 1.3),
    mass=90.0,
    friction=0.7,
    description="a {colour} rolling tool chest with {drawers} drawers, a lift-up top chest "
    "and a side handle on casters",
    variants=(None, (0.5, 0.9, 1.05), (0.4, 0.6, 0.85)),
)
def tool_chest(size: Vec3, rng: Rng) -> Design:
    """A roller cabinet with many drawers, a top chest with a lid (a surface), casters and a
    push handle on -Y."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    colour = pick(rng, (RED_PAINT, BLACK_METAL, BLUE_PAINT, STEEL))
    handle_w = 0.05
    y0 = -hw + handle_w
    caster = 0.1
    face = hd - 0.036
    lid = 0.05
    parts: list[Part] = [
        block((-hd, face), (y0, hw), (caster, h), colour, surface=True),
        block((-hd, hd), (y0, hw), (caster, caster + 0.02), BLACK_METAL),
        block((-0.1 * d, 0.1 * d), (-hw, -hw + 0.02), (0.45 * h, 0.75 * h), CHROME),
        block((-0.1 * d - 0.03, -0.1 * d), (-hw + 0.01, y0), (0.45 * h, 0.75 * h), CHROME),
        block((0.1 * d, 0.1 * d + 0.03), (-hw + 0.01, y0), (0.45 * h, 0.75 * h), CHROME),
    ]
    for x in (-hd + 0.05, hd - 0.1):
        for y in (y0 + 0.05, hw - 0.05):
            parts.append(
                block((x - 0.03, x + 0.03), (y - 0.03, y + 0.03), (0.06, caster), BLACK_METAL)
            )
            parts.append(rod("y", y - 0.02, y + 0.02, x, 0.04, 0.04, RUBBER))
    lower = int(clamp(round((0.6 * h) / 0.12), 3, 6))
    upper = int(clamp(round((0.3 * h) / 0.09), 2, 4))
    split = caster + 0.02 + 0.62 * (h - caster - 0.02 - lid)
    parts += drawer_fronts(
        face, (y0 + 0.01, hw - 0.01), (caster + 0.02, split - 0.01), lower, 1, colour, CHROME
    )
    parts += drawer_fronts(
        face,
        (y0 + 0.01, hw - 0.01),
        (split + 0.01, h - lid - 0.01),
        upper,
        2 if w > 0.75 else 1,
        colour,
        CHROME,
    )
    parts.append(block((face, face + 0.036), (y0, hw), (split - 0.01, split + 0.01), BLACK_METAL))
    parts.append(block((face, face + 0.036), (y0, hw), (h - lid - 0.01, h - lid), colour))
    return Design(
        tuple(parts),
        {"colour": colour.words, "drawers": NUMBER_WORDS.get(lower + upper, str(lower + upper))},
    )


# --- labs -------------------------------------------------------------------------------------
@category(
    "lab_bench",
    "furniture",
    size=(0.75, 1.8, 0.9),
    low=(0.6, 1.2, 0.85),
    high=(0.95, 3.6, 0.95),
    mass=150.0,
    friction=0.7,
    description="a laboratory bench with a {top} worktop over {cabinets} cabinets with doors "
    "and drawers",
    variants=(None, (0.9, 2.4, 0.9), (0.7, 1.5, 0.9)),
)
def lab_bench(size: Vec3, rng: Rng) -> Design:
    """A resin worktop (a surface) over cabinets with drawers and doors on +X, a recessed
    plinth, maybe a knee space in the middle."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    top = pick(rng, (RESIN, GREY_RESIN, LAB_WHITE))
    case = pick(
        rng,
        (
            LAB_WHITE,
            OFFICE_GREY,
            SPACE_GREY,
            RecipeMaterial("lab_blue", (0.35, 0.50, 0.70, 1.0), 0.4, 0.4, "blue"),
        ),
    )
    handle = pick(rng, METAL_HANDLES)
    t = 0.03
    face = hd - 0.03 - 0.036
    n = max(2, round(w / 0.6))
    knee = n >= 3 and chance(rng, 0.5)
    parts: list[Part] = [block((-hd, hd), (-hw, hw), (h - t, h), top, surface=True)]
    cw = w / n
    for k in range(n):
        y = (-hw + k * cw, -hw + (k + 1) * cw)
        if knee and k == n // 2:
            parts.append(block((-hd, face), (y[0], y[1]), (h - t - 0.1, h - t), case))
            parts += drawer_fronts(face, y, (h - t - 0.1, h - t - 0.005), 1, 1, case, handle)
            continue
        parts.append(block((-hd + 0.02, face - 0.06), y, (0.0, 0.1), BLACK_PLASTIC))
        parts.append(block((-hd, face), y, (0.1, h - t), case))
        parts += drawer_fronts(face, y, (h - t - 0.17, h - t - 0.005), 1, 1, case, handle)
        doors = 2 if cw > 0.7 else 1
        parts += drawer_fronts(face, y, (0.1, h - t - 0.17), 1, doors, case, handle, style="door")
    return Design(tuple(parts), {"top": top.words, "cabinets": case.words})


@category(
    "fume_hood",
    "furniture",
    size=(0.8, 1.5, 2.3),
    low=(0.6, 1.0, 2.0),
    high=(1.0, 2.4, 2.6),
    mass=350.0,
    friction=0.7,
    description="a {case} laboratory fume hood with a glass sash, a {top} work surface, base "
    "cabinets and an exhaust duct",
    variants=(None, (0.85, 1.8, 2.4), (0.75, 1.2, 2.2)),
)
def fume_hood(size: Vec3, rng: Rng) -> Design:
    """Base cabinets, a work surface (a surface) inside an enclosure of side walls, a back
    wall and a top, a part-raised glass sash in front and a duct collar on top."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    case = pick(rng, (LAB_WHITE, OFFICE_GREY, PUTTY))
    top = pick(rng, (RESIN, GREY_RESIN))
    handle = pick(rng, METAL_HANDLES)
    base_z = 0.85
    work_z = 0.9
    wall = 0.1
    back = 0.08
    duct_h = 0.12
    roof = h - duct_h - clamp(uniform(rng, 0.3, 0.4), 0.25, 0.45)
    face = hd - 0.036
    parts: list[Part] = [
        block((-hd, face), (-hw, hw), (0.1, base_z), case),
        block((-hd + 0.02, face - 0.05), (-hw + 0.02, hw - 0.02), (0.0, 0.1), BLACK_PLASTIC),
        *drawer_fronts(face, (-hw, hw), (0.1, base_z - 0.005), 1, 2, case, handle, style="door"),
        block((-hd + back, hd), (-hw + wall, hw - wall), (base_z, work_z), top, surface=True),
        block((-hd, hd), (-hw, -hw + wall), (base_z, h - duct_h), case),
        block((-hd, hd), (hw - wall, hw), (base_z, h - duct_h), case),
        block((-hd, -hd + back), (-hw + wall, hw - wall), (work_z, roof), case),
        block((-hd, hd), (-hw + wall, hw - wall), (roof, h - duct_h), case),
        cyl(-0.1 * d, 0.0, h - duct_h, h, clamp(0.2 * d, 0.1, 0.16), STEEL),
    ]
    sash_z = work_z + clamp(uniform(rng, 0.35, 0.5), 0.3, roof - work_z - 0.2)
    xs = (hd - 0.04, hd - 0.02)
    parts += frame_rect(xs, (-hw + wall, hw - wall), (sash_z, roof), 0.04, case)
    parts.append(
        block(
            (xs[0] + 0.005, xs[1] - 0.005),
            (-hw + wall + 0.04, hw - wall - 0.04),
            (sash_z + 0.04, roof - 0.04),
            CLEAR_GLASS,
        )
    )
    parts.append(block((xs[1], hd), (-0.3 * w, 0.3 * w), (sash_z + 0.01, sash_z + 0.03), handle))
    return Design(tuple(parts), {"case": case.words, "top": top.words})
