"""Masses of imported meshes come from their material volume, not from their convex hulls."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
import trimesh

from asset_pipeline import physical
from asset_pipeline.importer import ImportOptions, import_asset
from asset_pipeline.load import load_file
from asset_pipeline.normalise import normalise
from asset_pipeline.repair import repair
from tests.asset_pipeline.import_helpers import LOW

# Real meshes of ../shared/assets: (file, category, what such a thing weighs, kg).
REAL = {
    "bm_shelving_unit": ("furniture/bm_shelving_unit/shelving_unit.glb", "shelf", (8.0, 45.0)),
    "bm_storage_shelving_01": (
        "furniture/bm_storage_shelving_01/storage_shelving_01.glb",
        "shelf",
        (15.0, 60.0),
    ),
    "bm_medieval_bookcase": (
        "furniture/bm_medieval_bookcase/medieval_bookcase.glb",
        "bookshelf",
        (15.0, 80.0),
    ),
    "bm_loaf_tin": ("objects/bm_loaf_tin/loaf_tin.glb", "baking_tin", (0.15, 0.8)),
    "bm_bucket": ("objects/bm_bucket/bucket.glb", "bucket", (0.4, 2.5)),
    "ycb_024_bowl": ("objects/ycb_024_bowl/textured.obj", "bowl", (0.05, 0.5)),
}


def _physics(path: Path) -> trimesh.Trimesh:
    """The repaired physics mesh of a shared asset, in the asset frame (as the importer has)."""
    loaded = load_file(path, 2_000_000)
    up = "y" if loaded.format in ("glb", "gltf") else "z"
    parts, _ = normalise(loaded.parts, str(path), up, "+x", None)
    return repair(parts).physics


def _hull_volume(mesh: trimesh.Trimesh) -> float:
    return float(mesh.convex_hull.volume)


def test_closed_solid_counts_its_enclosed_volume() -> None:
    block = trimesh.creation.box(extents=(0.3, 0.2, 0.1))
    assert physical.material_volume(block, None).volume_m3 == pytest.approx(0.006, rel=1e-6)
    # A board thinner than twice the wall keeps its whole volume.
    board = trimesh.creation.box(extents=(0.8, 0.3, 0.018))
    measured = physical.material_volume(board, 0.018)
    assert measured.volume_m3 == pytest.approx(0.8 * 0.3 * 0.018, rel=1e-6)
    assert measured.closed_bodies == 1 and measured.hollowed_bodies == 0


def test_block_and_sphere_models_of_hollow_things_count_their_walls() -> None:
    cabinet = trimesh.creation.box(extents=(1.0, 0.5, 2.0))  # a cabinet modelled as a block
    walls = physical.material_volume(cabinet, 0.018)
    assert walls.volume_m3 == pytest.approx(cabinet.area * 0.018, rel=1e-6)
    assert walls.hollowed_bodies == 1 and walls.volume_m3 < 0.15 * cabinet.volume
    globe = trimesh.creation.icosphere(subdivisions=3, radius=0.15)
    shell = physical.material_volume(globe, 0.002)
    assert shell.volume_m3 == pytest.approx(globe.area * 0.002, rel=1e-6)


def _open_top_box(size: tuple[float, float, float], wall: float) -> trimesh.Trimesh:
    """One closed body: a bin with outer and inner walls ``wall`` thick, joined at the rim."""
    a, b, h, w = size[0] / 2, size[1] / 2, size[2], wall
    ring = lambda x, y, z: [[-x, -y, z], [x, -y, z], [x, y, z], [-x, y, z]]  # noqa: E731
    vertices = ring(a, b, 0) + ring(a, b, h) + ring(a - w, b - w, h) + ring(a - w, b - w, w)
    faces = [[0, 2, 1], [0, 3, 2]]  # outer bottom
    for i in range(4):
        j = (i + 1) % 4
        faces += [[i, j, 4 + j], [i, 4 + j, 4 + i]]  # outer side
        faces += [[4 + i, 4 + j, 8 + j], [4 + i, 8 + j, 8 + i]]  # rim
        faces += [[8 + i, 8 + j, 12 + j], [8 + i, 12 + j, 12 + i]]  # inner side
    faces += [[12, 13, 14], [12, 14, 15]]  # inner floor
    mesh = trimesh.Trimesh(vertices, faces, process=False)
    trimesh.repair.fix_normals(mesh)
    return mesh


def test_model_with_inner_and_outer_walls_gets_one_real_wall_per_pair() -> None:
    bin_ = _open_top_box((0.5, 0.5, 1.5), 0.03)  # a steel cabinet modelled with 3 cm walls
    assert bin_.is_watertight and bin_.volume > 0
    measured = physical.material_volume(bin_, 0.001)
    assert measured.closed_bodies == 1 and measured.hollowed_bodies == 1
    # Hollowed to a skin under the outward-facing half of the surface, not under both sides.
    assert 0.45 * bin_.area * 0.001 < measured.volume_m3 < 0.65 * bin_.area * 0.001


def test_open_sheet_counts_as_a_sheet_of_wall_thickness() -> None:
    quad = trimesh.Trimesh(
        vertices=[[0, 0, 0], [0.4, 0, 0], [0.4, 0.3, 0], [0, 0.3, 0]],
        faces=[[0, 1, 2], [0, 2, 3]],
        process=False,
    )
    sheet = physical.material_volume(quad, 0.001)
    assert sheet.open_bodies == 1
    assert sheet.volume_m3 == pytest.approx(0.12 * 0.001, rel=1e-6)
    # An open bowl-shaped surface: a sheet, far below its hull.
    bowl = _pan_surface()
    measured = physical.material_volume(bowl, 0.003)
    assert measured.volume_m3 == pytest.approx(bowl.area * 0.003, rel=0.02)
    assert measured.volume_m3 < 0.2 * _hull_volume(bowl)


def test_board_missing_its_end_faces_is_closed_by_filling_holes() -> None:
    board = trimesh.creation.box(extents=(0.9, 0.25, 0.027))
    keep = np.abs(board.face_normals[:, 0]) < 0.5  # drop the two end faces
    tube = trimesh.Trimesh(board.vertices, board.faces[keep], process=False)
    assert not tube.is_watertight
    measured = physical.material_volume(tube, 0.018)
    assert measured.holes_filled == 1
    assert measured.volume_m3 == pytest.approx(0.9 * 0.25 * 0.027, rel=1e-6)


def test_given_and_sidecar_density_win_and_are_never_clamped() -> None:
    mug = physical.category_info("mug")
    block = trimesh.creation.box(extents=(0.1, 0.1, 0.1))
    given = physical.resolve_mass(mug, block, 0.001, given=5.0)
    assert given.mass_kg == 5.0 and given.derivation["method"] == "given"
    assert given.warnings and "outside the plausible range" in given.warnings[0]
    dense = physical.resolve_mass(mug, block, 0.001, density=300.0)
    assert dense.mass_kg == pytest.approx(0.3)
    assert dense.derivation["method"] == "density x collision volume" and not dense.warnings


def test_estimate_outside_the_range_is_clamped_with_a_recorded_reason() -> None:
    shelf = physical.category_info("shelf")
    lo, hi = shelf.mass_range_kg
    huge = trimesh.creation.box(extents=(3.0, 0.5, 3.0))  # 3 m of shelving
    result = physical.resolve_mass(shelf, huge, 1.0)
    record = result.derivation
    assert record["estimate_kg"] > hi and result.mass_kg == hi
    assert record["clamped"] is True and f"clamped to {hi:g} kg" in record["clamp_reason"]
    assert "above the plausible range" in record["clamp_reason"]
    assert result.warnings and "mass clamped" in result.warnings[0]
    tiny = physical.resolve_mass(shelf, trimesh.creation.box(extents=(0.1, 0.1, 0.01)), 1.0)
    assert tiny.mass_kg == lo and "below" in tiny.derivation["clamp_reason"]


def test_category_table_materials_are_complete() -> None:
    names = physical.materials()
    assert {"wood", "steel_sheet", "plastic", "glass", "ceramic"} <= set(names)
    for category in physical.categories():
        info = physical.category_info(category)
        assert info.material in names
        assert info.density_kg_m3 > 0
        assert info.wall_m is None or 0.0002 <= info.wall_m <= 0.05
    default = physical.category_info("spaceship", (2.0, 1.0, 1.0))
    assert not default.known and default.material in names


@pytest.mark.parametrize("asset", sorted(REAL))
def test_real_meshes_get_plausible_unclamped_masses(asset: str, shared_assets: Path) -> None:
    rel, category, (lo, hi) = REAL[asset]
    mesh = _physics(shared_assets / rel)
    info = physical.category_info(category)
    result = physical.resolve_mass(info, mesh, 1.0)
    assert lo <= result.mass_kg <= hi, result.derivation
    assert result.derivation["clamped"] is False  # the estimate itself is plausible
    # The hull of these open and hollow things is mostly air.
    assert result.derivation["material_volume_m3"] < 0.35 * _hull_volume(mesh)


def _pan_surface() -> trimesh.Trimesh:
    """A 26 cm frying pan as one open, single-sided surface of revolution (no handle)."""
    profile = np.array([[0.0, 0.0], [0.11, 0.0], [0.118, 0.004], [0.13, 0.045]])
    return trimesh.creation.revolve(profile, sections=48)


def _write(mesh: trimesh.Trimesh, path: Path) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    mesh.export(path)
    return path


def test_imported_globe_and_pan_are_plausible_and_say_how(tmp_path: Path) -> None:
    sphere = trimesh.creation.icosphere(subdivisions=3, radius=0.15)
    sphere.apply_translation((0, 0, 0.21))
    stand = trimesh.creation.cylinder(radius=0.008, height=0.04)
    stand.apply_translation((0, 0, 0.05))
    base = trimesh.creation.cylinder(radius=0.08, height=0.03)
    base.apply_translation((0, 0, 0.015))
    globe = _write(trimesh.util.concatenate([sphere, stand, base]), tmp_path / "desk_globe.obj")
    handle = trimesh.creation.box(extents=(0.2, 0.03, 0.015))
    handle.apply_translation((0.23, 0, 0.04))
    pan = _write(trimesh.util.concatenate([_pan_surface(), handle]), tmp_path / "frying_pan.obj")
    for path, category in ((globe, "globe"), (pan, "pan")):
        imported = import_asset(path, path.stem, ImportOptions(coacd=LOW))
        meta, physical_report = imported.bundle.meta, imported.report["physical"]
        lo, hi = physical.category_info(category).mass_range_kg
        record = physical_report["mass_derivation"]
        assert meta.category == category
        assert lo <= meta.mass <= hi and record["clamped"] is False, record
        assert record["method"] == "material density x material volume"
        assert record["material"] == physical.category_info(category).material
        # density x collision volume still gives the mass (AssetMeta's meaning).
        assert meta.density_kg_m3 * meta.collision_volume_m3 == pytest.approx(meta.mass)
        json.dumps(imported.report)  # the derivation record is JSON-able
        # The old rule (hull volume x an effective density) would have made a globe of
        # several kilograms: the hulls hold far more than the material.
        assert record["material_volume_m3"] < 0.25 * meta.collision_volume_m3
