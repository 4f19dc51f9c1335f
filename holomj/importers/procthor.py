"""ProcTHOR and Holodeck house JSON -> holomj SceneSpec.

Supported inputs
----------------
* ProcTHOR schema ``1.0.0`` (``metadata.schema == "1.0.0"``): materials are objects
  ``{"name": ..., "color": {"r", "g", "b"}}``; openings carry ``holePolygon``.
* Older ProcTHOR houses: materials are plain strings, openings may carry ``boundingBox``
  (``{"min": {x, y, z}, "max": {x, y, z}}``) instead of ``holePolygon``.
* Holodeck houses: the 1.0.0 structure plus ``wall_height``, room ids such as ``"living room"``,
  objects with ``object_name``, ``roomId`` and a ``vertices`` footprint in centimetres, small
  objects whose id is ``"<name>|<receptacle id>"``, and ``open_walls.segments`` for open
  connections between rooms.

Fields read: ``rooms[].{id, roomType, floorPolygon, floorMaterial, wallMaterial}``,
``walls[].{id, roomId, polygon, material, color, empty}``, ``doors[]``/``windows[]``
``.{id, assetId, room0, room1, wall0, wall1, holePolygon | boundingBox, openable}``,
``objects[].{id, assetId, position, rotation, kinematic, children, object_name, roomId,
vertices}``, ``proceduralParameters.{lights, ceilingMaterial, ceilingColor}``, ``wall_height``,
``open_walls``. Everything else (agent, skybox, metadata...) is ignored.

Conventions (see :mod:`holomj.importers.frames`)
-----------------------------------------------
* holomj ``(X, Y, Z) = (unity x, unity z, unity y)``; ``yaw_deg = 90 - rotation.y``; a non-zero
  ``rotation.x``/``rotation.z`` gives a full ``quat`` instead.
* What an object is and how big: an assetId in the AI2-THOR table
  (:mod:`holomj.importers.thor_assets`, 1,653 assets) gives its THOR type, hence its holomj
  category (``holomj/data/thor_types.json``), and its true bounding box (THOR ``(width, height,
  depth)`` -> holomj ``(depth, width, height)`` in the object's own frame). The stand-in asset
  is then scaled to that box within the limits of :mod:`holomj.importers.substitute` (else a
  box of that size). Other assetIds: the THOR type spelled by the assetId or the id, with a
  typical size (no scaling). Holodeck objects (Objaverse uids) stand in with a model of their
  own kind at their authored size (:mod:`holomj.importers.object_kinds`); THOR's L- and
  U-shaped countertops become counter runs (:mod:`holomj.importers.counter_shapes`). Ids of
  the 0.0.1 schema (``4|2|4``, ``small|4|1``) never name a category.
* An object's ProcTHOR ``position`` is the centre of its bounding box; holomj wants the centre of
  the footprint at the bottom, so ``z = unity y - height / 2`` with the height of the asset used.
  The source's bottom comes from the true (THOR) height, so an object that stood on the floor
  (or on its parent's top) in the source is put on the floor (or on the stand-in parent's top).
* Walls: holomj derives walls from the room polygons, so ProcTHOR walls only serve to locate
  openings (``holePolygon`` x runs along ``wall0`` from its polygon's first vertex, y is up),
  to give each room its wall material (the most common one of its walls) and the wall height
  (their highest point, or Holodeck's ``wall_height``). Imported scenes use thin walls,
  ``wall_thickness = 0.05`` m, like ProcTHOR's; exterior walls keep the default thickness
  (they grow outwards, so they take no room space and stop fast objects tunnelling).
* Door kinds: an assetId with ``Doorframe`` -> ``doorframe`` (a frame, no leaf); ``Doorway`` ->
  ``doorway`` (a frame with a leaf); no assetId, or one containing ``open`` -> ``open``; any
  other asset -> ``doorway``. ``Double`` in the assetId or a hole wider than 1.5 m -> two
  leaves. Walls marked ``empty`` (ProcTHOR) and Holodeck ``open_walls`` become ``open``
  doors as wide as the shared wall allows (at most 4 m).
* Windows: ``Window_Fixed`` / ``Window_Hung`` / ``Window_Slider`` -> ``fixed`` / ``hung`` /
  ``slider`` (``fixed`` when the asset says nothing).
* Ids are sanitised (:mod:`holomj.importers.ids`). An id used twice among the rooms, among the
  doors and windows, or among the objects (``children`` included) is an error naming both
  places; ids that only clash once sanitised get a suffix and a warning. Lights with the same
  id are renamed with a warning (they take no space).
"""

from __future__ import annotations

import math
from collections import Counter
from pathlib import PurePath
from typing import Any

from shapely.geometry import Point, Polygon

