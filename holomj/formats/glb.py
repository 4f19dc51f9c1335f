"""The scene as a glTF 2.0 binary (GLB): what MuJoCo draws, for Blender, three.js and the report.

Built from the compiled model (every visual geom with its mesh or primitive, material and 2D
texture, as simulated) and the scene (which room an object is in, which geoms are floors, walls,
ceilings, doors and windows), posed at the model's initial state. Node tree::

    <scene name>                 root: turns MuJoCo's Z-up into glTF's Y-up (-90 deg about X)
      <room id>                  one per room
        <room id>/floor, /walls, /ceiling
        <object id>              one per object, at its body's pose; the mesh of its visual geoms
          <object id>/colliders  its collision-only geoms (only with ``colliders``)
          <child body>           articulated parts (hinge/slide bodies), nested as in the model
      openings
        <door or window id>      frame and glass; door leaves as child nodes at their hinges
      lights                     KHR_lights_punctual, one node per MuJoCo light
      <other bodies>             a robot or bodies of no scene object, as in the model

Units are metres. Every node carries ``extras.holomj`` with its ``kind`` (scene, room, floor,
walls, ceiling, object, part, colliders, opening, leaf, light, body, group) and ``id``; objects
also carry what ``object_info`` gives (category, asset, mass, ...). Identical objects share one
mesh, and materials and textures are shared by name. The output is deterministic: same model
and scene, same bytes.
"""

from __future__ import annotations

import json
import struct
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import mujoco
import numpy as np

from holomj.formats.model_geometry import (
    CEILING_GROUP,
    Look,
    ModelGeometry,
    Triangles,
    matrix_to_quat_wxyz,
    quat_from_to,
)
from holomj.mjcf import names
from holomj.spec.robot import ROBOT_PREFIX
from holomj.spec.scene import Door, SceneSpec, Window
from holomj.version import __version__

# glTF is Y-up: the root node turns MuJoCo's Z-up world by -90 degrees about X, (x, y, z) ->
# (x, z, -y). As a glTF quaternion (x, y, z, w):
Z_UP_TO_Y_UP = (-0.7071067811865476, 0.0, 0.0, 0.7071067811865476)
COLLIDER_RGBA = (1.0, 0.45, 0.1, 0.45)
_FLOAT, _UINT16, _UINT32 = 5126, 5123, 5125
_ARRAY_BUFFER, _ELEMENT_ARRAY_BUFFER = 34962, 34963
_REPEAT, _LINEAR, _LINEAR_MIPMAP_LINEAR = 10497, 9729, 9987
_DIGITS = 7


def scene_glb(
    model: mujoco.MjModel,
    scene: SceneSpec,
    *,
    qpos: np.ndarray | None = None,
    colliders: bool = False,
    object_info: Mapping[str, Mapping[str, Any]] | None = None,
) -> bytes:
    """The GLB bytes of ``scene`` as compiled into ``model`` (see module docstring).

    ``qpos``: joint positions to pose it in (default: the model's initial state, the poses of
    ``objects.json``). ``colliders``: also the collision-only geoms, as ``<id>/colliders`` nodes
    in a translucent orange. ``object_info``: extra facts per object id for its node's extras.
    """
    return GlbScene(ModelGeometry(model, qpos), scene, colliders, object_info or {}).build()


@dataclass
class _Primitives:
    """Triangles grouped by look, in one node's frame."""

    parts: dict[str, tuple[Look, list[Triangles]]] = field(default_factory=dict)

    def add(self, look: Look, tris: Triangles) -> None:
        self.parts.setdefault(look.name, (look, []))[1].append(tris)

    def __bool__(self) -> bool:
        return bool(self.parts)


