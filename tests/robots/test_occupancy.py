"""The floor occupancy grid and reachability from the entrance."""

from __future__ import annotations

import math

import numpy as np
import pytest

from holomj.library import AssetLibrary
from holomj.mjcf import compile_scene
from holomj.mjcf.compiler import CompiledScene
from holomj.robots.occupancy import build_floor_grid
from holomj.robots.reach import compute_reach, find_entrance
from holomj.spec.scene import SceneSpec
from tests.conftest import two_room_data


def _cell(grid, x: float, y: float) -> tuple[int, int]:
    return grid.cell_of(x, y)


def test_rooms_walls_and_furniture(two_room_compiled: CompiledScene) -> None:
    grid = build_floor_grid(two_room_compiled.model, two_room_compiled.scene)
    assert grid.room_ids == ["kitchen", "living"]
    assert grid.room_index[_cell(grid, 1.0, 2.5)] == 0
    assert grid.room_index[_cell(grid, 6.0, 4.0)] == 1
    assert grid.room_index[_cell(grid, -0.3, 2.0)] == -1
    assert grid.blocked[_cell(grid, 2.0, 1.2)]  # the table (1.2 x 0.8 m at (2, 1.2))
    assert grid.blocked[_cell(grid, 2.55, 1.55)]
    assert not grid.blocked[_cell(grid, 2.7, 1.2)]
    assert grid.blocked[_cell(grid, 4.0, 1.0)]  # the wall between kitchen and living room
    assert grid.blocked[_cell(grid, 5.5, 2.5)]  # the crate
    assert not grid.blocked[_cell(grid, 3.0, 4.2)]
    # The kitchen door's gap is open, its closed leaf (flush with the kitchen face) kept apart.
    assert not grid.blocked[_cell(grid, 2.0, 2.97)] and grid.leaves[_cell(grid, 2.0, 2.97)]
    assert not grid.blocked[_cell(grid, 2.0, 3.02)]


def test_door_swing_zone(two_room_compiled: CompiledScene) -> None:
    grid = build_floor_grid(two_room_compiled.model, two_room_compiled.scene)
    model = two_room_compiled.model
    hinge = model.jnt_pos[model.joint("kitchen_door/hinge_0").id]
    # The leaf (0.88 m) swings into the kitchen (range [-90°, 0]): a quarter disc below y = 3.
    anchor = model.body("kitchen_door/leaf_0").pos[:2] + hinge[:2]
    assert grid.swing[_cell(grid, anchor[0] + 0.3, anchor[1] - 0.3)]
    assert grid.swing[_cell(grid, anchor[0] + 0.05, anchor[1] - 0.8)]
    assert not grid.swing[_cell(grid, anchor[0] + 0.3, anchor[1] + 0.4)]
    assert not grid.swing[_cell(grid, anchor[0] + 1.2, anchor[1] - 1.0)]


def test_clearance_is_distance_to_obstacles(two_room_compiled: CompiledScene) -> None:
    grid = build_floor_grid(two_room_compiled.model, two_room_compiled.scene)
    clearance = grid.clearance(grid.blocked)
    # From (2, 2.3) the table's far edge (y = 1.6) is 0.7 m away, the wall (y = 2.95) 0.65 m.
    assert clearance[_cell(grid, 2.0, 2.3)] == pytest.approx(0.65, abs=grid.cell)
    assert clearance[_cell(grid, 2.0, 1.2)] < 0


def test_entrance_and_reachability(two_room_compiled: CompiledScene) -> None:
    scene = two_room_compiled.scene
    entrance = find_entrance(scene)
    assert (entrance.room, entrance.door) == ("living", "front_door")
    grid = build_floor_grid(two_room_compiled.model, scene)
    reach = compute_reach(grid, scene, agent_radius=0.25)
    stats = reach.room_stats()
    assert stats["kitchen"]["reachable"] and stats["living"]["reachable"]
    for room in stats.values():
        assert 0 < room["reachable_area_m2"] <= room["walkable_area_m2"] <= room["floor_area_m2"]
    # Too wide to pass the kitchen door (0.9 m clear): the kitchen is cut off.
    wide = compute_reach(grid, scene, agent_radius=0.5).room_stats()
    assert wide["living"]["reachable"] and not wide["kitchen"]["reachable"]


def _scene(**changes) -> SceneSpec:
    data = two_room_data()
    data.update(changes)
    return SceneSpec.model_validate(data)


def test_a_room_without_a_door_is_unreachable(empty_library: AssetLibrary) -> None:
    data = two_room_data()
    scene = _scene(doors=[d for d in data["doors"] if d["id"] != "kitchen_door"])
    compiled = compile_scene(scene, empty_library)
    reach = compute_reach(build_floor_grid(compiled.model, scene), scene)
    stats = reach.room_stats()
    assert stats["living"]["reachable"] and not stats["kitchen"]["reachable"]
    assert stats["kitchen"]["walkable_area_m2"] > 3.0


def test_blocked_doorway_cuts_a_room_off(empty_library: AssetLibrary) -> None:
    data = two_room_data()
    blocker = {
        "id": "wardrobe",
        "asset": "builtin:box",
        "position": [2.0, 3.45, 0.0],
        "scale": [1.4, 0.7, 1.8],
        "static": True,
        "room": "living",
    }
    scene = _scene(objects=[*data["objects"], blocker])
    compiled = compile_scene(scene, empty_library)
    stats = compute_reach(build_floor_grid(compiled.model, scene), scene).room_stats()
    assert not stats["kitchen"]["reachable"]


def test_no_exterior_door_starts_in_the_first_room(empty_library: AssetLibrary) -> None:
    data = two_room_data()
    scene = _scene(doors=[d for d in data["doors"] if d["id"] == "kitchen_door"])
    entrance = find_entrance(scene)
    assert entrance.door is None and entrance.room == "kitchen"
    compiled = compile_scene(scene, empty_library)
    stats = compute_reach(build_floor_grid(compiled.model, scene), scene).room_stats()
    assert stats["kitchen"]["reachable"] and stats["living"]["reachable"]


def test_height_band_ignores_low_and_high_geoms(two_room_compiled: CompiledScene) -> None:
    grid = build_floor_grid(two_room_compiled.model, two_room_compiled.scene, z_band=(0.8, 2.0))
    assert not grid.blocked[_cell(grid, 1.6, 1.0)]  # the 0.75 m table is below the band
    assert grid.blocked[_cell(grid, 2.0, 1.2)]  # the cube on it (0.75 to 0.85 m) is not
    assert grid.blocked[_cell(grid, 4.0, 1.0)]
    assert math.isclose(grid.cell, 0.05) and np.all(grid.room_index[0] == -1)
