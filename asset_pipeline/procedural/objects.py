"""Designs of small objects that rest on furniture (placement ``object``)."""

from __future__ import annotations

from asset_pipeline.procedural.assembly import AssetDesign
from asset_pipeline.procedural.kit import (
    ALUMINIUM,
    APPLE_RED,
    BLACK_METAL,
    CARDBOARD,
    CERAMIC_BLUE,
    FOLIAGE,
    GREEN_GLASS,
    LAMP_SHADE,
    PAPER,
    PORCELAIN,
    RED_COVER,
    SCREEN,
    SOIL,
    STEM,
    TAPE,
    TERRACOTTA,
    TOY_RED,
    block,
)
from asset_pipeline.procedural.parts import Part
from asset_pipeline.procedural.round_parts import Cylinder, Lathe, Sphere

OBJECT = ("object",)


def mug() -> AssetDesign:
    """A porcelain mug with a handle on its +Y side."""
    parts: list[Part] = [
        Lathe((0.0, 0.0, 0.0), ((0.04, 0.0), (0.041, 0.095)), PORCELAIN, hollow=(0.005, 0.008)),
        block((-0.006, 0.006), (0.038, 0.066), (0.07, 0.08), PORCELAIN),
        block((-0.006, 0.006), (0.038, 0.066), (0.02, 0.03), PORCELAIN),
        block((-0.006, 0.006), (0.056, 0.066), (0.03, 0.07), PORCELAIN),
    ]
    return AssetDesign(
        "mug_01", "mug", "a white porcelain coffee mug", 0.3, 0.6, OBJECT, tuple(parts)
    )


def book() -> AssetDesign:
    """A hardback book lying flat, spine at -Y."""
    parts: list[Part] = [
        block((-0.115, 0.115), (-0.08, 0.08), (0.0, 0.003), RED_COVER),
        block((-0.115, 0.115), (-0.08, 0.08), (0.027, 0.03), RED_COVER, surface=True),
        block((-0.115, 0.115), (-0.08, -0.077), (0.003, 0.027), RED_COVER),
        block((-0.112, 0.112), (-0.077, 0.078), (0.003, 0.027), PAPER),
    ]
    return AssetDesign(
        "book_01", "book", "a red hardback book lying flat", 0.5, 0.6, OBJECT, tuple(parts)
    )


def bowl() -> AssetDesign:
    """A flared ceramic bowl."""
    profile = ((0.045, 0.0), (0.06, 0.02), (0.08, 0.065))
    parts: list[Part] = [Lathe((0.0, 0.0, 0.0), profile, CERAMIC_BLUE, hollow=(0.004, 0.006))]
    return AssetDesign(
        "bowl_01", "bowl", "a blue ceramic cereal bowl", 0.35, 0.6, OBJECT, tuple(parts)
    )


def plate() -> AssetDesign:
    """A dinner plate with a shallow well."""
    profile = ((0.075, 0.0), (0.09, 0.008), (0.13, 0.02))
    parts: list[Part] = [Lathe((0.0, 0.0, 0.0), profile, PORCELAIN, hollow=(0.004, 0.008))]
    return AssetDesign(
        "plate_01", "plate", "a round white porcelain dinner plate", 0.45, 0.6, OBJECT, tuple(parts)
    )


def bottle() -> AssetDesign:
    """A glass wine bottle."""
    profile = ((0.036, 0.0), (0.036, 0.2), (0.014, 0.25), (0.013, 0.29), (0.015, 0.3))
    parts: list[Part] = [Lathe((0.0, 0.0, 0.0), profile, GREEN_GLASS)]
    return AssetDesign(
        "bottle_01", "bottle", "a full green glass wine bottle", 1.3, 0.5, OBJECT, tuple(parts)
    )


def laptop() -> AssetDesign:
    """An open laptop; its screen faces +X, the lid hinges at -X."""
    parts: list[Part] = [
        block((-0.12, 0.12), (-0.17, 0.17), (0.0, 0.018), ALUMINIUM),
        block((-0.1, 0.04), (-0.15, 0.15), (0.018, 0.019), BLACK_METAL, collide=False),
        block((-0.128, -0.12), (-0.17, 0.17), (0.0, 0.23), ALUMINIUM),
        block((-0.12, -0.119), (-0.16, 0.16), (0.03, 0.22), SCREEN, collide=False),
    ]
    return AssetDesign(
        "laptop_01", "laptop", "an open silver laptop", 1.8, 0.6, OBJECT, tuple(parts)
    )


