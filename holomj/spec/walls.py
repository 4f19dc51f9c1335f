"""Walls derived from room polygons: every shared stretch of edge once, every exterior one once.

Rooms are simple polygons that may share edges fully or partly (an L-shaped room beside two
rectangles). We group all room edges by the line they lie on, cut each line at every edge end,
and record which rooms border each piece. Pieces bordered by two rooms are interior walls,
pieces bordered by one room are exterior walls; consecutive pieces with the same rooms merge.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Protocol

from shapely.geometry import Polygon
from shapely.geometry.polygon import orient

from holomj.errors import SpecError

Point = tuple[float, float]

_ANGLE_TOL = 1e-5  # radians
_OFFSET_TOL = 1e-3  # metres: edges closer than this lie on the same line
_T_TOL = 1e-4  # metres along a line
_ON_WALL_TOL = 0.05  # an opening's centre may sit this far off the wall line


@dataclass(frozen=True)
class Wall:
    """One straight wall between ``start`` and ``end`` (metres, world x/y).

    ``rooms`` holds one room id (exterior wall) or two (interior wall), sorted. ``normal`` is the
    unit vector to the left of ``start -> end``; ``left_room`` is the room on that side (None for an
    exterior wall whose room lies on the right).
    """

    id: str
    start: Point
    end: Point
    rooms: tuple[str, ...]
    left_room: str | None

    @property
    def exterior(self) -> bool:
        """True for a wall with a room on one side only."""
        return len(self.rooms) == 1

    @property
    def length(self) -> float:
        """Length in metres."""
        return math.dist(self.start, self.end)

    @property
    def direction(self) -> Point:
        """Unit vector from start to end."""
        length = self.length
        return ((self.end[0] - self.start[0]) / length, (self.end[1] - self.start[1]) / length)

    @property
    def normal(self) -> Point:
        """Unit vector to the left of the direction."""
        dx, dy = self.direction
        return (-dy, dx)

    @property
    def outward(self) -> Point:
        """For an exterior wall, the unit vector pointing away from its room."""
        nx, ny = self.normal
        return (nx, ny) if self.left_room is None else (-nx, -ny)

    @property
    def yaw(self) -> float:
        """Angle of the direction from +X, radians."""
        dx, dy = self.direction
        return math.atan2(dy, dx)

    def locate(self, point: Point) -> tuple[float, float]:
        """Distance along the wall from ``start`` and signed distance from the wall line."""
        dx, dy = self.direction
        px, py = point[0] - self.start[0], point[1] - self.start[1]
        return px * dx + py * dy, -px * dy + py * dx

    def point_at(self, t: float) -> Point:
        """The point ``t`` metres from start along the wall."""
        dx, dy = self.direction
        return (self.start[0] + dx * t, self.start[1] + dy * t)


_VERTEX_TOL = 1e-6  # metres: vertices (or a vertex and an edge) closer than this are degenerate


def room_polygon(points: Sequence[Sequence[float]]) -> Polygon:
    """A validated, counter-clockwise shapely polygon for a room's floor outline.

    A ring may repeat its first vertex exactly at its end; any other pair of vertices closer than
    1 µm, or a vertex that close to an edge it does not bound (the outline touches itself), is
    refused with the vertex's index, as are self-intersecting outlines and areas below 0.25 m².
    """
    pts = [(float(p[0]), float(p[1])) for p in points]
    if len(pts) > 3 and pts[0] == pts[-1]:
        pts = pts[:-1]
    for i, p in enumerate(pts):
        if max(abs(p[0]), abs(p[1])) > 1e4:
            raise SpecError(f"vertex {i} is more than 10 km from the origin")
    if len(pts) < 3:
        raise SpecError("a polygon needs at least three distinct vertices")
    _check_vertex_spacing(pts)
    polygon = Polygon(pts)
    if not polygon.is_valid or not polygon.exterior.is_simple:
        raise SpecError("polygon intersects itself", fix="list the vertices in order around it")
    if polygon.area < 0.25:
        raise SpecError(f"polygon area {polygon.area:.3f} m² is below 0.25 m²")
    return orient(polygon, sign=1.0)


def _check_vertex_spacing(pts: Sequence[Point]) -> None:
    """Refuse coincident vertices and vertices touching an edge they do not bound."""
    n = len(pts)
    for i, p in enumerate(pts):
        following = (i + 1) % n
        if math.dist(p, pts[following]) < _VERTEX_TOL:
            raise SpecError(f"vertices {i} and {following} coincide")
    for i in range(n):
        for j in range(i + 2, n):
            if math.dist(pts[i], pts[j]) < _VERTEX_TOL:
                raise SpecError(
                    f"vertices {i} and {j} coincide",
                    fix="a room's outline must not touch itself; split it into two rooms",
                )
    for i, p in enumerate(pts):
        for a in range(n):
            b = (a + 1) % n
            if i in (a, b):
                continue
            if _segment_distance(p, pts[a], pts[b]) < _VERTEX_TOL:
                raise SpecError(
                    f"vertex {i} touches edge {a}-{b} (closer than 1 µm)",
                    fix="a room's outline must not touch itself; split it into two rooms",
                )


def _segment_distance(p: Point, a: Point, b: Point) -> float:
    """Distance from point ``p`` to the segment ``a``-``b``."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    length2 = dx * dx + dy * dy
    t = 0.0 if length2 == 0 else ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / length2
    t = min(1.0, max(0.0, t))
    return math.dist(p, (a[0] + t * dx, a[1] + t * dy))


