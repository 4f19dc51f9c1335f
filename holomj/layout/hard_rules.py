"""The hard rules of a room layout, tested in metres on the final poses.

No overlap, the clearance between objects, inside the room, out of the doors' keep-out zones,
tall objects away from windows, room in front of each object, and a walkable path between the
doors. The solvers, the pocket opener and the post-check of :mod:`holomj.layout.solve` all judge
a layout with :func:`hard_checks`.
"""

from __future__ import annotations

from collections.abc import Mapping

from shapely.geometry import box

from holomj.layout import geometry as geo
from holomj.layout.layout_result import HardChecks
from holomj.layout.room_problem import PreparedRoom


def hard_checks(
    prep: PreparedRoom, poses: Mapping[int, tuple[float, float, int]]
) -> tuple[HardChecks, dict[int, str]]:
    """Test every hard rule in metres; also return, per offending object, the first problem."""
    g = prep.grid
    s = prep.settings
    checks = HardChecks()
    blame: dict[int, str] = {}
    rects = {i: prep.footprint(i, x * g, y * g, k) for i, (x, y, k) in poses.items()}
    ids = sorted(rects)
    room = prep.room.buffer(1e-7)
    for n, i in enumerate(ids):
        a = prep.items[i].id
        for j in ids[n + 1 :]:
            gx, gy = geo.rect_gaps(rects[i], rects[j])
            b = prep.items[j].id
            if gx < -1e-7 and gy < -1e-7:
                checks.overlaps.append(f"{a} overlaps {b}")
                blame.setdefault(j, f"overlaps {a}")
            elif max(gx, gy) < s.clearance_m - 1e-6:
                checks.clearance.append(f"{a} and {b} are {max(gx, gy):.3f} m apart")
                blame.setdefault(j, f"closer than {s.clearance_m:g} m to {a}")
        shape = box(*rects[i])
        if not room.covers(shape):
            checks.outside_room.append(a)
            blame.setdefault(i, "not inside the room")
        for door, zone in zip(prep.problem.doors, prep.door_zones):
            if shape.intersection(zone).area > 1e-9:
                checks.door_zones.append(f"{a} in front of {door.id}")
                blame.setdefault(i, f"in the keep-out zone of {door.id}")
        if prep.items[i].tall:
            for w in prep.items[i].windows:
                window, zone = prep.problem.windows[w], prep.window_zones[w]
                if shape.intersection(zone).area > 1e-9:
                    checks.windows.append(f"{a} blocks {window.id}")
                    blame.setdefault(i, f"taller than the sill of {window.id} and in front of it")
        x, y, k = poses[i]
        if not geo.front_is_clear(
            x * g, y * g, k, prep.items[i].depth, prep.room, s.front_clearance_m
        ):
            checks.facing_wall.append(a)
            blame.setdefault(i, f"faces a wall closer than {s.front_clearance_m:g} m")
    walk = prep.walk.check(list(rects.values()))
    checks.walkable = walk.ok if walk.applicable else None
    checks.walkable_detail = walk.detail
    return checks, blame
