"""Open shelving: bookshelves and shelving units."""

from __future__ import annotations

from asset_pipeline.procedural.kit import (
    BLACK_METAL,
    CASE_FINISHES,
    GREY_LAMINATE,
    STEEL,
    WHITE_LACQUER,
    WOODS,
    block,
    chance,
    count_word,
    pick,
    uniform,
)
from asset_pipeline.procedural.parts import Part, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.storage import (
    Rng,
)


# --- open shelving -----------------------------------------------------------------------------
@category(
    "bookshelf",
    "furniture",
    size=(0.3, 0.8, 1.8),
    low=(0.22, 0.4, 0.6),
    high=(0.45, 1.8, 2.4),
    mass=30.0,
    friction=0.6,
    description="a {body} bookshelf with {levels} open shelves{divider}",
    variants=(None, (0.35, 1.2, 2.0)),
)
def bookshelf(size: Vec3, rng: Rng) -> Design:
    """An open bookcase (open side +X) with a back panel; every level and the top are surfaces."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    body = pick(rng, CASE_FINISHES)
    t = uniform(rng, 0.018, 0.03)
    kick = uniform(rng, 0.04, 0.1)
    top_bottom = h - t
    pitch_target = uniform(rng, 0.28, 0.38)
    levels = max(1, round((top_bottom - kick) / pitch_target))
    divider = w > 1.1 and chance(rng, 0.6)
    parts: list[Part] = [
        block((-hd, hd), (-hw, -hw + t), (0.0, top_bottom), body),
        block((-hd, hd), (hw - t, hw), (0.0, top_bottom), body),
        block((-hd, -hd + 0.01), (-hw + t, hw - t), (0.0, top_bottom), body),
        block((hd - t, hd), (-hw + t, hw - t), (0.0, kick - t), body),
        block((-hd, hd), (-hw, hw), (top_bottom, h), body, surface=True),
    ]
    spans = [(-hw + t, hw - t)]
    if divider:
        parts.append(block((-hd + 0.01, hd), (-0.5 * t, 0.5 * t), (kick, top_bottom), body))
        spans = [(-hw + t, -0.5 * t), (0.5 * t, hw - t)]
    pitch = (top_bottom - kick) / levels
    for i in range(levels):
        z = kick + i * pitch
        for y in spans:
            parts.append(block((-hd + 0.01, hd), y, (z - t, z), body, surface=True))
    words = {
        "body": body.words,
        "levels": count_word(levels + 1),
        "divider": " and a central divider" if divider else "",
    }
    return Design(tuple(parts), words)


@category(
    "shelving_unit",
    "furniture",
    size=(0.4, 0.9, 1.5),
    low=(0.3, 0.6, 0.8),
    high=(0.6, 1.6, 2.2),
    mass=15.0,
    friction=0.5,
    description="an open {post} shelving unit with {levels} {shelf} shelves",
    variants=(None, (0.45, 1.2, 1.8)),
)
def shelving_unit(size: Vec3, rng: Rng) -> Design:
    """Open shelving: four corner posts and evenly spaced shelves (each a surface)."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    post_mat = pick(rng, (STEEL, BLACK_METAL, *WOODS[:2]))
    shelf_mat = pick(rng, (GREY_LAMINATE, WHITE_LACQUER, *WOODS))
    post = uniform(rng, 0.025, 0.04)
    levels = max(3, round((h - 0.15) / uniform(rng, 0.35, 0.5)) + 1)
    parts: list[Part] = []
    for x in ((-hd, -hd + post), (hd - post, hd)):
        for y in ((-hw, -hw + post), (hw - post, hw)):
            parts.append(block(x, y, (0.0, h), post_mat))
    low = uniform(rng, 0.1, 0.18)
    for i in range(levels):
        top = low + i * (h - low) / (levels - 1)
        parts.append(
            block((-hd, hd), (-hw + post, hw - post), (top - 0.02, top), shelf_mat, surface=True)
        )
    words = {
        "post": post_mat.words,
        "levels": count_word(levels),
        "shelf": shelf_mat.words,
    }
    return Design(tuple(parts), words)
