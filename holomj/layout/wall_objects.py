"""Wall objects (paintings, mirrors, shelves, wall cabinets, TVs, clocks) and ceiling lights.

A wall object hangs on the interior face of one of its room's walls: interior walls are centred
on the room edge, so their face is ``wall_thickness / 2`` into the room; exterior walls grow
outwards, so their face is the room edge itself. The object's back touches the face and its
front (+X) points into the room; its position is the centre of its footprint at its bottom, as
for every SceneObject.

Heights (``WALL_HEIGHTS``): the default z of a kind, given as the height of its centre or of its
bottom. ``height_m`` in a request overrides it (always the bottom). An object ``above`` a floor
object is centred over it, on the wall nearest to it, at least ``ABOVE_GAP_M`` above its top (a
TV sits exactly that far above its stand); a TV whose stand's wall is taken (by a window, say)
goes to the widest free stretch of wall instead, and the placement says so.

============  ===================
kind          default height
============  ===================
painting      centre at 1.5 m
mirror        centre at 1.4 m
clock         centre at 1.8 m
wall_cabinet  bottom at 1.45 m
shelf         bottom at 1.3 m
television    centre at 1.2 m
whiteboard    centre at 1.4 m
other         centre at 1.5 m
============  ===================

Nothing may overlap, in the wall plane, a door with its frame (up to the header, and the whole
height for ``open`` doors; an object deeper than ``DEEP_M``, a wall cabinet, also keeps
``DOOR_SIDE_M`` beside the frame, so that the way through the door stays wide), a window with
its frame, another wall object (checked in 3D, so objects on two walls meeting at a corner are
caught), or floor furniture near the wall that rises above the object's bottom.

A deep object hung lower than ``HEAD_BAND_M`` (a wall cabinet) goes over furniture against the
wall (a counter run) when it can; over open floor it wants ``FRONT_CLEAR_M`` free in front of it
and ``SIDE_CLEAR_M`` beside its ends, so that it narrows no way and cuts off no corner, and one
the prompt did not ask for is left out (with the reason) rather than hung where it would.

Curtains and blinds (kinds ``curtains`` and ``blinds``, ``DRESSING_KINDS``) are the exception:
they hang at the room's windows, sized to them, and are placed before everything else (see
:mod:`holomj.layout.window_dressing`). The geometry of wall faces is in
:mod:`holomj.layout.wall_faces`.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Annotated

import numpy as np
from pydantic import Field
from shapely.geometry import LineString, Point, Polygon

from holomj.errors import SpecError
from holomj.layout.floorplan import normal_type
from holomj.layout.wall_faces import (
    CEILING_GAP_M,
    END_MARGIN_M,
    OBJECT_GAP_M,
    OPENING_MARGIN_M,
    FloorItem,
    PlacedBox,
    Unplaced,
    WallFace,
    WallPlacement,
    face_band,
    face_point,
    face_rect,
    fits_on,
    hits_placed,
    room_faces,
)
from holomj.layout.window_dressing import DRESSING_KINDS, DressingRequest, dress_windows
from holomj.spec.base import FrozenModel, Identifier, PositiveFloat
from holomj.spec.scene import Door, Light, Room, Window
from holomj.spec.walls import Wall, find_wall_for_opening

__all__ = [
    "ABOVE_GAP_M",
    "CEILING_GAP_M",
    "DRESSING_KINDS",
    "END_MARGIN_M",
    "OBJECT_GAP_M",
    "OPENING_MARGIN_M",
    "FloorItem",
    "Unplaced",
    "WallObjectRequest",
    "WallPlacement",
    "ceiling_lights",
    "default_bottom",
    "place_wall_objects",
]

# (reference, metres): reference "centre" or "bottom".
WALL_HEIGHTS: dict[str, tuple[str, float]] = {
    "painting": ("centre", 1.5),
    "mirror": ("centre", 1.4),
    "clock": ("centre", 1.8),
    "wall_cabinet": ("bottom", 1.45),
    "shelf": ("bottom", 1.3),
    "television": ("centre", 1.2),
    "whiteboard": ("centre", 1.4),
}
DEFAULT_WALL_HEIGHT = ("centre", 1.5)
ABOVE_GAP_M = 0.1  # between a floor object's top and the wall object above it
NEAR_WALL_M = 0.3  # furniture closer than object depth + this to the face counts as in front
FREE_STEP_M = 0.05
DEEP_M = 0.2  # a wall object deeper than this (a wall cabinet) narrows the floor below it
HEAD_BAND_M = 2.0  # ... when it hangs lower than this over the floor (the navigation band)
AGAINST_WALL_M = 0.15  # furniture this close to the wall stands under a wall object there
FRONT_CLEAR_M = 0.9  # ... and, over open floor, wants this much free floor in front of it
SIDE_CLEAR_M = 0.5  # ... and beside its ends
DOOR_SIDE_M = 0.6  # kept free beside a door by a deep wall object


class WallObjectRequest(FrozenModel):
    """A wall object to place: size (width along the wall, depth, height), where and how high."""

    id: Identifier
    size: tuple[PositiveFloat, PositiveFloat, PositiveFloat]
    kind: str = Field(default="painting", max_length=64)
    above: Identifier | None = None
    faced_by: Identifier | None = Field(
        default=None, description="Hang where this floor object looks (its front ray)."
    )
    height_m: Annotated[float, Field(ge=0.0, le=20.0)] | None = Field(
        default=None, description="Height of the object's bottom; default by kind."
    )
    optional: bool = Field(
        default=False,
        description="Not asked for: a wall cabinet that would narrow the way is left out.",
    )


def default_bottom(kind: str, height: float) -> float:
    """Default z of the bottom of a wall object of this kind and height."""
    ref, value = WALL_HEIGHTS.get(normal_type(kind), DEFAULT_WALL_HEIGHT)
    return value - height / 2 if ref == "centre" else value


def _blocks(
    face: WallFace,
    doors: Sequence[Door],
    windows: Sequence[Window],
    walls: Sequence[Wall],
    floor: Sequence[FloorItem],
    depth: float,
    wall_height: float,
    skip: str | None,
) -> list[tuple[float, float, float, float, str]]:
    """Rectangles (t0, t1, z0, z1, what) in the face's wall plane that a wall object must avoid."""
    out = []
    for opening in [*doors, *windows]:
        width = opening.effective_width if isinstance(opening, Door) else opening.width
        try:
            wall, t = find_wall_for_opening(walls, opening.rooms, opening.position, width)
        except SpecError:  # an opening elsewhere in the scene: not on this wall
            continue
        if wall.id != face.wall.id:
            continue
        if isinstance(opening, Door):
            z0 = 0.0
            z1 = wall_height if opening.kind == "open" else opening.height + OPENING_MARGIN_M
            what = f"door {opening.id}"
        else:
            z0 = opening.base_height - OPENING_MARGIN_M
            z1 = opening.base_height + opening.height + OPENING_MARGIN_M
            what = f"window {opening.id}"
        half = width / 2 + OPENING_MARGIN_M
        if isinstance(opening, Door) and depth > DEEP_M:
            half += DOOR_SIDE_M  # a deep object beside a door narrows the way through it
        out.append((t - half, t + half, z0, z1, what))
    # Furniture standing near the face, projected onto it.
    near = face_band(face, depth + NEAR_WALL_M)
    for item in floor:
        if item.id == skip or not item.footprint.intersects(near):
            continue
        t0, t1 = _span_along(face, item)
        out.append((t0, t1, 0.0, item.height, f"floor object {item.id}"))
    return out


