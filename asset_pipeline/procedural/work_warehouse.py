"""Generators of warehouse furniture (front +X).

Every generator fills exactly ``[-d/2, d/2] x [-w/2, w/2] x [0, h]`` (x = depth, y = width).
"""

from __future__ import annotations

from asset_pipeline.procedural.kit import (
    CARDBOARD,
    PINE,
    SPACE_GREY,
    STEEL,
    Rng,
    block,
    chance,
    clamp,
    pick,
    uniform,
)
from asset_pipeline.procedural.leisure_kit import (
    BLUE_PAINT,
    YELLOW_PAINT,
)
from asset_pipeline.procedural.parts import Part, RecipeMaterial, Vec3
from asset_pipeline.procedural.registry import Design, category
from asset_pipeline.procedural.work_kit import (
    NUMBER_WORDS,
)

ORANGE_STEEL = RecipeMaterial("orange_steel", (0.92, 0.42, 0.08, 1.0), 0.5, 0.5, "orange")


# --- warehouse --------------------------------------------------------------------------------
@category(
    "pallet_rack",
    "furniture",
    size=(1.0, 2.7, 2.5),
    low=(0.8, 1.5, 1.8),
    high=(1.2, 3.6, 3.2),
    mass=450.0,
    friction=0.8,
    description="a steel pallet rack with {beams} beams and {levels} levels of pallets loaded "
    "with cardboard boxes",
    variants=(None, (0.9, 1.8, 2.0), (1.1, 3.3, 3.0)),
)
def pallet_rack(size: Vec3, rng: Rng) -> Design:
    """Two upright frames at +-Y with braces, beam pairs at each level, pallets with boxes."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    upright = pick(rng, (BLUE_PAINT, ORANGE_STEEL, SPACE_GREY))
    beam = pick(rng, (ORANGE_STEEL, YELLOW_PAINT, BLUE_PAINT))
    post = 0.08
    levels = int(clamp(round(h / 0.95), 2, 4))
    pitch = (h - 0.1) / levels
    parts: list[Part] = []
    for y in ((-hw, -hw + post), (hw - post, hw)):
        for x in ((-hd, -hd + post), (hd - post, hd)):
            parts.append(block(x, y, (0.0, h), upright))
        for k in range(int(h // 0.6)):
            z = 0.3 + k * 0.6
            parts.append(
                block((-hd + post, hd - post), (y[0] + 0.02, y[1] - 0.02), (z, z + 0.04), upright)
            )
    yi = (-hw + post, hw - post)
    bays = max(1, round((w - 2 * post) / 1.3))
    bw = (yi[1] - yi[0]) / bays
    for lev in range(levels):
        z = 0.0 if lev == 0 else lev * pitch
        if lev:
            for x in ((-hd, -hd + 0.05), (hd - 0.05, hd)):
                parts.append(block(x, yi, (z - 0.1, z), beam))
            parts.append(block((-hd + 0.05, hd - 0.05), yi, (z - 0.01, z), STEEL))
        room = pitch - 0.25 if lev < levels - 1 else h - z - 0.2
        for b in range(bays):
            y0 = yi[0] + b * bw + 0.05
            y1 = y0 + bw - 0.1
            if not chance(rng, 0.85):
                continue
            px = (-hd + 0.02, hd - 0.02)
            for x0 in (px[0], 0.0, px[1] - 0.1):
                xx = (x0 - 0.05, x0 + 0.05) if x0 == 0.0 else (x0, x0 + 0.1)
                parts.append(block(xx, (y0, y1), (z, z + 0.1), PINE))
            parts.append(block(px, (y0, y1), (z + 0.1, z + 0.14), PINE))
            boxes = int(rng.integers(1, 4))
            for j in range(boxes):
                by = (y0 + j * (y1 - y0) / boxes + 0.01, y0 + (j + 1) * (y1 - y0) / boxes - 0.01)
                bh = uniform(rng, 0.3, 1.0) * max(0.1, room - 0.14)
                parts.append(
                    block((px[0] + 0.03, px[1] - 0.03), by, (z + 0.14, z + 0.14 + bh), CARDBOARD)
                )
    return Design(tuple(parts), {"beams": beam.words, "levels": NUMBER_WORDS[levels]})
