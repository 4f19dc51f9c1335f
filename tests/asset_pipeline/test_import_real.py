"""Importing real meshes from ../shared/assets: frame, hulls, quality, surfaces, simulation."""

from __future__ import annotations

import io
import json
from pathlib import Path

import numpy as np
import pytest
import trimesh

from asset_pipeline.hulls import DEVIATION_TOL_M, HULL_VERTEX_CAP
from asset_pipeline.importer import ImportedAsset, ImportOptions, import_asset
from asset_pipeline.proximity import MeshProximity
from tests.asset_pipeline.import_helpers import LOW, simulate_asset

CASES = {
    "mug": ("objects/bm_coffee_cup/coffee_cup.glb", ImportOptions(category="mug", coacd=LOW)),
    "soup_can": ("objects/ycb_005_tomato_soup_can/textured.obj", ImportOptions(coacd=LOW)),
    "stool": (
        "furniture/ph_painted_wooden_stool/painted_wooden_stool_1k.gltf",
        ImportOptions(coacd=LOW),
    ),
    "table": ("furniture/bm_square_table/square_table.glb", ImportOptions(coacd=LOW)),
    "bookcase": ("furniture/bm_medieval_bookcase/medieval_bookcase.glb", ImportOptions(coacd=LOW)),
}


@pytest.fixture(scope="module")
def imports(shared_assets: Path) -> dict[str, ImportedAsset]:
    cache: dict[str, ImportedAsset] = {}

    class Lazy(dict):
        def __missing__(self, key: str) -> ImportedAsset:
            rel, options = CASES[key]
            cache[key] = import_asset(shared_assets / rel, key, options)
            self[key] = cache[key]
            return cache[key]

    return Lazy()


def _mesh(data: bytes) -> trimesh.Trimesh:
    return trimesh.load(io.BytesIO(data), file_type="obj", process=False, force="mesh")


def _visual(imported: ImportedAsset) -> trimesh.Trimesh:
    parts = [_mesh(imported.bundle.files[v.mesh]) for v in imported.bundle.meta.visual]
    return trimesh.util.concatenate(parts)


@pytest.mark.parametrize("case", sorted(CASES))
def test_import_is_in_the_asset_frame_with_good_hulls(
    case: str, imports: dict, tmp_path: Path
) -> None:
    imported = imports[case]
    meta, report = imported.bundle.meta, imported.report
    visual = _visual(imported)
    lo, hi = visual.bounds
    assert lo[2] == pytest.approx(0.0, abs=1e-5)
    assert (lo[:2] + hi[:2]) / 2 == pytest.approx([0.0, 0.0], abs=1e-5)
    assert meta.size == pytest.approx(hi - lo, abs=1e-5)
    assert len(meta.collision) >= 1
    assert meta.maxhullvert <= HULL_VERTEX_CAP
    quality = report["quality"]
    assert quality["hull_count"] == len(meta.collision)
    assert quality["max_outward_deviation_m"] <= DEVIATION_TOL_M + 1e-6
    assert quality["volume_ratio"] > 0
    assert quality["volume_reference"] in ("mesh", "convex_hull")
    # Re-measure every hull against the written visual mesh.
    proximity = MeshProximity(visual)
    for part in meta.collision:
        if part.kind == "mesh":
            hull = _mesh(imported.bundle.files[part.mesh])
            assert len(hull.vertices) <= meta.maxhullvert
            assert hull.volume == pytest.approx(part.volume_m3, rel=1e-3)
            deviation = proximity.outward_deviation(hull.vertices, exact_above=DEVIATION_TOL_M)
            assert deviation.max() <= DEVIATION_TOL_M + 1e-5
    assert report["decomposition"]["method"]
    json.dumps(report, allow_nan=False)  # JSON-able, no NaN
    assert not any(name.endswith(".png") and "thumb" in name for name in imported.bundle.files)

    sim = simulate_asset(imported, tmp_path)
    assert sim["warnings"] == {}
    assert sim["drift"] < 0.005
    assert sim["rotation_deg"] < 2.0
    assert sim["mass"] == pytest.approx(meta.mass, rel=0.01)


def test_mug_is_a_mug_of_plausible_mass(imports: dict) -> None:
    imported = imports["mug"]
    assert imported.bundle.meta.category == "mug"
    assert 0.15 <= imported.bundle.meta.mass <= 0.8  # a large mug, 12.5 cm across
    derivation = imported.report["physical"]["mass_derivation"]
    assert derivation["material"] == "ceramic" and derivation["clamped"] is False
    assert imported.bundle.meta.placement == ["object"]
    assert imported.report["normalisation"]["up_axis"] == "y"
    assert imported.report["watertight"] is True
    assert imported.report["decomposition"]["preprocess_mode"] == "off"


def test_textured_obj_keeps_its_texture_and_uvs(imports: dict, tmp_path: Path) -> None:
    imported = imports["soup_can"]
    meta = imported.bundle.meta
    assert meta.category == "can"  # guessed from the folder name
    assert imported.report["normalisation"]["up_axis"] == "z"
    (part,) = meta.visual
    assert part.texture is not None
    assert imported.bundle.files[part.texture].startswith(b"\x89PNG")
    assert b"\nvt " in imported.bundle.files[part.mesh]
    sim = simulate_asset(imported, tmp_path)
    assert sim["texcoords"]["asset/soup_can/visual_0"] > 0
    assert sim["model"].ntex >= 1


def test_gltf_with_external_buffers_and_textures(imports: dict) -> None:
    imported = imports["stool"]
    meta = imported.bundle.meta
    assert meta.category == "stool"
    assert all(part.texture for part in meta.visual)
    assert imported.report["source"]["format"] == "gltf"
    assert 0.5 < meta.size[2] < 0.65


def test_table_has_a_top_surface(imports: dict) -> None:
    meta = imports["table"].bundle.meta
    assert meta.placement == ["floor"]
    top = max(meta.surfaces, key=lambda s: s.height)
    assert top.height == pytest.approx(meta.size[2], abs=0.01)
    assert top.area_m2 > 0.3
    assert all(s.height >= 0.01 for s in meta.surfaces)


def test_bookcase_has_several_levels(imports: dict) -> None:
    meta = imports["bookcase"].bundle.meta
    levels = sorted({round(s.height, 2) for s in meta.surfaces})
    assert len(levels) >= 3
    assert meta.category == "bookshelf"
    # The volume of its boards in wood: a plausible bookcase, derived and recorded.
    assert 15.0 <= meta.mass <= 80.0
    derivation = imports["bookcase"].report["physical"]["mass_derivation"]
    assert derivation["method"] == "material density x material volume"
    assert derivation["material"] == "wood" and derivation["clamped"] is False


def test_import_is_byte_deterministic(shared_assets: Path, imports: dict) -> None:
    rel, options = CASES["table"]
    again = import_asset(shared_assets / rel, "table", options)
    assert again.bundle.files == imports["table"].bundle.files
    assert again.bundle.meta == imports["table"].bundle.meta


def test_requested_size_scales_uniformly_to_fit(shared_assets: Path) -> None:
    rel, _ = CASES["table"]
    imported = import_asset(
        shared_assets / rel, "small_table", ImportOptions(size=(0.4, 0.8, 0.72), coacd=LOW)
    )
    size = np.array(imported.bundle.meta.size)
    assert size == pytest.approx([0.4, 0.4, 0.36], abs=1e-4)
    assert imported.report["normalisation"]["scale"] == pytest.approx(0.5, rel=1e-4)