def _span_along(face: WallFace, item: FloorItem) -> tuple[float, float]:
    """The stretch of the face's wall (t0, t1) that floor object ``item`` stands along."""
    ts = [face.wall.locate(p)[0] for p in item.footprint.exterior.coords]
    return min(ts), max(ts)


def _clear(
    t0: float,
    t1: float,
    z0: float,
    z1: float,
    blocks: Sequence[tuple[float, float, float, float, str]],
) -> str | None:
    for b0, b1, c0, c1, what in blocks:
        if t0 < b1 - 1e-9 and b0 < t1 - 1e-9 and z0 < c1 - 1e-9 and c0 < z1 - 1e-9:
            return what
    return None


def place_wall_objects(
    room: Room,
    walls: Sequence[Wall],
    doors: Sequence[Door],
    windows: Sequence[Window],
    floor_objects: Sequence[FloorItem | tuple[str, Polygon, float]],
    requests: Sequence[WallObjectRequest],
    rng: np.random.Generator,
    *,
    wall_height: float = 2.7,
    wall_thickness: float = 0.1,
) -> tuple[list[WallPlacement], list[Unplaced]]:
    """Hang the requested objects on the walls of ``room``; report the ones that do not fit.

    ``walls`` are the scene's walls (``derive_walls``); ``floor_objects`` are (id, footprint
    polygon, height) of the floor furniture already placed. Requests are handled in order; a
    free object goes to the middle of the widest free stretch at its height (ties broken by
    ``rng``), an object ``above`` a floor object is centred over it or reported.
    """
    floor = [
        f if isinstance(f, FloorItem) else FloorItem(f[0], Polygon(f[1]), float(f[2]))
        for f in floor_objects
    ]
    by_id = {f.id: f for f in floor}
    faces = room_faces(room, walls, wall_thickness)
    placed: list[PlacedBox] = []
    # Curtains and blinds first: they belong at windows, everything else can go elsewhere.
    dressings = [r for r in requests if normal_type(r.kind) in DRESSING_KINDS]
    result, unplaced = dress_windows(
        room,
        faces,
        walls,
        doors,
        windows,
        floor,
        [DressingRequest(r.id, normal_type(r.kind), r.size) for r in dressings],
        placed,
        wall_height=wall_height,
    )
    for req in requests:
        if normal_type(req.kind) in DRESSING_KINDS:
            continue
        width, depth, height = req.size
        if req.above is not None and req.above not in by_id:
            unplaced.append(Unplaced(req.id, f"unknown floor object {req.above!r} to hang above"))
            continue
        base = req.height_m if req.height_m is not None else default_bottom(req.kind, height)
        if req.above is not None:
            top = by_id[req.above].height + ABOVE_GAP_M
            if normal_type(req.kind) == "television" and req.height_m is None:
                base = top
            base = max(base, top)
        base = max(base, 0.0)
        z1 = base + height
        if z1 > wall_height - CEILING_GAP_M + 1e-9:
            unplaced.append(
                Unplaced(
                    req.id, f"top at {z1:.2f} m would reach the wall top ({wall_height:.2f} m)"
                )
            )
            continue
        note = None
        looker = by_id.get(req.faced_by) if req.faced_by is not None else None
        if looker is not None and looker.front is not None and req.above is None:
            outcome = _place_faced(
                req, looker, faces, doors, windows, walls, floor, placed, base, wall_height
            )
            if isinstance(outcome, str):
                fallback = _place_free(
                    req, faces, doors, windows, walls, floor, placed, base, wall_height, rng
                )
                if not isinstance(fallback, str):
                    note = f"{outcome}: hung on the widest free stretch instead"
                    outcome = fallback
        elif req.above is not None:
            outcome = _place_above(
                req,
                by_id[req.above],
                faces,
                doors,
                windows,
                walls,
                floor,
                placed,
                base,
                wall_height,
            )
            if isinstance(outcome, str) and normal_type(req.kind) == "television":
                # A TV is always placed: when the wall over its stand is taken, on the widest
                # free stretch of wall at a TV's height.
                free_base = req.height_m if req.height_m is not None else base
                fallback = _place_free(
                    req, faces, doors, windows, walls, floor, placed, free_base, wall_height, rng
                )
                if not isinstance(fallback, str):
                    note = f"{outcome}: hung on another wall"
                    outcome, base = fallback, free_base
                    z1 = base + height
        else:
            outcome = _place_free(
                req, faces, doors, windows, walls, floor, placed, base, wall_height, rng
            )
        if isinstance(outcome, str):
            unplaced.append(Unplaced(req.id, outcome))
            continue
        face, t = outcome
        foot = face_rect(face, t, width, depth)
        placed.append(PlacedBox(foot, base, z1, face.wall.id, t - width / 2, t + width / 2))
        x, y = face_point(face, t, depth / 2)
        yaw = math.degrees(math.atan2(face.inward[1], face.inward[0]))
        result.append(
            WallPlacement(
                id=req.id,
                x=round(x, 4),
                y=round(y, 4),
                z=round(base, 4),
                yaw_deg=round(yaw, 4) + 0.0,
                wall_id=face.wall.id,
                room=room.id,
                note=note,
            )
        )
    order = {req.id: k for k, req in enumerate(requests)}
    result.sort(key=lambda p: order[p.id])
    unplaced.sort(key=lambda u: order[u.id])
    return result, unplaced


