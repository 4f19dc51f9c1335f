"""Choosing the robot's spot: free, reachable, deterministic, facing the room."""

from __future__ import annotations

import math

import numpy as np
import pytest

from holomj.errors import InputError
from holomj.mjcf.compiler import CompiledScene
from holomj.robots.occupancy import build_floor_grid
from holomj.robots.placement import choose_spot
from holomj.robots.reach import cells_in_disc, compute_reach
from holomj.spec.robot import Footprint


def _footprint(radius: float, front_deg: float = 0.0) -> Footprint:
    return Footprint(
        radius_m=radius,
        height_m=1.0,
        front_deg=front_deg,
        polygon=[(radius, 0.0), (0.0, radius), (-radius, 0.0)],
    )


@pytest.fixture
def maps(two_room_compiled: CompiledScene):
    grid = build_floor_grid(two_room_compiled.model, two_room_compiled.scene)
    return grid, compute_reach(grid, two_room_compiled.scene)


def test_spot_is_free_reachable_and_in_a_room(maps, two_room_compiled: CompiledScene) -> None:
    grid, reach = maps
    for seed in range(5):
        spot = choose_spot(
            grid, reach, two_room_compiled.scene, _footprint(0.4), np.random.default_rng(seed)
        )
        disc = cells_in_disc(grid, spot.x, spot.y, 0.4 + 0.1)
        assert not (disc & (grid.blocked | grid.leaves | grid.swing | ~grid.inside)).any()
        assert reach.reachable[grid.cell_of(spot.x, spot.y)]
        assert grid.room_ids[grid.room_index[grid.cell_of(spot.x, spot.y)]] == spot.room
        assert spot.clearance_m >= 0.1


def test_same_seed_same_spot(maps, two_room_compiled: CompiledScene) -> None:
    grid, reach = maps
    scene = two_room_compiled.scene
    spots = [
        choose_spot(grid, reach, scene, _footprint(0.3), np.random.default_rng(4)) for _ in "ab"
    ]
    assert spots[0] == spots[1]
    many = {
        choose_spot(grid, reach, scene, _footprint(0.3), np.random.default_rng(s)) for s in range(8)
    }
    assert len(many) > 1  # the seed picks among equally good spots


def test_room_choice_and_facing(maps, two_room_compiled: CompiledScene) -> None:
    grid, reach = maps
    scene = two_room_compiled.scene
    spot = choose_spot(
        grid,
        reach,
        scene,
        _footprint(0.3, front_deg=30.0),
        np.random.default_rng(0),
        room="kitchen",
    )
    assert spot.room == "kitchen"
    # It turns its reach direction (30° in its base frame) towards the kitchen table at (2, 1.2).
    heading = math.radians(spot.yaw_deg + 30.0)
    towards = math.atan2(1.2 - spot.y, 2.0 - spot.x)
    assert math.cos(heading - towards) == pytest.approx(1.0, abs=1e-6)
    with pytest.raises(InputError, match=r"unknown room 'attic'.*kitchen, living"):
        choose_spot(grid, reach, scene, _footprint(0.3), np.random.default_rng(0), room="attic")


def test_no_free_spot_is_an_input_error(maps, two_room_compiled: CompiledScene) -> None:
    grid, reach = maps
    with pytest.raises(InputError, match="no free floor spot for the robot") as info:
        choose_spot(grid, reach, two_room_compiled.scene, _footprint(2.0), np.random.default_rng(0))
    assert info.value.exit_code == 2 and "2.10 m radius" in info.value.one_line()
