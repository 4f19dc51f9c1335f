"""Small scenes for the validation tests: built as SceneSpecs, compiled and exported."""

from __future__ import annotations

import math
from pathlib import Path

import trimesh

from asset_pipeline.library_writer import AssetBundle, write_library
from holomj.jobs.folder import write_scene_folder
from holomj.library import AssetLibrary
from holomj.mjcf import compile_scene
from holomj.spec.assets import AssetMeta
from holomj.spec.report import Thresholds
from holomj.spec.scene import SceneSpec

ROOM = {"id": "room", "polygon": [[0, 0], [6, 0], [6, 6], [0, 6]]}
# Shorter windows than the defaults keep the suite fast; every case still settles or fails.
FAST = Thresholds(settle_cap_s=3.0, monitor_s=1.5)


def box(object_id: str, position, size, **fields) -> dict:
    """A builtin:box object of ``size`` (x, y, z extents) whose bottom centre is ``position``."""
    return {
        "id": object_id,
        "asset": "builtin:box",
        "position": list(position),
        "scale": list(size),
        "room": "room",
        **fields,
    }


def make_scene(objects: list[dict], name: str = "test") -> SceneSpec:
    """A 6 x 6 m room holding ``objects``."""
    return SceneSpec.model_validate({"name": name, "rooms": [ROOM], "objects": objects})


def export(
    scene: SceneSpec, library: AssetLibrary, out: Path, extra_json: dict | None = None
) -> Path:
    """Compile ``scene`` and export it to ``out`` (with extra JSON files); returns ``out``."""
    return write_scene_folder(compile_scene(scene, library), out, extra_json=extra_json)


def _primitive_mesh(part: dict) -> trimesh.Trimesh:
    """A visual mesh of one primitive collider (MuJoCo half-sizes), placed as the collider."""
    kind, size = part["kind"], part["size"]
    if kind == "sphere":
        mesh = trimesh.creation.icosphere(subdivisions=2, radius=size[0])
    elif kind == "cylinder":
        mesh = trimesh.creation.cylinder(radius=size[0], height=2 * size[1], sections=24)
    else:
        mesh = trimesh.creation.box(extents=[2 * h for h in size])
    mesh.apply_translation(part.get("pos", (0.0, 0.0, 0.0)))
    return mesh


def _primitive_volume(part: dict) -> float:
    kind, size = part["kind"], part["size"]
    if kind == "sphere":
        return 4.0 / 3.0 * math.pi * size[0] ** 3
    if kind == "cylinder":
        return math.pi * size[0] ** 2 * 2 * size[1]
    return 8.0 * size[0] * size[1] * size[2]


def primitive_library(root: Path, assets: dict[str, dict]) -> AssetLibrary:
    """A library of assets made of primitive colliders, each drawn by a mesh of its own shape.

    ``assets`` maps an id to AssetMeta fields whose ``collision`` parts give ``kind``, ``size``
    and ``pos`` only (volumes are computed); ``visual`` is made from the colliders."""
    bundles = []
    for asset_id, fields in assets.items():
        parts = [{**part, "volume_m3": _primitive_volume(part)} for part in fields["collision"]]
        mesh = trimesh.util.concatenate([_primitive_mesh(part) for part in parts])
        obj = trimesh.exchange.obj.export_obj(mesh, include_normals=False, include_texture=False)
        meta = AssetMeta.model_validate(
            {
                "category": asset_id,
                **fields,
                "id": asset_id,
                "visual": [{"mesh": f"{asset_id}.obj"}],
                "collision": parts,
            }
        )
        bundles.append(AssetBundle(meta, {f"{asset_id}.obj": obj.encode()}))
    write_library(root, "primitives", bundles)
    return AssetLibrary.open(root)


def sphere_library(root: Path, radius: float = 0.05) -> AssetLibrary:
    """A library with one asset, ``ball``: a sphere collider and an icosphere visual mesh."""
    ball = {
        "size": [2 * radius] * 3,
        "density_kg_m3": 800.0,
        "placement": ["object"],
        "collision": [{"kind": "sphere", "size": [radius], "pos": [0.0, 0.0, radius]}],
    }
    return primitive_library(root, {"ball": ball})
