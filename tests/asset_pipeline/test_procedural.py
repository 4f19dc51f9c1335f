"""The procedural generators and the default library: API, geometry, metadata and physics.

Every check runs on the default library's assets and on each category generated with three
seeds at random in-range sizes.
"""

from __future__ import annotations

import io
import itertools
import math
import re
import zlib
from pathlib import Path

import mujoco
import numpy as np
import pytest
import trimesh
from scipy.spatial import ConvexHull as scipy_hull
from shapely.geometry import Point, Polygon

from asset_pipeline.library_writer import AssetBundle
from asset_pipeline.procedural import (
    CATEGORIES,
    DEFAULT_LIBRARY_NAME,
    DEFAULT_LIBRARY_VERSION,
    build_default_library,
    default_assets,
    default_variants,
    generate_asset,
)
from asset_pipeline.procedural.assembly import AssetDesign, assemble, centred_parts
from asset_pipeline.procedural.catalog import design_for
from asset_pipeline.procedural.kit import LINEN, block
from asset_pipeline.procedural.parts import Box, Collider, Mesh
from asset_pipeline.procedural.round_parts import Cylinder, Lathe, Sphere, lathe_mesh
from holomj.errors import InputError
from holomj.spec.assets import AssetMeta

MM = 1e-3
SEEDS = (0, 1, 2)
ID_PATTERN = re.compile(r"^[A-Za-z0-9_][A-Za-z0-9_.:|+\-]*$")

FURNITURE = {
    "bed", "bunk_bed", "sofa", "armchair", "coffee_table", "dining_table", "desk",
    "office_chair", "dining_chair", "stool", "wardrobe", "dresser", "nightstand", "bookshelf",
    "tv_stand", "television", "kitchen_counter", "base_cabinet", "wall_cabinet", "fridge",
    "stove", "sink_counter", "washbasin", "toilet", "bathtub", "shower_tray", "floor_lamp",
    "potted_plant", "rug",
}  # fmt: skip
SMALL = {
    "book", "cardboard_box", "mug", "bowl", "plate", "bottle", "vase", "laptop", "desk_lamp",
    "apple", "orange", "toy_block", "toy_ball", "cup", "remote", "pot", "pan", "candle",
}  # fmt: skip
# Plausible masses (kg) at the default size.
MASS_RANGES = {
    "mug": (0.2, 0.45), "book": (0.3, 0.8), "dining_chair": (3.0, 8.0), "sofa": (35.0, 65.0),
    "fridge": (55.0, 90.0), "bathtub": (35.0, 70.0), "rug": (3.0, 8.0), "bed": (40.0, 90.0),
    "apple": (0.12, 0.25), "plate": (0.3, 0.6), "wardrobe": (50.0, 120.0), "laptop": (1.0, 2.5),
}  # fmt: skip


def _random_size(name: str, seed: int) -> tuple[float, float, float]:
    rng = np.random.default_rng([seed, zlib.crc32(name.encode()), 7])
    return CATEGORIES[name].sample_size(rng)


DEFAULT = {asset_id: (name, size, seed) for asset_id, name, size, seed in default_variants()}
RANDOM = {
    f"{name}-seed{seed}": (name, _random_size(name, seed), seed)
    for name in CATEGORIES
    for seed in SEEDS
}
ALL_CASES = {**DEFAULT, **RANDOM}
_BUNDLES: dict[str, AssetBundle] = {}


def bundle(case: str) -> AssetBundle:
    if case not in _BUNDLES:
        name, size, seed = ALL_CASES[case]
        _BUNDLES[case] = generate_asset(name, case.replace("-", "_"), size, seed)
    return _BUNDLES[case]


def _files(root: Path) -> dict[str, bytes]:
    return {p.relative_to(root).as_posix(): p.read_bytes() for p in root.rglob("*") if p.is_file()}


