"""Articulated appliances: fridges, ovens and cookers, dishwashers, microwaves and washing
machines (front +X). Side-hinged doors, drop-down doors on counterbalance springs, sliding
racks; shelves, oven racks, rack bottoms and drum floors are interior surfaces."""

from __future__ import annotations

from asset_pipeline.procedural.appliances import APPLIANCE_FINISHES, BLACK_APPLIANCE, OVEN_GLASS
from asset_pipeline.procedural.articulated.kit import (
    GAP,
    HANDLE_OUT,
    PANEL,
    SEAM,
    Cavity,
    carcass,
    door,
    floor_surface,
    handle,
)
from asset_pipeline.procedural.articulated.links import (
    HandleDesign,
    Link,
    drawer_slide,
    flap_hinge,
    inside,
    moving,
    side_hinge,
)
from asset_pipeline.procedural.articulated.registry import articulated
from asset_pipeline.procedural.kit import (
    BLACK_METAL,
    CHROME,
    CLEAR_GLASS,
    STEEL,
    WHITE_LACQUER,
    Rng,
    block,
    chance,
    clamp,
    pick,
    uniform,
)
from asset_pipeline.procedural.parts import Part, RecipeMaterial, Vec3
from asset_pipeline.procedural.registry import Design
from asset_pipeline.procedural.roles import tagged
from asset_pipeline.procedural.round_parts import Cylinder

WIRE = STEEL  # oven and dishwasher racks
APPLIANCE_DOOR_DENSITY = 250.0  # kg/m^3 of door volume: insulated sheet-metal doors
RACK_DENSITY = 400.0


def _shelves(
    cavity: Cavity, count: int, material: RecipeMaterial, behind: tuple[str, ...]
) -> list[Part]:
    """``count`` thin shelves evenly up a compartment (interior surfaces)."""
    parts: list[Part] = []
    height = cavity.z1 - cavity.z0
    for k in range(count):
        z = cavity.z0 + (k + 1) * height / (count + 1)
        board = block(
            (cavity.x0, cavity.x1 - 0.03),
            (cavity.y0, cavity.y1),
            (z - 0.006, z),
            material,
            surface=True,
        )
        parts += tagged("shelves", inside(behind, [board]))
    return parts


