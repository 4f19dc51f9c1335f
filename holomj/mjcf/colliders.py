"""The MjsGeom fields of a library collider (box, cylinder, capsule, sphere or mesh) at a scale.

Used for a scene object's carcass (:mod:`holomj.mjcf.objects`) and for the moving parts of an
articulated one (:mod:`holomj.mjcf.articulation`).
"""

from __future__ import annotations

import math

import mujoco
import numpy as np

from holomj.mjcf.geometry import clean
from holomj.spec.assets import CollisionPart

_PRIMITIVES = {
    "box": mujoco.mjtGeom.mjGEOM_BOX,
    "cylinder": mujoco.mjtGeom.mjGEOM_CYLINDER,
    "sphere": mujoco.mjtGeom.mjGEOM_SPHERE,
    "capsule": mujoco.mjtGeom.mjGEOM_CAPSULE,
}


def collider_fields(
    part: CollisionPart, scale: tuple[float, float, float], mesh_name: str | None
) -> dict[str, object]:
    """MjsGeom fields (type, size, pos, quat, mesh) of a collider at a given scale."""
    pos = clean(np.array(part.pos) * np.array(scale))
    quat = clean(part.quat)
    if part.kind == "mesh":
        return {"type": mujoco.mjtGeom.mjGEOM_MESH, "meshname": mesh_name, "pos": pos, "quat": quat}
    rot = np.zeros(9)
    mujoco.mju_quat2Mat(rot, np.array(part.quat, dtype=float))
    # Scale factors seen along the collider's own axes.
    lsx, lsy, lsz = np.abs(rot.reshape(3, 3).T) @ np.array(scale)
    size = list(part.size)
    if part.kind == "box":
        size = [size[0] * lsx, size[1] * lsy, size[2] * lsz]
    elif part.kind in ("cylinder", "capsule"):
        size = [size[0] * math.sqrt(lsx * lsy), size[1] * lsz]
    else:
        size = [size[0] * (lsx * lsy * lsz) ** (1 / 3)]
    return {
        "type": _PRIMITIVES[part.kind],
        "size": clean(size + [0.0] * (3 - len(size))),
        "pos": pos,
        "quat": quat,
    }
