"""Bodies welded together (no joint between them) as one rigid piece: which bodies they are and
their combined mass properties. The URDF and USD exports both make one link (rigid body) of
each such piece."""

from __future__ import annotations

import numpy as np

from holomj.formats.model_geometry import ModelGeometry


def welded(geo: ModelGeometry, body: int) -> list[int]:
    """``body`` and the descendants welded to it (no joint in between), depth first."""
    out = [body]
    for child in geo.children[body]:
        if not geo.model.body_jntnum[child]:
            out += welded(geo, child)
    return out


def welded_inertia(
    geo: ModelGeometry, members: list[int], frame_pos: np.ndarray, frame_rot: np.ndarray
) -> tuple[float, np.ndarray, np.ndarray, np.ndarray] | None:
    """Mass, centre of mass, principal inertia and principal axes (a rotation matrix, columns
    the axes) of ``members`` in the frame at ``frame_pos``/``frame_rot`` (world); a single
    body keeps its own principal frame. None when they have no mass."""
    model, data = geo.model, geo.data
    masses = np.array([float(model.body_mass[m]) for m in members])
    total = float(masses.sum())
    if total <= 0:
        return None
    centres = np.array([frame_rot.T @ (data.xipos[m] - frame_pos) for m in members])
    centre = (masses[:, None] * centres).sum(axis=0) / total
    if len(members) == 1:
        axes = frame_rot.T @ data.ximat[members[0]].reshape(3, 3)
        return total, centre, np.asarray(model.body_inertia[members[0]], dtype=float), axes
    tensor = np.zeros((3, 3))
    for index, member in enumerate(members):
        irot = frame_rot.T @ data.ximat[member].reshape(3, 3)
        offset = centres[index] - centre
        tensor += irot @ np.diag(model.body_inertia[member]) @ irot.T
        tensor += masses[index] * (np.dot(offset, offset) * np.eye(3) - np.outer(offset, offset))
    values, vectors = np.linalg.eigh(tensor)
    if np.linalg.det(vectors) < 0:
        vectors[:, 2] *= -1
    return total, centre, values, vectors
