"""Where a prompt puts an object in its room: in a corner, under or by a window, by a door.

These are the layout language's *place* constraints (global: no target object). Their anchors,
the room's convex corners, windows and doors, are computed once per room
(:func:`room_anchors`); the predicates below define what each constraint means, vectorised over
candidate centres like :func:`holomj.layout.geometry.relation_holds`:

* ``corner``: the footprint lies within ``CORNER_TOLERANCE_M`` (or the edge tolerance, if
  smaller) of both walls of a convex corner
  (only corners between walls along x and y, as objects turn in quarter turns);
* ``centre``: the footprint's centre lies within ``CENTRE_REACH_M`` of the room's centre
  (its polygon's centroid) along x and along y;
* ``under_window``: the object has its back to a window's wall, within the edge tolerance, and
  overlaps the window's span by at least ``UNDER_WINDOW_OVERLAP_M`` (or half its own width);
  objects taller than the sill cannot be there (the window zone is a hard rule);
* ``by_window``: the footprint is at most ``BY_WINDOW_GAP_M`` from the window's opening;
* ``by_door``: the footprint is at most ``BY_DOOR_GAP_M`` from the door's opening (the door's
  keep-out zone stays a hard rule, so the object stands beside it);
* ``facing_window`` / ``facing_door``: the ray from the object's centre along its front meets
  the opening (as Holodeck's ``face to`` meets a footprint);
* ``adjacent_to`` (a relation to another object): the footprints are at most
  ``ADJACENT_GAP_M`` apart.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import cast

import numpy as np

from holomj.layout.geometry import (
    ADJACENT_GAP_M,
    EPS,
    FRONT,
    WallSegment,
    half_extents,
    wall_of,
)

BY_WINDOW_GAP_M = 0.4
BY_DOOR_GAP_M = 1.0
UNDER_WINDOW_OVERLAP_M = 0.3
CENTRE_REACH_M = 0.3  # 'centre': the centre at most this far from the room's along x and y
CORNER_TOLERANCE_M = 0.08  # 'corner': tighter than 'edge', so it reads as in the corner


@dataclass(frozen=True)
class Corner:
    """A convex corner at ``(x, y)``; the room lies towards ``+sx`` along x and ``+sy`` along y."""

    x: float
    y: float
    sx: int
    sy: int


@dataclass(frozen=True)
class OpeningSpan:
    """A door or window: its wall, its span along the wall and its opening as a world box."""

    wall: WallSegment
    a0: float
    a1: float
    box: tuple[float, float, float, float]  # xmin, xmax, ymin, ymax

    @property
    def center(self) -> tuple[float, float]:
        """The middle of the opening."""
        x0, x1, y0, y1 = self.box
        return ((x0 + x1) / 2, (y0 + y1) / 2)

    @property
    def half(self) -> tuple[float, float]:
        """Half sizes of the opening's box along x and y."""
        x0, x1, y0, y1 = self.box
        return ((x1 - x0) / 2, (y1 - y0) / 2)


@dataclass(frozen=True)
class Anchors:
    """The corners, windows and doors a room's place constraints refer to."""

    corners: tuple[Corner, ...] = ()
    centre: tuple[float, float] = (0.0, 0.0)
    windows: tuple[OpeningSpan, ...] = ()
    doors: tuple[OpeningSpan, ...] = ()


def room_anchors(
    walls: Sequence[WallSegment],
    centre: tuple[float, float],
    windows: Sequence[tuple[Sequence[float], float]],
    doors: Sequence[tuple[Sequence[float], float]],
) -> Anchors:
    """Anchors of a room from its counter-clockwise walls and openings ``(position, width)``."""
    return Anchors(
        corners=tuple(_convex_corners(walls)),
        centre=centre,
        windows=tuple(_span(walls, p, w) for p, w in windows),
        doors=tuple(_span(walls, p, w) for p, w in doors),
    )


