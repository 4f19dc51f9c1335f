"""Generators of kitchen islands, bar counters and tables, stands and racks (front +X).

Sizes are bounding boxes (x = depth, y = width, z = height); fronts face +X. Like every
asset they have their lowest point at z = 0 and stand upright on a flat bottom.
"""

from __future__ import annotations

from asset_pipeline.procedural.home_kit import (
    BRICK,
    DARK_GREY,
    HANDLES,
    MARBLE,
    PROUD,
    ROUND,
)
from asset_pipeline.procedural.kit import (
    ASH,
    BLACK_METAL,
    BRASS,
    CHROME,
    FABRICS,
    NAVY_LACQUER,
    OAK,
    PAINTED,
    WALNUT,
    WHITE_LACQUER,
    WOODS,
    Rng,
    block,
    chance,
    clamp,
    count_word,
    drawer_fronts,
    pick,
    square_legs,
    uniform,
)
from asset_pipeline.procedural.parts import Part, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.round_parts import Cylinder
from asset_pipeline.procedural.storage import DARK_STONE, WORKTOPS


@category(
    "kitchen_island",
    "furniture",
    size=(0.9, 1.8, 0.92),
    low=(0.7, 1.0, 0.85),
    high=(1.2, 3.0, 1.0),
    mass=150.0,
    friction=0.6,
    description="a kitchen island with a {top} worktop over {body} cupboards{ends}"
    " and an overhang for stools",
    variants=(None, (0.8, 1.2, 0.92), (1.0, 2.4, 0.92)),
)
def kitchen_island(size: Vec3, rng: Rng) -> Design:
    """A kitchen island: base cupboards and drawers facing +X, a worktop (a surface) that
    overhangs the -X side for bar stools, and plain or waterfall ends."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    body = pick(rng, (*PAINTED, OAK, WALNUT))
    top = pick(rng, (*WORKTOPS, MARBLE))
    handle = pick(rng, HANDLES)
    top_t = 0.04
    over = clamp(uniform(rng, 0.25, 0.32), 0.15, d - 0.55)
    fx = hd - 0.02 - PROUD
    ends = pick(rng, ("plain", "waterfall", "shelves"))
    end_t = 0.04 if ends == "waterfall" else 0.0
    y0, y1 = -hw + end_t, hw - end_t
    shelf_w = clamp(0.3 * w, 0.3, 0.45) if ends == "shelves" else 0.0
    kick = 0.08
    x0 = -hd + over
    parts: list[Part] = [
        block((-hd, hd), (-hw, hw), (h - top_t, h), top, surface=True),
        block(
            (x0, fx - 0.04),
            (y0, y1 - shelf_w),
            (0.0, kick),
            BLACK_METAL if chance(rng, 0.3) else body,
        ),
        block((x0, fx), (y0, y1 - shelf_w), (kick, h - top_t), body),
    ]
    if end_t:
        for y in ((-hw, y0), (y1, hw)):
            parts.append(block((-hd, hd), y, (0.0, h - top_t), top))
    if shelf_w:
        ys = (y1 - shelf_w, y1)
        parts.append(block((x0, hd - 0.02), (ys[1] - 0.02, ys[1]), (0.0, h - top_t), body))
        parts.append(block((x0, x0 + 0.015), (ys[0], ys[1] - 0.02), (0.0, h - top_t), body))
        for z in (0.0, 0.5 * (h - top_t)):
            parts.append(
                block(
                    (x0 + 0.015, hd - 0.02),
                    (ys[0], ys[1] - 0.02),
                    (z, z + 0.02),
                    body,
                    surface=True,
                )
            )
    cols = max(1, round((y1 - shelf_w - y0) / 0.6))
    zf = (kick + 0.005, h - top_t - 0.005)
    zm = zf[0] + 0.75 * (zf[1] - zf[0])
    parts += drawer_fronts(
        fx, (y0 + 0.002, y1 - shelf_w - 0.002), (zf[0], zm), 1, cols, body, handle, style="door"
    )
    parts += drawer_fronts(
        fx, (y0 + 0.002, y1 - shelf_w - 0.002), (zm, zf[1]), 1, cols, body, handle
    )
    words = {
        "top": top.words,
        "body": body.words,
        "ends": {
            "waterfall": " with waterfall ends",
            "shelves": " with open shelves at one end",
        }.get(ends, ""),
    }
    return Design(tuple(parts), words)


@category(
    "bar_counter",
    "furniture",
    size=(0.7, 2.0, 1.1),
    low=(0.55, 1.0, 1.0),
    high=(0.9, 4.0, 1.2),
    mass=150.0,
    friction=0.6,
    description="a long {panel} bar counter with a {top} bar top, a {metal} foot rail and a "
    "lower work counter behind",
    variants=(None, (0.75, 3.0, 1.1), (0.6, 1.4, 1.05)),
)
def bar_counter(size: Vec3, rng: Rng) -> Design:
    """A bar: a front panel (customers at +X) under a raised bar top (a surface) that
    overhangs the front, a foot rail, and a lower work counter (a surface) behind at -X."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    panel = pick(rng, (*WOODS, NAVY_LACQUER, DARK_GREY, BRICK))
    top = pick(rng, (WALNUT, OAK, DARK_STONE, MARBLE))
    metal = pick(rng, (BRASS, CHROME, BLACK_METAL))
    top_t = 0.045
    back_d = clamp(uniform(rng, 0.38, 0.45) * d, 0.25, d - 0.3)
    px0 = -hd + back_d
    pt = 0.05
    over = hd - (px0 + pt)
    work_z = min(uniform(rng, 0.86, 0.92), h - 0.12)
    parts: list[Part] = [
        block((px0, hd), (-hw, hw), (h - top_t, h), top, surface=True),
        block((px0, px0 + pt), (-hw, hw), (0.0, h - top_t), panel),
        block((-hd, px0), (-hw, hw), (0.0, work_z - 0.03), panel),
        block((-hd, px0), (-hw, hw), (work_z - 0.03, work_z), top, surface=True),
    ]
    rail_x = px0 + pt + min(0.1, over - 0.04)
    rail_r = 0.022
    ry = hw - 0.08
    parts.append(Cylinder((rail_x, 0.0, 0.2), rail_r, ry, metal, axis="y"))
    for y in (-ry + 0.04, ry - 0.04):
        parts.append(block((px0 + pt, rail_x), (y - 0.01, y + 0.01), (0.19, 0.21), metal))
    if chance(rng, 0.5):
        for z in (0.35, 0.65):
            parts.append(
                block(
                    (px0 + pt, px0 + pt + 0.004),
                    (-hw, hw),
                    (z * (h - top_t), z * (h - top_t) + 0.02),
                    metal,
                    collide=False,
                )
            )
    words = {"panel": panel.words, "top": top.words, "metal": metal.words}
    return Design(tuple(parts), words)


