"""Reading a scene folder for evaluation: ``scene.json`` (rooms, doors, windows, walls),
``objects.json`` (every object's pose, box, support and surfaces), ``assets/*/asset.json`` (sizes,
descriptions, visual parts), ``report.json`` and ``navmap.json`` when present, and the source
categories of stand-ins from ``import_report.json`` (a ProcTHOR countertop compiled as a box is
still a kitchen counter).

Read-only and lenient: a missing or unreadable file reads as absent, so any holomj folder
(generated, compiled from a holomj scene, a ProcTHOR/Holodeck house or a SceneDef) can be
measured. Checking that a folder *is* a scene is the caller's.
"""

from __future__ import annotations

import json
import math
import re
from pathlib import Path
from typing import Any

from shapely.geometry import LineString, Point, Polygon, box
from shapely.ops import nearest_points

from holomj.evaluation.geometry import oriented_rect
from holomj.evaluation.objects import EvaluatedObject, EvaluatedRoom, Opening
from holomj.evaluation.text import id_noun
from holomj.file_names import ASSETS_DIR, LIBRARY_META

GENERIC_CATEGORIES = {"", "box", "object", "proxy", "unknown"}
DEFAULT_WALL_HEIGHT_M = 2.7


def read_json(path: Path) -> Any:
    """The JSON of ``path``, or None when it is missing or not JSON."""
    try:
        return json.loads(Path(path).read_text())
    except (OSError, ValueError):
        return None


