"""Assets made of real visual meshes and convex hull meshes, read from an on-disk library."""

from __future__ import annotations

import json
from pathlib import Path

import mujoco
import numpy as np
import pytest
import trimesh

from holomj.library import AssetLibrary
from holomj.mjcf import compile_scene
from holomj.physics.smoke import simulate
from holomj.spec.scene import SceneSpec

Y_UP_TO_Z_UP = np.array([[1, 0, 0, 0], [0, 0, -1, 0], [0, 1, 0, 0], [0, 0, 0, 1]], dtype=float)


def _write_mesh_asset(root: Path, asset_id: str, source: Path, category: str, mass: float) -> None:
    """Normalise a glTF mesh (y-up) and store it with its convex hull as a library asset."""
    mesh = trimesh.load(source, force="mesh")
    mesh.apply_transform(Y_UP_TO_Z_UP)
    lo, hi = mesh.bounds
    mesh.apply_translation([-(lo[0] + hi[0]) / 2, -(lo[1] + hi[1]) / 2, -lo[2]])
    hull = mesh.convex_hull
    folder = root / "assets" / asset_id
    folder.mkdir(parents=True)
    mesh.export(folder / "visual.obj", include_texture=False)
    hull.export(folder / "hull.obj")
    meta = {
        "id": asset_id,
        "category": category,
        "size": [float(v) for v in mesh.extents],
        "mass_kg": mass,
        "placement": ["object"],
        "visual": [{"mesh": "visual.obj", "rgba": [0.8, 0.8, 0.8, 1.0]}],
        "collision": [{"kind": "mesh", "mesh": "hull.obj", "volume_m3": float(hull.volume)}],
    }
    (folder / "asset.json").write_text(json.dumps(meta))


@pytest.fixture
def mesh_library(tmp_path: Path, shared_assets: Path) -> AssetLibrary:
    root = tmp_path / "lib"
    sources = {
        "mug": ("objects/bm_coffee_cup", "mug", 0.3),
        "bowl": ("objects/bm_bowl_01", "bowl", 0.4),
    }
    index = {}
    for asset_id, (folder, category, mass) in sources.items():
        glb = next((shared_assets / folder).glob("*.glb"))
        _write_mesh_asset(root, asset_id, glb, category, mass)
        index[asset_id] = f"assets/{asset_id}"
    (root / "library.json").write_text(json.dumps({"name": "meshes", "assets": index}))
    return AssetLibrary.open(root)


def test_mesh_assets_compile_rest_and_weigh_what_they_should(mesh_library: AssetLibrary) -> None:
    scene = SceneSpec.model_validate(
        {
            "rooms": [{"id": "room", "polygon": [[0, 0], [3, 0], [3, 3], [0, 3]]}],
            "objects": [
                {"id": "mug_1", "asset": "mug", "position": [1, 1, 0], "yaw_deg": 45},
                {"id": "mug_2", "asset": "mug", "position": [2, 1, 0], "scale": 1.5},
                {"id": "bowl_1", "asset": "bowl", "position": [1.5, 2, 0]},
            ],
        }
    )
    compiled = compile_scene(scene, mesh_library)
    model = compiled.model
    assert model.body("mug_1/body").mass[0] == pytest.approx(0.3, rel=0.02)
    assert model.body("mug_2/body").mass[0] == pytest.approx(0.3 * 1.5**3, rel=0.02)
    assert (
        model.mesh("asset/mug/collision_0").id != model.mesh("asset/mug@1.5x1.5x1.5/collision_0").id
    )
    # Each unique file is written once, under a folder named after the asset.
    assert sorted(compiled.files) == [
        "bowl/hull.obj",
        "bowl/visual.obj",
        "mug/hull.obj",
        "mug/visual.obj",
    ]
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    start = data.body("mug_1/body").xpos.copy()
    assert simulate(model, 1.0).ok
    for _ in range(1000):
        mujoco.mj_step(model, data)
    assert np.linalg.norm(data.body("mug_1/body").xpos - start) < 0.005
