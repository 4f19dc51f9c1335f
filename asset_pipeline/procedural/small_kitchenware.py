"""Generators of kitchen utensils, containers and food.

Small items stand on furniture (placement ``object``, issue 15). Sizes follow the knowledge
base (``objects.json``, whose (width, depth, height) is (y, x, z) here); fronts face +X.
"""

from __future__ import annotations

import numpy as np

from asset_pipeline.procedural.kit import (
    BLACK_METAL,
    BLACK_PLASTIC,
    CERAMICS,
    CHROME,
    CLEAR_GLASS,
    PORCELAIN,
    STEEL,
    WHITE_PLASTIC,
    WOODS,
    Rng,
    block,
    chance,
    clamp,
    pick,
    uniform,
)
from asset_pipeline.procedural.parts import Part, RecipeMaterial, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.round_parts import Lathe
from asset_pipeline.procedural.small_kit import (
    GREY_PLASTIC,
    OBJECT,
    RED_PLASTIC,
    ROUND,
    SILVER,
    cyl_y,
    cyl_z,
    deco,
    handle_arch,
)

WICKER = RecipeMaterial("wicker", (0.72, 0.56, 0.34, 1.0), 0.1, 0.1)
SEAGRASS = RecipeMaterial("seagrass", (0.66, 0.62, 0.44, 1.0), 0.1, 0.1)
DARK_WICKER = RecipeMaterial("dark_wicker", (0.40, 0.28, 0.17, 1.0), 0.1, 0.1, "dark rattan")
CRUST = RecipeMaterial("crust", (0.74, 0.50, 0.24, 1.0), 0.1, 0.1, "golden")
DARK_CRUST = RecipeMaterial("dark_crust", (0.42, 0.27, 0.15, 1.0), 0.1, 0.1, "dark rye")
ICING = RecipeMaterial("icing", (0.97, 0.95, 0.92, 1.0), 0.3, 0.3, "white icing")
PINK_ICING = RecipeMaterial("pink_icing", (0.95, 0.68, 0.74, 1.0), 0.3, 0.3, "pink icing")
CHOCOLATE = RecipeMaterial("chocolate", (0.30, 0.17, 0.10, 1.0), 0.3, 0.3)
SPONGE = RecipeMaterial("sponge", (0.93, 0.80, 0.55, 1.0), 0.05, 0.05)
BERRY = RecipeMaterial("berry", (0.65, 0.05, 0.12, 1.0), 0.6, 0.6)
BEANS = RecipeMaterial("beans", (0.45, 0.25, 0.13, 1.0), 0.3, 0.3, "coffee beans")
PASTA = RecipeMaterial("pasta", (0.93, 0.80, 0.45, 1.0), 0.2, 0.2, "pasta")
RICE = RecipeMaterial("rice", (0.95, 0.94, 0.90, 1.0), 0.1, 0.1, "rice")


# --- kitchen utensils and food -------------------------------------------------------------
@category(
    "cutting_board",
    "object",
    size=(0.28, 0.4, 0.02),
    low=(0.15, 0.2, 0.01),
    high=(0.4, 0.6, 0.05),
    mass=1.2,
    placement=OBJECT,
    description="a {wood} cutting board",
    variants=(None, (0.22, 0.32, 0.018)),
)
def cutting_board(size: Vec3, rng: Rng) -> Design:
    """A chopping board lying flat with a handle tab at +Y; its top is a surface."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    wood = pick(rng, (*WOODS, WHITE_PLASTIC))
    tab = clamp(0.12 * w, 0.03, 0.07)
    parts: list[Part] = [
        block((-hd, hd), (-hw, hw - tab), (0.0, h), wood, surface=True),
        block((-0.2 * d, 0.2 * d), (hw - tab, hw), (0.0, h), wood),
    ]
    return Design(tuple(parts), {"wood": wood.words})


@category(
    "knife_block",
    "object",
    size=(0.12, 0.15, 0.3),
    low=(0.08, 0.1, 0.18),
    high=(0.2, 0.25, 0.42),
    mass=2.2,
    placement=OBJECT,
    description="a {wood} knife block with knives",
    variants=(None, (0.1, 0.13, 0.26)),
)
def knife_block(size: Vec3, rng: Rng) -> Design:
    """A knife block with the knives' handles standing out of its top."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    wood = pick(rng, (*WOODS, BLACK_PLASTIC))
    grip = pick(rng, (BLACK_PLASTIC, *WOODS[:2]))
    top = 0.7 * h
    parts: list[Part] = [block((-hd, hd), (-hw, hw), (0.0, top), wood)]
    n = 4
    for i in range(n):
        y = -hw + (i + 0.5) * w / n
        z1 = h if i == 1 else top + uniform(rng, 0.6, 0.95) * (h - top)
        x = -0.15 * d if i % 2 else 0.15 * d
        parts.append(deco((x - 0.01, x + 0.01), (y - 0.008, y + 0.008), (top, z1), grip))
    return Design(tuple(parts), {"wood": wood.words})


