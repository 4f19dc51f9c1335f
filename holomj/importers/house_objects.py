"""Reading the objects of a ProcTHOR or Holodeck house: kind, asset, pose and what rests on what.

Each object gets its kind (:mod:`holomj.importers.object_kinds`), an asset from the library
(:func:`holomj.importers.substitute.choose_asset`: the asset itself, a stand-in of its kind at
the authored size, else a box of that size), and its pose (the ProcTHOR centre of its bounding
box -> the centre of its footprint at the bottom: an object that stood on the floor, or on its
parent's top, in the source is put on the floor, or on the stand-in parent's top). ``children``
(ProcTHOR) and Holodeck small objects whose id names their receptacle
(``"<name>|<receptacle id>"``) get that receptacle as their ``support``. A child whose kind is
a fixture its parent's stand-in already has (a THOR sink's faucet) is merged into it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from shapely.geometry import Polygon

from holomj.importers.common import build_model
from holomj.importers.counter_shapes import counter_shape, nearest_run, split_counter
from holomj.importers.frames import (
    is_tilted,
    normalise_deg,
    quat_from_unity,
    unity_point,
    yaw_from_unity,
)
from holomj.importers.holodeck_hints import HolodeckHints
from holomj.importers.jsonpath import Node
from holomj.importers.object_kinds import Authored, Kind, holodeck_object_kind, thor_object_kind
from holomj.importers.state import ImportState
from holomj.importers.substitute import MIN_EXTENT, AssetChoice, choose_asset
from holomj.spec.scene import SceneObject

REST_TOL = 0.05  # metres: a bottom this close to a surface rests on it
FITTED_SIZES = ("thor", "footprint", "extent")  # authored sizes a stand-in is scaled to

# A fixture that a stand-in of its parent's category already has (a THOR sink's faucet is an
# object of its own; holomj's washbasins and sink counters come with theirs).
FIXTURES: dict[str, frozenset[str]] = {
    "faucet": frozenset({"washbasin", "sink_counter", "sink", "kitchen_sink", "bathtub"}),
}


@dataclass
class Placed:
    """What children need to know about their parent."""

    id: str
    room: str | None
    src_top: float  # top in the source (metres, world z)
    used_top: float  # top of the asset used
    category: str = ""
    substituted: bool = False


def fixture_of(category: str, parent: Placed) -> bool:
    """Whether an object of ``category`` is a fixture of its substituted ``parent``."""
    return parent.substituted and parent.category in FIXTURES.get(category, frozenset())


@dataclass(frozen=True)
class _Pose:
    raw: tuple[float, float, float]  # unity x, y, z
    rotation: tuple[float, float, float]  # unity degrees
    yaw: float  # holomj yaw, degrees


class HouseObjects(ImportState):
    """The object reading of the house importer (a base of it: it needs ``holodeck``,
    ``hints``, ``objects`` and ``room_at``)."""

    holodeck: bool
    hints: HolodeckHints
    objects: list[SceneObject]
    room_shapes: list[tuple[str, Polygon]]
    counter_runs: dict[str, list[SceneObject]]  # shaped countertops, by their id

    def room_at(self, x: float, y: float) -> str | None:  # pragma: no cover - overridden
        """The room that holds the point (the importer knows its rooms)."""
        raise NotImplementedError

    def read_objects(self) -> None:
        """Every object of ``objects`` (nested ``children`` included) into ``self.objects``."""
        self.counter_runs = {}
        nodes = self.root.opt("objects")
        if nodes is None:
            return
        items = nodes.items()
        raw_ids = {
            item.value["id"]
            for item in items
            if isinstance(item.value, dict) and isinstance(item.value.get("id"), str)
        }
        placed: dict[str, Placed] = {}
        deferred: list[tuple[Node, str]] = []
        for item in items:
            parent_raw = holodeck_parent(item, raw_ids) if self.holodeck else None
            if parent_raw is not None:
                deferred.append((item, parent_raw))
            else:
                self._object(item, None, placed)
        for item, parent_raw in deferred:
            self._object(item, placed.get(parent_raw), placed)
        self._onto_counter_runs()

    def _onto_counter_runs(self) -> None:
        """What rested on a shaped countertop rests on the run under it (the nearest)."""
        runs = self.counter_runs
        if not runs:
            return
        self.objects = [
            o.model_copy(update={"support": nearest_run(runs[o.support], *o.position[:2])})
            if o.support in runs
            else o
            for o in self.objects
        ]

    def _counter_runs(
        self, obj: SceneObject, shape: str, kind: Kind, size: tuple[float, float, float]
    ) -> list[SceneObject]:
        """A THOR L- or U-shaped countertop as its counter runs (:mod:`counter_shapes`)."""

        def choose(run_id: str, size: tuple[float, float, float]) -> tuple[str, Any]:
            choice, _ = choose_asset(
                self.library,
                object_id=run_id,
                requested="",
                category=kind.category,
                size=size,
                fit=True,
                stand_ins=kind.stand_ins,
                size_source="thor",
                nearest_when_none_fits=True,
            )
            if choice.substitution is not None:
                self.substitutions.append(choice.substitution)
            return choice.asset, choice.scale

        room = next((poly for rid, poly in self.room_shapes if rid == obj.room), None)
        runs = split_counter(obj, shape, size, room, choose)
        self.counter_runs[obj.id] = runs
        self.warnings.append(
            f"{obj.id}: {shape}-shaped countertop built as {len(runs)} counter runs"
        )
        return runs

    def _object(self, node: Node, parent: Placed | None, placed: dict[str, Placed]) -> None:
        node.dict()
        raw_id = node.str_("id")
        asset = node.str_("assetId", "")
        pose = _read_pose(node)
        room = self._room_of(node, parent, pose)
        kind = self._kind(node, raw_id, asset, pose, room, parent)
        if parent is not None and fixture_of(kind.category, parent):
            self.merged.append(
                {
                    "object": raw_id,
                    "category": kind.category,
                    "into": parent.id,
                    "why": f"the stand-in {parent.category} has its own {kind.category}",
                }
            )
            return
        object_id = self.object_ids.new(raw_id, f"{node.path}.id")
        choice = self._choose(node, object_id, asset, kind, record=counter_shape(asset) is None)
        # The source's bottom: from its true height when a table or the input gives one.
        src_height = choice.height
        sub = choice.substitution
        if kind.size_source == "thor" and kind.size is not None:
            src_height = kind.size[2]
        elif sub is not None and sub.source_size is not None:
            src_height = sub.source_size[2]
        uy = pose.raw[1]
        z = _object_z(uy, src_height, choice.height, parent)
        x, y, _ = unity_point(*pose.raw)
        fields: dict[str, Any] = {
            "id": object_id,
            "asset": choice.asset,
            "position": (x, y, z),
            "yaw_deg": normalise_deg(pose.yaw + choice.turn_deg) if choice.turn_deg else pose.yaw,
            "scale": choice.scale,
            "static": node.bool_("kinematic", False),
            "support": parent.id if parent is not None else None,
            "room": room,
        }
        rx, ry, rz = pose.rotation
        if is_tilted(rx, rz):
            fields["quat"] = turn_quat(quat_from_unity(rx, ry, rz), choice.turn_deg)
        built = build_model(SceneObject, fields, self.source, node.path)
        shape = counter_shape(asset) if kind.size_source == "thor" else None
        if shape is not None and kind.size is not None:
            self.objects.extend(self._counter_runs(built, shape, kind, kind.size))
        else:
            self.objects.append(built)
        me = Placed(
            object_id, room, uy + src_height / 2, z + choice.height, kind.category, sub is not None
        )
        placed.setdefault(raw_id, me)
        children = node.opt("children")
        for child in children.items() if children is not None else []:
            self._object(child, me, placed)

    def _room_of(self, node: Node, parent: Placed | None, pose: _Pose) -> str | None:
        room = None
        room_node = node.opt("roomId")
        if room_node is not None:
            room = self.room_ids.lookup(room_node.string())
        if room is None and parent is not None:
            room = parent.room
        if room is None:
            x, y, _ = unity_point(*pose.raw)
            room = self.room_at(x, y)
        return room

    def _kind(
        self,
        node: Node,
        raw_id: str,
        asset: str,
        pose: _Pose,
        room: str | None,
        parent: Placed | None,
    ) -> Kind:
        if self.holodeck:
            room_node = node.opt("roomId")
            authored = Authored(
                footprint=footprint(node, pose.yaw),
                centre_height=pose.raw[1],
                room=room_node.string() if room_node is not None else room,
                child=parent is not None,
                above_support=pose.raw[1] - parent.src_top if parent is not None else None,
            )
            return holodeck_object_kind(node, raw_id, asset, self.hints, self.library, authored)
        return thor_object_kind(node, raw_id, asset)

    def _choose(
        self, node: Node, object_id: str, asset: str, kind: Kind, record: bool = True
    ) -> AssetChoice:
        choice, warning = choose_asset(
            self.library,
            object_id=object_id,
            requested=asset,
            category=kind.category,
            size=positive(kind.size) if kind.size else None,
            fit=kind.size_source in FITTED_SIZES,
            stand_ins=kind.stand_ins,
            size_source=kind.size_source,
            prefer_articulated=kind.can_open,
            nearest_when_none_fits=self.holodeck,
        )
        if warning:
            self.warnings.append(f"{node.path}: {warning}")
        if record and choice.substitution is not None:
            self.substitutions.append(choice.substitution)
        return choice


def _read_pose(node: Node) -> _Pose:
    raw = node.get("position").dict().xyz()
    rot = node.opt("rotation")
    rx = ry = rz = 0.0
    if rot is not None:
        rot.dict()
        rx, ry, rz = rot.num("x", 0.0), rot.num("y", 0.0), rot.num("z", 0.0)
    return _Pose(raw, (rx, ry, rz), yaw_from_unity(ry))


def _object_z(
    centre_y: float, src_height: float, used_height: float, parent: Placed | None
) -> float:
    """The z of an object's footprint centre: on its surface when it rested on it in the
    source, else where its centre was."""
    src_bottom = centre_y - src_height / 2
    surface_src, surface_used = (0.0, 0.0) if parent is None else (parent.src_top, parent.used_top)
    if abs(src_bottom - surface_src) <= REST_TOL:
        return round(surface_used, 9)
    return round(max(centre_y - used_height / 2, 0.0), 9)


def holodeck_parent(item: Node, raw_ids: set[str]) -> str | None:
    """Holodeck small objects are ``"<name>|<receptacle id>"``: the receptacle, if listed."""
    value = item.value
    if not isinstance(value, dict) or not isinstance(value.get("id"), str):
        return None
    raw = value["id"]
    if "|" not in raw:
        return None
    parent = raw.split("|", 1)[1]
    return parent if parent in raw_ids and parent != raw else None


def footprint(node: Node, yaw_deg: float) -> tuple[float, float] | None:
    """Holodeck ``vertices`` (centimetres, world x/z) measured along the object's own axes."""
    vertices = node.opt("vertices")
    if vertices is None:
        return None
    points = []
    for vertex in vertices.items():
        if isinstance(vertex.value, dict):
            points.append((vertex.num("x", limit=1e6), vertex.num("z", limit=1e6)))
        else:
            a, b = vertex.vector(2, limit=1e6)
            points.append((a, b))
    if len(points) < 3:
        raise vertices.error("expected at least three footprint points")
    c, s = math.cos(math.radians(yaw_deg)), math.sin(math.radians(yaw_deg))
    along = [(px * c + py * s) / 100 for px, py in points]
    across = [(-px * s + py * c) / 100 for px, py in points]
    return (round(max(along) - min(along), 6), round(max(across) - min(across), 6))


def turn_quat(
    quat: tuple[float, float, float, float], turn_deg: float
) -> tuple[float, float, float, float]:
    """``quat`` followed by a turn of ``turn_deg`` about the object's own Z."""
    if not turn_deg:
        return quat
    half = math.radians(turn_deg) / 2
    c, s = math.cos(half), math.sin(half)
    w, x, y, z = quat
    return (w * c - z * s, x * c + y * s, y * c - x * s, z * c + w * s)


def positive(size: tuple[float, float, float]) -> tuple[float, float, float]:
    return (max(size[0], MIN_EXTENT), max(size[1], MIN_EXTENT), max(size[2], MIN_EXTENT))
