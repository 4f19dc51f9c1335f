"""Procedural surface patterns: seamless, deterministic, valid PNG, chosen by material words."""

from __future__ import annotations

import io

import numpy as np
import pytest
from PIL import Image

from holomj.mjcf import textures
from holomj.mjcf.png import png_bytes
from holomj.mjcf.textures import (
    PATTERNS,
    SIZE_PX,
    pattern_for_name,
    pattern_image,
    pattern_mean,
    pattern_png,
    procedural_look,
    tinted,
)
from holomj.spec.materials import BUILTIN_MATERIALS, Material

ASSET_PATTERNS = ("wood", "fabric", "velvet", "leather", "marble", "tile", "carpet", "concrete")


@pytest.mark.parametrize("name", sorted(PATTERNS))
def test_pattern_png_decodes_to_its_image(name: str) -> None:
    data = pattern_png(name)
    assert data.startswith(b"\x89PNG\r\n\x1a\n") and len(data) < 80 * 1024
    decoded = np.asarray(Image.open(io.BytesIO(data)))
    assert decoded.shape == (SIZE_PX, SIZE_PX) and decoded.dtype == np.uint8
    np.testing.assert_array_equal(decoded, pattern_image(name))


@pytest.mark.parametrize("name", sorted(PATTERNS))
def test_patterns_tile_without_seams(name: str) -> None:
    """Across the wrap-around edge the image changes no more than between neighbouring columns
    or rows inside it (the largest such change: a board or grout joint is one)."""
    image = pattern_image(name).astype(float)
    for axis in (0, 1):
        inside = np.abs(np.diff(image, axis=axis)).mean(axis=1 - axis)
        seam = np.abs(np.take(image, 0, axis=axis) - np.take(image, -1, axis=axis)).mean()
        assert seam <= inside.max() + 1e-9, (name, axis, seam, inside.max())
        assert seam <= 3.0 * np.median(inside) or name in ("planks", "tile", "brick"), name


@pytest.mark.parametrize("name", sorted(PATTERNS))
def test_patterns_are_deterministic_and_have_texture(name: str) -> None:
    first = pattern_png(name)
    pattern_image.cache_clear()
    pattern_png.cache_clear()
    assert pattern_png(name) == first
    image = pattern_image(name)
    assert image.std() > 2.0, "a pattern must not be flat"


@pytest.mark.parametrize("name", ASSET_PATTERNS)
def test_asset_patterns_are_bright_so_tints_rarely_saturate(name: str) -> None:
    assert pattern_mean(name) >= 0.84


def test_patterns_differ_from_each_other() -> None:
    pngs = {pattern_png(name) for name in PATTERNS}
    assert len(pngs) == len(PATTERNS)


def test_png_writer_round_trips_any_image() -> None:
    rng = np.random.default_rng(0)
    for image in (
        rng.integers(0, 256, size=(17, 33), dtype=np.uint8),
        np.zeros((4, 4), dtype=np.uint8),
        np.tile(np.arange(256, dtype=np.uint8), (3, 1)),
    ):
        np.testing.assert_array_equal(np.asarray(Image.open(io.BytesIO(png_bytes(image)))), image)
    with pytest.raises(ValueError, match="2-D"):
        png_bytes(np.zeros((2, 2, 3), dtype=np.uint8))


@pytest.mark.parametrize(
    ("name", "pattern"),
    [
        ("oak_floor", "planks"),
        ("dark_wood_floor", "planks"),
        ("wood_panel_wall", "planks"),
        ("wood_ceiling", "planks"),
        ("white_tile", "tile"),
        ("acoustic_ceiling_tile", "tile"),
        ("marble", "marble"),
        ("brick", "brick"),
        ("carpet_grey", "carpet"),
        ("light_grey_carpet", "carpet"),
        ("polished_concrete", "concrete"),
        ("dark_slate", "concrete"),
        ("oak_door", "wood"),
        ("white_paint", None),
        ("brick_red_paint", None),
        ("floor_default", None),
        ("plain_oak_floor", None),
        ("glass", None),
        ("vinyl_floor", None),
    ],
)
def test_room_material_names_pick_their_pattern(name: str, pattern: str | None) -> None:
    assert pattern_for_name(name) == pattern


def test_every_builtin_wood_tile_carpet_or_stone_surface_is_textured() -> None:
    words = ("wood", "oak", "walnut", "pine", "cherry", "bamboo", "tile", "carpet", "marble")
    for name, material in BUILTIN_MATERIALS.items():
        if any(w in name for w in words) and "paint" not in name:
            assert procedural_look(name, material) is not None, name


def test_looks_keep_the_average_colour_and_respect_own_textures() -> None:
    oak = BUILTIN_MATERIALS["oak_floor"]
    look = procedural_look("oak_floor", oak)
    assert look is not None and look.pattern == "planks"
    assert look.tile_m == PATTERNS["planks"].tile_m and look.png == pattern_png("planks")
    np.testing.assert_allclose(
        np.asarray(look.rgba[:3]) * pattern_mean("planks"), oak.rgba[:3], atol=1e-3
    )
    own = Material(rgba=oak.rgba, texture="/some/where/planks.png")
    assert procedural_look("oak_floor", own) is None
    # A colour brighter than the pattern allows is capped, alpha kept.
    assert tinted((1.0, 1.0, 1.0, 0.5), "wood") == (1.0, 1.0, 1.0, 0.5)


def test_words_ignore_case_and_separators() -> None:
    assert textures.words_of("Light-Oak_Floor 2") == ["light", "oak", "floor"]
    assert textures.pattern_for_words(["red", "leather"]) == "leather"
    assert textures.pattern_for_words(["wool", "rug"]) == "carpet"  # carpet wins over fabric
