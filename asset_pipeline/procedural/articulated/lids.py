"""Articulated things with lids: toilets (seat and lid), laptops, trunks and toy boxes.

Lids turn up about a horizontal axis at their back edge (about -Y: a positive angle lifts the
front) and are held at any angle by a counterbalance and friction (a friction hinge, a lid
stay), so they stay where they are left; their handle is the front edge (or a bar on it) and
the pull is upwards."""

from __future__ import annotations

import math

from asset_pipeline.procedural.articulated.kit import (
    HANDLE_BAR,
    HANDLE_OUT,
    POST,
    Cavity,
    floor_surface,
)
from asset_pipeline.procedural.articulated.links import (
    HandleDesign,
    Link,
    flap_hinge,
    moving,
)
from asset_pipeline.procedural.articulated.registry import articulated
from asset_pipeline.procedural.home_kit import HANDLES, SAGE_TOY
from asset_pipeline.procedural.kit import (
    ALUMINIUM,
    BLACK_PLASTIC,
    BRASS,
    OAK,
    PORCELAIN,
    SCREEN,
    SPACE_GREY,
    TOYS,
    WALNUT,
    WHITE_LACQUER,
    WOODS,
    Rng,
    block,
    pick,
    uniform,
)
from asset_pipeline.procedural.parts import Part, Vec3
from asset_pipeline.procedural.registry import Design
from asset_pipeline.procedural.roles import tagged
from asset_pipeline.procedural.round_parts import Cylinder, Lathe

LID_AXIS = (0.0, -1.0, 0.0)
UP = (0.0, 0.0, 1.0)
ALONG_Y = (0.0, 1.0, 0.0)


def _lid_link(
    name: str, kind: str, pivot: Vec3, max_deg: float, grip: HandleDesign, density: float
) -> Link:
    joint = flap_hinge(pivot, max_deg, axis=LID_AXIS)
    return Link(name, kind, joint, grip, density=density)


def _upright_limit(length: float, thickness: float, room: float) -> float:
    """The largest opening angle (degrees, at most 95) at which a lid of ``length`` whose top
    lies ``thickness`` above its pivot reaches no more than ``room`` behind the pivot."""
    best = 80.0
    for tenth in range(800, 951):
        angle = math.radians(tenth / 10.0)
        if length * math.cos(angle) - thickness * math.sin(angle) >= -room:
            best = tenth / 10.0
    return best


@articulated(
    "toilet",
    "furniture",
    size=(0.68, 0.4, 0.8),
    low=(0.55, 0.35, 0.7),
    high=(0.8, 0.5, 0.9),
    mass=30.0,
    description="a white toilet with a {seat} seat and lid that lift",
    variants=(None, (0.62, 0.38, 0.75)),
)
def toilet(size: Vec3, rng: Rng) -> Design:
    """A toilet: pedestal and round bowl at +X, cistern at -X (its lid is a surface); the seat
    and the lid above it turn up about one axis at their back edge."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    seat_mat = pick(rng, (WHITE_LACQUER, PORCELAIN, OAK))
    t = 0.02  # seat and lid thickness
    r = min(hw, 0.5 * (d - 0.1 - 0.04))
    bx = hd - r
    cd = min(uniform(rng, 0.16, 0.22), d - 2.0 * r - 0.04)
    rim = uniform(rng, 0.36, 0.4)
    seat = (rim + 0.002, rim + 0.002 + t)
    lid = (seat[1] + 0.002, seat[1] + 0.002 + t)
    bowl = ((0.55 * r, 0.0), (0.6 * r, 0.4 * rim), (0.95 * r, rim))
    parts: list[Part] = tagged(
        "body",
        [
            Lathe((bx, 0.0, 0.0), bowl, PORCELAIN),
            block((-hd + 0.04, bx), (-0.4 * r, 0.4 * r), (0.0, rim), PORCELAIN),
        ],
    )
    parts += tagged("top", [block((-hd, -hd + cd), (-hw, hw), (rim, h), PORCELAIN, surface=True)])
    pivot_x = bx - r
    upright = _upright_limit(2.0 * r, lid[1] - seat[1], pivot_x - (-hd + cd) - 0.01)
    for name, kind, (z0, z1) in (("seat", "seat", seat), ("lid", "lid", lid)):
        disc = Cylinder((bx, 0.0, 0.5 * (z0 + z1)), r, 0.5 * t, seat_mat)
        grip = HandleDesign((hd - 0.01, 0.0, 0.5 * (z0 + z1)), UP, ALONG_Y, 0.1)
        # Both turn about the seat's top back edge, so that they nest when opened together,
        # and stop before the lid's far edge reaches the cistern.
        link = _lid_link(name, kind, (pivot_x, 0.0, seat[1]), upright, grip, 500.0)
        parts += tagged("seat", moving(link, [disc]))
    return Design(tuple(parts), {"seat": seat_mat.words})


@articulated(
    "laptop",
    "object",
    size=(0.24, 0.34, 0.022),
    low=(0.19, 0.26, 0.014),
    high=(0.3, 0.42, 0.035),
    mass=1.8,
    placement=("object",),
    description="a closed {finish} laptop whose lid opens",
    variants=(None,),
)
def laptop(size: Vec3, rng: Rng) -> Design:
    """A laptop, closed: a base with a keyboard and a lid with the screen on its underside,
    on a friction hinge at the back (0 to 130 degrees)."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, (ALUMINIUM, SPACE_GREY, BLACK_PLASTIC))
    gap = 0.0015
    base_t = 0.6 * (h - gap)
    parts: list[Part] = tagged("body", [block((-hd, hd), (-hw, hw), (0.0, base_t), finish)])
    keys = block(
        (-hd + 0.03, hd - 0.06),
        (-hw + 0.02, hw - 0.02),
        (base_t, base_t + 0.0005),
        BLACK_PLASTIC,
        collide=False,
    )
    parts.append(keys)
    z0 = base_t + gap
    shell = block((-hd, hd), (-hw, hw), (z0 + 0.001, h), finish)
    screen = block(
        (-hd + 0.008, hd - 0.008),
        (-hw + 0.008, hw - 0.008),
        (z0, z0 + 0.001),
        SCREEN,
        collide=False,
    )
    mass = 0.35 * 1.8
    grip = HandleDesign((hd - 0.005, 0.0, 0.5 * (z0 + h)), UP, ALONG_Y, 0.1)
    link = _lid_link("lid", "lid", (-hd, 0.0, h), 130.0, grip, mass / (d * w * (h - z0 - 0.001)))
    parts += tagged("top", moving(link, [shell, screen]))
    return Design(tuple(parts), {"finish": finish.words})


