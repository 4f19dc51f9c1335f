"""Shared helpers of the articulated-asset tests: one-object scenes and a hand on a handle.

A "pull" is what the issue asks of every moving part: a 30 N force on the handle's body, applied
at the handle (``xfrc_applied``: the force and its moment about the body's centre of mass),
along the direction that opens the part there (the tangent of a hinge's circle through the
handle, a slide's axis); a "push" is the same force reversed.
"""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np

from asset_pipeline.procedural.articulated import build_articulated_library
from holomj.library import AssetLibrary
from holomj.mjcf import compile_scene
from holomj.mjcf.compiler import CompiledScene
from holomj.spec.scene import SceneSpec

PULL_N = 30.0
HINGE = int(mujoco.mjtJoint.mjJNT_HINGE)
SLIDE = int(mujoco.mjtJoint.mjJNT_SLIDE)
ROOM = {"id": "room", "polygon": [[0, 0], [6, 0], [6, 6], [0, 6]]}


def articulated_library(root: Path, categories: list[str] | None = None) -> AssetLibrary:
    """A library of the articulated assets (of ``categories``) at ``root``."""
    return AssetLibrary.open(build_articulated_library(root, categories))


def one_object_scene(asset: str, *, static: bool = True, objects: list[dict] | None = None):
    """A 6 x 6 m room with ``asset`` standing at its centre (object id ``obj``)."""
    main = {"id": "obj", "asset": asset, "position": [3.0, 3.0, 0.0], "room": "room"}
    main["static"] = static
    data = {"name": "articulated", "rooms": [ROOM], "objects": [main, *(objects or [])]}
    return SceneSpec.model_validate(data)


def compiled_object(library: AssetLibrary, asset: str, *, static: bool = True) -> CompiledScene:
    """``asset`` compiled alone in a room (fixed carcass unless ``static`` is False)."""
    return compile_scene(one_object_scene(asset, static=static), library)


def part_joints(model: mujoco.MjModel, prefix: str = "obj/") -> list[int]:
    """The hinge and slide joints of the object's moving parts."""
    return [
        j
        for j in range(model.njnt)
        if int(model.jnt_type[j]) in (HINGE, SLIDE) and model.joint(j).name.startswith(prefix)
    ]


def value(model: mujoco.MjModel, data: mujoco.MjData, joint: int) -> float:
    """The joint's value (radians or metres)."""
    return float(data.qpos[model.jnt_qposadr[joint]])


def handle_site(model: mujoco.MjModel, joint: int) -> int:
    """The handle site of the part the joint moves."""
    body = model.body(int(model.jnt_bodyid[joint])).name
    return model.site(f"{body}/handle").id


def apply_pull(model: mujoco.MjModel, data: mujoco.MjData, joint: int, sign: float) -> None:
    """Set ``xfrc_applied`` to a PULL_N force at the handle along the opening (sign +1) or
    closing (sign -1) direction; clears every other applied force."""
    data.xfrc_applied[:] = 0.0
    body = int(model.jnt_bodyid[joint])
    point = data.site_xpos[handle_site(model, joint)]
    if int(model.jnt_type[joint]) == HINGE:
        direction = np.cross(data.xaxis[joint], point - data.xanchor[joint])
        direction /= np.linalg.norm(direction)
    else:
        direction = data.xaxis[joint].copy()
    force = sign * PULL_N * direction
    data.xfrc_applied[body, :3] = force
    data.xfrc_applied[body, 3:] = np.cross(point - data.xipos[body], force)


def simulate(
    model: mujoco.MjModel,
    data: mujoco.MjData,
    seconds: float,
    joint: int | None = None,
    sign: float = 0.0,
) -> float:
    """Step ``seconds`` (pulling on ``joint`` when given); returns the deepest contact seen
    (metres, 0 when none)."""
    deepest = 0.0
    for _ in range(round(seconds / model.opt.timestep)):
        if joint is not None:
            apply_pull(model, data, joint, sign)
        mujoco.mj_step(model, data)
        if data.ncon:
            deepest = max(deepest, float(-data.contact.dist[: data.ncon].min()))
    data.xfrc_applied[:] = 0.0
    return deepest


def clearance_to_parent(model: mujoco.MjModel, data: mujoco.MjData, joint: int) -> float:
    """The smallest signed distance between a colliding geom of the part the joint moves and one
    of the body it hangs on (their contacts are excluded, so this is checked by geometry)."""
    body = int(model.jnt_bodyid[joint])
    parent = int(model.body_parentid[body])

    def colliders(b: int) -> list[int]:
        first, count = model.body_geomadr[b], model.body_geomnum[b]
        return [
            g
            for g in range(first, first + count)
            if model.geom_contype[g] or model.geom_conaffinity[g]
        ]

    fromto = np.zeros(6)
    return min(
        mujoco.mj_geomDistance(model, data, a, b, 0.05, fromto)
        for a in colliders(body)
        for b in colliders(parent)
    )


def warnings_of(data: mujoco.MjData) -> dict[str, int]:
    """MuJoCo's warnings raised so far, by name."""
    return {
        mujoco.mjtWarning(k).name: int(w.number) for k, w in enumerate(data.warning) if w.number
    }
