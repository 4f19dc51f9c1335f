"""Standing home pieces: high chairs, floor mirrors, grandfather clocks and folding screens."""

from __future__ import annotations

from asset_pipeline.procedural.appliances import MIRROR
from asset_pipeline.procedural.home_kit import (
    CLOCK_FACE,
    IVORY_FACE,
    RICE_PAPER,
    WICKER,
)
from asset_pipeline.procedural.home_utility import (
    MAHOGANY,
)
from asset_pipeline.procedural.kit import (
    BLACK_METAL,
    BRASS,
    CANVAS_WARM,
    CLEAR_GLASS,
    FABRICS,
    GILT,
    LINEN,
    NAVY_LACQUER,
    OAK,
    TOYS,
    WALNUT,
    WHITE_LACQUER,
    WHITE_PLASTIC,
    WOODS,
    Rng,
    block,
    clamp,
    count_word,
    pick,
    square_legs,
)
from asset_pipeline.procedural.parts import Part, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.round_parts import Cylinder


# --- standing pieces ------------------------------------------------------------------------------
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
