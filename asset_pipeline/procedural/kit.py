"""The designer's kit: the material palette and shorthand constructors for common parts."""

from __future__ import annotations

from asset_pipeline.procedural.parts import Box, Material, Rect
from asset_pipeline.procedural.round_parts import Cylinder

# --- palette -------------------------------------------------------------------------------
OAK = Material("oak", (0.66, 0.49, 0.31, 1.0), 0.2, 0.3)
WALNUT = Material("walnut", (0.40, 0.27, 0.17, 1.0), 0.2, 0.3)
PINE = Material("pine", (0.82, 0.68, 0.48, 1.0), 0.15, 0.2)
WHITE_LACQUER = Material("white_lacquer", (0.92, 0.91, 0.88, 1.0), 0.4, 0.5)
GREY_LAMINATE = Material("grey_laminate", (0.55, 0.56, 0.57, 1.0), 0.3, 0.3)
BLACK_METAL = Material("black_metal", (0.08, 0.08, 0.09, 1.0), 0.6, 0.6)
STEEL = Material("steel", (0.72, 0.74, 0.76, 1.0), 0.8, 0.8)
CHROME = Material("chrome", (0.85, 0.86, 0.88, 1.0), 0.9, 0.9)
GREY_FABRIC = Material("grey_fabric", (0.45, 0.46, 0.48, 1.0), 0.05, 0.1)
BLUE_FABRIC = Material("blue_fabric", (0.20, 0.30, 0.48, 1.0), 0.05, 0.1)
GREEN_FABRIC = Material("green_fabric", (0.30, 0.42, 0.30, 1.0), 0.05, 0.1)
BEIGE_FABRIC = Material("beige_fabric", (0.80, 0.74, 0.64, 1.0), 0.05, 0.1)
LINEN = Material("linen", (0.95, 0.94, 0.91, 1.0), 0.05, 0.1)
LEATHER = Material("leather", (0.36, 0.22, 0.14, 1.0), 0.3, 0.4)
PORCELAIN = Material("porcelain", (0.97, 0.97, 0.96, 1.0), 0.7, 0.8)
CERAMIC_BLUE = Material("ceramic_blue", (0.24, 0.42, 0.62, 1.0), 0.6, 0.7)
TERRACOTTA = Material("terracotta", (0.72, 0.38, 0.24, 1.0), 0.1, 0.2)
FOLIAGE = Material("foliage", (0.22, 0.48, 0.20, 1.0), 0.1, 0.2)
BARK = Material("bark", (0.35, 0.25, 0.16, 1.0), 0.05, 0.1)
SCREEN = Material("screen", (0.03, 0.04, 0.06, 1.0), 0.9, 0.9)
WHITEBOARD = Material("whiteboard", (0.98, 0.98, 0.98, 1.0), 0.7, 0.8)
ALUMINIUM = Material("aluminium", (0.78, 0.79, 0.80, 1.0), 0.6, 0.6)
CANVAS = Material("canvas", (0.55, 0.62, 0.70, 1.0), 0.05, 0.1)
GILT = Material("gilt", (0.76, 0.60, 0.28, 1.0), 0.7, 0.7)
PAPER = Material("paper", (0.96, 0.95, 0.90, 1.0), 0.05, 0.1)
RED_COVER = Material("red_cover", (0.62, 0.12, 0.12, 1.0), 0.2, 0.2)
CARDBOARD = Material("cardboard", (0.70, 0.55, 0.38, 1.0), 0.05, 0.1)
TAPE = Material("tape", (0.80, 0.72, 0.55, 1.0), 0.4, 0.4)
GREEN_GLASS = Material("green_glass", (0.16, 0.38, 0.20, 1.0), 0.9, 0.9)
APPLE_RED = Material("apple_red", (0.72, 0.10, 0.10, 1.0), 0.5, 0.6)
STEM = Material("stem", (0.30, 0.22, 0.10, 1.0), 0.1, 0.1)
IVORY = Material("ivory", (0.96, 0.94, 0.88, 1.0), 0.5, 0.6)
PIANO_BLACK = Material("piano_black", (0.03, 0.03, 0.03, 1.0), 0.9, 0.9)
LAMP_SHADE = Material("lamp_shade", (0.93, 0.89, 0.78, 1.0), 0.05, 0.1)
TOY_RED = Material("toy_red", (0.85, 0.20, 0.15, 1.0), 0.3, 0.4)
SOIL = Material("soil", (0.24, 0.17, 0.11, 1.0), 0.0, 0.0)


def block(
    x: tuple[float, float],
    y: tuple[float, float],
    z: tuple[float, float],
    material: Material,
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
    depth: float, width: float, height: float, side: float, material: Material, inset: float = 0.0
) -> list[Box]:
    """Four square legs of ``side`` under a ``depth`` x ``width`` footprint centred on 0."""
    xs = (-0.5 * depth + inset, 0.5 * depth - inset - side)
    ys = (-0.5 * width + inset, 0.5 * width - inset - side)
    return [block((x, x + side), (y, y + side), (0.0, height), material) for x in xs for y in ys]


def round_legs(
    depth: float, width: float, height: float, radius: float, material: Material, inset: float
) -> list[Cylinder]:
    """Four upright round legs whose centres sit ``inset`` inside the footprint's corners."""
    xs = (-0.5 * depth + inset, 0.5 * depth - inset)
    ys = (-0.5 * width + inset, 0.5 * width - inset)
    return [Cylinder((x, y, 0.5 * height), radius, 0.5 * height, material) for x in xs for y in ys]


def drawer_fronts(
    x_face: float,
    y: tuple[float, float],
    z: tuple[float, float],
    rows: int,
    columns: int,
    front: Material,
    handle: Material,
    gap: float = 0.006,
) -> list[Box]:
    """A grid of drawer (or door) fronts on the +X face at ``x_face``, each with a handle."""
    parts: list[Box] = []
    cell_w = (y[1] - y[0]) / columns
    cell_h = (z[1] - z[0]) / rows
    for i in range(rows):
        for j in range(columns):
            y0, z0 = y[0] + j * cell_w, z[0] + i * cell_h
            parts.append(
                block(
                    (x_face, x_face + 0.018),
                    (y0 + gap, y0 + cell_w - gap),
                    (z0 + gap, z0 + cell_h - gap),
                    front,
                )
            )
            yc, zc = y0 + 0.5 * cell_w, z0 + 0.5 * cell_h
            handle_w = min(0.12, 0.4 * cell_w)
            parts.append(
                block(
                    (x_face + 0.018, x_face + 0.036),
                    (yc - 0.5 * handle_w, yc + 0.5 * handle_w),
                    (zc - 0.008, zc + 0.008),
                    handle,
                )
            )
    return parts