@category(
    "bar_table",
    "furniture",
    size=(0.7, 0.7, 1.05),
    low=(0.5, 0.5, 0.95),
    high=(1.0, 1.0, 1.15),
    mass=20.0,
    friction=0.6,
    yx_ratio=ROUND,
    description="a tall {shape} {top} bar table on {base}",
    variants=(None, (0.6, 0.6, 1.0), (0.8, 0.8, 1.1)),
)
def bar_table(size: Vec3, rng: Rng) -> Design:
    """A tall table: a round top on a pedestal or cross base, or a square top on four legs
    with footrests; the top is a surface."""
    d, _, h = size
    r = 0.5 * d
    top = pick(rng, (*WOODS, WHITE_LACQUER, MARBLE, BLACK_METAL))
    metal = pick(rng, (BLACK_METAL, CHROME, BRASS))
    t = 0.035
    style = pick(rng, ("pedestal", "cross", "legs"))
    if style == "legs":
        parts: list[Part] = [block((-r, r), (-r, r), (h - t, h), top, surface=True)]
        parts += square_legs(d, d, h - t, 0.04, metal, inset=0.03)
        for s in (-1.0, 1.0):
            xs = sorted((s * (r - 0.03), s * (r - 0.05)))
            parts.append(block((xs[0], xs[1]), (-r + 0.07, r - 0.07), (0.28, 0.3), metal))
        return Design(
            tuple(parts),
            {
                "shape": "square",
                "top": top.words,
                "base": f"four {metal.words} legs with footrests",
            },
        )
    parts = [Cylinder((0.0, 0.0, h - 0.5 * t), r, 0.5 * t, top, surface=True)]
    col_r = 0.035
    parts.append(Cylinder((0.0, 0.0, 0.5 * (h - t + 0.03)), col_r, 0.5 * (h - t - 0.03), metal))
    if style == "pedestal":
        parts.append(Cylinder((0.0, 0.0, 0.015), clamp(0.65 * r, 0.22, r), 0.015, metal))
        base = f"a heavy {metal.words} pedestal"
    else:
        reach = clamp(0.8 * r, 0.22, r)
        parts.append(block((-reach, reach), (-0.03, 0.03), (0.0, 0.04), metal))
        parts.append(block((-0.03, 0.03), (-reach, reach), (0.0, 0.04), metal))
        base = f"a {metal.words} cross base"
    return Design(tuple(parts), {"shape": "round", "top": top.words, "base": base})


