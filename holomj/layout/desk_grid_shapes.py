"""The shapes a grid group's block can take: rows and columns of stations, single desks or pairs,
with aisles of :data:`STANDARD` or :data:`COMPACT` widths (:class:`Shape`), the candidates for a
group (:func:`candidate_shapes`) ranked by how they fit the room's free floor, a raster test
before any solve (:func:`rank_shapes`).

See :mod:`holomj.layout.desk_grid` for the whole method.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from holomj.layout.desk_grid_groups import GridGroup
from holomj.layout.room_problem import MAX_OBJECT_SIZE_M, PreparedRoom

JOIN_GAP_M = 0.002  # between two desks of a pair: they touch


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
