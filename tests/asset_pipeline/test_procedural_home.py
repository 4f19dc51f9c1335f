"""The home categories of issue 15 (asset_pipeline/procedural/home_*.py): registry facts that
match the knowledge base, every style variant, masses, surfaces and category-specific
geometry (an open firebox, thin curtains, flat rockers, ceiling pieces hung from their top)."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from asset_pipeline.procedural import CATEGORIES, generate_asset
from holomj.spec.assets import AssetMeta

MM = 1e-3
FLOOR = (
    "fireplace", "rocking_chair", "crib", "changing_table", "toy_box", "ottoman", "bench",
    "sideboard", "console_table", "coat_rack", "shoe_rack", "kitchen_island", "wine_rack",
    "washing_machine", "dryer", "ironing_board", "laundry_basket", "radiator", "bean_bag",
    "chaise_longue", "vanity_table", "trunk", "floor_mirror", "trash_bin", "high_chair",
    "dishwasher", "tall_cabinet", "bar_counter", "bar_table", "pet_bed", "grandfather_clock",
    "umbrella_stand", "plant_stand", "magazine_rack", "display_cabinet", "folding_screen",
)  # fmt: skip
WALL = (
    "curtains", "blinds", "wall_clock", "wall_sconce", "towel_rail", "coat_hooks",
    "range_hood", "tapestry", "bulletin_board",
)  # fmt: skip
CEILING = (
    "pendant_light", "chandelier", "ceiling_fan", "ceiling_light", "paper_lantern",
    "hanging_plant",
)  # fmt: skip
HOME = FLOOR + WALL + CEILING
# Things go on these (the knowledge base's receptacles, plus the pieces with a usable top).
RECEPTACLES = (
    "fireplace", "changing_table", "toy_box", "bench", "sideboard", "console_table",
    "shoe_rack", "kitchen_island", "wine_rack", "ironing_board", "vanity_table", "trunk",
    "bar_counter", "bar_table", "plant_stand", "magazine_rack", "tall_cabinet",
    "display_cabinet", "washing_machine", "dryer", "dishwasher", "crib", "ottoman",
)  # fmt: skip
# Plausible masses (kg) at the default size.
MASS = {
    "fireplace": (60, 400), "rocking_chair": (6, 20), "crib": (15, 40),
    "changing_table": (15, 50), "toy_box": (5, 25), "ottoman": (3, 15), "bench": (5, 25),
    "sideboard": (30, 90), "console_table": (8, 30), "coat_rack": (3, 12),
    "shoe_rack": (2, 12), "kitchen_island": (80, 250), "wine_rack": (6, 30),
    "washing_machine": (55, 90), "dryer": (30, 55), "ironing_board": (4, 10),
    "laundry_basket": (0.5, 4), "radiator": (10, 45), "bean_bag": (3, 12),
    "chaise_longue": (20, 60), "vanity_table": (12, 45), "trunk": (8, 35),
    "floor_mirror": (8, 30), "trash_bin": (1.5, 8), "high_chair": (4, 12),
    "dishwasher": (30, 60), "tall_cabinet": (35, 100), "bar_counter": (80, 300),
    "bar_table": (10, 40), "pet_bed": (1, 5), "grandfather_clock": (35, 100),
    "umbrella_stand": (1, 6), "plant_stand": (2, 8), "magazine_rack": (4, 20),
    "display_cabinet": (35, 100), "folding_screen": (6, 25), "curtains": (2, 12),
    "blinds": (1.5, 8), "wall_clock": (0.5, 3), "wall_sconce": (0.5, 3),
    "towel_rail": (3, 12), "coat_hooks": (0.4, 3), "range_hood": (8, 25),
    "tapestry": (1, 6), "bulletin_board": (1.5, 6), "pendant_light": (0.8, 4),
    "chandelier": (5, 25), "ceiling_fan": (4, 12), "ceiling_light": (0.5, 3),
    "paper_lantern": (0.1, 1), "hanging_plant": (1, 6),
}  # fmt: skip
KNOWLEDGE = Path(__file__).resolve().parents[2] / "holomj" / "data" / "knowledge" / "objects.json"
_CACHE: dict[tuple[str, tuple | None, int], AssetMeta] = {}


def meta(name: str, size=None, seed: int = 0) -> AssetMeta:
    key = (name, size, seed)
    if key not in _CACHE:
        _CACHE[key] = generate_asset(name, f"{name}_{seed}", size, seed).meta
    return _CACHE[key]


def _knowledge() -> dict[str, dict]:
    objects = json.loads(KNOWLEDGE.read_text())["objects"]
    return {v.get("category", k.replace(" ", "_")): v for k, v in objects.items()}


def _box(part) -> tuple[np.ndarray, np.ndarray]:
    """Axis-aligned bounds of a collision part (boxes, hulls -- their size is their bounding
    box's half extents -- and cylinders along x, y or z)."""
    pos, size = np.asarray(part.pos), part.size
    if part.kind in ("box", "mesh"):
        half = np.asarray(size)
    elif part.kind == "sphere":
        half = np.full(3, size[0])
    else:
        radius, length = size
        q = tuple(round(v, 4) for v in part.quat)
        axis = {(1.0, 0.0, 0.0, 0.0): 2, (0.7071, 0.0, 0.7071, 0.0): 0}.get(q, 1)
        half = np.full(3, radius)
        half[axis] = length
    return pos - half, pos + half


def _occupied(m: AssetMeta, point) -> bool:
    p = np.asarray(point)
    return any(
        np.all(lo - 1e-9 <= p) and np.all(p <= hi + 1e-9) for lo, hi in map(_box, m.collision)
    )


def test_every_home_category_is_registered_like_the_knowledge_base() -> None:
    known = _knowledge()
    assert len(HOME) == 51 and len(set(HOME)) == 51
    for name in HOME:
        info = CATEGORIES[name]
        assert info.builder.__module__.startswith("asset_pipeline.procedural.home_"), name
        expected = {"wall": ("wall",), "ceiling": ("ceiling",)}.get(
            known[name]["placement"], ("floor",)
        )
        assert info.placement == expected, name
        # objects.json holds sizes in the asset axes (x = depth, y = width, z = height)
        np.testing.assert_allclose(info.default_size, known[name]["size"], err_msg=name)
        for key in ("small", "large"):
            if key in known[name]:
                info.check_size(tuple(known[name][key]))  # raises if outside the range
        assert len(info.variants) >= 3 and info.variants[0] is None, name
        assert len({v for v in info.variants if v is not None}) == len(info.variants) - 1
    for name in WALL:
        assert CATEGORIES[name].placement == ("wall",)
    for name in CEILING:
        assert CATEGORIES[name].placement == ("ceiling",) and CATEGORIES[name].round


@pytest.mark.parametrize("name", HOME)
def test_variants_build_to_their_size_with_filled_descriptions(name: str) -> None:
    info = CATEGORIES[name]
    descriptions = set()
    for seed, size in enumerate(info.variants):
        m = meta(name, size, seed)
        np.testing.assert_allclose(m.size, size or info.default_size, atol=MM)
        assert m.collision and m.visual and "{" not in m.description
        descriptions.add(m.description)
    for seed in range(3, 8):
        descriptions.add(meta(name, None, seed).description)
    assert len(descriptions) >= 3, f"{name}: styles do not vary: {descriptions}"


@pytest.mark.parametrize("name", HOME)
def test_mass_is_plausible(name: str) -> None:
    low, high = MASS[name]
    info = CATEGORIES[name]
    assert low <= info.mass_for(info.default_size) <= high
    assert 0.5 <= info.friction <= 1.0


@pytest.mark.parametrize("name", RECEPTACLES)
def test_receptacles_have_a_top_surface(name: str) -> None:
    for seed in range(4):
        m = meta(name, None, seed)
        assert m.surfaces, (name, seed)
        top = max(s.height for s in m.surfaces)
        if name not in ("fireplace", "crib"):
            assert top >= 0.8 * m.size[2], (name, seed, top)


def test_worktops_and_bar_counter_levels() -> None:
    for seed in range(4):
        island = meta("kitchen_island", None, seed)
        assert max(s.height for s in island.surfaces) == pytest.approx(island.size[2], abs=MM)
        assert max(s.area_m2 for s in island.surfaces) > 1.0
        bar = meta("bar_counter", None, seed)
        heights = sorted({round(s.height, 3) for s in bar.surfaces})
        assert heights[-1] == pytest.approx(bar.size[2], abs=MM)
        assert 0.8 <= heights[0] <= heights[-1] - 0.1, heights  # the work counter behind


def test_fireplace_firebox_is_an_open_mantel_topped_opening() -> None:
    for seed in range(6):
        m = meta("fireplace", None, seed)
        d, w, h = m.size
        z = 0.3 * h
        xs = np.linspace(-0.5 * d + 0.002, 0.5 * d - 0.002, 400)
        free = [not _occupied(m, (x, 0.0, z)) for x in xs]
        assert not free[0], "no back wall behind the firebox"
        assert free[-1], "the front of the firebox is closed"
        run = 0
        for f in reversed(free):
            if not f:
                break
            run += 1
        assert run * (xs[1] - xs[0]) >= 0.4 * d, "the firebox is too shallow"
        assert _occupied(m, (-0.5 * d + 0.01, 0.5 * w - 0.01, z)), "no jamb beside the firebox"
        heights = sorted(s.height for s in m.surfaces)
        assert heights[-1] == pytest.approx(h, abs=MM), "no mantel shelf"
        assert heights[0] < 0.1, "no hearth in front"


def test_curtains_are_thin_pleated_panels_on_a_rod() -> None:
    for seed in range(6):
        m = meta("curtains", None, seed)
        d, _w, h = m.size
        assert d <= 0.12
        cylinders = [c for c in m.collision if c.kind == "cylinder"]
        assert len(cylinders) == 1 and cylinders[0].pos[2] > h - 0.03, "no rod at the top"
        panels = [c for c in m.collision if c.kind == "box" and 2 * c.size[2] > 0.8 * h]
        # The pleats' own colliders cover them (the collider audit): a few centimetres deep.
        assert panels and all(2 * c.size[0] <= 0.04 for c in panels), "panels are not thin"
        assert all(abs(c.pos[2] - c.size[2]) < MM for c in panels), "panels do not reach the floor"


def test_rocking_chair_rockers_rest_flat_and_curve_up() -> None:
    for seed in range(6):
        m = meta("rocking_chair", None, seed)
        d = m.size[0]
        bottoms = [_box(c) for c in m.collision]
        flat = [(lo, hi) for lo, hi in bottoms if abs(lo[2]) < MM]
        assert len(flat) == 2, "two rockers stand on the floor"
        assert all(hi[0] - lo[0] >= 0.4 * d for lo, hi in flat)
        lifted = [lo for lo, hi in bottoms if hi[0] >= 0.5 * d - MM]
        assert lifted and min(lo[2] for lo in lifted) > 0.02, "rocker ends do not curve up"


def test_crib_has_slatted_sides_and_a_mattress() -> None:
    m = meta("crib")
    slats = [c for c in m.collision if c.kind == "box" and c.size[0] < 0.02 and c.size[1] < 0.02]
    assert len(slats) >= 20
    assert m.surfaces and 0.3 < m.surfaces[0].height < 0.5 * m.size[2]


def test_laundry_machines_have_a_round_door_on_the_front() -> None:
    for name in ("washing_machine", "dryer"):
        m = meta(name)
        doors = [
            c for c in m.collision
            if c.kind == "cylinder" and abs(c.quat[2] - 0.7071) < 1e-3 and c.size[0] > 0.15
        ]  # fmt: skip
        assert doors and doors[0].pos[0] > 0.2 * m.size[0], name


@pytest.mark.parametrize("name", CEILING)
def test_ceiling_pieces_hang_from_their_top_and_have_a_flat_bottom(name: str) -> None:
    for seed in range(3):
        m = meta(name, None, seed)
        h = m.size[2]
        assert _occupied(m, (0.0, 0.0, h - 0.004)), "nothing reaches the ceiling at the centre"
        assert _occupied(m, (0.0, 0.0, 0.85 * h)), "no cord, chain or rod below the top"
        assert any(_box(c)[0][2] < 0.01 and c.kind != "sphere" for c in m.collision)


@pytest.mark.parametrize("name", WALL)
def test_wall_pieces_are_shallow(name: str) -> None:
    info = CATEGORIES[name]
    d, w, _h = info.default_size
    assert d <= max(0.5, 0.6 * w) and info.size_max[0] <= 0.65
    m = meta(name)
    assert min(_box(c)[0][0] for c in m.collision) == pytest.approx(-0.5 * d, abs=0.01)
