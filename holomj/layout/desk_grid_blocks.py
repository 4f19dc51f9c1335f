"""A grid block laid out and placed: its slots, the stations assigned to them (the first seat's
station in the front row's middle), the desks and seats laid in the block and placed in the room
(:func:`world_placements`), the block's front wall (:func:`choose_front`), and the room's
problem with each block as one composite object (:func:`composite_problem`); the record of a
laid block (:func:`block_record`) and the free floor inside the blocks out of a robot's reach
(:func:`unreachable_inside`).

See :mod:`holomj.layout.desk_grid` for the whole method.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
from scipy import ndimage
from shapely.geometry import LineString, Point

from holomj.layout import geometry as geo
from holomj.layout.composite import HeaviestConstraints, composite_room
from holomj.layout.constraints import Constraint
from holomj.layout.desk_grid_groups import (
    SEAT_GAP_M,
    SEAT_SPACING_M,
    GridGroup,
    Piece,
    Station,
    seats_span,
)
from holomj.layout.desk_grid_shapes import JOIN_GAP_M, Shape
from holomj.layout.open_pockets import ReachMeter
from holomj.layout.room_problem import LayoutObject, PreparedRoom, RoomProblem
from holomj.layout.solve import Placement

BOARD_WIDTH_M = 1.2  # a board's width when the plan gives none
BOARD_MARGIN_M = 0.1  # kept between a board and a door or window on the front wall
# A pocket of free floor inside a block at most this big may stay out of reach: the nook
# beside an end seat at a wall, a robot's width, which the reach measure's wider passage
# robot does not enter.
NOOK_M2 = 0.1


GRID_WEIGHT = 5.0  # the block's own place constraints


# --------------------------------------------------------------------------- layout of a block


@dataclass(frozen=True)
class Slot:
    """One slot of a block: its row (0 at the front), column, and centre across the rows."""

    row: int
    column: int
    v: float


def block_slots(group: GridGroup, shape: Shape) -> list[Slot]:
    """The block's slots, row by row from the front, across each row in the block's frame."""
    w = shape.width(group)
    sw = group.slot_width
    out = []
    for row in range(shape.rows):
        for c in range(shape.columns):
            g = c // shape.pair
            left = -w / 2 + shape.side + c * sw + (c - g) * JOIN_GAP_M + g * shape.aisles.column
            out.append(Slot(row, c, left + sw / 2))
    return out


def assign_slots(
    group: GridGroup, shape: Shape, stations: Sequence[Station], board: bool
) -> list[tuple[Station, Slot]]:
    """Stations to slots: row by row from the front; with a ``board`` to face (and no
    ``in_row`` order to keep), the first station (that of the first seat) takes the front
    row's middle slot. The back row's spare slots stay at its ends."""
    slots = block_slots(group, shape)
    spare = shape.rows * shape.columns - len(stations)
    if spare:
        back = [s for s in slots if s.row == shape.rows - 1]
        keep = len(back) - spare
        lo = (len(back) - keep) // 2
        kept = set(range(lo, lo + keep))
        slots = [s for s in slots if s.row < shape.rows - 1 or s.column in kept]
    order = list(slots)
    if board and not group.in_row and len(order) > 1:
        front = [s for s in order if s.row == 0]
        middle = min(front, key=lambda s: (abs(s.v), s.v))
        order.remove(middle)
        order.insert(0, middle)
    return list(zip(stations, order))


def block_pieces(
    group: GridGroup, shape: Shape, pairs: Sequence[tuple[Station, Slot]]
) -> dict[str, tuple[float, float, bool]]:
    """Every piece in the block's own frame: ``(u, v, turned)`` with ``u`` from front to back
    (the users' backs), ``v`` across, and ``turned`` for seats that face the block's front
    (the user side's seats); desks and back seats face the back (their +X, where users sit)."""
    depth = shape.depth(group)
    front = shape.aisles.row if shape.symmetric else 0.0
    out: dict[str, tuple[float, float, bool]] = {}
    for station, slot in pairs:
        u0 = -depth / 2 + front + slot.row * (group.row_depth + shape.aisles.row)
        if group.back_depth:
            _place_seats(out, station.back, u0 + group.back_depth, slot.v, -1)
            u0 += group.back_depth + SEAT_GAP_M
        desk_end = u0 + group.desk_depth
        out[station.desk.id] = (desk_end - station.desk.depth / 2, slot.v, False)
        _place_seats(out, station.front, desk_end + SEAT_GAP_M, slot.v, 1)
    return out


def _place_seats(
    out: dict[str, tuple[float, float, bool]],
    seats: Sequence[Piece],
    edge: float,
    v: float,
    side: int,
) -> None:
    """Seats side by side centred on ``v``, their fronts at ``edge`` (facing the desk)."""
    at = v - seats_span(seats) / 2
    for seat in seats:
        u = edge + side * seat.depth / 2
        out[seat.id] = (u, at + seat.width / 2, side > 0)
        at += seat.width + SEAT_SPACING_M


def world_placements(
    group: GridGroup,
    local: Mapping[str, tuple[float, float, bool]],
    centre: tuple[float, float],
    k: int,
) -> dict[str, Placement]:
    """The block's pieces in the room, the block centred at ``centre`` with its back (the
    users' side) towards ``FRONT[k]``."""
    fx, fy = geo.FRONT[k]
    lx, ly = -fy, fx
    sizes = {p.id: p for s in group.stations for p in s.pieces}
    out = {}
    for pid, (u, v, turned) in local.items():
        piece = sizes[pid]
        out[pid] = Placement(
            x=round(centre[0] + u * fx + v * lx, 6),
            y=round(centre[1] + u * fy + v * ly, 6),
            yaw_deg=90.0 * ((k + 2) % 4 if turned else k),
            width=piece.width,
            depth=piece.depth,
        )
    return out


# --------------------------------------------------------------------------- the front wall


@dataclass(frozen=True)
class FrontChoice:
    """Where a solved block's users look: the yaw index of its desks, the wall they face and
    why it was chosen."""

    k: int
    wall: geo.WallSegment | None
    reason: str
    board_fits: bool


def _wall_ahead(
    walls: Sequence[geo.WallSegment], centre: tuple[float, float], look: tuple[int, int]
) -> geo.WallSegment | None:
    ray = LineString([centre, (centre[0] + look[0] * 100.0, centre[1] + look[1] * 100.0)])
    best: tuple[float, geo.WallSegment] | None = None
    for wall in walls:
        hit = ray.intersection(LineString([wall.a, wall.b]))
        if hit.is_empty:
            continue
        dist = Point(centre).distance(hit)
        if dist > 1e-6 and (best is None or dist < best[0]):
            best = (dist, wall)
    return None if best is None else best[1]


def _board_room(prep: PreparedRoom, wall: geo.WallSegment, width: float) -> bool:
    """Whether ``wall`` has a stretch free of doors and windows for a board ``width`` wide."""
    spans = [
        (o.a0 - BOARD_MARGIN_M, o.a1 + BOARD_MARGIN_M)
        for o in (*prep.anchors.doors, *prep.anchors.windows)
        if o.wall == wall
    ]
    at = 0.0
    for a0, a1 in sorted(spans):
        if a0 - at >= width - 1e-9:
            return True
        at = max(at, a1)
    return wall.length - at >= width - 1e-9


def choose_front(
    prep: PreparedRoom,
    centre: tuple[float, float],
    ks: Sequence[int],
    facing: str | None,
    board_width: float | None,
) -> FrontChoice:
    """The best of the yaw indices ``ks`` for a block's desks at ``centre``: the users look at
    the opening the prompt names (``facing``: "window" or "door"), else away from the doors,
    else at a wall with room for the board (``board_width``; None: no board)."""
    best: tuple[tuple[float, ...], FrontChoice] | None = None
    for k in ks:
        fx, fy = geo.FRONT[k]
        look = (-fx, -fy)
        wall = _wall_ahead(prep.walls, centre, look)
        openings = {
            "window": [o for o in prep.anchors.windows if o.wall == wall],
            "door": [o for o in prep.anchors.doors if o.wall == wall],
        }
        named = bool(facing and openings.get(facing))
        ahead = sum(
            1
            for o in prep.anchors.doors
            if (o.center[0] - centre[0]) * look[0] + (o.center[1] - centre[1]) * look[1] > 0.5
        )
        board = board_width is None or (wall is not None and _board_room(prep, wall, board_width))
        key = (0.0 if named or not facing else 1.0, float(ahead), 0.0 if board else 1.0)
        if named:
            reason = f"the prompt has the desks facing the {facing}"
        elif ahead == 0:
            reason = "the wall away from the door"
        else:
            reason = "the wall with room for the board" if board else "the solved block's side"
        choice = FrontChoice(k, wall, reason, board and board_width is not None)
        if best is None or key < best[0]:
            best = (key, choice)
    assert best is not None
    return best[1]


# --------------------------------------------------------------------------- solving


def block_record(
    group: GridGroup,
    shape: Shape,
    p: Placement,
    choice: FrontChoice,
    pairs: Sequence[tuple[Station, Slot]],
) -> dict[str, Any]:
    """The record of one laid block: its shape and aisles, its size, centre and facing, its
    front wall and why, and its desks row by row (``pairs``: each station with its slot)."""
    rows: list[list[str]] = [[] for _ in range(shape.rows)]
    for station, slot in sorted(pairs, key=lambda t: (t[1].row, t[1].column)):
        rows[slot.row].append(station.desk.id)
    return {
        "shape": shape.label(),
        "rows": shape.rows,
        "columns": shape.columns,
        "desks_side_by_side": shape.pair,
        "aisles": shape.aisles.name,
        "row_aisle_m": shape.aisles.row,
        "column_aisle_m": shape.aisles.column if shape.groups > 1 else None,
        "front_zone_m": shape.aisles.row if shape.symmetric else 0.0,
        "size_m": [round(shape.width(group), 3), round(shape.depth(group), 3)],
        "centre": [round(p.x, 3), round(p.y, 3)],
        "facing": [-geo.FRONT[choice.k][0], -geo.FRONT[choice.k][1]],
        "front_wall": (
            [[round(v, 3) for v in choice.wall.a], [round(v, 3) for v in choice.wall.b]]
            if choice.wall is not None
            else None
        ),
        "front_chosen_by": choice.reason,
        "rows_of_desks": rows,
    }


def unreachable_inside(
    prep: PreparedRoom, placements: Mapping[str, Placement], blocks: Sequence[Placement]
) -> float:
    """The free floor (m²) inside the blocks that no robot reaches from a door, not counting
    pockets up to :data:`NOOK_M2`."""
    # the grid's aisles are built to measure (at least 0.6 m) and its seats are smaller than
    # their footprints: a navigation map's cells do not close them, so footprints stay as they are
    meter = ReachMeter(prep, nav_cells=False)
    if not meter.applicable:
        return 0.0
    rects = [
        geo.footprint(p.x, p.y, geo.yaw_index(p.yaw_deg), p.width, p.depth)
        for p in placements.values()
    ]
    _, pocket = meter.pockets(rects)
    inside = np.zeros_like(pocket)
    for b in blocks:
        x0, y0, x1, y1 = geo.footprint(b.x, b.y, geo.yaw_index(b.yaw_deg), b.width, b.depth)
        inside |= (meter.xs >= x0) & (meter.xs <= x1) & (meter.ys >= y0) & (meter.ys <= y1)
    labels, count = ndimage.label(pocket, structure=np.ones((3, 3), dtype=bool))
    cell = meter.raster.cell**2
    out = 0.0
    for n in range(1, count + 1):
        component = labels == n
        if component.sum() * cell > NOOK_M2 + 1e-9:
            out += float((component & inside).sum()) * cell
    return out


# Kinds a block keeps from its members' constraints with other objects; place kinds a block
# keeps from its members. Directions (in front of, facing) mean other things for a block.
_KEPT_RELATIONS = frozenset({"near", "far", "adjacent_to", "center_aligned"})
_KEPT_PLACES = frozenset({"by_window", "by_door", "corner"})


def composite_problem(
    problem: RoomProblem,
    group: GridGroup,
    blocks: Sequence[tuple[str, Shape]],
    owner: Mapping[str, str],
) -> RoomProblem:
    """The problem with each block as one object (``owner``: member -> block), the members'
    constraints with other objects moved onto their block and the blocks' own constraints
    added (each ``middle``, one without a front zone ``facing door`` with its back, where the
    users sit; a second block ``near`` the first and facing the same way)."""
    objects: list[LayoutObject] = []
    ids = [b for b, _ in blocks]
    for obj in problem.objects:
        if obj.id not in owner:
            objects.append(obj)
    for block, shape in blocks:
        objects.append(
            LayoutObject(
                id=block,
                width=round(shape.width(group), 6),
                depth=round(shape.depth(group), 6),
                height=group.height,
                unit="m",
                priority=group.priority,
            )
        )
    kept = HeaviestConstraints()
    add = kept.add
    for c in problem.all_constraints().constraints:
        inside = c.object in owner
        target_inside = c.target in owner if c.target is not None else False
        if c.target is None:
            if not inside:
                add(c)
            elif c.kind in _KEPT_PLACES:
                add(c.model_copy(update={"object": owner[c.object]}))
            continue
        if inside and target_inside:
            continue  # between the block's own pieces: kept by the grid
        if (inside or target_inside) and c.kind not in _KEPT_RELATIONS:
            continue
        subject = owner.get(c.object, c.object)
        target = owner.get(c.target, c.target)
        if subject != target:
            add(c.model_copy(update={"object": subject, "target": target}))
    source = "desk grid"
    for block, shape in blocks:
        add(Constraint(object=block, kind="middle", weight=GRID_WEIGHT, source=source))
        if not shape.symmetric and problem.doors:
            # the users' backs to the door: the block's back (+X, where they sit) looks at it
            add(Constraint(object=block, kind="facing_door", weight=GRID_WEIGHT, source=source))
    for block in ids[1:]:
        add(Constraint(object=block, kind="near", target=ids[0], weight=GRID_WEIGHT, source=source))
        add(
            Constraint(
                object=block, kind="face_same_as", target=ids[0], weight=GRID_WEIGHT, source=source
            )
        )
    return composite_room(problem, objects, kept.all())
