"""The procedural default library: committed files, loading, geometry and physics of every asset."""

from __future__ import annotations

import io
import itertools
import math
from functools import cache
from pathlib import Path

import mujoco
import numpy as np
import pytest
import trimesh

from asset_pipeline.procedural import build_default_library, default_assets
from asset_pipeline.procedural.assembly import centred_parts
from asset_pipeline.procedural.catalog import default_designs
from asset_pipeline.procedural.parts import Box, Collider, Mesh
from asset_pipeline.procedural.round_parts import Cylinder, Lathe, Sphere, lathe_mesh
from holomj.library.store import AssetLibrary, LibraryAsset, default_library_path

LIBRARY = default_library_path()
ALL_IDS = sorted(b.meta.id for b in default_assets())
REGENERATE = "run: python scripts/build_default_library.py"
MM = 1e-3


@cache
def library() -> AssetLibrary:
    return AssetLibrary.open()


def _files(root: Path) -> dict[str, bytes]:
    return {p.relative_to(root).as_posix(): p.read_bytes() for p in root.rglob("*") if p.is_file()}


def test_committed_library_matches_the_generator(tmp_path: Path) -> None:
    fresh = build_default_library(tmp_path / "lib")
    expected, committed = _files(fresh), _files(LIBRARY)
    missing = sorted(set(expected) - set(committed))
    extra = sorted(set(committed) - set(expected))
    changed = sorted(k for k in set(expected) & set(committed) if expected[k] != committed[k])
    assert not (missing or extra or changed), (
        f"holomj/data/default_library is stale (missing {missing[:5]}, extra {extra[:5]}, "
        f"changed {changed[:5]}); {REGENERATE}"
    )


def test_generator_is_deterministic(tmp_path: Path) -> None:
    first = _files(build_default_library(tmp_path / "a"))
    second = _files(build_default_library(tmp_path / "b"))
    assert first == second


def test_library_is_small() -> None:
    size = sum(len(data) for data in _files(LIBRARY).values())
    assert size < 2 * 1024 * 1024, f"default library is {size / 1e6:.2f} MB"


def test_default_library_opens() -> None:
    lib = library()
    assert set(ALL_IDS) <= set(lib.ids())
    assert len(ALL_IDS) >= 35
    for category in ("bed", "sofa", "dining_table", "bookshelf", "mug", "apple", "potted_plant"):
        assert lib.by_category(category), category
    for asset_id in ALL_IDS:
        meta = lib.get(asset_id).meta
        assert 0.5 <= meta.friction <= 1.0
        assert meta.source == "holomj procedural" and meta.license == "Apache-2.0"
        assert meta.description and meta.category == meta.category.lower()


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


def _depth_inside(mesh: Mesh, points: np.ndarray) -> np.ndarray:
    """Signed depth of points inside a convex outward mesh (negative outside)."""
    tm = trimesh.Trimesh(mesh.vertices, mesh.faces, process=False)
    offsets = points[:, None, :] - tm.triangles[None, :, 0, :]
    return -np.einsum("pfk,fk->pf", offsets, tm.face_normals).max(axis=1)


def _collider_samples(collider: Collider) -> np.ndarray:
    """Points on the collider's boundary: corners, edge and face centres, rims."""
    pos = np.asarray(collider.pos)
    if collider.kind == "box":
        grid = np.stack(np.meshgrid([-1, 0, 1], [-1, 0, 1], [-1, 0, 1]), -1).reshape(-1, 3)
        return pos + grid * np.asarray(collider.size)
    if collider.kind == "sphere":
        return pos + collider.size[0] * trimesh.creation.icosphere(subdivisions=2).vertices
    radius, half = collider.size
    angles = np.linspace(0.0, 2.0 * np.pi, 96, endpoint=False)
    rims = [
        np.stack([radius * np.cos(angles), radius * np.sin(angles), np.full(96, z)], axis=1)
        for z in (-half, 0.0, half)
    ]
    local = np.concatenate(rims)
    rotated = np.array([_rotate(collider.quat, p) for p in local])
    return pos + rotated


@pytest.mark.parametrize("design", default_designs(), ids=lambda d: d.id)
def test_colliders_lie_inside_the_visual_parts(design) -> None:
    parts = centred_parts(design.parts)
    pieces = [m for part in parts for m in _convex_pieces(part)]
    for part in parts:
        for collider in part.colliders():
            points = _collider_samples(collider)
            depth = np.max([_depth_inside(m, points) for m in pieces], axis=0)
            assert depth.min() > -1e-6, f"{collider} sticks out by {-depth.min() * 1000:.2f} mm"


# --- per-asset checks --------------------------------------------------------------------


def _visual_union(asset: LibraryAsset) -> trimesh.Trimesh:
    meshes = [
        trimesh.load(asset.path(v.mesh), file_type="obj", force="mesh", process=False)
        for v in asset.meta.visual
    ]
    return trimesh.util.concatenate(meshes)


def _collider_aabb(part) -> tuple[np.ndarray, np.ndarray]:
    pos = np.asarray(part.pos)
    if part.kind == "box":
        half = np.asarray(part.size)
    elif part.kind == "sphere":
        half = np.full(3, part.size[0])
    else:
        radius, length = part.size
        axis = _rotate(part.quat, np.array([0.0, 0.0, 1.0]))
        half = np.abs(axis) * length + radius * np.sqrt(np.clip(1.0 - axis**2, 0.0, 1.0))
    return pos - half, pos + half


