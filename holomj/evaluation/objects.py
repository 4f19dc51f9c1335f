"""What the evaluator knows about a scene's rooms, openings and objects (read by
:mod:`holomj.evaluation.folder`): footprints, fronts, heights."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from shapely.geometry import LineString, Polygon

FLOOR_OBJECT_MIN_H = 0.05  # shorter things (rugs) stand in nobody's way
FLOOR_OBJECT_MAX_BOTTOM = 0.3  # a bottom higher than this is not standing on the floor


@dataclass
class EvaluatedRoom:
    """A room: id, type, polygon, and the id's stem (``bedroom_1`` -> ``bedroom``)."""

    id: str
    type: str
    poly: Polygon
    stem: str


@dataclass
class Opening:
    """A door or window: its segment on the wall line and the normal into each of its rooms."""

    id: str
    kind: str
    rooms: list[str]
    point: tuple[float, float]
    width: float
    base: float
    height: float
    along: tuple[float, float]
    normals: dict[str, tuple[float, float]]
    style: str = ""  # the scene's kind: doorway, doorframe, open; fixed, hung, slider

    @property
    def segment(self) -> LineString:
        """The opening's span on the wall line."""
        (px, py), (ux, uy), h = self.point, self.along, self.width / 2
        return LineString([(px - ux * h, py - uy * h), (px + ux * h, py + uy * h)])

    def zone(self, room: str, depth: float) -> Polygon:
        """The opening-wide rectangle ``depth`` deep in front of it, on ``room``'s side."""
        (ax, ay), (bx, by) = self.segment.coords
        nx, ny = self.normals[room]
        return Polygon(
            [
                (ax, ay),
                (bx, by),
                (bx + nx * depth, by + ny * depth),
                (ax + nx * depth, ay + ny * depth),
            ]
        )


@dataclass
class EvaluatedObject:
    """One object of objects.json with what the evaluator derives from it."""

    id: str
    labels: set[str]
    room: str | None
    fp: Polygon
    center: tuple[float, float]
    yaw: float
    zmin: float
    zmax: float
    support: str | None
    meta: dict[str, Any] | None
    surfaces: list[dict[str, Any]] = field(default_factory=list)
    folder: Path | None = None
    view_sign: float = 1.0
    from_id: bool = False
    category: str = ""
    static: bool = False
    interior_surfaces: list[dict[str, Any]] = field(default_factory=list)

    @property
    def front(self) -> tuple[float, float]:
        """The unit front direction (+X of the asset rotated by yaw)."""
        return (math.cos(math.radians(self.yaw)), math.sin(math.radians(self.yaw)))

    @property
    def view(self) -> tuple[float, float]:
        """Where the object "faces": its front, reversed for work furniture used from its front."""
        fx, fy = self.front
        return (fx * self.view_sign, fy * self.view_sign)

    @property
    def height(self) -> float:
        """World height of its bounding box."""
        return self.zmax - self.zmin

    def extent(self, axis: tuple[float, float]) -> tuple[float, float]:
        """Min and max of the footprint projected on ``axis`` (relative to its centre)."""
        cx, cy = self.center
        values = [(x - cx) * axis[0] + (y - cy) * axis[1] for x, y in self.fp.exterior.coords]
        return min(values), max(values)

    @property
    def is_floor_standing(self) -> bool:
        """On the floor (not resting on another object, not hung on a wall), taller than a rug."""
        return (
            self.support is None
            and self.zmin < FLOOR_OBJECT_MAX_BOTTOM
            and self.height >= FLOOR_OBJECT_MIN_H
        )