def _chest(
    size: Vec3, rng: Rng, body_choices: tuple, lid_density: float
) -> tuple[list[Part], dict]:
    """A box open at the top under a lid hinged at its back; a bar handle on the lid's front
    edge; the box floor is an interior surface."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    body = pick(rng, body_choices)
    metal = pick(rng, (*HANDLES, BRASS))
    wall = 0.018
    lid_t = 0.03
    front = hd - HANDLE_OUT
    top = h - lid_t - 0.003
    parts: list[Part] = tagged(
        "body",
        [
            block((-hd, front), (-hw, hw), (0.0, wall), body),
            block((-hd, front), (-hw, -hw + wall), (wall, top), body),
            block((-hd, front), (hw - wall, hw), (wall, top), body),
            block((-hd, -hd + wall), (-hw + wall, hw - wall), (wall, top), body),
            block((front - wall, front), (-hw + wall, hw - wall), (wall, top), body),
        ],
    )
    cavity = Cavity(-hd + wall, front - wall, -hw + wall, hw - wall, wall, top)
    bar_z = h - 0.5 * lid_t
    half = min(0.08, 0.2 * w)
    bar = block(
        (hd - HANDLE_BAR, hd),
        (-half, half),
        (bar_z - 0.5 * HANDLE_BAR, bar_z + 0.5 * HANDLE_BAR),
        metal,
    )
    posts = [
        block(
            (front, hd - HANDLE_BAR),
            (y - 0.5 * POST, y + 0.5 * POST),
            (bar_z - 0.5 * POST, bar_z + 0.5 * POST),
            metal,
        )
        for y in (-half + 0.5 * POST, half - 0.5 * POST)
    ]
    lid = block((-hd, front), (-hw, hw), (h - lid_t, h), body)
    grip = HandleDesign((hd - 0.5 * HANDLE_BAR, 0.0, bar_z), UP, ALONG_Y, 2 * half)
    link = _lid_link("lid", "lid", (-hd, 0.0, h), 90.0, grip, lid_density)
    parts += tagged("top", moving(link, [lid]))
    parts += tagged("handles", moving(link, [bar, *posts]))
    parts += floor_surface(cavity, body, (link.name,))
    return parts, {"body": body.words, "metal": metal.words}


@articulated(
    "trunk",
    "furniture",
    size=(0.5, 1.0, 0.5),
    low=(0.35, 0.6, 0.3),
    high=(0.7, 1.4, 0.7),
    mass=20.0,
    description="a {body} storage trunk with a lid that lifts and a {metal} handle",
    variants=(None, (0.45, 0.8, 0.45), (0.6, 1.2, 0.6)),
)
def trunk(size: Vec3, rng: Rng) -> Design:
    """A blanket chest with a lifting lid."""
    parts, words = _chest(size, rng, (*WOODS, WALNUT), 600.0)
    return Design(tuple(parts), words)


@articulated(
    "toy_box",
    "furniture",
    size=(0.45, 0.8, 0.5),
    low=(0.3, 0.5, 0.35),
    high=(0.6, 1.1, 0.65),
    mass=12.0,
    description="a {body} toy box with a lid that lifts",
    variants=(None, (0.4, 0.65, 0.45), (0.55, 1.0, 0.6)),
)
def toy_box(size: Vec3, rng: Rng) -> Design:
    """A painted toy chest with a lifting lid."""
    parts, words = _chest(size, rng, (*TOYS, SAGE_TOY, WHITE_LACQUER), 500.0)
    return Design(tuple(parts), words)