def _rotate(quat, vec: np.ndarray) -> np.ndarray:
    out = np.zeros(3)
    mujoco.mju_rotVecQuat(out, vec, np.asarray(quat, dtype=float) / np.linalg.norm(quat))
    return out


@pytest.mark.parametrize("asset_id", ALL_IDS)
def test_bbox_matches_visual_meshes(asset_id: str) -> None:
    asset = library().get(asset_id)
    low, high = _visual_union(asset).bounds
    np.testing.assert_allclose(high - low, asset.meta.size, atol=MM)
    assert abs(low[2]) <= MM, "mesh bottom is not at z = 0"
    np.testing.assert_allclose(0.5 * (low[:2] + high[:2]), [0.0, 0.0], atol=MM)
    for part in asset.meta.collision:
        c_low, c_high = _collider_aabb(part)
        assert np.all(c_low >= low - MM) and np.all(c_high <= high + MM), (
            f"collider {part} sticks out of the visual bounding box"
        )


def _top_and_contains(part, x: float, y: float) -> tuple[float, bool]:
    """The collider's top z and whether it covers (x, y) in plan (upright colliders only)."""
    px, py, pz = part.pos
    if part.kind == "box" and tuple(part.quat) == (1.0, 0.0, 0.0, 0.0):
        hx, hy, hz = part.size
        return pz + hz, abs(x - px) <= hx + 1e-6 and abs(y - py) <= hy + 1e-6
    if part.kind == "cylinder" and tuple(part.quat) == (1.0, 0.0, 0.0, 0.0):
        radius, half = part.size
        return pz + half, math.hypot(x - px, y - py) <= radius + 1e-6
    return math.nan, False


@pytest.mark.parametrize("asset_id", ALL_IDS)
def test_surfaces_rest_on_colliders(asset_id: str) -> None:
    meta = library().get(asset_id).meta
    sx, sy, sz = meta.size
    for surface in meta.surfaces:
        assert 0.0 < surface.height <= sz + MM
        for x, y in surface.polygon:
            assert abs(x) <= 0.5 * sx + MM and abs(y) <= 0.5 * sy + MM
            supported = False
            for part in meta.collision:
                top, inside = _top_and_contains(part, x, y)
                supported |= inside and abs(top - surface.height) <= MM
            assert supported, f"surface point {(x, y)} at {surface.height} has no collider top"
        assert surface.area_m2 > 0.005


def test_main_furniture_has_surfaces() -> None:
    for asset_id in ALL_IDS:
        meta = library().get(asset_id).meta
        if meta.category in {"dining_table", "desk", "bed", "bookshelf", "kitchen_counter"}:
            assert meta.surfaces, asset_id
    levels = library().get("bookshelf_01").meta.surfaces
    assert len({s.height for s in levels}) >= 5


def _build_model(asset: LibraryAsset) -> mujoco.MjModel:
    meta = asset.meta
    spec = mujoco.MjSpec()
    spec.option.timestep = 0.002
    spec.option.integrator = mujoco.mjtIntegrator.mjINT_IMPLICITFAST
    spec.option.cone = mujoco.mjtCone.mjCONE_ELLIPTIC
    spec.worldbody.add_geom(type=mujoco.mjtGeom.mjGEOM_PLANE, size=[5.0, 5.0, 0.1])
    body = spec.worldbody.add_body(name=meta.id)
    body.add_freejoint()
    spec.assets = {v.mesh: asset.path(v.mesh).read_bytes() for v in meta.visual}
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
    density = meta.mass / meta.collision_volume_m3
    kinds = {
        "box": mujoco.mjtGeom.mjGEOM_BOX,
        "cylinder": mujoco.mjtGeom.mjGEOM_CYLINDER,
        "sphere": mujoco.mjtGeom.mjGEOM_SPHERE,
    }
    for part in meta.collision:
        size = [*part.size, 0.0, 0.0][:3]
        body.add_geom(
            type=kinds[part.kind],
            size=size,
            pos=list(part.pos),
            quat=list(part.quat),
            density=density,
            friction=[meta.friction, 0.005, 0.0001],
            group=3,
        )
    return spec.compile()


def _rotation_deg(quat: np.ndarray) -> float:
    return math.degrees(2.0 * math.acos(min(1.0, abs(float(quat[0])))))


@pytest.mark.parametrize("asset_id", ALL_IDS)
def test_asset_rests_on_the_floor(asset_id: str) -> None:
    asset = library().get(asset_id)
    model = _build_model(asset)
    body_mass = model.body_mass[1]
    assert abs(body_mass - asset.meta.mass) <= 0.01 * asset.meta.mass, (
        f"model mass {body_mass:.3f} kg, metadata {asset.meta.mass} kg"
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
    asset = library().get("mug_01")
    text = asset.path(asset.meta.visual[0].mesh).read_text()
    lines = [ln for ln in text.splitlines() if not ln.startswith("#")]
    assert all(ln.startswith(("v ", "f ")) for ln in lines)
    assert all(len(ln.split()[1].split(".")[1]) == 5 for ln in lines if ln.startswith("v "))
    assert "-0.00000" not in text
    mesh = trimesh.load(io.BytesIO(text.encode()), file_type="obj", force="mesh")
    assert mesh.volume > 0.0
