"""Shared helpers of the spawn-and-drop tests: one-receptacle scenes and a physical check."""

from __future__ import annotations

import mujoco
import numpy as np

from holomj.library import AssetLibrary
from holomj.mjcf import compile_scene, names
from holomj.physics.drop_world import tilt_deg
from holomj.physics.smoke import warning_counts
from holomj.spec.scene import Room, SceneObject, SceneSpec

SMALL = ["mug", "book", "bowl", "apple", "toy_block", "bottle", "cup", "plate", "candle", "remote"]


def receptacle_scene(asset: str, *, static: bool = True, yaw_deg: float = 30.0) -> SceneSpec:
    """A 4 x 4 m room with one receptacle (id ``rec``) at its centre."""
    return SceneSpec(
        name="spawn_test",
        rooms=[Room(id="room", polygon=[(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (0.0, 4.0)])],
        objects=[
            SceneObject(
                id="rec",
                asset=asset,
                position=(2.0, 2.0, 0.0),
                yaw_deg=yaw_deg,
                static=static,
                room="room",
            )
        ],
    )


def settle_check(scene: SceneSpec, library: AssetLibrary, ids: list[str], seconds: float = 2.0):
    """Compile ``scene`` (small objects free), simulate, and report per object: how far it
    moved, whether it touches the receptacle ``rec``, its final tilt; plus MuJoCo warnings."""
    model = compile_scene(scene, library).model
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    bodies = {i: model.body(names.object_body(i)).id for i in ids}
    start = {i: data.xpos[b].copy() for i, b in bodies.items()}
    for _ in range(round(seconds / model.opt.timestep)):
        mujoco.mj_step(model, data)
    rec = model.body(names.object_body("rec")).id
    touching = set()
    for k in range(data.ncon):
        b1, b2 = (int(b) for b in model.geom_bodyid[data.contact.geom[k]])
        if rec in (b1, b2):
            touching.add(b2 if b1 == rec else b1)
    return {
        i: {
            "moved": float(np.linalg.norm(data.xpos[b] - start[i])),
            "on_rec": b in touching,
            "tilt_deg": tilt_deg(data.xquat[b]),
        }
        for i, b in bodies.items()
    }, warning_counts(data)
