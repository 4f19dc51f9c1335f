"""The small-item categories of ``asset_pipeline.procedural.small_*`` (issue 15).

Checks that every category exists under its knowledge-base name and size, builds at the
default, variant and random in-range sizes with the requested bounding box, has a plausible
mass, varies its style with the seed, and stands stably: the centre of mass lies well inside
the convex hull of the colliders touching the table, and a dropped item comes to rest upright.
"""

from __future__ import annotations

import json
import math
import zlib
from pathlib import Path

import mujoco
import numpy as np
import pytest
from scipy.spatial import ConvexHull

from asset_pipeline.procedural import CATEGORIES, generate_asset
from asset_pipeline.procedural.assembly import centred_parts
from asset_pipeline.procedural.catalog import design_for

KNOWLEDGE = Path(__file__).parents[2] / "holomj" / "data" / "knowledge" / "objects.json"

# Plausible mass (kg) at the default size, per category.
MASS_RANGES: dict[str, tuple[float, float]] = {
    "microscope": (3.0, 9.0), "cash_register": (4.0, 15.0), "printer": (4.0, 15.0),
    "monitor": (2.5, 8.0), "microwave": (9.0, 18.0), "toaster": (1.0, 3.0),
    "kettle": (0.7, 1.6), "coffee_machine": (4.0, 14.0), "blender": (1.5, 5.0),
    "desktop_computer": (5.0, 15.0), "computer_keyboard": (0.4, 1.3),
    "computer_mouse": (0.05, 0.2), "phone": (0.12, 0.3), "desk_phone": (0.5, 1.5),
    "tablet": (0.3, 0.8), "radio": (0.5, 3.0), "globe": (0.8, 3.0),
    "picture_frame": (0.2, 1.2), "alarm_clock": (0.15, 0.6), "toolbox": (2.0, 9.0),
    "basket": (0.3, 1.5), "tray": (0.3, 1.5), "teapot": (0.5, 1.5), "headphones": (0.3, 1.0),
    "trophy": (0.4, 3.0), "jewelry_box": (0.3, 1.5), "tissue_box": (0.1, 0.4),
    "board_game": (0.5, 2.0), "chess_set": (1.0, 3.0), "cutting_board": (0.5, 2.5),
    "knife_block": (1.2, 3.5), "dumbbell": (2.0, 10.0), "kettlebell": (8.0, 16.0),
    "soap_dispenser": (0.2, 0.7), "towel": (0.2, 0.9), "toy_car": (0.05, 0.3),
    "teddy_bear": (0.2, 0.8), "bread": (0.3, 0.9), "cake": (0.8, 2.5),
    "storage_jar": (0.4, 1.5), "pen_holder": (0.15, 0.5), "stapler": (0.15, 0.6),
    "binder": (0.3, 1.2), "paper_stack": (1.5, 3.5), "record_player": (3.0, 9.0),
    "game_console": (1.5, 5.0), "watering_can": (0.5, 2.0), "salt_shaker": (0.05, 0.2),
    "spice_rack": (1.0, 3.5), "beaker": (0.05, 0.3), "test_tube_rack": (0.2, 0.8),
    "paint_can": (2.5, 5.5), "power_drill": (1.0, 2.5), "sewing_machine": (5.0, 12.0),
    "stand_mixer": (6.0, 13.0), "dish_rack": (0.7, 2.5), "hair_dryer": (0.3, 1.0),
    "shoe": (0.25, 1.0), "handbag": (0.4, 1.5), "backpack": (0.5, 2.5),
}  # fmt: skip
NAMES = sorted(MASS_RANGES)
SEEDS = (0, 1, 2)
MIN_TIP_DEG = 4.5  # the centre of mass must be this far (as an angle) inside the base
MIN_BASE_FRACTION = 0.1  # base hull area / bounding-box footprint


def _cases(name: str) -> list[tuple[tuple[float, float, float] | None, int]]:
    info = CATEGORIES[name]
    cases: list[tuple[tuple[float, float, float] | None, int]] = [
        (size, seed) for seed, size in enumerate(info.variants)
    ]
    for seed in SEEDS:
        rng = np.random.default_rng([seed, zlib.crc32(name.encode()), 11])
        cases.append((info.sample_size(rng), seed + 10))
    return cases