@articulated(
    "fridge",
    "furniture",
    size=(0.7, 0.7, 1.8),
    low=(0.55, 0.5, 0.8),
    high=(0.85, 1.0, 2.1),
    mass=70.0,
    friction=0.5,
    description="a {finish} {layout} with hinged doors, {metal} handles and shelves inside",
    variants=(None, (0.75, 0.9, 1.8)),
)
def fridge(size: Vec3, rng: Rng) -> Design:
    """A fridge: an insulated carcass open at the front, one door (under-counter), a fridge
    door over a freezer door, or two side by side; glass shelves inside."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, APPLIANCE_FINISHES)
    metal = pick(rng, (CHROME, BLACK_METAL, STEEL))
    door_t = 0.05
    face = hd - HANDLE_OUT - door_t - GAP
    panels, cavity = carcass((-hd, face), (-hw, hw), (0.0, h - PANEL), finish, top=False)
    parts: list[Part] = tagged("body", panels)
    parts += tagged("top", [block((-hd, face), (-hw, hw), (h - PANEL, h), finish, surface=True)])
    fy = (-hw + 0.002, hw - 0.002)
    fz = (0.02, h - 0.003)

    def one_door(
        name: str, y: tuple[float, float], z: tuple[float, float], side: str, handle_z: float
    ) -> tuple[list[Part], Link]:
        return door(
            name,
            face,
            y,
            z,
            side,
            finish,
            metal,
            handle_z,
            thickness=door_t,
            density=APPLIANCE_DOOR_DENSITY,
            handle_length=min(0.3, 0.4 * (z[1] - z[0])),
        )

    side = "-y" if chance(rng, 0.5) else "+y"
    if h < 1.0:
        layout = "under-counter fridge"
        made, link = one_door("door_0", fy, fz, side, fz[1] - 0.12)
        parts += made + _shelves(cavity, 1, CLEAR_GLASS, (link.name,))
        parts += floor_surface(cavity, finish, (link.name,))
    elif w >= 0.85 and chance(rng, 0.6):
        layout = "side-by-side fridge-freezer"
        split = 0.0
        parts += tagged(
            "body",
            [
                block(
                    (cavity.x0, face),
                    (split - 0.5 * PANEL, split + 0.5 * PANEL),
                    (cavity.z0, cavity.z1),
                    finish,
                )
            ],
        )
        left = Cavity(cavity.x0, cavity.x1, cavity.y0, split - 0.5 * PANEL, cavity.z0, cavity.z1)
        right = Cavity(cavity.x0, cavity.x1, split + 0.5 * PANEL, cavity.y1, cavity.z0, cavity.z1)
        for k, (y, hinge, room) in enumerate(
            (((fy[0], -0.5 * SEAM), "-y", left), ((0.5 * SEAM, fy[1]), "+y", right))
        ):
            made, link = one_door(f"door_{k}", y, fz, hinge, 1.1)
            parts += made + _shelves(room, 3, CLEAR_GLASS, (link.name,))
            parts += floor_surface(room, finish, (link.name,))
    else:
        layout = "fridge-freezer"
        split = uniform(rng, 0.3, 0.38) * h
        parts += tagged(
            "body",
            [
                block(
                    (cavity.x0, face),
                    (cavity.y0, cavity.y1),
                    (split - 0.5 * PANEL, split + 0.5 * PANEL),
                    finish,
                )
            ],
        )
        below = Cavity(cavity.x0, cavity.x1, cavity.y0, cavity.y1, cavity.z0, split - 0.5 * PANEL)
        above = Cavity(cavity.x0, cavity.x1, cavity.y0, cavity.y1, split + 0.5 * PANEL, cavity.z1)
        made, freezer = one_door("door_0", fy, (fz[0], split - 0.5 * SEAM), side, split - 0.15)
        parts += made + floor_surface(below, finish, (freezer.name,))
        parts += _shelves(below, 1, CLEAR_GLASS, (freezer.name,))
        made, main = one_door("door_1", fy, (split + 0.5 * SEAM, fz[1]), side, 1.1)
        parts += made + floor_surface(above, finish, (main.name,))
        levels = int(clamp((above.z1 - above.z0) / 0.3 - 1, 1, 4))
        parts += _shelves(above, levels, CLEAR_GLASS, (main.name,))
    words = {"finish": finish.words, "layout": layout, "metal": metal.words}
    return Design(tuple(parts), words)


def _drop_door(
    name: str,
    x_face: float,
    y: tuple[float, float],
    z: tuple[float, float],
    thickness: float,
    finish: RecipeMaterial,
    metal: RecipeMaterial,
    window: bool,
) -> tuple[list[Part], Link]:
    """A door hinged at its bottom edge that drops open forwards to 90 degrees, held at any
    angle by its counterbalance spring and friction; a horizontal handle near its top."""
    (y0, y1), (z0, z1) = y, z
    xb = x_face + GAP
    xf = xb + thickness
    hy = 0.5 * (y0 + y1)
    grip_parts, grip = handle(xf, hy, z1 - 0.05, min(0.45, 0.7 * (y1 - y0)), False, metal)
    joint = flap_hinge((xf, hy, z0), 90.0, axis=(0.0, 1.0, 0.0))
    link = Link(name, "door", joint, grip, density=APPLIANCE_DOOR_DENSITY)
    parts = tagged("doors", moving(link, [block((xb, xf), (y0, y1), (z0, z1), finish)]))
    if window:
        glass = block(
            (xf, xf + 0.002),
            (y0 + 0.08, y1 - 0.08),
            (z0 + 0.08, z1 - 0.12),
            OVEN_GLASS,
            collide=False,
        )
        parts += moving(link, [glass])
    parts += tagged("handles", moving(link, grip_parts))
    return parts, link


def _oven_box(
    x: tuple[float, float],
    y: tuple[float, float],
    z: tuple[float, float],
    rng: Rng,
    finish: RecipeMaterial,
    metal: RecipeMaterial,
) -> tuple[list[Part], Link]:
    """An oven: a carcass open at the front between ``z``, a drop-down glass door and one
    wire rack (the oven floor and the rack are interior surfaces)."""
    (x0, face), (y0, y1), (z0, z1) = x, y, z
    panels, cavity = carcass((x0, face), (y0, y1), (z0, z1), finish)
    parts: list[Part] = tagged("body", panels)
    made, link = _drop_door(
        "door_0",
        face,
        (y0 + 0.002, y1 - 0.002),
        (z0 + 0.003, z1 - 0.003),
        0.03,
        finish,
        metal,
        window=True,
    )
    parts += made + floor_surface(cavity, BLACK_APPLIANCE, (link.name,))
    rack_z = cavity.z0 + uniform(rng, 0.45, 0.55) * (cavity.z1 - cavity.z0)
    rack = block(
        (cavity.x0, cavity.x1 - 0.03),
        (cavity.y0, cavity.y1),
        (rack_z - 0.008, rack_z),
        WIRE,
        surface=True,
    )
    parts += tagged("shelves", inside((link.name,), [rack]))
    return parts, link


@articulated(
    "oven",
    "furniture",
    size=(0.58, 0.6, 0.6),
    low=(0.5, 0.45, 0.45),
    high=(0.7, 0.9, 0.9),
    mass=35.0,
    description="a {finish} oven with a drop-down glass door and a wire rack",
    variants=(None, (0.55, 0.6, 0.72)),
)
def oven(size: Vec3, rng: Rng) -> Design:
    """A stand-alone or built-in oven: a control strip over a drop-down door."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, APPLIANCE_FINISHES)
    metal = pick(rng, (CHROME, STEEL, BLACK_METAL))
    face = hd - HANDLE_OUT - 0.03 - GAP
    strip = uniform(rng, 0.08, 0.11)
    kick = 0.05  # the open door's handle hangs below its hinge
    parts: list[Part] = tagged("base", [block((-hd, face), (-hw, hw), (0.0, kick), finish)])
    made, _ = _oven_box((-hd, face), (-hw, hw), (kick, h - strip), rng, finish, metal)
    parts += made
    x_front = face + GAP + 0.03
    parts += tagged(
        "body", [block((-hd, x_front), (-hw, hw), (h - strip + 0.001, h), BLACK_APPLIANCE)]
    )
    return Design(tuple(parts), {"finish": finish.words})


