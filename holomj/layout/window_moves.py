"""Make room for a room's defining furniture: move a window that keeps it out, or raise it.

Nothing taller than a window's sill may stand in front of it, so in a small room a window can
leave no wall long enough for a bed. The room's furnishing then lays the room out without that
window and puts the window back (:func:`relocate_window`) where the new layout leaves a stretch
of exterior wall free: clear of doors, other windows and the wall's ends, with nothing taller
than its sill in front of it. When no such stretch exists, the window stays where it was with
its sill raised above what now stands in front of it (:func:`raise_sill`, a high window over a
bed's headboard); only when the wall is too low for that is it left out, and the reason says so.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from shapely.geometry import LineString, Polygon

from holomj.spec.scene import Door, Window
from holomj.spec.walls import Wall

OPENING_GAP_M = 0.3  # a window keeps this from doors, other windows and the wall's ends
FRONT_CLEAR_M = 0.4  # depth in front of a window kept free of anything taller than its sill
STEP_M = 0.05
SILL_CLEARANCE_M = 0.05  # a raised sill stands this much above what is in front of it
MIN_WINDOW_HEIGHT_M = 0.5
WINDOW_TOP_MARGIN_M = 0.2  # from the ceiling
ON_WALL_TOL_M = 0.02


def _spans(wall: Wall, openings: Sequence[Door | Window]) -> list[tuple[float, float]]:
    """The stretches (along ``wall``) the openings standing on it take."""
    taken = []
    for opening in openings:
        width = opening.effective_width if isinstance(opening, Door) else opening.width
        t, off = wall.locate(opening.position)
        if abs(off) <= ON_WALL_TOL_M and -width / 2 <= t <= wall.length + width / 2:
            taken.append((t - width / 2, t + width / 2))
    return taken


def relocate_window(
    window: Window,
    room_id: str,
    room_polygon: Polygon,
    walls: Sequence[Wall],
    doors: Sequence[Door],
    other_windows: Sequence[Window],
    tall_footprints: Sequence[Polygon],
) -> Window | None:
    """``window`` moved to the free stretch of the room's exterior walls nearest its old spot,
    or None when no stretch is free (see the module docstring)."""
    openings: list[Door | Window] = [*doors, *other_windows]
    best: tuple[float, tuple[float, float]] | None = None
    half = window.width / 2
    for wall in walls:
        if not wall.exterior or room_id not in wall.rooms:
            continue
        length = wall.length
        taken = _spans(wall, openings)
        (x0, y0), (x1, y1) = wall.start, wall.end
        ux, uy = (x1 - x0) / length, (y1 - y0) / length
        steps = math.floor((length - 2 * (half + OPENING_GAP_M)) / STEP_M + 1e-9)
        for k in range(max(steps + 1, 0)):
            t = half + OPENING_GAP_M + k * STEP_M
            lo, hi = t - half - OPENING_GAP_M, t + half + OPENING_GAP_M
            if any(a < hi and lo < b for a, b in taken):
                continue
            a = (x0 + ux * (t - half), y0 + uy * (t - half))
            b = (x0 + ux * (t + half), y0 + uy * (t + half))
            front = LineString([a, b]).buffer(FRONT_CLEAR_M, cap_style="flat")
            front = front.intersection(room_polygon)
            if any(front.intersects(f) for f in tall_footprints):
                continue
            centre = (x0 + ux * t, y0 + uy * t)
            cost = math.dist(centre, window.position)
            if best is None or cost < best[0] - 1e-9:
                best = (cost, centre)
    if best is None:
        return None
    x, y = best[1]
    return window.model_copy(update={"position": (round(x, 4), round(y, 4))})


def raise_sill(window: Window, above: float, wall_height: float) -> Window | None:
    """``window`` at its place with its sill :data:`SILL_CLEARANCE_M` above ``above`` metres (a
    bed's headboard), its height cut to stay below the ceiling; None when less than
    :data:`MIN_WINDOW_HEIGHT_M` of window would be left."""
    base = max(window.base_height, above + SILL_CLEARANCE_M)
    height = min(window.height, wall_height - WINDOW_TOP_MARGIN_M - base)
    if height < MIN_WINDOW_HEIGHT_M:
        return None
    return window.model_copy(update={"base_height": round(base, 3), "height": round(height, 3)})