# --- registry and API --------------------------------------------------------------------
def test_categories_cover_the_brief() -> None:
    furniture = {n for n, i in CATEGORIES.items() if i.kind == "furniture"}
    small = {n for n, i in CATEGORIES.items() if i.kind == "object"}
    assert furniture >= FURNITURE and len(furniture) >= 27, sorted(FURNITURE - furniture)
    assert small >= SMALL and len(small) >= 15, sorted(SMALL - small)
    assert CATEGORIES["wall_cabinet"].placement == ("wall",)
    assert CATEGORIES["rug"].placement == ("floor",) and CATEGORIES["rug"].size_min[2] >= 0.008
    for name, info in CATEGORIES.items():
        assert name == name.lower() and info.description
        assert all(
            lo <= d <= hi for lo, d, hi in zip(info.size_min, info.default_size, info.size_max)
        )
        expected = 2 if info.kind == "furniture" else 1
        assert len(info.variants) >= min(expected, 1) and len(info.variants) <= 3


def test_default_variants() -> None:
    ids = [asset_id for asset_id, *_ in default_variants()]
    assert len(ids) == len(set(ids)) >= 90
    assert all(ID_PATTERN.match(i) for i in ids)
    assert {"bed_000", "bed_001", "mug_000"} <= set(ids)
    per_category = {n: sum(1 for _, c, *_ in default_variants() if c == n) for n in CATEGORIES}
    assert sum(1 for n, k in per_category.items() if k >= 2) >= 27


def test_build_is_deterministic_and_valid(tmp_path: Path) -> None:
    # the build time is measured by scripts/bench_synthesis.py, not here
    first_root = build_default_library(tmp_path / "a")
    second = _files(build_default_library(tmp_path / "b"))
    first = _files(first_root)
    assert first == second
    # Size on disk: the shared texture images are hard links to one blob each, counted once.
    stats = [p.stat() for p in first_root.rglob("*") if p.is_file()]
    inodes = {(st.st_dev, st.st_ino): st.st_size for st in stats}
    assert sum(inodes.values()) < 16 * 1024 * 1024
    textures = list(first_root.glob("*/texture_*.png"))
    assert textures and all(p.stat().st_nlink > 1 for p in textures)
    assert len({p.stat().st_ino for p in textures}) == len(list((first_root / ".blobs").iterdir()))
    index = first["library.json"].decode()
    assert DEFAULT_LIBRARY_NAME in index and DEFAULT_LIBRARY_VERSION in DEFAULT_LIBRARY_NAME
    assert re.fullmatch(r"[0-9a-f]{12}", DEFAULT_LIBRARY_VERSION)
    from holomj.library.store import AssetLibrary

    lib = AssetLibrary.open(first_root)
    assert {a for a, *_ in default_variants()} <= set(lib.ids())
    with pytest.raises(InputError):
        build_default_library(first_root, overwrite=False)


def test_generate_asset_is_deterministic_per_seed() -> None:
    a = generate_asset("sofa", "s", (0.9, 2.2, 0.85), seed=5)
    b = generate_asset("sofa", "s", (0.9, 2.2, 0.85), seed=5)
    assert a.files == b.files and a.meta == b.meta
    styles = {generate_asset("sofa", "s", None, seed).meta.description for seed in range(8)}
    assert len(styles) >= 3, "seeds do not vary the style"


@pytest.mark.parametrize(
    ("category", "size", "needle"),
    [
        ("bed", (0.5, 1.6, 1.0), "x = 0.5 m not in [1.8, 2.4]"),
        ("mug", (0.08, 0.3, 0.1), "y = 0.3 m not in"),
        ("plate", (0.26, 0.2, 0.02), "round"),
        ("mug", (0.1, 0.1, 0.1), "y / x"),
        ("rug", (2.0, 2.0, 0.004), "z = 0.004 m"),
        ("bottle", (0.05, 0.05, float("nan")), "finite"),
        ("bottle", "big", "three finite numbers"),
    ],
)
def test_sizes_out_of_range_are_rejected(category: str, size, needle: str) -> None:
    with pytest.raises(InputError) as info:
        generate_asset(category, "x", size)
    message = str(info.value)
    assert needle in message and repr(category) in message
    assert info.value.exit_code == 2


