"""Layout predicates over candidate centres of a new floor object, and the room's openings and
sizes as the layout problem takes them."""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Literal

import numpy as np
import shapely

from holomj.layout import geometry as geo
from holomj.layout.constraints import PLACE_KINDS, Constraint
from holomj.layout.place_relations import place_holds
from holomj.layout.room_problem import (
    LayoutDoor,
    LayoutWindow,
    PreparedRoom,
)
from holomj.spec.scene import SceneSpec


def constraint_holds(
    prep: PreparedRoom,
    c: Constraint,
    xs: np.ndarray,
    ys: np.ndarray,
    k: int,
    new: int,
    poses: dict[int, tuple[float, float, int]],
) -> np.ndarray:
    """Whether constraint ``c`` on the new object holds at each candidate centre."""
    item = prep.items[new]
    th = prep.thresholds
    if c.kind == "edge":
        return np.asarray(geo.edge_holds(xs, ys, k, item.size, prep.walls, th.edge_tolerance))
    if c.kind in PLACE_KINDS:
        return np.asarray(
            place_holds(c.kind, xs, ys, k, item.size, prep.anchors, th.edge_tolerance)
        )
    if c.kind == "middle":
        hx, hy = geo.half_extents(item.width, item.depth, k)
        boxes = shapely.box(xs - hx, ys - hy, xs + hx, ys + hy)
        return np.asarray(shapely.distance(prep.room.exterior, boxes)) >= th.middle_gap - geo.EPS
    assert c.target is not None  # a relation's target is checked when the wish is made
    j = prep.index[c.target]
    xt, yt, kt = poses[j]
    target = prep.items[j]
    return np.asarray(
        geo.relation_holds(c.kind, xs, ys, k, item.size, xt, yt, kt, target.size, th), dtype=bool
    )


def opening_on_edge(
    ring: Sequence[Sequence[float]], xy: Sequence[float], width: float, least: float
) -> tuple[tuple[float, float], float]:
    """An opening at ``xy`` moved onto the nearest edge of the layout polygon ``ring``, as wide
    as it is but no wider than that edge (the inset edge is shorter than the wall: an opening
    as wide as its wall is clipped by the inset)."""
    best: tuple[float, float, float, float, float, float, float] | None = None
    for i in range(len(ring)):
        (ax, ay), (bx, by) = ring[i], ring[(i + 1) % len(ring)]
        length = math.hypot(bx - ax, by - ay)
        if length < 1e-9:
            continue
        tx, ty = (bx - ax) / length, (by - ay) / length
        t = min(max((xy[0] - ax) * tx + (xy[1] - ay) * ty, 0.0), length)
        dist = math.hypot(ax + tx * t - xy[0], ay + ty * t - xy[1])
        if best is None or dist < best[0]:
            best = (dist, ax, ay, tx, ty, t, length)
    assert best is not None  # a polygon has edges
    _, ax, ay, tx, ty, t, length = best
    span = max(min(width, length - 2e-3), least)
    t = min(max(t, span / 2), max(length - span / 2, span / 2))
    return (round(ax + tx * t, 6), round(ay + ty * t, 6)), span


def turned_half_extents(width: float, depth: float, yaw: float) -> tuple[float, float]:
    """Half extents along x and y of a footprint turned by ``yaw``."""
    c, s = abs(math.cos(math.radians(yaw))), abs(math.sin(math.radians(yaw)))
    return depth / 2 * c + width / 2 * s, depth / 2 * s + width / 2 * c


def bounded_extent(value: float) -> float:
    return min(max(value, 0.011), 9.99)


def layout_openings(
    scene: SceneSpec, room_id: str, ring: Sequence[Sequence[float]]
) -> tuple[list[LayoutDoor], list[LayoutWindow]]:
    """The room's doors and windows as the layout problem takes them: on the nearest edge of
    its layout polygon ``ring``, no wider than that edge."""
    doors: list[LayoutDoor] = []
    for door in scene.doors:
        if room_id not in door.rooms:
            continue
        swing: Literal["in", "out", "none"] = "none"
        if door.kind == "doorway":
            swing = "in" if (door.opens_into or door.rooms[0]) == room_id else "out"
        position, span = opening_on_edge(ring, door.position, door.effective_width, 0.4)
        doors.append(
            LayoutDoor(
                id=f"d{len(doors)}", position=position, width=span, swing=swing,
                hinge=door.hinge_side,
            )
        )  # fmt: skip
    windows = []
    for k, w in enumerate(x for x in scene.windows if room_id in x.rooms):
        position, span = opening_on_edge(ring, w.position, w.width, 0.2)
        windows.append(
            LayoutWindow(
                id=f"w{k}", position=position, width=span, sill_height=w.base_height,
                height=w.height,
            )
        )  # fmt: skip
    return doors, windows
