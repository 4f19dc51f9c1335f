"""Shared materials and part builders of the home generators (``home_*.py``).

Sizes are bounding boxes (x = depth, y = width, z = height). Wall pieces (placement ``wall``)
have their back at -X; ceiling pieces (placement ``ceiling``) are hung by the layout so that
the top of the box touches the ceiling, so their cord, rod or canopy reaches the top. Like
every asset they have their lowest point at z = 0 and stand upright on a floor on a flat
bottom (the generic physics test drops every asset on a plane).
"""

from __future__ import annotations

from asset_pipeline.procedural.kit import (
    BLACK_METAL,
    BRASS,
    CHARCOAL_FABRIC,
    CHROME,
    FRONT_T,
    HANDLE_D,
    LAMP_SHADE,
    LINEN,
    MUSTARD_FABRIC,
    WHITE_SHADE,
)
from asset_pipeline.procedural.parts import Part, RecipeMaterial
from asset_pipeline.procedural.round_parts import Cylinder

ROUND = (1.0, 1.0)
PROUD = FRONT_T + HANDLE_D  # fronts and handles stand this far in front of a carcass
HANDLES = (BLACK_METAL, CHROME, BRASS)

BRICK = RecipeMaterial("brick", (0.60, 0.28, 0.20, 1.0), 0.1, 0.1, "red brick")
MARBLE = RecipeMaterial("marble", (0.90, 0.89, 0.86, 1.0), 0.6, 0.7, "white marble")
SOOT = RecipeMaterial("soot", (0.05, 0.04, 0.04, 1.0), 0.0, 0.0, "sooty black")
WICKER = RecipeMaterial("wicker", (0.72, 0.58, 0.38, 1.0), 0.1, 0.1, "woven wicker")
RICE_PAPER = RecipeMaterial("rice_paper", (0.96, 0.94, 0.88, 1.0), 0.05, 0.1, "white rice paper")
OPAL_GLASS = RecipeMaterial("opal_glass", (0.96, 0.96, 0.94, 0.9), 0.6, 0.7, "opal glass")
CLOCK_FACE = RecipeMaterial("clock_face", (0.97, 0.96, 0.92, 1.0), 0.3, 0.3, "white")
DARK_GREY = RecipeMaterial("dark_grey", (0.25, 0.26, 0.28, 1.0), 0.4, 0.4, "graphite")
SAGE_TOY = RecipeMaterial("sage_toy", (0.62, 0.72, 0.60, 1.0), 0.3, 0.4, "sage")
IVORY_FACE = RecipeMaterial("ivory_face", (0.95, 0.92, 0.82, 1.0), 0.3, 0.3, "ivory")
DRUM_GLASS = RecipeMaterial("drum_glass", (0.20, 0.24, 0.27, 0.8), 0.9, 0.9, "tinted glass")
FABRIC_SHADES = (LAMP_SHADE, WHITE_SHADE, LINEN, MUSTARD_FABRIC, CHARCOAL_FABRIC)


def upright_rod(
    z0: float, z1: float, radius: float, material: RecipeMaterial, collide: bool = True
) -> Part:
    """An upright cord, chain or downrod from ``z0`` to ``z1`` on the Z axis."""
    return Cylinder((0.0, 0.0, 0.5 * (z0 + z1)), radius, 0.5 * (z1 - z0), material, collide=collide)
