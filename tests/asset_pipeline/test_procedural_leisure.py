"""The leisure categories (gym, games, music, art, hospitality, salon): every style variant
builds at its size, masses are plausible, game tables have their playing surface at the right
height and tall pieces do not tip."""

from __future__ import annotations

import math

import numpy as np
import pytest

from asset_pipeline.procedural import CATEGORIES, generate_asset
from asset_pipeline.procedural.registry import rng_for

MM = 1e-3
FLOOR = (
    "treadmill", "exercise_bike", "weight_bench", "dumbbell_rack", "squat_rack", "punching_bag",
    "rowing_machine", "pool_table", "foosball_table", "table_tennis_table", "air_hockey_table",
    "arcade_cabinet", "pinball_machine", "drum_kit", "digital_piano", "speaker",
    "guitar_amplifier", "easel", "salon_chair", "styling_station", "shampoo_station",
    "popcorn_machine", "vending_machine", "slot_machine", "massage_table", "telescope",
)  # fmt: skip
WALL = ("dartboard", "neon_sign", "menu_board", "acoustic_panel")
MASS_RANGES = {
    "treadmill": (60, 140), "exercise_bike": (25, 70), "weight_bench": (12, 45),
    "dumbbell_rack": (20, 80), "squat_rack": (70, 200), "punching_bag": (60, 180),
    "rowing_machine": (20, 50), "pool_table": (150, 450), "foosball_table": (40, 110),
    "table_tennis_table": (60, 150), "air_hockey_table": (70, 200), "arcade_cabinet": (70, 160),
    "pinball_machine": (80, 160), "drum_kit": (20, 60), "digital_piano": (25, 70),
    "speaker": (10, 45), "guitar_amplifier": (8, 35), "easel": (3, 15), "salon_chair": (25, 70),
    "styling_station": (20, 70), "shampoo_station": (40, 120), "popcorn_machine": (25, 80),
    "vending_machine": (200, 400), "slot_machine": (70, 160), "massage_table": (10, 30),
    "telescope": (5, 40), "dartboard": (2, 10), "neon_sign": (1, 10), "menu_board": (2, 15),
    "acoustic_panel": (0.5, 6),
}  # fmt: skip


def _centre_of_mass(meta) -> np.ndarray:
    volumes = np.array([c.volume_m3 for c in meta.collision])
    positions = np.array([c.pos for c in meta.collision])
    return (volumes[:, None] * positions).sum(axis=0) / volumes.sum()


def test_every_category_is_registered_with_three_variants() -> None:
    for name in FLOOR + WALL:
        info = CATEGORIES[name]
        assert info.builder.__module__.startswith("asset_pipeline.procedural.leisure_"), name
        assert len(info.variants) >= 3 and info.variants[0] is None, name
        assert info.placement == (("wall",) if name in WALL else ("floor",)), name
        assert 0.5 <= info.friction <= 1.0


@pytest.mark.parametrize("name", FLOOR + WALL)
def test_variants_build_at_their_size_with_distinct_styles(name: str) -> None:
    info = CATEGORIES[name]
    for seed, size in enumerate(info.variants):
        meta = generate_asset(name, f"{name}_{seed}", size, seed).meta
        np.testing.assert_allclose(meta.size, size or info.default_size, atol=MM)
        assert "{" not in meta.description and meta.collision
    styles = {generate_asset(name, "x", None, seed).meta.description for seed in range(8)}
    looks = {
        tuple(v.mesh for v in generate_asset(name, "x", None, seed).meta.visual)
        for seed in range(8)
    }
    assert len(styles) >= 2 or len(looks) >= 2, f"{name}: seeds do not vary the style"


@pytest.mark.parametrize("name", sorted(MASS_RANGES))
def test_mass_is_plausible(name: str) -> None:
    low, high = MASS_RANGES[name]
    info = CATEGORIES[name]
    assert low <= info.mass_for(info.default_size) <= high