class GlbScene:
    """Builds the glTF document of a scene (one use: :meth:`build`)."""

    def __init__(
        self,
        geometry: ModelGeometry,
        scene: SceneSpec,
        colliders: bool,
        object_info: Mapping[str, Mapping[str, Any]],
    ) -> None:
        self.geo = geometry
        self.model = geometry.model
        self.scene = scene
        self.colliders = colliders
        self.object_info = object_info
        self.doc = _Document(geometry)
        self._collider_look = Look(
            "holomj/collider", COLLIDER_RGBA, None, (1.0, 1.0), 0.0, 0.0, 0.0, 0.0
        )
        self._mesh_cache: dict[tuple, int] = {}
        self.objects = {names.object_body(o.id): o for o in scene.objects}
        self.openings: dict[str, tuple[str, Door | Window]] = {
            o.id: ("door", o) for o in scene.doors
        }
        self.openings.update({o.id: ("window", o) for o in scene.windows})
        self.leaves = {
            names.door_leaf_body(door.id, index): door.id
            for door in scene.doors
            for index in range(2)
        }

    # --- the tree ---------------------------------------------------------------------------

    def build(self) -> bytes:
        doc = self.doc
        rooms = {room.id: self._group(room.id, "room", room.id) for room in self.scene.rooms}
        opening_nodes: dict[str, int] = {}
        top: list[int] = list(rooms.values())
        structure = self._world_geoms()
        for room_id, room_node in rooms.items():
            for part in ("floor", "walls", "ceiling"):
                prims = structure.pop((part, room_id), None)
                if prims:
                    node = self._mesh_node(
                        f"{room_id}/{part}", prims, {"kind": part, "id": room_id}
                    )
                    doc.nodes[room_node]["children"].append(node)
        for key in sorted(k for k in structure if k[0] == "opening"):
            opening_id = key[1]
            kind = self.openings[opening_id][0]
            opening_nodes[opening_id] = self._mesh_node(
                opening_id, structure.pop(key), {"kind": kind, "id": opening_id}
            )
        for (part, owner), prims in sorted(structure.items()):
            node = self._mesh_node(f"{owner}/{part}", prims, {"kind": part, "id": owner})
            top.append(node)

        for body in self.geo.children[0]:
            name = self.geo.body_name(body)
            obj = self.objects.get(name)
            if obj is not None:
                node = self._body_node(body, obj.id, "object", np.zeros(3), np.eye(3))
                parent = rooms.get(obj.room) if obj.room else None
                if parent is None:
                    top.append(node)
                else:
                    doc.nodes[parent]["children"].append(node)
            elif name in self.leaves:
                door_id = self.leaves[name]
                if door_id not in opening_nodes:
                    opening_nodes[door_id] = self._empty(door_id, {"kind": "door", "id": door_id})
                pos, rot = self.geo.body_pose(self.model.body_parentid[body])
                node = self._body_node(body, name, "leaf", pos, rot)
                doc.nodes[opening_nodes[door_id]]["children"].append(node)
            else:
                kind = "robot" if name.startswith(ROBOT_PREFIX) else "body"
                top.append(self._body_node(body, name, kind, np.zeros(3), np.eye(3)))
        if opening_nodes:
            openings = self._group("openings", "group", "openings")
            doc.nodes[openings]["children"] += [opening_nodes[k] for k in sorted(opening_nodes)]
            top.append(openings)
        lights = self._lights()
        if lights is not None:
            top.append(lights)

        root = doc.add_node(
            {
                "name": self.scene.name,
                "rotation": list(Z_UP_TO_Y_UP),
                "children": top,
                "extras": {
                    "holomj": {
                        "kind": "scene",
                        "id": self.scene.name,
                        "frame": "MuJoCo Z-up world, turned Y-up by this node; metres",
                    }
                },
            }
        )
        doc.gltf["scene"] = 0
        doc.gltf["scenes"] = [{"name": self.scene.name, "nodes": [root]}]
        return doc.glb()

    def _group(self, name: str, kind: str, ident: str) -> int:
        return self.doc.add_node(
            {"name": name, "children": [], "extras": {"holomj": {"kind": kind, "id": ident}}}
        )

    def _empty(self, name: str, extras: dict[str, Any]) -> int:
        return self.doc.add_node({"name": name, "children": [], "extras": {"holomj": extras}})

    def _world_geoms(self) -> dict[tuple[str, str], _Primitives]:
        """The world body's drawn geoms by (part, owner): floors, walls and ceilings by room,
        openings by id, anything else as ("structure", "misc")."""
        out: dict[tuple[str, str], _Primitives] = {}
        rooms = {room.id for room in self.scene.rooms}
        for geom in self.geo.body_geoms(0):
            if not self.geo.is_visible(geom):
                continue
            key = self._world_key(self.geo.geom_name(geom), rooms, geom)
            self._add_geom(out.setdefault(key, _Primitives()), geom, None)
        return out

    def _world_key(self, name: str, rooms: set[str], geom: int) -> tuple[str, str]:
        if name.startswith("structure/"):
            rest = name[len("structure/") :]
            for part, prefix in (("floor", "floor/"), ("ceiling", "ceiling/")):
                if rest.startswith(prefix) and rest[len(prefix) :] in rooms:
                    return (part, rest[len(prefix) :])
            side = rest.rsplit("/", 1)[-1]
            if side in rooms:
                kind = "ceiling" if self.model.geom_group[geom] == CEILING_GROUP else "walls"
                return (kind, side)
            return ("structure", "misc")
        head = name.split("/", 1)[0]
        if head in self.openings and "/" in name:
            return ("opening", head)
        return ("structure", "misc")

    def _body_node(
        self,
        body: int,
        ident: str,
        kind: str,
        parent_pos: np.ndarray,
        parent_rot: np.ndarray,
    ) -> int:
        """A node for ``body`` (relative to its parent's world pose), its geoms and subtree."""
        pos, rot = self.geo.body_pose(body)
        local_pos = parent_rot.T @ (pos - parent_pos)
        local_rot = parent_rot.T @ rot
        visible = [g for g in self.geo.body_geoms(body) if self.geo.is_visible(g)]
        extras: dict[str, Any] = {"kind": kind, "id": ident}
        if kind == "object":
            extras.update(self._object_extras(ident))
        node: dict[str, Any] = {"name": ident, "children": [], "extras": {"holomj": extras}}
        _set_transform(node, local_pos, local_rot)
        mesh = self._body_mesh(visible, ident)
        if mesh is not None:
            node["mesh"] = mesh
        index = self.doc.add_node(node)
        if self.colliders:
            hidden = [g for g in self.geo.body_geoms(body) if self.geo.is_hidden_collider(g)]
            hidden = [g for g in hidden if self.model.geom_type[g] != mujoco.mjtGeom.mjGEOM_PLANE]
            mesh = self._body_mesh(hidden, f"{ident}/colliders", collider=True)
            if mesh is not None:
                child = self.doc.add_node(
                    {
                        "name": f"{ident}/colliders",
                        "mesh": mesh,
                        "extras": {"holomj": {"kind": "colliders", "id": ident}},
                    }
                )
                node["children"].append(child)
        for sub in self.geo.children[body]:
            sub_kind = "part" if kind in ("object", "part") else kind
            node["children"].append(
                self._body_node(sub, self.geo.body_name(sub), sub_kind, pos, rot)
            )
        return index

    def _object_extras(self, object_id: str) -> dict[str, Any]:
        obj = self.objects[names.object_body(object_id)]
        extras: dict[str, Any] = {
            "room": obj.room,
            "asset": obj.asset,
            "support": obj.support,
            "static": bool(obj.static),
        }
        extras.update(self.object_info.get(object_id, {}))
        return extras

    def _body_mesh(self, geoms: Sequence[int], name: str, collider: bool = False) -> int | None:
        """The glTF mesh of ``geoms`` in their body's frame (shared by identical bodies)."""
        if not geoms:
            return None
        key_parts = []
        for geom in geoms:
            look = self._collider_look if collider else self.geo.look(geom)
            pos, rot = self.geo.geom_in_body(geom)
            shape = (
                int(self.model.geom_type[geom]),
                int(self.model.geom_dataid[geom]),
                tuple(np.round(self.model.geom_size[geom], 6)),
            )
            key_parts.append(
                (shape, look.name, tuple(np.round(pos, 6)), tuple(np.round(rot, 6).ravel()))
            )
        key = (collider, tuple(key_parts))
        if key in self._mesh_cache:
            return self._mesh_cache[key]
        prims = _Primitives()
        for geom in geoms:
            self._add_geom(prims, geom, self.geo.geom_in_body(geom), collider)
        mesh = self.doc.add_mesh(name, prims) if prims else None
        if mesh is not None:
            self._mesh_cache[key] = mesh
        return mesh

    def _add_geom(
        self,
        prims: _Primitives,
        geom: int,
        pose: tuple[np.ndarray, np.ndarray] | None,
        collider: bool = False,
    ) -> None:
        """Add ``geom``'s triangles to ``prims`` at ``pose`` (None: its world pose)."""
        look = self._collider_look if collider else self.geo.look(geom)
        tris = self.geo.triangles(geom, look.repeat if look.texture is not None else (1.0, 1.0))
        if tris is None or tris.empty:
            return
        pos, rot = pose if pose is not None else self.geo.geom_pose(geom)
        prims.add(look, tris.transformed(rot, pos))

    def _mesh_node(self, name: str, prims: _Primitives, extras: dict[str, Any]) -> int:
        mesh = self.doc.add_mesh(name, prims)
        return self.doc.add_node(
            {"name": name, "mesh": mesh, "children": [], "extras": {"holomj": extras}}
        )

    def _lights(self) -> int | None:
        model, data = self.model, self.geo.data
        if model.nlight == 0:
            return None
        children = []
        for light in range(model.nlight):
            name = model.light(light).name or f"light_{light}"
            kind = int(model.light_type[light])
            diffuse = np.asarray(model.light_diffuse[light], dtype=float)
            strength = float(diffuse.max())
            color = (diffuse / strength).round(4).tolist() if strength > 0 else [1.0, 1.0, 1.0]
            entry: dict[str, Any] = {"name": name, "color": color}
            if kind == mujoco.mjtLightType.mjLIGHT_DIRECTIONAL:
                entry.update(type="directional", intensity=round(4.0 * strength, 4))
            elif kind == mujoco.mjtLightType.mjLIGHT_SPOT:
                cutoff = float(np.radians(min(89.0, max(1.0, float(model.light_cutoff[light])))))
                entry.update(
                    type="spot",
                    intensity=round(40.0 * strength, 4),
                    spot={
                        "innerConeAngle": round(cutoff * 0.5, 6),
                        "outerConeAngle": round(cutoff, 6),
                    },
                )
            else:
                entry.update(type="point", intensity=round(40.0 * strength, 4))
            index = self.doc.add_light(entry)
            rotation = _quat_xyzw(quat_from_to((0.0, 0.0, -1.0), data.light_xdir[light]))
            children.append(
                self.doc.add_node(
                    {
                        "name": name,
                        "translation": _vec(data.light_xpos[light]),
                        "rotation": rotation,
                        "extensions": {"KHR_lights_punctual": {"light": index}},
                        "extras": {"holomj": {"kind": "light", "id": name}},
                    }
                )
            )
        return self.doc.add_node(
            {
                "name": "lights",
                "children": children,
                "extras": {"holomj": {"kind": "group", "id": "lights"}},
            }
        )


