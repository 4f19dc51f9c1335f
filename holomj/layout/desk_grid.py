"""Classrooms, computer labs, open offices and lab rooms: many identical desks and their seats
laid out in rows facing one front wall, with aisles between the rows, instead of a jumble that
cuts the floor into pockets.

A room's *grid group* is a floor kind (instances ``student desk-0`` ... ``student desk-15``) of
a work surface used from one side (:data:`GRID_CATEGORIES`: desks, lab benches, drafting
tables, workbenches...; a table of :data:`TABLE_CATEGORIES` only when its name says it is a work
or canteen table, and then it is used from both sides) with at least :data:`MIN_INSTANCES`
instances, or two when the plan asks for rows (:attr:`holomj.spec.plan.PlanObject.rows`, its
``in_row`` relation). Its *seats* are the chairs and stools whose constraints point at exactly
one of its desks (``school chair-3 | near, student desk-3 | face to, student desk-3``): each desk
and its seats make a *station*. A desk's +X front is where its user sits, so a station puts its
seats side by side at the desk's front, :data:`SEAT_GAP_M` away and facing it.

How it is solved (the composite approach of :mod:`holomj.layout.counter_runs`): the stations
are laid out as a *block*, a grid of ``rows x columns`` slots, each row's desks side by side
(in pairs, or one by one, with a column aisle between pairs), all facing the front; behind
every row of seats there is a row aisle, and in front of the first row a front zone as deep as
the aisle behind the last row (the block is then symmetric front to back, so that the front
can be chosen after the solve). The block becomes one :class:`LayoutObject`, the room's solver
places it with the other furniture (softly in the ``middle`` of the room), then it is split
back into desks and seats and the layout is checked against every hard rule with their own
footprints, and the free floor inside the block must all be reachable from the doors. The front
wall is the side of the solved block that the plan's relations name (desks facing the window or the
door), else the one away from the room's doors, else the one with a free stretch for the
board; the station of the first seat takes the front row's middle, so that a whiteboard, a TV
or a projector screen hung where that seat looks (:func:`front_lookers`) hangs on the front
wall.

Shapes are tried from the roomiest: aisles of :data:`STANDARD` widths (0.9 m behind each seat
row, 0.6 m between column pairs), then :data:`COMPACT` ones (still wider than a robot), rows
and columns chosen to fit the room's free floor (a raster test before any solve), then the
stations in two blocks, and finally independent placement (the plan's constraints as they
are): no desk or seat is ever dropped for the sake of a grid. The record
(:func:`solve_desk_grid`) says which group, the rows and columns, the aisles, the front wall,
every shape tried and the fallback with its reason.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
from scipy import ndimage
from shapely.geometry import LineString, Point

from holomj.layout import geometry as geo
from holomj.layout.constraints import Constraint, normalize_name
from holomj.layout.counter_runs import check_split, split_result
from holomj.layout.open_pockets import ReachMeter
from holomj.layout.room_problem import (
    MAX_OBJECT_SIZE_M,
    LayoutObject,
    PreparedRoom,
    RoomProblem,
)
from holomj.layout.solve import LayoutResult, Placement
from holomj.spec.plan import PlanRelation, PlanRoom

# Work surfaces used from one side (the user sits at the desk's +X front).
GRID_CATEGORIES = frozenset(
    {
        "desk",
        "student_desk",
        "school_desk",
        "computer_desk",
        "standing_desk",
        "lab_bench",
        "drafting_table",
        "workbench",
        "work_table",
        "sewing_table",
        "study_carrel",
    }
)
# Tables used from both sides: a grid only when the name says what they are for.
TABLE_CATEGORIES = frozenset({"dining_table", "table"})
_TABLE_NAMES = re.compile(
    r"\b(?:work|study|school|student|classroom|exam|examination|reading|library|computer|"
    r"cafeteria|canteen|lunch|refectory|mess|drafting|lab|laboratory|training|banquet)\b"
)
SEAT_CATEGORIES = frozenset(
    {
        "chair",
        "dining_chair",
        "office_chair",
        "stool",
        "school_chair",
        "folding_chair",
        "gaming_chair",
        "executive_chair",
        "lab_stool",
        "bar_stool",
        "drafting_chair",
        "task_chair",
    }
)
_SEAT_NAMES = re.compile(r"\b(?:chair|stool|seat)s?\b")
PAIRING_KINDS = frozenset({"near", "face_to", "in_front_of", "adjacent_to"})
# Wall objects that a room's users look at: they hang where the front row looks.
BOARD_CATEGORIES = frozenset(
    {
        "whiteboard",
        "blackboard",
        "chalkboard",
        "smartboard",
        "projector_screen",
        "television",
        "wall_television",
        "screen",
    }
)
BOARD_WIDTH_M = 1.2  # a board's width when the plan gives none
BOARD_MARGIN_M = 0.1  # kept between a board and a door or window on the front wall

MIN_INSTANCES = 4
MIN_INSTANCES_IN_ROWS = 2
SEAT_GAP_M = 0.05  # between a desk's front and its seats' fronts: within reach
SEAT_SPACING_M = 0.05  # between two seats of one desk
SEAT_SLACK_M = 0.1  # a desk's seats may stick out this far past its width
JOIN_GAP_M = 0.002  # between two desks of a pair: they touch
GRID_WEIGHT = 5.0  # the block's own place constraints
BLOCK_PREFIX = "desk grid "
MAX_ATTEMPTS = 3  # one-block shapes solved before two blocks are tried
MAX_TWO_BLOCK_ATTEMPTS = 2
# A pocket of free floor inside a block at most this big may stay out of reach: the nook
# beside an end seat at a wall, a robot's width, which the reach measure's wider passage
# robot does not enter.
NOOK_M2 = 0.1


@dataclass(frozen=True)
class Aisles:
    """The widths of a block's aisles (metres): ``row`` behind every row of seats (and the front
    zone before the first row), ``column`` between two desk pairs and at both ends of rows that
    have no column aisle."""

    name: str
    row: float
    column: float


STANDARD = Aisles("standard", 0.9, 0.6)
COMPACT = Aisles("compact", 0.6, 0.6)
AISLE_LEVELS = (STANDARD, COMPACT)


@dataclass(frozen=True)
class Piece:
    """A desk or a seat: its instance and real footprint (``width`` left-right, ``depth``
    front-back) and height, in metres."""

    id: str
    width: float
    depth: float
    height: float
    priority: int = 1


@dataclass(frozen=True)
class Station:
    """A desk and its seats: ``front`` at the user side, ``back`` behind the desk (tables used
    from both sides)."""

    desk: Piece
    front: tuple[Piece, ...] = ()
    back: tuple[Piece, ...] = ()

    @property
    def pieces(self) -> tuple[Piece, ...]:
        """The desk and its seats."""
        return (self.desk, *self.front, *self.back)


def _span(seats: Sequence[Piece]) -> float:
    return sum(s.width for s in seats) + SEAT_SPACING_M * max(len(seats) - 1, 0)


@dataclass(frozen=True)
class GridGroup:
    """A room's desks of one kind with their seats; ``rows_asked``: the rows the plan asks
    for (None: any)."""

    name: str
    category: str
    stations: tuple[Station, ...]
    two_sided: bool = False
    rows_asked: int | None = None
    in_row: bool = False  # the plan asks for the instances in a row (consecutive neighbours)

    @property
    def members(self) -> set[str]:
        """Every desk and seat instance of the group."""
        return {p.id for s in self.stations for p in s.pieces}

    @property
    def slot_width(self) -> float:
        """The width of one slot of a row: the widest desk, or the widest set of seats."""
        widest = max(s.desk.width for s in self.stations)
        seats = max(max(_span(s.front), _span(s.back)) for s in self.stations)
        return max(widest, seats)

    @property
    def desk_depth(self) -> float:
        """The deepest desk."""
        return max(s.desk.depth for s in self.stations)

    @property
    def front_depth(self) -> float:
        """The deepest seat at the user side (0 without seats)."""
        return max((p.depth for s in self.stations for p in s.front), default=0.0)

    @property
    def back_depth(self) -> float:
        """The deepest seat behind the desks (0 without)."""
        return max((p.depth for s in self.stations for p in s.back), default=0.0)

    @property
    def row_depth(self) -> float:
        """Front to back of one row: desk and seats."""
        out = self.desk_depth
        if self.front_depth:
            out += SEAT_GAP_M + self.front_depth
        if self.back_depth:
            out += SEAT_GAP_M + self.back_depth
        return out

    @property
    def height(self) -> float:
        """The tallest desk or seat."""
        return max(p.height for s in self.stations for p in s.pieces)

    @property
    def priority(self) -> int:
        """The highest priority of its desks and seats."""
        return max(p.priority for s in self.stations for p in s.pieces)


@dataclass(frozen=True)
class Shape:
    """How one block lays out ``count`` stations: ``rows`` x ``columns`` slots, ``pair``
    desks side by side between column aisles (1 or 2), the aisle widths, and ``symmetric``
    (a front zone as deep as the aisle behind the last row: the front is chosen after the
    solve)."""

    count: int
    rows: int
    columns: int
    pair: int
    aisles: Aisles
    symmetric: bool = True
    ends: bool = True

    @property
    def groups(self) -> int:
        """How many column groups (pairs, or single desks) a row has."""
        return math.ceil(self.columns / self.pair)

    @property
    def side(self) -> float:
        """The aisle kept at both ends of the rows inside the block: rows without a column
        aisle open only at their ends (without ``ends``, the room's floor around the block
        must keep them open: the check of the split layout says whether it does)."""
        return self.aisles.column if self.groups == 1 and self.ends else 0.0

    def width(self, group: GridGroup) -> float:
        """The block's width along the rows."""
        c = self.columns
        return (
            c * group.slot_width
            + (c - self.groups) * JOIN_GAP_M
            + (self.groups - 1) * self.aisles.column
            + 2 * self.side
        )

    def depth(self, group: GridGroup) -> float:
        """The block's depth, front zone to the aisle behind the last row."""
        rows = self.rows * group.row_depth + self.rows * self.aisles.row
        return rows + (self.aisles.row if self.symmetric else 0.0)

    def label(self) -> str:
        """A short description for the record."""
        pairs = "pairs" if self.pair == 2 else "single desks"
        front = "" if self.symmetric else ", no front zone"
        ends = "" if self.ends or self.groups > 1 else ", no end aisles"
        return f"{self.rows} x {self.columns} ({pairs}, {self.aisles.name} aisles{front}{ends})"


