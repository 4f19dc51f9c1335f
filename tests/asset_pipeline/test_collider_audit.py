"""The collider-vs-visual audit: exact distances, seams between colliders, and every procedural
category's real generated assets covered by their colliders within 5 mm."""

from __future__ import annotations

import math
from collections import defaultdict
from pathlib import Path

import numpy as np
import pytest

from asset_pipeline.collider_audit import (
    GAP_LIMIT_M,
    SAMPLE_STEP,
    audit_asset_folder,
    collider_gap,
    gap_summary,
    hull_distance,
    outside_distance,
)
from asset_pipeline.library_writer import write_library
from asset_pipeline.procedural import CATEGORIES, default_variants, generate_asset
from asset_pipeline.procedural.assembly import covering_colliders
from asset_pipeline.procedural.kit import OAK, block
from asset_pipeline.procedural.parts import Box, Collider
from asset_pipeline.procedural.round_parts import INSCRIBED, Cylinder, Lathe, Sphere
from holomj.library.store import AssetLibrary
from holomj.spec.assets import CollisionPart

CUBE = np.array(
    [[x, y, z] for x in (-0.5, 0.5) for y in (-0.5, 0.5) for z in (-0.5, 0.5)], dtype=float
)


def box_mesh(low, high) -> tuple[np.ndarray, np.ndarray]:
    """The visual (vertices, faces) of an axis-aligned box."""
    mesh = block((low[0], high[0]), (low[1], high[1]), (low[2], high[2]), OAK).mesh()
    assert mesh is not None
    return mesh.vertices, mesh.faces


def box(half, pos=(0.0, 0.0, 0.0), quat=(1.0, 0.0, 0.0, 0.0)) -> CollisionPart:
    return CollisionPart(kind="box", size=half, pos=pos, quat=quat, volume_m3=1.0)