def test_generators_take_none_for_the_default_size() -> None:
    from asset_pipeline.procedural import furniture, objects

    rng = np.random.default_rng(0)
    assert furniture.bed(None, rng).parts and objects.mug((0.09, 0.12, 0.1), rng).parts
    with pytest.raises(InputError, match="'mug'"):
        objects.mug((0.3, 0.3, 0.3), rng)
    for info in CATEGORIES.values():
        assert info.generate(None, np.random.default_rng(1)).parts
    assert generate_asset("Bunk Bed", "b").meta.category == "bunk_bed"


def test_unknown_category_and_bad_seed_are_rejected() -> None:
    with pytest.raises(InputError, match="did you mean: sofa"):
        generate_asset("sofaa", "x")
    with pytest.raises(InputError, match="seed"):
        generate_asset("sofa", "x", seed=-1)


def test_mass_is_realistic_and_scales_with_volume() -> None:
    for name, (low, high) in MASS_RANGES.items():
        mass = CATEGORIES[name].mass_for(CATEGORIES[name].default_size)
        assert low <= mass <= high, (name, mass)
    info = CATEGORIES["dresser"]
    small, big = (0.4, 0.8, 0.8), (0.5, 1.6, 1.0)
    ratio = info.mass_for(big) / info.mass_for(small)
    assert ratio == pytest.approx(math.prod(big) / math.prod(small), rel=1e-3)
    meta = generate_asset("dresser", "d", big).meta
    assert meta.mass_kg == info.mass_for(big)
    assert meta.density_kg_m3 == pytest.approx(meta.mass_kg / meta.collision_volume_m3, rel=1e-3)


def test_surfaces_need_free_space_above() -> None:
    parts = (
        block((-0.5, 0.5), (-0.5, 0.5), (0.0, 0.5), LINEN, surface=True),
        block((-0.1, 0.1), (-0.1, 0.1), (0.5, 0.53), LINEN),
    )
    design = AssetDesign("bad", "table", "", 1.0, 0.5, ("floor",), parts)
    with pytest.raises(ValueError, match=r"within 0\.05 m above"):
        assemble(design)


# --- parts ---------------------------------------------------------------------------------
@pytest.mark.parametrize(
    "part",
    [
        Box((0.0, 0.0, 0.5), (0.2, 0.3, 0.5), None),  # type: ignore[arg-type]
        Cylinder((0.0, 0.0, 0.0), 0.1, 0.3, None, axis="x"),  # type: ignore[arg-type]
        Cylinder((0.0, 0.0, 0.0), 0.1, 0.3, None, axis="y"),  # type: ignore[arg-type]
        Lathe((0.0, 0.0, 0.0), ((0.04, 0.0), (0.05, 0.1)), None, hollow=(0.005, 0.01)),  # type: ignore[arg-type]
        Sphere((0.0, 0.0, 0.04), 0.05, None, cut=0.0),  # type: ignore[arg-type]
    ],
    ids=["box", "cylinder_x", "cylinder_y", "hollow_lathe", "cut_sphere"],
)
def test_part_meshes_are_closed_and_outward(part) -> None:
    mesh = part.mesh()
    tm = trimesh.Trimesh(mesh.vertices, mesh.faces, process=True)
    assert tm.is_watertight and tm.is_winding_consistent
    assert tm.volume > 0.0, "triangles face inward"
    low, high = part.bounds()
    np.testing.assert_allclose(tm.bounds, [low, high], atol=1e-9)


def test_lathe_rejects_two_axis_points_in_a_row() -> None:
    with pytest.raises(ValueError):
        lathe_mesh([(0.0, 0.0), (0.0, 1.0), (1.0, 1.0)])


def _convex_pieces(part) -> list[Mesh]:
    """The part's visual solid as convex meshes (a lathe is split into its frustums)."""
    if isinstance(part, Lathe):
        segments = itertools.pairwise(part.outer)
        return [
            lathe_mesh([(0.0, z0), (r0, z0), (r1, z1), (0.0, z1)]).translated(part.base)
            for (r0, z0), (r1, z1) in segments
            if z1 > z0
        ]
    mesh = part.mesh()
    return [] if mesh is None else [mesh]


