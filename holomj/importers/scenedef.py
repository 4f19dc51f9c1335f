"""3D-Generalist SceneDef JSON -> holomj SceneSpec.

Which schema
------------
3D-Generalist's public repository (github.com/sunfanyunn/3D-Generalist, searched July 2025)
ships only its Omniverse integration and Objaverse preprocessing; the pydantic ``SceneDef``
model of the paper (arXiv 2507.06484) is not published. This module therefore implements the
shape documented in holomj's design brief, which follows the paper's description (a scene is
rooms, objects with placements, materials and lighting). Frame: z up, metres, yaw
counter-clockwise about +Z in degrees, 0 facing +X (the same as holomj)::

    {
      "scenedef": "1.0",                      # optional marker
      "name": "bedroom",                      # optional
      "wall_height": 2.8,                     # optional (else a room's bbox height, else 2.7)
      "room": {...} | "rooms": [{...}, ...],  # one room or several
      "doors": [...], "windows": [...],       # optional
      "objects": [...],
      "lighting": {"lights": [...]} | [...],  # optional
      "materials": {"name": {"color": [r, g, b(, a)]}}   # optional scene materials
    }

A room: ``{"id", "type", "floor": [[x, y], ...]`` or ``"bbox": [[x0, y0(, z0)], [x1, y1(, z1)]]``,
``"floor_material", "wall_material" | "walls": [{"material"}, ...], "ceiling_material"}``
(the most common wall material wins).

A door: ``{"id", "position": [x, y], "width", "height", "kind", "leaves", "rooms"}``; a window:
``{"id", "position": [x, y], "width", "height", "base_height", "kind"}``. ``rooms`` defaults to
the rooms of the wall the position lies on.

An object: ``{"id", "category", "asset" | "asset_id", "bbox_size": [x, y, z], "static",
"material", "placements": [{"position": [x, y, z], "rotation": [rx, ry, rz] | "yaw": deg,
"scale": s | [sx, sy, sz], "on": "<object id>"}]}``. ``position`` is the centre of the
placement's bounding box (``bbox_size`` times ``scale``); holomj stands the asset on the box's
bottom. ``rotation`` is right-handed Euler angles in degrees about x, then y, then z; with
``rx = ry = 0`` it is a yaw of ``rz``. Each placement becomes one holomj object with id
``<id>`` (one placement) or ``<id>_<k>``. Object materials are not supported by holomj assets
and are reported as warnings.

Ids: two rooms, two openings (doors and windows together) or two objects with the same ``id``
are an error naming both places. Ids the importer makes (``<id>_<k>``, a category for an object
without an id) that clash with another id get a ``_2``... suffix; so does an id of the input
that only clashes once sanitised, with a warning.

A light: ``{"id", "type": "point" | "spot" | "directional", "position": [x, y, z],
"direction": [x, y, z], "intensity", "color": [r, g, b]}``.
"""

from __future__ import annotations

from collections import Counter
from pathlib import PurePath
from typing import Any

from holomj.errors import SpecError
from holomj.importers.common import build_model, light_kind, snap_opening
from holomj.importers.frames import normalise_deg, quat_from_euler_xyz, triple
from holomj.importers.ids import sanitise
from holomj.importers.jsonpath import Node
from holomj.importers.result import ImportResult
from holomj.importers.state import ImportState
from holomj.importers.substitute import choose_asset
from holomj.library.store import AssetLibrary
from holomj.spec.materials import BUILTIN_MATERIALS, Material
from holomj.spec.scene import Door, Light, Room, SceneObject, Window
from holomj.spec.walls import room_polygon

DEFAULT_WALL_HEIGHT = 2.7
_TILT_TOL = 1e-6


def import_scenedef(data: Any, library: AssetLibrary, source: str) -> ImportResult:
    """Import a 3D-Generalist SceneDef dictionary (schema in this module's docstring)."""
    return _SceneDefImport(data, library, source).run()


