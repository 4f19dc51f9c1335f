"""Reading a GLB back in tests: its JSON and binary chunk checked against the glTF 2.0 layout,
accessors as arrays, node world matrices and per-node bounds (in glTF's Y-up frame or turned
back into MuJoCo's Z-up one)."""

from __future__ import annotations

import json
import struct
from dataclasses import dataclass, field
from typing import Any

import numpy as np

_COMPONENTS = {
    5120: np.int8,
    5121: np.uint8,
    5122: np.int16,
    5123: np.uint16,
    5125: np.uint32,
    5126: np.float32,
}
_WIDTH = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT4": 16}
# MuJoCo Z-up from glTF Y-up: (x, y, z)_gltf = (x, z, -y)_mujoco
Y_UP_TO_Z_UP = np.array([[1.0, 0, 0, 0], [0, 0, -1, 0], [0, 1, 0, 0], [0, 0, 0, 1]])


@dataclass
class Glb:
    gltf: dict[str, Any]
    binary: bytes
    parents: dict[int, int] = field(default_factory=dict)

    @property
    def nodes(self) -> list[dict[str, Any]]:
        return self.gltf["nodes"]

    def kind(self, index: int) -> str | None:
        return self.nodes[index].get("extras", {}).get("holomj", {}).get("kind")

    def by_kind(self, kind: str) -> dict[str, int]:
        """Node index by holomj id for the nodes of one kind."""
        return {
            self.nodes[i]["extras"]["holomj"]["id"]: i
            for i in range(len(self.nodes))
            if self.kind(i) == kind
        }

    def accessor(self, index: int) -> np.ndarray:
        acc = self.gltf["accessors"][index]
        view = self.gltf["bufferViews"][acc["bufferView"]]
        dtype = np.dtype(_COMPONENTS[acc["componentType"]])
        width = _WIDTH[acc["type"]]
        start = view.get("byteOffset", 0) + acc.get("byteOffset", 0)
        count = acc["count"] * width
        assert start + count * dtype.itemsize <= view.get("byteOffset", 0) + view["byteLength"]
        data = np.frombuffer(self.binary, dtype=dtype, count=count, offset=start)
        return data.reshape(acc["count"], width) if width > 1 else data

    def local(self, index: int) -> np.ndarray:
        node = self.nodes[index]
        if "matrix" in node:
            return np.array(node["matrix"], dtype=float).reshape(4, 4).T
        matrix = np.eye(4)
        x, y, z, w = node.get("rotation", (0.0, 0.0, 0.0, 1.0))
        matrix[:3, :3] = _quat_matrix(w, x, y, z)
        matrix[:3, :3] *= np.asarray(node.get("scale", (1.0, 1.0, 1.0)))[None, :]
        matrix[:3, 3] = node.get("translation", (0.0, 0.0, 0.0))
        return matrix

    def world(self, index: int) -> np.ndarray:
        """The node's world matrix in glTF's frame (Y up)."""
        matrix = self.local(index)
        parent = self.parents.get(index)
        while parent is not None:
            matrix = self.local(parent) @ matrix
            parent = self.parents.get(parent)
        return matrix

    def world_z_up(self, index: int) -> np.ndarray:
        """The node's world matrix in MuJoCo's frame (Z up)."""
        return Y_UP_TO_Z_UP @ self.world(index)

    def points(self, index: int, recursive: bool = True, z_up: bool = True) -> np.ndarray:
        """The vertices of a node's mesh (and its descendants'), in the world frame."""
        out = []
        stack = [index]
        while stack:
            current = stack.pop()
            node = self.nodes[current]
            if "mesh" in node:
                matrix = self.world_z_up(current) if z_up else self.world(current)
                for primitive in self.gltf["meshes"][node["mesh"]]["primitives"]:
                    local = self.accessor(primitive["attributes"]["POSITION"]).astype(float)
                    out.append(local @ matrix[:3, :3].T + matrix[:3, 3])
            if recursive:
                stack += node.get("children", [])
        return np.vstack(out) if out else np.zeros((0, 3))


def _quat_matrix(w: float, x: float, y: float, z: float) -> np.ndarray:
    return np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
        ]
    )


def read_glb(data: bytes) -> Glb:
    """Parse and check a GLB: header, chunk layout, buffer views and accessors in bounds,
    every index in range, node tree without cycles."""
    magic, version, length = struct.unpack_from("<4sII", data, 0)
    assert magic == b"glTF" and version == 2 and length == len(data)
    json_length, json_type = struct.unpack_from("<II", data, 12)
    assert json_type == 0x4E4F534A and json_length % 4 == 0
    gltf = json.loads(data[20 : 20 + json_length])
    offset = 20 + json_length
    binary = b""
    if offset < len(data):
        bin_length, bin_type = struct.unpack_from("<II", data, offset)
        assert bin_type == 0x004E4942 and bin_length % 4 == 0
        binary = data[offset + 8 : offset + 8 + bin_length]
        assert gltf["buffers"][0]["byteLength"] <= bin_length
    assert gltf["asset"]["version"] == "2.0"
    for view in gltf.get("bufferViews", []):
        assert view["byteOffset"] + view["byteLength"] <= len(binary)
        assert view["byteOffset"] % 4 == 0
    parents: dict[int, int] = {}
    for index, node in enumerate(gltf["nodes"]):
        for child in node.get("children", []):
            assert child not in parents, f"node {child} has two parents"
            parents[child] = index
    glb = Glb(gltf, binary, parents)
    for mesh in gltf.get("meshes", []):
        for primitive in mesh["primitives"]:
            positions = glb.accessor(primitive["attributes"]["POSITION"])
            acc = gltf["accessors"][primitive["attributes"]["POSITION"]]
            assert np.allclose(positions.min(axis=0), acc["min"]) and np.allclose(
                positions.max(axis=0), acc["max"]
            )
            normals = glb.accessor(primitive["attributes"]["NORMAL"])
            assert len(normals) == len(positions)
            assert np.allclose(np.linalg.norm(normals, axis=1), 1.0, atol=1e-3)
            if "TEXCOORD_0" in primitive["attributes"]:
                assert len(glb.accessor(primitive["attributes"]["TEXCOORD_0"])) == len(positions)
            indices = glb.accessor(primitive["indices"])
            assert indices.size % 3 == 0 and int(indices.max()) < len(positions)
            assert 0 <= primitive["material"] < len(gltf["materials"])
    for texture in gltf.get("textures", []):
        image = gltf["images"][texture["source"]]
        view = gltf["bufferViews"][image["bufferView"]]
        start = view["byteOffset"]
        assert binary[start : start + 8] == b"\x89PNG\r\n\x1a\n"
    return glb
