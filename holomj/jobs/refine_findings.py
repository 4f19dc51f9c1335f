"""What the evaluation finds that moving one object can fix, for the refine planners.

- a door whose 1 m zone an object stands in: that object (``doors_clear``);
- a window an object hides: that object (``windows_clear``);
- a room the robot cannot reach, or a pocket of free floor it cannot reach: the movable floor
  object that fences it off: of the objects whose footprints come within the robot's reach
  (radius + two cells) of both the pocket and the reached floor, the smallest (``navigability``).

Each finding is a :class:`~holomj.refinement.finding.Finding`; pockets smaller than
:data:`MIN_POCKET_M2` are ignored.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from holomj.evaluation.report import EvalReport
from holomj.refinement.finding import Finding

MIN_POCKET_M2 = 0.25
MAX_FINDINGS = 12


def _blocker(text: str) -> str:
    """``living_room.sofa_0 (living_room side, 0.40 m2)`` -> ``living_room.sofa_0``."""
    return text.split(" (", 1)[0].strip()


def findings(report: EvalReport) -> list[Finding]:
    """The findings of one evaluation (see the module docstring)."""
    out: list[Finding] = []
    details = report.details
    for row in details.get("doors", []):
        for text in [] if row.get("clear") else row.get("blocking", []):
            out.append(
                Finding(metric="doors_clear", object=_blocker(text), reason=f"blocks {row['door']}")
            )
    for row in details.get("windows", []):
        for text in [] if row.get("clear") else row.get("blocking", []):
            out.append(
                Finding(
                    metric="windows_clear", object=_blocker(text), reason=f"hides {row['window']}"
                )
            )
    out += fences(report.folder)
    seen: set[str] = set()
    unique = []
    for finding in out:
        if finding.object not in seen:
            seen.add(finding.object)
            unique.append(finding)
    return unique[:MAX_FINDINGS]


def fences(folder: str) -> list[Finding]:
    """The objects that fence off unreachable floor (see the module docstring)."""
    from scipy import ndimage
    from shapely import contains_xy

    from holomj.evaluation.folder import MeasuredFolder
    from holomj.evaluation.reachability import robot_reach

    scene = MeasuredFolder(Path(folder))
    grid = robot_reach(scene)
    if grid is None or not grid.entrance_found:
        return []
    pockets = grid.fits & ~grid.reach & (grid.rooms >= 0)
    labels, count = ndimage.label(pockets)
    if not count:
        return []
    xs, ys = grid.centres()
    near_cells = int(np.ceil((grid.radius + 2 * grid.cell) / grid.cell))
    structure = np.ones((2 * near_cells + 1, 2 * near_cells + 1), dtype=bool)
    reached_zone = ndimage.binary_dilation(grid.reach, structure=structure)
    movable = [o for o in scene.objects if o.is_floor_standing and not o.static]
    out = []
    for label in range(1, count + 1):
        pocket = labels == label
        area = float(pocket.sum()) * grid.cell**2
        if area < MIN_POCKET_M2:
            continue
        zone = ndimage.binary_dilation(pocket, structure=structure) & reached_zone
        if not zone.any():
            continue
        candidates = []
        for obj in movable:
            inside = contains_xy(obj.fp.buffer(grid.cell), xs, ys)
            if (inside & zone).any():
                candidates.append((float(obj.fp.area), obj.id))
        if not candidates:
            continue
        where = int(np.argmax(pocket.ravel()))
        x, y = float(xs.ravel()[where]), float(ys.ravel()[where])
        room_index = int(grid.rooms.ravel()[where])
        room = grid.room_names[room_index] if 0 <= room_index < len(grid.room_names) else "?"
        _, object_id = min(candidates)
        out.append(
            Finding(
                metric="navigability",
                object=object_id,
                reason=f"fences off {area:.2f} m2 of floor in {room} near ({x:.2f}, {y:.2f})",
            )
        )
    return out