from holomj.errors import SpecError
from holomj.importers.common import (
    build_model,
    light_kind,
)
from holomj.importers.frames import unity_forward, unity_point
from holomj.importers.holodeck_hints import HolodeckHints
from holomj.importers.house_objects import HouseObjects
from holomj.importers.house_openings import HouseOpenings, WallInfo
from holomj.importers.ids import sanitise
from holomj.importers.jsonpath import Node
from holomj.importers.result import ImportResult
from holomj.library.store import AssetLibrary
from holomj.spec.scene import Light, Room, SceneObject
from holomj.spec.walls import Wall, room_polygon

IMPORT_WALL_THICKNESS = 0.05
DEFAULT_WALL_HEIGHT = 2.7


def import_procthor(data: Any, library: AssetLibrary, source: str) -> ImportResult:
    """Import a ProcTHOR (1.0.0 or older) or Holodeck house dictionary.

    ``source`` names the file in error messages and becomes ``SceneSpec.source``. Errors are
    :class:`~holomj.errors.FormatError` (shape of the JSON) or :class:`SpecError` (geometry),
    each naming the source and the JSON path.
    """
    return _ProcthorImport(data, library, source).run()


class _ProcthorImport(HouseObjects, HouseOpenings):
    def __init__(self, data: Any, library: AssetLibrary, source: str) -> None:
        super().__init__(data, library, source)
        self.room_shapes: list[tuple[str, Polygon]] = []
        self.walls: dict[str, WallInfo] = {}
        self.derived: list[Wall] = []
        self.spans: dict[str, list[tuple[float, float]]] = {}
        self.objects: list[SceneObject] = []
        self.wall_height = DEFAULT_WALL_HEIGHT
        self.holodeck = False
        self.hints = HolodeckHints()

    # -- driver ----------------------------------------------------------------------------
    def run(self) -> ImportResult:
        room_nodes = self.root.get("rooms").items()
        if not room_nodes:
            raise self.root.get("rooms").error("a house needs at least one room")
        self._check_ids()
        self.holodeck = self._looks_like_holodeck(room_nodes)
        if self.holodeck:
            self.hints = HolodeckHints.read(self.root.value)
        self._read_walls()
        self.wall_height = self._wall_height()
        self._read_rooms(room_nodes)
        self.derived = self.derive_walls()
        doors = self.read_openings("doors")
        windows = self.read_openings("windows")
        doors += self.open_walls()
        self.read_objects()
        lights = self._read_lights()
        fields = {
            "name": sanitise(PurePath(self.source).stem, "scene")[:128],
            "wall_height": self.wall_height,
            "wall_thickness": IMPORT_WALL_THICKNESS,
            "rooms": self.rooms,
            "doors": doors,
            "windows": windows,
            "objects": self.objects,
            "lights": lights,
            "materials": self.materials.scene_materials,
            "source": self.source,
        }
        return self.result(fields, "holodeck" if self.holodeck else "procthor")

    def _check_ids(self) -> None:
        """Reject ids used twice among the rooms, the openings (doors and windows share holomj's
        namespace) or the objects (nested ``children`` included), naming both places."""
        self.check_scene_ids(self.root.value, children="children")

    def _looks_like_holodeck(self, room_nodes: list[Node]) -> bool:
        if self.root.has("wall_height") or self.root.has("open_walls"):
            return True
        objects = self.root.opt("objects")
        if (
            objects is not None
            and isinstance(objects.value, list)
            and any(isinstance(o, dict) and "object_name" in o for o in objects.value)
        ):
            return True
        return any(isinstance(r.value, dict) and "full_vertices" in r.value for r in room_nodes)

    # -- walls and wall height -------------------------------------------------------------
    def _read_walls(self) -> None:
        walls = self.root.opt("walls")
        if walls is None:
            return
        for node in walls.items():
            node.dict()
            wall_id = node.str_("id")
            points = node.get("polygon").items()
            if len(points) < 2:
                raise node.get("polygon").error("a wall polygon needs at least two points")
            coords = [p.dict().xyz() for p in points]
            start = (coords[0][0], coords[0][2])
            end = max(((c[0], c[2]) for c in coords), key=lambda q: math.dist(q, start))
            room = node.str_("roomId", None)
            self.walls[wall_id] = WallInfo(
                start=start,
                end=end,
                top=max(c[1] for c in coords),
                room=room,
                material=_material_spec(node.opt("material"), node.opt("color")),
                empty=node.bool_("empty", False),
                exterior="exterior" in wall_id.split("|"),
            )

    def _wall_height(self) -> float:
        given = self.root.opt("wall_height")
        if given is not None:
            return given.number()
        tops = [w.top for w in self.walls.values()]
        return max(tops) if tops else DEFAULT_WALL_HEIGHT

    # -- rooms -----------------------------------------------------------------------------
    def _read_rooms(self, room_nodes: list[Node]) -> None:
        ceiling = self._ceiling_material()
        for index, node in enumerate(room_nodes):
            path = f"rooms[{index}]"
            node.dict()
            raw_id = node.str_("id")
            room_id = self.room_ids.new(raw_id, f"{path}.id")
            poly_node = node.get("floorPolygon")
            points = []
            for p in poly_node.items():
                p.dict()
                points.append((p.num("x", limit=1e4), p.num("z", limit=1e4)))
            if len(points) < 3:
                raise poly_node.error("a floor polygon needs at least three points")
            try:
                shape = room_polygon(points)
            except SpecError as err:
                raise err.located(poly_node.where()) from None
            floor_name, floor_rgb = _material_spec(node.opt("floorMaterial"))
            floor = self.materials.resolve(
                floor_name, floor_rgb, "floor_default", f"{path}.floorMaterial"
            )
            wall = self._room_wall_material(raw_id, node, path)
            fields = {
                "id": room_id,
                "type": node.str_("roomType", "room")[:64],
                "polygon": points,
                "floor_material": floor,
                "wall_material": wall,
                "ceiling_material": ceiling,
            }
            self.rooms.append(build_model(Room, fields, self.source, path))
            self.room_shapes.append((room_id, shape))

    def _room_wall_material(self, raw_id: str, node: Node, path: str) -> str:
        specs = [
            w.material
            for w in self.walls.values()
            if w.room == raw_id and not w.exterior and (w.material[0] or w.material[1])
        ]
        if specs:
            counts = Counter(specs)
            best = max(counts.values())
            name, rgb = next(s for s in specs if counts[s] == best)
            return self.materials.resolve(name, rgb, "wall_default", f"walls of {path}")
        name, rgb = _material_spec(node.opt("wallMaterial"))
        return self.materials.resolve(name, rgb, "wall_default", f"{path}.wallMaterial")

    def _ceiling_material(self) -> str:
        params = self.root.opt("proceduralParameters")
        if params is None:
            return "ceiling_default"
        params.dict()
        name, rgb = _material_spec(params.opt("ceilingMaterial"))
        color = params.opt("ceilingColor")
        if rgb is None and color is not None:
            rgb = _rgb(color)
        return self.materials.resolve(
            name, rgb, "ceiling_default", "proceduralParameters.ceilingMaterial"
        )

    def room_at(self, x: float, y: float) -> str | None:
        """The first room whose floor covers the point."""
        point = Point(x, y)
        for room_id, shape in self.room_shapes:
            if shape.covers(point):
                return room_id
        return None

    # -- lights ----------------------------------------------------------------------------
    def _read_lights(self) -> list[Light]:
        params = self.root.opt("proceduralParameters")
        if params is None:
            return []
        params.dict()
        nodes = params.opt("lights")
        if nodes is None:
            return []
        return [self._light(node) for node in nodes.items()]

    def _light(self, node: Node) -> Light:
        node.dict()
        kind = light_kind(node)
        pos = node.opt("position")
        position = unity_point(*pos.dict().xyz()) if pos is not None else (0.0, 0.0, 2.5)
        rot = node.opt("rotation")
        rx = ry = rz = 0.0
        if rot is not None:
            rot.dict()
            rx, ry, rz = rot.num("x", 0.0), rot.num("y", 0.0), rot.num("z", 0.0)
        direction = unity_forward(rx, ry, rz) if kind != "point" else (0.0, 0.0, -1.0)
        if kind == "spot" and rot is None:
            direction = (0.0, 0.0, -1.0)
        energy = min(max(node.num("intensity", 1.0), 0.0), 100.0)
        rgb_node = node.opt("rgb")
        color = _rgb(rgb_node) if rgb_node is not None else (1.0, 1.0, 1.0)
        raw_id = node.str_("id", None)
        fields: dict[str, Any] = {
            "id": self.light_ids.new(raw_id or "light", f"{node.path}.id" if raw_id else None),
            "kind": kind,
            "position": position,
            "direction": tuple(round(d, 9) for d in direction),
            "energy": energy,
            "color": tuple(min(max(c, 0.0), 1.0) for c in color[:3]),
            "cast_shadow": node.has("shadow") and kind == "directional",
        }
        spot = node.opt("spotAngle")
        if kind == "spot" and spot is not None:
            fields["cutoff_deg"] = min(max(spot.number() / 2, 1.0), 90.0)
        return build_model(Light, fields, self.source, node.path)


# -- small readers ---------------------------------------------------------------------------
def _material_spec(
    node: Node | None, color: Node | None = None
) -> tuple[str | None, tuple[float, ...] | None]:
    """A material given as a string (old schema) or ``{"name", "color"}`` (1.0.0). ``color``:
    a colour given beside the material (old-schema walls tint ``PureWhite`` with their own
    ``color``), used when the material brings none."""
    own = color if color is not None and color.is_dict() else None
    if node is None or node.value is None:
        return None, _rgb(own) if own is not None else None
    if isinstance(node.value, str):
        return node.value, _rgb(own) if own is not None else None
    node.dict()
    inner = node.opt("color")
    inner = inner if inner is not None else own
    return node.str_("name", None), _rgb(inner) if inner is not None else None


def _rgb(node: Node) -> tuple[float, ...]:
    node.dict()
    rgb = (node.num("r"), node.num("g"), node.num("b"))
    alpha = node.opt("a")
    return (*rgb, alpha.number()) if alpha is not None else rgb