@dataclass
class _Edge:
    room: str
    t0: float
    t1: float
    left: bool  # the room lies to the left of the line's canonical direction


@dataclass
class _Line:
    origin: Point
    direction: Point
    edges: list[_Edge]


class RoomOutline(Protocol):
    """What walls are derived from: a room's id and its floor polygon."""

    @property
    def id(self) -> str: ...

    @property
    def polygon(self) -> Sequence[Sequence[float]]: ...


def derive_walls(rooms: Sequence[RoomOutline]) -> list[Wall]:
    """Walls of a set of rooms (objects with ``id`` and ``polygon``), in a deterministic order."""
    lines: list[_Line] = []
    for room in rooms:
        polygon = room_polygon(room.polygon)
        coords = list(polygon.exterior.coords)[:-1]
        for a, b in zip(coords, coords[1:] + coords[:1]):
            _add_edge(lines, room.id, a, b)
    walls: list[tuple[tuple[str, ...], Point, Point, str | None]] = []
    for line in lines:
        walls.extend(_split_line(line))
    walls.sort(key=lambda w: (len(w[0]), w[0], _rounded(w[1]), _rounded(w[2])))
    return [
        Wall(id=f"wall_{i:03d}", start=start, end=end, rooms=room_ids, left_room=left)
        for i, (room_ids, start, end, left) in enumerate(walls)
    ]


def _rounded(p: Point) -> Point:
    return (round(p[0], 6), round(p[1], 6))


def _add_edge(lines: list[_Line], room_id: str, a: Point, b: Point) -> None:
    length = math.dist(a, b)
    if length < _T_TOL:
        return
    dx, dy = (b[0] - a[0]) / length, (b[1] - a[1]) / length
    forward = dx > 1e-9 or (abs(dx) <= 1e-9 and dy > 0)
    cdx, cdy = (dx, dy) if forward else (-dx, -dy)
    for line in lines:
        ldx, ldy = line.direction
        if abs(ldx * cdy - ldy * cdx) > _ANGLE_TOL:
            continue
        ox, oy = a[0] - line.origin[0], a[1] - line.origin[1]
        if abs(-ox * ldy + oy * ldx) > _OFFSET_TOL:
            continue
        break
    else:
        line = _Line(origin=a, direction=(cdx, cdy), edges=[])
        lines.append(line)
    ldx, ldy = line.direction
    ta = (a[0] - line.origin[0]) * ldx + (a[1] - line.origin[1]) * ldy
    tb = (b[0] - line.origin[0]) * ldx + (b[1] - line.origin[1]) * ldy
    # Polygons are counter-clockwise, so the room lies to the left of a -> b.
    line.edges.append(_Edge(room=room_id, t0=min(ta, tb), t1=max(ta, tb), left=forward))


