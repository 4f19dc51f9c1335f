"""Generators of home utility and hallway pieces: radiators, bins, stands, mirrors (front +X).

Sizes are bounding boxes (x = depth, y = width, z = height); fronts face +X. Like every
asset they have their lowest point at z = 0 and stand upright on a flat bottom.
"""

from __future__ import annotations

from asset_pipeline.procedural.appliances import MIRROR
from asset_pipeline.procedural.home_kit import (
    CLOCK_FACE,
    DARK_GREY,
    IVORY_FACE,
    RICE_PAPER,
    ROUND,
    WICKER,
    upright_rod,
)
from asset_pipeline.procedural.kit import (
    BLACK_METAL,
    BLACK_PLASTIC,
    BLUE_FABRIC,
    BRASS,
    CANVAS_WARM,
    CERAMIC_BLACK,
    CERAMIC_BLUE,
    CHARCOAL_FABRIC,
    CHROME,
    CLEAR_GLASS,
    FABRICS,
    GILT,
    GREEN_FABRIC,
    LEATHER,
    LINEN,
    NAVY_LACQUER,
    OAK,
    PORCELAIN,
    RUG_RED,
    STEEL,
    TOYS,
    WALNUT,
    WHITE_LACQUER,
    WHITE_PLASTIC,
    WOODS,
    Rng,
    block,
    chance,
    clamp,
    count_word,
    pick,
    square_legs,
    uniform,
)
from asset_pipeline.procedural.parts import Material, Part, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.round_parts import Cylinder, Lathe

MAHOGANY = Material("mahogany", (0.45, 0.20, 0.12, 1.0), 0.3, 0.4, "mahogany")


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