class _SceneDefImport(ImportState):
    def __init__(self, data: Any, library: AssetLibrary, source: str) -> None:
        super().__init__(data, library, source)
        self.defined: dict[str, Material] = {}
        self.heights: list[float] = []

    def run(self) -> ImportResult:
        self._check_ids()
        self._read_material_table()
        room_nodes = self._room_nodes()
        for index, node in enumerate(room_nodes):
            self._room(node, index)
        wall_height = self.root.num("wall_height", max(self.heights, default=DEFAULT_WALL_HEIGHT))
        walls = self.derive_walls()
        doors = [self._opening(n, "doors", walls) for n in self._list("doors")]
        windows = [self._opening(n, "windows", walls) for n in self._list("windows")]
        objects = self._objects()
        lights = [self._light(n) for n in self._light_nodes()]
        fields = {
            "name": (self.root.str_("name", "") or sanitise(PurePath(self.source).stem))[:128],
            "wall_height": wall_height,
            "rooms": self.rooms,
            "doors": doors,
            "windows": windows,
            "objects": objects,
            "lights": lights,
            "materials": {**self.materials.scene_materials, **self.defined},
            "source": self.source,
        }
        return self.result(fields, "scenedef")

    def _check_ids(self) -> None:
        """Reject ids used twice among the rooms, the openings (doors and windows share holomj's
        namespace) or the objects, naming both places. Ids made from a placement number
        (``<id>_<k>``) or a category are the importer's, not the input's, and are not checked."""
        self.check_scene_ids(self.root.value)

    # -- helpers ---------------------------------------------------------------------------
    def _list(self, key: str) -> list[Node]:
        node = self.root.opt(key)
        return node.items() if node is not None else []

    def _material(self, name: str | None, default: str, where: str) -> str:
        if not name:
            return default
        if name in self.defined or name in BUILTIN_MATERIALS:
            return name
        return self.materials.resolve(name, None, default, where)

    def _read_material_table(self) -> None:
        table = self.root.opt("materials")
        if table is None:
            return
        table.dict()
        for name in sorted(table.value):
            entry = table.get(name).dict()
            color = entry.opt("color") or entry.opt("rgba")
            if color is None:
                raise entry.error("missing required field 'color'")
            values = [c.number() for c in color.items()]
            if len(values) not in (3, 4):
                raise color.error(f"expected 3 or 4 numbers, got {len(values)}")
            rgba = [min(max(v, 0.0), 1.0) for v in values] + ([1.0] if len(values) == 3 else [])
            material_id = sanitise(name, "material")
            r, g, b, a = rgba
            self.defined[material_id] = Material(rgba=(r, g, b, a))
            if material_id != name:
                self.warnings.append(f"materials.{name}: renamed to {material_id!r}")

    # -- rooms -----------------------------------------------------------------------------
    def _room_nodes(self) -> list[Node]:
        rooms = self.root.opt("rooms")
        if rooms is not None:
            nodes = rooms.items()
            if not nodes:
                raise rooms.error("a scene needs at least one room")
            return nodes
        return [self.root.get("room")]

    def _room(self, node: Node, index: int) -> None:
        node.dict()
        path = node.path
        raw_id = node.str_("id", None)
        room_id = self.room_ids.new(raw_id or f"room_{index}", f"{path}.id" if raw_id else None)
        floor = node.opt("floor")
        if floor is not None:
            points = [p.vector(2, limit=1e4) for p in floor.items()]
            if len(points) < 3:
                raise floor.error("a floor polygon needs at least three points")
            poly_node = floor
        else:
            bbox = node.get("bbox")
            corners = bbox.items()
            if len(corners) != 2:
                raise bbox.error("expected two corners [min, max]")
            lo, hi = (c.items() for c in corners)
            if len(lo) not in (2, 3) or len(hi) != len(lo):
                raise bbox.error("corners need 2 or 3 numbers each")
            lo_v = [c.number(limit=1e4) for c in lo]
            hi_v = [c.number(limit=1e4) for c in hi]
            x0, x1 = sorted((lo_v[0], hi_v[0]))
            y0, y1 = sorted((lo_v[1], hi_v[1]))
            points = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
            if len(lo_v) == 3:
                self.heights.append(abs(hi_v[2] - lo_v[2]))
            poly_node = bbox
        try:
            room_polygon(points)
        except SpecError as err:
            raise err.located(poly_node.where()) from None
        wall_material = node.str_("wall_material", None)
        walls = node.opt("walls")
        if wall_material is None and walls is not None:
            names = [w.dict().str_("material", None) for w in walls.items()]
            names = [n for n in names if n]
            if names:
                counts = Counter(names)
                wall_material = next(n for n in names if counts[n] == max(counts.values()))
        fields = {
            "id": room_id,
            "type": node.str_("type", "room")[:64],
            "polygon": [tuple(p) for p in points],
            "floor_material": self._material(
                node.str_("floor_material", None), "floor_default", f"{path}.floor_material"
            ),
            "wall_material": self._material(wall_material, "wall_default", f"{path}.walls"),
            "ceiling_material": self._material(
                node.str_("ceiling_material", None), "ceiling_default", f"{path}.ceiling_material"
            ),
        }
        self.rooms.append(build_model(Room, fields, self.source, path))

    # -- openings --------------------------------------------------------------------------
    def _opening(self, node: Node, kind: str, walls: list[Any]) -> Door | Window:
        node.dict()
        path = node.path
        x, y = node.get("position").vector(2, limit=1e4)
        default_width = 1.0 if kind == "doors" else 1.2
        width = node.num("width", default_width)
        rooms_node = node.opt("rooms")
        rooms: list[str] | None = None
        if rooms_node is not None:
            rooms = []
            for r in rooms_node.items():
                room_id = self.room_ids.lookup(r.string())
                if room_id is None:
                    raise r.error(f"unknown room {r.value!r}")
                rooms.append(room_id)
        else:
            rooms = self._rooms_at_wall(walls, (x, y))
            if rooms is None:
                raise node.get("position").error(
                    f"({x:.2f}, {y:.2f}) is not on any wall", fix="put it on a room edge"
                )
        try:
            position, _, _ = snap_opening(walls, rooms, (x, y), width)
        except SpecError as err:
            raise err.located(f"{self.source}: {path}") from None
        raw_id = node.str_("id", None)
        fields: dict[str, Any] = {
            "id": self.opening_ids.new(raw_id or kind[:-1], f"{path}.id" if raw_id else None),
            "rooms": rooms,
            "position": position,
            "width": width,
        }
        for key in ("kind", "height", "base_height", "leaves"):
            if node.has(key):
                fields[key] = node.get(key).value
        if kind == "doors":
            return build_model(Door, fields, self.source, path)
        fields.pop("leaves", None)
        return build_model(Window, fields, self.source, path)

    @staticmethod
    def _rooms_at_wall(walls: list[Any], point: tuple[float, float]) -> list[str] | None:
        best = None
        for wall in walls:
            t, off = wall.locate(point)
            on_wall = abs(off) <= 0.05 and -1e-6 <= t <= wall.length + 1e-6
            if on_wall and (best is None or abs(off) < best[0]):
                best = (abs(off), list(wall.rooms))
        return best[1] if best else None

    # -- objects ---------------------------------------------------------------------------
    def _objects(self) -> list[SceneObject]:
        objects: list[SceneObject] = []
        pending_support: list[tuple[int, Node]] = []
        by_raw: dict[str, tuple[str, float]] = {}  # raw id -> (holomj id, top z)
        for index, node in enumerate(self._list("objects")):
            node.dict()
            category = node.str_("category", "")
            given_id = node.str_("id", None)
            raw_id = given_id or (sanitise(category, "object") if category else None)
            asset = node.str_("asset", None) or node.str_("asset_id", "")
            if not category and not asset:
                raise node.error("an object needs a 'category' or an 'asset'")
            bbox = node.opt("bbox_size")
            base_size = bbox.vector3(limit=1e3) if bbox is not None else None
            if bbox is not None and base_size is not None and min(base_size) <= 0:
                raise bbox.error("sizes must be positive")
            if node.has("material"):
                self.warnings.append(f"{node.path}.material: object materials are not supported")
            placements = node.get("placements").items()
            if not placements:
                raise node.get("placements").error("expected at least one placement")
            for k, placement in enumerate(placements):
                single = len(placements) == 1
                name = raw_id if single else f"{raw_id or 'object'}_{k}"
                where = f"{node.path}.id" if single and given_id else None
                obj, top = self._placement(
                    placement, node, name, where, category, asset, base_size, index
                )
                if placement.has("on"):
                    pending_support.append((len(objects), placement.get("on")))
                objects.append(obj)
                by_raw.setdefault(name or obj.id, (obj.id, top))
                if raw_id and len(placements) > 1:
                    by_raw.setdefault(raw_id, (obj.id, top))
        for position, on in pending_support:
            target = by_raw.get(on.string())
            if target is None:
                raise on.error(f"unknown object {on.value!r}")
            objects[position] = objects[position].model_copy(update={"support": target[0]})
        return objects

    def _placement(
        self,
        node: Node,
        obj: Node,
        name: str | None,
        where: str | None,
        category: str,
        asset: str,
        base_size: tuple[float, ...] | None,
        index: int,
    ) -> tuple[SceneObject, float]:
        node.dict()
        x, y, z = node.get("position").vector(3, limit=1e4)
        scale_node = node.opt("scale")
        scale3 = (1.0, 1.0, 1.0)
        if scale_node is not None:
            if isinstance(scale_node.value, list):
                scale3 = scale_node.vector3(limit=1e3)
            else:
                s = scale_node.number(limit=1e3)
                scale3 = (s, s, s)
            if min(scale3) <= 0:
                raise scale_node.error("scale must be positive")
        size = None
        if base_size is not None:
            size = triple(b * s for b, s in zip(base_size, scale3, strict=True))
        object_id = self.object_ids.new(name or f"object_{index}", where)
        choice, warning = choose_asset(
            self.library,
            object_id=object_id,
            requested=asset,
            category=category,
            size=size,
        )
        if warning:
            self.warnings.append(f"{obj.path}: {warning}")
        if choice.substitution is not None:
            self.substitutions.append(choice.substitution)
        scale: Any = choice.scale
        height = choice.height
        if choice.substitution is None and scale_node is not None:
            scale = scale3[0] if len(set(scale3)) == 1 else scale3
            height = choice.height * scale3[2]
        source_height = size[2] if size is not None else height
        bottom = max(z - source_height / 2, 0.0)
        fields: dict[str, Any] = {
            "id": object_id,
            "asset": choice.asset,
            "position": (x, y, round(bottom, 9)),
            "scale": scale,
            "static": obj.bool_("static", False),
        }
        rotation = node.opt("rotation")
        if rotation is not None:
            rx, ry, rz = rotation.vector(3, limit=1e5)
            if abs(normalise_deg(rx)) > _TILT_TOL or abs(normalise_deg(ry)) > _TILT_TOL:
                fields["quat"] = quat_from_euler_xyz(rx, ry, rz)
            fields["yaw_deg"] = normalise_deg(rz)
        elif node.has("yaw"):
            fields["yaw_deg"] = normalise_deg(node.num("yaw", limit=1e5))
        model = build_model(SceneObject, fields, self.source, node.path)
        return model, bottom + height

    # -- lights ----------------------------------------------------------------------------
    def _light_nodes(self) -> list[Node]:
        lighting = self.root.opt("lighting")
        if lighting is None:
            return []
        if isinstance(lighting.value, list):
            return lighting.items()
        lights = lighting.dict().opt("lights")
        return lights.items() if lights is not None else []

    def _light(self, node: Node) -> Light:
        node.dict()
        kind = light_kind(node)
        raw_id = node.str_("id", None)
        fields: dict[str, Any] = {
            "id": self.light_ids.new(raw_id or "light", f"{node.path}.id" if raw_id else None),
            "kind": kind,
            "energy": min(max(node.num("intensity", 1.0), 0.0), 100.0),
        }
        if node.has("position"):
            fields["position"] = node.get("position").vector(3, limit=1e4)
        if node.has("direction"):
            fields["direction"] = node.get("direction").vector(3, limit=1e4)
        if node.has("color"):
            color = node.get("color").vector(3, limit=1e3)
            fields["color"] = tuple(min(max(c, 0.0), 1.0) for c in color)
        return build_model(Light, fields, self.source, node.path)