def test_at_least_45_small_items_with_knowledge_base_names_and_sizes() -> None:
    objects = json.loads(KNOWLEDGE.read_text())["objects"]
    kinds = {v["category"]: v for v in objects.values() if v["placement"] == "object"}
    mine = {
        n
        for n, i in CATEGORIES.items()
        if i.builder.__module__.startswith("asset_pipeline.procedural.small_")
    }
    assert mine == set(NAMES)
    assert len(mine) >= 45
    small = [n for n, i in CATEGORIES.items() if i.kind == "object"]
    assert len(small) >= 60
    for name in NAMES:
        info = CATEGORIES[name]
        assert info.kind == "object" and "object" in info.placement, name
        assert name in kinds, f"{name} is not a small-object kind of the knowledge base"
        width, depth, height = kinds[name]["size"]
        np.testing.assert_allclose(info.default_size, (depth, width, height), atol=1e-9)
        assert all(lo < v < hi for lo, v, hi in zip(info.size_min, info.default_size,
                                                    info.size_max, strict=True)), name  # fmt: skip
        assert len(info.variants) == 2 and info.variants[0] is None, name
        assert 0.5 <= info.friction <= 1.0


@pytest.mark.parametrize("name", NAMES)
def test_mass_is_plausible(name: str) -> None:
    info = CATEGORIES[name]
    low, high = MASS_RANGES[name]
    assert low <= info.mass_for(info.default_size) <= high
    # A typical item of the category: the brief's reference masses.
    reference = {"kettle": 1.0, "microwave": 12.0, "dumbbell": 5.0, "phone": 0.2}
    if name in reference:
        assert info.mass_kg == pytest.approx(reference[name], rel=0.25)


@pytest.mark.parametrize("name", NAMES)
def test_builds_with_the_requested_size_and_words(name: str) -> None:
    info = CATEGORIES[name]
    for size, seed in _cases(name):
        meta = generate_asset(name, f"{name}_t", size, seed).meta
        expected = size or info.default_size
        np.testing.assert_allclose(meta.size, expected, atol=1e-3)
        assert meta.mass_kg == info.mass_for(expected)
        assert "{" not in meta.description and meta.description.startswith(("a ", "an "))
        assert meta.collision and meta.visual


@pytest.mark.parametrize("name", NAMES)
def test_seeds_vary_the_style(name: str) -> None:
    bundles = [generate_asset(name, "s", None, seed) for seed in range(8)]
    looks = {tuple(v.rgba for v in b.meta.visual) for b in bundles}
    assert len(looks) >= 2, f"{name}: every seed looks the same"
    words = {b.meta.description for b in bundles}
    assert len(words) >= 2, f"{name}: the description never changes"


def _base_and_com(name: str, size, seed: int) -> tuple[float, float, float]:
    """(tipping angle in degrees, base hull area / bbox footprint, COM height)."""
    design, resolved = design_for(name, "x", size, seed)
    colliders = [c for part in centred_parts(design.parts) for c in part.colliders()]
    volume = np.array([c.volume for c in colliders])
    com = (volume[:, None] * np.array([c.pos for c in colliders])).sum(0) / volume.sum()
    floor = min(c.pos[2] - c.half_extents()[2] for c in colliders)
    points: list[tuple[float, float]] = []
    for c in colliders:
        if c.pos[2] - c.half_extents()[2] > floor + 1e-3:
            continue
        x, y, _ = c.pos
        if c.kind == "box":
            hx, hy, _ = c.size
            points += [(x + sx * hx, y + sy * hy) for sx in (-1, 1) for sy in (-1, 1)]
        elif c.kind == "cylinder" and c.axis == "z":
            r = c.size[0]
            angles = np.linspace(0.0, 2.0 * math.pi, 16, endpoint=False)
            points += [(x + r * math.cos(a), y + r * math.sin(a)) for a in angles]
        elif c.kind == "cylinder":  # lying: it touches along a line
            half = c.size[1]
            along = (half, 0.0) if c.axis == "x" else (0.0, half)
            points += [(x - along[0], y - along[1]), (x + along[0], y + along[1])]
        elif c.kind == "mesh":  # a hull stands on its lowest vertices
            hull = np.asarray(c.vertices) + np.asarray(c.pos)
            points += [(px, py) for px, py, pz in hull if pz <= floor + 1e-3]
        else:
            points.append((x, y))
    hull = ConvexHull(np.array(points))
    margin = -float((hull.equations[:, :2] @ com[:2] + hull.equations[:, 2]).max())
    tip = math.degrees(math.atan2(margin, com[2] - floor))
    return tip, hull.volume / (resolved[0] * resolved[1]), float(com[2])