def vase() -> AssetDesign:
    """A bulbous ceramic vase with a narrow neck."""
    profile = ((0.05, 0.0), (0.075, 0.1), (0.06, 0.2), (0.035, 0.27), (0.045, 0.3))
    parts: list[Part] = [Lathe((0.0, 0.0, 0.0), profile, CERAMIC_BLUE)]
    return AssetDesign(
        "vase_01", "vase", "a blue ceramic vase with a narrow neck", 1.0, 0.6, OBJECT, tuple(parts)
    )


def cardboard_box() -> AssetDesign:
    """A closed, taped cardboard box."""
    parts: list[Part] = [
        block((-0.2, 0.2), (-0.15, 0.15), (0.0, 0.25), CARDBOARD, surface=True),
        block((-0.2, 0.2), (-0.025, 0.025), (0.25, 0.2505), TAPE, collide=False),
    ]
    return AssetDesign(
        "cardboard_box_01",
        "cardboard_box",
        "a closed brown cardboard box sealed with tape",
        0.8,
        0.7,
        ("floor", "object"),
        tuple(parts),
    )


def apple() -> AssetDesign:
    """A red apple with a slightly flattened base and a stem."""
    parts: list[Part] = [
        Sphere((0.0, 0.0, 0.037), 0.04, APPLE_RED, cut=0.0),
        Cylinder((0.0, 0.0, 0.081), 0.003, 0.006, STEM, collide=False),
    ]
    return AssetDesign("apple_01", "apple", "a red apple", 0.18, 0.7, OBJECT, tuple(parts))


def small_potted_plant() -> AssetDesign:
    """A small plant in a terracotta pot, for shelves and tables."""
    parts: list[Part] = [
        Lathe((0.0, 0.0, 0.0), ((0.05, 0.0), (0.065, 0.11)), TERRACOTTA, hollow=(0.008, 0.015)),
        Cylinder((0.0, 0.0, 0.095), 0.05, 0.005, SOIL, collide=False),
        Sphere((0.0, 0.0, 0.19), 0.09, FOLIAGE),
    ]
    return AssetDesign(
        "potted_plant_small_01",
        "potted_plant",
        "a small green houseplant in a terracotta pot",
        1.5,
        0.7,
        OBJECT,
        tuple(parts),
    )


def desk_lamp() -> AssetDesign:
    """A desk lamp: round base, upright pole, arm reaching +X and a downward shade."""
    parts: list[Part] = [
        Cylinder((0.0, 0.0, 0.015), 0.08, 0.015, BLACK_METAL),
        Cylinder((-0.04, 0.0, 0.2), 0.008, 0.185, BLACK_METAL),
        Cylinder((0.01, 0.0, 0.38), 0.008, 0.05, BLACK_METAL, axis="x"),
        Lathe((0.06, 0.0, 0.29), ((0.06, 0.0), (0.025, 0.09)), LAMP_SHADE),
    ]
    return AssetDesign(
        "desk_lamp_01",
        "desk_lamp",
        "a black desk lamp with a cream shade",
        1.2,
        0.7,
        OBJECT,
        tuple(parts),
    )


def toy_block() -> AssetDesign:
    """A 5 cm wooden toy block."""
    parts: list[Part] = [block((-0.025, 0.025), (-0.025, 0.025), (0.0, 0.05), TOY_RED)]
    return AssetDesign(
        "toy_block_01", "toy_block", "a red wooden toy block", 0.06, 0.6, OBJECT, tuple(parts)
    )


def designs() -> list[AssetDesign]:
    """All designs of this module."""
    return [
        mug(),
        book(),
        bowl(),
        plate(),
        bottle(),
        laptop(),
        vase(),
        cardboard_box(),
        apple(),
        small_potted_plant(),
        desk_lamp(),
        toy_block(),
    ]
