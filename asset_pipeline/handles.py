"""Where a hand grasps an imported moving part: a heuristic for files without handle annotations.

PartNet-Mobility, URDF and MJCF files say how a part moves, not where to hold it. From the
part's own geometry (its vertices, asset frame, closed pose) and its joint:

**Hinge** (doors, lids, flaps): the free edge is where a hand pulls, as far from the axis as
the part goes. The *outward* direction ``n`` is the mean direction in which the part's farthest
points (within :data:`STRIP_M` of the largest distance from the axis) move as it opens; the
*front face* is the slab of points within :data:`FRONT_SLAB_M` of the part's extreme along
``n`` (a knob or a bar standing proud of the door is that slab; a flat door's whole face is).
The grasp point is the middle of the front-face points within ``STRIP_M`` of the face's largest
distance from the axis (the knob, the bar, or a strip along a flat door's free edge, at its
mid-height), moved along the pull direction onto the outermost of those points. The pull
direction is the direction that middle moves when the part opens (``axis x (p - anchor)``);
the grip runs along the axis.

**Slide** (drawers, racks): the front face is the slab of points within ``FRONT_SLAB_M`` of the
part's extreme along the opening axis (the knob or handle when one stands proud, else the
drawer front); the grasp point is its middle, on the surface; the pull direction is the axis;
the grip runs horizontally across it.

The grip's recorded length is the selected points' extent along the grip, at most
:data:`MAX_GRIP_M`. The grasp frame has x along the pull and z along the grip.
"""

from __future__ import annotations

from dataclasses import dataclass

import mujoco
import numpy as np

FRONT_SLAB_M = 0.01
STRIP_M = 0.04
MAX_GRIP_M = 0.3


@dataclass(frozen=True)
class Grasp:
    """A derived handle: position, grasp-frame quaternion (w, x, y, z), pull, grip length."""

    pos: tuple[float, float, float]
    quat: tuple[float, float, float, float]
    pull: tuple[float, float, float]
    length_m: float

    def record(self) -> dict:
        """The :class:`~holomj.spec.assets.Handle` fields."""
        return {
            "pos": list(self.pos),
            "quat": list(self.quat),
            "pull": list(self.pull),
            "length_m": self.length_m,
        }


def derive_grasp(points: np.ndarray, kind: str, axis: np.ndarray, anchor: np.ndarray) -> Grasp:
    """The grasp of a part with vertices ``points`` moving on a ``kind`` (hinge or slide) joint
    with unit ``axis`` through ``anchor`` (positive values open)."""
    points = np.asarray(points, dtype=float)
    axis = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    anchor = np.asarray(anchor, dtype=float)
    if kind == "slide":
        return _slide(points, axis)
    return _hinge(points, axis, anchor)


def _slide(points: np.ndarray, axis: np.ndarray) -> Grasp:
    depth = points @ axis
    front = points[depth >= depth.max() - FRONT_SLAB_M]
    pos = _on_face((front.min(axis=0) + front.max(axis=0)) / 2, axis, float(depth.max()))
    grip = np.cross((0.0, 0.0, 1.0), axis)
    if np.linalg.norm(grip) < 0.1:  # a vertical slide: grip along x
        grip = np.cross((1.0, 0.0, 0.0), axis)
    grip /= np.linalg.norm(grip)
    return _grasp(pos, axis, grip, front)


def _hinge(points: np.ndarray, axis: np.ndarray, anchor: np.ndarray) -> Grasp:
    rel = points - anchor
    radial = rel - np.outer(rel @ axis, axis)
    r = np.linalg.norm(radial, axis=1)
    if r.max() < 1e-6:  # a part on its own axis (a knob): its centre, pulled sideways
        side = np.cross(axis, (0.0, 0.0, 1.0))
        if np.linalg.norm(side) < 0.1:
            side = np.cross(axis, (1.0, 0.0, 0.0))
        return _grasp(points.mean(axis=0), side / np.linalg.norm(side), axis, points)
    strip = min(STRIP_M, 0.25 * float(r.max()))
    far = r >= r.max() - strip
    moves = np.cross(axis, radial[far])
    moves /= np.maximum(np.linalg.norm(moves, axis=1, keepdims=True), 1e-12)
    outward = moves.mean(axis=0)
    outward /= max(float(np.linalg.norm(outward)), 1e-12)
    depth = points @ outward
    face = depth >= depth.max() - FRONT_SLAB_M
    chosen = face & (r >= r[face].max() - strip)
    selected = points[chosen]
    middle = (selected.min(axis=0) + selected.max(axis=0)) / 2
    pull = np.cross(axis, middle - anchor)
    pull = pull / np.linalg.norm(pull) if np.linalg.norm(pull) > 1e-9 else outward
    pos = _on_face(middle, pull, float((selected @ pull).max()))
    return _grasp(pos, pull, axis, selected)


def _on_face(point: np.ndarray, normal: np.ndarray, level: float) -> np.ndarray:
    """``point`` moved along ``normal`` onto the plane ``x . normal = level``."""
    return point + normal * (level - float(point @ normal))


def _grasp(pos: np.ndarray, pull: np.ndarray, grip: np.ndarray, selected: np.ndarray) -> Grasp:
    pull = pull / np.linalg.norm(pull)
    grip = grip - pull * float(grip @ pull)
    grip /= np.linalg.norm(grip)
    along = selected @ grip
    length = min(MAX_GRIP_M, float(along.max() - along.min())) if len(selected) else 0.0
    return Grasp(
        pos=_round(pos),
        quat=frame_quat(pull, grip),
        pull=_round(pull),
        length_m=round(length, 4),
    )


def frame_quat(x_axis: np.ndarray, z_axis: np.ndarray) -> tuple[float, float, float, float]:
    """The unit quaternion (w, x, y, z) of the right-handed frame with these x and z axes."""
    x = np.asarray(x_axis, dtype=float)
    z = np.asarray(z_axis, dtype=float)
    y = np.cross(z, x)
    matrix = np.column_stack([x, y, z])
    quat = np.zeros(4)
    mujoco.mju_mat2Quat(quat, matrix.ravel())
    if quat[0] < 0:
        quat = -quat
    qw, qx, qy, qz = (round(float(v), 9) + 0.0 for v in quat)
    return (qw, qx, qy, qz)


def _round(vector: np.ndarray) -> tuple[float, float, float]:
    x, y, z = (round(float(v), 6) + 0.0 for v in vector)
    return (x, y, z)


def lever_m(pos: tuple[float, float, float], axis: np.ndarray, anchor: np.ndarray) -> float:
    """The distance of ``pos`` from the hinge axis."""
    rel = np.asarray(pos) - anchor
    return float(np.linalg.norm(rel - axis * float(rel @ axis)))
