"""World-aligned bounding boxes of geoms at a simulation state (shared by the audit and robot
placement)."""

from __future__ import annotations

import mujoco
import numpy as np


def world_aabbs(model: mujoco.MjModel, data: mujoco.MjData) -> tuple[np.ndarray, np.ndarray]:
    """World-aligned bounding boxes (low, high corners) of every geom at the current pose."""
    centre = model.geom_aabb[:, :3]
    half = model.geom_aabb[:, 3:]
    xmat = data.geom_xmat.reshape(-1, 3, 3)
    world_centre = data.geom_xpos + np.einsum("gij,gj->gi", xmat, centre)
    world_half = np.einsum("gij,gj->gi", np.abs(xmat), half)
    return world_centre - world_half, world_centre + world_half
