"""Articulated case furniture: base and wall cabinets, drawer units, wardrobes, dressers,
nightstands and sideboards (front +X). Doors turn on hinges, drawers slide; shelves, cupboard
floors and drawer bottoms are interior surfaces; the top board is the outer surface."""

from __future__ import annotations

from dataclasses import dataclass

from asset_pipeline.procedural.articulated.kit import (
    FRONT_T,
    GAP,
    HANDLE_OUT,
    PANEL,
    PROUD,
    SEAM,
    Cavity,
    carcass,
    door_pair,
    drawer_stack,
    floor_surface,
    joint_names,
    shelf,
)
from asset_pipeline.procedural.articulated.links import Link
from asset_pipeline.procedural.articulated.registry import articulated
from asset_pipeline.procedural.home_kit import HANDLES
from asset_pipeline.procedural.kit import (
    BLACK_METAL,
    CASE_FINISHES,
    OAK,
    PAINTED,
    PINE,
    WOODS,
    Rng,
    block,
    chance,
    clamp,
    count_word,
    pick,
    square_legs,
    uniform,
)
from asset_pipeline.procedural.parts import Part, RecipeMaterial, Vec3
from asset_pipeline.procedural.registry import Design
from asset_pipeline.procedural.roles import tagged
from asset_pipeline.procedural.round_parts import Cylinder
from asset_pipeline.procedural.storage import WORKTOPS

LINER = PINE  # drawer boxes and cupboard liners
SHELF_MIN_DEPTH = 0.1  # a compartment shallower than this (front to back) gets no shelf


@dataclass
class Shell:
    """A cabinet's fixed parts and where its fronts go."""

    parts: list[Part]
    cavity: Cavity
    face: float  # x of the carcass face
    fronts_z: tuple[float, float]  # the fronts' bottom and top


