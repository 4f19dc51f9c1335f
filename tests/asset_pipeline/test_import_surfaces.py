"""Support surfaces on synthetic meshes: a table, an open bookcase, a plain block."""

from __future__ import annotations

import pytest
import trimesh

from asset_pipeline.surfaces import ERODE_M, support_surfaces


def _box(size: tuple[float, float, float], centre: tuple[float, float, float]) -> trimesh.Trimesh:
    return trimesh.creation.box(
        extents=size, transform=trimesh.transformations.translation_matrix(centre)
    )


def _table() -> trimesh.Trimesh:
    top = _box((1.0, 0.6, 0.04), (0, 0, 0.73))
    legs = [_box((0.05, 0.05, 0.71), (x, y, 0.355)) for x in (-0.45, 0.45) for y in (-0.25, 0.25)]
    return trimesh.util.concatenate([top, *legs])


def _bookcase(levels: int = 3) -> trimesh.Trimesh:
    """Open front, two sides, a back, ``levels`` boards and a top."""
    w, d, h, t = 0.8, 0.3, 1.2, 0.02
    parts = [
        _box((t, d, h), (-w / 2 + t / 2, 0, h / 2)),
        _box((t, d, h), (w / 2 - t / 2, 0, h / 2)),
        _box((w, t, h), (0, -d / 2 + t / 2, h / 2)),
        _box((w, d, t), (0, 0, h - t / 2)),
    ]
    for k in range(levels):
        z = 0.05 + k * 0.35
        parts.append(_box((w - 2 * t, d - t, t), (0, t / 2, z)))
    return trimesh.util.concatenate(parts)


def test_table_top_is_one_eroded_surface() -> None:
    (top,) = support_surfaces(_table())
    assert top.height == pytest.approx(0.75, abs=1e-3)
    expected = (1.0 - 2 * ERODE_M) * (0.6 - 2 * ERODE_M)
    assert top.area == pytest.approx(expected, rel=0.02)
    xs = [p[0] for p in top.polygon]
    assert max(xs) == pytest.approx(0.5 - ERODE_M, abs=0.005)


def test_open_bookcase_has_every_level() -> None:
    surfaces = support_surfaces(_bookcase(3))
    heights = [round(s.height, 3) for s in surfaces]
    assert heights == pytest.approx([0.06, 0.41, 0.76, 1.2], abs=0.002)
    for surface in surfaces[:-1]:  # the inner levels, not the top
        xs = [p[0] for p in surface.polygon]
        # The side panels (inner faces at +-0.38) and the erosion keep objects inside.
        assert max(xs) <= 0.38 - ERODE_M + 0.011
        assert min(xs) >= -0.38 + ERODE_M - 0.011


def test_a_board_right_above_blocks_the_level_below() -> None:
    low = _box((0.6, 0.4, 0.02), (0, 0, 0.30))
    lid = _box((0.6, 0.4, 0.02), (0, 0, 0.34))  # 2 cm gap: no room for objects
    legs = [_box((0.02, 0.02, 0.35), (x, y, 0.175)) for x in (-0.29, 0.29) for y in (-0.19, 0.19)]
    surfaces = support_surfaces(trimesh.util.concatenate([low, lid, *legs]))
    assert [round(s.height, 2) for s in surfaces] == [0.35]


def test_floor_contact_face_is_never_a_surface() -> None:
    block = _box((0.5, 0.5, 0.005), (0, 0, 0.0025))  # a 5 mm mat: its top is under 1 cm
    assert support_surfaces(block) == []
    flipped = _box((0.5, 0.5, 0.3), (0, 0, 0.15))
    flipped.invert()  # even with inward normals the bottom (now facing up) is skipped
    assert all(s.height > 0.01 for s in support_surfaces(flipped))


def test_small_tops_are_dropped() -> None:
    assert support_surfaces(_box((0.1, 0.1, 0.1), (0, 0, 0.05))) == []
