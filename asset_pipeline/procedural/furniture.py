"""Designs of beds, sofas, chairs, tables and desks (depth along X, width along Y, front +X)."""

from __future__ import annotations

from asset_pipeline.procedural.assembly import AssetDesign
from asset_pipeline.procedural.kit import (
    BEIGE_FABRIC,
    BLACK_METAL,
    BLUE_FABRIC,
    CHROME,
    GREEN_FABRIC,
    GREY_FABRIC,
    LINEN,
    OAK,
    PINE,
    WALNUT,
    WHITE_LACQUER,
    block,
    drawer_fronts,
    round_legs,
    square_legs,
)
from asset_pipeline.procedural.parts import Material, Part
from asset_pipeline.procedural.round_parts import Cylinder

FLOOR = ("floor",)


def bed(
    asset_id: str,
    description: str,
    length: float,
    width: float,
    mass_kg: float,
    headboard_height: float,
    frame: Material,
    headboard: Material,
) -> AssetDesign:
    """A bed on four legs with a mattress, pillows and a headboard at -X."""
    half_l, half_w = 0.5 * length, 0.5 * width
    leg_h, frame_top, mattress_top = 0.1, 0.32, 0.56
    parts: list[Part] = list(square_legs(length, width, leg_h, 0.07, frame))
    parts.append(block((-half_l, half_l), (-half_w, half_w), (leg_h, frame_top), frame))
    parts.append(
        block((-half_l - 0.05, -half_l), (-half_w, half_w), (0.0, headboard_height), headboard)
    )
    pillow_front = -half_l + 0.42
    parts.append(
        block(
            (-half_l + 0.02, half_l - 0.02),
            (-half_w + 0.02, half_w - 0.02),
            (frame_top, mattress_top),
            LINEN,
            surface=(pillow_front + 0.02, half_l, -half_w, half_w),
        )
    )
    pillows = 1 if width < 1.2 else 2
    span = (width - 0.16) / pillows
    for i in range(pillows):
        y0 = -half_w + 0.08 + i * span
        parts.append(
            block(
                (-half_l + 0.06, pillow_front),
                (y0 + 0.02, y0 + span - 0.02),
                (mattress_top, mattress_top + 0.12),
                LINEN,
            )
        )
    return AssetDesign(asset_id, "bed", description, mass_kg, 0.8, FLOOR, tuple(parts))


def sofa(
    asset_id: str,
    description: str,
    width: float,
    depth: float,
    seats: int,
    mass_kg: float,
    fabric: Material,
    on_legs: bool,
) -> AssetDesign:
    """A sofa: base, back at -X, two arms and ``seats`` seat cushions (each a surface)."""
    hd, hw = 0.5 * depth, 0.5 * width
    base_z = 0.1 if on_legs else 0.06
    seat_z, arm_w, back_d = 0.4, 0.15, 0.22
    parts: list[Part] = []
    if on_legs:
        parts += round_legs(depth, width, base_z, 0.025, BLACK_METAL, inset=0.06)
    else:
        parts.append(block((-hd + 0.03, hd - 0.03), (-hw + 0.03, hw - 0.03), (0.0, base_z), WALNUT))
    parts.append(block((-hd, hd), (-hw, hw), (base_z, seat_z), fabric))
    parts.append(block((-hd, -hd + back_d), (-hw, hw), (seat_z, 0.86), fabric))
    for sign in (-1.0, 1.0):
        y = sorted((sign * hw, sign * (hw - arm_w)))
        parts.append(block((-hd + back_d, hd), (y[0], y[1]), (seat_z, 0.62), fabric))
    inner = width - 2 * arm_w
    for i in range(seats):
        y0 = -hw + arm_w + i * inner / seats
        parts.append(
            block(
                (-hd + back_d, hd - 0.02),
                (y0, y0 + inner / seats),
                (seat_z, seat_z + 0.1),
                fabric,
                surface=True,
            )
        )
    return AssetDesign(asset_id, "sofa", description, mass_kg, 0.9, FLOOR, tuple(parts))


