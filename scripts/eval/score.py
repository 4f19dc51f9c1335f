"""Prompt-fidelity scorer for holomj scene folders (issue 14), independent of the planner.

It reads only the scene folder (``scene.json``, ``objects.json``, ``assets/*/asset.json`` and their
OBJ meshes, ``report.json``, ``navmap.json``) and one hand-written annotation (a line of
``scripts/eval/prompts_dev.jsonl``), and never imports holomj: names are matched to scene objects
through the scorer's own ``vocabulary.json``, not through the planner's parser. ::

    python scripts/eval/score.py FOLDER --spec scripts/eval/prompts_dev.jsonl --id m001
    python scripts/eval/score.py FOLDER --spec '{"id": "x", "prompt": "...", "objects": [...]}'

Methods (thresholds are the constants below):

- **Names.** An annotation name is normalised (lower case, ``_``/``-`` as spaces, articles and
  ``'s`` dropped), looked up in the vocabulary (names and synonyms, then singular forms) and
  becomes a set of library categories; an unknown name maps to itself (``arcade cabinet`` ->
  ``arcade_cabinet``). A scene object's labels are its ``category`` (objects.json, else its
  asset.json) and, when that is missing or generic (``box``: ``builtin:box`` proxies), the noun of
  its id (``kitchen.arcade_cabinet_0`` -> ``arcade_cabinet``) and the categories the vocabulary
  gives that noun.
- **Counts.** Objects whose labels meet the name's categories (in rooms of the spec's room type
  when given), compared with ``eq``/``ge``. Room totals and room types count scene rooms.
- **Attributes.** ``color``: the colour words of the main phrase of the asset description (up to
  the first "with"/"on"/"in"/",") and the colour of the visual part with the largest surface area
  (its rgba named by hue/saturation/value, and the colour words of its material name).
  ``material``: material words (oak -> wood, chrome -> metal, ...) of the description's main
  phrase and of the largest visual part's material name. ``shape``: description words (round,
  oval, square, rectangular, long, tall, low) or geometry (footprint aspect, height, a top surface
  polygon with 8+ vertices for round). At least n instances (n = the spec's count) must have it.
  Limits: one colour per part, no texture colours, a description naming only a secondary part's
  colour is not seen, proxies (``builtin:box``) have no real colour or material.
- **Relations** (footprints are the asset's size x scale rotated by yaw about the position, else
  the world AABB; front = +X rotated by yaw; walls = room polygon edges, interior walls (shared
  edges) inset by half the wall thickness): near = footprints buffered 5 cm per side closer than
  1.5 m; next to = footprints at most 0.5 m apart; in front of / behind = the subject's centre in
  the object's front / back half-space beyond its face, overlapping it sideways, within 1.5 m;
  facing = the front points at the target's centre within 30 degrees or its ray hits the target's
  footprint (Holodeck); for work furniture used from its front (desks, counters, pianos, ...:
  ``faces_away_from_front`` in the vocabulary) the user looks the other way, so its facing
  direction is the back; across from = both face each other within 45 degrees, or they stand at
  opposite parallel walls; against wall = the back edge within 15 cm of a wall surface and
  parallel to it within 20 degrees; in corner = the footprint within 20 cm of both walls of a
  convex room corner; middle = more than 1 m from every wall, or (small rooms) its centre within
  0.5 m of the room's centroid and more than 0.3 m from every wall; under window = within 60 cm
  of the window's wall, overlapping its span by 30 cm (or half the object's width), top below
  the sill + 30 cm; on = ``support`` in objects.json or resting (within 3 cm) on the object's top
  or a surface, centre over its footprint; above = bottom above the object's top (5 cm slack)
  and footprints within 30 cm, overlapping along an axis; around = at least 2 (and 75 %) of the
  subjects within 0.6 m of one object, on at least 2 of its sides. Subject and object must share
  a room. ``quantifier``: ``any`` (default), ``all`` or ``most`` (75 %) of the subject's
  instances.
- **Absent.** No object of the name; a room-type name means no such room; ``window``/``door``
  mean no such opening.
- **Defining furniture.** Every scene room whose type has a rule in the vocabulary (bedroom: bed;
  bathroom: toilet, washbasin; kitchen: fridge, stove, sink; living room: sofa; office: desk,
  chair; dining room: table, 2 chairs) holds it, and every room type the annotation lists exists.
- **Validation.** ``report.json`` says ``ok``.
- **Doors.** No floor-standing object (taller than 5 cm, bottom below 30 cm, not resting on
  another) overlaps, by more than 25 cm2, the door-wide, 1 m deep zone in front of either side.
- **Reachability.** Free floor = room cells not blocked (navmap.json's obstacles; without a
  navmap, room polygons minus walls and furniture footprints rasterised on a 5 cm grid). A 0.2 m
  robot's centre fits where the nearest blocked cell is at least 0.2 m + half a cell away; the
  share is the fitting cells connected to the entrance over all fitting cells (``coverage``: the
  free floor its body sweeps from there over all free floor).
"""

from __future__ import annotations

import argparse
import colorsys
import json
import math
import re
import sys
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import shapely
from scipy import ndimage
from shapely.geometry import LineString, Point, Polygon, box
from shapely.ops import nearest_points, unary_union

HERE = Path(__file__).resolve().parent
VOCABULARY_FILE = HERE / "vocabulary.json"

BUFFER_M = 0.05  # footprints grown per side for "near" (Holodeck)
NEAR_M = 1.5
NEXT_TO_M = 0.5
FRONT_M = 1.5
FACING_DEG = 30.0
ACROSS_DEG = 45.0
WALL_M = 0.15
WALL_PARALLEL_DEG = 20.0
CORNER_M = 0.2
MIDDLE_M = 1.0
MIDDLE_CENTROID_M = 0.5
MIDDLE_MIN_WALL_M = 0.3
WINDOW_WALL_M = 0.6
WINDOW_OVERLAP_M = 0.3
WINDOW_SILL_SLACK_M = 0.3
ON_M = 0.03
ABOVE_SLACK_M = 0.05
ABOVE_PLAN_M = 0.3
AROUND_M = 0.6
MOST = 0.75
DOOR_ZONE_DEPTH_M = 1.0
DOOR_OVERLAP_M2 = 0.0025
FLOOR_OBJECT_MIN_H = 0.05
FLOOR_OBJECT_MAX_BOTTOM = 0.3
ROBOT_RADIUS_M = 0.2
GRID_M = 0.05
GENERIC_CATEGORIES = {"", "box", "object", "proxy", "unknown"}
RELATIONS = (
    "near",
    "next to",
    "in front of",
    "behind",
    "facing",
    "against wall",
    "in corner",
    "middle",
    "under window",
    "on",
    "above",
    "around",
    "across from",
)
NAVMAP_FREE = ("door", "narrow", "reachable", "unreachable")


