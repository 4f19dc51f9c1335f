"""Unity (ProcTHOR/Holodeck) frame -> holomj (MuJoCo) frame.

Unity is y-up and left-handed; holomj is z-up and right-handed. A point converts by swapping
the last two axes: holomj ``(X, Y, Z) = (unity x, unity z, unity y)`` (a reflection, which is what
turns a left-handed frame into a right-handed one).

Unity Euler angles ``(x, y, z)`` in degrees rotate about z, then x, then y (all about the world
axes), so the rotation matrix acting on Unity column vectors is ``R_u = Ry(y) Rx(x) Rz(z)`` with
the usual matrix formulas. In holomj coordinates that rotation is ``P R_u P`` (``P`` swaps the
last two axes). ProcTHOR assets face Unity ``+z`` (holomj ``+Y``) at rotation 0, while holomj
assets face ``+X``, so the holomj orientation is ``Q = P R_u P Rz(90°)``.

For a pure yaw this gives ``yaw_deg = 90 - rotation.y``: ``rotation.y = 90`` turns the front from
Unity ``+z`` to Unity ``+x`` (clockwise seen from above), which is holomj ``+X``, i.e. yaw 0.
"""

from __future__ import annotations

import math
from collections.abc import Iterable

Matrix = tuple[tuple[float, float, float], tuple[float, float, float], tuple[float, float, float]]

_TILT_TOL_DEG = 1e-6


def unity_point(x: float, y: float, z: float) -> tuple[float, float, float]:
    """A Unity point or vector in holomj coordinates."""
    return (x, z, y)


def normalise_deg(angle: float) -> float:
    """An angle in degrees mapped to (-180, 180]."""
    wrapped = math.fmod(angle, 360.0)
    if wrapped <= -180.0:
        wrapped += 360.0
    elif wrapped > 180.0:
        wrapped -= 360.0
    return 0.0 if wrapped == 0.0 else wrapped


def yaw_from_unity(rotation_y: float) -> float:
    """holomj yaw (degrees, CCW about +Z, 0 facing +X) for a Unity yaw (CW, 0 facing +z)."""
    return normalise_deg(90.0 - rotation_y)


def is_tilted(rx: float, rz: float) -> bool:
    """True if a Unity rotation has a non-zero x or z component (modulo 360)."""
    return abs(normalise_deg(rx)) > _TILT_TOL_DEG or abs(normalise_deg(rz)) > _TILT_TOL_DEG


def _rot_x(deg: float) -> Matrix:
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return ((1.0, 0.0, 0.0), (0.0, c, -s), (0.0, s, c))


def _rot_y(deg: float) -> Matrix:
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return ((c, 0.0, s), (0.0, 1.0, 0.0), (-s, 0.0, c))


def _rot_z(deg: float) -> Matrix:
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return ((c, -s, 0.0), (s, c, 0.0), (0.0, 0.0, 1.0))


def _mul(a: Matrix, b: Matrix) -> Matrix:
    rows = [triple(sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)) for i in range(3)]
    return (rows[0], rows[1], rows[2])


def triple(values: Iterable[float]) -> tuple[float, float, float]:
    """Exactly three values as a typed triple."""
    x, y, z = values
    return (x, y, z)


_SWAP: Matrix = ((1.0, 0.0, 0.0), (0.0, 0.0, 1.0), (0.0, 1.0, 0.0))


def unity_rotation_matrix(rx: float, ry: float, rz: float) -> Matrix:
    """The Unity rotation ``Ry Rx Rz`` acting on Unity column vectors."""
    return _mul(_rot_y(ry), _mul(_rot_x(rx), _rot_z(rz)))


def apply(matrix: Matrix, vector: tuple[float, float, float]) -> tuple[float, float, float]:
    """``matrix @ vector``."""
    return triple(sum(matrix[i][k] * vector[k] for k in range(3)) for i in range(3))


def orientation_from_unity(rx: float, ry: float, rz: float) -> Matrix:
    """The holomj orientation matrix of an object with Unity Euler angles (degrees)."""
    in_holomj = _mul(_SWAP, _mul(unity_rotation_matrix(rx, ry, rz), _SWAP))
    return _mul(in_holomj, _rot_z(90.0))


def quat_from_matrix(m: Matrix) -> tuple[float, float, float, float]:
    """A unit quaternion (w, x, y, z) with w >= 0 for a rotation matrix."""
    trace = m[0][0] + m[1][1] + m[2][2]
    if trace > 0.0:
        s = math.sqrt(trace + 1.0) * 2.0
        w, x = 0.25 * s, (m[2][1] - m[1][2]) / s
        y, z = (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s
    elif m[0][0] > m[1][1] and m[0][0] > m[2][2]:
        s = math.sqrt(1.0 + m[0][0] - m[1][1] - m[2][2]) * 2.0
        w, x = (m[2][1] - m[1][2]) / s, 0.25 * s
        y, z = (m[0][1] + m[1][0]) / s, (m[0][2] + m[2][0]) / s
    elif m[1][1] > m[2][2]:
        s = math.sqrt(1.0 + m[1][1] - m[0][0] - m[2][2]) * 2.0
        w, x = (m[0][2] - m[2][0]) / s, (m[0][1] + m[1][0]) / s
        y, z = 0.25 * s, (m[1][2] + m[2][1]) / s
    else:
        s = math.sqrt(1.0 + m[2][2] - m[0][0] - m[1][1]) * 2.0
        w, x = (m[1][0] - m[0][1]) / s, (m[0][2] + m[2][0]) / s
        y, z = (m[1][2] + m[2][1]) / s, 0.25 * s
    norm = math.sqrt(w * w + x * x + y * y + z * z)
    w, x, y, z = (w / norm, x / norm, y / norm, z / norm)
    if w < 0.0:
        w, x, y, z = -w, -x, -y, -z
    return (w, x, y, z)


def quat_from_unity(rx: float, ry: float, rz: float) -> tuple[float, float, float, float]:
    """The holomj orientation quaternion (w, x, y, z) for Unity Euler angles (degrees)."""
    return quat_from_matrix(orientation_from_unity(rx, ry, rz))


def unity_forward(rx: float, ry: float, rz: float) -> tuple[float, float, float]:
    """Where a Unity object (a light, say) with these angles points, in holomj coordinates."""
    fx, fy, fz = apply(unity_rotation_matrix(rx, ry, rz), (0.0, 0.0, 1.0))
    return unity_point(fx, fy, fz)


def quat_from_euler_xyz(rx: float, ry: float, rz: float) -> tuple[float, float, float, float]:
    """Quaternion for right-handed Euler angles (degrees) applied about x, then y, then z."""
    return quat_from_matrix(_mul(_rot_z(rz), _mul(_rot_y(ry), _rot_x(rx))))