def _planes(mesh: Mesh) -> tuple[np.ndarray, np.ndarray]:
    """A point and the outward unit normal of every face of a convex outward mesh."""
    tri = mesh.vertices[mesh.faces]
    normals = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    lengths = np.linalg.norm(normals, axis=1)
    keep = lengths > 1e-15
    return tri[keep, 0], normals[keep] / lengths[keep, None]


def _depth_inside(planes: tuple[np.ndarray, np.ndarray], points: np.ndarray) -> np.ndarray:
    """Signed depth of points inside a convex outward mesh (negative outside)."""
    origins, normals = planes
    offsets = points[:, None, :] - origins[None, :, :]
    return -np.einsum("pfk,fk->pf", offsets, normals).max(axis=1)


def _collider_samples(collider: Collider) -> np.ndarray:
    """Points on the collider's boundary: corners, edge and face centres, rims (a hull: its
    vertices and the points halfway to its centre)."""
    pos = np.asarray(collider.pos)
    if collider.kind == "mesh":
        vertices = np.asarray(collider.vertices)
        return pos + np.concatenate([vertices, 0.5 * (vertices + vertices.mean(axis=0))])
    if collider.kind == "box":
        grid = np.stack(np.meshgrid([-1, 0, 1], [-1, 0, 1], [-1, 0, 1]), -1).reshape(-1, 3)
        return pos + grid * np.asarray(collider.size)
    if collider.kind == "sphere":
        return pos + collider.size[0] * trimesh.creation.icosphere(subdivisions=1).vertices
    radius, half = collider.size
    angles = np.linspace(0.0, 2.0 * np.pi, 48, endpoint=False)
    rims = [
        np.stack([radius * np.cos(angles), radius * np.sin(angles), np.full(48, z)], axis=1)
        for z in (-half, 0.0, half)
    ]
    local = np.concatenate(rims)
    rotated = np.array([_rotate(collider.quat, p) for p in local])
    return pos + rotated


@pytest.mark.parametrize("case", sorted(ALL_CASES))
def test_colliders_lie_inside_the_visual_parts(case: str) -> None:
    name, size, seed = ALL_CASES[case]
    design, _ = design_for(name, "x", size, seed)
    parts = centred_parts(design.parts)
    pieces = [_planes(m) for part in parts for m in _convex_pieces(part)]
    for part in parts:
        for collider in part.colliders():
            points = _collider_samples(collider)
            depth = np.max([_depth_inside(m, points) for m in pieces], axis=0)
            assert depth.min() > -1e-6, f"{collider} sticks out by {-depth.min() * 1000:.2f} mm"


# --- per-asset checks ----------------------------------------------------------------------
def _visual_union(b: AssetBundle) -> trimesh.Trimesh:
    meshes = [
        trimesh.load(io.BytesIO(b.files[v.mesh]), file_type="obj", force="mesh", process=False)
        for v in b.meta.visual
    ]
    return trimesh.util.concatenate(meshes)


def _rotate(quat, vec: np.ndarray) -> np.ndarray:
    out = np.zeros(3)
    mujoco.mju_rotVecQuat(out, vec, np.asarray(quat, dtype=float) / np.linalg.norm(quat))
    return out


def _hull_points(b: AssetBundle, part) -> np.ndarray:
    """A mesh collider's vertices in the asset frame, as its file stores them."""
    text = b.files[part.mesh].decode()
    local = np.array(
        [[float(v) for v in ln.split()[1:4]] for ln in text.splitlines() if ln[:2] == "v "]
    )
    return np.asarray(part.pos) + np.array([_rotate(part.quat, v) for v in local])


def _collider_aabb(b: AssetBundle, part) -> tuple[np.ndarray, np.ndarray]:
    pos = np.asarray(part.pos)
    if part.kind == "mesh":
        points = _hull_points(b, part)
        return points.min(axis=0), points.max(axis=0)
    if part.kind == "box":
        half = np.asarray(part.size)
    elif part.kind == "sphere":
        half = np.full(3, part.size[0])
    else:
        radius, length = part.size
        axis = _rotate(part.quat, np.array([0.0, 0.0, 1.0]))
        half = np.abs(axis) * length + radius * np.sqrt(np.clip(1.0 - axis**2, 0.0, 1.0))
    return pos - half, pos + half


