"""Build small objathor-format directories from the shared meshes (for the objathor tests).

A mesh is first brought into the holomj asset frame with the pipeline's own loader and
normaliser; it is then written as objathor stores it: Unity frame (``v = Ry(-yRotOffset) M^T a``,
the inverse of :func:`asset_pipeline.objathor.unity_to_asset`, triangles re-wound), one vertex
per face corner, ``{x, y, z}`` dicts, a flat triangle list, per-corner UVs, a gzip pickle of
protocol 4, an ``albedo.jpg`` and convex colliders (one hull per connected body).
"""

from __future__ import annotations

import gzip
import json
import pickle
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import trimesh

from asset_pipeline.load import load_file
from asset_pipeline.normalise import normalise
from asset_pipeline.objathor import unity_to_asset

DESK_UID = "0d3e5a7c9b1f4e2d8c6a4b2e0f1d3c5a"
BOX_UID = "1a2b3c4d5e6f47a8b9c0d1e2f3a4b5c6"
CLOCK_UID = "2f4e6d8c0b1a49382716a5b4c3d2e1f0"

# uid: (mesh under shared/assets, source front axis, annotation)
SPECS = {
    DESK_UID: (
        "furniture/bm_writing_desk/writing_desk.glb",
        "+y",
        {
            "category": "writing desk",
            "description": "A plain wooden writing desk with four legs.",
            "height": 75,
            "mass": 25,
            "receptacle": True,
            "onFloor": True,
            "onWall": False,
            "onObject": False,
            "onCeiling": False,
            "license_info": {"license": "by", "creator_display_name": "Tester", "uri": "u:1"},
        },
    ),
    BOX_UID: (
        "objects/bm_cardboard_box_01/cardboard_box_01.glb",
        "+x",
        {
            "category": "cardboard box",
            "description_auto": "A closed brown cardboard box.",
            "mass": "0.4",
            "receptacle": "true",
            "onFloor": True,
            "onObject": True,
        },
    ),
    CLOCK_UID: (
        "objects/bm_wall_clock/wall_clock.glb",
        "+y",
        {
            "category": "wall clock",
            "description": "A round wall clock.",
            "mass": 1.2,
            "receptacle": False,
            "onWall": True,
            "onFloor": False,
            "onObject": False,
        },
    ),
}


@dataclass(frozen=True)
class AssetMesh:
    """A mesh in the holomj asset frame: vertices, faces, planar UVs (bottom-left origin)."""

    vertices: np.ndarray
    faces: np.ndarray
    uv: np.ndarray

    @property
    def size(self) -> np.ndarray:
        return self.vertices.max(axis=0) - self.vertices.min(axis=0)


def asset_mesh(shared: Path, rel: str, front: str) -> AssetMesh:
    """The shared mesh ``rel`` (a glTF: Y up) in the asset frame, one part, planar UVs."""
    path = shared / rel
    parts, _ = normalise(load_file(path).parts, str(path), "y", front, None)  # type: ignore[arg-type]
    vertices, faces, offset = [], [], 0
    for part in parts:
        vertices.append(part.vertices)
        faces.append(part.faces + offset)
        offset += len(part.vertices)
    v = np.concatenate(vertices)
    lo, hi = v.min(axis=0), v.max(axis=0)
    uv = np.stack([(v[:, 0] - lo[0]) / (hi[0] - lo[0]), (v[:, 2] - lo[2]) / (hi[2] - lo[2])], 1)
    return AssetMesh(v, np.concatenate(faces), uv)


def to_unity(points: np.ndarray, y_rot_offset_deg: float = 0.0) -> np.ndarray:
    """Asset frame -> the frame objathor stores (the inverse of ``unity_to_asset``)."""
    inverse = np.linalg.inv(unity_to_asset(y_rot_offset_deg))
    return np.asarray(points, dtype=np.float64) @ inverse.T


def _dicts(points: np.ndarray, keys: str = "xyz") -> list[dict[str, float]]:
    return [dict(zip(keys, map(float, row), strict=True)) for row in points]