# --- distances ---------------------------------------------------------------------------------
def test_primitive_distances_are_exact() -> None:
    points = np.array([[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [2.0, 2.0, 0.0], [0.0, 0.0, 3.0]])
    np.testing.assert_allclose(outside_distance(points, [box((1.0, 1.0, 1.0))]), [0, 1, 2**0.5, 2])
    cylinder = CollisionPart(kind="cylinder", size=(1.0, 0.5), volume_m3=1.0)
    np.testing.assert_allclose(outside_distance(points, [cylinder]), [0, 1, 8**0.5 - 1, 2.5])
    sphere = CollisionPart(kind="sphere", size=(1.0,), volume_m3=1.0)
    np.testing.assert_allclose(outside_distance(points, [sphere]), [0, 1, 8**0.5 - 1, 2])
    capsule = CollisionPart(kind="capsule", size=(0.5, 1.0), volume_m3=1.0)
    np.testing.assert_allclose(outside_distance(points, [capsule]), [0, 1.5, 8**0.5 - 0.5, 1.5])


def test_rotation_is_applied() -> None:
    # A 2 x 0.2 x 0.2 box turned 90 degrees about z lies along y.
    half = math.sqrt(0.5)
    turned = box((1.0, 0.1, 0.1), quat=(half, 0.0, 0.0, half))
    points = np.array([[0.0, 0.9, 0.0], [0.9, 0.0, 0.0]])
    np.testing.assert_allclose(outside_distance(points, [turned]), [0.0, 0.8], atol=1e-12)


def test_hull_distance_matches_the_box_it_spans() -> None:
    rng = np.random.default_rng(3)
    points = rng.uniform(-2.0, 2.0, size=(500, 3))
    exact = outside_distance(points, [box((0.5, 0.5, 0.5))])
    np.testing.assert_allclose(hull_distance(points, CUBE), exact, atol=1e-12)
    hull = CollisionPart(kind="mesh", mesh="hull.obj", pos=(1.0, 0.0, 0.0), volume_m3=1.0)
    moved = outside_distance(points, [hull], {0: CUBE})
    np.testing.assert_allclose(moved, outside_distance(points - [1.0, 0.0, 0.0], [box((0.5,) * 3)]))


def test_a_mesh_collider_without_vertices_is_an_error() -> None:
    hull = CollisionPart(kind="mesh", mesh="hull.obj", volume_m3=1.0)
    with pytest.raises(ValueError, match="no hull vertices"):
        outside_distance(np.zeros((1, 3)), [hull])


# --- gaps ----------------------------------------------------------------------------------------
def test_an_exact_collider_leaves_no_gap_and_a_shrunk_one_its_shrink() -> None:
    visual = [box_mesh((-0.5, -0.3, 0.0), (0.5, 0.3, 0.8))]
    assert collider_gap(visual, [box((0.5, 0.3, 0.4), (0.0, 0.0, 0.4))]).distance_m == 0.0
    gap = collider_gap(visual, [box((0.49, 0.3, 0.4), (0.0, 0.0, 0.4))])
    assert gap.distance_m == pytest.approx(0.01)
    assert abs(gap.point[0]) == pytest.approx(0.5)


def test_the_seam_between_two_colliders_is_found_inside_faces() -> None:
    # Every vertex of the long box lies in a collider; the middle of its faces does not.
    visual = [box_mesh((-0.5, -0.05, 0.0), (0.5, 0.05, 0.1))]
    halves = [box((0.2, 0.05, 0.05), (-0.3, 0.0, 0.05)), box((0.2, 0.05, 0.05), (0.3, 0.0, 0.05))]
    gap = collider_gap(visual, halves)
    assert gap.distance_m == pytest.approx(0.1, abs=SAMPLE_STEP / 2)
    assert abs(gap.point[0]) < SAMPLE_STEP
    # stop_above: the search stops once the gap is known to exceed the limit.
    quick = collider_gap(visual, halves, stop_above=0.01)
    assert 0.01 < quick.distance_m <= gap.distance_m and quick.samples <= gap.samples


def test_gap_summary_reports_the_worst_per_category() -> None:
    metas = [
        generate_asset("mug", f"mug_{k}", None, k).meta.model_copy(update={"collider_gap_m": g})
        for k, g in enumerate((0.001, 0.009))
    ]
    metas.append(metas[0].model_copy(update={"id": "mug_x", "collider_gap_m": None}))
    summary = gap_summary(metas)
    assert summary["categories"] == {"mug": {"asset": "mug_1", "gap_mm": 9.0}}
    assert summary["over_limit"] == {"mug_1": 9.0} and summary["unmeasured"] == 1


# --- what assembly does about gaps ---------------------------------------------------------------
def test_a_steep_taper_gets_its_frustum_hull_and_a_straight_piece_a_cylinder() -> None:
    shade = Lathe((0.0, 0.0, 0.0), ((0.05, 0.0), (0.2, 0.3)), OAK)
    (hull,) = shade.colliders()
    assert hull.kind == "mesh" and len(hull.vertices) == 48
    mesh = shade.mesh()
    assert mesh is not None
    assert collider_gap([(mesh.vertices, mesh.faces)], [hull]).distance_m < 1e-9
    post = Lathe((0.0, 0.0, 0.0), ((0.03, 0.0), (0.03, 1.0)), OAK)
    (cylinder,) = post.colliders()
    assert cylinder.kind == "cylinder" and cylinder.size[0] == pytest.approx(0.03 * INSCRIBED)


def test_a_wide_disc_and_a_cut_sphere_are_covered() -> None:
    disc = Cylinder((0.0, 0.0, 0.02), 0.6, 0.02, OAK)
    assert [c.kind for c in disc.colliders()] == ["mesh"]
    ball = Sphere((0.0, 0.0, 0.065), 0.075, OAK, cut=0.0)
    for part in (disc, ball):
        mesh = part.mesh()
        assert mesh is not None
        gap = collider_gap([(mesh.vertices, mesh.faces)], part.colliders())
        assert gap.distance_m < 0.003, part


def test_visual_only_parts_get_colliders_back_where_they_stick_out() -> None:
    top = block((-0.5, 0.5), (-0.3, 0.3), (0.7, 0.75), OAK)
    decal = block((-0.2, 0.2), (-0.1, 0.1), (0.75, 0.7505), OAK, collide=False)  # flush
    post = Box((0.0, 0.0, 0.35), (0.02, 0.02, 0.35), OAK, collide=False)  # sticks out below
    colliders, gap = covering_colliders([top, decal, post])
    assert gap.distance_m <= 0.003
    assert len(colliders) == 2  # the top's and the post's; the flush decal needs none
    assert Collider("box", post.half, post.center) in colliders


# --- every procedural category, on real generated assets -----------------------------------------
@pytest.fixture(scope="module")
def default_bundles() -> dict[str, object]:
    return {
        asset_id: generate_asset(name, asset_id, size, seed)
        for asset_id, name, size, seed in default_variants()
    }


def test_every_procedural_category_is_covered_within_5_mm(default_bundles) -> None:
    worst: dict[str, tuple[float, str]] = defaultdict(lambda: (0.0, ""))
    for asset_id, item in default_bundles.items():
        meta = item.meta
        assert meta.collider_gap_m is not None, asset_id
        if meta.collider_gap_m >= worst[meta.category][0]:
            worst[meta.category] = (meta.collider_gap_m, asset_id)
    assert set(worst) == set(CATEGORIES)
    over = {c: w for c, w in worst.items() if w[0] > GAP_LIMIT_M}
    assert not over, f"categories whose colliders leave more than 5 mm uncovered: {over}"


CHECKED = (
    "floor_lamp_000", "shampoo_station_000", "kettlebell_000", "blinds_000", "lectern_000",
    "bean_bag_002", "table_tennis_table_001", "sofa_000", "chandelier_000", "mug_000",
)  # fmt: skip


def test_recorded_gaps_match_an_audit_of_the_written_files(tmp_path: Path, default_bundles) -> None:
    """What the metadata records is what the files on disk give (hulls read back from OBJ)."""
    root = write_library(tmp_path / "lib", "t", [default_bundles[i] for i in CHECKED])
    library = AssetLibrary.open(root)
    for asset_id in CHECKED:
        asset = library.get(asset_id)
        audit = audit_asset_folder(asset.root, asset.meta)
        assert audit.distance_m == pytest.approx(asset.meta.collider_gap_m, abs=2e-4), asset_id
        assert audit.distance_m <= GAP_LIMIT_M
