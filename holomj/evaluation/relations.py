"""Spatial relations between scene objects, walls, doors and windows, judged on footprints.

Footprints are the asset's size x scale rotated by yaw about the position (else the world
box); front = +X rotated by yaw; walls = room polygon edges, interior walls (shared edges) inset
by half the wall thickness. near = footprints buffered 5 cm per side closer than 1.5 m; next to
= footprints at most 0.5 m apart; in front of / behind = the subject's centre in the object's
front / back half-space beyond its face, overlapping it sideways, within 1.5 m; facing = the
front points at the target's centre within 30 degrees or its ray hits the target's footprint
(Holodeck); work furniture used from its front (desks, counters, pianos: the vocabulary's
``faces_away_from_front``) looks the other way; across from = both face each other within 45
degrees, or they stand at opposite parallel walls; against wall = the back edge within 15 cm of
a wall surface and parallel to it within 20 degrees; in corner = the footprint within 20 cm of
both walls of a convex room corner; middle = more than 1 m from every wall, or (small rooms) its
centre within 0.5 m of the room's centroid and more than 0.3 m from every wall; under window =
within 60 cm of the window's wall, overlapping its span by 30 cm (or half the object's width),
top below the sill + 30 cm; on = ``support`` in objects.json or resting (within 3 cm) on the
object's top or a surface, centre over its footprint; above = bottom above the object's top (5
cm slack) and footprints within 30 cm, overlapping along an axis; around = at least 2 (and 75
%) of the subjects within 0.6 m of one object, on at least 2 of its sides.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from shapely.geometry import LineString, Point

from holomj.evaluation.folder import MeasuredFolder
from holomj.evaluation.geometry import angle_deg, direction
from holomj.evaluation.objects import EvaluatedObject, Opening

BUFFER_M = 0.05  # footprints grown per side for "near" (Holodeck)
NEAR_M = 1.5
NEXT_TO_M = 0.5
FRONT_M = 1.5
FACING_DEG = 30.0
ACROSS_DEG = 45.0
WALL_M = 0.15
WALL_PARALLEL_DEG = 20.0
CORNER_M = 0.2
MIDDLE_M = 1.0
MIDDLE_CENTROID_M = 0.5
MIDDLE_MIN_WALL_M = 0.3
WINDOW_WALL_M = 0.6
WINDOW_OVERLAP_M = 0.3
WINDOW_SILL_SLACK_M = 0.3
ON_M = 0.03
ABOVE_SLACK_M = 0.05
ABOVE_PLAN_M = 0.3
AROUND_M = 0.6
MOST = 0.75
RELATIONS = (
    "near",
    "next to",
    "in front of",
    "behind",
    "facing",
    "against wall",
    "in corner",
    "middle",
    "under window",
    "on",
    "above",
    "around",
    "across from",
)


@dataclass
class Verdict:
    """Whether one spec holds, and why."""

    held: bool
    reason: str


def same_room(a: EvaluatedObject, b: EvaluatedObject) -> bool:
    """Whether two objects share a room (an object without a room shares every room)."""
    return a.room is None or b.room is None or a.room == b.room


def near(s: EvaluatedObject, o: EvaluatedObject) -> bool:
    """Footprints, each grown by 5 cm, closer than 1.5 m."""
    return s.fp.buffer(BUFFER_M).distance(o.fp.buffer(BUFFER_M)) < NEAR_M


def next_to(s: EvaluatedObject, o: EvaluatedObject) -> bool:
    """Footprints at most 0.5 m apart."""
    return s.fp.distance(o.fp) <= NEXT_TO_M


def in_front(s: EvaluatedObject, o: EvaluatedObject, sign: float = 1.0) -> bool:
    """``s`` in front of ``o`` (behind it with ``sign`` -1)."""
    fx, fy = o.front
    f = (fx * sign, fy * sign)
    side = (-f[1], f[0])
    dx, dy = s.center[0] - o.center[0], s.center[1] - o.center[1]
    along = dx * f[0] + dy * f[1]
    face = o.extent(f)[1]
    if along < face - 0.05:
        return False
    lat = dx * side[0] + dy * side[1]
    olo, ohi = o.extent(side)
    slo, shi = s.extent(side)
    if lat + shi < olo or lat + slo > ohi:
        return False
    return s.fp.distance(o.fp) <= FRONT_M


def faces_point(s: EvaluatedObject, target: tuple[float, float], limit: float) -> bool:
    """Whether ``s`` looks at ``target`` within ``limit`` degrees."""
    v = (target[0] - s.center[0], target[1] - s.center[1])
    return angle_deg(s.view, v) <= limit


def ray_hits(s: EvaluatedObject, geom: Any) -> bool:
    """Whether the ray ``s`` looks along meets ``geom``."""
    fx, fy = s.view
    ray = LineString([s.center, (s.center[0] + fx * 30.0, s.center[1] + fy * 30.0)])
    return ray.intersects(geom) and not s.fp.contains(geom)


def facing(s: EvaluatedObject, o: EvaluatedObject) -> bool:
    """``s`` looks at ``o``'s centre (30 degrees) or its ray meets ``o``'s footprint."""
    return faces_point(s, o.center, FACING_DEG) or ray_hits(s, o.fp)


def wall_side(scene: MeasuredFolder, obj: EvaluatedObject) -> tuple[float, LineString] | None:
    """The distance to, and the edge of, the wall nearest ``obj`` in its room."""
    room = scene.room_of(obj)
    return scene.nearest_wall(room, obj.fp) if room is not None else None


def across(scene: MeasuredFolder, s: EvaluatedObject, o: EvaluatedObject) -> bool:
    """Both face each other (45 degrees), or they stand at opposite parallel walls."""
    if faces_point(s, o.center, ACROSS_DEG) and faces_point(o, s.center, ACROSS_DEG):
        return True
    ws, wo = wall_side(scene, s), wall_side(scene, o)
    if ws is None or wo is None or ws[0] > NEXT_TO_M or wo[0] > NEXT_TO_M:
        return False
    parallel = angle_deg(direction(ws[1]), direction(wo[1]))
    return min(parallel, 180 - parallel) <= 10.0 and ws[1].distance(wo[1]) > 1.0


def against_wall(scene: MeasuredFolder, s: EvaluatedObject) -> tuple[bool, str]:
    """The back edge within 15 cm of a wall surface, parallel within 20 degrees."""
    room = scene.room_of(s)
    if room is None:
        return False, "not in a room"
    f = s.front
    side = (-f[1], f[0])
    back = s.extent(f)[0]
    lo, hi = s.extent(side)
    bx, by = s.center[0] + f[0] * back, s.center[1] + f[1] * back
    edge = LineString(
        [
            (bx + side[0] * lo * 0.8, by + side[1] * lo * 0.8),
            (bx + side[0] * hi * 0.8, by + side[1] * hi * 0.8),
        ]
    )
    best = (math.inf, "")
    for wall in scene.wall_edges(room):
        dist = scene.surface_distance(room, edge, wall)
        angle = angle_deg(direction(wall), side)
        angle = min(angle, 180.0 - angle)
        if angle <= WALL_PARALLEL_DEG and dist < best[0]:
            best = (dist, f"back {dist:.2f} m from a wall")
    if best[0] == math.inf:
        return False, "back parallel to no wall"
    return best[0] <= WALL_M, best[1]


def in_corner(scene: MeasuredFolder, s: EvaluatedObject) -> tuple[bool, str]:
    """The footprint within 20 cm of both walls of a convex corner of its room."""
    room = scene.room_of(s)
    if room is None:
        return False, "not in a room"
    coords = list(room.poly.exterior.coords)[:-1]
    n = len(coords)
    orient = 1.0 if room.poly.exterior.is_ccw else -1.0
    best = math.inf
    for i in range(n):
        a, v, b = coords[i - 1], coords[i], coords[(i + 1) % n]
        cross = (v[0] - a[0]) * (b[1] - v[1]) - (v[1] - a[1]) * (b[0] - v[0])
        if cross * orient <= 1e-9:
            continue  # reflex or straight vertex
        d1 = scene.surface_distance(room, s.fp, LineString([a, v]))
        d2 = scene.surface_distance(room, s.fp, LineString([v, b]))
        best = min(best, max(d1, d2))
    return best <= CORNER_M, f"{best:.2f} m from the farther wall of its nearest corner"


def middle(scene: MeasuredFolder, s: EvaluatedObject) -> tuple[bool, str]:
    """More than 1 m from every wall, or centred in a small room."""
    room = scene.room_of(s)
    if room is None:
        return False, "not in a room"
    dist = scene.nearest_wall(room, s.fp)[0]
    centred = (
        Point(s.center).distance(room.poly.centroid) <= MIDDLE_CENTROID_M
        and dist > MIDDLE_MIN_WALL_M
    )
    return dist > MIDDLE_M or centred, f"{dist:.2f} m from the nearest wall" + (
        ", centred in the room" if centred else ""
    )


def on(s: EvaluatedObject, o: EvaluatedObject) -> bool:
    """``s`` was dropped on ``o`` or rests on its top or a surface, centre over its footprint."""
    if s.support is not None and s.support == o.id:
        return True
    tops = [o.zmax] + [float(x.get("height", -9)) for x in o.surfaces]
    resting = any(abs(s.zmin - t) <= ON_M for t in tops)
    return resting and o.fp.buffer(0.02).contains(Point(s.center)) and s.id != o.id


def above(s: EvaluatedObject, o: EvaluatedObject) -> bool:
    """Bottom above ``o``'s top and footprints within 30 cm, overlapping along an axis."""
    if s.zmin < o.zmax - ABOVE_SLACK_M or s.fp.distance(o.fp) > ABOVE_PLAN_M:
        return False
    sx0, sy0, sx1, sy1 = s.fp.bounds
    ox0, oy0, ox1, oy1 = o.fp.bounds
    return min(sx1, ox1) - max(sx0, ox0) > 0 or min(sy1, oy1) - max(sy0, oy0) > 0


