"""Designs of appliances, instruments, wall decor, lamps and floor plants (front +X)."""

from __future__ import annotations

from asset_pipeline.procedural.assembly import AssetDesign
from asset_pipeline.procedural.kit import (
    ALUMINIUM,
    BARK,
    BLACK_METAL,
    CANVAS,
    CHROME,
    FOLIAGE,
    GILT,
    IVORY,
    LAMP_SHADE,
    PIANO_BLACK,
    SCREEN,
    SOIL,
    TERRACOTTA,
    WHITE_LACQUER,
    WHITEBOARD,
    block,
)
from asset_pipeline.procedural.parts import Part
from asset_pipeline.procedural.round_parts import Cylinder, Lathe, Sphere

FLOOR = ("floor",)
WALL = ("wall",)


def fridge() -> AssetDesign:
    """A fridge-freezer: freezer door below, fridge door above, handles on the +X doors."""
    parts: list[Part] = [
        block((-0.35, 0.31), (-0.35, 0.35), (0.0, 1.8), WHITE_LACQUER, surface=True),
        block((0.31, 0.33), (-0.345, 0.345), (0.02, 0.62), WHITE_LACQUER),
        block((0.31, 0.33), (-0.345, 0.345), (0.63, 1.78), WHITE_LACQUER),
        block((0.33, 0.35), (0.27, 0.29), (0.4, 0.56), CHROME),
        block((0.33, 0.35), (0.27, 0.29), (0.85, 1.3), CHROME),
    ]
    return AssetDesign(
        "fridge_01",
        "fridge",
        "a tall white fridge-freezer with chrome handles",
        70.0,
        0.5,
        FLOOR,
        tuple(parts),
    )


def television() -> AssetDesign:
    """A flat-screen television on a foot; the screen faces +X. Stands on furniture."""
    parts: list[Part] = [
        block((-0.12, 0.12), (-0.25, 0.25), (0.0, 0.02), BLACK_METAL),
        block((-0.045, -0.01), (-0.04, 0.04), (0.02, 0.12), BLACK_METAL),
        block((-0.03, 0.02), (-0.625, 0.625), (0.08, 0.8), BLACK_METAL),
        block((0.02, 0.022), (-0.605, 0.605), (0.1, 0.78), SCREEN, collide=False),
    ]
    return AssetDesign(
        "television_01",
        "television",
        "a 55-inch black flat-screen television on a stand",
        14.0,
        0.6,
        ("object",),
        tuple(parts),
    )


def piano() -> AssetDesign:
    """An upright piano with its keyboard at +X."""
    parts: list[Part] = [
        block((-0.3, 0.0), (-0.75, 0.75), (0.0, 1.25), PIANO_BLACK, surface=True),
        block((0.0, 0.25), (-0.75, 0.75), (0.64, 0.72), PIANO_BLACK),
        block((0.0, 0.25), (-0.75, -0.69), (0.72, 0.8), PIANO_BLACK),
        block((0.0, 0.25), (0.69, 0.75), (0.72, 0.8), PIANO_BLACK),
        block((0.0, 0.09), (-0.69, 0.69), (0.72, 0.82), PIANO_BLACK),
        block((0.09, 0.25), (-0.69, 0.69), (0.72, 0.74), IVORY),
        block((0.09, 0.16), (-0.67, 0.67), (0.74, 0.75), PIANO_BLACK),
        block((0.19, 0.25), (-0.75, -0.69), (0.0, 0.64), PIANO_BLACK),
        block((0.19, 0.25), (0.69, 0.75), (0.0, 0.64), PIANO_BLACK),
    ]
    return AssetDesign(
        "piano_01",
        "piano",
        "a black upright piano with ivory keys",
        220.0,
        0.6,
        FLOOR,
        tuple(parts),
    )


def whiteboard() -> AssetDesign:
    """A wall-mounted whiteboard with an aluminium frame and a marker tray."""
    parts: list[Part] = [
        block((-0.025, -0.005), (-0.6, 0.6), (0.0, 0.9), ALUMINIUM),
        block((-0.005, 0.0), (-0.58, 0.58), (0.02, 0.88), WHITEBOARD),
        block((-0.005, 0.01), (-0.6, 0.6), (0.0, 0.02), ALUMINIUM),
        block((-0.005, 0.01), (-0.6, 0.6), (0.88, 0.9), ALUMINIUM),
        block((-0.005, 0.01), (-0.6, -0.58), (0.02, 0.88), ALUMINIUM),
        block((-0.005, 0.01), (0.58, 0.6), (0.02, 0.88), ALUMINIUM),
        block((0.01, 0.06), (-0.3, 0.3), (0.02, 0.035), ALUMINIUM),
    ]
    return AssetDesign(
        "whiteboard_01",
        "whiteboard",
        "a wall-mounted whiteboard with an aluminium frame and a marker tray",
        8.0,
        0.5,
        WALL,
        tuple(parts),
    )


def painting() -> AssetDesign:
    """A framed painting for a wall; the canvas faces +X."""
    parts: list[Part] = [
        block((-0.03, -0.01), (-0.36, 0.36), (0.04, 0.56), CANVAS),
        block((-0.03, 0.0), (-0.4, 0.4), (0.0, 0.04), GILT),
        block((-0.03, 0.0), (-0.4, 0.4), (0.56, 0.6), GILT),
        block((-0.03, 0.0), (-0.4, -0.36), (0.04, 0.56), GILT),
        block((-0.03, 0.0), (0.36, 0.4), (0.04, 0.56), GILT),
    ]
    return AssetDesign(
        "painting_01",
        "painting",
        "a framed landscape painting with a gilt frame",
        3.0,
        0.6,
        WALL,
        tuple(parts),
    )


def floor_lamp() -> AssetDesign:
    """A floor lamp: heavy round base, thin pole, conical fabric shade."""
    parts: list[Part] = [
        Cylinder((0.0, 0.0, 0.02), 0.16, 0.02, BLACK_METAL),
        Cylinder((0.0, 0.0, 0.81), 0.012, 0.77, BLACK_METAL),
        Lathe((0.0, 0.0, 1.35), ((0.2, 0.0), (0.13, 0.3)), LAMP_SHADE),
    ]
    return AssetDesign(
        "floor_lamp_01",
        "floor_lamp",
        "a black floor lamp with a cream conical shade",
        6.0,
        0.7,
        FLOOR,
        tuple(parts),
    )


def potted_plant() -> AssetDesign:
    """A floor plant: terracotta pot, trunk and a round crown of leaves."""
    parts: list[Part] = [
        Lathe((0.0, 0.0, 0.0), ((0.14, 0.0), (0.18, 0.38)), TERRACOTTA, hollow=(0.015, 0.04)),
        Cylinder((0.0, 0.0, 0.345), 0.155, 0.015, SOIL, collide=False),
        Cylinder((0.0, 0.0, 0.55), 0.02, 0.2, BARK),
        Sphere((0.0, 0.0, 0.95), 0.3, FOLIAGE),
    ]
    for x, y in ((0.2, 0.0), (-0.2, 0.0), (0.0, 0.2), (0.0, -0.2)):
        parts.append(Sphere((x, y, 0.8), 0.14, FOLIAGE))
    return AssetDesign(
        "potted_plant_01",
        "potted_plant",
        "a leafy indoor tree in a terracotta pot",
        12.0,
        0.8,
        FLOOR,
        tuple(parts),
    )


def designs() -> list[AssetDesign]:
    """All designs of this module."""
    return [fridge(), television(), piano(), whiteboard(), painting(), floor_lamp(), potted_plant()]