def _convex_corners(walls: Sequence[WallSegment]) -> list[Corner]:
    corners = []
    for n, wall in enumerate(walls):
        prev = walls[n - 1]
        if prev.b != wall.a and math.dist(prev.b, wall.a) > 1e-6:
            continue
        (tx0, ty0), (tx1, ty1) = prev.tangent, wall.tangent
        if tx0 * ty1 - ty0 * tx1 <= 1e-9:  # a right turn or straight on: not convex
            continue
        back = (-tx0, -ty0)  # from the corner along the previous wall, into its span
        ahead = (tx1, ty1)
        dx, dy = back[0] + ahead[0], back[1] + ahead[1]
        if abs(abs(dx) - 1) > 1e-6 or abs(abs(dy) - 1) > 1e-6:
            continue  # not a corner between an x wall and a y wall
        corners.append(Corner(wall.a[0], wall.a[1], round(dx), round(dy)))
    return corners


def _span(walls: Sequence[WallSegment], position: Sequence[float], width: float) -> OpeningSpan:
    wall, along = wall_of(position, walls)
    a0, a1 = along - width / 2, along + width / 2
    (ax, ay), (tx, ty) = wall.a, wall.tangent
    p0 = (ax + tx * a0, ay + ty * a0)
    p1 = (ax + tx * a1, ay + ty * a1)
    box = (min(p0[0], p1[0]), max(p0[0], p1[0]), min(p0[1], p1[1]), max(p0[1], p1[1]))
    return OpeningSpan(wall, a0, a1, box)


def opening_gap(
    x: np.ndarray | float,
    y: np.ndarray | float,
    k: int,
    size: tuple[float, float],
    opening: OpeningSpan,
) -> np.ndarray:
    """Euclidean gap between a footprint (centre, yaw index, ``(width, depth)``) and an opening."""
    hx, hy = half_extents(size[0], size[1], k)
    (cx, cy), (ox, oy) = opening.center, opening.half
    gx = np.maximum(np.abs(np.asarray(x, dtype=float) - cx) - (hx + ox), 0.0)
    gy = np.maximum(np.abs(np.asarray(y, dtype=float) - cy) - (hy + oy), 0.0)
    return np.hypot(gx, gy)


def corner_holds(
    x: np.ndarray | float,
    y: np.ndarray | float,
    k: int,
    size: tuple[float, float],
    corners: Sequence[Corner],
    tolerance: float,
) -> np.ndarray:
    """'corner': the footprint is within ``tolerance`` of both walls of a convex corner."""
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    hx, hy = half_extents(size[0], size[1], k)
    result = np.zeros(np.broadcast(x, y).shape, dtype=bool)
    for c in corners:
        result |= (c.sx * (x - c.x) - hx <= tolerance + EPS) & (
            c.sy * (y - c.y) - hy <= tolerance + EPS
        )
    return result


def under_window_holds(
    x: np.ndarray | float,
    y: np.ndarray | float,
    k: int,
    size: tuple[float, float],
    windows: Sequence[OpeningSpan],
    tolerance: float,
) -> np.ndarray:
    """'under window': back to a window's wall within ``tolerance``, overlapping its span."""
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    fx, fy = FRONT[k]
    hw, hd = size[0] / 2, size[1] / 2
    bx, by = x - fx * hd, y - fy * hd
    result = np.zeros(np.broadcast(x, y).shape, dtype=bool)
    for w in windows:
        if w.wall.facing_k != k:
            continue
        along, off = w.wall.locate(cast(Sequence[float], (bx, by)))  # elementwise on arrays
        need = under_window_overlap(size[0], w)
        overlap = np.minimum(along + hw, w.a1) - np.maximum(along - hw, w.a0)
        result |= (off >= -EPS) & (off <= tolerance + EPS) & (overlap >= need - EPS)
    return result