def _top_and_contains(b: AssetBundle, part, x: float, y: float) -> tuple[float, bool]:
    """The collider's top z and whether it covers (x, y) in plan (upright colliders only; a
    hull: its flat top face)."""
    px, py, pz = part.pos
    if part.kind == "mesh":
        points = _hull_points(b, part)
        top = points[:, 2].max()
        face = points[points[:, 2] >= top - 1e-6, :2]
        if len(face) < 3:
            return top, False
        hull = Polygon(face[scipy_hull(face).vertices])
        return top, bool(hull.buffer(1e-6).contains(Point(x, y)))
    if part.kind == "box" and tuple(part.quat) == (1.0, 0.0, 0.0, 0.0):
        hx, hy, hz = part.size
        return pz + hz, abs(x - px) <= hx + 1e-6 and abs(y - py) <= hy + 1e-6
    if part.kind == "cylinder" and tuple(part.quat) == (1.0, 0.0, 0.0, 0.0):
        radius, half = part.size
        return pz + half, math.hypot(x - px, y - py) <= radius + 1e-6
    return math.nan, False


@pytest.mark.parametrize("case", sorted(ALL_CASES))
def test_geometry_and_metadata(case: str) -> None:
    b = bundle(case)
    meta = b.meta
    name, size, _ = ALL_CASES[case]
    AssetMeta.model_validate(meta.model_dump(mode="json"))
    assert ID_PATTERN.match(meta.id)
    assert meta.category == name and meta.description and "{" not in meta.description
    assert meta.source == "holomj procedural" and meta.license == "Apache-2.0"
    assert 0.5 <= meta.friction <= 1.0
    assert meta.mass_kg == CATEGORIES[name].mass_for(size or CATEGORIES[name].default_size)
    low, high = _visual_union(b).bounds
    expected = size or CATEGORIES[name].default_size
    np.testing.assert_allclose(high - low, expected, atol=MM)
    np.testing.assert_allclose(meta.size, expected, atol=MM)
    assert abs(low[2]) <= 1e-6, "mesh bottom is not at z = 0"
    np.testing.assert_allclose(0.5 * (low[:2] + high[:2]), [0.0, 0.0], atol=1e-5)
    for part in meta.collision:
        c_low, c_high = _collider_aabb(b, part)
        assert np.all(c_low >= low - MM) and np.all(c_high <= high + MM), part
    for surface in meta.surfaces:
        assert 0.0 < surface.height <= meta.size[2] + MM
        assert surface.area_m2 > 0.0005
        for x, y in surface.polygon:
            assert abs(x) <= 0.5 * meta.size[0] + MM and abs(y) <= 0.5 * meta.size[1] + MM
            supported = any(
                inside and abs(top - surface.height) <= MM
                for top, inside in (_top_and_contains(b, p, x, y) for p in meta.collision)
            )
            assert supported, f"surface point {(x, y)} at {surface.height} has no collider top"


MUST_HAVE_SURFACES = {
    "bed", "bunk_bed", "sofa", "dining_table", "coffee_table", "side_table", "desk",
    "bookshelf", "kitchen_counter", "base_cabinet", "nightstand", "dresser", "tv_stand",
    "shelving_unit", "sink_counter", "stove", "dining_chair", "stool", "bathtub",
}  # fmt: skip


@pytest.mark.parametrize("name", sorted(MUST_HAVE_SURFACES))
def test_receptacles_have_surfaces(name: str) -> None:
    for seed in SEEDS:
        meta = bundle(f"{name}-seed{seed}").meta
        assert meta.surfaces, (name, seed)


def test_bookshelf_has_every_level() -> None:
    meta = generate_asset("bookshelf", "b", (0.3, 0.8, 2.0), seed=0).meta
    heights = sorted({s.height for s in meta.surfaces})
    assert len(heights) >= 5 and heights[-1] == pytest.approx(2.0, abs=MM)