@category(
    "plant_stand",
    "furniture",
    size=(0.35, 0.35, 0.7),
    low=(0.25, 0.25, 0.3),
    high=(0.5, 0.5, 1.1),
    mass=4.0,
    friction=0.7,
    yx_ratio=(0.8, 1.25),
    description="a small {shape} {wood} plant stand {style}",
    variants=(None, (0.3, 0.3, 0.5), (0.4, 0.4, 0.9)),
)
def plant_stand(size: Vec3, rng: Rng) -> Design:
    """A plant stand: a top (a surface) on four legs with a lower shelf (a surface), or a
    round top on a column and a base."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    wood = pick(rng, (*WOODS, BLACK_METAL, BRASS, WHITE_LACQUER))
    t = 0.025
    if abs(d - w) < 1e-3 and chance(rng, 0.4):
        parts: list[Part] = [
            Cylinder((0.0, 0.0, h - 0.5 * t), hd, 0.5 * t, wood, surface=True),
            Cylinder((0.0, 0.0, 0.5 * h), 0.03, 0.5 * h - t, wood),
            Cylinder((0.0, 0.0, 0.5 * t), 0.85 * hd, 0.5 * t, wood),
        ]
        return Design(tuple(parts), {"shape": "round", "wood": wood.words, "style": "on a column"})
    parts = [block((-hd, hd), (-hw, hw), (h - t, h), wood, surface=True)]
    parts += square_legs(d, w, h - t, 0.03, wood)
    shelf = h > 0.45
    if shelf:
        z = clamp(0.3 * h, 0.1, 0.3)
        parts.append(
            block(
                (-hd + 0.03, hd - 0.03), (-hw + 0.03, hw - 0.03), (z - 0.02, z), wood, surface=True
            )
        )
    words = {
        "shape": "square" if abs(d - w) < 1e-3 else "rectangular",
        "wood": wood.words,
        "style": "with a lower shelf" if shelf else "on four legs",
    }
    return Design(tuple(parts), words)


@category(
    "shoe_rack",
    "furniture",
    size=(0.3, 0.8, 0.5),
    low=(0.22, 0.5, 0.3),
    high=(0.45, 1.2, 1.1),
    mass=6.0,
    friction=0.7,
    description="a low {body} shoe rack with {levels} shelves{seat}",
    variants=(None, (0.28, 0.6, 0.45), (0.35, 1.0, 0.9)),
)
def shoe_rack(size: Vec3, rng: Rng) -> Design:
    """Open shoe shelves between two side panels; every shelf and the top are surfaces (a
    cushioned top makes a shoe bench)."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    body = pick(rng, (*WOODS, BLACK_METAL, WHITE_LACQUER, ASH))
    t = 0.02 if body is not BLACK_METAL else 0.012
    seat = h <= 0.6 and chance(rng, 0.4)
    top = h - (0.05 if seat else 0.0)
    parts: list[Part] = [
        block((-hd, hd), (-hw, -hw + t), (0.0, top - t), body),
        block((-hd, hd), (hw - t, hw), (0.0, top - t), body),
        block((-hd, hd), (-hw, hw), (top - t, top), body, surface=not seat),
    ]
    if seat:
        parts.append(
            block(
                (-hd + 0.01, hd - 0.01),
                (-hw + 0.01, hw - 0.01),
                (top, h),
                pick(rng, FABRICS),
                surface=True,
            )
        )
    levels = int(clamp(round((top - 0.05) / 0.17), 1, 5))
    pitch = (top - t - 0.04) / levels
    for i in range(levels):
        z = 0.04 + i * pitch
        parts.append(block((-hd, hd), (-hw + t, hw - t), (z, z + t), body, surface=True))
    words = {
        "body": body.words,
        "levels": count_word(levels + (0 if seat else 1)),
        "seat": " and a cushioned seat on top" if seat else "",
    }
    return Design(tuple(parts), words)