class MeasuredFolder:
    """What the evaluator reads from a scene folder."""

    def __init__(self, folder: Path) -> None:
        self.folder = Path(folder)
        self.spec = read_json(self.folder / "scene.json") or {}
        self.objects_json = read_json(self.folder / "objects.json") or {}
        self.report = read_json(self.folder / "report.json")
        self.navmap = read_json(self.folder / "navmap.json")
        self.wall_t = float(self.spec.get("wall_thickness", 0.1))
        self.wall_height = float(self.spec.get("wall_height") or DEFAULT_WALL_HEIGHT_M)
        self.rooms = [
            EvaluatedRoom(
                id=r["id"],
                type=str(r.get("type") or ""),
                poly=Polygon(r["polygon"]),
                stem=re.sub(r"_?\d+$", "", r["id"]),
            )
            for r in self.spec.get("rooms", [])
        ]
        self.room_by_id = {r.id: r for r in self.rooms}
        self.assets = self._read_assets()
        self.source_categories = self._read_source_categories()
        self.objects = [self._object(o) for o in self.objects_json.get("objects", [])]
        door_widths = {d["id"]: d.get("width") for d in self.objects_json.get("doors", [])}
        self.doors = [
            self._opening(d, "door", door_widths.get(d["id"])) for d in self.spec.get("doors", [])
        ]
        self.windows = [self._opening(w, "window", None) for w in self.spec.get("windows", [])]

    def _read_assets(self) -> dict[str, tuple[dict[str, Any], Path]]:
        assets = {}
        for path in sorted((self.folder / ASSETS_DIR).glob(f"*/{LIBRARY_META}")):
            meta = read_json(path)
            if meta and "id" in meta:
                assets[meta["id"]] = (meta, path.parent)
        return assets

    def _read_source_categories(self) -> dict[str, str]:
        """Object id -> the category its source named, for stand-ins of a compiled house."""
        report = read_json(self.folder / "import_report.json")
        subs = report.get("substitutions") if isinstance(report, dict) else None
        return {
            str(s["object_id"]): str(s["category"]).lower()
            for s in subs or []
            if isinstance(s, dict) and s.get("object_id") and s.get("category")
        }

    def _object(self, o: dict[str, Any]) -> EvaluatedObject:
        meta, folder = self.assets.get(o.get("asset", ""), (None, None))
        category = str(o.get("category") or (meta or {}).get("category") or "").lower()
        labels = {category} if category not in GENERIC_CATEGORIES else set()
        from_id = not labels
        if from_id:
            noun = self.source_categories.get(str(o["id"])) or id_noun(o["id"])
            labels = {noun} if noun else set()
            category = noun or category
        lo, hi = o["aabb"]["min"], o["aabb"]["max"]
        yaw = float(o.get("yaw_deg") or 0.0)
        pos = o.get("position") or [(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, lo[2]]
        size = None
        if meta is not None and meta.get("size"):
            size = meta["size"]
        elif o.get("asset") == "builtin:box":
            size = [1.0, 1.0, 1.0]
        if size is not None:
            scale = o.get("scale", [1.0, 1.0, 1.0])
            scale = [scale] * 3 if isinstance(scale, (int, float)) else scale
            fp = oriented_rect((pos[0], pos[1]), size[0] * scale[0], size[1] * scale[1], yaw)
            center = (float(pos[0]), float(pos[1]))
        else:
            fp = box(lo[0], lo[1], hi[0], hi[1])
            center = ((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2)
        return EvaluatedObject(
            id=str(o["id"]),
            labels=labels,
            room=o.get("room"),
            fp=fp,
            center=center,
            yaw=yaw,
            zmin=float(lo[2]),
            zmax=float(hi[2]),
            support=o.get("support"),
            meta=meta,
            surfaces=o.get("surfaces") or [],
            folder=folder,
            from_id=from_id,
            category=category,
            static=bool(o.get("static")),
            interior_surfaces=o.get("interior_surfaces") or [],
        )

    def _opening(self, d: dict[str, Any], kind: str, width: float | None) -> Opening:
        if width is None:
            width = d.get("width") or (2.0 if d.get("leaves") == "double" else 1.0)
        point = (float(d["position"][0]), float(d["position"][1]))
        rooms = [r for r in d.get("rooms", []) if r in self.room_by_id]
        along = (1.0, 0.0)
        best = math.inf
        for rid in rooms or [r.id for r in self.rooms]:
            coords = list(self.room_by_id[rid].poly.exterior.coords)
            for a, b in zip(coords[:-1], coords[1:]):
                dist = LineString([a, b]).distance(Point(point))
                if dist < best - 1e-9:
                    length = math.dist(a, b) or 1.0
                    best, along = dist, ((b[0] - a[0]) / length, (b[1] - a[1]) / length)
        normals = {}
        for rid in rooms:
            n = (-along[1], along[0])
            probe = Point(point[0] + n[0] * 0.1, point[1] + n[1] * 0.1)
            normals[rid] = n if self.room_by_id[rid].poly.contains(probe) else (-n[0], -n[1])
        return Opening(
            id=str(d["id"]),
            kind=kind,
            rooms=rooms,
            point=point,
            width=float(width),
            base=float(d.get("base_height", 0.0)),
            height=float(d.get("height", 2.1)),
            along=along,
            normals=normals,
            style=str(d.get("kind") or ""),
        )

    # -- walls

    def _inset(self, room: EvaluatedRoom, point: Point) -> float:
        """Half the wall thickness where ``point`` (on ``room``'s boundary) is an interior wall."""
        for other in self.rooms:
            if other.id != room.id and other.poly.exterior.distance(point) < 1e-3:
                return self.wall_t / 2
        return 0.0

    def wall_edges(self, room: EvaluatedRoom) -> list[LineString]:
        """The edges of ``room``'s polygon."""
        coords = list(room.poly.exterior.coords)
        return [LineString([a, b]) for a, b in zip(coords[:-1], coords[1:]) if a != b]

    def surface_distance(self, room: EvaluatedRoom, geom: Any, edge: LineString) -> float:
        """Distance from ``geom`` to the wall surface along ``edge``."""
        near = nearest_points(edge, geom)[0]
        return geom.distance(edge) - self._inset(room, near)

    def nearest_wall(self, room: EvaluatedRoom, geom: Any) -> tuple[float, LineString]:
        """The wall surface distance of ``geom`` and the edge it is measured to."""
        return min(
            ((self.surface_distance(room, geom, e), e) for e in self.wall_edges(room)),
            key=lambda t: t[0],
        )

    def room_of(self, obj: EvaluatedObject) -> EvaluatedRoom | None:
        """The object's room (by id, else the room holding its centre)."""
        if obj.room in self.room_by_id:
            return self.room_by_id[obj.room]
        for room in self.rooms:
            if room.poly.contains(Point(obj.center)):
                return room
        return None
