"""Floor plans: rectangular rooms packed in rows from a list of requests, and validation of
explicit room polygons.

The packer (:func:`plan_floor`) lays rooms out in *rows*. All rooms of a row share one depth
``d`` (so each is ``area / d`` wide); rows are stacked along +Y and all start at x = 0. This gives
three guarantees by construction:

* every room keeps its requested area (to the centimetre) and its sides within
  ``[min_side, max_side]`` (a room's feasible depths are ``[max(min, A/max), min(max, A/min)]``;
  a row's depth lies in the intersection of its rooms' intervals, and a room alone in a row can
  always be a square),
* rooms in a row share a full-depth wall (>= ``min_side``), and the first rooms of consecutive
  rows overlap by at least the narrower one's width, so the plan is connected through shared
  edges long enough for a door,
* the first and last room of every row touch the outside, so an entrance with an exterior wall
  always exists.

Which rooms go in which row, in which order, is searched: a few hundred random greedy row
packings (driven by the caller's generator, so a seed gives one plan) are scored by unmet
adjacency wishes, then compactness (bounding box area over room area) and aspect ratio; the best
one wins. Plans are rectangles only; explicit polygons (L-shapes or any rectilinear outline) go
through :func:`validate_floor`.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Annotated, Any

import numpy as np
from pydantic import Field, ValidationError, model_validator
from shapely.geometry import Polygon
from shapely.ops import unary_union

from holomj.errors import SpecError, closest_names
from holomj.spec.base import FrozenModel, Identifier, spec_error_from_validation
from holomj.spec.scene import Room
from holomj.spec.walls import room_polygon

DOOR_SPAN_M = 1.6  # a 1 m door with 0.3 m clearance from both ends of its wall segment
MIN_SHARED_EDGE_M = 1.2  # rooms sharing at least this much edge count as adjacent in a plan
CONNECT_EDGE_M = 1.0  # validate_floor: rooms sharing less than this are not connected
SEARCH_TRIES = 300

# Target floor area (m²) of a room type when a request gives neither area nor size.
DEFAULT_AREAS: dict[str, float] = {
    "living_room": 22.0,
    "dining_room": 14.0,
    "kitchen": 11.0,
    "bedroom": 13.0,
    "master_bedroom": 16.0,
    "kids_room": 11.0,
    "bathroom": 6.5,
    "office": 10.0,
    "study": 10.0,
    "hallway": 7.0,
    "corridor": 7.0,
    "foyer": 7.0,
    "entrance": 7.0,
    "closet": 6.5,
    "laundry": 6.5,
    "garage": 30.0,
}
DEFAULT_AREA = 12.0

# Which room becomes the entrance when none is named: the first type of this list present.
ENTRANCE_PREFERENCE = (
    "foyer",
    "entrance",
    "hallway",
    "corridor",
    "living_room",
    "kitchen",
    "dining_room",
)

Side = Annotated[float, Field(gt=0.0, le=100.0)]


def normal_type(room_type: str) -> str:
    """``"Living Room"`` -> ``"living_room"``: the form the tables of this package use."""
    return "_".join(room_type.strip().lower().replace("-", " ").split())


class RoomRequest(FrozenModel):
    """One room wanted in a floor plan: an area (or an exact size) and neighbours it should touch.

    Give ``area_m2`` or ``size`` (width, depth in metres, either orientation), or neither for the
    type's default area. ``min_side``/``max_side`` bound both sides of the rectangle.
    """

    id: Identifier
    type: str = Field(default="room", min_length=1, max_length=64)
    area_m2: Annotated[float, Field(gt=0.0, le=10000.0)] | None = None
    size: tuple[Side, Side] | None = None
    adjacent_to: list[Identifier] = Field(default_factory=list)
    min_side: Annotated[float, Field(ge=1.0, le=50.0)] = 2.5
    max_side: Annotated[float, Field(ge=1.0, le=100.0)] = 8.0

    @model_validator(mode="after")
    def _consistent(self) -> RoomRequest:
        if self.min_side > self.max_side:
            raise ValueError(f"min_side {self.min_side} exceeds max_side {self.max_side}")
        if self.area_m2 is not None and self.size is not None:
            raise ValueError("give area_m2 or size, not both")
        if self.size is not None:
            for side in self.size:
                if not self.min_side - 1e-9 <= side <= self.max_side + 1e-9:
                    raise ValueError(
                        f"size side {side} m is outside [{self.min_side}, {self.max_side}] m; "
                        "set min_side/max_side to allow it"
                    )
        if self.id in self.adjacent_to:
            raise ValueError("a room cannot be adjacent to itself")
        return self

    @property
    def target_area(self) -> float:
        """The area asked for (size, area_m2, or the type's default), before clamping."""
        if self.size is not None:
            return self.size[0] * self.size[1]
        if self.area_m2 is not None:
            return self.area_m2
        return DEFAULT_AREAS.get(normal_type(self.type), DEFAULT_AREA)


@dataclass(frozen=True)
class FloorPlan:
    """Rooms of a plan, the entrance room, which rooms touch (shared edge >= 1.2 m), warnings."""

    rooms: list[Room]
    entrance: str
    adjacency: dict[str, list[str]]
    warnings: list[str] = field(default_factory=list)

    def room(self, room_id: str) -> Room:
        """The room with this id."""
        for room in self.rooms:
            if room.id == room_id:
                return room
        raise SpecError(f"no room with id {room_id!r}", where="floor plan")


# ---------------------------------------------------------------------------------------------
# The packer


@dataclass(frozen=True)
class _Item:
    """A room to pack, in centimetres: area and the interval of depths it accepts."""

    index: int
    area: float  # cm²
    lo: int  # cm
    hi: int  # cm
    fixed: tuple[int, int] | None  # exact (w, d) in cm; either orientation


@dataclass
class _Row:
    items: list[tuple[_Item, int | None]]  # item and, for fixed-size rooms, the depth it needs
    lo: int
    hi: int

    @property
    def area(self) -> float:
        return sum(item.area for item, _ in self.items)


def plan_floor(
    requests: Sequence[RoomRequest | Mapping[str, Any]],
    rng: np.random.Generator,
    *,
    entrance_room: str | None = None,
) -> FloorPlan:
    """Pack the requested rooms into a connected, non-overlapping rectangular floor plan.

    Raises :class:`SpecError` for bad requests (duplicate ids, unknown neighbours or entrance).
    Areas outside ``[min_side², max_side²]`` are clamped with a warning; adjacency wishes that
    the best plan found cannot meet are reported as warnings.
    """
    reqs = _parse_requests(requests)
    warnings: list[str] = []
    items = [_item(i, req, warnings) for i, req in enumerate(reqs)]
    ids = [req.id for req in reqs]
    if entrance_room is not None and entrance_room not in ids:
        hint = closest_names(entrance_room, ids)
        raise SpecError(
            f"unknown entrance room {entrance_room!r}",
            where="entrance_room",
            fix=f"did you mean {hint}?" if hint else f"use one of {', '.join(ids)}",
        )
    wishes = {_pair(i, ids.index(n)) for i, r in enumerate(reqs) for n in r.adjacent_to}
    entrance_index = ids.index(entrance_room) if entrance_room else _default_entrance(reqs)

    best: tuple[tuple[float, ...], list[list[tuple[int, int, int, int, int]]]] | None = None
    total = sum(item.area for item in items) / 1e4  # m²
    widest = max(_min_width(item) for item in items)
    tries = 1 if len(items) == 1 else SEARCH_TRIES
    for _ in range(tries):
        order = [int(k) for k in rng.permutation(len(items))]
        target = max(widest, math.sqrt(total) * float(rng.uniform(0.7, 1.5)))
        rows = _pack_rows([items[k] for k in order], target, rng)
        rows = _entrance_first(rows, entrance_index)
        rects = _realise(rows, target)
        key = _score(rects, wishes, total * 1e4)
        if best is None or key < best[0]:
            best = (key, rects)
    assert best is not None
    placed = [r for row in best[1] for r in row]
    by_index = {index: (x0, y0, x1, y1) for index, x0, y0, x1, y1 in placed}
    rooms = [
        Room(id=req.id, type=normal_type(req.type), polygon=_rect_polygon(*by_index[i]))
        for i, req in enumerate(reqs)
    ]
    adjacency = room_adjacency(rooms, MIN_SHARED_EDGE_M)
    for a, b in sorted(wishes):
        if ids[b] not in adjacency[ids[a]]:
            warnings.append(f"rooms {ids[a]!r} and {ids[b]!r} asked to be adjacent but are not")
    warnings.extend(validate_floor(rooms))
    return FloorPlan(
        rooms=rooms, entrance=ids[entrance_index], adjacency=adjacency, warnings=warnings
    )


def _parse_requests(requests: Sequence[RoomRequest | Mapping[str, Any]]) -> list[RoomRequest]:
    if not requests:
        raise SpecError("no rooms requested", where="rooms", fix="ask for at least one room")
    reqs: list[RoomRequest] = []
    for i, req in enumerate(requests):
        if isinstance(req, RoomRequest):
            reqs.append(req)
            continue
        try:
            reqs.append(RoomRequest.model_validate(req))
        except ValidationError as err:
            raise spec_error_from_validation(err, f"rooms[{i}]") from None
    ids = [r.id for r in reqs]
    for i, rid in enumerate(ids):
        if rid in ids[:i]:
            raise SpecError(f"duplicate room id {rid!r}", where=f"rooms[{i}].id")
    for i, req in enumerate(reqs):
        for name in req.adjacent_to:
            if name not in ids:
                hint = closest_names(name, ids)
                raise SpecError(
                    f"unknown room {name!r}",
                    where=f"rooms[{i}].adjacent_to",
                    fix=f"did you mean {hint}?" if hint else f"use one of {', '.join(ids)}",
                )
    return reqs


def _item(index: int, req: RoomRequest, warnings: list[str]) -> _Item:
    lo_side = math.ceil(req.min_side * 100 - 1e-6)
    hi_side = math.floor(req.max_side * 100 + 1e-6)
    if req.size is not None:
        w, d = (round(s * 100) for s in req.size)
        w, d = min(max(w, lo_side), hi_side), min(max(d, lo_side), hi_side)
        return _Item(index, float(w * d), min(w, d), max(w, d), (w, d))
    area = req.target_area * 1e4
    lo_area, hi_area = float(lo_side * lo_side), float(hi_side * hi_side)
    if not lo_area <= area <= hi_area:
        clamped = min(max(area, lo_area), hi_area)
        warnings.append(
            f"room {req.id!r}: area {req.target_area:.1f} m² cannot have sides within "
            f"[{req.min_side}, {req.max_side}] m; using {clamped / 1e4:.1f} m²"
        )
        area = clamped
    lo = max(lo_side, math.ceil(area / hi_side))
    hi = min(hi_side, math.floor(area / lo_side))
    if lo > hi:  # rounding at the very edge of the range: a square is always feasible
        lo = hi = round(math.sqrt(area))
    return _Item(index, area, lo, hi, None)


def _min_width(item: _Item) -> float:
    """The narrowest the room can be, metres."""
    if item.fixed is not None:
        return min(item.fixed) / 100
    return item.area / item.hi / 100


def _default_entrance(reqs: Sequence[RoomRequest]) -> int:
    types = [normal_type(r.type) for r in reqs]
    for wanted in ENTRANCE_PREFERENCE:
        if wanted in types:
            return types.index(wanted)
    return max(range(len(reqs)), key=lambda i: reqs[i].target_area)


def _fits(row: _Row, item: _Item, rng: np.random.Generator) -> tuple[int, int, int | None] | None:
    """The row's depth interval with ``item`` added (and its needed depth), or None."""
    if item.fixed is None:
        lo, hi = max(row.lo, item.lo), min(row.hi, item.hi)
        return (lo, hi, None) if lo <= hi else None
    options = sorted(set(item.fixed))
    if len(options) == 2 and rng.random() < 0.5:
        options.reverse()
    for depth in options:
        if row.lo <= depth <= row.hi:
            return depth, depth, depth
    return None


def _row_depth(row: _Row, target_width: float) -> int:
    return int(min(max(round(row.area / target_width), row.lo), row.hi))


def _pack_rows(items: list[_Item], target: float, rng: np.random.Generator) -> list[_Row]:
    """Greedy: add rooms to the current row while the depths agree and it is not too wide."""
    target_cm = target * 100
    rows: list[_Row] = []
    for item in items:
        if rows:
            row = rows[-1]
            fit = _fits(row, item, rng)
            if fit is not None:
                trial = _Row(row.items + [(item, fit[2])], fit[0], fit[1])
                if trial.area / _row_depth(trial, target_cm) <= target_cm * 1.1:
                    rows[-1] = trial
                    continue
        fresh = _Row([], 0, 10**9)
        fit = _fits(fresh, item, rng)
        assert fit is not None
        rows.append(_Row([(item, fit[2])], fit[0], fit[1]))
    return rows


def _entrance_first(rows: list[_Row], entrance: int) -> list[_Row]:
    """Put the entrance room at the start of its row (so it has an exterior wall at x = 0)."""
    out = []
    for row in rows:
        items = sorted(row.items, key=lambda pair: pair[0].index != entrance)
        out.append(_Row(items, row.lo, row.hi))
    return out


def _realise(rows: list[_Row], target: float) -> list[list[tuple[int, int, int, int, int]]]:
    """Rectangles (index, x0, y0, x1, y1) in centimetres, rows stacked from y = 0."""
    out: list[list[tuple[int, int, int, int, int]]] = []
    y = 0
    for row in rows:
        depth = _row_depth(row, target * 100)
        x = 0
        placed = []
        for item, fixed_depth in row.items:
            if item.fixed is not None:
                w = item.fixed[0] if item.fixed[1] == fixed_depth else item.fixed[1]
            else:
                w = round(item.area / depth)
                w = min(max(w, math.ceil(item.area / item.hi)), math.floor(item.area / item.lo))
            placed.append((item.index, x, y, x + w, y + depth))
            x += w
        out.append(placed)
        y += depth
    return out


def _pair(i: int, j: int) -> tuple[int, int]:
    """The unordered pair of room indices ``i`` and ``j`` (the smaller first)."""
    return (i, j) if i <= j else (j, i)


def _score(
    rects: list[list[tuple[int, int, int, int, int]]],
    wishes: set[tuple[int, int]],
    total_area: float,
) -> tuple[float, ...]:
    flat = [r for row in rects for r in row]
    touching = set()
    for i, a in enumerate(flat):
        for b in flat[i + 1 :]:
            if _shared_cm(a, b) >= MIN_SHARED_EDGE_M * 100:
                touching.add(_pair(a[0], b[0]))
    unmet = sum(1 for pair in wishes if pair not in touching)
    width = max(r[3] for r in flat)
    height = max(r[4] for r in flat)
    compact = width * height / total_area
    aspect = max(width, height) / min(width, height)
    elongation = sum(
        max(0.0, max(r[3] - r[1], r[4] - r[2]) / min(r[3] - r[1], r[4] - r[2]) - 1.5) for r in flat
    ) / len(flat)
    penalty = compact + 0.5 * max(0.0, aspect - 1.6) + 0.5 * elongation
    return (float(unmet), round(penalty, 6))


def _shared_cm(a: tuple[int, ...], b: tuple[int, ...]) -> int:
    _, ax0, ay0, ax1, ay1 = a
    _, bx0, by0, bx1, by1 = b
    if ax1 == bx0 or bx1 == ax0:
        return max(0, min(ay1, by1) - max(ay0, by0))
    if ay1 == by0 or by1 == ay0:
        return max(0, min(ax1, bx1) - max(ax0, bx0))
    return 0


def _rect_polygon(x0: int, y0: int, x1: int, y1: int) -> list[tuple[float, float]]:
    return [(x0 / 100, y0 / 100), (x1 / 100, y0 / 100), (x1 / 100, y1 / 100), (x0 / 100, y1 / 100)]


# ---------------------------------------------------------------------------------------------
# Validation of explicit polygons


def shared_edge_length(a: Polygon, b: Polygon) -> float:
    """Length of boundary the two polygons have in common (metres)."""
    if a.distance(b) > 1e-6:
        return 0.0
    return float(a.boundary.intersection(b.boundary).length)


def room_adjacency(
    rooms: Sequence[Room], min_edge: float = MIN_SHARED_EDGE_M
) -> dict[str, list[str]]:
    """For every room, the rooms sharing at least ``min_edge`` metres of edge with it (sorted)."""
    polys = [room_polygon(r.polygon) for r in rooms]
    adjacency: dict[str, list[str]] = {r.id: [] for r in rooms}
    for i in range(len(rooms)):
        for j in range(i + 1, len(rooms)):
            if shared_edge_length(polys[i], polys[j]) >= min_edge - 1e-6:
                adjacency[rooms[i].id].append(rooms[j].id)
                adjacency[rooms[j].id].append(rooms[i].id)
    return {rid: sorted(nbrs) for rid, nbrs in adjacency.items()}


def validate_floor(rooms: Iterable[Room | Mapping[str, Any]]) -> list[str]:
    """Check explicit room polygons: return warnings, raise :class:`SpecError` for defects.

    Errors: a polygon that intersects itself, two rooms overlapping or one containing another,
    rooms not connected through shared edges of at least 1 m. Warnings: holes between rooms
    inside the outline of the house, rooms whose edges are not axis-aligned.
    """
    parsed = _parse_rooms(rooms)
    polys = []
    for i, room in enumerate(parsed):
        try:
            polys.append(room_polygon(room.polygon))
        except SpecError as err:
            raise err.located(f"rooms[{i}].polygon ({room.id})") from None
    warnings: list[str] = []
    for i, room in enumerate(parsed):
        if not _rectilinear(polys[i]):
            warnings.append(f"room {room.id!r} has edges that are not axis-aligned")
    for i in range(len(parsed)):
        for j in range(i + 1, len(parsed)):
            a, b = polys[i], polys[j]
            if not a.intersects(b):
                continue
            overlap = a.intersection(b).area
            if overlap <= 1e-4:
                continue
            small, big = (i, j) if a.area <= b.area else (j, i)
            if overlap >= polys[small].area - 1e-4:
                raise SpecError(
                    f"room {parsed[big].id!r} contains room {parsed[small].id!r}",
                    where=f"rooms[{max(i, j)}].polygon",
                    fix="rooms must not nest; cut the outer room around the inner one",
                )
            raise SpecError(
                f"room {parsed[i].id!r} overlaps room {parsed[j].id!r} by {overlap:.2f} m²",
                where=f"rooms[{j}].polygon",
                fix="rooms may share edges but not area",
            )
    adjacency = room_adjacency(parsed, CONNECT_EDGE_M)
    groups = _components(adjacency)
    if len(groups) > 1:
        listed = "; ".join(", ".join(sorted(g)) for g in groups)
        raise SpecError(
            f"rooms are not connected: {len(groups)} groups ({listed})",
            where="rooms",
            fix=f"make every room share at least {CONNECT_EDGE_M:.0f} m of wall with another",
        )
    union = unary_union(polys)
    holes = [Polygon(ring) for ring in getattr(union, "interiors", [])]
    for hole in holes:
        if hole.area > 1e-3:
            c = hole.representative_point()
            warnings.append(f"gap of {hole.area:.2f} m² between rooms near ({c.x:.2f}, {c.y:.2f})")
    return warnings


def _parse_rooms(rooms: Iterable[Room | Mapping[str, Any]]) -> list[Room]:
    parsed: list[Room] = []
    for i, room in enumerate(rooms):
        if isinstance(room, Room):
            parsed.append(room)
            continue
        try:
            parsed.append(Room.model_validate(room))
        except ValidationError as err:
            raise spec_error_from_validation(err, f"rooms[{i}]") from None
    if not parsed:
        raise SpecError("no rooms", where="rooms", fix="give at least one room polygon")
    seen: set[str] = set()
    for i, room in enumerate(parsed):
        if room.id in seen:
            raise SpecError(f"duplicate room id {room.id!r}", where=f"rooms[{i}].id")
        seen.add(room.id)
    return parsed


def _rectilinear(poly: Polygon) -> bool:
    coords = list(poly.exterior.coords)
    return all(
        abs(a[0] - b[0]) < 1e-6 or abs(a[1] - b[1]) < 1e-6 for a, b in zip(coords, coords[1:])
    )


def _components(adjacency: Mapping[str, Sequence[str]]) -> list[set[str]]:
    seen: set[str] = set()
    groups: list[set[str]] = []
    for start in sorted(adjacency):
        if start in seen:
            continue
        group = {start}
        stack = [start]
        while stack:
            for nbr in adjacency[stack.pop()]:
                if nbr not in group:
                    group.add(nbr)
                    stack.append(nbr)
        seen |= group
        groups.append(group)
    return groups