@category(
    "wine_rack",
    "furniture",
    size=(0.35, 0.6, 1.2),
    low=(0.25, 0.3, 0.4),
    high=(0.45, 1.2, 2.0),
    mass=15.0,
    friction=0.7,
    description="a {body} wine rack with {cells} bottle cubbies holding {bottles} bottles",
    variants=(None, (0.35, 1.0, 1.8), (0.3, 0.45, 0.6)),
)
def wine_rack(size: Vec3, rng: Rng) -> Design:
    """A grid of bottle cubbies (bottles lie along X, necks out) under a top (a surface)."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    body = pick(rng, (*WOODS, BLACK_METAL, WHITE_LACQUER))
    t = 0.015
    base = 0.04
    cell = uniform(rng, 0.1, 0.12)
    cols = max(1, int((w - t) / cell))
    rows = max(1, int((h - 2 * t - base) / cell))
    cw = (w - 2 * t) / cols
    ch = (h - t - base) / rows
    parts: list[Part] = [
        block((-hd, hd), (-hw, hw), (h - t, h), body, surface=True),
        block((-hd, hd), (-hw, -hw + t), (0.0, h - t), body),
        block((-hd, hd), (hw - t, hw), (0.0, h - t), body),
        block((-hd, hd - 0.02), (-hw + t, hw - t), (0.0, base), body),
    ]
    for i in range(1, rows):
        z = base + i * ch
        parts.append(block((-hd, hd), (-hw + t, hw - t), (z - 0.5 * t, z + 0.5 * t), body))
    for j in range(1, cols):
        y = -hw + t + j * cw
        parts.append(block((-hd, hd), (y - 0.004, y + 0.004), (base, h - t), body))
    glass = pick(rng, ("green_glass", "amber_glass"))
    from asset_pipeline.procedural.kit import AMBER_GLASS, GREEN_GLASS

    bottle_mat = GREEN_GLASS if glass == "green_glass" else AMBER_GLASS
    cells = [(i, j) for i in range(rows) for j in range(cols)]
    count = min(len(cells), int(rng.integers(2, 5)))
    chosen = rng.choice(len(cells), size=count, replace=False)
    br = min(0.037, 0.5 * min(cw - 0.008, ch - t) - 0.004)
    for k in sorted(int(c) for c in chosen):
        i, j = cells[k]
        yc = -hw + t + (j + 0.5) * cw
        zc = base + i * ch + 0.5 * t + br + 0.001
        parts.append(Cylinder((0.0, yc, zc), br, hd - 0.03, bottle_mat, axis="x"))
    words = {"body": body.words, "cells": str(rows * cols), "bottles": count_word(count)}
    return Design(tuple(parts), words)


@category(
    "magazine_rack",
    "furniture",
    size=(0.35, 0.6, 1.2),
    low=(0.25, 0.35, 0.35),
    high=(0.45, 0.9, 1.5),
    mass=10.0,
    friction=0.7,
    description="a {body} magazine rack with {levels} lipped shelves",
    variants=(None, (0.3, 0.45, 0.5), (0.4, 0.8, 1.4)),
)
def magazine_rack(size: Vec3, rng: Rng) -> Design:
    """A literature rack: side panels, a back, and shelves with a front lip that holds the
    magazines (every shelf and the top are surfaces)."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    body = pick(rng, (*WOODS, BLACK_METAL, WHITE_LACQUER, CHROME))
    t = 0.018
    lip = 0.012
    parts: list[Part] = [
        block((-hd, hd), (-hw, -hw + t), (0.0, h - t), body),
        block((-hd, hd), (hw - t, hw), (0.0, h - t), body),
        block((-hd, -hd + 0.01), (-hw + t, hw - t), (0.0, h - t), body),
        block((-hd, hd), (-hw, hw), (h - t, h), body, surface=True),
    ]
    levels = int(clamp(round((h - 0.1) / 0.3), 1, 5))
    pitch = (h - t - 0.03) / levels
    for i in range(levels):
        z = 0.03 + i * pitch
        parts.append(block((-hd + 0.01, hd), (-hw + t, hw - t), (z, z + t), body, surface=True))
        parts.append(block((hd - lip, hd), (-hw + t, hw - t), (z + t, z + t + 0.05), body))
    return Design(tuple(parts), {"body": body.words, "levels": count_word(levels + 1)})
