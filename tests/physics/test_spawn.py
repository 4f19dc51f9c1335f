"""Spawn-and-drop with the procedural default library: tables, shelves, limits, determinism."""

from __future__ import annotations

import numpy as np
import pytest

from holomj.errors import InputError
from holomj.library import AssetLibrary
from holomj.physics.drop_world import tilt_deg
from holomj.physics.spawn import UPRIGHT_TOL_DEG, populate
from holomj.physics.surfaces_world import SurfaceSampler, footprint_polygon, world_surfaces
from holomj.spec.scene import SceneObject
from tests.physics.spawn_helpers import SMALL, receptacle_scene, settle_check


def test_world_surfaces_follow_pose_and_scale(default_library: AssetLibrary) -> None:
    meta = default_library.get("dining_table_000").meta
    obj = SceneObject(id="t", asset=meta.id, position=(1.0, 2.0, 0.1), yaw_deg=90.0, scale=2.0)
    (surface,) = world_surfaces(obj, meta)
    assert surface.height == pytest.approx(0.1 + 2.0 * meta.surfaces[0].height)
    assert surface.area == pytest.approx(4.0 * meta.surfaces[0].area_m2, rel=1e-6)
    minx, miny, maxx, maxy = surface.polygon.bounds
    # the table is longer along its local y; turned by 90 degrees it is longer along x
    assert (maxx - minx) > (maxy - miny)
    assert surface.polygon.centroid.x == pytest.approx(1.0, abs=1e-6)
    assert surface.polygon.centroid.y == pytest.approx(2.0, abs=1e-6)


def test_sampler_keeps_the_footprint_on_the_surface(default_library: AssetLibrary) -> None:
    meta = default_library.get("bookshelf_000").meta
    obj = SceneObject(id="s", asset=meta.id, position=(0.0, 0.0, 0.0), yaw_deg=20.0)
    shelf = world_surfaces(obj, meta)[1]
    sampler = SurfaceSampler(shelf, (0.11, 0.07))  # a book: its footprint fits only turned
    rng = np.random.default_rng(0)
    for _ in range(20):
        x, y, yaw = sampler.sample(rng)
        assert shelf.polygon.contains(footprint_polygon((0.11, 0.07), x, y, yaw))
    assert not SurfaceSampler(shelf, (0.5, 0.5)).feasible


def test_ten_objects_on_a_table_rest_on_it(default_library: AssetLibrary) -> None:
    scene = receptacle_scene("dining_table_000")
    result = populate(
        scene, default_library, "rec", [(c, 1) for c in SMALL], np.random.default_rng(1)
    )
    assert [p.accepted for p in result.placements] == [True] * 10, result.to_dict()
    assert result.all_placed
    added = result.scene.objects[1:]
    assert len(added) == 10
    assert all(o.support == "rec" and o.room == "room" and not o.static for o in added)
    assert result.scene.objects[0] == scene.objects[0]  # the receptacle keeps its pose
    for p in result.placements:
        assert 1 <= p.attempts <= 20 and p.reason == "placed" and p.surface_index == 0
        assert p.final_pose is not None and p.final_pose["height_above_surface_m"] > -0.01
    checks, warnings = settle_check(result.scene, default_library, [o.id for o in added])
    assert warnings == {}
    for object_id, check in checks.items():
        assert check["moved"] < 0.01, (object_id, check)
        assert check["on_rec"], (object_id, check)
    for obj in added:
        if default_library.get(obj.asset).meta.upright:
            assert checks[obj.id]["tilt_deg"] < UPRIGHT_TOL_DEG, obj.id