# --------------------------------------------------------------------------- detection


def _base(instance: str) -> str:
    head, _, tail = instance.rpartition("-")
    return head if head and tail.isdigit() else instance


def _index(instance: str) -> int:
    tail = instance.rpartition("-")[2]
    return int(tail) if tail.isdigit() else 0


def is_grid_kind(category: str | None, name: str) -> bool:
    """Whether a floor kind of ``category`` called ``name`` is a work surface for rows."""
    if category in GRID_CATEGORIES:
        return True
    return category in TABLE_CATEGORIES and bool(_TABLE_NAMES.search(name.lower()))


def is_seat(category: str | None, name: str) -> bool:
    """Whether a floor kind is something to sit on at a desk."""
    return category in SEAT_CATEGORIES or bool(_SEAT_NAMES.search(name.lower()))


def grid_groups(
    problem: RoomProblem,
    categories: Mapping[str, str],
    plan_room: PlanRoom | None = None,
) -> list[GridGroup]:
    """The problem's grid groups (see the module docstring), largest first.

    ``categories``: instance -> library category; ``plan_room``: the room's plan (the rows its
    objects are asked in, its ``in_row`` relations)."""
    relations = plan_room.relations if plan_room is not None else ()
    rows = {o.name: o.rows for o in plan_room.objects} if plan_room is not None else {}
    sizes = {o.id: problem.object_size_m(o) for o in problem.objects}
    priority = {o.id: o.priority for o in problem.objects}
    kinds: dict[str, list[str]] = {}
    for obj in problem.objects:
        kinds.setdefault(_base(obj.id), []).append(obj.id)
    constraints = problem.all_constraints().constraints
    out: list[GridGroup] = []
    taken: set[str] = set()
    for name, instances in sorted(kinds.items(), key=lambda kv: (-len(kv[1]), kv[0])):
        category = categories.get(instances[0])
        if not is_grid_kind(category, name) or any(
            categories.get(i) != category for i in instances
        ):
            continue
        own = [r for r in relations if r.subject == name]
        in_row = any(r.kind == "in_row" for r in own)
        asked_rows = rows.get(name)
        count = asked_rows if isinstance(asked_rows, int) else None
        asked = asked_rows is not None or in_row
        if len(instances) < (MIN_INSTANCES_IN_ROWS if asked else MIN_INSTANCES):
            continue
        desks = set(instances)
        seats: dict[str, list[str]] = {}
        for seat in sorted({c.object for c in constraints if c.target in desks}):
            if seat in desks or seat in taken or seat not in sizes:
                continue
            if not is_seat(categories.get(seat), _base(seat)):
                continue
            targets = {
                c.target
                for c in constraints
                if c.object == seat and c.target is not None and c.target in desks
            }
            kinds_to = {c.kind for c in constraints if c.object == seat and c.target in desks}
            if len(targets) == 1 and kinds_to & PAIRING_KINDS:
                seats.setdefault(targets.pop(), []).append(seat)
        two_sided = category in TABLE_CATEGORIES
        stations = []
        for desk in sorted(instances, key=lambda i: (_index(i), i)):
            w, d, h = sizes[desk]
            mine = sorted(seats.get(desk, []), key=lambda i: (_base(i), _index(i)))
            pieces = []
            for s in mine:
                sw, sd, sh = sizes[s]
                pieces.append(Piece(s, sw, sd, sh or sd, priority[s]))
            front, back = (pieces[0::2], pieces[1::2]) if two_sided else (pieces, [])
            stations.append(
                Station(Piece(desk, w, d, h or 0.75, priority[desk]), tuple(front), tuple(back))
            )
        out.append(
            GridGroup(
                name,
                category or "",
                tuple(stations),
                two_sided,
                count,
                in_row,
            )
        )
        taken |= desks | {s for v in seats.values() for s in v}
    return out


