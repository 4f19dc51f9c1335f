"""Textures on procedural assets: which materials wear which pattern, UVs in metres, the files
an asset gets, and MuJoCo loading them."""

from __future__ import annotations

import dataclasses

import mujoco
import numpy as np
import pytest

from asset_pipeline.procedural import generate_asset
from asset_pipeline.procedural.assembly import AssetDesign, assemble
from asset_pipeline.procedural.kit import (
    BLACK_LEATHER,
    BRASS,
    CONCRETE,
    GREY_FABRIC,
    LINEN,
    OAK,
    RUG_RED,
    WHITE_LACQUER,
    block,
)
from asset_pipeline.procedural.obj_writer import obj_bytes
from asset_pipeline.procedural.parts import RecipeMaterial
from asset_pipeline.procedural.textures import (
    PATTERNS,
    box_uv,
    pattern_of,
    pattern_png,
    texture_file,
)
from holomj.mjcf.textures import pattern_mean


@pytest.mark.parametrize(
    ("material", "pattern"),
    [
        (OAK, "wood"),
        (GREY_FABRIC, "fabric"),
        (LINEN, "fabric"),
        (BLACK_LEATHER, "leather"),
        (RUG_RED, "carpet"),
        (CONCRETE, "concrete"),
        (WHITE_LACQUER, None),
        (BRASS, None),
        (RecipeMaterial("marble", (0.9, 0.9, 0.9, 1.0)), "marble"),
        (RecipeMaterial("plush_honey", (0.8, 0.6, 0.3, 1.0)), "velvet"),
        # A finish asked for by attribute names the look in its label.
        (
            RecipeMaterial("grey_fabric__red_leather", (0.6, 0.1, 0.1, 1.0), label="red leather"),
            "leather",
        ),
        (RecipeMaterial("oak__lacquered", (0.6, 0.4, 0.3, 1.0), label="lacquered"), None),
        (RecipeMaterial("oak__red", (0.6, 0.1, 0.1, 1.0), label="red"), "wood"),
        # The explicit switch wins either way.
        (dataclasses.replace(OAK, pattern="plain"), None),
        (dataclasses.replace(BRASS, pattern="leather"), "leather"),
    ],
)
def test_materials_wear_the_pattern_their_words_name(material: RecipeMaterial, pattern) -> None:
    assert pattern_of(material) == pattern


def test_an_unknown_pattern_is_an_error() -> None:
    with pytest.raises(ValueError, match="unknown pattern 'plaid'"):
        pattern_of(dataclasses.replace(OAK, pattern="plaid"))


def test_box_uvs_are_metres_over_the_tile_with_the_grain_along_the_longest_side() -> None:
    board = block((0.0, 2.0), (0.0, 0.5), (0.0, 0.1), OAK).mesh()
    assert board is not None
    textured = box_uv(board, tile_m=0.5, grain_axis=0)
    assert textured.uv is not None and textured.uv_faces is not None
    assert textured.uv_faces.shape == board.faces.shape
    corners = board.vertices[board.faces]  # (m, 3, 3)
    uv = textured.uv[textured.uv_faces]  # (m, 3, 2)
    normal = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    for face in range(len(board.faces)):
        facing = int(np.argmax(np.abs(normal[face])))
        if facing != 0:  # every face but the end grain: u runs along x, in tiles of 0.5 m
            np.testing.assert_allclose(uv[face, :, 0], corners[face, :, 0] / 0.5)
        other = ({0, 1, 2} - {facing, 0}).pop() if facing != 0 else 2
        np.testing.assert_allclose(uv[face, :, 1], corners[face, :, other] / 0.5)
    # Shared vertices keep one position; only their texture coordinates split per face.
    assert len(textured.vertices) == 8 and len(textured.uv) == 24