def sides_of(o: EvaluatedObject, subjects: list[EvaluatedObject]) -> set[int]:
    """Which of ``o``'s four sides (front, left, back, right) the subjects stand at."""
    sides = set()
    for s in subjects:
        v = (s.center[0] - o.center[0], s.center[1] - o.center[1])
        ang = math.degrees(math.atan2(v[1], v[0])) - o.yaw
        sides.add(int(((ang + 45.0) % 360.0) // 90.0))
    return sides


def opening_relation(rel: str, s: EvaluatedObject, op: Opening) -> bool:
    """Whether ``s`` is ``rel`` to the door or window ``op``."""
    seg = op.segment
    normal = op.normals.get(s.room or "", next(iter(op.normals.values()), (0.0, 1.0)))
    if rel == "near":
        return s.fp.buffer(BUFFER_M).distance(seg) < NEAR_M
    if rel == "next to":
        return s.fp.distance(seg) <= NEXT_TO_M
    if rel == "facing":
        return faces_point(s, op.point, FACING_DEG) or ray_hits(s, seg.buffer(0.05))
    if rel in ("in front of", "under window"):
        dx, dy = s.center[0] - op.point[0], s.center[1] - op.point[1]
        if dx * normal[0] + dy * normal[1] <= 0:
            return False
        lo, hi = s.extent(op.along)
        lat = dx * op.along[0] + dy * op.along[1]
        overlap = min(lat + hi, op.width / 2) - max(lat + lo, -op.width / 2)
        if rel == "in front of":
            return overlap > 0 and s.fp.distance(seg) <= FRONT_M
        need = min(WINDOW_OVERLAP_M, 0.5 * (hi - lo))
        return (
            overlap >= need
            and s.fp.distance(seg) <= WINDOW_WALL_M
            and s.zmax <= op.base + WINDOW_SILL_SLACK_M
        )
    return False


def pair_relation(scene: MeasuredFolder, kind: str, s: EvaluatedObject, o: EvaluatedObject) -> bool:
    """Whether ``s`` is ``kind`` to the object ``o``."""
    if kind == "near":
        return near(s, o)
    if kind == "next to":
        return next_to(s, o)
    if kind == "in front of":
        return in_front(s, o)
    if kind == "behind":
        return in_front(s, o, -1.0)
    if kind == "facing":
        return facing(s, o)
    if kind == "across from":
        return across(scene, s, o)
    if kind == "on":
        return on(s, o)
    if kind == "above":
        return above(s, o)
    return False