def _place_above(
    req: WallObjectRequest,
    item: FloorItem,
    faces: Sequence[WallFace],
    doors: Sequence[Door],
    windows: Sequence[Window],
    walls: Sequence[Wall],
    floor: Sequence[FloorItem],
    placed: Sequence[PlacedBox],
    base: float,
    wall_height: float,
) -> tuple[WallFace, float] | str:
    width, depth, height = req.size
    centre = item.footprint.centroid
    ranked = []
    for face in faces:
        t, _ = face.wall.locate((centre.x, centre.y))
        if not fits_on(face, t, width):
            continue
        band = face_band(face, 10.0)
        if not band.contains(centre):
            continue
        ranked.append((_dist_to_face(face, centre), face, t))
    if not ranked:
        return f"no wall of the room lies behind {item.id!r} with room for {width:.2f} m"
    ranked.sort(key=lambda r: (r[0], r[1].wall.id))
    _, face, t = ranked[0]
    blocks = _blocks(face, doors, windows, walls, floor, depth, wall_height, item.id)
    hit = _clear(t - width / 2, t + width / 2, base, base + height, blocks)
    if hit is not None:
        return f"the wall above {item.id!r} is taken by {hit}"
    if hits_placed(face_rect(face, t, width, depth), base, base + height, placed):
        return f"the wall above {item.id!r} is taken by another wall object"
    return face, t


