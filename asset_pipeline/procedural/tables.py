"""Tables and desks: coffee, side and dining tables, and desks."""

from __future__ import annotations

from asset_pipeline.procedural.kit import (
    BLACK_METAL,
    BRASS,
    CASE_FINISHES,
    CHROME,
    WOODS,
    Rng,
    block,
    chance,
    clamp,
    drawer_fronts,
    pick,
    round_legs,
    square_legs,
    uniform,
)
from asset_pipeline.procedural.parts import Part, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.roles import fronts, tagged
from asset_pipeline.procedural.round_parts import Cylinder


# --- tables and desks ------------------------------------------------------------------------
def _table(
    size: Vec3, rng: Rng, *, shelf_chance: float, allow_round: bool
) -> tuple[list[Part], dict[str, str]]:
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    top_mat = pick(rng, CASE_FINISHES)
    leg_mat = top_mat if chance(rng, 0.6) else pick(rng, (BLACK_METAL, *WOODS))
    t = uniform(rng, 0.02, 0.045)
    parts: list[Part] = []
    if allow_round and abs(d - w) < 1e-3 and chance(rng, 0.6):
        r = hd
        base_r = min(0.6 * r, 0.3)
        foot = Cylinder((0.0, 0.0, 0.02), base_r, 0.02, leg_mat)
        column = Cylinder((0.0, 0.0, 0.5 * (h - t + 0.04)), 0.05, 0.5 * (h - t - 0.04), leg_mat)
        parts += tagged("base", [foot, column])
        top = Cylinder((0.0, 0.0, h - 0.5 * t), r, 0.5 * t, top_mat, surface=True)
        parts += tagged("top", [top])
        return parts, {"top": top_mat.words, "shape": "round", "legs": "a pedestal", "shelf": ""}
    legs = pick(rng, ("square legs", "round legs", "panel legs"))
    inset = uniform(rng, 0.0, min(0.06, 0.1 * d))
    side = clamp(uniform(rng, 0.035, 0.07), 0.03, 0.12 * min(d, w))
    leg_h = h - t
    if legs == "square legs":
        parts += tagged("legs", square_legs(d, w, leg_h, side, leg_mat, inset=inset))
    elif legs == "round legs":
        supports = round_legs(d, w, leg_h, 0.5 * side, leg_mat, inset=inset + 0.5 * side)
        parts += tagged("legs", supports)
    else:
        for y in ((-hw + inset, -hw + inset + side), (hw - inset - side, hw - inset)):
            parts += tagged("legs", [block((-hd + inset, hd - inset), y, (0.0, leg_h), leg_mat)])
    parts += tagged("top", [block((-hd, hd), (-hw, hw), (leg_h, h), top_mat, surface=True)])
    shelf = chance(rng, shelf_chance) and h > 0.3
    if shelf:
        x_in = hd - inset - (side if legs == "square legs" else 0.0) - 0.002
        y_in = hw - inset - side - 0.002
        z = min(0.12, 0.3 * h)
        board = block((-x_in, x_in), (-y_in, y_in), (z - 0.02, z), top_mat, surface=True)
        parts += tagged("shelves", [board])
    return parts, {
        "top": top_mat.words,
        "shape": "square" if abs(d - w) < 1e-3 else "rectangular",
        "legs": legs if leg_mat is top_mat else f"{leg_mat.words} {legs}",
        "shelf": " and a lower shelf" if shelf else "",
    }


@category(
    "coffee_table",
    "furniture",
    size=(0.6, 1.1, 0.42),
    low=(0.4, 0.4, 0.3),
    high=(1.0, 1.6, 0.55),
    mass=15.0,
    friction=0.6,
    description="a low {shape} {top} coffee table on {legs}{shelf}",
    variants=(None, (0.8, 0.8, 0.4)),
)
def coffee_table(size: Vec3, rng: Rng) -> Design:
    """A low table, often with a lower shelf."""
    parts, words = _table(size, rng, shelf_chance=0.5, allow_round=True)
    return Design(tuple(parts), words)


@category(
    "side_table",
    "furniture",
    size=(0.45, 0.45, 0.55),
    low=(0.3, 0.3, 0.4),
    high=(0.7, 0.7, 0.8),
    mass=6.0,
    friction=0.6,
    description="a small {shape} {top} side table on {legs}{shelf}",
    variants=(None, (0.4, 0.5, 0.6)),
)
def side_table(size: Vec3, rng: Rng) -> Design:
    """A small table beside a sofa or a bed."""
    parts, words = _table(size, rng, shelf_chance=0.3, allow_round=True)
    return Design(tuple(parts), words)


@category(
    "dining_table",
    "furniture",
    size=(0.9, 1.6, 0.75),
    low=(0.7, 0.7, 0.7),
    high=(1.2, 2.6, 0.8),
    mass=35.0,
    friction=0.6,
    description="a {shape} {top} dining table on {legs}",
    variants=(None, (1.1, 1.1, 0.75)),
)
def dining_table(size: Vec3, rng: Rng) -> Design:
    """A dining table: four legs, panel legs, or (square footprint) a round pedestal table."""
    parts, words = _table(size, rng, shelf_chance=0.0, allow_round=True)
    return Design(tuple(parts), words)


@category(
    "desk",
    "furniture",
    size=(0.7, 1.4, 0.75),
    low=(0.5, 0.8, 0.7),
    high=(0.9, 2.0, 0.8),
    mass=30.0,
    friction=0.6,
    description="a {top} desk {style}",
    variants=(None, (0.6, 1.2, 0.75)),
)
def desk(size: Vec3, rng: Rng) -> Design:
    """A desk on legs or with a drawer pedestal on its right (+Y) and panel legs."""
    d, w, h = size
    if chance(rng, 0.4):
        table, words = _table(size, rng, shelf_chance=0.0, allow_round=False)
        return Design(tuple(table), {"top": words["top"], "style": f"on {words['legs']}"})
    hd, hw = 0.5 * d, 0.5 * w
    mat = pick(rng, CASE_FINISHES)
    handle = pick(rng, (BLACK_METAL, CHROME, BRASS))
    t = uniform(rng, 0.025, 0.04)
    drawers = int(rng.integers(2, 5))
    ped_w = clamp(uniform(rng, 0.38, 0.45), 0.3, 0.35 * w)
    face = hd - 0.05 - 0.036
    parts: list[Part] = [
        *tagged("top", [block((-hd, hd), (-hw, hw), (h - t, h), mat, surface=True)]),
        *tagged(
            "body", [block((-hd + 0.02, face), (hw - 0.02 - ped_w, hw - 0.02), (0.0, h - t), mat)]
        ),
        *tagged(
            "legs", [block((-hd + 0.02, hd - 0.05), (-hw + 0.02, -hw + 0.05), (0.0, h - t), mat)]
        ),
    ]
    parts += fronts(
        drawer_fronts(
            face, (hw - 0.02 - ped_w, hw - 0.02), (0.02, h - t - 0.01), drawers, 1, mat, handle
        )
    )
    return Design(tuple(parts), {"top": mat.words, "style": f"with a {drawers}-drawer pedestal"})
