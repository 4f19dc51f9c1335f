"""Small scenes for the validation tests: built as SceneSpecs, compiled and exported."""

from __future__ import annotations

import math
from pathlib import Path

import trimesh

from asset_pipeline.library_writer import AssetBundle, write_library
from holomj.export import export_scene
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
    return export_scene(compile_scene(scene, library), out, extra_json=extra_json)


def sphere_library(root: Path, radius: float = 0.05) -> AssetLibrary:
    """A library with one asset, ``ball``: a sphere collider and an icosphere visual mesh."""
    mesh = trimesh.creation.icosphere(subdivisions=2, radius=radius)
    mesh.apply_translation([0.0, 0.0, radius])
    obj = trimesh.exchange.obj.export_obj(mesh, include_normals=False, include_texture=False)
    meta = AssetMeta.model_validate(
        {
            "id": "ball",
            "category": "ball",
            "size": [2 * radius] * 3,
            "density_kg_m3": 800.0,
            "placement": ["object"],
            "visual": [{"mesh": "ball.obj"}],
            "collision": [
                {
                    "kind": "sphere",
                    "size": [radius],
                    "pos": [0.0, 0.0, radius],
                    "volume_m3": 4.0 / 3.0 * math.pi * radius**3,
                }
            ],
        }
    )
    write_library(root, "balls", [AssetBundle(meta, {"ball.obj": obj.encode()})])
    return AssetLibrary.open(root)
