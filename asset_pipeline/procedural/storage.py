"""Designs of storage furniture and kitchen and bathroom fixtures (front +X)."""

from __future__ import annotations

from asset_pipeline.procedural.assembly import AssetDesign
from asset_pipeline.procedural.kit import (
    BLACK_METAL,
    CHROME,
    GREY_LAMINATE,
    OAK,
    PORCELAIN,
    STEEL,
    WALNUT,
    WHITE_LACQUER,
    block,
    drawer_fronts,
    square_legs,
)
from asset_pipeline.procedural.parts import Material, Part
from asset_pipeline.procedural.round_parts import Cylinder

FLOOR = ("floor",)


def cabinet(
    asset_id: str,
    category: str,
    description: str,
    size: tuple[float, float, float],
    mass_kg: float,
    body: Material,
    top: Material,
    handles: Material,
    grid: tuple[int, int],
    *,
    top_thickness: float = 0.03,
    plinth: float = 0.0,
    placement: tuple[str, ...] = FLOOR,
) -> AssetDesign:
    """A box carcass with a top board (a surface) and a grid of drawer or door fronts."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    face = hd - 0.02
    top_z = h - top_thickness
    parts: list[Part] = []
    if plinth > 0.0:
        parts.append(block((-hd, face - 0.05), (-hw, hw), (0.0, plinth), BLACK_METAL))
    parts.append(block((-hd, face), (-hw, hw), (plinth, top_z), body))
    parts.append(block((-hd, hd), (-hw, hw), (top_z, h), top, surface=True))
    parts += drawer_fronts(
        face, (-hw, hw), (plinth + 0.01, top_z - 0.01), grid[0], grid[1], body, handles
    )
    return AssetDesign(asset_id, category, description, mass_kg, 0.6, placement, tuple(parts))


def bookshelf(
    asset_id: str,
    description: str,
    size: tuple[float, float, float],
    levels: int,
    mass_kg: float,
    material: Material,
) -> AssetDesign:
    """An open bookshelf (open side +X) with a back panel; every level is a surface."""
    d, w, h = size
    hd, hw, t = 0.5 * d, 0.5 * w, 0.02
    bottom_top, top_bottom = 0.08, h - t
    parts: list[Part] = [
        block((-hd, hd), (-hw, -hw + t), (0.0, top_bottom), material),
        block((-hd, hd), (hw - t, hw), (0.0, top_bottom), material),
        block((-hd, -hd + 0.01), (-hw + t, hw - t), (0.0, top_bottom), material),
        block((hd - t, hd), (-hw + t, hw - t), (0.0, bottom_top - t), material),
        block((-hd, hd), (-hw, hw), (top_bottom, h), material, surface=True),
    ]
    pitch = (top_bottom - bottom_top) / levels
    for i in range(levels):
        z = bottom_top + i * pitch
        parts.append(block((-hd + 0.01, hd), (-hw + t, hw - t), (z - t, z), material, surface=True))
    return AssetDesign(asset_id, "bookshelf", description, mass_kg, 0.6, FLOOR, tuple(parts))


def shelving_unit() -> AssetDesign:
    """Open steel shelving: four corner posts and four laminate shelves."""
    hd, hw, post = 0.2, 0.45, 0.03
    parts: list[Part] = []
    for x in ((-hd, -hd + post), (hd - post, hd)):
        for y in ((-hw, -hw + post), (hw - post, hw)):
            parts.append(block(x, y, (0.0, 1.5), STEEL))
    for top in (0.15, 0.6, 1.05, 1.5):
        parts.append(
            block(
                (-hd, hd), (-hw + post, hw - post), (top - 0.02, top), GREY_LAMINATE, surface=True
            )
        )
    return AssetDesign(
        "shelving_unit_01",
        "shelving_unit",
        "an open steel shelving unit with four grey shelves",
        15.0,
        0.5,
        FLOOR,
        tuple(parts),
    )


def tv_stand() -> AssetDesign:
    """A low media cabinet on short legs."""
    parts: list[Part] = list(square_legs(0.43, 1.56, 0.06, 0.04, BLACK_METAL, inset=0.03))
    parts.append(block((-0.225, 0.205), (-0.8, 0.8), (0.06, 0.47), WALNUT))
    parts.append(block((-0.225, 0.225), (-0.8, 0.8), (0.47, 0.5), WALNUT, surface=True))
    parts += drawer_fronts(0.205, (-0.79, 0.79), (0.08, 0.45), 1, 3, WALNUT, BLACK_METAL)
    return AssetDesign(
        "tv_stand_01",
        "tv_stand",
        "a long low walnut tv stand with three doors",
        30.0,
        0.6,
        FLOOR,
        tuple(parts),
    )


def sink_counter() -> AssetDesign:
    """A kitchen base cabinet with a steel sink basin and a faucet at the back."""
    parts: list[Part] = [
        block((-0.3, 0.22), (-0.6, 0.6), (0.0, 0.1), BLACK_METAL),
        block((-0.3, 0.27), (-0.6, 0.6), (0.1, 0.86), WHITE_LACQUER),
        block((-0.3, 0.3), (-0.6, -0.25), (0.86, 0.9), GREY_LAMINATE, surface=True),
        block((-0.3, 0.3), (0.25, 0.6), (0.86, 0.9), GREY_LAMINATE, surface=True),
        block((-0.3, -0.2), (-0.25, 0.25), (0.86, 0.9), GREY_LAMINATE),
        block((0.2, 0.3), (-0.25, 0.25), (0.86, 0.9), GREY_LAMINATE),
        block((-0.2, 0.2), (-0.25, 0.25), (0.8, 0.88), STEEL),
        Cylinder((-0.25, 0.0, 0.96), 0.015, 0.06, CHROME),
        block((-0.25, -0.14), (-0.012, 0.012), (0.995, 1.02), CHROME),
    ]
    parts += drawer_fronts(0.27, (-0.6, 0.6), (0.11, 0.85), 1, 2, WHITE_LACQUER, CHROME)
    return AssetDesign(
        "sink_counter_01",
        "sink_counter",
        "a white kitchen sink cabinet with a steel basin and a chrome faucet",
        55.0,
        0.6,
        FLOOR,
        tuple(parts),
    )


def toilet() -> AssetDesign:
    """A porcelain toilet: pedestal, round bowl and seat at +X, cistern at -X."""
    parts: list[Part] = [
        block((-0.3, 0.18), (-0.12, 0.12), (0.0, 0.25), PORCELAIN),
        Cylinder((0.08, 0.0, 0.32), 0.19, 0.07, PORCELAIN),
        Cylinder((0.08, 0.0, 0.4), 0.19, 0.01, WHITE_LACQUER),
        block((-0.3, -0.1), (-0.12, 0.12), (0.25, 0.41), PORCELAIN),
        block((-0.36, -0.16), (-0.2, 0.2), (0.41, 0.8), PORCELAIN, surface=True),
    ]
    return AssetDesign(
        "toilet_01",
        "toilet",
        "a white porcelain toilet with a cistern",
        30.0,
        0.6,
        FLOOR,
        tuple(parts),
    )


def bathtub() -> AssetDesign:
    """A rectangular built-in style bathtub, long along Y."""
    hd, hw, wall = 0.375, 0.85, 0.06
    parts: list[Part] = [
        block(
            (-hd, hd),
            (-hw, hw),
            (0.0, 0.12),
            PORCELAIN,
            surface=(-hd + wall, hd - wall, -hw + wall, hw - wall),
        ),
        block((hd - wall, hd), (-hw, hw), (0.12, 0.55), PORCELAIN),
        block((-hd, -hd + wall), (-hw, hw), (0.12, 0.55), PORCELAIN),
        block((-hd + wall, hd - wall), (-hw, -hw + wall), (0.12, 0.55), PORCELAIN),
        block((-hd + wall, hd - wall), (hw - wall, hw), (0.12, 0.55), PORCELAIN),
    ]
    return AssetDesign(
        "bathtub_01",
        "bathtub",
        "a white rectangular bathtub",
        50.0,
        0.6,
        FLOOR,
        tuple(parts),
    )


def designs() -> list[AssetDesign]:
    """All designs of this module."""
    return [
        cabinet(
            "nightstand_01",
            "nightstand",
            "a white nightstand with two drawers and an oak top",
            (0.4, 0.45, 0.55),
            12.0,
            WHITE_LACQUER,
            OAK,
            CHROME,
            (2, 1),
        ),
        cabinet(
            "dresser_01",
            "dresser",
            "a walnut chest of six drawers",
            (0.5, 1.2, 0.85),
            50.0,
            WALNUT,
            WALNUT,
            BLACK_METAL,
            (3, 2),
        ),
        cabinet(
            "wardrobe_01",
            "wardrobe",
            "a tall white two-door wardrobe",
            (0.6, 1.2, 2.0),
            80.0,
            WHITE_LACQUER,
            WHITE_LACQUER,
            CHROME,
            (1, 2),
            top_thickness=0.02,
            plinth=0.08,
        ),
        bookshelf(
            "bookshelf_01",
            "an oak bookshelf with five open shelves",
            (0.3, 0.8, 1.8),
            5,
            30.0,
            OAK,
        ),
        bookshelf(
            "bookshelf_02",
            "a tall wide white bookshelf with six open shelves",
            (0.35, 1.0, 2.0),
            6,
            45.0,
            WHITE_LACQUER,
        ),
        shelving_unit(),
        tv_stand(),
        cabinet(
            "kitchen_counter_01",
            "kitchen_counter",
            "a white kitchen base cabinet with a grey laminate countertop",
            (0.6, 1.2, 0.9),
            60.0,
            WHITE_LACQUER,
            GREY_LAMINATE,
            CHROME,
            (1, 2),
            top_thickness=0.04,
            plinth=0.1,
        ),
        cabinet(
            "kitchen_cabinet_01",
            "kitchen_cabinet",
            "a white wall-mounted kitchen cabinet with two doors",
            (0.35, 0.8, 0.7),
            18.0,
            WHITE_LACQUER,
            WHITE_LACQUER,
            CHROME,
            (1, 2),
            top_thickness=0.02,
            placement=("wall",),
        ),
        sink_counter(),
        toilet(),
        bathtub(),
    ]