@category(
    "high_chair",
    "furniture",
    size=(0.6, 0.55, 1.0),
    low=(0.5, 0.45, 0.85),
    high=(0.75, 0.65, 1.1),
    mass=7.0,
    friction=0.7,
    description="a {material} baby high chair with a {tray} tray and a footrest",
    variants=(None, (0.55, 0.5, 0.95), (0.7, 0.6, 1.05)),
)
def high_chair(size: Vec3, rng: Rng) -> Design:
    """A high chair: four tall legs braced near the floor, a seat with side rails and a back
    (-X), a footrest, and a tray (a surface) in front (+X)."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    frame = pick(rng, (*WOODS, WHITE_PLASTIC, WHITE_LACQUER))
    tray_mat = pick(rng, (WHITE_PLASTIC, *TOYS))
    ls = 0.035
    tray_proj = clamp(0.18 * d, 0.08, 0.14)
    xf = hd - tray_proj
    seat_z = clamp(0.56 * h, 0.5, 0.6)
    tray_z = seat_z + 0.2
    parts: list[Part] = [*square_legs(hd + xf, w, seat_z, ls, frame)]
    parts = [p.translated((0.5 * (xf - hd), 0.0, 0.0)) for p in parts]
    for y in ((-hw, -hw + ls), (hw - ls, hw)):
        parts.append(block((-hd + ls, xf - ls), y, (0.08, 0.11), frame))
    parts.append(block((-hd, xf), (-hw, hw), (seat_z, seat_z + 0.03), frame))
    parts.append(block((xf - ls, xf), (-hw + ls, hw - ls), (0.22, 0.25), frame))
    parts.append(block((-hd, -hd + ls), (-hw, hw), (seat_z + 0.03, h), frame))
    for y in ((-hw, -hw + 0.03), (hw - 0.03, hw)):
        parts.append(block((-hd + ls, xf), y, (seat_z + 0.03, tray_z - 0.01), frame))
    parts.append(
        block((xf - 0.1, hd), (-hw, hw), (tray_z - 0.01, tray_z + 0.02), tray_mat, surface=True)
    )
    return Design(tuple(parts), {"material": frame.words, "tray": tray_mat.words})


@category(
    "floor_mirror",
    "furniture",
    size=(0.4, 0.6, 1.7),
    low=(0.3, 0.35, 1.4),
    high=(0.6, 1.0, 2.0),
    mass=15.0,
    friction=0.7,
    description="a full-length standing mirror in a {frame} frame {stand}",
    variants=(None, (0.35, 0.5, 1.6), (0.5, 0.8, 1.9)),
)
def floor_mirror(size: Vec3, rng: Rng) -> Design:
    """A standing mirror facing +X: a cheval mirror between two posts on feet along X, or a
    framed mirror on a plinth with rear feet."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    frame = pick(rng, (*WOODS, GILT, BLACK_METAL, WHITE_LACQUER))
    ft = 0.03
    f = 0.04
    style = pick(rng, ("cheval", "plinth", "arched"))
    parts: list[Part] = []
    if style == "cheval":
        ps = 0.04
        for y in ((-hw, -hw + ps), (hw - ps, hw)):
            parts.append(block((-hd, hd), y, (0.0, 0.03), frame))
            parts.append(block((-ps / 2, ps / 2), y, (0.03, h - 0.1), frame))
            parts.append(block((-ps / 2, ps / 2), y, (h - 0.1, h), frame))
        y0, y1, z0, z1 = -hw + ps + 0.01, hw - ps - 0.01, 0.25, h - 0.05
        stand = "between two posts on feet"
    else:
        parts.append(block((-hd, hd), (-hw, hw), (0.0, 0.06), frame))
        y0, y1, z0, z1 = -hw, hw, 0.06, h
        stand = "on a plinth"
    parts += [
        block((-ft / 2, ft / 2), (y0, y1), (z0, z0 + f), frame),
        block((-ft / 2, ft / 2), (y0, y0 + f), (z0 + f, z1 - f), frame),
        block((-ft / 2, ft / 2), (y1 - f, y1), (z0 + f, z1 - f), frame),
        block((-ft / 2, ft / 2 - 0.004), (y0 + f, y1 - f), (z0 + f, z1 - f), MIRROR),
    ]
    if style == "arched":
        steps = 3
        for i in range(steps):
            inset = 0.12 * (y1 - y0) * i * i / (steps - 1) ** 2
            zb = z1 - f * (steps - i) / steps
            parts.append(
                block((-ft / 2, ft / 2), (y0 + inset, y1 - inset), (zb, zb + f / steps), frame)
            )
        stand = "with a stepped arched top, on a plinth"
    else:
        parts.append(block((-ft / 2, ft / 2), (y0, y1), (z1 - f, z1), frame))
    return Design(tuple(parts), {"frame": frame.words, "stand": stand})