@articulated(
    "stove",
    "furniture",
    size=(0.65, 0.6, 0.95),
    low=(0.55, 0.5, 0.85),
    high=(0.75, 0.9, 1.1),
    mass=55.0,
    description="a {finish} freestanding cooker with {burners} burners over an oven with a "
    "drop-down door",
    variants=(None, (0.62, 0.9, 0.92)),
)
def stove(size: Vec3, rng: Rng) -> Design:
    """A cooker: burners on a hob (each a surface), knobs on a control strip, an oven with a
    drop-down door below on a kick plinth."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, APPLIANCE_FINISHES)
    metal = pick(rng, (CHROME, STEEL, BLACK_METAL))
    burner_h = 0.012
    top_z = h - burner_h
    face = hd - HANDLE_OUT - 0.03 - GAP
    x_front = face + GAP + 0.03
    kick = uniform(rng, 0.06, 0.09)
    strip = 0.1
    parts: list[Part] = tagged("base", [block((-hd, face), (-hw, hw), (0.0, kick), finish)])
    made, _ = _oven_box((-hd, face), (-hw, hw), (kick, top_z - 0.02 - strip), rng, finish, metal)
    parts += made
    parts += tagged(
        "body",
        [
            block((-hd, x_front), (-hw, hw), (top_z - 0.02 - strip + 0.001, top_z - 0.02), finish),
            block((-hd, x_front), (-hw, hw), (top_z - 0.02, top_z), BLACK_APPLIANCE),
        ],
    )
    cols = 3 if w >= 0.85 else 2
    cell_x = (x_front + hd) / 2
    cell_y = w / cols
    radius = clamp((min(0.5 * cell_x, 0.5 * cell_y) - 0.02) * uniform(rng, 0.8, 1.0), 0.05, 0.11)
    for i in range(2):
        for j in range(cols):
            x, y = -hd + (i + 0.5) * cell_x, -hw + (j + 0.5) * cell_y
            parts.append(
                Cylinder(
                    (x, y, top_z + 0.5 * burner_h),
                    radius,
                    0.5 * burner_h,
                    BLACK_METAL,
                    surface=True,
                )
            )
    knobs = 2 * cols
    for k in range(knobs):
        y = -hw + (k + 0.5) * w / knobs
        parts.append(
            Cylinder(
                (x_front + 0.01, y, top_z - 0.02 - 0.5 * strip), 0.018, 0.01, BLACK_METAL, axis="x"
            )
        )
    return Design(tuple(parts), {"finish": finish.words, "burners": str(2 * cols)})


def _rack(
    name: str, cavity: Cavity, z: float, height: float, x_stop: float
) -> tuple[list[Part], Link]:
    """A dishwasher rack: a wire tray on rollers sliding out along +X; its front rail is the
    handle, its bottom an interior surface."""
    x0, x1 = cavity.x0 + 0.01, x_stop
    y0, y1 = cavity.y0 + 0.01, cavity.y1 - 0.01
    t = 0.006
    grip = HandleDesign(
        (x1 - 0.5 * t, 0.5 * (y0 + y1), z + height - 0.01), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), 0.2
    )
    link = Link(
        name,
        "rack",
        drawer_slide((x1, 0.5 * (y0 + y1), z), 0.9 * (x1 - x0)),
        grip,
        density=RACK_DENSITY,
    )
    bottom = block((x0, x1), (y0, y1), (z, z + t), WIRE, surface=True)
    walls = [
        block((x0, x1), (y0, y0 + t), (z + t, z + height), WIRE),
        block((x0, x1), (y1 - t, y1), (z + t, z + height), WIRE),
        block((x0, x0 + t), (y0 + t, y1 - t), (z + t, z + height), WIRE),
        block((x1 - t, x1), (y0 + t, y1 - t), (z + t, z + height), WIRE),
    ]
    parts = tagged("shelves", moving(link, walls))
    parts += tagged("shelves", moving(link, inside(("door_0", name), [bottom])))
    return parts, link


@articulated(
    "dishwasher",
    "furniture",
    size=(0.6, 0.6, 0.85),
    low=(0.55, 0.45, 0.8),
    high=(0.7, 0.65, 0.9),
    mass=45.0,
    description="a {finish} dishwasher with a drop-down door and two sliding racks",
    variants=(None, (0.58, 0.45, 0.82), (0.62, 0.6, 0.88)),
)
def dishwasher(size: Vec3, rng: Rng) -> Design:
    """A dishwasher: a tub open at the front on a kick plinth, a full-height drop-down door
    and two racks that slide out over the open door."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, APPLIANCE_FINISHES)
    metal = pick(rng, (CHROME, STEEL, BLACK_METAL))
    door_t = 0.04
    face = hd - HANDLE_OUT - door_t - GAP
    kick = uniform(rng, 0.08, 0.11)
    parts: list[Part] = tagged("base", [block((-hd, face - 0.03), (-hw, hw), (0.0, kick), finish)])
    panels, cavity = carcass((-hd, face), (-hw, hw), (kick, h), finish)
    parts += tagged("body", panels)
    made, door_link = _drop_door(
        "door_0",
        face,
        (-hw + 0.002, hw - 0.002),
        (kick + 0.003, h - 0.003),
        door_t,
        finish,
        metal,
        window=False,
    )
    parts += made
    # Racks ride above the open door (its top face lies at the pivot height + door_t).
    low_z = max(cavity.z0 + 0.02, kick + 0.003 + door_t + 0.015)
    inner = cavity.z1 - low_z
    made, _ = _rack("rack_0", cavity, low_z, 0.1, face - 0.008)
    parts += made
    made, _ = _rack("rack_1", cavity, low_z + 0.5 * inner, 0.08, face - 0.008)
    parts += made
    return Design(tuple(parts), {"finish": finish.words, "door": door_link.name})