FACED_SHIFT_M = 0.6  # how far along the wall a faced object may slide off the ray's point


def _place_faced(
    req: WallObjectRequest,
    looker: FloorItem,
    faces: Sequence[WallFace],
    doors: Sequence[Door],
    windows: Sequence[Window],
    walls: Sequence[Wall],
    floor: Sequence[FloorItem],
    placed: Sequence[PlacedBox],
    base: float,
    wall_height: float,
) -> tuple[WallFace, float] | str:
    """Where the ray from ``looker``'s centre along its front meets a wall face, or as near
    along that face as the object fits (up to ``FACED_SHIFT_M``)."""
    width, depth, height = req.size
    assert looker.front is not None
    c = looker.footprint.centroid
    fx, fy = looker.front
    ray = LineString([(c.x, c.y), (c.x + fx * 50.0, c.y + fy * 50.0)])
    hits = []
    for face in faces:
        segment = LineString([face.wall.point_at(0.0), face.wall.point_at(face.wall.length)])
        point = ray.intersection(segment)
        if point.is_empty or point.geom_type != "Point":
            continue
        hits.append((Point(c.x, c.y).distance(point), face, point))
    if not hits:
        return f"{looker.id!r} looks at no wall"
    _, face, point = min(hits, key=lambda h: (h[0], h[1].wall.id))
    t0, _ = face.wall.locate((point.x, point.y))
    blocks = _blocks(face, doors, windows, walls, floor, depth, wall_height, None)
    for shift in sorted({round(k * 0.05, 2) for k in range(-12, 13)}, key=abs):
        if abs(shift) > FACED_SHIFT_M + 1e-9:
            continue
        t = t0 + shift
        if not fits_on(face, t, width):
            continue
        if _clear(t - width / 2, t + width / 2, base, base + height, blocks) is not None:
            continue
        if hits_placed(face_rect(face, t, width, depth), base, base + height, placed):
            continue
        return face, t
    return f"the wall {looker.id!r} looks at is taken where it looks"