def _set_transform(node: dict[str, Any], pos: np.ndarray, rot: np.ndarray) -> None:
    if np.abs(pos).max() > 1e-9:
        node["translation"] = _vec(pos)
    quat = matrix_to_quat_wxyz(rot)
    if abs(abs(quat[0]) - 1.0) > 1e-9:
        node["rotation"] = _quat_xyzw(quat)


def _quat_xyzw(wxyz: np.ndarray) -> list[float]:
    w, x, y, z = (float(v) for v in wxyz)
    if w < 0:
        w, x, y, z = -w, -x, -y, -z
    return [_r(x), _r(y), _r(z), _r(w)]


def _vec(values: Sequence[float] | np.ndarray) -> list[float]:
    return [_r(v) for v in values]


def _r(value: float) -> float:
    rounded = round(float(value), _DIGITS)
    return 0.0 if rounded == 0 else rounded


class _Document:
    """A glTF document being filled: JSON, one binary buffer, shared materials and textures."""

    def __init__(self, geometry: ModelGeometry) -> None:
        self.gltf: dict[str, Any] = {
            "asset": {"version": "2.0", "generator": f"holomj {__version__}"},
            "nodes": [],
            "meshes": [],
            "materials": [],
            "accessors": [],
            "bufferViews": [],
            "buffers": [],
        }
        self.nodes: list[dict[str, Any]] = self.gltf["nodes"]
        self.binary = bytearray()
        self._materials: dict[str, int] = {}
        self._textures: dict[int, int] = {}
        self._lights: list[dict[str, Any]] = []
        self._geometry = geometry

    def add_node(self, node: dict[str, Any]) -> int:
        self.nodes.append(node)
        return len(self.nodes) - 1

    def add_light(self, light: dict[str, Any]) -> int:
        self._lights.append(light)
        return len(self._lights) - 1

    def add_mesh(self, name: str, prims: _Primitives) -> int:
        primitives = []
        for look_name in sorted(prims.parts):
            look, parts = prims.parts[look_name]
            tris = Triangles.concat(parts)
            uvs = tris.uvs if look.texture is not None else None
            attributes = {
                "POSITION": self._accessor(tris.positions, "VEC3", with_bounds=True),
                "NORMAL": self._accessor(tris.normals, "VEC3"),
            }
            if uvs is not None:
                attributes["TEXCOORD_0"] = self._accessor(uvs, "VEC2")
            primitives.append(
                {
                    "attributes": attributes,
                    "indices": self._indices(tris.faces),
                    "material": self._material(look, uvs is not None),
                    "mode": 4,
                }
            )
        self.gltf["meshes"].append({"name": name, "primitives": primitives})
        return len(self.gltf["meshes"]) - 1

    def _material(self, look: Look, textured: bool) -> int:
        key = look.name if textured or look.texture is None else f"{look.name}/untextured"
        if key in self._materials:
            return self._materials[key]
        rgba = list(look.linear_rgba)
        pbr: dict[str, Any] = {
            "baseColorFactor": [_r(v) for v in rgba],
            "metallicFactor": 0.0,
            "roughnessFactor": look.roughness,
        }
        if textured and look.texture is not None:
            pbr["baseColorTexture"] = {"index": self._texture(look.texture)}
        material: dict[str, Any] = {"name": key, "pbrMetallicRoughness": pbr, "doubleSided": True}
        if rgba[3] < 1.0:
            material["alphaMode"] = "BLEND"
        if look.emission > 0:
            material["emissiveFactor"] = [_r(min(1.0, c * look.emission)) for c in rgba[:3]]
        self.gltf["materials"].append(material)
        self._materials[key] = len(self.gltf["materials"]) - 1
        return self._materials[key]

    def _texture(self, texture: int) -> int:
        if texture not in self._textures:
            png = self._geometry.texture_png(texture)
            view = self._view(png, None)
            images = self.gltf.setdefault("images", [])
            images.append(
                {
                    "name": self._geometry.texture_name(texture),
                    "bufferView": view,
                    "mimeType": "image/png",
                }
            )
            self.gltf.setdefault(
                "samplers",
                [
                    {
                        "magFilter": _LINEAR,
                        "minFilter": _LINEAR_MIPMAP_LINEAR,
                        "wrapS": _REPEAT,
                        "wrapT": _REPEAT,
                    }
                ],
            )
            textures = self.gltf.setdefault("textures", [])
            textures.append({"sampler": 0, "source": len(images) - 1})
            self._textures[texture] = len(textures) - 1
        return self._textures[texture]

    def _view(self, data: bytes, target: int | None) -> int:
        while len(self.binary) % 4:
            self.binary.append(0)
        view: dict[str, Any] = {
            "buffer": 0,
            "byteOffset": len(self.binary),
            "byteLength": len(data),
        }
        if target is not None:
            view["target"] = target
        self.binary += data
        self.gltf["bufferViews"].append(view)
        return len(self.gltf["bufferViews"]) - 1

    def _accessor(self, values: np.ndarray, kind: str, with_bounds: bool = False) -> int:
        array = np.ascontiguousarray(values, dtype=np.float32)
        accessor: dict[str, Any] = {
            "bufferView": self._view(array.tobytes(), _ARRAY_BUFFER),
            "componentType": _FLOAT,
            "count": len(array),
            "type": kind,
        }
        if with_bounds:
            accessor["min"] = [float(v) for v in array.min(axis=0)]
            accessor["max"] = [float(v) for v in array.max(axis=0)]
        self.gltf["accessors"].append(accessor)
        return len(self.gltf["accessors"]) - 1

    def _indices(self, faces: np.ndarray) -> int:
        flat = faces.reshape(-1)
        small = flat.size == 0 or int(flat.max()) < 65535
        array = flat.astype(np.uint16 if small else np.uint32)
        self.gltf["accessors"].append(
            {
                "bufferView": self._view(array.tobytes(), _ELEMENT_ARRAY_BUFFER),
                "componentType": _UINT16 if small else _UINT32,
                "count": int(array.size),
                "type": "SCALAR",
            }
        )
        return len(self.gltf["accessors"]) - 1

    def glb(self) -> bytes:
        while len(self.binary) % 4:
            self.binary.append(0)
        for node in self.nodes:
            if "children" in node and not node["children"]:
                del node["children"]
        gltf = dict(self.gltf)
        gltf["buffers"] = [{"byteLength": len(self.binary)}]
        if self._lights:
            gltf["extensionsUsed"] = ["KHR_lights_punctual"]
            gltf["extensions"] = {"KHR_lights_punctual": {"lights": self._lights}}
        for key in ("meshes", "materials", "accessors", "bufferViews"):
            if not gltf[key]:
                del gltf[key]
        if not self.binary:
            del gltf["buffers"]
        text = json.dumps(gltf, separators=(",", ":"), ensure_ascii=False).encode("utf-8")
        text += b" " * (-len(text) % 4)
        chunks = struct.pack("<II", len(text), 0x4E4F534A) + text
        if self.binary:
            chunks += struct.pack("<II", len(self.binary), 0x004E4942) + bytes(self.binary)
        return struct.pack("<4sII", b"glTF", 2, 12 + len(chunks)) + chunks
