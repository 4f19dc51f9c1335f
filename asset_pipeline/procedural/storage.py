"""Generators of storage furniture and kitchen and bathroom fixtures (front +X)."""

from __future__ import annotations

from asset_pipeline.procedural.kit import (
    BLACK_METAL,
    BRASS,
    CASE_FINISHES,
    CHROME,
    FRONT_T,
    GREY_LAMINATE,
    HANDLE_D,
    OAK,
    PAINTED,
    WALNUT,
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
from asset_pipeline.procedural.parts import Part, RecipeMaterial, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.roles import fronts as tag_fronts
from asset_pipeline.procedural.roles import tagged

PROUD = FRONT_T + HANDLE_D  # fronts and handles stand this far in front of a carcass
STONE = RecipeMaterial("stone_top", (0.85, 0.84, 0.80, 1.0), 0.5, 0.6, "pale stone")
DARK_STONE = RecipeMaterial("dark_stone", (0.20, 0.20, 0.21, 1.0), 0.5, 0.6, "dark stone")
WORKTOPS = (GREY_LAMINATE, STONE, DARK_STONE, OAK, WALNUT)
HANDLES = (BLACK_METAL, CHROME, BRASS)


def _case(
    size: Vec3,
    rng: Rng,
    *,
    body: RecipeMaterial,
    top: RecipeMaterial,
    top_t: float,
    overhang: float,
    base: str,
    fronts: list[tuple[tuple[float, float], int, int, str]],
    handle: RecipeMaterial,
) -> list[Part]:
    """A carcass with a top board (a surface) and rows of fronts.

    ``fronts`` lists (z fraction range of the front area, rows, columns, handle style).
    ``base``: ``plinth``, ``legs`` or ``none``. The top overhangs the fronts by ``overhang``.
    """
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    face = hd - overhang - PROUD
    base_h = {"none": 0.0, "plinth": uniform(rng, 0.06, 0.1), "legs": uniform(rng, 0.08, 0.15)}[
        base
    ]
    parts: list[Part] = []
    if base == "plinth":
        plinth = block(
            (-hd, face - 0.04),
            (-hw, hw),
            (0.0, base_h),
            BLACK_METAL if chance(rng, 0.3) else body,
        )
        parts += tagged("base", [plinth])
    elif base == "legs":
        legs = square_legs(face + hd, w, base_h, 0.04, pick(rng, (BLACK_METAL, *WOODS)), inset=0.02)
        parts += tagged("legs", (leg.translated((0.5 * (face - hd), 0.0, 0.0)) for leg in legs))
    parts += tagged("body", [block((-hd, face), (-hw, hw), (base_h, h - top_t), body)])
    parts += tagged("top", [block((-hd, hd), (-hw, hw), (h - top_t, h), top, surface=True)])
    z0, z1 = base_h + 0.005, h - top_t - 0.005
    for (f0, f1), rows, cols, style in fronts:
        made = drawer_fronts(
            face,
            (-hw + 0.002, hw - 0.002),
            (z0 + f0 * (z1 - z0), z0 + f1 * (z1 - z0)),
            rows,
            cols,
            body,
            handle,
            style=style,
        )
        parts += tag_fronts(made, style)
    return parts


@category(
    "wardrobe",
    "furniture",
    size=(0.6, 1.2, 2.0),
    low=(0.45, 0.5, 1.5),
    high=(0.7, 2.4, 2.4),
    mass=80.0,
    friction=0.6,
    description="a tall {body} wardrobe with {doors} doors{drawers}",
    variants=(None, (0.58, 1.8, 2.1)),
)
def wardrobe(size: Vec3, rng: Rng) -> Design:
    """A wardrobe: a row of doors, optionally above a row of drawers; the top is a surface."""
    w = size[1]
    doors = 1 if w < 0.7 else (2 if w < 1.4 else (3 if w < 2.0 else 4))
    drawers = chance(rng, 0.4)
    fronts = (
        [((0.2, 1.0), 1, doors, "door"), ((0.0, 0.2), 1, doors, "bar")]
        if drawers
        else [((0.0, 1.0), 1, doors, "door")]
    )
    body = pick(rng, CASE_FINISHES)
    parts = _case(
        size,
        rng,
        body=body,
        top=body,
        top_t=0.025,
        overhang=0.0,
        base=pick(rng, ("plinth", "legs", "none")),
        fronts=fronts,
        handle=pick(rng, HANDLES),
    )
    words = {
        "body": body.words,
        "doors": count_word(doors),
        "drawers": " above drawers" if drawers else "",
    }
    return Design(tuple(parts), words)


@category(
    "dresser",
    "furniture",
    size=(0.5, 1.2, 0.85),
    low=(0.35, 0.5, 0.6),
    high=(0.65, 2.0, 1.3),
    mass=50.0,
    friction=0.6,
    description="a {body} chest of {count} drawers with {handle} handles",
    variants=(None, (0.45, 0.8, 1.1)),
)
def dresser(size: Vec3, rng: Rng) -> Design:
    """A chest of drawers in one or two columns; the top is a surface."""
    _, w, h = size
    rows = int(clamp(int(rng.integers(3, 6)), 2, max(2, int((h - 0.15) / 0.14))))
    cols = 1 if w < 0.8 else (2 if w < 1.6 else 3)
    if cols == 2 and w < 1.0 and chance(rng, 0.5):
        cols = 1
    body = pick(rng, CASE_FINISHES)
    top = body if chance(rng, 0.6) else pick(rng, WOODS)
    handle = pick(rng, HANDLES)
    parts = _case(
        size,
        rng,
        body=body,
        top=top,
        top_t=uniform(rng, 0.02, 0.035),
        overhang=0.0,
        base=pick(rng, ("plinth", "legs")),
        fronts=[((0.0, 1.0), rows, cols, pick(rng, ("bar", "knob")))],
        handle=handle,
    )
    words = {
        "body": body.words,
        "count": count_word(rows * cols),
        "handle": handle.words,
    }
    return Design(tuple(parts), words)


@category(
    "nightstand",
    "furniture",
    size=(0.4, 0.45, 0.55),
    low=(0.3, 0.3, 0.4),
    high=(0.55, 0.65, 0.75),
    mass=12.0,
    friction=0.6,
    description="a {body} nightstand with {count} drawer{s} and a {top} top",
    variants=(None, (0.38, 0.5, 0.6)),
)
def nightstand(size: Vec3, rng: Rng) -> Design:
    """A bedside cabinet with one to three drawers; the top is a surface."""
    rows = int(rng.integers(1, 4))
    body = pick(rng, CASE_FINISHES)
    top = body if chance(rng, 0.5) else pick(rng, WOODS)
    parts = _case(
        size,
        rng,
        body=body,
        top=top,
        top_t=uniform(rng, 0.02, 0.03),
        overhang=0.0,
        base=pick(rng, ("plinth", "legs", "none")),
        fronts=[((0.0, 1.0), rows, 1, pick(rng, ("bar", "knob")))],
        handle=pick(rng, HANDLES),
    )
    words = {
        "body": body.words,
        "count": count_word(rows),
        "s": "s" if rows > 1 else "",
        "top": top.words,
    }
    return Design(tuple(parts), words)


@category(
    "tv_stand",
    "furniture",
    size=(0.45, 1.6, 0.5),
    low=(0.3, 0.8, 0.35),
    high=(0.6, 2.4, 0.7),
    mass=30.0,
    friction=0.6,
    description="a long low {body} tv stand with {count} {kind}",
    variants=(None, (0.4, 1.2, 0.55)),
)
def tv_stand(size: Vec3, rng: Rng) -> Design:
    """A low media cabinet with doors or drawers; the top is a surface."""
    cols = int(clamp(round(size[1] / 0.55), 2, 4))
    kind = pick(rng, ("doors", "drawers"))
    body = pick(rng, CASE_FINISHES)
    parts = _case(
        size,
        rng,
        body=body,
        top=body,
        top_t=uniform(rng, 0.025, 0.04),
        overhang=0.0,
        base=pick(rng, ("legs", "plinth")),
        fronts=[((0.0, 1.0), 1, cols, "door" if kind == "doors" else "bar")],
        handle=pick(rng, HANDLES),
    )
    return Design(tuple(parts), {"body": body.words, "count": count_word(cols), "kind": kind})


def _kitchen_base(size: Vec3, rng: Rng, worktop: bool) -> tuple[list[Part], dict[str, str]]:
    w = size[1]
    cols = max(1, round(w / 0.5))
    body = pick(rng, (*PAINTED, OAK))
    top = pick(rng, WORKTOPS) if worktop else body
    drawer_row = chance(rng, 0.5) and size[2] > 0.6
    fronts = (
        [((0.0, 0.78), 1, cols, "door"), ((0.78, 1.0), 1, cols, "bar")]
        if drawer_row
        else [((0.0, 1.0), 1, cols, "door")]
    )
    parts = _case(
        size,
        rng,
        body=body,
        top=top,
        top_t=0.04 if worktop else 0.02,
        overhang=uniform(rng, 0.015, 0.03) if worktop else 0.0,
        base="plinth",
        fronts=fronts,
        handle=pick(rng, HANDLES),
    )
    return parts, {
        "body": body.words,
        "top": top.words,
        "doors": count_word(cols),
        "drawers": " under a row of drawers" if drawer_row else "",
    }


@category(
    "kitchen_counter",
    "furniture",
    size=(0.62, 1.2, 0.9),
    low=(0.55, 0.3, 0.85),
    high=(0.75, 3.0, 0.95),
    mass=60.0,
    friction=0.6,
    description="a {body} kitchen counter with a {top} worktop and {doors} door(s){drawers}",
    variants=(None, (0.62, 2.4, 0.92)),
)
def kitchen_counter(size: Vec3, rng: Rng) -> Design:
    """A run of kitchen base units under one worktop (a surface)."""
    parts, words = _kitchen_base(size, rng, worktop=True)
    return Design(tuple(parts), words)


@category(
    "base_cabinet",
    "furniture",
    size=(0.58, 0.6, 0.88),
    low=(0.35, 0.3, 0.5),
    high=(0.7, 1.2, 0.95),
    mass=28.0,
    friction=0.6,
    description="a {body} base cabinet with {doors} door(s){drawers}",
    variants=(None, (0.45, 0.9, 0.8)),
)
def base_cabinet(size: Vec3, rng: Rng) -> Design:
    """A single floor cabinet with a flush top (a surface)."""
    parts, words = _kitchen_base(size, rng, worktop=False)
    return Design(tuple(parts), words)


def _wall_unit(
    size: Vec3, rng: Rng, bodies: tuple[RecipeMaterial, ...]
) -> tuple[list[Part], dict[str, str]]:
    cols = 1 if size[1] < 0.55 else (2 if size[1] < 1.1 else 3)
    body = pick(rng, bodies)
    parts = _case(
        size,
        rng,
        body=body,
        top=body,
        top_t=0.02,
        overhang=0.0,
        base="none",
        fronts=[((0.0, 1.0), 1, cols, "door")],
        handle=pick(rng, HANDLES),
    )
    return parts, {"body": body.words, "doors": count_word(cols), "s": "s" if cols > 1 else ""}


@category(
    "kitchen_cabinet",
    "furniture",
    size=(0.35, 0.8, 0.7),
    low=(0.25, 0.3, 0.3),
    high=(0.45, 1.5, 1.0),
    mass=18.0,
    friction=0.6,
    placement=("wall",),
    description="a {body} wall-mounted kitchen cabinet with {doors} door{s}",
    variants=(None, (0.33, 0.6, 0.9)),
)
def kitchen_cabinet(size: Vec3, rng: Rng) -> Design:
    """A kitchen wall unit (hangs on a wall; its bottom is z = 0 of the asset)."""
    parts, words = _wall_unit(size, rng, (*PAINTED, OAK))
    return Design(tuple(parts), words)


@category(
    "wall_cabinet",
    "furniture",
    size=(0.2, 0.6, 0.7),
    low=(0.12, 0.3, 0.3),
    high=(0.45, 1.5, 1.2),
    mass=10.0,
    friction=0.6,
    placement=("wall",),
    description="a {body} wall cabinet with {doors} door{s}",
    variants=(None, (0.3, 1.0, 0.5)),
)
def wall_cabinet(size: Vec3, rng: Rng) -> Design:
    """A wall-mounted cabinet (bathroom, hall, utility room)."""
    parts, words = _wall_unit(size, rng, CASE_FINISHES)
    return Design(tuple(parts), words)