def _dist_to_face(face: WallFace, point: Point) -> float:
    _, off = face.wall.locate((point.x, point.y))
    return abs(off)


def _place_free(
    req: WallObjectRequest,
    faces: Sequence[WallFace],
    doors: Sequence[Door],
    windows: Sequence[Window],
    walls: Sequence[Wall],
    floor: Sequence[FloorItem],
    placed: Sequence[PlacedBox],
    base: float,
    wall_height: float,
    rng: np.random.Generator,
) -> tuple[WallFace, float] | str:
    width, depth, height = req.size
    z0, z1 = base, base + height
    stretches = []
    for face in faces:
        blocks = _blocks(face, doors, windows, walls, floor, depth, wall_height, None)
        spans = [(b0, b1) for b0, b1, c0, c1, _ in blocks if z0 < c1 and c0 < z1]
        spans += [
            (p.t0 - OBJECT_GAP_M, p.t1 + OBJECT_GAP_M)
            for p in placed
            if p.wall_id == face.wall.id and z0 < p.z1 + OBJECT_GAP_M and p.z0 < z1 + OBJECT_GAP_M
        ]
        spans.sort()
        cursor = END_MARGIN_M
        end = face.wall.length - END_MARGIN_M
        for b0, b1 in spans + [(end, end)]:
            if min(b0, end) - cursor >= width - 1e-9:
                stretches.append((cursor, min(b0, end), face))
            cursor = max(cursor, b1)
    if not stretches:
        return f"no free stretch of wall {width:.2f} m wide at {z0:.2f}-{z1:.2f} m"
    low_and_deep = depth > DEEP_M and z0 < HEAD_BAND_M
    if low_and_deep:
        # a wall cabinet hangs over furniture below it (a counter run), not over the floor
        # people and robots walk on, when it can
        for face, t in _over_furniture(stretches, floor, req.size, z0, placed):
            return face, t
    jitter = rng.uniform(0.0, 0.1, size=len(stretches))
    order = sorted(
        range(len(stretches)), key=lambda i: -(stretches[i][1] - stretches[i][0] + float(jitter[i]))
    )
    fenced: tuple[WallFace, float] | None = None  # the first spot that narrows a way past
    for i in order:
        a, b, face = stretches[i]
        candidates = [(a + b) / 2]
        # Slide from the middle towards both ends if another wall object (a corner) is in the way.
        steps = int((b - a - width) / 2 / FREE_STEP_M)
        for k in range(1, steps + 1):
            candidates += [(a + b) / 2 - k * FREE_STEP_M, (a + b) / 2 + k * FREE_STEP_M]
        for t in candidates:
            if hits_placed(face_rect(face, t, width, depth), z0, z1, placed):
                continue
            spot = face, round(t, 3) if _fits_within(round(t, 3), width, a, b) else t
            if low_and_deep and _narrows_way(face, t, width, depth, floor):
                fenced = fenced or spot
                continue
            return spot
    if fenced is not None and not req.optional:
        return fenced
    if fenced is not None:
        return (
            f"no counter to hang over, and every free stretch of wall has furniture within "
            f"{FRONT_CLEAR_M:.1f} m of its front or {SIDE_CLEAR_M:.1f} m of its ends (it would "
            f"narrow the way past it or cut off a corner)"
        )
    return f"every free stretch of wall {width:.2f} m wide is taken by other wall objects"