def seats_fit(group: GridGroup) -> str | None:
    """Why the group's seats do not fit at its desks, or None when they do."""
    for station in group.stations:
        for side in (station.front, station.back):
            if _span(side) > station.desk.width + SEAT_SLACK_M + 1e-9:
                return (
                    f"{len(side)} seats ({_span(side):.2f} m) do not fit at "
                    f"{station.desk.id} ({station.desk.width:.2f} m wide)"
                )
    return None


# --------------------------------------------------------------------------- shapes


def candidate_shapes(group: GridGroup, count: int) -> list[Shape]:
    """Every shape for ``count`` stations: rows 1..count, as few columns as hold them, pairs
    or single desks, each aisle level, with and without a front zone."""
    out = []
    for aisles in AISLE_LEVELS:
        for symmetric in (True, False):
            for rows in range(1, count + 1):
                columns = math.ceil(count / rows)
                if rows > 1 and (rows - 1) * columns >= count:
                    continue  # a row would stay empty
                for pair in (2, 1) if columns >= 2 else (1,):
                    out.append(Shape(count, rows, columns, pair, aisles, symmetric))
                    if math.ceil(columns / pair) == 1:
                        out.append(Shape(count, rows, columns, pair, aisles, symmetric, False))
    return out


class FreeFloor:
    """Where a rectangle fits in a room: the room's raster less door zones (and window zones
    for tall blocks), with summed-area tables for quick tests."""

    def __init__(self, prep: PreparedRoom, tall: bool) -> None:
        blocked = prep.wall_block | prep.door_block
        if tall:
            blocked = blocked | prep.window_block
        self.grid = prep.grid
        self.clearance = prep.settings.clearance_m
        self.front = prep.settings.front_clearance_m  # kept free before a block's front face
        self.table = _summed(blocked)
        self.walls = _summed(prep.wall_block)
        self.free_area = float((~blocked).sum()) * self.grid**2

    def slack(self, along_x: float, along_y: float) -> float | None:
        """The least room left around an ``along_x`` x ``along_y`` rectangle where it fits
        (metres, the smaller of the two axes' spare room), or None where it fits nowhere."""
        return self._fit(self.table, along_x, along_y)

    def within_walls(self, along_x: float, along_y: float) -> bool:
        """Whether such a rectangle fits between the walls (doors and windows aside), either
        way round."""
        return any(
            self._fit(self.walls, a, b) is not None
            for a, b in ((along_x, along_y), (along_y, along_x))
        )

    def _fit(self, table: np.ndarray, along_x: float, along_y: float) -> float | None:
        g = self.grid
        a = math.ceil((along_x + self.clearance) / g - 1e-9)
        b = math.ceil((along_y + self.clearance) / g - 1e-9)
        nx, ny = table.shape[0] - 1, table.shape[1] - 1
        if a > nx or b > ny:
            return None
        sums = table[a:, b:] - table[:-a, b:] - table[a:, :-b] + table[:-a, :-b]
        if not (sums == 0).any():
            return None
        return min((nx - a) * g, (ny - b) * g)