@pytest.mark.parametrize("seed", range(4))
def test_pool_table_felt_is_a_surface_between_the_cushions(seed: int) -> None:
    meta = generate_asset("pool_table", "p", None, seed).meta
    (felt,) = meta.surfaces
    assert 0.76 <= felt.height <= 0.8
    xs = [x for x, _ in felt.polygon]
    ys = [y for _, y in felt.polygon]
    # the felt stops short of the rails on every side and covers most of the table
    assert max(xs) < 0.5 * meta.size[0] - 0.1 and max(ys) < 0.5 * meta.size[1] - 0.1
    assert felt.area_m2 > 0.6 * meta.size[0] * meta.size[1] - 1.0
    names = {v.mesh for v in meta.visual}
    assert any(n.startswith("felt") for n in names) and "piano_black.obj" in names


@pytest.mark.parametrize(
    ("name", "low", "high"),
    [("table_tennis_table", 0.74, 0.77), ("air_hockey_table", 0.7, 0.8),
     ("dumbbell_rack", 0.75, 0.81), ("styling_station", 0.79, 0.81),
     ("massage_table", 0.6, 0.66)],
)  # fmt: skip
def test_tables_and_counters_have_their_top_surface(name: str, low: float, high: float) -> None:
    for seed in range(3):
        meta = generate_asset(name, "t", None, seed).meta
        top = max(s.height for s in meta.surfaces)
        assert low <= top <= high, (name, seed, top)


def test_table_tennis_net_only_where_it_fits() -> None:
    low = generate_asset("table_tennis_table", "t", None, 0).meta
    high = generate_asset("table_tennis_table", "t", (2.74, 1.525, 0.9125), 0).meta
    assert "taken down" in low.description and "and a net" in high.description
    assert max(s.height for s in high.surfaces) == pytest.approx(0.76, abs=0.005)


@pytest.mark.parametrize(
    "name", ["arcade_cabinet", "pinball_machine", "vending_machine", "slot_machine",
             "speaker", "punching_bag", "popcorn_machine", "telescope", "easel", "squat_rack"],
)  # fmt: skip
def test_tall_pieces_have_a_low_enough_centre_of_mass(name: str) -> None:
    info = CATEGORIES[name]
    for seed, size in enumerate(info.variants):
        meta = generate_asset(name, "t", size, seed).meta
        com = _centre_of_mass(meta)
        if name != "telescope":  # a telescope's tube is its heaviest part, up on the tripod
            assert com[2] < 0.62 * meta.size[2], (name, com)
        # the footprint of the colliders that touch the floor contains the centre of mass
        feet = [c for c in meta.collision if abs(c.pos[2] - _half_z(c)) < 2e-3]
        xs = [c.pos[0] + s * _half_xy(c)[0] for c in feet for s in (-1, 1)]
        ys = [c.pos[1] + s * _half_xy(c)[1] for c in feet for s in (-1, 1)]
        margin = min(com[0] - min(xs), max(xs) - com[0], com[1] - min(ys), max(ys) - com[1])
        assert margin > 0.0, (name, seed)
        assert math.degrees(math.atan2(margin, com[2])) > 3.0, (name, seed)


def _half(c) -> tuple[float, float, float]:
    """Half extents of a collider's bounding box (cylinders along z, x or y; a hull's size is
    its bounding box's half extents)."""
    if c.kind in ("box", "mesh"):
        return c.size[0], c.size[1], c.size[2]
    if c.kind == "sphere":
        return (c.size[0],) * 3
    r, half = c.size
    if tuple(c.quat) == (1.0, 0.0, 0.0, 0.0):
        return r, r, half
    return (half, r, r) if abs(c.quat[2]) > 0.5 else (r, half, r)


def _half_z(c) -> float:
    return _half(c)[2]


def _half_xy(c) -> tuple[float, float]:
    return _half(c)[0], _half(c)[1]


def test_telescope_stands_on_three_slanted_legs() -> None:
    design = CATEGORIES["telescope"].generate(None, rng_for("telescope", 0))
    slabs = [p for p in design.parts if type(p).__name__ == "Slab"]
    assert len(slabs) == 3
    for leg in slabs:
        (low, high) = leg.bounds()
        assert high[2] - low[2] > 0.6 and leg.colliders()
        assert high[0] - low[0] > 0.05 or high[1] - low[1] > 0.05, "the leg is not slanted"
