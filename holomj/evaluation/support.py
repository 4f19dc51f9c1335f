"""What each object rests on, from its geometry, and whether that is plausible.

**Rests on.** A wall-mounted kind (the vocabulary's ``support.wall_mounted``) within 10 cm of a
wall of its room hangs on the ``wall``. Otherwise an object whose bottom is within 3 cm of the
floor stands on the ``floor``; else on the object whose top (its box's top, a receptacle surface
or an interior shelf of objects.json) lies within 3 cm of its bottom under its centre (the
closest such top; a rug counts as floor); else on the receptacle objects.json says it was
dropped on; else on a ``wall`` within 10 cm, or the ``ceiling`` when its top is within 10 cm of
the wall height; else on nothing.

**Plausible.** On the floor: anything but a ceiling fixture. On a wall: wall-mounted kinds, and
other fixed (static) objects that are not floor furniture. On the ceiling: ceiling fixtures,
and other fixed objects that are not floor furniture. On an object: anything that is neither
floor furniture (``support.floor_furniture``: sofas, beds, chairs, tables, wardrobes, ...: they
stand on the floor or a rug) nor a ceiling fixture, and whose footprint is no larger than what
it rests on (a mug on a table yes, a sofa on a bed no, a chair on a bed no). On nothing: never.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from shapely.geometry import Point, Polygon

from holomj.evaluation.folder import MeasuredFolder
from holomj.evaluation.objects import EvaluatedObject
from holomj.evaluation.vocabulary import Vocabulary

FLOOR_M = 0.03
ON_M = 0.03
CENTRE_SLACK_M = 0.02
WALL_GAP_M = 0.1
CEILING_GAP_M = 0.1
FIT_AREA_RATIO = 1.0


@dataclass(frozen=True)
class Support:
    """What one object rests on (``floor``, ``wall``, ``ceiling``, an object id, or None) and
    whether that is plausible."""

    id: str
    category: str
    rests_on: str | None
    how: str
    plausible: bool
    reason: str

    def to_json(self) -> dict[str, Any]:
        """The record of the report's ``details.support``."""
        return {
            "id": self.id,
            "category": self.category,
            "rests_on": self.rests_on,
            "how": self.how,
            "plausible": self.plausible,
            "reason": self.reason,
        }


def _tops(obj: EvaluatedObject) -> list[tuple[float, Polygon]]:
    """Heights and outlines of the places others may rest on ``obj``."""
    tops = [(obj.zmax, obj.fp)]
    for surface in [*obj.surfaces, *obj.interior_surfaces]:
        poly = surface.get("polygon") or []
        if len(poly) >= 3 and surface.get("height") is not None:
            outline = Polygon(poly)
            if outline.is_valid and outline.area > 0:
                tops.append((float(surface["height"]), outline))
    return tops


def _near_wall(scene: MeasuredFolder, obj: EvaluatedObject) -> bool:
    room = scene.room_of(obj)
    if room is None:
        return False
    return scene.nearest_wall(room, obj.fp)[0] <= WALL_GAP_M


def rests_on(
    scene: MeasuredFolder, obj: EvaluatedObject, vocab: Vocabulary
) -> tuple[str | None, str, float]:
    """(what ``obj`` rests on, how that was found, the area it rests on in m²)."""
    if obj.labels & vocab.wall_mounted and _near_wall(scene, obj):
        return "wall", "wall-mounted kind beside a wall", 0.0
    if obj.zmin <= FLOOR_M:
        return "floor", f"bottom {obj.zmin:.3f} m", 0.0
    centre = Point(obj.center)
    best: tuple[float, EvaluatedObject, Polygon] | None = None
    for other in scene.objects:
        if other is obj:
            continue
        for height, outline in _tops(other):
            gap = abs(obj.zmin - height)
            if gap > ON_M or (best is not None and gap >= best[0]):
                continue
            if outline.buffer(CENTRE_SLACK_M).contains(centre):
                best = (gap, other, outline)
    if best is not None:
        gap, other, outline = best
        if other.labels & vocab.floor_like:
            return "floor", f"on {other.id} (a rug)", 0.0
        return other.id, f"bottom {gap * 100:.1f} cm from its top", outline.area
    by_id = {o.id: o for o in scene.objects}
    if obj.support in by_id:
        return obj.support, "dropped there (objects.json)", by_id[obj.support].fp.area
    if _near_wall(scene, obj):
        return "wall", "hangs beside a wall", 0.0
    if obj.zmax >= scene.wall_height - CEILING_GAP_M:
        return "ceiling", f"top {scene.wall_height - obj.zmax:.2f} m below the ceiling", 0.0
    return None, f"bottom {obj.zmin:.2f} m above the floor, nothing under it", 0.0


def judge(obj: EvaluatedObject, on: str | None, area: float, vocab: Vocabulary) -> tuple[bool, str]:
    """Whether resting on ``on`` (over ``area`` m²) is plausible for ``obj``, and why."""
    furniture = bool(obj.labels & vocab.floor_furniture)
    ceiling = bool(obj.labels & vocab.ceiling_mounted)
    if on is None:
        return False, "rests on nothing"
    if on == "floor":
        return (False, "a ceiling fixture on the floor") if ceiling else (True, "on the floor")
    if on in ("wall", "ceiling"):
        if obj.labels & (vocab.wall_mounted if on == "wall" else vocab.ceiling_mounted):
            return True, f"{on}-mounted"
        if furniture:
            return False, f"floor furniture hanging on the {on}"
        if obj.static:
            return True, f"fixed to the {on}"
        return False, f"hangs on the {on} but is not fixed"
    if furniture:
        return False, f"floor furniture standing on {on}"
    if ceiling:
        return False, f"a ceiling fixture standing on {on}"
    if area > 0 and obj.fp.area > FIT_AREA_RATIO * area:
        return False, f"footprint {obj.fp.area:.2f} m² larger than {on}'s {area:.2f} m²"
    return True, f"on {on}"


def supports(scene: MeasuredFolder, vocab: Vocabulary) -> list[Support]:
    """What every object of ``scene`` rests on, and whether that is plausible."""
    out = []
    for obj in scene.objects:
        on, how, area = rests_on(scene, obj, vocab)
        ok, reason = judge(obj, on, area, vocab)
        category = obj.category or next(iter(sorted(obj.labels)), "")
        out.append(Support(obj.id, category, on, how, ok, reason))
    return out