def _summed(blocked: np.ndarray) -> np.ndarray:
    """The summed-area table of a boolean mask (one row and column of zeros in front)."""
    table = np.zeros((blocked.shape[0] + 1, blocked.shape[1] + 1), dtype=np.int64)
    table[1:, 1:] = np.cumsum(np.cumsum(blocked.astype(np.int64), axis=0), axis=1)
    return table


def rank_shapes(
    group: GridGroup,
    shapes: Sequence[Shape],
    floor: FreeFloor,
    others_area: float,
    copies: int = 1,
) -> list[tuple[float, Shape, float]]:
    """The shapes that fit the room's free floor, best first, with their cost and slack;
    with ``copies`` blocks of a shape, each must fit and all together in the free floor's
    area (the solver finds where).

    Costs: compact aisles, no front zone, rows other than asked, empty slots, single desks
    where pairs would do, a block out of proportion with the room, and floor too tight for
    the other furniture."""
    out = []
    for shape in shapes:
        w, d = shape.width(group), shape.depth(group)
        if max(w, d) > MAX_OBJECT_SIZE_M:
            continue
        d_front = d + floor.front  # the block's front face keeps the front clearance
        fits = [s for s in (floor.slack(d_front, w), floor.slack(w, d_front)) if s is not None]
        if copies > 1 and fits:
            # side by side (a column aisle apart) or one behind the other, within the walls
            # (a door's zone may lie between them)
            wide = copies * w + (copies - 1) * shape.aisles.column
            deep = copies * d + floor.front
            spans = ((wide, d_front), (w, deep))
            if not any(floor.within_walls(a, b) for a, b in spans):
                fits = []
        if not fits or copies * w * d > floor.free_area:
            continue
        slack = max(fits)
        cost = 0.0
        cost += 100.0 if shape.aisles is COMPACT else 0.0
        cost += 20.0 if not shape.symmetric else 0.0
        if group.rows_asked is not None:
            cost += 150.0 * abs(shape.rows - group.rows_asked)  # before roomy aisles
        cost += 3.0 * (shape.rows * shape.columns - shape.count)
        cost += 2.0 if shape.pair == 1 else 0.0
        cost += 8.0 if shape.side == 0.0 and shape.groups == 1 else 0.0
        cost += 4.0 * abs(math.log(max(w, 1e-3) / max(d, 1e-3)))
        left = floor.free_area - copies * w * d
        if left < 1.3 * others_area:
            cost += 30.0
        cost -= min(slack, 1.0)
        out.append((round(cost, 6), shape, slack))
    out.sort(key=lambda t: (t[0], t[1].rows, t[1].pair))
    return out


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
    at = v - _span(seats) / 2
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


