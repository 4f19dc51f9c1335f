"""Unit tests of the importer's steps: frames, repair, hull post-processing, categories."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import trimesh

from asset_pipeline import physical
from asset_pipeline.hulls import HULL_VERTEX_CAP, postprocess
from asset_pipeline.load import MeshMaterial, MeshPart
from asset_pipeline.normalise import normalise
from asset_pipeline.objfile import obj_bytes
from asset_pipeline.proximity import MeshProximity
from asset_pipeline.repair import repair

GREY = MeshMaterial(rgba=(0.5, 0.5, 0.5, 1.0))


def _part(mesh: trimesh.Trimesh, material: MeshMaterial = GREY) -> MeshPart:
    return MeshPart(np.asarray(mesh.vertices, float), np.asarray(mesh.faces), None, material)


def test_y_up_and_front_are_turned_to_z_up_and_plus_x() -> None:
    # A box long along file +Z (glTF's "forward"), tall along file +Y.
    box = trimesh.creation.box(extents=(0.2, 1.0, 0.6))
    (out,), frame = normalise([_part(box)], "f", "y", "+x", None)
    extent = out.vertices.max(axis=0) - out.vertices.min(axis=0)
    assert extent == pytest.approx([0.2, 0.6, 1.0])
    (turned,), _ = normalise([_part(box)], "f", "y", "+y", None)
    extent = turned.vertices.max(axis=0) - turned.vertices.min(axis=0)
    assert extent == pytest.approx([0.6, 0.2, 1.0])
    assert out.vertices[:, 2].min() == pytest.approx(0.0)
    assert frame.as_report()["up_axis"] == "y"


def test_front_axis_maps_to_plus_x() -> None:
    marker = trimesh.creation.box(extents=(0.1, 0.1, 0.1))
    marker.apply_translation((0, -1.0, 0.05))  # something sticking out towards -y
    base = trimesh.creation.box(extents=(0.4, 0.4, 0.1))
    base.apply_translation((0, 0, 0.05))
    parts = [_part(base), _part(marker)]
    out, _ = normalise(parts, "f", "z", "-y", None)
    assert out[1].vertices[:, 0].mean() > 0.5  # the -y marker is now in front (+x)
    assert abs(out[1].vertices[:, 1].mean()) < 1e-9


def test_repair_fixes_winding_and_inside_out_bodies() -> None:
    box = trimesh.creation.box(extents=(0.3, 0.3, 0.3))
    faces = np.asarray(box.faces).copy()
    faces[:4] = faces[:4, ::-1]  # inconsistent winding
    broken = MeshPart(np.asarray(box.vertices, float), faces, None, GREY)
    result = repair([broken])
    assert result.watertight and result.winding_consistent
    assert result.physics.volume == pytest.approx(0.027)
    assert result.stats["faces_flipped"] > 0
    inside_out = MeshPart(
        np.asarray(box.vertices, float), np.asarray(box.faces)[:, ::-1], None, GREY
    )
    result = repair([inside_out])
    assert result.stats["bodies_inverted"] == 1
    assert result.physics.volume == pytest.approx(0.027)


def test_repair_merges_parts_by_material_and_drops_degenerate_faces() -> None:
    red = MeshMaterial(rgba=(1.0, 0.0, 0.0, 1.0))
    a = trimesh.creation.box(extents=(0.1, 0.1, 0.1))
    b = a.copy()
    b.apply_translation((0.2, 0, 0))
    c = a.copy()
    c.apply_translation((0.4, 0, 0))
    degenerate = MeshPart(np.zeros((3, 3)), np.array([[0, 1, 2]]), None, GREY)
    result = repair([_part(a), _part(b, red), _part(c), degenerate])
    assert [v.material.rgba for v in result.visuals] == [GREY.rgba, red.rgba]
    assert len(result.visuals[0].faces) == 24
    assert result.stats["degenerate_faces_removed"] == 1


def test_hulls_are_capped_pulled_inside_and_slivers_become_boxes() -> None:
    sphere = trimesh.creation.icosphere(subdivisions=3, radius=0.1)
    sphere.apply_translation((0, 0, 0.1))
    proximity = MeshProximity(sphere)
    too_big = np.asarray(sphere.vertices) * 1.0 + np.array([0.0, 0.0, 0.0])
    bulging = (too_big - [0, 0, 0.1]) * 1.2 + [0, 0, 0.1]  # 2 cm out
    sliver = np.array([[0, 0, 0.1], [0.05, 0, 0.1], [0, 0.05, 0.1], [0.05, 0.05, 0.1]])
    result = postprocess([bulging, sliver], sphere, proximity, watertight=True)
    kinds = [c.kind for c in result.colliders]
    assert kinds.count("mesh") == 1
    hull = result.colliders[0]
    assert len(hull.vertices) <= HULL_VERTEX_CAP
    assert result.quality["hulls_capped"] == 1 and result.quality["hulls_pulled_inside"] == 1
    assert result.quality["max_outward_deviation_m"] <= 0.003 + 1e-9
    assert result.quality["volume_reference"] == "mesh"
    # The flat square sits inside the sphere's hull: it is dropped as covered.
    assert result.quality["slivers_dropped"] == 1


def test_a_lone_flat_mesh_becomes_a_thin_box() -> None:
    plane = trimesh.Trimesh(
        vertices=[[0, 0, 0], [0.3, 0, 0], [0.3, 0.2, 0], [0, 0.2, 0]], faces=[[0, 1, 2], [0, 2, 3]]
    )
    result = postprocess([np.asarray(plane.vertices)], plane, MeshProximity(plane), False)
    (box,) = result.colliders
    assert box.kind == "box"
    assert sorted(box.size) == pytest.approx([0.0005, 0.1, 0.15])


def test_obj_text_is_fixed_point_and_has_texcoords() -> None:
    text = obj_bytes(np.array([[-0.0, 1e-9, 1.0]]), np.zeros((0, 3), int), np.array([[0.5, -0.0]]))
    assert text == b"v 0.000000 0.000000 1.000000\nvt 0.500000 0.000000\n"


@pytest.mark.parametrize(
    ("name", "category"),
    [
        ("coffee_table.glb", "coffee_table"),
        ("bedside_table_01.glb", "nightstand"),
        ("ycb_005_tomato_soup_can/textured.obj", "can"),
        ("medieval_bookcase.glb", "bookshelf"),
        ("ycb_065-a_cups/textured.obj", "cup"),
        ("thing.obj", None),
    ],
)
def test_category_guess(name: str, category: str | None) -> None:
    assert physical.guess_category(Path(name)) == category


def test_category_table_is_complete_and_sane() -> None:
    names = physical.categories()
    assert len(names) >= 60
    for needed in ["mug", "plate", "book", "dining_chair", "sofa", "bookshelf", "monitor"]:
        assert needed in names
    for name in names:
        info = physical.category_info(name)
        lo, hi = info.mass_range_kg
        assert 0 < lo < hi and 0 < info.friction <= 5 and info.density_kg_m3 > 0
        assert set(info.placement) <= {"floor", "wall", "object", "ceiling"}
    unknown = physical.category_info("spaceship", (2.0, 1.0, 1.0))
    assert not unknown.known and unknown.placement == ("floor",)
    # Typical material volumes land in their ranges: a mug's 0.05 m2 of 5 mm ceramic wall,
    # a sofa's 1.2 m3 of upholstery.
    mug = physical.category_info("mug")
    assert mug.wall_m is not None
    assert mug.mass_range_kg[0] < mug.density_kg_m3 * 0.05 * mug.wall_m < mug.mass_range_kg[1]
    sofa = physical.category_info("sofa")
    assert sofa.wall_m is None and 25 < sofa.density_kg_m3 * 1.2 < 60