def _narrows_way(
    face: WallFace, t: float, width: float, depth: float, floor: Sequence[FloorItem]
) -> bool:
    """Whether floor furniture stands within ``FRONT_CLEAR_M`` of the front of a deep wall
    object hung over open floor at ``t``, or within ``SIDE_CLEAR_M`` of its ends (the way
    between them would be too narrow, or the corner beside it cut off)."""
    front = face_rect(face, t, width + 2 * SIDE_CLEAR_M, depth + FRONT_CLEAR_M)
    return any(item.footprint.intersects(front) for item in floor)


def _over_furniture(
    stretches: Sequence[tuple[float, float, WallFace]],
    floor: Sequence[FloorItem],
    size: tuple[float, float, float],
    z0: float,
    placed: Sequence[PlacedBox],
) -> list[tuple[WallFace, float]]:
    """Positions on the free ``stretches`` where a deep wall object of ``size`` hangs wholly
    over floor furniture against the wall that stays below its bottom ``z0`` (the longest run
    of such furniture first, centred on it)."""
    width, depth, height = size
    out: list[tuple[float, WallFace, float]] = []
    for a, b, face in stretches:
        near = face_band(face, AGAINST_WALL_M)  # furniture against the wall: under the object
        spans = sorted(
            _span_along(face, item)
            for item in floor
            if item.height <= z0 and item.footprint.intersects(near)
        )
        merged: list[list[float]] = []
        for u0, u1 in spans:  # counter modules side by side make one run
            if merged and u0 <= merged[-1][1] + 0.02:
                merged[-1][1] = max(merged[-1][1], u1)
            else:
                merged.append([u0, u1])
        for u0, u1 in merged:
            lo, hi = max(a, u0) + width / 2, min(b, u1) - width / 2
            if lo > hi + 1e-9:
                continue
            middle = (lo + hi) / 2
            steps = int((hi - lo) / 2 / FREE_STEP_M)
            for k in [0, *(j for i in range(1, steps + 1) for j in (-i, i))]:
                t = round(middle + k * FREE_STEP_M, 3)
                if not hits_placed(face_rect(face, t, width, depth), z0, z0 + height, placed):
                    out.append((u1 - u0, face, t))
                    break
    out.sort(key=lambda c: -c[0])
    return [(face, t) for _, face, t in out]


def _fits_within(t: float, width: float, a: float, b: float) -> bool:
    return t - width / 2 >= a - 1e-9 and t + width / 2 <= b + 1e-9


# ---------------------------------------------------------------------------------------------
# Ceiling lights

BIG_ROOM_M2 = 25.0
LIGHT_BELOW_CEILING_M = 0.3


def ceiling_lights(rooms: Sequence[Room], wall_height: float) -> list[Light]:
    """Point lights under the ceiling: one per room at its centroid, a 2 x 2 grid in rooms over
    25 m². Total energy grows with the area (0.2 + 0.012 per m², at most 0.8), shared by the
    room's lights."""
    lights: list[Light] = []
    z = max(wall_height - LIGHT_BELOW_CEILING_M, 0.5)
    for room in rooms:
        poly = Polygon(room.polygon)
        total = min(0.8, 0.2 + 0.012 * poly.area)
        if poly.area > BIG_ROOM_M2:
            x0, y0, x1, y1 = poly.bounds
            points = [
                (x0 + (x1 - x0) * fx, y0 + (y1 - y0) * fy)
                for fy in (0.25, 0.75)
                for fx in (0.25, 0.75)
            ]
            points = [_inside(poly, p) for p in points]
        else:
            points = [_inside(poly, (poly.centroid.x, poly.centroid.y))]
        for k, (x, y) in enumerate(points):
            lights.append(
                Light(
                    id=f"light_{room.id}" if len(points) == 1 else f"light_{room.id}_{k}",
                    kind="point",
                    position=(round(x, 4), round(y, 4), round(z, 4)),
                    energy=round(total / len(points), 4),
                    color=(1.0, 0.96, 0.9),
                )
            )
    return lights


def _inside(poly: Polygon, point: tuple[float, float]) -> tuple[float, float]:
    p = Point(point)
    if poly.contains(p):
        return point
    q = poly.representative_point()
    return (q.x, q.y)
