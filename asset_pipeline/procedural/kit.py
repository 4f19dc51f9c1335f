"""The designer's kit: the material palette and shorthand constructors for common parts."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TypeVar

import numpy as np

from asset_pipeline.procedural.parts import Box, RecipeMaterial, Rect
from asset_pipeline.procedural.round_parts import Cylinder

# --- palette -------------------------------------------------------------------------------
OAK = RecipeMaterial("oak", (0.66, 0.49, 0.31, 1.0), 0.2, 0.3)
WALNUT = RecipeMaterial("walnut", (0.40, 0.27, 0.17, 1.0), 0.2, 0.3)
PINE = RecipeMaterial("pine", (0.82, 0.68, 0.48, 1.0), 0.15, 0.2)
ASH = RecipeMaterial("ash", (0.86, 0.78, 0.64, 1.0), 0.15, 0.2, "pale ash")
WHITE_LACQUER = RecipeMaterial("white_lacquer", (0.92, 0.91, 0.88, 1.0), 0.4, 0.5, "white")
GREY_LAMINATE = RecipeMaterial("grey_laminate", (0.55, 0.56, 0.57, 1.0), 0.3, 0.3, "grey laminate")
SAGE_LACQUER = RecipeMaterial("sage_lacquer", (0.56, 0.64, 0.55, 1.0), 0.4, 0.5, "sage green")
NAVY_LACQUER = RecipeMaterial("navy_lacquer", (0.16, 0.21, 0.32, 1.0), 0.4, 0.5, "navy blue")
BLACK_METAL = RecipeMaterial("black_metal", (0.08, 0.08, 0.09, 1.0), 0.6, 0.6, "black metal")
STEEL = RecipeMaterial("steel", (0.72, 0.74, 0.76, 1.0), 0.8, 0.8, "stainless steel")
CHROME = RecipeMaterial("chrome", (0.85, 0.86, 0.88, 1.0), 0.9, 0.9)
BRASS = RecipeMaterial("brass", (0.78, 0.62, 0.30, 1.0), 0.8, 0.8)
GREY_FABRIC = RecipeMaterial("grey_fabric", (0.45, 0.46, 0.48, 1.0), 0.05, 0.1, "grey")
BLUE_FABRIC = RecipeMaterial("blue_fabric", (0.20, 0.30, 0.48, 1.0), 0.05, 0.1, "blue")
GREEN_FABRIC = RecipeMaterial("green_fabric", (0.30, 0.42, 0.30, 1.0), 0.05, 0.1, "green")
BEIGE_FABRIC = RecipeMaterial("beige_fabric", (0.80, 0.74, 0.64, 1.0), 0.05, 0.1, "beige")
MUSTARD_FABRIC = RecipeMaterial("mustard_fabric", (0.78, 0.58, 0.18, 1.0), 0.05, 0.1, "mustard")
CHARCOAL_FABRIC = RecipeMaterial("charcoal_fabric", (0.20, 0.20, 0.22, 1.0), 0.05, 0.1, "charcoal")
RUST_FABRIC = RecipeMaterial("rust_fabric", (0.62, 0.30, 0.18, 1.0), 0.05, 0.1, "rust red")
LINEN = RecipeMaterial("linen", (0.95, 0.94, 0.91, 1.0), 0.05, 0.1)
LEATHER = RecipeMaterial("leather", (0.36, 0.22, 0.14, 1.0), 0.3, 0.4, "brown leather")
BLACK_LEATHER = RecipeMaterial("black_leather", (0.07, 0.07, 0.08, 1.0), 0.4, 0.5, "black leather")
PORCELAIN = RecipeMaterial("porcelain", (0.97, 0.97, 0.96, 1.0), 0.7, 0.8, "white porcelain")
CERAMIC_BLUE = RecipeMaterial("ceramic_blue", (0.24, 0.42, 0.62, 1.0), 0.6, 0.7, "blue ceramic")
CERAMIC_GREEN = RecipeMaterial("ceramic_green", (0.38, 0.55, 0.44, 1.0), 0.6, 0.7, "green ceramic")
CERAMIC_YELLOW = RecipeMaterial(
    "ceramic_yellow", (0.92, 0.78, 0.32, 1.0), 0.6, 0.7, "yellow ceramic"
)
CERAMIC_BLACK = RecipeMaterial("ceramic_black", (0.12, 0.12, 0.13, 1.0), 0.6, 0.7, "black ceramic")
TERRACOTTA = RecipeMaterial("terracotta", (0.72, 0.38, 0.24, 1.0), 0.1, 0.2)
CONCRETE = RecipeMaterial("concrete", (0.62, 0.62, 0.60, 1.0), 0.1, 0.1, "grey concrete")
FOLIAGE = RecipeMaterial("foliage", (0.22, 0.48, 0.20, 1.0), 0.1, 0.2, "green")
DARK_FOLIAGE = RecipeMaterial("dark_foliage", (0.12, 0.32, 0.14, 1.0), 0.1, 0.2, "dark green")
BARK = RecipeMaterial("bark", (0.35, 0.25, 0.16, 1.0), 0.05, 0.1)
SCREEN = RecipeMaterial("screen", (0.03, 0.04, 0.06, 1.0), 0.9, 0.9)
WHITEBOARD = RecipeMaterial("whiteboard", (0.98, 0.98, 0.98, 1.0), 0.7, 0.8)
ALUMINIUM = RecipeMaterial("aluminium", (0.78, 0.79, 0.80, 1.0), 0.6, 0.6, "silver")
SPACE_GREY = RecipeMaterial("space_grey", (0.32, 0.33, 0.35, 1.0), 0.6, 0.6, "space grey")
BLACK_PLASTIC = RecipeMaterial("black_plastic", (0.06, 0.06, 0.07, 1.0), 0.3, 0.3, "black")
WHITE_PLASTIC = RecipeMaterial("white_plastic", (0.90, 0.90, 0.90, 1.0), 0.3, 0.3, "white")
CANVAS = RecipeMaterial("canvas", (0.55, 0.62, 0.70, 1.0), 0.05, 0.1)
CANVAS_WARM = RecipeMaterial("canvas_warm", (0.80, 0.55, 0.38, 1.0), 0.05, 0.1, "canvas")
GILT = RecipeMaterial("gilt", (0.76, 0.60, 0.28, 1.0), 0.7, 0.7)
PAPER = RecipeMaterial("paper", (0.96, 0.95, 0.90, 1.0), 0.05, 0.1)
RED_COVER = RecipeMaterial("red_cover", (0.62, 0.12, 0.12, 1.0), 0.2, 0.2, "red")
BLUE_COVER = RecipeMaterial("blue_cover", (0.14, 0.24, 0.50, 1.0), 0.2, 0.2, "blue")
GREEN_COVER = RecipeMaterial("green_cover", (0.16, 0.40, 0.25, 1.0), 0.2, 0.2, "green")
BLACK_COVER = RecipeMaterial("black_cover", (0.10, 0.10, 0.11, 1.0), 0.2, 0.2, "black")
CARDBOARD = RecipeMaterial("cardboard", (0.70, 0.55, 0.38, 1.0), 0.05, 0.1, "brown cardboard")
TAPE = RecipeMaterial("tape", (0.80, 0.72, 0.55, 1.0), 0.4, 0.4)
GREEN_GLASS = RecipeMaterial("green_glass", (0.16, 0.38, 0.20, 1.0), 0.9, 0.9, "green glass")
AMBER_GLASS = RecipeMaterial("amber_glass", (0.55, 0.30, 0.08, 1.0), 0.9, 0.9, "amber glass")
CLEAR_GLASS = RecipeMaterial("clear_glass", (0.80, 0.88, 0.90, 0.6), 0.9, 0.9, "clear glass")
APPLE_RED = RecipeMaterial("apple_red", (0.72, 0.10, 0.10, 1.0), 0.5, 0.6, "red")
APPLE_GREEN = RecipeMaterial("apple_green", (0.55, 0.75, 0.25, 1.0), 0.5, 0.6, "green")
ORANGE_PEEL = RecipeMaterial("orange_peel", (0.95, 0.55, 0.10, 1.0), 0.3, 0.4, "orange")
STEM = RecipeMaterial("stem", (0.30, 0.22, 0.10, 1.0), 0.1, 0.1)
IVORY = RecipeMaterial("ivory", (0.96, 0.94, 0.88, 1.0), 0.5, 0.6)
PIANO_BLACK = RecipeMaterial("piano_black", (0.03, 0.03, 0.03, 1.0), 0.9, 0.9, "black")
LAMP_SHADE = RecipeMaterial("lamp_shade", (0.93, 0.89, 0.78, 1.0), 0.05, 0.1, "cream")
WHITE_SHADE = RecipeMaterial("white_shade", (0.97, 0.97, 0.95, 1.0), 0.05, 0.1, "white")
TOY_RED = RecipeMaterial("toy_red", (0.85, 0.20, 0.15, 1.0), 0.3, 0.4, "red")
TOY_BLUE = RecipeMaterial("toy_blue", (0.15, 0.40, 0.85, 1.0), 0.3, 0.4, "blue")
TOY_YELLOW = RecipeMaterial("toy_yellow", (0.95, 0.80, 0.15, 1.0), 0.3, 0.4, "yellow")
TOY_GREEN = RecipeMaterial("toy_green", (0.20, 0.70, 0.30, 1.0), 0.3, 0.4, "green")
SOIL = RecipeMaterial("soil", (0.24, 0.17, 0.11, 1.0), 0.0, 0.0)
WAX = RecipeMaterial("wax", (0.97, 0.95, 0.88, 1.0), 0.2, 0.3, "ivory wax")
RED_WAX = RecipeMaterial("red_wax", (0.70, 0.12, 0.14, 1.0), 0.2, 0.3, "red wax")
WICK = RecipeMaterial("wick", (0.10, 0.09, 0.08, 1.0), 0.0, 0.0)
RUG_RED = RecipeMaterial("rug_red", (0.58, 0.16, 0.14, 1.0), 0.0, 0.05, "deep red")
RUG_BLUE = RecipeMaterial("rug_blue", (0.22, 0.30, 0.48, 1.0), 0.0, 0.05, "indigo")
RUG_BEIGE = RecipeMaterial("rug_beige", (0.82, 0.76, 0.64, 1.0), 0.0, 0.05, "beige")
RUG_GREY = RecipeMaterial("rug_grey", (0.50, 0.50, 0.50, 1.0), 0.0, 0.05, "grey")
RUG_BORDER = RecipeMaterial("rug_border", (0.92, 0.88, 0.78, 1.0), 0.0, 0.05, "cream")
RUG_DARK_BORDER = RecipeMaterial("rug_dark_border", (0.18, 0.14, 0.12, 1.0), 0.0, 0.05, "dark")

WOODS = (OAK, WALNUT, PINE, ASH)
PAINTED = (WHITE_LACQUER, SAGE_LACQUER, NAVY_LACQUER, GREY_LAMINATE)
CASE_FINISHES = (*WOODS, WHITE_LACQUER, SAGE_LACQUER, NAVY_LACQUER)
FABRICS = (
    GREY_FABRIC,
    BLUE_FABRIC,
    GREEN_FABRIC,
    BEIGE_FABRIC,
    MUSTARD_FABRIC,
    CHARCOAL_FABRIC,
    RUST_FABRIC,
)
METALS = (BLACK_METAL, CHROME, BRASS, STEEL)
CERAMICS = (PORCELAIN, CERAMIC_BLUE, CERAMIC_GREEN, CERAMIC_YELLOW, CERAMIC_BLACK, TERRACOTTA)
COVERS = (RED_COVER, BLUE_COVER, GREEN_COVER, BLACK_COVER)
TOYS = (TOY_RED, TOY_BLUE, TOY_YELLOW, TOY_GREEN)


# --- randomness ----------------------------------------------------------------------------
T = TypeVar("T")
Rng = np.random.Generator
Span = Sequence[float]
"""A (low, high) pair of coordinates along one axis (a tuple, or a list a builder edits)."""


COUNT_WORDS = {
    1: "one",
    2: "two",
    3: "three",
    4: "four",
    5: "five",
    6: "six",
    7: "seven",
    8: "eight",
}


def count_word(count: int) -> str:
    """``count`` in words (one to eight), else in digits."""
    return COUNT_WORDS.get(count, str(count))


def pick(rng: np.random.Generator, options: Sequence[T]) -> T:
    """One of ``options``, uniformly."""
    return options[int(rng.integers(len(options)))]


def uniform(rng: np.random.Generator, low: float, high: float) -> float:
    """A float drawn uniformly from [low, high] (``low`` if the interval is empty)."""
    if high <= low:
        return float(low)
    return float(rng.uniform(low, high))


def chance(rng: np.random.Generator, p: float) -> bool:
    """True with probability ``p``."""
    return bool(rng.random() < p)


def clamp(value: float, low: float, high: float) -> float:
    """``value`` limited to [low, high] (``low`` wins if they cross)."""
    return max(low, min(high, value))


def block(
    x: Span,
    y: Span,
    z: Span,
    material: RecipeMaterial,
    *,
    surface: bool | Rect = False,
    collide: bool = True,
) -> Box:
    """A box spanning ``x``, ``y`` and ``z`` (each a (low, high) pair)."""
    if x[1] <= x[0] or y[1] <= y[0] or z[1] <= z[0]:
        raise ValueError(f"empty block {x} {y} {z}")
    return Box(
        center=(0.5 * (x[0] + x[1]), 0.5 * (y[0] + y[1]), 0.5 * (z[0] + z[1])),
        half=(0.5 * (x[1] - x[0]), 0.5 * (y[1] - y[0]), 0.5 * (z[1] - z[0])),
        material=material,
        surface=surface,
        collide=collide,
    )


def square_legs(
    depth: float,
    width: float,
    height: float,
    side: float,
    material: RecipeMaterial,
    inset: float = 0.0,
) -> list[Box]:
    """Four square legs of ``side`` under a ``depth`` x ``width`` footprint centred on 0."""
    xs = (-0.5 * depth + inset, 0.5 * depth - inset - side)
    ys = (-0.5 * width + inset, 0.5 * width - inset - side)
    return [block((x, x + side), (y, y + side), (0.0, height), material) for x in xs for y in ys]


def round_legs(
    depth: float, width: float, height: float, radius: float, material: RecipeMaterial, inset: float
) -> list[Cylinder]:
    """Four upright round legs whose centres sit ``inset`` inside the footprint's corners."""
    xs = (-0.5 * depth + inset, 0.5 * depth - inset)
    ys = (-0.5 * width + inset, 0.5 * width - inset)
    return [Cylinder((x, y, 0.5 * height), radius, 0.5 * height, material) for x in xs for y in ys]