# ----------------------------------------------------------------------------- vocabulary


def normalise(name: str) -> str:
    """Lower case, ``_``/``-`` as spaces, no articles, possessives or punctuation."""
    text = name.lower().replace("_", " ").replace("-", " ")
    text = re.sub(r"'s\b|’s\b", "", text)
    text = re.sub(r"[^a-z0-9 ]+", " ", text)
    words = [w for w in text.split() if w not in ("a", "an", "the")]
    return " ".join(words)


def singular_forms(name: str) -> list[str]:
    """Candidate singular forms of ``name`` (its last word made singular by English rules)."""
    words = name.split()
    if not words:
        return []
    last = words[-1]
    forms = []
    if last.endswith("ies") and len(last) > 4:
        forms.append(last[:-3] + "y")
    if last.endswith("ves") and len(last) > 4:
        forms += [last[:-3] + "f", last[:-3] + "fe"]
    if last.endswith("es") and len(last) > 3:
        forms.append(last[:-2])
    if last.endswith("s") and not last.endswith("ss") and len(last) > 2:
        forms.append(last[:-1])
    return [" ".join([*words[:-1], f]) for f in forms]


def slug(name: str) -> str:
    """``arcade cabinet`` -> ``arcade_cabinet`` (how an unknown name is looked for)."""
    return normalise(name).replace(" ", "_")


class Vocabulary:
    """The scorer's own mapping of annotation names to scene categories, room types and words."""

    def __init__(self, data: dict[str, Any]) -> None:
        self.data = data
        self.categories: dict[str, list[str]] = {}
        self.lookup: dict[str, str] = {}
        for canon, entry in data["names"].items():
            key = normalise(canon)
            self.categories[key] = list(entry.get("categories") or [slug(canon)])
            self.lookup[key] = key
            for syn in entry.get("synonyms", []):
                self.lookup.setdefault(normalise(syn), key)
        self.room_lookup: dict[str, str] = {}
        self.room_types: dict[str, list[str]] = {}
        for canon, entry in data["room_types"].items():
            key = normalise(canon)
            self.room_types[key] = [t.lower() for t in entry["types"]]
            self.room_lookup[key] = key
            for syn in entry.get("synonyms", []):
                self.room_lookup.setdefault(normalise(syn), key)
        self.defining: dict[str, list[dict[str, Any]]] = {
            normalise(k): v for k, v in data["defining"].items()
        }
        self.colors = {normalise(k): set(v) for k, v in data["colors"].items()}
        self.materials = {normalise(k): v for k, v in data["materials"].items()}
        self.shapes = {normalise(k): v for k, v in data["shapes"].items()}
        self.faces_away = {c.lower() for c in data.get("faces_away_from_front", [])}

    @classmethod
    def load(cls, path: Path = VOCABULARY_FILE) -> Vocabulary:
        """Read ``vocabulary.json``."""
        return cls(json.loads(Path(path).read_text()))

    def canonical(self, name: str) -> str | None:
        """The vocabulary entry ``name`` (or a singular form of it) belongs to, if any."""
        key = normalise(name)
        for cand in [key, *singular_forms(key)]:
            if cand in self.lookup:
                return self.lookup[cand]
        return None

    def resolve(self, name: str) -> set[str]:
        """The scene categories that count as ``name``."""
        canon = self.canonical(name)
        if canon is not None:
            return set(self.categories[canon])
        key = normalise(name)
        return {slug(key)} | {slug(form) for form in singular_forms(key)}

    def room_canonical(self, name: str) -> str | None:
        """The canonical room type of an annotation's room name, if the vocabulary knows it."""
        key = normalise(name)
        for cand in [key, *singular_forms(key)]:
            if cand in self.room_lookup:
                return self.room_lookup[cand]
        return None

    def room_type_of(self, room: SceneRoom) -> str | None:
        """The first canonical room type of a scene room: by its ``type``, else its id's stem."""
        for value in (room.type, room.stem):
            if not value:
                continue
            for canon, types in self.room_types.items():
                if value.lower() in types:
                    return canon
        return None

    def room_is(self, room: SceneRoom, canon: str) -> bool:
        """Whether a scene room counts as the canonical room type ``canon``."""
        types = self.room_types.get(canon, [canon.replace(" ", "_")])
        return any(v and v.lower() in types for v in (room.type, room.stem))

    def colour_words(self, text: str) -> set[str]:
        """Colour families named in ``text`` (longest words first, each word used once)."""
        return {fam for word in _find_words(text, self.colors) for fam in self.colors[word]}

    def material_words(self, text: str) -> set[str]:
        """Material families named in ``text``."""
        return {self.materials[w] for w in _find_words(text, self.materials)}


def _find_words(text: str, table: dict[str, Any]) -> list[str]:
    """Entries of ``table`` found as whole words in ``text``, longest first, without overlaps."""
    words = normalise(text)
    found = []
    for entry in sorted(table, key=len, reverse=True):
        pattern = r"\b" + re.escape(entry) + r"\b"
        if re.search(pattern, words):
            found.append(entry)
            words = re.sub(pattern, " ", words)
    return found


# ----------------------------------------------------------------------------- scene


@dataclass
class SceneRoom:
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

    @property
    def segment(self) -> LineString:
        """The opening's span on the wall line."""
        (px, py), (ux, uy), h = self.point, self.along, self.width / 2
        return LineString([(px - ux * h, py - uy * h), (px + ux * h, py + uy * h)])


@dataclass
class SceneObject:
    """One object of objects.json with what the scorer derives from it."""

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