def _split_line(line: _Line) -> list[tuple[tuple[str, ...], Point, Point, str | None]]:
    cuts: list[float] = []
    for t in sorted({e.t0 for e in line.edges} | {e.t1 for e in line.edges}):
        if not cuts or t - cuts[-1] > _T_TOL:
            cuts.append(t)
    pieces: list[tuple[float, float, tuple[tuple[str, bool], ...]]] = []
    for t0, t1 in zip(cuts, cuts[1:]):
        cover = tuple(
            sorted(
                (e.room, e.left) for e in line.edges if e.t0 <= t0 + _T_TOL and e.t1 >= t1 - _T_TOL
            )
        )
        if not cover:
            continue
        sides = [left for _, left in cover]
        if len(cover) == 2 and cover[0][0] == cover[1][0]:
            raise SpecError(f"room {cover[0][0]} borders itself along an edge")
        if len(cover) > 2 or len(set(sides)) != len(sides):
            names = ", ".join(sorted({room for room, _ in cover}))
            raise SpecError(f"rooms {names} overlap along a shared edge")
        if pieces and abs(pieces[-1][1] - t0) <= _T_TOL and pieces[-1][2] == cover:
            pieces[-1] = (pieces[-1][0], t1, cover)
        else:
            pieces.append((t0, t1, cover))
    ox, oy = line.origin
    dx, dy = line.direction
    result = []
    for t0, t1, cover in pieces:
        start = (ox + dx * t0, oy + dy * t0)
        end = (ox + dx * t1, oy + dy * t1)
        left = next((room for room, is_left in cover if is_left), None)
        result.append((tuple(sorted(room for room, _ in cover)), start, end, left))
    return result


def find_wall_for_opening(
    walls: Sequence[Wall], rooms: Sequence[str], position: Point, width: float
) -> tuple[Wall, float]:
    """The wall an opening sits on and the distance of its centre along that wall.

    ``rooms`` names one room (an exterior wall of it) or two (the wall they share).
    """
    wanted = tuple(sorted(set(rooms)))
    candidates = [w for w in walls if w.rooms == wanted]
    label = " and ".join(repr(r) for r in wanted)
    kind = "exterior wall of room" if len(wanted) == 1 else "wall between rooms"
    if not candidates:
        raise SpecError(f"there is no {kind} {label}", fix="check the rooms the opening joins")
    best: tuple[float, Wall, float] | None = None
    for wall in candidates:
        t, off = wall.locate(position)
        clamped = min(max(t, 0.0), wall.length)
        gap = math.hypot(t - clamped, off)
        if best is None or gap < best[0]:
            best = (gap, wall, t)
        if (
            abs(off) <= _ON_WALL_TOL
            and t - width / 2 >= -1e-6
            and t + width / 2 <= wall.length + 1e-6
        ):
            return wall, t
    assert best is not None
    gap, wall, t = best
    if gap <= _ON_WALL_TOL:
        raise SpecError(
            f"an opening {width:.2f} m wide centred {t:.2f} m along {wall.id} "
            f"does not fit on that wall ({wall.length:.2f} m long)",
            fix="move it along the wall or make it narrower",
        )
    px, py = position
    raise SpecError(
        f"centre ({px:.2f}, {py:.2f}) is not on the {kind} {label}; "
        f"the nearest such wall is {gap:.2f} m away",
        fix="put the opening's position on the wall line",
    )