def body_hulls(mesh: AssetMesh) -> list[np.ndarray]:
    """Convex hull vertices of each connected body (the shipped colliders of the tests)."""
    tm = trimesh.Trimesh(mesh.vertices, mesh.faces, process=True)
    hulls = []
    for body in tm.split(only_watertight=False):
        if len(body.vertices) >= 4:
            hulls.append(np.asarray(body.convex_hull.vertices))
    return hulls


def mesh_dict(
    mesh: AssetMesh,
    uid: str,
    *,
    colliders: bool = True,
    y_rot_offset_deg: float = 0.0,
    receptacle: bool = True,
) -> dict:
    """The objathor mesh dict of ``mesh`` (unwelded corners, flat triangles, Unity frame)."""
    corners = mesh.faces[:, ::-1].reshape(-1)  # one vertex per corner, re-wound
    vertices = to_unity(mesh.vertices[corners], y_rot_offset_deg)
    data = {
        "name": uid,
        "receptacleCandidate": receptacle,
        "albedoTexturePath": f"/machine/that/converted/{uid}/albedo.jpg",
        "normalTexturePath": "normal.jpg",
        "emissionTexturePath": "emission.jpg",
        "vertices": _dicts(vertices),
        "triangles": list(range(len(corners))),
        "normals": _dicts(np.tile([0.0, 1.0, 0.0], (len(corners), 1))),
        "uvs": _dicts(mesh.uv[corners], "xy"),
        "visibilityPoints": [],
        "physicalProperties": {"mass": 1.0, "drag": 0, "angularDrag": 0.05},
        "yRotOffset": y_rot_offset_deg,
    }
    if colliders:
        data["colliders"] = []
        for hull in body_hulls(mesh):
            tri = trimesh.convex.convex_hull(hull)
            data["colliders"].append(
                {
                    "vertices": _dicts(to_unity(tri.vertices, y_rot_offset_deg)),
                    "triangles": np.asarray(tri.faces)[:, ::-1].reshape(-1).tolist(),
                }
            )
    return data


def write_texture(path: Path) -> None:
    """A small checker JPEG."""
    from PIL import Image

    cells = (np.indices((8, 8)).sum(axis=0) % 2).astype(np.uint8)
    pixels = np.kron(cells, np.ones((8, 8), dtype=np.uint8))
    rgb = np.stack([pixels * 200 + 30, pixels * 120 + 60, 90 + 0 * pixels], axis=-1)
    Image.fromarray(rgb.astype(np.uint8)).save(path, format="JPEG", quality=90)


def write_pickle(path: Path, data: object) -> None:
    with gzip.open(path, "wb") as handle:
        pickle.dump(data, handle, protocol=4)


def thor_bbox(mesh: AssetMesh) -> dict:
    """THOR's axis-aligned box of the asset at rotation 0 (Unity axes: x = -Y, y = Z, z = X)."""
    sx, sy, sz = mesh.size
    return {
        "min": {"x": -sy / 2, "y": 0.0, "z": -sx / 2},
        "max": {"x": sy / 2, "y": sz, "z": sx / 2},
    }


def build_objathor_dir(
    root: Path,
    shared: Path,
    uids: tuple[str, ...] = (DESK_UID, BOX_UID, CLOCK_UID),
    *,
    y_rot_offset_deg: float = 0.0,
) -> dict[str, AssetMesh]:
    """Write ``root/annotations.json.gz`` and ``root/assets/<uid>/`` for ``uids``."""
    meshes, annotations = {}, {}
    for uid in uids:
        rel, front, annotation = SPECS[uid]
        mesh = asset_mesh(shared, rel, front)
        folder = root / "assets" / uid
        folder.mkdir(parents=True)
        data = mesh_dict(
            mesh,
            uid,
            y_rot_offset_deg=y_rot_offset_deg,
            receptacle=annotation["receptacle"] in (True, "true"),
        )
        write_pickle(folder / f"{uid}.pkl.gz", data)
        write_texture(folder / "albedo.jpg")
        meshes[uid] = mesh
        annotations[uid] = {
            **annotation,
            "uid": uid,
            "thor_metadata": {"assetMetadata": {"boundingBox": thor_bbox(mesh)}},
        }
    with gzip.open(root / "annotations.json.gz", "wt", encoding="utf-8") as handle:
        json.dump(annotations, handle)
    return meshes
