"""Building blocks of articulated assets: open carcasses, hinged doors, drawers and handles.

Depth runs along X (front +X), width along Y, height along Z. A carcass is a set of panels
around an open front (sides, back, bottom, top board, shelves and rails), never one solid box,
so that what is inside sits in free space and a door or drawer closes in front of it. Fronts
stand :data:`GAP` in front of the carcass face and :data:`SEAM` apart from each other; handles
(two posts and a bar a hand can close around) stand :data:`HANDLE_OUT` proud of the fronts.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from asset_pipeline.procedural.articulated.links import (
    HandleDesign,
    Link,
    drawer_slide,
    inside,
    moving,
    side_hinge,
)
from asset_pipeline.procedural.kit import block
from asset_pipeline.procedural.parts import Box, Part, RecipeMaterial
from asset_pipeline.procedural.roles import tagged

Rng = np.random.Generator
PANEL = 0.018  # carcass panel thickness
BACK = 0.008  # back panel thickness
FRONT_T = 0.018  # door and drawer front thickness
GAP = 0.003  # closed front to carcass face
SEAM = 0.004  # between neighbouring fronts
HANDLE_OUT = 0.035  # handle bar's front from the front's face
HANDLE_BAR = 0.012  # bar thickness (the grip a hand closes around)
POST = 0.012  # post side
PROUD = FRONT_T + GAP + HANDLE_OUT  # a cabinet's front from its carcass face to handle tips
DRAWER_WALL = 0.012
DRAWER_SIDE_CLEAR = 0.006  # drawer box to carcass sides
DRAWER_FLOOR_CLEAR = 0.004  # drawer box above its rail
DRAWER_HEAD_CLEAR = 0.008  # drawer box below the rail above
DRAWER_TRAVEL = 0.9  # drawers open to this share of their depth


@dataclass(frozen=True)
class Cavity:
    """The free inside of a carcass compartment: x from the back panel to the open face."""

    x0: float
    x1: float
    y0: float
    y1: float
    z0: float
    z1: float


def handle(
    x_front: float,
    y: float,
    z: float,
    length: float,
    vertical: bool,
    material: RecipeMaterial,
    pull: tuple[float, float, float] = (1.0, 0.0, 0.0),
) -> tuple[list[Part], HandleDesign]:
    """A bar handle on a front whose face is at ``x_front`` (facing +X): two posts and a bar
    of ``length`` centred at (y, z), vertical or horizontal. Returns the parts and the grasp."""
    x_bar = (x_front + HANDLE_OUT - HANDLE_BAR, x_front + HANDLE_OUT)
    h = 0.5 * length
    if vertical:
        bar = block(x_bar, (y - 0.5 * HANDLE_BAR, y + 0.5 * HANDLE_BAR), (z - h, z + h), material)
        posts = [
            block(
                (x_front, x_bar[0]),
                (y - 0.5 * POST, y + 0.5 * POST),
                (zc - 0.5 * POST, zc + 0.5 * POST),
                material,
            )
            for zc in (z - h + 0.5 * POST, z + h - 0.5 * POST)
        ]
        along = (0.0, 0.0, 1.0)
    else:
        bar = block(x_bar, (y - h, y + h), (z - 0.5 * HANDLE_BAR, z + 0.5 * HANDLE_BAR), material)
        posts = [
            block(
                (x_front, x_bar[0]),
                (yc - 0.5 * POST, yc + 0.5 * POST),
                (z - 0.5 * POST, z + 0.5 * POST),
                material,
            )
            for yc in (y - h + 0.5 * POST, y + h - 0.5 * POST)
        ]
        along = (0.0, 1.0, 0.0)
    grip = HandleDesign((0.5 * (x_bar[0] + x_bar[1]), y, z), pull, along, length)
    return [bar, *posts], grip


def carcass(
    x: tuple[float, float],
    y: tuple[float, float],
    z: tuple[float, float],
    material: RecipeMaterial,
    *,
    top: bool = True,
    bottom: bool = True,
) -> tuple[list[Box], Cavity]:
    """Panels around an open +X front: sides, back, bottom and top (between the sides).

    Returns the panels and the cavity inside them."""
    (x0, x1), (y0, y1), (z0, z1) = x, y, z
    t = PANEL
    panels = [
        block((x0, x1), (y0, y0 + t), (z0, z1), material),
        block((x0, x1), (y1 - t, y1), (z0, z1), material),
        block((x0, x0 + BACK), (y0 + t, y1 - t), (z0, z1), material),
    ]
    inner_z0, inner_z1 = z0, z1
    if bottom:
        panels.append(block((x0 + BACK, x1), (y0 + t, y1 - t), (z0, z0 + t), material))
        inner_z0 = z0 + t
    if top:
        panels.append(block((x0 + BACK, x1), (y0 + t, y1 - t), (z1 - t, z1), material))
        inner_z1 = z1 - t
    return panels, Cavity(x0 + BACK, x1, y0 + t, y1 - t, inner_z0, inner_z1)


def shelf(
    cavity: Cavity, z: float, material: RecipeMaterial, behind: tuple[str, ...]
) -> list[Part]:
    """A shelf board with its top at ``z`` across ``cavity``, set back 2 cm from the face; its
    top is an interior surface reached through ``behind``."""
    board = block(
        (cavity.x0, cavity.x1 - 0.02),
        (cavity.y0, cavity.y1),
        (z - PANEL, z),
        material,
        surface=True,
    )
    return tagged("shelves", inside(behind, [board]))


def floor_surface(cavity: Cavity, material: RecipeMaterial, behind: tuple[str, ...]) -> list[Part]:
    """A thin liner on a compartment's floor whose top is an interior surface (the floor of a
    cupboard); it lies on the bottom panel, inside the cavity."""
    liner = block(
        (cavity.x0, cavity.x1 - 0.01),
        (cavity.y0, cavity.y1),
        (cavity.z0, cavity.z0 + 0.003),
        material,
        surface=True,
    )
    return inside(behind, [liner])


def door(
    name: str,
    x_face: float,
    y: tuple[float, float],
    z: tuple[float, float],
    hinge_at: str,
    front: RecipeMaterial,
    handle_material: RecipeMaterial,
    handle_z: float,
    *,
    thickness: float = FRONT_T,
    max_deg: float = 110.0,
    density: float = 600.0,
    handle_length: float | None = None,
) -> tuple[list[Part], Link]:
    """A door in front of the carcass face ``x_face`` spanning ``y`` and ``z``, hinged on its
    ``-y`` or ``+y`` edge, with a vertical handle near the free edge at ``handle_z``."""
    (y0, y1), (z0, z1) = y, z
    xb = x_face + GAP
    xf = xb + thickness
    hinge_y, free_y = (y0, y1) if hinge_at == "-y" else (y1, y0)
    length = handle_length or min(0.16, 0.5 * (z1 - z0))
    hz = min(max(handle_z, z0 + 0.5 * length + 0.02), z1 - 0.5 * length - 0.02)
    hy = free_y - math.copysign(0.04, free_y - hinge_y)
    handle_parts, grip = handle(xf, hy, hz, length, True, handle_material)
    joint = side_hinge(hinge_y, free_y, xf, 0.5 * (z0 + z1), max_deg)
    link = Link(name, "door", joint, grip, density=density)
    panel = block((xb, xf), (y0, y1), (z0, z1), front)
    parts = tagged("doors", moving(link, [panel])) + tagged("handles", moving(link, handle_parts))
    return parts, link


def drawer(
    name: str,
    x_face: float,
    front_y: tuple[float, float],
    front_z: tuple[float, float],
    cell: Cavity,
    front: RecipeMaterial,
    box: RecipeMaterial,
    handle_material: RecipeMaterial,
    *,
    knob: bool = False,
) -> tuple[list[Part], Link]:
    """A drawer: a front in front of ``x_face`` spanning ``front_y`` x ``front_z`` and an open
    box (bottom, sides, back) inside the compartment ``cell``; it slides out along +X up to
    :data:`DRAWER_TRAVEL` of its depth. The box bottom is an interior surface."""
    (fy0, fy1), (fz0, fz1) = front_y, front_z
    xb = x_face + GAP
    xf = xb + FRONT_T
    bx0 = cell.x0 + 0.01
    by0, by1 = cell.y0 + DRAWER_SIDE_CLEAR, cell.y1 - DRAWER_SIDE_CLEAR
    bz0, bz1 = cell.z0 + DRAWER_FLOOR_CLEAR, cell.z1 - DRAWER_HEAD_CLEAR
    w = DRAWER_WALL
    depth = xb - bx0
    yc, zc = 0.5 * (fy0 + fy1), 0.5 * (fz0 + fz1)
    length = min(0.16, 0.5 * (fy1 - fy0))
    if knob:
        length = 0.03
    handle_parts, grip = handle(xf, yc, zc, length, False, handle_material)
    link = Link(name, "drawer", drawer_slide((xf, yc, zc), DRAWER_TRAVEL * depth), grip)
    bottom = block((bx0, xb), (by0, by1), (bz0, bz0 + w), box, surface=True)
    walls = [
        block((bx0, xb), (by0, by0 + w), (bz0 + w, bz1), box),
        block((bx0, xb), (by1 - w, by1), (bz0 + w, bz1), box),
        block((bx0, bx0 + w), (by0 + w, by1 - w), (bz0 + w, bz1), box),
    ]
    panel = block((xb, xf), (fy0, fy1), (fz0, fz1), front)
    parts = (
        tagged("drawers", moving(link, [panel, *walls]))
        + tagged("drawers", moving(link, inside((name,), [bottom])))
        + tagged("handles", moving(link, handle_parts))
    )
    return parts, link


def drawer_stack(
    prefix: str,
    x_face: float,
    cavity: Cavity,
    z: tuple[float, float],
    rows: int,
    columns: int,
    carcass_material: RecipeMaterial,
    front: RecipeMaterial,
    box: RecipeMaterial,
    handle_material: RecipeMaterial,
    *,
    knob: bool = False,
    first: int = 0,
) -> tuple[list[Part], list[Link]]:
    """``rows`` x ``columns`` drawers filling the front between heights ``z`` (the fronts)
    and the carcass ``cavity`` behind them, with the rails between rows and the uprights
    between columns (carcass parts). Drawer ``k`` is ``f"{prefix}_{first + k}"``, bottom row
    first, left (-Y) to right."""
    z0, z1 = z
    row_h = (z1 - z0) / rows
    col_w = (cavity.y1 - cavity.y0) / columns
    parts: list[Part] = []
    links: list[Link] = []
    # Rails between rows (centred on the seams) and uprights between columns.
    rails = [z0 + i * row_h for i in range(1, rows)]
    for zr in rails:
        parts.append(
            block(
                (cavity.x0, cavity.x1),
                (cavity.y0, cavity.y1),
                (zr - 0.5 * PANEL, zr + 0.5 * PANEL),
                carcass_material,
            )
        )
    uprights = [cavity.y0 + j * col_w for j in range(1, columns)]
    for yu in uprights:
        parts.append(
            block(
                (cavity.x0, cavity.x1),
                (yu - 0.5 * PANEL, yu + 0.5 * PANEL),
                (cavity.z0, cavity.z1),
                carcass_material,
            )
        )
    parts = tagged("body", parts)
    # Fronts span the whole front (the carcass sides included), split at the seams.
    fy_edges = [cavity.y0 - PANEL + 0.002] + uprights + [cavity.y1 + PANEL - 0.002]
    cy_edges = [cavity.y0] + [yu for yu in uprights] + [cavity.y1]
    k = first
    for i in range(rows):
        cz0 = (rails[i - 1] + 0.5 * PANEL) if i > 0 else cavity.z0
        cz1 = (rails[i] - 0.5 * PANEL) if i < rows - 1 else cavity.z1
        fz0 = z0 + i * row_h + (0.5 * SEAM if i > 0 else 0.0)
        fz1 = z0 + (i + 1) * row_h - (0.5 * SEAM if i < rows - 1 else 0.0)
        for j in range(columns):
            cy0 = cy_edges[j] + (0.5 * PANEL if j > 0 else 0.0)
            cy1 = cy_edges[j + 1] - (0.5 * PANEL if j < columns - 1 else 0.0)
            fy0 = fy_edges[j] + (0.5 * SEAM if j > 0 else 0.0)
            fy1 = fy_edges[j + 1] - (0.5 * SEAM if j < columns - 1 else 0.0)
            cell = Cavity(cavity.x0, cavity.x1, cy0, cy1, cz0, cz1)
            made, link = drawer(
                f"{prefix}_{k}",
                x_face,
                (fy0, fy1),
                (fz0, fz1),
                cell,
                front,
                box,
                handle_material,
                knob=knob,
            )
            parts += made
            links.append(link)
            k += 1
    return parts, links


def door_pair(
    prefix: str,
    x_face: float,
    y: tuple[float, float],
    z: tuple[float, float],
    count: int,
    front: RecipeMaterial,
    handle_material: RecipeMaterial,
    handle_z: float,
    rng: Rng,
    *,
    first: int = 0,
    max_deg: float = 110.0,
    density: float = 600.0,
) -> tuple[list[Part], list[Link]]:
    """``count`` doors side by side across ``y`` (fronts split at seams). Pairs open from the
    middle; a single door (or the odd last one) is hinged on a random side."""
    y0, y1 = y
    width = (y1 - y0) / count
    parts: list[Part] = []
    links: list[Link] = []
    single_side = "-y" if rng.random() < 0.5 else "+y"
    for j in range(count):
        dy0 = y0 + j * width + (0.5 * SEAM if j > 0 else 0.0)
        dy1 = y0 + (j + 1) * width - (0.5 * SEAM if j < count - 1 else 0.0)
        if count == 1 or (count % 2 == 1 and j == count - 1):
            side = single_side
        else:
            side = "-y" if j % 2 == 0 else "+y"
        made, link = door(
            f"{prefix}_{first + j}",
            x_face,
            (dy0, dy1),
            z,
            side,
            front,
            handle_material,
            handle_z,
            max_deg=max_deg,
            density=density,
        )
        parts += made
        links.append(link)
    return parts, links


def joint_names(links: list[Link]) -> tuple[str, ...]:
    """The link names (what :class:`~.links.Inside` takes as ``behind``)."""
    return tuple(link.name for link in links)