FRONT_T = 0.018  # thickness of drawer and door fronts
HANDLE_D = 0.018  # how far handles stand proud of the fronts


def drawer_fronts(
    x_face: float,
    y: tuple[float, float],
    z: tuple[float, float],
    rows: int,
    columns: int,
    front: RecipeMaterial,
    handle: RecipeMaterial,
    gap: float = 0.006,
    style: str = "bar",
) -> list[Box]:
    """A grid of drawer (or door) fronts on the +X face at ``x_face``, each with a handle.

    The fronts span ``x_face`` to ``x_face + FRONT_T`` and the handles a further
    :data:`HANDLE_D`. ``style``: ``bar`` (horizontal, centred), ``knob`` (small square),
    ``door`` (vertical bar at the inner edge of each door: doors open from the middle).
    """
    parts: list[Box] = []
    cell_w = (y[1] - y[0]) / columns
    cell_h = (z[1] - z[0]) / rows
    x_front = x_face + FRONT_T
    for i in range(rows):
        for j in range(columns):
            y0, z0 = y[0] + j * cell_w, z[0] + i * cell_h
            parts.append(
                block(
                    (x_face, x_front),
                    (y0 + gap, y0 + cell_w - gap),
                    (z0 + gap, z0 + cell_h - gap),
                    front,
                )
            )
            yc, zc = y0 + 0.5 * cell_w, z0 + 0.5 * cell_h
            if style == "knob":
                hy, hz = 0.012, 0.012
            elif style == "door":
                right = columns == 1 or j < columns / 2
                yc = y0 + cell_w - 0.05 if right else y0 + 0.05
                hy, hz = 0.008, min(0.1, 0.3 * cell_h)
            else:
                hy, hz = 0.5 * min(0.12, 0.4 * cell_w), 0.008
            parts.append(
                block((x_front, x_front + HANDLE_D), (yc - hy, yc + hy), (zc - hz, zc + hz), handle)
            )
    return parts
