"""Unity -> holomj frame conversion on worked examples."""

from __future__ import annotations

import math

import pytest

from holomj.importers.frames import (
    apply,
    is_tilted,
    normalise_deg,
    orientation_from_unity,
    quat_from_unity,
    unity_forward,
    unity_point,
    yaw_from_unity,
)


def _quat_yaw(yaw_deg: float) -> tuple[float, float, float, float]:
    half = math.radians(yaw_deg) / 2
    return (math.cos(half), 0.0, 0.0, math.sin(half))


def _same_rotation(q1: tuple[float, ...], q2: tuple[float, ...]) -> bool:
    return abs(abs(sum(a * b for a, b in zip(q1, q2, strict=True))) - 1.0) < 1e-9


def test_point_swaps_y_and_z() -> None:
    assert unity_point(1.0, 2.0, 3.0) == (1.0, 3.0, 2.0)


@pytest.mark.parametrize(
    ("rotation_y", "yaw"),
    [(90.0, 0.0), (0.0, 90.0), (180.0, -90.0), (270.0, 180.0), (-90.0, 180.0), (45.0, 45.0)],
)
def test_yaw_worked_examples(rotation_y: float, yaw: float) -> None:
    # rotation.y = 90 turns the front from unity +z to unity +x, which is holomj +X: yaw 0.
    assert yaw_from_unity(rotation_y) == pytest.approx(yaw)


def test_front_of_rotated_object_points_where_unity_says() -> None:
    for rotation_y in (0.0, 30.0, 90.0, 135.0, 200.0, 300.0):
        # Unity: front +z rotated by Ry(rotation_y) (clockwise seen from above).
        ry = math.radians(rotation_y)
        unity_front = (math.sin(ry), 0.0, math.cos(ry))
        expected = unity_point(*unity_front)
        # holomj: the asset front +X turned by the yaw.
        yaw = math.radians(yaw_from_unity(rotation_y))
        assert (math.cos(yaw), math.sin(yaw)) == pytest.approx(expected[:2], abs=1e-12)
        assert apply(orientation_from_unity(0, rotation_y, 0), (1.0, 0.0, 0.0)) == pytest.approx(
            expected, abs=1e-12
        )


def test_quaternion_of_pure_yaw_matches_yaw() -> None:
    for rotation_y in (0.0, 90.0, 123.0, -45.0):
        assert _same_rotation(
            quat_from_unity(0.0, rotation_y, 0.0), _quat_yaw(yaw_from_unity(rotation_y))
        )


def test_tilted_worked_example() -> None:
    # Unity rotation.x = 90 tips an object forward: its up axis (unity +y) goes to unity +z...
    m = orientation_from_unity(90.0, 0.0, 0.0)
    # ... i.e. holomj up (+Z) goes to holomj +Y, and its front (holomj +X after the +90 turn,
    # which is unity +z) goes down to unity -y = holomj -Z.
    assert apply(m, (0.0, 0.0, 1.0)) == pytest.approx((0.0, 1.0, 0.0), abs=1e-12)
    assert apply(m, (1.0, 0.0, 0.0)) == pytest.approx((0.0, 0.0, -1.0), abs=1e-12)
    q = quat_from_unity(90.0, 0.0, 0.0)
    assert math.isclose(sum(c * c for c in q), 1.0)
    # A proper rotation, not a reflection.
    assert _det(m) == pytest.approx(1.0)


def test_tilt_detection_is_modulo_360() -> None:
    assert not is_tilted(0.0, 360.0)
    assert not is_tilted(-360.0, 0.0)
    assert is_tilted(0.5, 0.0)


def test_light_forward() -> None:
    # A Unity light with rotation.x = 90 points down.
    assert unity_forward(90.0, 0.0, 0.0) == pytest.approx((0.0, 0.0, -1.0), abs=1e-12)
    # ProcTHOR's default directional light points downwards too.
    assert unity_forward(43.375, -3.902, -63.618)[2] < -0.5


def test_normalise_range() -> None:
    assert normalise_deg(180.0) == 180.0
    assert normalise_deg(-180.0) == 180.0
    assert normalise_deg(540.0) == 180.0
    assert normalise_deg(-190.0) == pytest.approx(170.0)


def _det(m: tuple[tuple[float, ...], ...]) -> float:
    return (
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
        - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
        + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    )