class Scene:
    """What the scorer reads from a scene folder."""

    def __init__(self, folder: Path) -> None:
        self.folder = Path(folder)
        self.spec = _read_json(self.folder / "scene.json") or {}
        self.objects_json = _read_json(self.folder / "objects.json") or {}
        self.report = _read_json(self.folder / "report.json")
        self.navmap = _read_json(self.folder / "navmap.json")
        self.wall_t = float(self.spec.get("wall_thickness", 0.1))
        self.rooms = [
            SceneRoom(
                id=r["id"],
                type=str(r.get("type") or ""),
                poly=Polygon(r["polygon"]),
                stem=re.sub(r"_?\d+$", "", r["id"]),
            )
            for r in self.spec.get("rooms", [])
        ]
        self.room_by_id = {r.id: r for r in self.rooms}
        self.assets = self._read_assets()
        self.objects = [self._object(o) for o in self.objects_json.get("objects", [])]
        door_widths = {d["id"]: d.get("width") for d in self.objects_json.get("doors", [])}
        self.doors = [
            self._opening(d, "door", door_widths.get(d["id"])) for d in self.spec.get("doors", [])
        ]
        self.windows = [self._opening(w, "window", None) for w in self.spec.get("windows", [])]

    def _read_assets(self) -> dict[str, tuple[dict[str, Any], Path]]:
        assets = {}
        for path in sorted((self.folder / "assets").glob("*/asset.json")):
            meta = _read_json(path)
            if meta and "id" in meta:
                assets[meta["id"]] = (meta, path.parent)
        return assets

    def _object(self, o: dict[str, Any]) -> SceneObject:
        meta, folder = self.assets.get(o.get("asset", ""), (None, None))
        category = str(o.get("category") or (meta or {}).get("category") or "").lower()
        labels = {category} if category not in GENERIC_CATEGORIES else set()
        from_id = not labels
        if from_id:
            noun = re.sub(r"_?\d+$", "", str(o["id"]).split(".")[-1]).lower()
            labels = {noun} if noun else set()
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
            fp = _oriented_rect((pos[0], pos[1]), size[0] * scale[0], size[1] * scale[1], yaw)
            center = (float(pos[0]), float(pos[1]))
        else:
            fp = box(lo[0], lo[1], hi[0], hi[1])
            center = ((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2)
        return SceneObject(
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
        )

    # -- walls

    def _inset(self, room: SceneRoom, point: Point) -> float:
        """Half the wall thickness where ``point`` (on ``room``'s boundary) is an interior wall."""
        for other in self.rooms:
            if other.id != room.id and other.poly.exterior.distance(point) < 1e-3:
                return self.wall_t / 2
        return 0.0

    def wall_edges(self, room: SceneRoom) -> list[LineString]:
        """The edges of ``room``'s polygon."""
        coords = list(room.poly.exterior.coords)
        return [LineString([a, b]) for a, b in zip(coords[:-1], coords[1:]) if a != b]

    def surface_distance(self, room: SceneRoom, geom: Any, edge: LineString) -> float:
        """Distance from ``geom`` to the wall surface along ``edge``."""
        near = nearest_points(edge, geom)[0]
        return geom.distance(edge) - self._inset(room, near)

    def nearest_wall(self, room: SceneRoom, geom: Any) -> tuple[float, LineString]:
        """The wall surface distance of ``geom`` and the edge it is measured to."""
        return min(
            ((self.surface_distance(room, geom, e), e) for e in self.wall_edges(room)),
            key=lambda t: t[0],
        )

    def room_of(self, obj: SceneObject) -> SceneRoom | None:
        """The object's room (by id, else the room holding its centre)."""
        if obj.room in self.room_by_id:
            return self.room_by_id[obj.room]
        for room in self.rooms:
            if room.poly.contains(Point(obj.center)):
                return room
        return None


def _read_json(path: Path) -> Any:
    try:
        return json.loads(Path(path).read_text())
    except (OSError, ValueError):
        return None


def _oriented_rect(center: tuple[float, float], sx: float, sy: float, yaw: float) -> Polygon:
    c, s = math.cos(math.radians(yaw)), math.sin(math.radians(yaw))
    pts = []
    for dx, dy in ((sx / 2, sy / 2), (-sx / 2, sy / 2), (-sx / 2, -sy / 2), (sx / 2, -sy / 2)):
        pts.append((center[0] + c * dx - s * dy, center[1] + s * dx + c * dy))
    return Polygon(pts)


def _angle_deg(u: tuple[float, float], v: tuple[float, float]) -> float:
    nu, nv = math.hypot(*u), math.hypot(*v)
    if nu < 1e-9 or nv < 1e-9:
        return 180.0
    cos = max(-1.0, min(1.0, (u[0] * v[0] + u[1] * v[1]) / (nu * nv)))
    return math.degrees(math.acos(cos))


def _direction(line: LineString) -> tuple[float, float]:
    (ax, ay), (bx, by) = line.coords[0], line.coords[-1]
    length = math.hypot(bx - ax, by - ay) or 1.0
    return ((bx - ax) / length, (by - ay) / length)


# ----------------------------------------------------------------------------- attributes

_MESH_AREA: dict[Path, float] = {}


def _obj_area(path: Path) -> float:
    """Surface area of an OBJ mesh (0 when it cannot be read)."""
    if path in _MESH_AREA:
        return _MESH_AREA[path]
    verts: list[list[float]] = []
    area = 0.0
    try:
        lines = path.read_text().splitlines()
    except OSError:
        lines = []
    for line in lines:
        if line.startswith("v "):
            verts.append([float(v) for v in line.split()[1:4]])
    arr = np.asarray(verts) if verts else np.zeros((0, 3))
    for line in lines:
        if not line.startswith("f "):
            continue
        idx = [int(tok.split("/")[0]) for tok in line.split()[1:]]
        idx = [i - 1 if i > 0 else len(arr) + i for i in idx]
        for k in range(1, len(idx) - 1):
            a, b, c = arr[idx[0]], arr[idx[k]], arr[idx[k + 1]]
            area += 0.5 * float(np.linalg.norm(np.cross(b - a, c - a)))
    _MESH_AREA[path] = area
    return area


def rgba_colour(rgba: Iterable[float]) -> str:
    """A basic colour name for an rgba (by hue, saturation and value)."""
    r, g, b = list(rgba)[:3]
    h, s, v = colorsys.rgb_to_hsv(r, g, b)
    hue = h * 360.0
    if v < 0.18:
        return "black"
    if s < 0.15:
        return "white" if v > 0.85 else ("black" if v < 0.3 else "grey")
    if s < 0.35 and v > 0.7 and 20.0 <= hue <= 65.0:
        return "beige"
    if hue < 15.0 or hue >= 345.0:
        return "red"
    if hue < 45.0:
        return "orange" if (v > 0.75 and s > 0.6) else "brown"
    if hue < 70.0:
        return "yellow" if v > 0.5 else "brown"
    if hue < 170.0:
        return "green"
    if hue < 260.0:
        return "blue"
    if hue < 300.0:
        return "purple"
    return "pink"


def _main_phrase(description: str) -> str:
    """The description up to its first "with"/"on"/"in"/"under"/"and"/comma clause."""
    text = " " + description.lower() + " "
    cut = len(text)
    for sep in (" with ", " on ", " in ", " under ", " and ", ","):
        pos = text.find(sep)
        if pos > 0:
            cut = min(cut, pos)
    return text[:cut].strip()


def _dominant_part(obj: SceneObject) -> dict[str, Any] | None:
    parts = (obj.meta or {}).get("visual") or []
    if not parts:
        return None
    if len(parts) == 1 or obj.folder is None:
        return parts[0]
    return max(parts, key=lambda p: _obj_area(obj.folder / p.get("mesh", "")))


def object_colours(obj: SceneObject, vocab: Vocabulary) -> set[str]:
    """Colour families of an object: description's main phrase + its largest visual part."""
    main = _main_phrase((obj.meta or {}).get("description", ""))
    colours = vocab.colour_words(main)
    part = _dominant_part(obj)
    if part is not None:
        if part.get("rgba"):
            colours.add(rgba_colour(part["rgba"]))
        colours |= vocab.colour_words(Path(part.get("mesh", "")).stem)
    return colours


def object_materials(obj: SceneObject, vocab: Vocabulary) -> set[str]:
    """Material families: description's main phrase + the largest visual part's name."""
    main = _main_phrase((obj.meta or {}).get("description", ""))
    found = vocab.material_words(main)
    part = _dominant_part(obj)
    if part is not None:
        found |= vocab.material_words(Path(part.get("mesh", "")).stem)
    return found


def object_has_shape(obj: SceneObject, shape: str, vocab: Vocabulary) -> bool:
    """Whether the object has ``shape`` by its description words or its geometry."""
    main = _main_phrase((obj.meta or {}).get("description", ""))
    words = {vocab.shapes[w] for w in _find_words(main, vocab.shapes)}
    lo, hi = obj.extent(obj.front)
    lo2, hi2 = obj.extent((-obj.front[1], obj.front[0]))
    a, b = sorted((hi - lo, hi2 - lo2))
    aspect = b / a if a > 1e-6 else math.inf
    many = max((len(s.get("polygon", [])) for s in obj.surfaces), default=0) >= 8
    roundish = "round" in words or "oval" in words or many
    geometric = {
        "round": roundish and aspect <= 1.25,
        "oval": "oval" in words or (many and aspect > 1.25),
        "square": not roundish and aspect <= 1.15,
        "rectangular": not roundish and aspect > 1.15,
        "long": aspect >= 1.8,
        "tall": obj.height >= 1.5,
        "low": obj.height <= 0.5,
    }
    return shape in words or geometric.get(shape, False)


# ----------------------------------------------------------------------------- relations


@dataclass
class Verdict:
    """Whether one spec holds, and why."""

    held: bool
    reason: str


def _same_room(a: SceneObject, b: SceneObject) -> bool:
    return a.room is None or b.room is None or a.room == b.room


def _near(s: SceneObject, o: SceneObject) -> bool:
    return s.fp.buffer(BUFFER_M).distance(o.fp.buffer(BUFFER_M)) < NEAR_M


def _next_to(s: SceneObject, o: SceneObject) -> bool:
    return s.fp.distance(o.fp) <= NEXT_TO_M


def _in_front(s: SceneObject, o: SceneObject, sign: float = 1.0) -> bool:
    fx, fy = o.front
    f = (fx * sign, fy * sign)
    side = (-f[1], f[0])
    dx, dy = s.center[0] - o.center[0], s.center[1] - o.center[1]
    along = dx * f[0] + dy * f[1]
    face = o.extent(f)[1]
    if along < face - 0.05:
        return False
    lat = dx * side[0] + dy * side[1]
    olo, ohi = o.extent(side)
    slo, shi = s.extent(side)
    if lat + shi < olo or lat + slo > ohi:
        return False
    return s.fp.distance(o.fp) <= FRONT_M


def _faces_point(s: SceneObject, target: tuple[float, float], limit: float) -> bool:
    v = (target[0] - s.center[0], target[1] - s.center[1])
    return _angle_deg(s.view, v) <= limit


def _ray_hits(s: SceneObject, geom: Any) -> bool:
    fx, fy = s.view
    ray = LineString([s.center, (s.center[0] + fx * 30.0, s.center[1] + fy * 30.0)])
    return ray.intersects(geom) and not s.fp.contains(geom)


def _facing(s: SceneObject, o: SceneObject) -> bool:
    return _faces_point(s, o.center, FACING_DEG) or _ray_hits(s, o.fp)


def _wall_side(scene: Scene, obj: SceneObject) -> tuple[float, LineString] | None:
    room = scene.room_of(obj)
    return scene.nearest_wall(room, obj.fp) if room is not None else None


def _across(scene: Scene, s: SceneObject, o: SceneObject) -> bool:
    if _faces_point(s, o.center, ACROSS_DEG) and _faces_point(o, s.center, ACROSS_DEG):
        return True
    ws, wo = _wall_side(scene, s), _wall_side(scene, o)
    if ws is None or wo is None or ws[0] > NEXT_TO_M or wo[0] > NEXT_TO_M:
        return False
    parallel = _angle_deg(_direction(ws[1]), _direction(wo[1]))
    return min(parallel, 180 - parallel) <= 10.0 and ws[1].distance(wo[1]) > 1.0


def _against_wall(scene: Scene, s: SceneObject) -> tuple[bool, str]:
    room = scene.room_of(s)
    if room is None:
        return False, "not in a room"
    f = s.front
    side = (-f[1], f[0])
    back = s.extent(f)[0]
    lo, hi = s.extent(side)
    bx, by = s.center[0] + f[0] * back, s.center[1] + f[1] * back
    edge = LineString(
        [
            (bx + side[0] * lo * 0.8, by + side[1] * lo * 0.8),
            (bx + side[0] * hi * 0.8, by + side[1] * hi * 0.8),
        ]
    )
    best = (math.inf, "")
    for wall in scene.wall_edges(room):
        dist = scene.surface_distance(room, edge, wall)
        angle = _angle_deg(_direction(wall), side)
        angle = min(angle, 180.0 - angle)
        if angle <= WALL_PARALLEL_DEG and dist < best[0]:
            best = (dist, f"back {dist:.2f} m from a wall")
    if best[0] == math.inf:
        return False, "back parallel to no wall"
    return best[0] <= WALL_M, best[1]


def _in_corner(scene: Scene, s: SceneObject) -> tuple[bool, str]:
    room = scene.room_of(s)
    if room is None:
        return False, "not in a room"
    coords = list(room.poly.exterior.coords)[:-1]
    n = len(coords)
    orient = 1.0 if room.poly.exterior.is_ccw else -1.0
    best = math.inf
    for i in range(n):
        a, v, b = coords[i - 1], coords[i], coords[(i + 1) % n]
        cross = (v[0] - a[0]) * (b[1] - v[1]) - (v[1] - a[1]) * (b[0] - v[0])
        if cross * orient <= 1e-9:
            continue  # reflex or straight vertex
        d1 = scene.surface_distance(room, s.fp, LineString([a, v]))
        d2 = scene.surface_distance(room, s.fp, LineString([v, b]))
        best = min(best, max(d1, d2))
    return best <= CORNER_M, f"{best:.2f} m from the farther wall of its nearest corner"


def _middle(scene: Scene, s: SceneObject) -> tuple[bool, str]:
    room = scene.room_of(s)
    if room is None:
        return False, "not in a room"
    dist = scene.nearest_wall(room, s.fp)[0]
    centred = (
        Point(s.center).distance(room.poly.centroid) <= MIDDLE_CENTROID_M
        and dist > MIDDLE_MIN_WALL_M
    )
    return dist > MIDDLE_M or centred, f"{dist:.2f} m from the nearest wall" + (
        ", centred in the room" if centred else ""
    )


def _on(s: SceneObject, o: SceneObject) -> bool:
    if s.support is not None and s.support == o.id:
        return True
    tops = [o.zmax] + [float(x.get("height", -9)) for x in o.surfaces]
    resting = any(abs(s.zmin - t) <= ON_M for t in tops)
    return resting and o.fp.buffer(0.02).contains(Point(s.center)) and s.id != o.id


def _above(s: SceneObject, o: SceneObject) -> bool:
    if s.zmin < o.zmax - ABOVE_SLACK_M or s.fp.distance(o.fp) > ABOVE_PLAN_M:
        return False
    sx0, sy0, sx1, sy1 = s.fp.bounds
    ox0, oy0, ox1, oy1 = o.fp.bounds
    return min(sx1, ox1) - max(sx0, ox0) > 0 or min(sy1, oy1) - max(sy0, oy0) > 0


def _sides_of(o: SceneObject, subjects: list[SceneObject]) -> set[int]:
    sides = set()
    for s in subjects:
        v = (s.center[0] - o.center[0], s.center[1] - o.center[1])
        ang = math.degrees(math.atan2(v[1], v[0])) - o.yaw
        sides.add(int(((ang + 45.0) % 360.0) // 90.0))
    return sides


def _opening_relation(rel: str, s: SceneObject, op: Opening) -> bool:
    """Whether ``s`` is ``rel`` to the door or window ``op``."""
    seg = op.segment
    normal = op.normals.get(s.room or "", next(iter(op.normals.values()), (0.0, 1.0)))
    if rel == "near":
        return s.fp.buffer(BUFFER_M).distance(seg) < NEAR_M
    if rel == "next to":
        return s.fp.distance(seg) <= NEXT_TO_M
    if rel == "facing":
        return _faces_point(s, op.point, FACING_DEG) or _ray_hits(s, seg.buffer(0.05))
    if rel in ("in front of", "under window"):
        dx, dy = s.center[0] - op.point[0], s.center[1] - op.point[1]
        if dx * normal[0] + dy * normal[1] <= 0:
            return False
        lo, hi = s.extent(op.along)
        lat = dx * op.along[0] + dy * op.along[1]
        overlap = min(lat + hi, op.width / 2) - max(lat + lo, -op.width / 2)
        if rel == "in front of":
            return overlap > 0 and s.fp.distance(seg) <= FRONT_M
        need = min(WINDOW_OVERLAP_M, 0.5 * (hi - lo))
        return (
            overlap >= need
            and s.fp.distance(seg) <= WINDOW_WALL_M
            and s.zmax <= op.base + WINDOW_SILL_SLACK_M
        )
    return False


# ----------------------------------------------------------------------------- scoring


class Scorer:
    """Scores one scene folder against one annotation."""

    def __init__(self, folder: Path, spec: dict[str, Any], vocab: Vocabulary | None = None):
        self.scene = Scene(folder)
        self.spec = spec
        self.vocab = vocab or Vocabulary.load()
        for obj in self.scene.objects:
            if obj.from_id:  # a proxy's noun counts as what the vocabulary makes of it
                obj.labels |= {c for label in obj.labels for c in self.vocab.resolve(label)}
            if obj.labels & self.vocab.faces_away:
                obj.view_sign = -1.0

    # -- selection

    def rooms_of_type(self, room_name: str | None) -> list[SceneRoom] | None:
        """Scene rooms of an annotation's room type (None: no restriction)."""
        if not room_name:
            return None
        canon = self.vocab.room_canonical(room_name) or normalise(room_name)
        return [r for r in self.scene.rooms if self.vocab.room_is(r, canon)]

    def instances(self, name: str, room_name: str | None = None) -> list[SceneObject]:
        """Scene objects that count as ``name`` (in rooms of ``room_name`` when given)."""
        cats = self.vocab.resolve(name)
        rooms = self.rooms_of_type(room_name)
        ids = None if rooms is None else {r.id for r in rooms}
        return [o for o in self.scene.objects if o.labels & cats and (ids is None or o.room in ids)]

    def _object_room(self, name: str) -> str | None:
        for o in self.spec.get("objects", []):
            if normalise(o["name"]) == normalise(name):
                return o.get("room")
        return None

    # -- specs

    @staticmethod
    def _count_ok(count: dict[str, int], n: int) -> bool:
        if "eq" in count:
            return n == int(count["eq"])
        return n >= int(count.get("ge", 1))

    @staticmethod
    def _count_text(count: dict[str, int]) -> str:
        return f"eq {count['eq']}" if "eq" in count else f"ge {count.get('ge', 1)}"

    def counts(self) -> list[dict[str, Any]]:
        """Object counts, the room total and room-type counts."""
        out = []
        rooms = self.spec.get("rooms")
        if rooms:
            n = len(self.scene.rooms)
            out.append(
                {
                    "kind": "rooms",
                    "spec": rooms,
                    "found": n,
                    "held": self._count_ok(rooms, n),
                    "reason": f"{n} rooms, expected {self._count_text(rooms)}",
                }
            )
        for rt in self.spec.get("room_types", []):
            found = self.rooms_of_type(rt["type"]) or []
            n = len(found)
            out.append(
                {
                    "kind": "room_type",
                    "spec": rt,
                    "found": n,
                    "held": self._count_ok(rt["count"], n),
                    "reason": f"{n} {rt['type']} rooms ({', '.join(r.id for r in found)}), "
                    f"expected {self._count_text(rt['count'])}",
                }
            )
        for spec in self.spec.get("objects", []):
            found = self.instances(spec["name"], spec.get("room"))
            n = len(found)
            where = f" in {spec['room']}" if spec.get("room") else ""
            out.append(
                {
                    "kind": "object",
                    "spec": spec,
                    "name": spec["name"],
                    "found": n,
                    "held": self._count_ok(spec["count"], n),
                    "reason": f"{n} found{where} ({', '.join(o.id for o in found[:8])}), "
                    f"expected {self._count_text(spec['count'])}",
                }
            )
        return out

    def attributes(self) -> list[dict[str, Any]]:
        """Colour, material and shape specs."""
        out = []
        for spec in self.spec.get("objects", []):
            found = self.instances(spec["name"], spec.get("room"))
            need = max(1, int(spec["count"].get("eq", spec["count"].get("ge", 1))))
            for key, value in (spec.get("attributes") or {}).items():
                have = []
                for o in found:
                    if key == "color":
                        fams = self.vocab.colour_words(value) or {normalise(value)}
                        seen = object_colours(o, self.vocab)
                        ok, what = bool(fams & seen), sorted(seen)
                    elif key == "material":
                        fams = self.vocab.material_words(value) or {normalise(value)}
                        seen = object_materials(o, self.vocab)
                        ok, what = bool(fams & seen), sorted(seen)
                    elif key == "shape":
                        shape = self.vocab.shapes.get(normalise(value), normalise(value))
                        ok, what = object_has_shape(o, shape, self.vocab), []
                    else:
                        ok, what = False, ["unsupported attribute"]
                    have.append((o.id, ok, what))
                n_ok = sum(1 for _, ok, _ in have if ok)
                held = bool(found) and n_ok >= min(need, len(found))
                detail = "; ".join(f"{i}: {'yes' if ok else 'no'} {w}" for i, ok, w in have[:6])
                out.append(
                    {
                        "kind": key,
                        "name": spec["name"],
                        "value": value,
                        "held": held,
                        "reason": f"{n_ok}/{len(found)} {spec['name']} {key} {value}"
                        + (f" ({detail})" if detail else ""),
                    }
                )
        return out

    def relation(self, rel: dict[str, Any]) -> Verdict:
        """One relation spec, quantified over the subject's instances."""
        kind = rel["relation"]
        if kind not in RELATIONS:
            return Verdict(False, f"unknown relation {kind!r}")
        room = rel.get("room") or self._object_room(rel["subject"])
        subjects = self.instances(rel["subject"], room)
        if not subjects:
            return Verdict(
                False, f"no {rel['subject']} in the scene" + (f" ({room})" if room else "")
            )
        target = rel.get("object")
        tnorm = normalise(target) if isinstance(target, str) else None
        quant = rel.get("quantifier", "any")
        if kind == "around":
            return self._around(subjects, rel)
        per: list[tuple[SceneObject, bool, str]] = []
        if kind in ("against wall", "in corner", "middle") or tnorm in ("wall", "walls"):
            for s in subjects:
                if kind == "in corner":
                    ok, why = _in_corner(self.scene, s)
                elif kind == "middle":
                    ok, why = _middle(self.scene, s)
                elif kind == "against wall":
                    ok, why = _against_wall(self.scene, s)
                elif kind in ("near", "next to"):
                    wall = _wall_side(self.scene, s)
                    dist = wall[0] if wall else math.inf
                    limit = NEAR_M if kind == "near" else NEXT_TO_M
                    ok, why = dist < limit, f"{dist:.2f} m from the nearest wall"
                else:
                    ok, why = _against_wall(self.scene, s)
                per.append((s, ok, why))
        elif tnorm in ("window", "windows", "door", "doors", "entrance", "door entrance"):
            ops = self.scene.windows if tnorm.startswith("window") else self.scene.doors
            for s in subjects:
                mine = [op for op in ops if not op.rooms or s.room in op.rooms] or []
                hit = [op.id for op in mine if _opening_relation(kind, s, op)]
                why = f"{kind} {hit[0]}" if hit else f"{kind} none of {len(mine)} {tnorm}(s)"
                per.append((s, bool(hit), why))
        else:
            if not target:
                return Verdict(False, f"relation {kind!r} needs an object")
            objects = self.instances(target, rel.get("object_room") or room)
            if not objects:
                return Verdict(False, f"no {target} in the scene")
            for s in subjects:
                hit = [
                    o.id
                    for o in objects
                    if o.id != s.id and _same_room(s, o) and self._pair(kind, s, o)
                ]
                per.append((s, bool(hit), f"with {hit[0]}" if hit else f"with none of {target}"))
        n_ok = sum(1 for _, ok, _ in per if ok)
        need = {"all": len(per), "most": math.ceil(MOST * len(per))}.get(quant, 1)
        held = n_ok >= need
        detail = "; ".join(f"{s.id}: {why}" for s, _, why in per[:6])
        return Verdict(held, f"{n_ok}/{len(per)} {rel['subject']} ({quant}): {detail}")

    def _pair(self, kind: str, s: SceneObject, o: SceneObject) -> bool:
        if kind == "near":
            return _near(s, o)
        if kind == "next to":
            return _next_to(s, o)
        if kind == "in front of":
            return _in_front(s, o)
        if kind == "behind":
            return _in_front(s, o, -1.0)
        if kind == "facing":
            return _facing(s, o)
        if kind == "across from":
            return _across(self.scene, s, o)
        if kind == "on":
            return _on(s, o)
        if kind == "above":
            return _above(s, o)
        if kind == "under window":
            return False
        return False

    def _around(self, subjects: list[SceneObject], rel: dict[str, Any]) -> Verdict:
        objects = self.instances(rel.get("object") or "", rel.get("room"))
        if not objects:
            return Verdict(False, f"no {rel.get('object')} in the scene")
        best = (0, 0, "")
        for o in objects:
            close = [s for s in subjects if _same_room(s, o) and s.fp.distance(o.fp) <= AROUND_M]
            peers = [s for s in subjects if _same_room(s, o)]
            sides = len(_sides_of(o, close))
            ok = len(close) >= max(2, math.ceil(MOST * len(peers))) and sides >= 2
            if ok:
                return Verdict(True, f"{len(close)}/{len(peers)} around {o.id} on {sides} sides")
            if len(close) > best[0]:
                best = (len(close), sides, o.id)
        return Verdict(
            False, f"at most {best[0]}/{len(subjects)} within {AROUND_M} m of {best[2] or '-'}"
        )

    def relations(self) -> list[dict[str, Any]]:
        """Every relation spec with its verdict."""
        out = []
        for rel in self.spec.get("relations", []):
            v = self.relation(rel)
            out.append({"kind": "relation", "spec": rel, "held": v.held, "reason": v.reason})
        return out

    def absent(self) -> list[dict[str, Any]]:
        """Names that must not appear (objects, room types, windows, doors)."""
        out = []
        for name in self.spec.get("absent", []):
            key = normalise(name)
            if key in ("window", "windows", "door", "doors"):
                ops = self.scene.windows if key.startswith("window") else self.scene.doors
                found = [op.id for op in ops]
            elif self.vocab.canonical(name) is None and self.vocab.room_canonical(name):
                found = [r.id for r in self.rooms_of_type(name) or []]
            else:
                found = [o.id for o in self.instances(name)]
            out.append(
                {
                    "kind": "absent",
                    "name": name,
                    "held": not found,
                    "reason": f"found {', '.join(found[:6])}" if found else "none found",
                }
            )
        return out

    def defining(self) -> list[dict[str, Any]]:
        """Defining furniture of every typed room, and every annotated room type exists."""
        out = []
        for room in self.scene.rooms:
            canon = self.vocab.room_type_of(room)
            rules = self.vocab.defining.get(canon or "")
            if not rules:
                continue
            missing = []
            for rule in rules:
                cats = set().union(*(self.vocab.resolve(n) for n in rule["names"]))
                n = sum(1 for o in self.scene.objects if o.room == room.id and o.labels & cats)
                if n < int(rule.get("ge", 1)):
                    missing.append(f"{'/'.join(rule['names'])} ({n} < {rule.get('ge', 1)})")
            out.append(
                {
                    "kind": "defining",
                    "room": room.id,
                    "room_type": canon,
                    "held": not missing,
                    "reason": "missing " + ", ".join(missing) if missing else "complete",
                }
            )
        for name in self.spec.get("defining", []):
            canon = self.vocab.room_canonical(name) or normalise(name)
            if not any(self.vocab.room_is(r, canon) for r in self.scene.rooms):
                out.append(
                    {
                        "kind": "defining",
                        "room": None,
                        "room_type": canon,
                        "held": False,
                        "reason": f"no {canon} room in the scene",
                    }
                )
        return out

    def validation(self) -> dict[str, Any]:
        """Whether report.json says the scene validated."""
        report = self.scene.report
        if not isinstance(report, dict):
            return {"ok": False, "reason": "no report.json"}
        unstable = [o.get("id") for o in report.get("objects", []) if not o.get("stable", True)]
        reason = (
            "ok" if report.get("ok") else f"not ok; unstable: {', '.join(map(str, unstable[:6]))}"
        )
        return {"ok": bool(report.get("ok")), "reason": reason}

    def doors(self) -> list[dict[str, Any]]:
        """For each door, the furniture overlapping the 1 m deep zone on either side."""
        out = []
        floor = [o for o in self.scene.objects if o.is_floor_standing]
        for door in self.scene.doors:
            blocking = []
            seg = door.segment
            (ax, ay), (bx, by) = seg.coords
            for rid, (nx, ny) in door.normals.items():
                d = DOOR_ZONE_DEPTH_M
                zone = Polygon(
                    [(ax, ay), (bx, by), (bx + nx * d, by + ny * d), (ax + nx * d, ay + ny * d)]
                )
                zone = zone.intersection(self.scene.room_by_id[rid].poly)
                for o in floor:
                    area = o.fp.intersection(zone).area
                    if area > DOOR_OVERLAP_M2:
                        blocking.append(f"{o.id} ({rid} side, {area:.2f} m2)")
            out.append({"door": door.id, "clear": not blocking, "blocking": blocking})
        return out

    def reachability(self) -> dict[str, Any]:
        """Share of free floor a 0.2 m robot reaches from the entrance."""
        return reachability(self.scene)

    def score(self) -> dict[str, Any]:
        """The full record of this scene."""
        counts = self.counts()
        attributes = self.attributes()
        relations = self.relations()
        absent = self.absent()
        defining = self.defining()
        doors = self.doors()

        def tally(rows: list[dict[str, Any]]) -> list[int]:
            return [sum(1 for r in rows if r["held"]), len(rows)]

        return {
            "id": self.spec.get("id"),
            "prompt": self.spec.get("prompt"),
            "difficulty": self.spec.get("difficulty"),
            "scene_type": self.spec.get("scene_type"),
            "folder": str(self.scene.folder),
            "scene_rooms": [
                {"id": r.id, "type": r.type, "as": self.vocab.room_type_of(r)}
                for r in self.scene.rooms
            ],
            "n_objects": len(self.scene.objects),
            "summary": {
                "count": tally(counts),
                "object_count": tally([c for c in counts if c["kind"] == "object"]),
                "room_count": tally([c for c in counts if c["kind"] != "object"]),
                "attribute": tally(attributes),
                "relation": tally(relations),
                "absent": tally(absent),
                "defining": tally(defining),
            },
            "validation": self.validation(),
            "doors_clear": all(d["clear"] for d in doors),
            "reachability": self.reachability(),
            "counts": counts,
            "attributes": attributes,
            "relations": relations,
            "absent": absent,
            "defining": defining,
            "doors": doors,
        }


# ----------------------------------------------------------------------------- reachability


def _decode(rle: Any, total: int) -> np.ndarray:
    runs = json.loads(rle) if isinstance(rle, str) else rle
    values = np.concatenate([np.full(int(n), int(v), dtype=np.int32) for v, n in runs])
    if values.size != total:
        raise ValueError(f"run lengths give {values.size} cells, shape needs {total}")
    return values


def _grid_from_navmap(nav: dict[str, Any]) -> tuple[np.ndarray, np.ndarray, tuple, float]:
    """(free mask, room-label grid, origin, cell) from navmap.json."""
    ny, nx = nav["shape"]
    codes = _decode(nav["cells"], ny * nx).reshape(ny, nx)
    names = nav.get("codes", {})
    free_codes = [names[k] for k in NAVMAP_FREE if k in names]
    free = np.isin(codes, free_codes)
    if "room_cells" in nav:
        rooms = _decode(nav["room_cells"], ny * nx).reshape(ny, nx)
    else:
        rooms = np.where(free, 0, -1)
    door = names.get("door")
    inside = (rooms >= 0) & ~(codes == door if door is not None else False)
    return free, np.where(inside, rooms, -1), tuple(nav["origin"]), float(nav["cell_m"])


def _grid_from_polygons(scene: Scene) -> tuple[np.ndarray, np.ndarray, tuple, float]:
    """(free mask, room-label grid, origin, cell) rasterised from rooms, walls and furniture."""
    union = unary_union([r.poly for r in scene.rooms])
    x0, y0, x1, y1 = union.bounds
    origin = (x0 - 0.5, y0 - 0.5)
    nx = math.ceil((x1 - x0 + 1.0) / GRID_M)
    ny = math.ceil((y1 - y0 + 1.0) / GRID_M)
    xs = origin[0] + (np.arange(nx) + 0.5) * GRID_M
    ys = origin[1] + (np.arange(ny) + 0.5) * GRID_M
    gx, gy = np.meshgrid(xs, ys)
    shared = [
        a.poly.exterior.intersection(b.poly.exterior)
        for i, a in enumerate(scene.rooms)
        for b in scene.rooms[i + 1 :]
    ]
    walls = unary_union([g for g in shared if g.length > 0]).buffer(
        scene.wall_t / 2, cap_style="flat"
    )
    gaps = [d.segment.buffer(scene.wall_t, cap_style="flat") for d in scene.doors]
    walls = walls.difference(unary_union(gaps)) if gaps else walls
    furniture = [
        o.fp for o in scene.objects if o.support is None and o.zmin < 2.0 and o.zmax > 0.02
    ]
    free_geom = union.union(unary_union(gaps) if gaps else union).difference(walls)
    if furniture:
        free_geom = free_geom.difference(unary_union(furniture))
    free = shapely.contains_xy(free_geom, gx, gy)
    rooms = np.full((ny, nx), -1, dtype=np.int32)
    for i, r in enumerate(scene.rooms):
        rooms[shapely.contains_xy(r.poly, gx, gy)] = i
    return free, rooms, origin, GRID_M


def _entrance(scene: Scene) -> tuple[tuple[float, float], tuple[float, float]] | None:
    """The entrance point and the normal into the house."""
    nav = scene.navmap or {}
    ent = nav.get("entrance") or {}
    door = None
    if ent.get("door"):
        door = next((d for d in scene.doors if d.id == ent["door"]), None)
    if door is None:
        door = next((d for d in scene.doors if len(d.rooms) == 1), None)
    if door is None:
        door = scene.doors[0] if scene.doors else None
    if door is None or not door.normals:
        return None
    return door.point, next(iter(door.normals.values()))


def reachability(scene: Scene, radius: float = ROBOT_RADIUS_M) -> dict[str, Any]:
    """Reachable share of the robot's free space (and swept coverage), overall and per room."""
    method = "navmap"
    try:
        if not scene.navmap:
            raise ValueError("no navmap")
        free, rooms, origin, cell = _grid_from_navmap(scene.navmap)
    except (KeyError, ValueError, TypeError):
        if not scene.rooms:
            return {"share": None, "coverage": None, "method": None, "reason": "no rooms"}
        method = "raster"
        free, rooms, origin, cell = _grid_from_polygons(scene)
    clearance = ndimage.distance_transform_edt(free) * cell
    fits = free & (clearance >= radius + cell / 2 - 1e-9)
    floor = free & (rooms >= 0)
    labels, _ = ndimage.label(fits)
    entrance = _entrance(scene)
    seed_label = 0
    if entrance is not None:
        (px, py), (nx_, ny_) = entrance
        best = math.inf
        iy, ix = np.nonzero(fits)
        if iy.size:
            cx = origin[0] + (ix + 0.5) * cell
            cy = origin[1] + (iy + 0.5) * cell
            tx, ty = px + nx_ * 0.4, py + ny_ * 0.4
            dist = np.hypot(cx - tx, cy - ty)
            k = int(np.argmin(dist))
            best = float(dist[k])
            if best <= 1.5:
                seed_label = int(labels[iy[k], ix[k]])
    reach = labels == seed_label if seed_label else np.zeros_like(fits)
    fit_floor = fits & (rooms >= 0)
    swept = ndimage.distance_transform_edt(~reach) * cell <= radius + cell / 2
    n_fit = int(fit_floor.sum())
    share = float((reach & fit_floor).sum() / n_fit) if n_fit else 0.0
    coverage = float((swept & floor).sum() / floor.sum()) if floor.sum() else 0.0
    per_room = {}
    names = (scene.navmap or {}).get("rooms_index") if method == "navmap" else None
    names = names or [r.id for r in scene.rooms]
    for i, name in enumerate(names):
        mask = fit_floor & (rooms == i)
        total = int(mask.sum())
        per_room[name] = round(float((reach & mask).sum() / total), 4) if total else 0.0
    return {
        "share": round(share, 4),
        "coverage": round(coverage, 4),
        "method": method,
        "robot_radius_m": radius,
        "entrance_found": bool(seed_label),
        "per_room": per_room,
    }


# ----------------------------------------------------------------------------- API / CLI


def load_specs(source: str) -> list[dict[str, Any]]:
    """Annotations from a JSON line/object, or a .jsonl/.json file."""
    text = source.strip()
    if text.startswith("{") or text.startswith("["):
        data = json.loads(text)
        return data if isinstance(data, list) else [data]
    path = Path(source)
    raw = path.read_text()
    if path.suffix == ".jsonl":
        return [json.loads(line) for line in raw.splitlines() if line.strip()]
    data = json.loads(raw)
    return data if isinstance(data, list) else [data]


def score_folder(
    folder: Path, spec: dict[str, Any], vocab: Vocabulary | None = None
) -> dict[str, Any]:
    """Score one scene folder against one annotation."""
    return Scorer(Path(folder), spec, vocab).score()


def main(argv: list[str] | None = None) -> int:
    """CLI: print the JSON record of one folder."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folder", type=Path)
    parser.add_argument("--spec", required=True, help="A JSON line, or a .jsonl/.json file.")
    parser.add_argument("--id", help="Which annotation of the file (by its id).")
    parser.add_argument("--vocabulary", type=Path, default=VOCABULARY_FILE)
    args = parser.parse_args(argv)
    specs = load_specs(args.spec)
    if args.id:
        specs = [s for s in specs if s.get("id") == args.id]
    if len(specs) != 1:
        print(f"--spec gives {len(specs)} annotations; pick one with --id", file=sys.stderr)
        return 2
    if not (args.folder / "scene.json").is_file():
        print(f"{args.folder}: no scene.json", file=sys.stderr)
        return 2
    record = score_folder(args.folder, specs[0], Vocabulary.load(args.vocabulary))
    print(json.dumps(record, indent=2))
    return 0


if __name__ == "__main__":
    sys.exit(main())