def shell(
    size: Vec3,
    rng: Rng,
    body: RecipeMaterial,
    top: RecipeMaterial,
    top_t: float,
    base: str,
    *,
    overhang: float = 0.0,
) -> Shell:
    """An open-front carcass on a plinth, legs or nothing, under a top board (the outer
    surface) that covers the fronts (and overhangs them by ``overhang``, less than the
    handles stand out: the handles are the front of the asset)."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    if not 0.0 <= overhang < HANDLE_OUT:
        raise ValueError(f"a worktop overhang of {overhang} m must lie in [0, {HANDLE_OUT}) m")
    face = hd - PROUD
    base_h = {"none": 0.0, "plinth": uniform(rng, 0.06, 0.1), "legs": uniform(rng, 0.1, 0.16)}[base]
    parts: list[Part] = []
    if base == "plinth":
        parts += tagged("base", [block((-hd, face - 0.04), (-hw, hw), (0.0, base_h), body)])
    elif base == "legs":
        legs = square_legs(face + hd, w, base_h, 0.04, pick(rng, (BLACK_METAL, *WOODS)), 0.02)
        parts += tagged("legs", (leg.translated((0.5 * (face - hd), 0.0, 0.0)) for leg in legs))
    panels, cavity = carcass((-hd, face), (-hw, hw), (base_h, h - top_t), body, top=False)
    parts += tagged("body", panels)
    top_front = face + GAP + FRONT_T + overhang
    parts += tagged("top", [block((-hd, top_front), (-hw, hw), (h - top_t, h), top, surface=True)])
    return Shell(parts, cavity, face, (base_h + 0.003, h - top_t - 0.003))


def _rail(cavity: Cavity, z: float, material: RecipeMaterial) -> Part:
    """A horizontal carcass panel centred at ``z`` across a cavity."""
    return block(
        (cavity.x0, cavity.x1),
        (cavity.y0, cavity.y1),
        (z - 0.5 * PANEL, z + 0.5 * PANEL),
        material,
    )


def cupboard(
    sh: Shell,
    z: tuple[float, float],
    cavity: Cavity,
    doors: int,
    body: RecipeMaterial,
    front: RecipeMaterial,
    handle: RecipeMaterial,
    handle_z: float,
    rng: Rng,
    *,
    shelves: int | None = None,
    first: int = 0,
) -> tuple[list[Part], list[Link]]:
    """Doors across the front between heights ``z`` over the compartment ``cavity``, with its
    floor and shelves (interior surfaces behind the doors)."""
    y0 = cavity.y0 - PANEL + 0.002
    y1 = cavity.y1 + PANEL - 0.002
    parts, links = door_pair(
        "door", sh.face, (y0, y1), z, doors, front, handle, handle_z, rng, first=first
    )
    behind = joint_names(links)
    parts += floor_surface(cavity, LINER, behind)
    height = cavity.z1 - cavity.z0
    count = shelves if shelves is not None else max(0, int(height / 0.32) - 1)
    count = min(count, max(0, int(height / 0.16) - 1))
    if cavity.x1 - cavity.x0 < SHELF_MIN_DEPTH:  # a shallow wall cabinet: no room for one
        count = 0
    for k in range(count):
        parts += shelf(cavity, cavity.z0 + (k + 1) * height / (count + 1), body, behind)
    return parts, links


def _split(cavity: Cavity, z: float) -> tuple[Cavity, Cavity]:
    """The compartments below and above a rail centred at ``z``."""
    below = Cavity(cavity.x0, cavity.x1, cavity.y0, cavity.y1, cavity.z0, z - 0.5 * PANEL)
    above = Cavity(cavity.x0, cavity.x1, cavity.y0, cavity.y1, z + 0.5 * PANEL, cavity.z1)
    return below, above


def doors_under_drawers(
    sh: Shell,
    rng: Rng,
    body: RecipeMaterial,
    front: RecipeMaterial,
    handle: RecipeMaterial,
    doors: int,
    drawer_h: float | None,
    handle_z: float,
    *,
    drawer_columns: int | None = None,
) -> tuple[list[Part], list[Link]]:
    """Doors, with a row of drawers of height ``drawer_h`` over them (None: no drawers)."""
    z0, z1 = sh.fronts_z
    parts: list[Part] = []
    links: list[Link] = []
    cavity = sh.cavity
    if drawer_h is not None:
        seam = z1 - drawer_h
        parts.append(tagged("body", [_rail(cavity, seam, body)])[0])
        below, above = _split(cavity, seam)
        made, drawers = drawer_stack(
            "drawer",
            sh.face,
            above,
            (seam + 0.5 * SEAM, z1),
            1,
            drawer_columns or doors,
            body,
            front,
            LINER,
            handle,
        )
        parts += made
        links += drawers
        z1, cavity = seam - 0.5 * SEAM, below
    made, door_links = cupboard(sh, (z0, z1), cavity, doors, body, front, handle, handle_z, rng)
    return parts + made, links + door_links


# === categories ===============================================================================
@articulated(
    "base_cabinet",
    "furniture",
    size=(0.58, 0.6, 0.88),
    low=(0.35, 0.3, 0.5),
    high=(0.7, 1.2, 0.95),
    mass=28.0,
    description="a {body} base cabinet with {doors} hinged door{s}{drawers} and a {top} top",
    variants=(None, (0.45, 0.9, 0.8)),
)
def base_cabinet(size: Vec3, rng: Rng) -> Design:
    """A floor cabinet: one or two doors, maybe under a drawer row; a shelf inside."""
    body = pick(rng, (*PAINTED, OAK))
    top = pick(rng, WORKTOPS) if chance(rng, 0.5) else body
    doors = 1 if size[1] < 0.55 else 2
    drawer_h = uniform(rng, 0.13, 0.17) if chance(rng, 0.5) and size[2] > 0.65 else None
    sh = shell(size, rng, body, top, uniform(rng, 0.025, 0.04), "plinth")
    z1 = sh.fronts_z[1]
    made, _ = doors_under_drawers(
        sh, rng, body, body, pick(rng, HANDLES), doors, drawer_h, z1 - (drawer_h or 0.0) - 0.1
    )
    words = {
        "body": body.words,
        "doors": count_word(doors),
        "s": "s" if doors > 1 else "",
        "drawers": (" under a row of drawers" if doors > 1 else " under a drawer")
        if drawer_h
        else "",
        "top": top.words,
    }
    return Design(tuple(sh.parts + made), words)


def _wall_unit(size: Vec3, rng: Rng) -> tuple[list[Part], dict[str, str]]:
    body = pick(rng, (*PAINTED, OAK))
    doors = 1 if size[1] < 0.55 else 2
    sh = shell(size, rng, body, body, PANEL, "none")
    made, _ = cupboard(sh, sh.fronts_z, sh.cavity, doors, body, body, pick(rng, HANDLES), 0.1, rng)
    return sh.parts + made, {
        "body": body.words,
        "doors": count_word(doors),
        "s": "s" if doors > 1 else "",
    }


@articulated(
    "kitchen_cabinet",
    "furniture",
    size=(0.35, 0.8, 0.7),
    low=(0.25, 0.3, 0.3),
    high=(0.45, 1.5, 1.0),
    mass=18.0,
    placement=("wall",),
    description="a {body} kitchen wall unit with {doors} hinged door{s} and shelves inside",
    variants=(None, (0.33, 0.6, 0.9)),
)
def kitchen_cabinet(size: Vec3, rng: Rng) -> Design:
    """A kitchen wall unit (hangs on a wall; its bottom is z = 0): doors with handles low."""
    parts, words = _wall_unit(size, rng)
    return Design(tuple(parts), words)


@articulated(
    "wall_cabinet",
    "furniture",
    size=(0.2, 0.6, 0.7),
    low=(0.12, 0.3, 0.3),
    high=(0.45, 1.5, 1.2),
    mass=10.0,
    placement=("wall",),
    description="a {body} wall cabinet with {doors} hinged door{s}",
    variants=(None, (0.3, 1.0, 0.5)),
)
def wall_cabinet(size: Vec3, rng: Rng) -> Design:
    """A wall-mounted cabinet (bathroom, hall, utility room)."""
    parts, words = _wall_unit(size, rng)
    return Design(tuple(parts), words)


@articulated(
    "drawer_unit",
    "furniture",
    size=(0.58, 0.5, 0.88),
    low=(0.4, 0.3, 0.5),
    high=(0.7, 1.0, 1.0),
    mass=30.0,
    description="a {body} drawer unit with {count} drawers",
    variants=(None, (0.5, 0.4, 0.7)),
)
def drawer_unit(size: Vec3, rng: Rng) -> Design:
    """A column of three or four drawers on a plinth (a kitchen drawer base, a pedestal)."""
    body = pick(rng, (*PAINTED, OAK))
    rows = int(clamp(int(rng.integers(3, 5)), 2, int((size[2] - 0.15) / 0.14)))
    sh = shell(size, rng, body, body, uniform(rng, 0.02, 0.03), "plinth")
    made, _ = drawer_stack(
        "drawer", sh.face, sh.cavity, sh.fronts_z, rows, 1, body, body, LINER, pick(rng, HANDLES)
    )
    return Design(tuple(sh.parts + made), {"body": body.words, "count": count_word(rows)})


@articulated(
    "wardrobe",
    "furniture",
    size=(0.6, 1.2, 2.0),
    low=(0.45, 0.5, 1.5),
    high=(0.7, 2.4, 2.4),
    mass=80.0,
    description="a tall {body} wardrobe with {doors} hinged door{s}{drawers}",
    variants=(None, (0.58, 1.8, 2.1)),
)
def wardrobe(size: Vec3, rng: Rng) -> Design:
    """Doors (one per 0.5-0.7 m) over a hanging space with a hat shelf, maybe over a row of
    drawers."""
    body = pick(rng, CASE_FINISHES)
    w = size[1]
    doors = 1 if w < 0.7 else (2 if w < 1.4 else (3 if w < 2.0 else 4))  # as the rigid one
    drawers = chance(rng, 0.4)
    sh = shell(size, rng, body, body, 0.025, pick(rng, ("plinth", "none")))
    handle = pick(rng, HANDLES)
    z0, z1 = sh.fronts_z
    parts: list[Part] = []
    cavity = sh.cavity
    if drawers:
        seam = z0 + uniform(rng, 0.2, 0.25)
        below, cavity = _split(cavity, seam)
        parts += tagged("body", [_rail(sh.cavity, seam, body)])
        made, _ = drawer_stack(
            "drawer", sh.face, below, (z0, seam - 0.5 * SEAM), 1, doors, body, body, LINER, handle
        )
        parts += made
        z0 = seam + 0.5 * SEAM
    made, links = door_pair(
        "door",
        sh.face,
        (cavity.y0 - PANEL + 0.002, cavity.y1 + PANEL - 0.002),
        (z0, z1),
        doors,
        body,
        handle,
        1.05,
        rng,
    )
    parts += made
    behind = joint_names(links)
    parts += floor_surface(cavity, LINER, behind)
    hat = cavity.z1 - uniform(rng, 0.3, 0.38)
    parts += shelf(cavity, hat, body, behind)
    rail_z = hat - PANEL - 0.08
    rail = Cylinder(
        (0.5 * (cavity.x0 + cavity.x1), 0.0, rail_z),
        0.012,
        0.5 * (cavity.y1 - cavity.y0),
        pick(rng, (BLACK_METAL, *WOODS)),
        axis="y",
    )
    parts += tagged("frame", [rail])
    words = {
        "body": body.words,
        "doors": count_word(doors),
        "s": "s" if doors > 1 else "",
        "drawers": " above drawers" if drawers else "",
    }
    return Design(tuple(sh.parts + parts), words)


@articulated(
    "dresser",
    "furniture",
    size=(0.5, 1.2, 0.85),
    low=(0.35, 0.5, 0.6),
    high=(0.65, 2.0, 1.3),
    mass=50.0,
    description="a {body} chest of {count} sliding drawers with {handle} handles",
    variants=(None, (0.45, 0.8, 1.1)),
)
def dresser(size: Vec3, rng: Rng) -> Design:
    """A chest of drawers in one or two columns; the top is a surface."""
    _, w, h = size
    rows = int(clamp(int(rng.integers(3, 6)), 2, max(2, int((h - 0.15) / 0.14))))
    cols = 1 if w < 0.8 else 2
    body = pick(rng, CASE_FINISHES)
    top = body if chance(rng, 0.6) else pick(rng, WOODS)
    handle = pick(rng, HANDLES)
    sh = shell(size, rng, body, top, uniform(rng, 0.02, 0.035), pick(rng, ("plinth", "legs")))
    made, _ = drawer_stack(
        "drawer",
        sh.face,
        sh.cavity,
        sh.fronts_z,
        rows,
        cols,
        body,
        body,
        LINER,
        handle,
        knob=chance(rng, 0.3),
    )
    words = {"body": body.words, "count": count_word(rows * cols), "handle": handle.words}
    return Design(tuple(sh.parts + made), words)


@articulated(
    "nightstand",
    "furniture",
    size=(0.4, 0.45, 0.55),
    low=(0.3, 0.3, 0.4),
    high=(0.55, 0.65, 0.75),
    mass=12.0,
    description="a {body} nightstand with {count} sliding drawer{s} and a {top} top",
    variants=(None, (0.38, 0.5, 0.6)),
)
def nightstand(size: Vec3, rng: Rng) -> Design:
    """A bedside cabinet with one to three drawers; the top is a surface."""
    rows = int(clamp(int(rng.integers(1, 4)), 1, int((size[2] - 0.12) / 0.12)))
    body = pick(rng, CASE_FINISHES)
    top = body if chance(rng, 0.5) else pick(rng, WOODS)
    sh = shell(size, rng, body, top, uniform(rng, 0.02, 0.03), pick(rng, ("plinth", "legs")))
    made, _ = drawer_stack(
        "drawer", sh.face, sh.cavity, sh.fronts_z, rows, 1, body, body, LINER, pick(rng, HANDLES)
    )
    words = {
        "body": body.words,
        "count": count_word(rows),
        "s": "s" if rows > 1 else "",
        "top": top.words,
    }
    return Design(tuple(sh.parts + made), words)


@articulated(
    "sideboard",
    "furniture",
    size=(0.45, 1.6, 0.85),
    low=(0.35, 0.9, 0.65),
    high=(0.6, 2.4, 1.0),
    mass=55.0,
    description="a long low {body} sideboard with {doors} hinged doors{drawers} and a {top} top",
    variants=(None, (0.42, 1.2, 0.8), (0.5, 2.0, 0.9)),
)
def sideboard(size: Vec3, rng: Rng) -> Design:
    """A row of doors opening in pairs, maybe under a row of drawers; a shelf inside."""
    doors = 2 if size[1] < 1.4 else 4
    body = pick(rng, CASE_FINISHES)
    top = body if chance(rng, 0.6) else pick(rng, WOODS)
    drawer_h = uniform(rng, 0.12, 0.16) if chance(rng, 0.5) else None
    sh = shell(size, rng, body, top, uniform(rng, 0.025, 0.04), pick(rng, ("legs", "plinth")))
    z1 = sh.fronts_z[1]
    made, _ = doors_under_drawers(
        sh, rng, body, body, pick(rng, HANDLES), doors, drawer_h, z1 - (drawer_h or 0.0) - 0.1
    )
    words = {
        "body": body.words,
        "doors": count_word(doors),
        "drawers": " under a row of drawers" if drawer_h else "",
        "top": top.words,
    }
    return Design(tuple(sh.parts + made), words)