def _block_ids(problem: RoomProblem, n: int) -> list[str]:
    taken = {normalize_name(o.id) for o in problem.objects}
    out, k = [], 0
    while len(out) < n:
        name = f"{BLOCK_PREFIX}{k}"
        if normalize_name(name) not in taken:
            out.append(name)
        k += 1
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
    kept: dict[tuple[str, str, str | None], Constraint] = {}

    def add(c: Constraint) -> None:
        old = kept.get(c.key)
        if old is None or old.weight < c.weight:
            kept[c.key] = c

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
        obj = owner.get(c.object, c.object)
        target = owner.get(c.target, c.target)
        if obj != target:
            add(c.model_copy(update={"object": obj, "target": target}))
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
    return RoomProblem(
        room_id=problem.room_id,
        polygon=problem.polygon,
        size_unit=problem.size_unit,
        doors=problem.doors,
        windows=problem.windows,
        objects=objects,
        constraints=list(kept.values()),
        settings=problem.settings,
    )


@dataclass(frozen=True)
class GridContext:
    """What an attempt needs besides the shapes: the room prepared, the prompt's facing
    opening, the board's width (None: no board), the defining priority (such an object left
    out fails the attempt) and the priority from which an object left out is reported
    (``left_out``: the attempt stands only if independent placement leaves it out too)."""

    prep: PreparedRoom
    facing: str | None
    board_width: float | None
    defining_priority: int
    keep_priority: int