def armchair() -> AssetDesign:
    """An upholstered armchair on short wooden legs."""
    d, w = 0.85, 0.85
    parts: list[Part] = list(round_legs(d, w, 0.12, 0.022, WALNUT, inset=0.06))
    parts.append(block((-0.425, 0.425), (-0.425, 0.425), (0.12, 0.4), GREEN_FABRIC))
    parts.append(block((-0.425, -0.215), (-0.425, 0.425), (0.4, 0.95), GREEN_FABRIC))
    parts.append(block((-0.215, 0.425), (-0.425, -0.3), (0.4, 0.65), GREEN_FABRIC))
    parts.append(block((-0.215, 0.425), (0.3, 0.425), (0.4, 0.65), GREEN_FABRIC))
    parts.append(block((-0.215, 0.41), (-0.3, 0.3), (0.4, 0.5), GREEN_FABRIC, surface=True))
    return AssetDesign(
        "armchair_01",
        "armchair",
        "a green upholstered armchair with wide arms on short walnut legs",
        25.0,
        0.9,
        FLOOR,
        tuple(parts),
    )


def dining_chair() -> AssetDesign:
    """A wooden dining chair; its rear legs rise into the back posts at -X."""
    hw, leg = 0.225, 0.04
    seat_bottom, seat_top = 0.43, 0.46
    parts: list[Part] = []
    for y in ((-hw, -hw + leg), (hw - leg, hw)):
        parts.append(block((hw - leg, hw), y, (0.0, seat_bottom), OAK))  # front legs
        parts.append(block((-hw, -hw + leg), y, (0.0, 0.9), OAK))  # rear legs and back posts
    parts.append(
        block((-hw, hw), (-hw, hw), (seat_bottom, seat_top), OAK, surface=(-hw + leg, hw, -hw, hw))
    )
    parts.append(block((-hw + 0.008, -hw + 0.032), (-hw + leg, hw - leg), (0.62, 0.88), OAK))
    return AssetDesign(
        "dining_chair_01",
        "dining_chair",
        "a simple oak dining chair with a slatted back",
        5.0,
        0.6,
        FLOOR,
        tuple(parts),
    )


def office_chair() -> AssetDesign:
    """A static office chair: cross base, gas column, padded seat and a backrest at -X."""
    parts: list[Part] = [
        block((-0.3, 0.3), (-0.03, 0.03), (0.0, 0.04), BLACK_METAL),
        block((-0.03, 0.03), (-0.3, 0.3), (0.0, 0.04), BLACK_METAL),
        Cylinder((0.0, 0.0, 0.24), 0.025, 0.2, CHROME),
        block((-0.25, 0.25), (-0.25, 0.25), (0.44, 0.52), GREY_FABRIC, surface=True),
        block((-0.29, -0.25), (-0.03, 0.03), (0.44, 0.64), BLACK_METAL),
        block((-0.31, -0.25), (-0.23, 0.23), (0.62, 1.0), GREY_FABRIC),
    ]
    return AssetDesign(
        "office_chair_01",
        "office_chair",
        "a grey fabric office chair with a chrome column and a black cross base",
        12.0,
        0.7,
        FLOOR,
        tuple(parts),
    )


def stool() -> AssetDesign:
    """A round pine stool on four legs."""
    parts: list[Part] = list(round_legs(0.34, 0.34, 0.43, 0.016, PINE, inset=0.09))
    parts.append(Cylinder((0.0, 0.0, 0.445), 0.17, 0.015, PINE, surface=True))
    return AssetDesign(
        "stool_01", "stool", "a round pine stool with four legs", 3.0, 0.6, FLOOR, tuple(parts)
    )


def rectangular_table(
    asset_id: str,
    category: str,
    description: str,
    size: tuple[float, float, float],
    mass_kg: float,
    top: Material,
    legs: Material,
    leg_side: float = 0.06,
    leg_inset: float = 0.04,
    shelf: bool = False,
) -> AssetDesign:
    """A table top on four square legs, optionally with a lower shelf between the legs."""
    d, w, h = size
    parts: list[Part] = list(square_legs(d, w, h - 0.04, leg_side, legs, inset=leg_inset))
    parts.append(block((-0.5 * d, 0.5 * d), (-0.5 * w, 0.5 * w), (h - 0.04, h), top, surface=True))
    if shelf:
        outer_x = 0.5 * d - leg_inset
        inner_y = 0.5 * w - leg_inset - leg_side
        parts.append(
            block((-outer_x, outer_x), (-inner_y, inner_y), (0.1, 0.12), top, surface=True)
        )
    return AssetDesign(asset_id, category, description, mass_kg, 0.6, FLOOR, tuple(parts))


