"""Where on a room's walls one wall object hangs: centred over a floor object
(:func:`place_above`), where a floor object looks (:func:`place_faced`), or on the widest free
stretch of wall at its height (:func:`place_free`: a deep object over furniture against the wall
first, and not where it would narrow the way past it), clear of doors, windows, the furniture in
front of the wall and the wall objects hung before it.

Used by :mod:`holomj.layout.wall_objects`.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from shapely.geometry import LineString, Point

from holomj.errors import SpecError
from holomj.layout.wall_faces import (
    END_MARGIN_M,
    OBJECT_GAP_M,
    OPENING_MARGIN_M,
    FloorItem,
    PlacedBox,
    WallFace,
    WallSite,
    face_band,
    face_rect,
    fits_on,
    hits_placed,
)
from holomj.spec.scene import Door, Window
from holomj.spec.walls import find_wall_for_opening

NEAR_WALL_M = 0.3  # furniture closer than object depth + this to the face counts as in front
FREE_STEP_M = 0.05
DEEP_M = 0.2  # a wall object deeper than this (a wall cabinet) narrows the floor below it
HEAD_BAND_M = 2.0  # ... when it hangs lower than this over the floor (the navigation band)
AGAINST_WALL_M = 0.15  # furniture this close to the wall stands under a wall object there
FRONT_CLEAR_M = 0.9  # ... and, over open floor, wants this much free floor in front of it
SIDE_CLEAR_M = 0.5  # ... and beside its ends
DOOR_SIDE_M = 0.6  # kept free beside a door by a deep wall object


def _blocks(
    face: WallFace, site: WallSite, depth: float, skip: str | None
) -> list[tuple[float, float, float, float, str]]:
    """Rectangles (t0, t1, z0, z1, what) in the face's wall plane that a wall object ``depth``
    deep must avoid (the floor object ``skip`` left out)."""
    out = []
    openings: list[Door | Window] = [*site.doors, *site.windows]
    for opening in openings:
        width = opening.effective_width if isinstance(opening, Door) else opening.width
        try:
            wall, t = find_wall_for_opening(site.walls, opening.rooms, opening.position, width)
        except SpecError:  # an opening elsewhere in the scene: not on this wall
            continue
        if wall.id != face.wall.id:
            continue
        if isinstance(opening, Door):
            z0 = 0.0
            z1 = site.wall_height if opening.kind == "open" else opening.height + OPENING_MARGIN_M
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
    for item in site.floor:
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


def place_above(
    size: tuple[float, float, float], item: FloorItem, site: WallSite, base: float
) -> tuple[WallFace, float] | str:
    """Where an object of ``size`` (width, depth, height) with its bottom at ``base`` hangs
    centred over floor object ``item``, on the nearest wall face behind it, or why not."""
    width, depth, height = size
    centre = item.footprint.centroid
    ranked = []
    for face in site.faces:
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
    blocks = _blocks(face, site, depth, item.id)
    hit = _clear(t - width / 2, t + width / 2, base, base + height, blocks)
    if hit is not None:
        return f"the wall above {item.id!r} is taken by {hit}"
    if hits_placed(face_rect(face, t, width, depth), base, base + height, site.placed):
        return f"the wall above {item.id!r} is taken by another wall object"
    return face, t


FACED_SHIFT_M = 0.6  # how far along the wall a faced object may slide off the ray's point


def place_faced(
    size: tuple[float, float, float], looker: FloorItem, site: WallSite, base: float
) -> tuple[WallFace, float] | str:
    """Where the ray from ``looker``'s centre along its front meets a wall face, or as near
    along that face as an object of ``size`` fits (up to ``FACED_SHIFT_M``)."""
    width, depth, height = size
    assert looker.front is not None
    c = looker.footprint.centroid
    fx, fy = looker.front
    ray = LineString([(c.x, c.y), (c.x + fx * 50.0, c.y + fy * 50.0)])
    hits = []
    for face in site.faces:
        segment = LineString([face.wall.point_at(0.0), face.wall.point_at(face.wall.length)])
        point = ray.intersection(segment)
        if point.is_empty or point.geom_type != "Point":
            continue
        hits.append((Point(c.x, c.y).distance(point), face, point))
    if not hits:
        return f"{looker.id!r} looks at no wall"
    _, face, point = min(hits, key=lambda h: (h[0], h[1].wall.id))
    t0, _ = face.wall.locate((point.x, point.y))
    blocks = _blocks(face, site, depth, None)
    for shift in sorted({round(k * 0.05, 2) for k in range(-12, 13)}, key=abs):
        if abs(shift) > FACED_SHIFT_M + 1e-9:
            continue
        t = t0 + shift
        if not fits_on(face, t, width):
            continue
        if _clear(t - width / 2, t + width / 2, base, base + height, blocks) is not None:
            continue
        if hits_placed(face_rect(face, t, width, depth), base, base + height, site.placed):
            continue
        return face, t
    return f"the wall {looker.id!r} looks at is taken where it looks"


def _dist_to_face(face: WallFace, point: Point) -> float:
    _, off = face.wall.locate((point.x, point.y))
    return abs(off)


def place_free(
    size: tuple[float, float, float],
    optional: bool,
    site: WallSite,
    base: float,
    rng: np.random.Generator,
) -> tuple[WallFace, float] | str:
    """In the middle of the widest free stretch of wall at the object's height (ties broken by
    ``rng``; a deep object over furniture against the wall first), or why nowhere. An
    ``optional`` object is not hung where it would narrow the way past it."""
    floor, placed = site.floor, site.placed
    width, depth, height = size
    z0, z1 = base, base + height
    stretches = []
    for face in site.faces:
        blocks = _blocks(face, site, depth, None)
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
        for face, t in _over_furniture(stretches, floor, size, z0, placed):
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
    if fenced is not None and not optional:
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
