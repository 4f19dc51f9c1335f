"""The geometry behind making a house stand: the shortest horizontal separation of two
footprints, and which world boxes count as walls."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

from holomj.physics.standing.pushes import (
    footprint_hull,
    geom_points,
    is_slab,
    min_translation_2d,
    wall_label,
)


def _square(x: float, y: float, half: float) -> np.ndarray:
    return np.array(
        [[x - half, y - half], [x + half, y - half], [x + half, y + half], [x - half, y + half]]
    )


def test_min_translation_is_the_shortest_way_out() -> None:
    mover, other = _square(0.8, 0.1, 0.5), _square(0.0, 0.0, 0.5)  # 20 cm overlap along x
    move = min_translation_2d(mover, other)
    assert move == pytest.approx([0.2, 0.0])
    assert min_translation_2d(_square(-0.8, 0.0, 0.5), other) == pytest.approx([-0.2, 0.0])
    assert min_translation_2d(_square(2.0, 0.0, 0.5), other) is None  # apart
    turned = footprint_hull(np.array([[0.0, -0.3, 0], [0.3, 0.0, 0], [0.0, 0.3, 0], [-0.3, 0, 0]]))
    move = min_translation_2d(turned + [0.7, 0.0], other)  # a diamond's tip 10 cm in
    assert move == pytest.approx([0.1, 0.0])


def test_walls_are_thin_world_boxes_and_round_colliders_are_not_underestimated() -> None:
    spec = mujoco.MjSpec()
    wall = spec.worldbody.add_geom(
        name="structure/wall_004/0/room|1", type=mujoco.mjtGeom.mjGEOM_BOX, size=[2, 0.025, 1.3]
    )
    floor = spec.worldbody.add_geom(name="ground", type=mujoco.mjtGeom.mjGEOM_PLANE, size=[5, 5, 1])
    body = spec.worldbody.add_body(name="ball", pos=[0, 1, 0.5])
    body.add_freejoint()
    ball = body.add_geom(name="ball/collision_0", type=mujoco.mjtGeom.mjGEOM_SPHERE, size=[0.2])
    big = spec.worldbody.add_geom(name="platform", type=mujoco.mjtGeom.mjGEOM_BOX, size=[2, 2, 0.1])
    model = spec.compile()
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    ids = {g.name: model.geom(g.name).id for g in (wall, floor, ball, big)}
    assert is_slab(model, ids[wall.name])
    assert not is_slab(model, ids[floor.name]) and not is_slab(model, ids[big.name])
    assert wall_label(model, ids[wall.name]) == "wall_004"
    points = geom_points(model, data, ids[ball.name])
    radial = np.linalg.norm(points[:, :2] - [0.0, 1.0], axis=1)
    assert radial.max() >= 0.2 - 1e-9
    hull = footprint_hull(points)
    assert min_translation_2d(hull, _square(0.0, 1.0, 0.19)) is not None
