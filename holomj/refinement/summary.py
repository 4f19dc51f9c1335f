"""The scene as the refine planners see it: rooms, windows, doors, lights and objects with ids,
categories, rooms, positions and sizes.

The jobs layer builds it from a folder (:func:`holomj.jobs.refine_views.scene_summary`); here
it is plain data with a few look-ups. Positions are metres in the scene's frame (x, y on the
floor, z up); an object's ``size`` is its world-aligned bounding box (x, y, z extents).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from shapely.geometry import Point, Polygon


@dataclass(frozen=True)
class RoomInfo:
    """A room: id, type, floor polygon, and the windows and doors in its walls."""

    id: str
    type: str
    polygon: tuple[tuple[float, float], ...]
    windows: tuple[str, ...] = ()
    doors: tuple[str, ...] = ()

    @property
    def shape(self) -> Polygon:
        """The floor polygon."""
        return Polygon(self.polygon)

    @property
    def area(self) -> float:
        """Floor area in m²."""
        return float(self.shape.area)


@dataclass(frozen=True)
class ObjectInfo:
    """A scene object: id, library category, room, position, yaw, size, what it rests on and
    how it is placed (``floor``, ``wall``, ``ceiling`` or ``object``: a small object)."""

    id: str
    category: str
    room: str | None
    position: tuple[float, float, float]
    yaw_deg: float
    size: tuple[float, float, float]
    support: str | None = None
    placement: str = "floor"
    static: bool = False


@dataclass
class PlannerSceneSummary:
    """What a planner knows of a scene (see the module docstring)."""

    rooms: list[RoomInfo]
    objects: list[ObjectInfo]
    windows: list[dict[str, Any]] = field(default_factory=list)
    doors: list[dict[str, Any]] = field(default_factory=list)
    lights: list[str] = field(default_factory=list)
    wall_height: float = 2.7

    def object(self, object_id: str) -> ObjectInfo | None:
        """The object ``object_id`` (None when the scene has none)."""
        return next((o for o in self.objects if o.id == object_id), None)

    def room(self, room_id: str) -> RoomInfo | None:
        """The room ``room_id`` (None when the scene has none)."""
        return next((r for r in self.rooms if r.id == room_id), None)

    @property
    def ids(self) -> set[str]:
        """Every object id."""
        return {o.id for o in self.objects}

    def of_category(self, categories: set[str], room: str | None = None) -> list[ObjectInfo]:
        """Objects of one of ``categories`` (in ``room`` when given), in scene order."""
        return [
            o for o in self.objects if o.category in categories and (room is None or o.room == room)
        ]

    def room_at(self, x: float, y: float) -> str | None:
        """The room holding the floor point (x, y), if any."""
        point = Point(x, y)
        for room in self.rooms:
            if room.shape.buffer(1e-6).contains(point):
                return room.id
        return None

    @property
    def bounds(self) -> tuple[float, float, float, float]:
        """(xmin, ymin, xmax, ymax) of the rooms."""
        xs = [x for r in self.rooms for x, _ in r.polygon] or [0.0]
        ys = [y for r in self.rooms for _, y in r.polygon] or [0.0]
        return min(xs), min(ys), max(xs), max(ys)

    def to_json(self, *, small: bool = True) -> dict[str, Any]:
        """The summary as JSON data (what a model is shown); ``small``: small objects too."""
        return {
            "wall_height_m": round(self.wall_height, 3),
            "rooms": [
                {
                    "id": r.id,
                    "type": r.type,
                    "polygon": [[round(x, 3), round(y, 3)] for x, y in r.polygon],
                    "area_m2": round(r.area, 2),
                    "windows": list(r.windows),
                    "doors": list(r.doors),
                }
                for r in self.rooms
            ],
            "windows": self.windows,
            "doors": self.doors,
            "lights": self.lights,
            "objects": [
                {
                    "id": o.id,
                    "category": o.category,
                    "room": o.room,
                    "position": [round(v, 3) for v in o.position],
                    "yaw_deg": round(o.yaw_deg, 1),
                    "size_m": [round(v, 3) for v in o.size],
                    **({"on": o.support} if o.support else {}),
                    "placement": o.placement,
                }
                for o in self.objects
                if small or o.support is None
            ],
        }
