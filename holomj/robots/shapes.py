"""World-frame outlines of collision geoms, for footprints and floor occupancy maps.

A geom is summed up by a cloud of world points whose convex hull contains it: a mesh by its
vertices, a cylinder by two circumscribed 16-gons, every other shape by the corners of its local
bounding box (``geom_aabb``, a box around spheres and capsules: conservative by design).
"""

from __future__ import annotations

import math

import mujoco
import numpy as np

_CYLINDER_SIDES = 16
_CORNERS = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)], dtype=float)


def is_collider(model: mujoco.MjModel, geom: int) -> bool:
    """Geoms that take part in contacts (contype or conaffinity set)."""
    return bool(model.geom_contype[geom] or model.geom_conaffinity[geom])


def collider_ids(model: mujoco.MjModel) -> np.ndarray:
    """Ids of the geoms that take part in contacts, planes excluded."""
    colliding = (model.geom_contype != 0) | (model.geom_conaffinity != 0)
    not_plane = model.geom_type != mujoco.mjtGeom.mjGEOM_PLANE
    return np.flatnonzero(colliding & not_plane)


def local_points(model: mujoco.MjModel, geom: int) -> np.ndarray:
    """Points in the geom's frame whose convex hull contains the geom, shape (n, 3)."""
    kind = model.geom_type[geom]
    if kind == mujoco.mjtGeom.mjGEOM_MESH and model.geom_dataid[geom] >= 0:
        mesh = model.geom_dataid[geom]
        start = model.mesh_vertadr[mesh]
        return np.asarray(model.mesh_vert[start : start + model.mesh_vertnum[mesh]], dtype=float)
    if kind == mujoco.mjtGeom.mjGEOM_CYLINDER:
        radius, half = model.geom_size[geom][:2]
        circumscribed = radius / math.cos(math.pi / _CYLINDER_SIDES)
        angles = np.arange(_CYLINDER_SIDES) * (2 * math.pi / _CYLINDER_SIDES)
        ring = np.column_stack([np.cos(angles), np.sin(angles)]) * circumscribed
        return np.vstack([np.column_stack([ring, np.full(len(ring), z)]) for z in (-half, half)])
    centre = model.geom_aabb[geom][:3]
    half = model.geom_aabb[geom][3:]
    return centre + _CORNERS * half


def world_points(model: mujoco.MjModel, data: mujoco.MjData, geom: int) -> np.ndarray:
    """:func:`local_points` in the world frame at ``data``'s pose (after ``mj_kinematics``)."""
    rot = data.geom_xmat[geom].reshape(3, 3)
    return local_points(model, geom) @ rot.T + data.geom_xpos[geom]