def round_dining_table() -> AssetDesign:
    """A round pedestal table."""
    parts: list[Part] = [
        Cylinder((0.0, 0.0, 0.02), 0.3, 0.02, BLACK_METAL),
        Cylinder((0.0, 0.0, 0.38), 0.05, 0.34, BLACK_METAL),
        Cylinder((0.0, 0.0, 0.735), 0.55, 0.015, WALNUT, surface=True),
    ]
    return AssetDesign(
        "dining_table_02",
        "dining_table",
        "a round walnut pedestal dining table for four",
        28.0,
        0.6,
        FLOOR,
        tuple(parts),
    )


def desk_with_drawers() -> AssetDesign:
    """A desk with a three-drawer pedestal on its right (+Y) and two legs on its left."""
    parts: list[Part] = [
        block((-0.3, 0.3), (-0.6, 0.6), (0.72, 0.75), WALNUT, surface=True),
        block((-0.28, 0.26), (0.18, 0.58), (0.0, 0.72), WALNUT),
        block((-0.28, -0.23), (-0.58, -0.53), (0.0, 0.72), WALNUT),
        block((0.21, 0.26), (-0.58, -0.53), (0.0, 0.72), WALNUT),
    ]
    parts += drawer_fronts(0.26, (0.18, 0.58), (0.02, 0.7), 3, 1, WALNUT, BLACK_METAL)
    return AssetDesign(
        "desk_02",
        "desk",
        "a walnut writing desk with a three-drawer pedestal",
        35.0,
        0.6,
        FLOOR,
        tuple(parts),
    )


def designs() -> list[AssetDesign]:
    """All designs of this module."""
    return [
        bed(
            "bed_single_01",
            "a single bed with an oak frame, a white mattress and a pillow",
            2.0,
            0.95,
            40.0,
            0.95,
            OAK,
            OAK,
        ),
        bed(
            "bed_double_01",
            "a double bed with an upholstered beige headboard and two pillows",
            2.1,
            1.6,
            65.0,
            1.1,
            WALNUT,
            BEIGE_FABRIC,
        ),
        sofa(
            "sofa_01",
            "a grey two-seat fabric sofa on black metal legs",
            1.6,
            0.9,
            2,
            45.0,
            GREY_FABRIC,
            on_legs=True,
        ),
        sofa(
            "sofa_02",
            "a blue three-seat sofa on a low wooden plinth",
            2.2,
            0.95,
            3,
            60.0,
            BLUE_FABRIC,
            on_legs=False,
        ),
        armchair(),
        dining_chair(),
        office_chair(),
        stool(),
        rectangular_table(
            "dining_table_01",
            "dining_table",
            "a rectangular oak dining table for six",
            (0.9, 1.8, 0.75),
            35.0,
            OAK,
            OAK,
            leg_side=0.07,
        ),
        round_dining_table(),
        rectangular_table(
            "coffee_table_01",
            "coffee_table",
            "a low walnut coffee table with a lower shelf",
            (0.6, 1.1, 0.42),
            15.0,
            WALNUT,
            WALNUT,
            leg_side=0.05,
            leg_inset=0.02,
            shelf=True,
        ),
        rectangular_table(
            "side_table_01",
            "side_table",
            "a small square oak side table",
            (0.45, 0.45, 0.55),
            6.0,
            OAK,
            OAK,
            leg_side=0.035,
            leg_inset=0.03,
        ),
        rectangular_table(
            "desk_01",
            "desk",
            "a white office desk on black metal legs",
            (0.7, 1.4, 0.75),
            25.0,
            WHITE_LACQUER,
            BLACK_METAL,
            leg_side=0.05,
            leg_inset=0.02,
        ),
        desk_with_drawers(),
    ]