def test_bookshelf_gets_objects_on_several_shelves(default_library: AssetLibrary) -> None:
    scene = receptacle_scene("bookshelf_001", static=False)
    requests = [("book", 4), ("toy_block", 3), ("apple", 3), ("cup", 2)]
    result = populate(scene, default_library, "rec", requests, np.random.default_rng(3))
    assert result.all_placed, result.to_dict()
    levels = {p.surface_index for p in result.placements}
    assert len(levels) >= 2
    assert result.receptacle_drift_m < 0.01
    heights = {round(o.position[2], 1) for o in result.scene.objects[1:]}
    assert len(heights) >= 2
    checks, warnings = settle_check(
        result.scene, default_library, [o.id for o in result.scene.objects[1:]]
    )
    assert warnings == {}
    assert all(c["moved"] < 0.01 and c["on_rec"] for c in checks.values()), checks


def test_same_seed_same_scene_other_seed_other_poses(default_library: AssetLibrary) -> None:
    scene = receptacle_scene("coffee_table_000")
    requests = [("mug", 2), ("book", 1), ("apple", 2)]
    one = populate(scene, default_library, "rec", requests, np.random.default_rng(7), nthread=1)
    two = populate(scene, default_library, "rec", requests, np.random.default_rng(7), nthread=2)
    assert one.scene == two.scene
    assert [p.attempts for p in one.placements] == [p.attempts for p in two.placements]
    other = populate(scene, default_library, "rec", requests, np.random.default_rng(8))
    assert [o.position for o in other.scene.objects] != [o.position for o in one.scene.objects]


def test_a_full_receptacle_reports_bounded_failures(default_library: AssetLibrary) -> None:
    scene = receptacle_scene("stool_000")
    result = populate(
        scene, default_library, "rec", [("bowl", 6), ("plate", 1)], np.random.default_rng(0),
        max_attempts=4,
    )  # fmt: skip
    placed = [p for p in result.placements if p.accepted]
    failed = [p for p in result.placements if not p.accepted]
    assert placed and failed
    assert len(result.scene.objects) == 1 + len(placed)
    for p in failed:
        assert p.attempts <= 4 and p.final_pose is None and p.surface_index is None
        assert p.reason and p.reason != "placed"
        assert sum(p.rejections.values()) == p.attempts or p.attempts == 0
    assert any(p.reason == "no free space" for p in failed)


def test_too_small_a_surface_is_reported(default_library: AssetLibrary) -> None:
    scene = receptacle_scene("bookshelf_000")
    result = populate(scene, default_library, "rec", [("plate_000", 1)], np.random.default_rng(0))
    (p,) = result.placements
    assert not p.accepted and p.attempts == 0
    assert "no surface" in p.reason
    assert result.scene == scene


def test_bad_requests_are_input_errors(default_library: AssetLibrary) -> None:
    scene = receptacle_scene("dining_table_000")
    rng = np.random.default_rng(0)
    with pytest.raises(InputError, match="unicorn"):
        populate(scene, default_library, "rec", [("unicorn", 1)], rng)
    with pytest.raises(InputError, match="sofa"):  # furniture is not a small object
        populate(scene, default_library, "rec", [("sofa", 1)], rng)
    with pytest.raises(InputError, match="no object 'tabel'"):
        populate(scene, default_library, "tabel", [("mug", 1)], rng)
    room_only = receptacle_scene("bottle_000")
    with pytest.raises(InputError, match="no support surfaces"):
        populate(room_only, default_library, "rec", [("mug", 1)], rng)
    with pytest.raises(InputError, match="max_attempts"):
        populate(scene, default_library, "rec", [("mug", 1)], rng, max_attempts=0)


def test_asset_ids_are_used_directly(default_library: AssetLibrary) -> None:
    scene = receptacle_scene("desk_000", yaw_deg=-75.0)
    result = populate(
        scene, default_library, "rec", [("mug_001", 2), ("bottle_000", 1)],
        np.random.default_rng(4),
    )  # fmt: skip
    assert result.all_placed
    assert [o.asset for o in result.scene.objects[1:]] == ["mug_001", "mug_001", "bottle_000"]
    assert [o.id for o in result.scene.objects[1:]] == ["mug_00", "mug_01", "bottle_00"]
    for obj in result.scene.objects[1:]:
        assert tilt_deg(np.array(obj.quat)) < UPRIGHT_TOL_DEG