@articulated(
    "microwave",
    "object",
    size=(0.38, 0.5, 0.3),
    low=(0.28, 0.38, 0.2),
    high=(0.5, 0.7, 0.42),
    mass=12.0,
    placement=("object",),
    description="a {finish} microwave with a side-hinged door",
    variants=(None, (0.34, 0.45, 0.26)),
)
def microwave(size: Vec3, rng: Rng) -> Design:
    """A microwave: a cavity on the left behind a door hinged on its left edge, a control
    panel on the right; the cavity floor is an interior surface, the top an outer one."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, (WHITE_LACQUER, STEEL, BLACK_APPLIANCE))
    metal = pick(rng, (CHROME, BLACK_METAL))
    door_t = 0.025
    face = hd - HANDLE_OUT - door_t - GAP
    panel_w = clamp(0.22 * w, 0.08, 0.14)
    panels, cavity = carcass((-hd, face), (-hw, hw), (0.0, h - PANEL), finish, top=False)
    parts: list[Part] = tagged("body", panels)
    parts += tagged(
        "top", [block((-hd, face + GAP + door_t), (-hw, hw), (h - PANEL, h), finish, surface=True)]
    )
    y_div = hw - panel_w
    parts += tagged(
        "body",
        [
            block((cavity.x0, face), (y_div, cavity.y1), (cavity.z0, cavity.z1), finish),
            block(
                (face + GAP, face + GAP + door_t),
                (y_div + 0.5 * SEAM, hw - 0.002),
                (0.003, h - PANEL - 0.003),
                BLACK_APPLIANCE,
            ),
        ],
    )
    room = Cavity(cavity.x0, cavity.x1, cavity.y0, y_div, cavity.z0, cavity.z1)
    made, link = door(
        "door_0",
        face,
        (-hw + 0.002, y_div - 0.5 * SEAM),
        (0.003, h - PANEL - 0.003),
        "-y",
        finish,
        metal,
        0.5 * h,
        thickness=door_t,
        density=APPLIANCE_DOOR_DENSITY,
    )
    parts += made
    x_front = face + GAP + door_t
    glass = block(
        (x_front, x_front + 0.002),
        (-hw + 0.04, y_div - 0.08),
        (0.04, h - PANEL - 0.04),
        OVEN_GLASS,
        collide=False,
    )
    parts += moving(link, [glass])
    parts += floor_surface(room, finish, (link.name,))
    return Design(tuple(parts), {"finish": finish.words})


@articulated(
    "washing_machine",
    "furniture",
    size=(0.6, 0.6, 0.85),
    low=(0.5, 0.5, 0.8),
    high=(0.7, 0.7, 0.9),
    mass=70.0,
    description="a {finish} front-loading washing machine with a round door",
    variants=(None, (0.55, 0.6, 0.85), (0.65, 0.6, 0.88)),
)
def washing_machine(size: Vec3, rng: Rng) -> Design:
    """A front loader: a cabinet whose front panel has a porthole, a round door hinged on its
    left edge, a control strip; the drum floor is an interior surface, the top an outer one."""
    d, w, h = size
    hd, hw = 0.5 * d, 0.5 * w
    finish = pick(rng, (WHITE_LACQUER, STEEL, BLACK_APPLIANCE))
    metal = pick(rng, (CHROME, BLACK_METAL))
    door_t = 0.04
    face = hd - HANDLE_OUT - door_t - GAP
    radius = clamp(0.36 * w, 0.17, 0.24)
    cz = clamp(0.45 * h, radius + 0.06, h - 0.2 - radius)
    hole = 0.75 * radius
    panels, cavity = carcass((-hd, face - PANEL), (-hw, hw), (0.0, h - PANEL), finish, top=False)
    parts: list[Part] = tagged("body", panels)
    parts += tagged("top", [block((-hd, face), (-hw, hw), (h - PANEL, h), finish, surface=True)])
    xf = (face - PANEL, face)  # the front panel, around a square porthole
    parts += tagged(
        "body",
        [
            block(xf, (-hw, hw), (0.0, cz - hole), finish),
            block(xf, (-hw, hw), (cz + hole, h - PANEL), finish),
            block(xf, (-hw, -hole), (cz - hole, cz + hole), finish),
            block(xf, (hole, hw), (cz - hole, cz + hole), finish),
        ],
    )
    knob_z = h - PANEL - 0.06
    parts.append(Cylinder((face + 0.012, hw - 0.1, knob_z), 0.03, 0.012, metal, axis="x"))
    xb = face + GAP
    xd = xb + door_t
    hinge_y = -radius
    grip_parts, grip = handle(xd, radius - 0.05, cz, 0.08, True, metal)
    joint = side_hinge(hinge_y, radius, xd, cz, 120.0)
    link = Link("door_0", "door", joint, grip, density=APPLIANCE_DOOR_DENSITY)
    ring = Cylinder((0.5 * (xb + xd), 0.0, cz), radius, 0.5 * door_t, finish, axis="x")
    glass = Cylinder(
        (xd + 0.001, 0.0, cz), 0.7 * radius, 0.001, CLEAR_GLASS, axis="x", collide=False
    )
    parts += tagged("doors", moving(link, [ring, glass]))
    parts += tagged("handles", moving(link, grip_parts))
    drum = Cavity(cavity.x0, face - PANEL, cavity.y0, cavity.y1, cavity.z0, cavity.z1)
    parts += floor_surface(drum, BLACK_APPLIANCE, (link.name,))
    return Design(tuple(parts), {"finish": finish.words})
