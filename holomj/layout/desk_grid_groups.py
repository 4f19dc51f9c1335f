"""A room's grid groups: the kinds of work surface laid out in rows (desks, lab benches, work and
canteen tables), each desk with the seats whose constraints point at it (:class:`Station`),
found from the room's problem and the rows its plan asks for (:func:`grid_groups`).

See :mod:`holomj.layout.desk_grid` for the whole method.
"""

from __future__ import annotations

import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

from holomj.layout.room_problem import RoomProblem
from holomj.spec.plan import PlanRoom

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


MIN_INSTANCES = 4
MIN_INSTANCES_IN_ROWS = 2
SEAT_GAP_M = 0.05  # between a desk's front and its seats' fronts: within reach
SEAT_SPACING_M = 0.05  # between two seats of one desk
SEAT_SLACK_M = 0.1  # a desk's seats may stick out this far past its width


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


def seats_span(seats: Sequence[Piece]) -> float:
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
        seats = max(max(seats_span(s.front), seats_span(s.back)) for s in self.stations)
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


# --------------------------------------------------------------------------- detection


def kind_of(instance: str) -> str:
    head, _, tail = instance.rpartition("-")
    return head if head and tail.isdigit() else instance


def index_of(instance: str) -> int:
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
        kinds.setdefault(kind_of(obj.id), []).append(obj.id)
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
            if not is_seat(categories.get(seat), kind_of(seat)):
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
        for desk in sorted(instances, key=lambda i: (index_of(i), i)):
            w, d, h = sizes[desk]
            mine = sorted(seats.get(desk, []), key=lambda i: (kind_of(i), index_of(i)))
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
            if seats_span(side) > station.desk.width + SEAT_SLACK_M + 1e-9:
                return (
                    f"{len(side)} seats ({seats_span(side):.2f} m) do not fit at "
                    f"{station.desk.id} ({station.desk.width:.2f} m wide)"
                )
    return None