def _attempt(
    problem: RoomProblem,
    group: GridGroup,
    parts: Sequence[tuple[Sequence[Station], Shape]],
    solve: Callable[[RoomProblem], LayoutResult],
    ctx: GridContext,
) -> tuple[LayoutResult | None, Any]:
    """Solve ``problem`` with each part (stations and shape) as one block, split the blocks
    and check the result; the layout and the record's fields (``left_out``: the objects of
    at least the keep priority the layout left out), or None and why not."""
    ids = _block_ids(problem, len(parts))
    owner = {
        p.id: ids[n] for n, (stations, _) in enumerate(parts) for s in stations for p in s.pieces
    }
    composite = composite_problem(
        problem, group, [(b, shape) for b, (_, shape) in zip(ids, parts)], owner
    )
    solved = solve(composite)
    for block in ids:
        if block not in solved.placements:
            why = next((u.reason for u in solved.unplaced if u.id == block), "not placed")
            return None, f"the layout left out the block ({why})"
    by_id = {o.id: o for o in problem.objects}
    for item in solved.unplaced:
        if item.id in by_id and by_id[item.id].priority >= ctx.defining_priority:
            return None, f"{item.id} did not fit beside the grid ({item.reason})"
    placements = {i: p for i, p in solved.placements.items() if i not in ids}
    blocks_out = []
    looker = None
    for n, (block, (stations, shape)) in enumerate(zip(ids, parts)):
        p = solved.placements[block]
        k = geo.yaw_index(p.yaw_deg)
        ks = [k, (k + 2) % 4] if shape.symmetric else [k]
        choice = choose_front(ctx.prep, (p.x, p.y), ks, ctx.facing, ctx.board_width)
        board = ctx.board_width is not None and n == 0
        pairs = assign_slots(group, shape, stations, board)
        local = block_pieces(group, shape, pairs)
        placements.update(world_placements(group, local, (p.x, p.y), choice.k))
        if board and pairs and pairs[0][0].front:
            looker = pairs[0][0].front[0].id
        rows: list[list[str]] = [[] for _ in range(shape.rows)]
        for station, slot in sorted(pairs, key=lambda t: (t[1].row, t[1].column)):
            rows[slot.row].append(station.desk.id)
        blocks_out.append(
            {
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
        )
    members = group.members & set(placements)
    checks = check_split(problem, placements, members)
    if not checks.ok:
        problems = checks.problems("the grid blocks the way between the doors")
        return None, "the split grid breaks a hard rule: " + "; ".join(problems[:3])
    cut = _cut_off(ctx.prep, placements, [solved.placements[b] for b in ids])
    if cut > 0:
        return None, f"{cut:.2f} m² of the grid's aisles are out of reach"
    left_out = sorted(
        u.id for u in solved.unplaced if u.id in by_id and by_id[u.id].priority >= ctx.keep_priority
    )
    fields: dict[str, Any] = {"blocks": blocks_out, "looker": looker, "left_out": left_out}
    return split_result(problem, solved, placements, checks, ids), fields


def _cut_off(
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


def _facing(relations: Sequence[PlanRelation], group: GridGroup) -> str | None:
    """The opening the prompt has the group's desks (or seats) face, if any."""
    names = {group.name} | {_base(p.id) for s in group.stations for p in (*s.front, *s.back)}
    for rel in relations:
        if rel.subject in names and rel.kind in ("facing_window", "facing_door"):
            return rel.kind.split("_", 1)[1]
    return None


def board_width(plan_room: PlanRoom | None) -> float | None:
    """The widest board of the room to face (None: the room has none)."""
    if plan_room is None:
        return None
    widths = [
        (obj.size[0] if obj.size else BOARD_WIDTH_M)
        for obj in plan_room.objects
        if obj.placement == "wall" and obj.category in BOARD_CATEGORIES and obj.above is None
    ]
    return max(widths) if widths else None


def solve_desk_grid(
    problem: RoomProblem,
    categories: Mapping[str, str],
    *,
    solve: Callable[[RoomProblem], LayoutResult],
    plan_room: PlanRoom | None = None,
    defining_priority: int = 100,
    keep_priority: int = 10,
) -> tuple[LayoutResult, dict[str, Any] | None]:
    """Lay out ``problem`` with its largest grid group in rows (see the module docstring);
    ``solve`` solves a layout problem (the room's solver), ``categories`` maps instances to
    library categories, ``plan_room`` gives the rows asked, the room's relations and boards.
    Returns the layout and the record (None when the room has no grid
    group). An object of at least ``defining_priority`` left out makes a shape fail; a shape
    that leaves out an object of at least ``keep_priority`` (one the prompt asked for) stands
    only if independent placement leaves it out as well."""
    relations = plan_room.relations if plan_room is not None else ()
    groups = grid_groups(problem, categories, plan_room)
    if not groups:
        return solve(problem), None
    group = groups[0]
    record: dict[str, Any] = {
        "group": group.name,
        "category": group.category,
        "desks": len(group.stations),
        "seats": sum(len(s.front) + len(s.back) for s in group.stations),
        "rows_asked": group.rows_asked,
        "rows": None,
        "columns": None,
        "front_wall": None,
        "blocks": [],
        "tried": [],
        "fallback": None,
    }
    misfit = seats_fit(group)
    if misfit is not None:
        record["fallback"] = f"{misfit}; the desks are laid out one by one"
        return solve(problem), record
    prep = PreparedRoom(problem)
    tall = any(group.height > w.sill_height for w in problem.windows)
    floor = FreeFloor(prep, tall)
    members = group.members
    others = 0.0
    for obj in problem.objects:
        if obj.id not in members:
            w, d, _ = problem.object_size_m(obj)
            others += w * d
    ctx = GridContext(
        prep, _facing(relations, group), board_width(plan_room), defining_priority, keep_priority
    )
    spare: tuple[LayoutResult, dict[str, Any]] | None = None  # a grid that left things out

    def laid(result: LayoutResult | None, outcome: Any, label: str) -> bool:
        nonlocal spare
        if result is not None and not outcome["left_out"]:
            return True
        if result is not None:
            if spare is None or len(outcome["left_out"]) < len(spare[1]["left_out"]):
                spare = (result, outcome)
            outcome = "the layout left out " + ", ".join(outcome["left_out"])
        record["tried"].append({"shape": label, "outcome": outcome})
        return False

    n = len(group.stations)
    ranked = rank_shapes(group, candidate_shapes(group, n), floor, others)
    tried_shapes: set[tuple[int, int, int, str, bool]] = set()
    attempts = 0
    for _, shape, _ in ranked:
        key = (shape.rows, shape.columns, shape.pair, shape.aisles.name, shape.ends)
        if key in tried_shapes:
            continue
        tried_shapes.add(key)
        attempts += 1
        result, outcome = _attempt(problem, group, [(group.stations, shape)], solve, ctx)
        if laid(result, outcome, shape.label()):
            assert result is not None
            return result, _finish(record, outcome)
        if attempts >= MAX_ATTEMPTS:
            break
    if not ranked:
        record["tried"].append(
            {"shape": "one block", "outcome": "no shape of one block fits the room's free floor"}
        )
    if n >= 2 * MIN_INSTANCES_IN_ROWS:
        half = math.ceil(n / 2)
        parts = (group.stations[:half], group.stations[half:])
        ranked2 = rank_shapes(group, candidate_shapes(group, half), floor, others, copies=2)
        attempts = 0
        for _, shape, _ in ranked2:
            rest = Shape(
                len(parts[1]),
                shape.rows,
                shape.columns,
                shape.pair,
                shape.aisles,
                shape.symmetric,
                shape.ends,
            )
            if rest.rows > 1 and (rest.rows - 1) * rest.columns >= rest.count:
                continue
            attempts += 1
            result, outcome = _attempt(
                problem, group, [(parts[0], shape), (parts[1], rest)], solve, ctx
            )
            if laid(result, outcome, f"two blocks of {shape.label()}"):
                assert result is not None
                return result, _finish(record, outcome)
            if attempts >= MAX_TWO_BLOCK_ATTEMPTS:
                break
    alone = solve(problem)
    if spare is not None:
        kept = {o.id for o in problem.objects if o.priority >= keep_priority}
        lost = {u.id for u in alone.unplaced if u.id in kept}
        if set(spare[1]["left_out"]) <= lost:  # placed one by one, they are left out as well
            return spare[0], _finish(record, spare[1])
    record["fallback"] = (
        "; ".join(f"{t['shape']}: {t['outcome']}" for t in record["tried"])
        or "no grid fits the room"
    ) + "; the desks are laid out one by one"
    return alone, record


def _finish(record: dict[str, Any], fields: Mapping[str, Any]) -> dict[str, Any]:
    """The record of a grid that was laid: rows, columns and front wall of the first block
    (``tried`` keeps the shapes that gave way before it; ``fallback`` stays None)."""
    blocks = list(fields["blocks"])
    out = dict(record)
    out["blocks"] = blocks
    out["rows"] = blocks[0]["rows"]
    out["columns"] = blocks[0]["columns"]
    out["block_count"] = len(blocks)
    out["front_wall"] = blocks[0]["front_wall"]
    out["looker"] = fields.get("looker")
    out["left_out"] = list(fields.get("left_out", []))
    return out


def front_lookers(plan_room: PlanRoom, record: Mapping[str, Any] | None) -> PlanRoom:
    """``plan_room`` with its boards (whiteboard, TV, projector screen) hung where the grid's
    front-row seat looks (its ``faced_by``), when a grid was laid and the board is not hung
    above something or faced by another object."""
    if not record or not record.get("looker") or not record.get("blocks"):
        return plan_room
    looker = _base(str(record["looker"]))
    if _index(str(record["looker"])) != 0:
        return plan_room
    ours = {looker, str(record.get("group"))}
    floor = {o.name for o in plan_room.objects if o.placement == "floor"}
    if looker not in floor:
        return plan_room
    objects = []
    for obj in plan_room.objects:
        if (
            obj.placement == "wall"
            and obj.category in BOARD_CATEGORIES
            and obj.above is None
            and (obj.faced_by is None or obj.faced_by in ours)
        ):
            obj = obj.model_copy(update={"faced_by": looker})
        objects.append(obj)
    return plan_room.model_copy(update={"objects": objects})
