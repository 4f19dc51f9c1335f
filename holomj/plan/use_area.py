"""The floor an object needs in use, not only the floor it stands on.

A table with four chairs around it takes far more floor than its top and four seats: the chairs
are pulled out to sit on, and people walk between the tables. A desk is used from its front; a
pool table needs room for the cue all round. Sizing rooms by bare footprints packs such rooms
until their floor is cut into pockets a robot cannot reach, so :func:`floor_needs` gives each
floor object of a draft room its *need* in the units of the footprint budget
(``footprint_fraction`` of the floor):

* a **table with its seats** (the templates' seat pairs, :func:`holomj.plan.seating.seat_pairs`:
  dining chairs at a dining table, school chairs at a student desk, stools at a bar counter):
  its *group* is the table, a :data:`SEAT_ZONE_M` deep zone for each side that has seats (one
  side, the front, for a work surface used from one side
  (:func:`holomj.layout.desk_grid.is_grid_kind` and bar counters); two sides for two seats or
  fewer; all four sides otherwise) and an aisle (:data:`AISLE_M`) on the sides people walk;
  its seats then need nothing of their own;
* a **play table** (:data:`PLAY_MARGINS_M`: pool, table tennis, foosball, air hockey) its table
  and the margin around it that players stand in;
* a **counter run module** (:data:`holomj.layout.counter_runs.RUN_CATEGORIES`: counters, the
  sink, the cooker) its width times its depth and the :data:`WORK_AISLE_M` in front of it
  where the cook stands (and a galley's two runs share); and the run as a whole needs walls
  as long as it is (:func:`least_area`);
* anything else its footprint.

Groups and play zones already hold their aisles, so they count at ``footprint_fraction /
GROUP_FILL`` of their area: a room whose floor is given to groups is full at ``GROUP_FILL`` of
its area, where one of loose furniture is full at ``footprint_fraction``.
"""

from __future__ import annotations

import math
from collections.abc import Mapping

from holomj.layout.counter_runs import RUN_CATEGORIES
from holomj.layout.desk_grid import is_grid_kind
from holomj.plan.draft import DraftObject, DraftRoom
from holomj.plan.knowledge_schema import KnowledgeBase
from holomj.plan.seating import seat_pairs

SEAT_ZONE_M = 0.7  # a seat's depth and the room to pull it out
AISLE_M = 0.6  # a walkway beside a group (a robot passes; two people pass sideways)
WORK_AISLE_M = 0.6  # half the 1.2 m kept before a counter run (the rest is the way through)
RUN_WALL_SHARE = 0.4  # the share of a room's walls a counter run may take (doors, windows, corners)
GROUP_FILL = 0.85  # the share of a room that groups with their aisles may fill
ONE_SIDED = frozenset({"bar_counter", "bar", "counter", "kitchen_island", "reception_desk"})
# Play tables: the margin (metres) kept free on every side for the players.
PLAY_MARGINS_M: Mapping[str, float] = {
    "pool_table": 1.0,
    "billiard_table": 1.0,
    "snooker_table": 1.0,
    "ping_pong_table": 1.2,
    "table_tennis_table": 1.2,
    "foosball_table": 0.6,
    "air_hockey_table": 0.7,
}


def _size(obj: DraftObject) -> tuple[float, float]:
    size = obj.size or obj.kind.size or (0.0, 0.0, 0.0)
    return size[0], size[1]


def group_area(width: float, depth: float, seats: int, one_sided: bool) -> float:
    """Floor (m²) of one table of ``width`` x ``depth`` with ``seats`` seats and its aisles."""
    if seats <= 0:
        return width * depth
    if one_sided:
        return (width + AISLE_M) * (depth + SEAT_ZONE_M + AISLE_M)
    if seats <= 2:  # one seat at each long side
        return (width + AISLE_M) * (depth + 2 * SEAT_ZONE_M + AISLE_M)
    return (width + 2 * SEAT_ZONE_M + AISLE_M) * (depth + 2 * SEAT_ZONE_M + AISLE_M)


def play_area(width: float, depth: float, margin: float) -> float:
    """Floor (m²) of a play table with ``margin`` free on every side."""
    return (width + 2 * margin) * (depth + 2 * margin)


def floor_needs(kb: KnowledgeBase, room: DraftRoom, fraction: float) -> dict[str, float]:
    """Object name -> the floor one instance needs, in footprint-budget units (see the module
    docstring), never less than its footprint (a table: with its seats'); seats counted in a
    table's group need 0 (those beyond its seats their own footprint, spread over the
    instances)."""
    pairs = seat_pairs(kb)
    floor = [o for o in room.objects if o.floor]
    needs = {o.name: o.footprint for o in floor}
    seats_left = {o.name: o.quantity for o in floor}
    scale = fraction / GROUP_FILL
    for table in floor:
        margin = PLAY_MARGINS_M.get(table.kind.category)
        width, depth = _size(table)
        if margin is not None:
            needs[table.name] = max(table.footprint, play_area(width, depth, margin) * scale)
            continue
        if table.kind.category in RUN_CATEGORIES:
            needs[table.name] = max(table.footprint, width * (depth + WORK_AISLE_M) * scale)
            continue
        partners = [room.get(name) for name in pairs.get(table.name, ())]
        seats = [s for s in partners if s is not None and s.floor and seats_left[s.name] > 0]
        if not seats or table.quantity <= 0:
            continue
        total = sum(seats_left[s.name] for s in seats)
        per_table = math.ceil(total / table.quantity)
        for seat in seats:
            seats_left[seat.name] = 0
        one_sided = table.kind.category in ONE_SIDED or is_grid_kind(
            table.kind.category, table.name
        )
        own = table.footprint + sum(s.footprint * s.quantity for s in seats) / table.quantity
        needs[table.name] = max(own, group_area(width, depth, per_table, one_sided) * scale)
    for obj in floor:
        if obj.name in seats_left and seats_left[obj.name] < obj.quantity:
            needs[obj.name] = obj.footprint * seats_left[obj.name] / max(obj.quantity, 1)
    return needs


def least_area(room: DraftRoom) -> float:
    """The smallest floor (m²) whose walls hold the room's counter run: a square-ish room's
    perimeter times :data:`RUN_WALL_SHARE` must be as long as the run's modules side by side."""
    run = sum(
        _size(o)[0] * o.quantity
        for o in room.objects
        if o.floor and o.kind.category in RUN_CATEGORIES
    )
    return (run / (4 * RUN_WALL_SHARE)) ** 2