def _build_model(b: AssetBundle) -> mujoco.MjModel:
    meta = b.meta
    spec = mujoco.MjSpec()
    spec.option.timestep = 0.002
    spec.option.integrator = mujoco.mjtIntegrator.mjINT_IMPLICITFAST
    spec.option.cone = mujoco.mjtCone.mjCONE_ELLIPTIC
    spec.worldbody.add_geom(type=mujoco.mjtGeom.mjGEOM_PLANE, size=[5.0, 5.0, 0.1])
    body = spec.worldbody.add_body(name=meta.id)
    body.add_freejoint()
    spec.assets = {v.mesh: b.files[v.mesh] for v in meta.visual}
    for i, vis in enumerate(meta.visual):
        spec.add_mesh(name=f"visual_{i}", file=vis.mesh)
        body.add_geom(
            type=mujoco.mjtGeom.mjGEOM_MESH,
            meshname=f"visual_{i}",
            contype=0,
            conaffinity=0,
            group=2,
            density=0.0,
            rgba=list(vis.rgba),
        )
    kinds = {
        "box": mujoco.mjtGeom.mjGEOM_BOX,
        "cylinder": mujoco.mjtGeom.mjGEOM_CYLINDER,
        "sphere": mujoco.mjtGeom.mjGEOM_SPHERE,
        "mesh": mujoco.mjtGeom.mjGEOM_MESH,
    }
    for k, part in enumerate(meta.collision):
        mesh = ""
        if part.kind == "mesh":
            spec.assets = {**spec.assets, part.mesh: b.files[part.mesh]}
            mesh = f"hull_{k}"
            spec.add_mesh(name=mesh, file=part.mesh, maxhullvert=meta.maxhullvert)
        body.add_geom(
            type=kinds[part.kind],
            meshname=mesh,
            size=[*part.size, 0.0, 0.0, 0.0][:3],
            pos=list(part.pos),
            quat=list(part.quat),
            density=meta.density_kg_m3,
            friction=[meta.friction, 0.005, 0.0001],
            group=3,
        )
    return spec.compile()


def _rotation_deg(quat: np.ndarray) -> float:
    return math.degrees(2.0 * math.acos(min(1.0, abs(float(quat[0])))))


@pytest.mark.parametrize("case", sorted(ALL_CASES))
def test_asset_rests_on_the_floor(case: str) -> None:
    b = bundle(case)
    model = _build_model(b)
    body_mass = model.body_mass[1]
    assert abs(body_mass - b.meta.mass) <= 0.01 * b.meta.mass, (
        f"model mass {body_mass:.3f} kg, metadata {b.meta.mass} kg"
    )
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    start = data.qpos[:3].copy()
    mujoco.mj_step(model, data, nstep=round(2.0 / model.opt.timestep))
    drift = float(np.linalg.norm(data.qpos[:3] - start))
    rotation = _rotation_deg(data.qpos[3:7])
    warnings = {
        mujoco.mjtWarning(i).name: int(data.warning[i].number)
        for i in range(len(data.warning))
        if data.warning[i].number
    }
    assert not warnings, f"MuJoCo warnings: {warnings}"
    assert drift < 0.01, f"moved {drift * 100:.2f} cm"
    assert rotation < 2.0, f"rotated {rotation:.2f} deg"


def test_obj_files_are_plain_and_fixed_format() -> None:
    b = bundle("mug_000")
    text = b.files[b.meta.visual[0].mesh].decode()
    lines = [ln for ln in text.splitlines() if not ln.startswith("#")]
    assert all(ln.startswith(("v ", "f ")) for ln in lines)
    assert all(len(ln.split()[1].split(".")[1]) == 5 for ln in lines if ln.startswith("v "))
    assert "-0.00000" not in text
    mesh = trimesh.load(io.BytesIO(text.encode()), file_type="obj", force="mesh")
    assert mesh.volume > 0.0


def test_default_assets_match_generate_asset() -> None:
    bundles = {b.meta.id: b for b in default_assets()}
    asset_id, (name, size, seed) = next(iter(DEFAULT.items()))
    again = generate_asset(name, asset_id, size, seed)
    assert bundles[asset_id].files == again.files and bundles[asset_id].meta == again.meta
