"""Shared palette and shorthands of the small-item generators (``small_*.py``).

Small items stand on furniture (placement ``object``, issue 15). Sizes follow the knowledge
base (``objects.json``, whose (width, depth, height) is (y, x, z) here); fronts face +X.
Every item stands on a flat base as wide as practical so that it rests when dropped on a
table; thin details (keys, labels, screens, pens) are visual only. Round items
(``yx_ratio=(1, 1)``) take x = y = diameter.
"""

from __future__ import annotations

from asset_pipeline.procedural.kit import (
    ALUMINIUM,
    BLACK_PLASTIC,
    SPACE_GREY,
    STEEL,
    WHITE_PLASTIC,
    block,
)
from asset_pipeline.procedural.parts import Part, RecipeMaterial
from asset_pipeline.procedural.round_parts import Cylinder

OBJECT = ("object",)
ROUND = (1.0, 1.0)

# --- palette of this module ----------------------------------------------------------------
RED_PLASTIC = RecipeMaterial("red_plastic", (0.75, 0.12, 0.12, 1.0), 0.4, 0.4, "red")
BLUE_PLASTIC = RecipeMaterial("blue_plastic", (0.16, 0.32, 0.62, 1.0), 0.4, 0.4, "blue")
GREY_PLASTIC = RecipeMaterial("grey_plastic", (0.55, 0.56, 0.58, 1.0), 0.3, 0.3, "grey")
CREAM_ENAMEL = RecipeMaterial("cream_enamel", (0.93, 0.89, 0.78, 1.0), 0.6, 0.6, "cream")
MINT_ENAMEL = RecipeMaterial("mint_enamel", (0.62, 0.82, 0.74, 1.0), 0.6, 0.6, "mint green")
RED_ENAMEL = RecipeMaterial("red_enamel", (0.70, 0.10, 0.10, 1.0), 0.6, 0.6, "red")
BLUE_METAL = RecipeMaterial("blue_metal", (0.14, 0.28, 0.55, 1.0), 0.5, 0.5, "blue metal")
GREEN_METAL = RecipeMaterial("green_metal", (0.22, 0.40, 0.26, 1.0), 0.5, 0.5, "green metal")
CAST_IRON = RecipeMaterial("cast_iron", (0.14, 0.14, 0.15, 1.0), 0.3, 0.3, "cast iron")
RUBBER = RecipeMaterial("rubber", (0.09, 0.09, 0.10, 1.0), 0.1, 0.1, "black rubber")
PLUSH_NOSE = RecipeMaterial("plush_nose", (0.12, 0.08, 0.06, 1.0), 0.4, 0.4)
DIAL = RecipeMaterial("dial", (0.97, 0.97, 0.94, 1.0), 0.5, 0.5)
LED = RecipeMaterial("led", (0.20, 0.85, 0.40, 1.0), 0.9, 0.9)
GOLD = RecipeMaterial("gold", (0.85, 0.68, 0.22, 1.0), 0.9, 0.9)
SILVER = RecipeMaterial("silver", (0.80, 0.80, 0.82, 1.0), 0.9, 0.9)
NYLON_RED = RecipeMaterial("nylon_red", (0.62, 0.14, 0.14, 1.0), 0.2, 0.2, "red")

APPLIANCE = (WHITE_PLASTIC, BLACK_PLASTIC, STEEL, CREAM_ENAMEL, RED_ENAMEL)
ELECTRONICS = (BLACK_PLASTIC, SPACE_GREY, ALUMINIUM, WHITE_PLASTIC)


# --- shorthands ----------------------------------------------------------------------------
def cyl_z(
    x: float, y: float, z0: float, z1: float, r: float, m: RecipeMaterial, collide: bool = True
) -> Cylinder:
    """An upright cylinder of radius ``r`` spanning heights z0..z1 at (x, y)."""
    return Cylinder((x, y, 0.5 * (z0 + z1)), r, 0.5 * (z1 - z0), m, collide=collide)


def cyl_x(
    x0: float, x1: float, y: float, z: float, r: float, m: RecipeMaterial, collide: bool = True
) -> Cylinder:
    """A cylinder along X spanning x0..x1, its axis at (y, z)."""
    return Cylinder((0.5 * (x0 + x1), y, z), r, 0.5 * (x1 - x0), m, axis="x", collide=collide)


def cyl_y(
    y0: float, y1: float, x: float, z: float, r: float, m: RecipeMaterial, collide: bool = True
) -> Cylinder:
    """A cylinder along Y spanning y0..y1, its axis at (x, z)."""
    return Cylinder((x, 0.5 * (y0 + y1), z), r, 0.5 * (y1 - y0), m, axis="y", collide=collide)


def deco(x: tuple[float, float], y: tuple[float, float], z: tuple[float, float], m: RecipeMaterial):
    """A visual-only box (labels, keys, screens)."""
    return block(x, y, z, m, collide=False)


def handle_arch(
    y: tuple[float, float], z: tuple[float, float], t: float, m: RecipeMaterial, x: float = 0.0
) -> list[Part]:
    """A carrying handle in the YZ plane: two posts and a top bar, ``t`` thick, at ``x``."""
    (y0, y1), (z0, z1) = y, z
    xs = (x - 0.5 * t, x + 0.5 * t)
    return [
        block(xs, (y0, y0 + t), (z0, z1 - t), m),
        block(xs, (y1 - t, y1), (z0, z1 - t), m),
        block(xs, (y0, y1), (z1 - t, z1), m),
    ]
