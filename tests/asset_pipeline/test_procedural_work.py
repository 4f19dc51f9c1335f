"""The work categories (offices, labs, shops, workshops, health): every style variant builds at
its size, masses are plausible, worktops and shelves are surfaces at the right height and tall
narrow pieces (lockers, server racks) have their centre of mass low enough not to tip."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

from asset_pipeline.procedural import CATEGORIES, generate_asset

MM = 1e-3
FLOOR = (
    "workbench", "tool_chest", "lab_bench", "fume_hood", "filing_cabinet", "locker",
    "clothes_rack", "shelving_gondola", "checkout_counter", "shop_counter", "display_case",
    "water_cooler", "server_rack", "hospital_bed", "examination_table", "mixing_desk", "lectern",
    "photocopier", "safe", "drafting_table", "sewing_table", "pallet_rack",
)  # fmt: skip
WALL = ("chalkboard", "projector_screen", "tool_wall", "eye_chart")
MASS_RANGES = {
    "workbench": (35, 120), "tool_chest": (50, 150), "lab_bench": (80, 250),
    "fume_hood": (200, 600), "filing_cabinet": (25, 70), "locker": (20, 60),
    "clothes_rack": (8, 40), "shelving_gondola": (40, 150), "checkout_counter": (70, 200),
    "shop_counter": (40, 120), "display_case": (40, 150), "water_cooler": (10, 35),
    "server_rack": (150, 700), "hospital_bed": (80, 200), "examination_table": (40, 150),
    "mixing_desk": (40, 150), "lectern": (15, 60), "photocopier": (50, 150), "safe": (40, 200),
    "drafting_table": (15, 60), "sewing_table": (15, 50), "pallet_rack": (150, 1500),
    "chalkboard": (4, 25), "projector_screen": (5, 30), "tool_wall": (8, 50),
    "eye_chart": (0.2, 4),
}  # fmt: skip
KNOWLEDGE = Path(__file__).parents[2] / "holomj" / "data" / "knowledge" / "objects.json"


def _centre_of_mass(meta) -> np.ndarray:
    volumes = np.array([c.volume_m3 for c in meta.collision])
    positions = np.array([c.pos for c in meta.collision])
    return (volumes[:, None] * positions).sum(axis=0) / volumes.sum()


def test_every_category_is_registered_with_three_variants() -> None:
    for name in FLOOR + WALL:
        info = CATEGORIES[name]
        assert info.builder.__module__.startswith("asset_pipeline.procedural.work_"), name
        assert len(info.variants) >= 3 and info.variants[0] is None, name
        assert info.placement == (("wall",) if name in WALL else ("floor",)), name


def test_default_sizes_follow_the_knowledge_base() -> None:
    """objects.json gives sizes in the library's axes (x = depth, y = width, z = height)."""
    kinds = json.loads(KNOWLEDGE.read_text())["objects"]
    by_category = {k["category"]: k for k in kinds.values()}
    for name in FLOOR + WALL:
        assert CATEGORIES[name].default_size == pytest.approx(by_category[name]["size"]), name
    assert "reception_desk" not in CATEGORIES  # objects.json files the reception desk as a desk


@pytest.mark.parametrize("name", FLOOR + WALL)
def test_variants_build_at_their_size(name: str) -> None:
    info = CATEGORIES[name]
    for seed, size in enumerate(info.variants):
        meta = generate_asset(name, f"{name}_{seed}", size, seed).meta
        np.testing.assert_allclose(meta.size, size or info.default_size, atol=MM)
        assert "{" not in meta.description and meta.collision


@pytest.mark.parametrize("name", sorted(MASS_RANGES))
def test_mass_is_plausible(name: str) -> None:
    low, high = MASS_RANGES[name]
    info = CATEGORIES[name]
    assert low <= info.mass_for(info.default_size) <= high


# category -> (lowest acceptable top surface height as a fraction of h, least number of levels)
TOPS = {
    "workbench": (1.0, 2), "lab_bench": (1.0, 1), "filing_cabinet": (1.0, 1),
    "checkout_counter": (1.0, 1), "shop_counter": (1.0, 3), "display_case": (1.0, 3),
    "tool_chest": (1.0, 1), "safe": (1.0, 1), "sewing_table": (1.0, 1),
    "shelving_gondola": (0.6, 4), "mixing_desk": (1.0, 2), "drafting_table": (0.1, 1),
    "fume_hood": (0.35, 1), "hospital_bed": (0.55, 1), "examination_table": (0.7, 1),
}  # fmt: skip


@pytest.mark.parametrize("name", sorted(TOPS))
def test_worktops_and_shelves_are_surfaces(name: str) -> None:
    fraction, levels = TOPS[name]
    for seed in range(3):
        meta = generate_asset(name, "s", None, seed).meta
        heights = sorted({round(s.height, 3) for s in meta.surfaces})
        assert len(heights) >= levels, (name, seed, heights)
        assert heights[-1] >= fraction * meta.size[2] - MM, (name, seed, heights)


def test_workbench_and_lab_bench_tops_are_at_working_height() -> None:
    for name in ("workbench", "lab_bench", "checkout_counter"):
        meta = generate_asset(name, "b", None, 1).meta
        top = max(meta.surfaces, key=lambda s: s.height)
        assert 0.85 <= top.height <= 0.95
        assert top.area_m2 > 0.6 * meta.size[0] * meta.size[1]


def test_fume_hood_work_surface_is_inside_the_enclosure() -> None:
    meta = generate_asset("fume_hood", "f", None, 0).meta
    (work,) = meta.surfaces
    assert 0.85 <= work.height <= 0.95
    assert max(abs(y) for _, y in work.polygon) < 0.5 * meta.size[1] - 0.05


@pytest.mark.parametrize(
    "name", ["locker", "server_rack", "filing_cabinet", "water_cooler", "photocopier",
             "clothes_rack", "pallet_rack", "shelving_gondola", "tool_chest"],
)  # fmt: skip
def test_tall_narrow_pieces_do_not_tip(name: str) -> None:
    info = CATEGORIES[name]
    for seed, size in enumerate(info.variants):
        meta = generate_asset(name, "t", size, seed).meta
        com = _centre_of_mass(meta)
        d, w, h = meta.size
        if name not in ("clothes_rack", "pallet_rack"):  # hung garments, loaded upper levels
            assert com[2] <= 0.55 * h, (name, seed, com)
        # static tipping angle about the nearer footprint edge
        margin = min(0.5 * d - abs(com[0]), 0.5 * w - abs(com[1])) - 0.03
        assert math.degrees(math.atan2(margin, com[2])) > 8.0, (name, seed, com)


def test_locker_has_doors_vents_and_latches() -> None:
    meta = generate_asset("locker", "l", (0.5, 0.9, 1.8), 0).meta
    assert "doors" in meta.description and "vents" in meta.description
    colours = {v.mesh for v in meta.visual}
    assert "black_metal.obj" in colours  # the vent slots and plinth