@category(
    "storage_jar",
    "object",
    size=(0.12, 0.12, 0.2),
    low=(0.07, 0.07, 0.1),
    high=(0.2, 0.2, 0.35),
    mass=0.9,
    placement=OBJECT,
    yx_ratio=ROUND,
    description="a glass storage jar of {contents} with a {lid} lid",
    variants=(None, (0.1, 0.1, 0.15)),
)
def storage_jar(size: Vec3, rng: Rng) -> Design:
    """A glass jar, its contents showing, with a lid."""
    d, _, h = size
    r = 0.5 * d
    contents = pick(rng, (BEANS, PASTA, RICE))
    lid = pick(rng, (*WOODS[:2], STEEL, BLACK_METAL))
    lid_h = clamp(0.1 * h, 0.012, 0.03)
    jar_h = h - lid_h
    fill = uniform(rng, 0.4, 0.8) * jar_h
    parts: list[Part] = [
        Lathe((0.0, 0.0, 0.0), ((r, 0.0), (r, jar_h)), CLEAR_GLASS, hollow=(0.004, 0.006)),
        cyl_z(0.0, 0.0, 0.006, fill, r - 0.005, contents, collide=False),
        cyl_z(0.0, 0.0, jar_h, h, 0.98 * r, lid),
    ]
    return Design(tuple(parts), {"contents": contents.words, "lid": lid.words})


@category(
    "salt_shaker",
    "object",
    size=(0.05, 0.05, 0.1),
    low=(0.03, 0.03, 0.05),
    high=(0.08, 0.08, 0.15),
    mass=0.12,
    placement=OBJECT,
    yx_ratio=ROUND,
    description="a {body} salt shaker with a {cap} cap",
    variants=(None, (0.04, 0.04, 0.08)),
)
def salt_shaker(size: Vec3, rng: Rng) -> Design:
    """A salt shaker: a tapered body and a domed metal cap."""
    d, _, h = size
    r = 0.5 * d
    body = pick(rng, (CLEAR_GLASS, PORCELAIN, CERAMICS[1], WOODS[1]))
    cap = pick(rng, (STEEL, CHROME, BLACK_METAL))
    body_h = 0.78 * h
    parts: list[Part] = [
        Lathe((0.0, 0.0, 0.0), ((r, 0.0), (0.85 * r, body_h)), body),
        Lathe((0.0, 0.0, body_h), ((0.85 * r, 0.0), (0.8 * r, 0.5 * (h - body_h)),
                                   (0.45 * r, h - body_h)), cap),
    ]  # fmt: skip
    return Design(tuple(parts), {"body": body.words, "cap": cap.words})