@pytest.mark.parametrize("name", NAMES)
def test_base_is_wide_enough_to_stand(name: str) -> None:
    for size, seed in _cases(name):
        tip, fraction, _ = _base_and_com(name, size, seed)
        assert tip >= MIN_TIP_DEG, f"{name} {size}: tips over at {tip:.1f} deg"
        assert fraction >= MIN_BASE_FRACTION, f"{name} {size}: base is {fraction:.2f} of bbox"


def _drop_model(name: str, size, seed: int, lift: float) -> mujoco.MjModel:
    bundle = generate_asset(name, "d", size, seed)
    meta = bundle.meta
    spec = mujoco.MjSpec()
    spec.assets = {p.mesh: bundle.files[p.mesh] for p in meta.collision if p.kind == "mesh"}
    spec.option.timestep = 0.002
    spec.option.integrator = mujoco.mjtIntegrator.mjINT_IMPLICITFAST
    spec.option.cone = mujoco.mjtCone.mjCONE_ELLIPTIC
    spec.worldbody.add_geom(type=mujoco.mjtGeom.mjGEOM_PLANE, size=[2.0, 2.0, 0.1])
    body = spec.worldbody.add_body(name="item", pos=[0.0, 0.0, lift])
    body.add_freejoint()
    kinds = {
        "box": mujoco.mjtGeom.mjGEOM_BOX,
        "cylinder": mujoco.mjtGeom.mjGEOM_CYLINDER,
        "sphere": mujoco.mjtGeom.mjGEOM_SPHERE,
        "mesh": mujoco.mjtGeom.mjGEOM_MESH,
    }
    for k, part in enumerate(meta.collision):
        if part.kind == "mesh":  # a convex hull: its file, capped as the library caps it
            spec.add_mesh(name=f"hull_{k}", file=part.mesh, maxhullvert=meta.maxhullvert)
        body.add_geom(
            type=kinds[part.kind],
            meshname=f"hull_{k}" if part.kind == "mesh" else "",
            size=[*part.size, 0.0, 0.0, 0.0][:3],
            pos=list(part.pos),
            quat=list(part.quat),
            density=meta.density_kg_m3,
            friction=[meta.friction, 0.005, 0.0001],
        )
    return spec.compile()


@pytest.mark.parametrize("name", NAMES)
def test_dropped_item_lands_upright(name: str) -> None:
    """Dropped from 2 cm onto a table, the item settles upright where it fell."""
    model = _drop_model(name, None, 0, lift=0.02)
    data = mujoco.MjData(model)
    mujoco.mj_step(model, data, nstep=round(1.5 / model.opt.timestep))
    quat = data.qpos[3:7]
    tilt = math.degrees(2.0 * math.acos(min(1.0, abs(float(quat[0])))))
    assert tilt < 2.0, f"{name} tilted {tilt:.1f} deg"
    assert float(np.linalg.norm(data.qpos[:2])) < 0.01
    assert abs(float(data.qpos[2])) < 2e-3, f"{name} did not come to rest on the table"
    assert float(np.linalg.norm(data.qvel)) < 0.05, f"{name} is still moving"


def test_tray_is_a_receptacle() -> None:
    meta = generate_asset("tray", "t").meta
    assert meta.surfaces and meta.surfaces[0].height < 0.5 * meta.size[2]
    assert meta.surfaces[0].area_m2 > 0.5 * meta.size[0] * meta.size[1] * 0.5