def _design(textured: bool = True) -> AssetDesign:
    parts = (
        block((-0.4, 0.4), (-0.9, 0.9), (0.0, 0.4), GREY_FABRIC),
        block((-0.4, -0.25), (-0.9, 0.9), (0.4, 0.8), BLACK_LEATHER),
        block((0.3, 0.4), (-0.9, 0.9), (0.4, 0.5), WHITE_LACQUER),
    )
    return AssetDesign(
        id="bench",
        category="sofa",
        description="a test bench",
        mass_kg=20.0,
        friction=0.8,
        placement=("floor",),
        parts=parts,
        textured=textured,
    )


def test_assembled_asset_carries_textures_uvs_and_its_colours() -> None:
    bundle = assemble(_design())
    by_mesh = {v.mesh: v for v in bundle.meta.visual}
    fabric = by_mesh["grey_fabric.obj"]
    assert fabric.texture == texture_file("fabric")
    # The tint times the pattern averages to the colour.
    np.testing.assert_allclose(
        np.asarray(fabric.rgba[:3]) * pattern_mean("fabric"), GREY_FABRIC.rgba[:3], atol=1e-3
    )
    assert bundle.files[texture_file("fabric")] == pattern_png("fabric")
    assert by_mesh["black_leather.obj"].texture == texture_file("leather")
    assert by_mesh["white_lacquer.obj"].texture is None
    assert b"\nvt " in bundle.files["grey_fabric.obj"]
    assert b"vt" not in bundle.files["white_lacquer.obj"]
    plain = assemble(_design(textured=False))
    assert all(v.texture is None for v in plain.meta.visual)
    assert not any(name.endswith(".png") for name in plain.files)
    # Only the looks change: the geometry, colliders and mass are the same.
    assert plain.meta.collision == bundle.meta.collision and plain.meta.size == bundle.meta.size


def test_mujoco_loads_textured_assets_with_their_texture_coordinates() -> None:
    bundle = generate_asset("sofa", "s", None, 0)
    spec = mujoco.MjSpec()
    spec.assets = dict(bundle.files)
    body = spec.worldbody.add_body()
    textured = 0
    for k, part in enumerate(bundle.meta.visual):
        spec.add_mesh(name=f"m{k}", file=part.mesh)
        material = spec.add_material(name=f"mat{k}", rgba=list(part.rgba))
        if part.texture:
            textured += 1
            spec.add_texture(name=f"t{k}", type=mujoco.mjtTexture.mjTEXTURE_2D, file=part.texture)
            material.textures[mujoco.mjtTextureRole.mjTEXROLE_RGB] = f"t{k}"
        body.add_geom(type=mujoco.mjtGeom.mjGEOM_MESH, meshname=f"m{k}", material=f"mat{k}")
    model = spec.compile()
    assert textured >= 1 and model.ntex == textured
    for k, part in enumerate(bundle.meta.visual):
        count = model.mesh_texcoordnum[model.mesh(f"m{k}").id]
        assert (count > 0) == (part.texture is not None), part.mesh


def test_texture_scale_is_physical_whatever_the_asset_size() -> None:
    """The same oak shows the same grain size on a small and a large board."""
    for length in (0.4, 1.6):
        design = dataclasses.replace(
            _design(), parts=(block((0.0, length), (0.0, 0.3), (0.0, 0.05), OAK),)
        )
        bundle = assemble(design)
        text = bundle.files["oak.obj"].decode().splitlines()
        uv = np.array([ln.split()[1:] for ln in text if ln.startswith("vt ")], dtype=float)
        assert np.ptp(uv[:, 0]) == pytest.approx(length / PATTERNS["wood"].tile_m, abs=1e-3)


def test_obj_writer_writes_texture_indices_apart_from_vertex_indices() -> None:
    board = block((0.0, 1.0), (0.0, 1.0), (0.0, 1.0), OAK).mesh()
    assert board is not None
    text = obj_bytes(box_uv(board, 0.5, 0), "c").decode().splitlines()
    assert text[0] == "# c" and sum(ln.startswith("v ") for ln in text) == 8
    faces = [ln for ln in text if ln.startswith("f ")]
    assert len(faces) == 12 and all(len(f.split()[1].split("/")) == 2 for f in faces)
    assert "-0.000" not in "\n".join(text)