@category(
    "spice_rack",
    "object",
    size=(0.1, 0.3, 0.3),
    low=(0.07, 0.2, 0.16),
    high=(0.16, 0.5, 0.45),
    mass=2.0,
    placement=OBJECT,
    description="a small {wood} spice rack with jars",
    variants=(None, (0.09, 0.25, 0.24)),
)
def spice_rack(size: Vec3, rng: Rng) -> Design:
    """A two-tier rack: back board, sides, shelves with front rails, a row of jars on each."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    wood = pick(rng, (*WOODS, WHITE_PLASTIC))
    cap = pick(rng, (BLACK_PLASTIC, CHROME, RED_PLASTIC))
    t = 0.01
    shelf_z = (0.0, 0.48 * h)
    parts: list[Part] = [
        block((-hd, -hd + t), (-hw, hw), (0.0, h), wood),
        block((-hd + t, hd), (-hw, -hw + t), (0.0, 0.85 * h), wood),
        block((-hd + t, hd), (hw - t, hw), (0.0, 0.85 * h), wood),
    ]
    jar_r = clamp(0.35 * (d - t), 0.012, 0.03)
    jar_h = min(0.3 * h, 0.48 * h - t - 0.02)
    n = max(1, int((w - 2 * t) / (2 * jar_r + 0.008)))
    pitch = (w - 2 * t) / n
    jx = -hd + t + 0.5 * (d - t)
    for z in shelf_z:
        parts.append(block((-hd + t, hd), (-hw + t, hw - t), (z, z + t), wood))
        parts.append(block((hd - 0.006, hd), (-hw + t, hw - t), (z + 0.035, z + 0.045), wood))
        for j in range(n):
            y = -hw + t + (j + 0.5) * pitch
            xs, ys = (jx - jar_r, jx + jar_r), (y - jar_r, y + jar_r)
            parts.append(deco(xs, ys, (z + t, z + t + 0.8 * jar_h), CLEAR_GLASS))
            parts.append(deco(xs, ys, (z + t + 0.8 * jar_h, z + t + jar_h), cap))
    return Design(tuple(parts), {"wood": wood.words})


@category(
    "dish_rack",
    "object",
    size=(0.33, 0.45, 0.15),
    low=(0.22, 0.3, 0.08),
    high=(0.45, 0.6, 0.25),
    mass=1.5,
    placement=OBJECT,
    description="a {finish} dish drying rack with plates",
    variants=(None, (0.3, 0.4, 0.13)),
)
def dish_rack(size: Vec3, rng: Rng) -> Design:
    """A drying rack: drip tray, corner posts, a top rail and plates standing in it."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, (CHROME, WHITE_PLASTIC, BLACK_METAL))
    tray = pick(rng, (WHITE_PLASTIC, GREY_PLASTIC, BLACK_PLASTIC))
    th = 0.015
    t = 0.006
    parts: list[Part] = [block((-hd, hd), (-hw, hw), (0.0, th), tray)]
    for x in (-hd, hd - t):
        for y in (-hw, hw - t):
            parts.append(block((x, x + t), (y, y + t), (th, h - t), finish))
    parts += [
        block((-hd, hd), (-hw, -hw + t), (h - t, h), finish),
        block((-hd, hd), (hw - t, hw), (h - t, h), finish),
        block((-hd, -hd + t), (-hw + t, hw - t), (h - t, h), finish),
        block((hd - t, hd), (-hw + t, hw - t), (h - t, h), finish),
    ]
    rp = min(0.4 * d, 0.5 * (h - th) - 0.005)
    plate = pick(rng, (PORCELAIN, *CERAMICS[1:4]))
    n = int(clamp((w - 0.08) // 0.05, 2, 5))
    for i in range(n):
        y = -hw + 0.04 + i * (w - 0.08) / (n - 1)
        parts.append(cyl_y(y - 0.005, y + 0.005, 0.0, th + rp, rp, plate, collide=False))
    return Design(tuple(parts), {"finish": finish.words})


@category(
    "tray",
    "object",
    size=(0.32, 0.45, 0.03),
    low=(0.2, 0.25, 0.015),
    high=(0.45, 0.65, 0.06),
    mass=0.8,
    placement=OBJECT,
    description="a {material} serving tray",
    variants=(None, (0.28, 0.4, 0.04)),
)
def tray(size: Vec3, rng: Rng) -> Design:
    """A serving tray: a flat floor (a surface) inside a low rim."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    material = pick(rng, (*WOODS, STEEL, BLACK_PLASTIC, SILVER))
    ft = 0.006
    t = 0.008
    parts: list[Part] = [
        block((-hd, hd), (-hw, hw), (0.0, ft), material, surface=True),
        block((-hd, hd), (-hw, -hw + t), (ft, h), material),
        block((-hd, hd), (hw - t, hw), (ft, h), material),
        block((-hd, -hd + t), (-hw + t, hw - t), (ft, h), material),
        block((hd - t, hd), (-hw + t, hw - t), (ft, h), material),
    ]
    return Design(tuple(parts), {"material": material.words})


@category(
    "basket",
    "object",
    size=(0.25, 0.35, 0.2),
    low=(0.15, 0.2, 0.08),
    high=(0.45, 0.6, 0.4),
    mass=0.6,
    placement=("floor", "object"),
    description="a woven {weave} basket{handle}",
    variants=(None, (0.3, 0.3, 0.25)),
)
def basket(size: Vec3, rng: Rng) -> Design:
    """An open woven basket, maybe with a carrying handle across it."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    weave = pick(rng, (WICKER, SEAGRASS, DARK_WICKER))
    handle = chance(rng, 0.5) and h > 0.12
    wall_h = 0.65 * h if handle else h
    t = 0.012
    parts: list[Part] = [
        block((-hd, hd), (-hw, hw), (0.0, t), weave),
        block((-hd, hd), (-hw, -hw + t), (t, wall_h), weave),
        block((-hd, hd), (hw - t, hw), (t, wall_h), weave),
        block((-hd, -hd + t), (-hw + t, hw - t), (t, wall_h), weave),
        block((hd - t, hd), (-hw + t, hw - t), (t, wall_h), weave),
    ]
    if handle:
        parts += handle_arch((-hw, hw), (wall_h, h), t, weave)
    return Design(
        tuple(parts), {"weave": weave.words, "handle": " with a handle" if handle else ""}
    )


@category(
    "bread",
    "object",
    size=(0.12, 0.3, 0.1),
    low=(0.07, 0.15, 0.05),
    high=(0.2, 0.45, 0.15),
    mass=0.5,
    placement=OBJECT,
    description="a {crust} loaf of bread",
    variants=(None, (0.1, 0.22, 0.09)),
)
def bread(size: Vec3, rng: Rng) -> Design:
    """A loaf along Y: a flat-bottomed base and a rounded crown."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    crust = pick(rng, (CRUST, DARK_CRUST))
    r = min(0.48 * d, 0.45 * h)
    parts: list[Part] = [
        block((-hd, hd), (-hw, hw), (0.0, h - r), crust),
        cyl_y(-hw + 0.01, hw - 0.01, 0.0, h - r, r, crust),
    ]
    return Design(tuple(parts), {"crust": crust.words})


@category(
    "cake",
    "object",
    size=(0.25, 0.25, 0.12),
    low=(0.12, 0.12, 0.05),
    high=(0.35, 0.35, 0.25),
    mass=1.5,
    placement=OBJECT,
    yx_ratio=ROUND,
    description="a round cake with {icing} and berries",
    variants=(None, (0.2, 0.2, 0.16)),
)
def cake(size: Vec3, rng: Rng) -> Design:
    """A round cake: one or two tiers, icing on top and a ring of berries."""
    d, _, h = size
    r = 0.5 * d
    icing = pick(rng, (ICING, PINK_ICING, CHOCOLATE))
    berry = clamp(0.06 * r, 0.006, 0.012)
    body_top = h - 2 * berry
    two = chance(rng, 0.5) and h > 0.1
    parts: list[Part] = []
    top_r = r
    if two:
        low_top = 0.55 * body_top
        parts.append(cyl_z(0.0, 0.0, 0.0, low_top, r, icing))
        top_r = 0.6 * r
        parts.append(cyl_z(0.0, 0.0, low_top, body_top, top_r, icing))
    else:
        parts.append(cyl_z(0.0, 0.0, 0.0, body_top - 0.004, r, SPONGE))
        parts.append(cyl_z(0.0, 0.0, body_top - 0.004, body_top, r, icing))
    n = 6
    for i in range(n):
        angle = 2 * np.pi * i / n
        rr = top_r - 1.5 * berry
        c = (rr * float(np.cos(angle)), rr * float(np.sin(angle)), body_top + berry)
        parts.append(cyl_z(c[0], c[1], body_top, h, berry, BERRY, collide=False))
    return Design(tuple(parts), {"icing": icing.words})