@category(
    "grandfather_clock",
    "furniture",
    size=(0.3, 0.5, 2.0),
    low=(0.22, 0.38, 1.7),
    high=(0.4, 0.65, 2.3),
    mass=60.0,
    friction=0.7,
    description="a tall {wood} grandfather clock with a {face} dial and a {metal} pendulum "
    "behind a glass door",
    variants=(None, (0.26, 0.45, 1.9), (0.35, 0.6, 2.2)),
)
def grandfather_clock(size: Vec3, rng: Rng) -> Design:
    """A longcase clock: a plinth, a narrower trunk with a glass door over the pendulum,
    a hood with a round dial (facing +X) and a stepped crown."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    wood = pick(rng, (WALNUT, OAK, NAVY_LACQUER, MAHOGANY))
    metal = pick(rng, (BRASS, GILT))
    face = pick(rng, (CLOCK_FACE, IVORY_FACE))
    base_h = clamp(0.15 * h, 0.2, 0.35)
    crown = clamp(0.06 * h, 0.08, 0.14)
    hood_h = clamp(0.6 * w, 0.25, 0.4)
    hood_z = h - crown - hood_h
    tf = hd - 0.03
    tw = 0.38 * w
    parts: list[Part] = [
        block((-hd, hd), (-hw, hw), (0.0, base_h), wood),
        block((-hd + 0.01, tf), (-tw, tw), (base_h, hood_z), wood),
        block((-hd, hd - 0.005), (-hw + 0.01, hw - 0.01), (hood_z, h - crown), wood),
        block(
            (tf, tf + 0.004), (-0.005, 0.005), (base_h + 0.2, hood_z - 0.05), metal, collide=False
        ),
        Cylinder((tf + 0.002, 0.0, base_h + 0.2), 0.055, 0.002, metal, axis="x", collide=False),
        block(
            (tf + 0.005, tf + 0.01),
            (-tw + 0.04, tw - 0.04),
            (base_h + 0.08, hood_z - 0.04),
            CLEAR_GLASS,
            collide=False,
        ),
    ]
    dial_r = 0.5 * hood_h - 0.03
    zc = hood_z + 0.5 * hood_h
    parts.append(
        Cylinder(
            (hd - 0.005 + 0.0025 - 0.0025, 0.0, zc), dial_r, 0.0025, face, axis="x", collide=False
        )
    )
    parts.append(
        block(
            (hd - 0.0015, hd), (-0.004, 0.004), (zc, zc + 0.7 * dial_r), BLACK_METAL, collide=False
        )
    )
    parts.append(
        block(
            (hd - 0.0015, hd),
            (0.0, 0.5 * dial_r),
            (zc - 0.004, zc + 0.004),
            BLACK_METAL,
            collide=False,
        )
    )
    steps = 3
    for i in range(steps):
        inset = 0.02 + i * 0.3 * hw / steps
        z0 = h - crown + i * crown / steps
        parts.append(
            block(
                (-hd + 0.01, hd - 0.01 - 0.02 * i),
                (-hw + inset, hw - inset),
                (z0, z0 + crown / steps),
                wood,
            )
        )
    return Design(tuple(parts), {"wood": wood.words, "face": face.words, "metal": metal.words})


@category(
    "folding_screen",
    "furniture",
    size=(0.4, 1.6, 1.7),
    low=(0.2, 0.9, 1.4),
    high=(0.6, 2.4, 2.0),
    mass=15.0,
    friction=0.8,
    description="a folding {count}-panel room divider screen of {infill} in a {frame} frame",
    variants=(None, (0.35, 1.2, 1.6), (0.5, 2.2, 1.8)),
)
def folding_screen(size: Vec3, rng: Rng) -> Design:
    """A zigzag of hinged panels standing half open: each panel runs diagonally across the
    depth (drawn as overlapping steps), with a frame post at every fold."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    frame = pick(rng, (*WOODS, BLACK_METAL, WHITE_LACQUER))
    infill = pick(rng, (RICE_PAPER, CANVAS_WARM, WICKER, LINEN, *FABRICS[:3]))
    panels = 4 if w > 1.9 else 3
    post = 0.03
    steps = 5
    pw = w / panels
    xs = [(-hd + 0.5 * post) if i % 2 == 0 else (hd - 0.5 * post) for i in range(panels + 1)]
    parts: list[Part] = []
    for i in range(panels):
        xa, xb = xs[i], xs[i + 1]
        ya = -hw + i * pw
        dx = (xb - xa) / steps
        dy = pw / steps
        for j in range(steps):
            xc = xa + (j + 0.5) * dx
            half = 0.5 * abs(dx) + 0.008
            y0 = max(-hw + post, ya + j * dy)
            y1 = min(hw - post, ya + (j + 1) * dy)
            parts.append(
                block(
                    (xc - half, xc + half),
                    (y0, y1),
                    (0.05, h - 0.05),
                    infill,
                    collide=j in (0, steps // 2, steps - 1),
                )
            )
    for i in range(panels + 1):
        x = xs[i]
        y = -hw + i * pw
        y0, y1 = max(-hw, y - 0.5 * post), min(hw, y + 0.5 * post)
        if i == 0:
            y0, y1 = -hw, -hw + post
        if i == panels:
            y0, y1 = hw - post, hw
        parts.append(block((x - 0.5 * post, x + 0.5 * post), (y0, y1), (0.0, h), frame))
    return Design(
        tuple(parts), {"count": count_word(panels), "infill": infill.words, "frame": frame.words}
    )