def under_window_overlap(width: float, window: OpeningSpan) -> float:
    """How much of a window's span an object of ``width`` must cover to stand under it."""
    return min(UNDER_WINDOW_OVERLAP_M, width / 2, (window.a1 - window.a0) / 2)


def facing_holds(
    x: np.ndarray | float,
    y: np.ndarray | float,
    k: int,
    openings: Sequence[OpeningSpan],
) -> np.ndarray:
    """The ray from the centre along the front (yaw index ``k``) meets one of ``openings``."""
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    fx, fy = FRONT[k]
    result = np.zeros(np.broadcast(x, y).shape, dtype=bool)
    for o in openings:
        (cx, cy), (ox, oy) = o.center, o.half
        if fx != 0:  # looking along x: the opening's y span must cover y, and lie ahead
            result |= (np.abs(y - cy) <= oy + EPS) & (fx * (cx - x) >= -ox - EPS)
        else:
            result |= (np.abs(x - cx) <= ox + EPS) & (fy * (cy - y) >= -oy - EPS)
    return result


def place_holds(
    kind: str,
    x: np.ndarray | float,
    y: np.ndarray | float,
    k: int,
    size: tuple[float, float],
    anchors: Anchors,
    edge_tolerance: float,
) -> np.ndarray:
    """Whether a footprint satisfies the place constraint ``kind`` (vectorised over centres)."""
    shape = np.broadcast(np.asarray(x), np.asarray(y)).shape
    if kind == "corner":
        tolerance = min(edge_tolerance, CORNER_TOLERANCE_M)
        return corner_holds(x, y, k, size, anchors.corners, tolerance)
    if kind == "under_window":
        return under_window_holds(x, y, k, size, anchors.windows, edge_tolerance)
    if kind == "centre":
        cx, cy = anchors.centre
        x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
        return (np.abs(x - cx) <= CENTRE_REACH_M + EPS) & (np.abs(y - cy) <= CENTRE_REACH_M + EPS)
    if kind in ("facing_window", "facing_door"):
        return facing_holds(x, y, k, anchors.windows if kind == "facing_window" else anchors.doors)
    if kind in ("by_window", "by_door"):
        openings = anchors.windows if kind == "by_window" else anchors.doors
        limit = BY_WINDOW_GAP_M if kind == "by_window" else BY_DOOR_GAP_M
        result = np.zeros(shape, dtype=bool)
        for opening in openings:
            result |= opening_gap(x, y, k, size, opening) <= limit + EPS
        return result
    raise ValueError(f"not a place constraint: {kind}")


def place_reason(kind: str, holds: bool, anchors: Anchors) -> str:
    """Why a place constraint holds or not, in words."""
    what = {
        "corner": ("corners", anchors.corners, "against both walls of a corner"),
        "centre": ("centre", (anchors.centre,), "at the room's centre"),
        "under_window": ("windows", anchors.windows, "under a window"),
        "by_window": ("windows", anchors.windows, f"within {BY_WINDOW_GAP_M:g} m of a window"),
        "by_door": ("doors", anchors.doors, f"within {BY_DOOR_GAP_M:g} m of a door"),
        "facing_window": ("windows", anchors.windows, "facing a window"),
        "facing_door": ("doors", anchors.doors, "facing a door"),
    }[kind]
    if not what[1]:
        return f"the room has no {what[0]}"
    return what[2] if holds else f"not {what[2]}"


__all__ = [
    "ADJACENT_GAP_M",
    "BY_DOOR_GAP_M",
    "BY_WINDOW_GAP_M",
    "CENTRE_REACH_M",
    "CORNER_TOLERANCE_M",
    "UNDER_WINDOW_OVERLAP_M",
    "Anchors",
    "Corner",
    "OpeningSpan",
    "corner_holds",
    "facing_holds",
    "opening_gap",
    "place_holds",
    "place_reason",
    "room_anchors",
    "under_window_holds",
    "under_window_overlap",
]
