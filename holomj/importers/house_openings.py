"""Doors, windows and open connections of a ProcTHOR or Holodeck house.

An opening is located on its ProcTHOR wall (``holePolygon`` x runs along ``wall0`` from its
polygon's first vertex, y is up; the older schema's ``boundingBox`` likewise) and snapped to
the wall holomj derives from the room polygons. Door kinds: an assetId with ``Doorframe`` ->
``doorframe``; ``Doorway`` -> ``doorway``; no assetId, or one containing ``open`` -> ``open``;
any other asset -> ``doorway``; ``Double`` in the assetId or a hole wider than 1.5 m -> two
leaves. Windows: ``Window_Fixed`` / ``Window_Hung`` / ``Window_Slider`` -> ``fixed`` /
``hung`` / ``slider``. Walls marked ``empty`` and Holodeck ``open_walls`` become ``open``
doors as wide as the shared wall allows (at most 4 m).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from holomj.errors import SpecError
from holomj.importers.common import build_model, clamp_noise, snap_opening
from holomj.importers.jsonpath import Node
from holomj.importers.state import ImportState
from holomj.spec.scene import Door, Window
from holomj.spec.walls import Wall

_DOUBLE_DOOR_WIDTH = 1.5
_TOP_CLEARANCE = 0.06  # openings must stay this far below the wall top
_MAX_NOISE = 0.2  # metres of overflow we clamp (with a warning) rather than reject


@dataclass(frozen=True)
class WallInfo:
    """A ProcTHOR wall: where it runs, its top, room, material, and whether it is empty or
    exterior."""

    start: tuple[float, float]
    end: tuple[float, float]
    top: float
    room: str | None
    material: tuple[str | None, tuple[float, ...] | None]
    empty: bool
    exterior: bool


class HouseOpenings(ImportState):
    """The opening reading of the house importer (a base of it: it needs the ProcTHOR
    ``walls``, the ``derived`` walls, their door ``spans`` and the ``wall_height``)."""

    walls: dict[str, WallInfo]
    derived: list[Wall]
    spans: dict[str, list[tuple[float, float]]]
    wall_height: float

    # -- doors and windows -----------------------------------------------------------------
    def read_openings(self, kind: str) -> list[Any]:
        """The doors or windows (``kind``) of the house."""
        nodes = self.root.opt(kind)
        if nodes is None:
            return []
        return [self._opening(node, kind, i) for i, node in enumerate(nodes.items())]

    def _opening(self, node: Node, kind: str, index: int) -> Door | Window:
        path = f"{kind}[{index}]"
        node.dict()
        raw_id = node.str_("id", None)
        asset = node.str_("assetId", "")
        x0, x1, y0, y1 = _hole(node)
        wall_name = node.str_("wall0")
        wall = self.walls.get(wall_name)
        if wall is None:
            raise node.get("wall0").error(
                f"unknown wall {wall_name!r}", fix="wall0 must be the id of one of 'walls'"
            )
        rooms = self._opening_rooms(node, wall)
        length = math.dist(wall.start, wall.end)
        if length < 1e-6:
            raise node.get("wall0").error(f"wall {wall_name!r} has zero length")
        t = (x0 + x1) / 2
        ux, uy = ((wall.end[0] - wall.start[0]) / length, (wall.end[1] - wall.start[1]) / length)
        centre = (wall.start[0] + ux * t, wall.start[1] + uy * t)
        width = round(x1 - x0, 6)
        try:
            position, placed_wall, along = snap_opening(self.derived, rooms, centre, width)
        except SpecError as err:
            raise err.located(f"{self.source}: {path}") from None
        self.spans.setdefault(placed_wall.id, []).append((along - width / 2, along + width / 2))
        opening_id = self.opening_ids.new(
            raw_id or f"{kind[:-1]}_{index}", f"{path}.id" if raw_id else None
        )
        top_limit = self.wall_height - _TOP_CLEARANCE
        top = y1
        if top_limit < top <= top_limit + _MAX_NOISE:
            self.warnings.append(f"{path}: top lowered from {top:.3f} to {top_limit:.3f} m")
            top = top_limit
        if kind == "doors":
            fields = self._door_fields(node, asset, width, top)
            fields.update(id=opening_id, rooms=rooms, position=position)
            return build_model(Door, fields, self.source, path)
        lower = asset.lower()
        window_kind = "fixed"
        if "hung" in lower:
            window_kind = "hung"
        elif "slid" in lower:
            window_kind = "slider"
        fields = {
            "id": opening_id,
            "kind": window_kind,
            "rooms": rooms,
            "position": position,
            "width": clamp_noise(width, 0.2, 6.0, 0.01),
            "height": clamp_noise(round(top - y0, 6), 0.2, 4.0, 0.01),
            "base_height": clamp_noise(y0, 0.0, 4.0, 0.01),
        }
        return build_model(Window, fields, self.source, path)

    def _door_fields(self, node: Node, asset: str, width: float, top: float) -> dict[str, Any]:
        lower = asset.lower()
        if not asset or "open" in lower.replace("openable", ""):
            door_kind = "open"
        elif "doorframe" in lower:
            door_kind = "doorframe"
        else:
            door_kind = "doorway"
        double = "double" in lower or width > _DOUBLE_DOOR_WIDTH
        return {
            "kind": door_kind,
            "leaves": "double" if double else "single",
            "width": clamp_noise(width, 0.4, 4.0, 0.01),
            "height": clamp_noise(top, 1.5, 4.0, 0.01),
        }

    def _opening_rooms(self, node: Node, wall: WallInfo) -> list[str]:
        names = [node.str_("room0", None), node.str_("room1", None)]
        known = []
        for name in names:
            room_id = self.room_ids.lookup(name) if name else None
            if room_id is not None and room_id not in known:
                known.append(room_id)
        if not known and wall.room:
            wall_room = self.room_ids.lookup(wall.room)
            if wall_room is not None:
                known.append(wall_room)
        if not known:
            raise node.error(
                f"none of the rooms {names[0]!r}, {names[1]!r} is in 'rooms'",
                fix="room0/room1 must name rooms of the house",
            )
        return known

    def open_walls(self) -> list[Door]:
        """Open connections: ProcTHOR's ``empty`` walls and Holodeck's ``open_walls``."""
        segments: list[tuple[tuple[float, float], tuple[float, float], str]] = []
        for wall_id, wall in self.walls.items():
            if wall.empty and not wall.exterior:
                segments.append((wall.start, wall.end, f"walls[{wall_id!r}]"))
        open_walls = self.root.opt("open_walls")
        if open_walls is not None and open_walls.is_dict():
            seg_nodes = open_walls.opt("segments")
            for seg in seg_nodes.items() if seg_nodes is not None else []:
                ends = seg.items()
                if len(ends) != 2:
                    raise seg.error("expected a segment of two points")
                a, b = (end.vector(2, limit=1e4) for end in ends)
                segments.append(((a[0], a[1]), (b[0], b[1]), seg.path))
        doors: list[Door] = []
        seen: set[tuple[float, float]] = set()
        for start, end, label in segments:
            mid = ((start[0] + end[0]) / 2, (start[1] + end[1]) / 2)
            key = (round(mid[0], 3), round(mid[1], 3))
            if key in seen:
                continue
            seen.add(key)
            door = self._open_door(mid, math.dist(start, end), label)
            if door is not None:
                doors.append(door)
        return doors

    def _open_door(self, mid: tuple[float, float], length: float, label: str) -> Door | None:
        height = min(self.wall_height - _TOP_CLEARANCE, 4.0)
        for wall in self.derived:
            if wall.exterior:
                continue
            t, off = wall.locate(mid)
            if abs(off) > 0.02 or not -0.01 <= t <= wall.length + 0.01:
                continue
            width = min(length, wall.length) - 0.1
            width = min(width, 4.0)
            if width < 0.4 or height < 1.5:
                self.warnings.append(f"{label}: open connection too small to keep; skipped")
                return None
            t = min(max(t, width / 2), wall.length - width / 2)
            spans = self.spans.setdefault(wall.id, [])
            if any(a < t + width / 2 and t - width / 2 < b for a, b in spans):
                self.warnings.append(f"{label}: open connection overlaps a door; skipped")
                return None
            spans.append((t - width / 2, t + width / 2))
            if width < length - 0.1 - 1e-6:
                self.warnings.append(f"{label}: open connection narrowed to {width:.2f} m")
            fields = {
                "id": self.opening_ids.new("open"),
                "kind": "open",
                "rooms": list(wall.rooms),
                "position": wall.point_at(t),
                "width": width,
                "height": height,
            }
            return build_model(Door, fields, self.source, label)
        self.warnings.append(f"{label}: open connection is not on a wall between rooms; skipped")
        return None


def _hole(node: Node) -> tuple[float, float, float, float]:
    """``(x0, x1, y0, y1)`` of an opening in its wall's frame (holePolygon or boundingBox)."""
    hole = node.opt("holePolygon")
    if hole is not None:
        points = hole.items()
        if len(points) < 2:
            raise hole.error("expected at least two corner points")
        xs = [p.dict().num("x", limit=1e4) for p in points]
        ys = [p.num("y", limit=1e4) for p in points]
    else:
        box = node.opt("boundingBox")
        if box is None:
            raise node.error("missing required field 'holePolygon'")
        box.dict()
        lo, hi = box.get("min").dict(), box.get("max").dict()
        xs = [lo.num("x", limit=1e4), hi.num("x", limit=1e4)]
        ys = [lo.num("y", limit=1e4), hi.num("y", limit=1e4)]
    x0, x1, y0, y1 = (round(v, 6) for v in (min(xs), max(xs), min(ys), max(ys)))
    if x1 - x0 < 1e-6 or y1 - y0 < 1e-6:
        raise (hole or node).error("the opening has no area")
    return x0, x1, max(y0, 0.0), y1
