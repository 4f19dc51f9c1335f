"""Shared helpers of the importer tests: low CoACD settings, a one-object scene, a box OBJ."""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np

from asset_pipeline.importer import CoacdParams, ImportedAsset
from asset_pipeline.library_writer import write_library
from holomj.library import AssetLibrary
from holomj.mjcf import compile_scene
from holomj.physics.smoke import warning_counts
from holomj.spec.scene import SceneSpec

# Low settings keep each CoACD run to a few seconds.
LOW = CoacdParams(
    threshold=0.2,
    max_convex_hull=4,
    mcts_iterations=20,
    preprocess_resolution=20,
    resolution=500,
    timeout_s=60.0,
)


def box_obj(sx: float = 0.2, sy: float = 0.1, sz: float = 0.05, z0: float = 0.0) -> str:
    """OBJ text of an axis-aligned box with outward faces."""
    x, y = sx / 2, sy / 2
    v = [
        (-x, -y, z0),
        (x, -y, z0),
        (x, y, z0),
        (-x, y, z0),
        (-x, -y, z0 + sz),
        (x, -y, z0 + sz),
        (x, y, z0 + sz),
        (-x, y, z0 + sz),
    ]
    f = [
        (1, 3, 2),
        (1, 4, 3),
        (5, 6, 7),
        (5, 7, 8),
        (1, 2, 6),
        (1, 6, 5),
        (2, 3, 7),
        (2, 7, 6),
        (3, 4, 8),
        (3, 8, 7),
        (4, 1, 5),
        (4, 5, 8),
    ]
    lines = [f"v {a} {b} {c}" for a, b, c in v] + [f"f {a} {b} {c}" for a, b, c in f]
    return "\n".join(lines) + "\n"


def simulate_asset(imported: ImportedAsset, tmp: Path, seconds: float = 2.0) -> dict:
    """Write the bundle, open the library, drop the asset as a free object and step it."""
    root = write_library(tmp / "lib", "imported", [imported.bundle])
    library = AssetLibrary.open(root)
    asset_id = imported.bundle.meta.id
    scene = SceneSpec.model_validate(
        {
            "rooms": [{"id": "room", "polygon": [[0, 0], [4, 0], [4, 4], [0, 4]]}],
            "objects": [{"id": "obj", "asset": asset_id, "position": [2, 2, 0], "yaw_deg": 30}],
        }
    )
    model = compile_scene(scene, library).model
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    body = model.body("obj/body").id
    pos0, quat0 = data.xpos[body].copy(), data.xquat[body].copy()
    for _ in range(round(seconds / model.opt.timestep)):
        mujoco.mj_step(model, data)
    turn = np.zeros(3)
    mujoco.mju_subQuat(turn, data.xquat[body], quat0)
    mesh_ids = [i for i in range(model.nmesh) if model.mesh(i).name.startswith(f"asset/{asset_id}")]
    return {
        "model": model,
        "mass": float(model.body_mass[body]),
        "drift": float(np.linalg.norm(data.xpos[body] - pos0)),
        "rotation_deg": float(np.degrees(np.linalg.norm(turn))),
        "warnings": warning_counts(data),
        "texcoords": {model.mesh(i).name: int(model.mesh_texcoordnum[i]) for i in mesh_ids},
    }
