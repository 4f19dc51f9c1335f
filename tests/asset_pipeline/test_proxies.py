"""Honest proxies: labelled with the asked category, sized by the plan, physically valid."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

from asset_pipeline.procedural.attributes import COLOURS, Attributes
from asset_pipeline.procedural.proxies import FAMILIES, build_proxy, mass_bounds, proxy_family


def _stands_still(bundle, seconds: float = 1.0) -> tuple[float, float]:
    """Drift (m) and tilt (rad) of the asset's colliders on a floor plane after ``seconds``."""
    meta = bundle.meta
    spec = mujoco.MjSpec()
    spec.assets = {p.mesh: bundle.files[p.mesh] for p in meta.collision if p.kind == "mesh"}
    spec.worldbody.add_geom(type=mujoco.mjtGeom.mjGEOM_PLANE, size=[5, 5, 0.1])
    body = spec.worldbody.add_body(name="proxy", pos=[0, 0, 0.0005])
    body.add_freejoint()
    density = meta.mass / meta.collision_volume_m3
    kinds = {
        "box": mujoco.mjtGeom.mjGEOM_BOX,
        "cylinder": mujoco.mjtGeom.mjGEOM_CYLINDER,
        "sphere": mujoco.mjtGeom.mjGEOM_SPHERE,
        "mesh": mujoco.mjtGeom.mjGEOM_MESH,
    }
    for k, part in enumerate(meta.collision):
        size = list(part.size) + [0.0] * (3 - len(part.size))
        mesh = f"hull_{k}" if part.kind == "mesh" else ""
        if mesh:  # a convex hull collider (a big sphere's or disc's)
            spec.add_mesh(name=mesh, file=part.mesh, maxhullvert=meta.maxhullvert)
        body.add_geom(
            type=kinds[part.kind],
            size=size,
            pos=part.pos,
            quat=part.quat,
            density=density,
            meshname=mesh,
        )
    model = spec.compile()
    data = mujoco.MjData(model)
    start = data.qpos[:3].copy()
    mujoco.mj_step(model, data, int(seconds / model.opt.timestep))
    drift = float(np.linalg.norm(data.qpos[:3] - start))
    tilt = 2 * float(np.arccos(min(1.0, abs(data.qpos[3]))))
    return drift, tilt


def test_treadmill_proxy() -> None:
    bundle, family = build_proxy("treadmill", "treadmill_p", (1.95, 0.85, 1.4))
    meta = bundle.meta
    assert meta.category == "treadmill"
    assert meta.proxy is True
    assert meta.size == (1.95, 0.85, 1.4)
    assert meta.description == f"a proxy for a treadmill ({family.replace('_', ' ')})"
    low, high = mass_bounds("floor")
    assert low <= meta.mass <= high
    drift, tilt = _stands_still(bundle)
    assert drift < 0.005 and tilt < np.radians(1.0)


@pytest.mark.parametrize("family", FAMILIES)
def test_every_family_is_valid_and_stands_still(family: str) -> None:
    size = (0.03, 1.2, 0.8) if family == "frame" else (0.6, 0.5, 0.9)
    bundle, got = build_proxy("widget", f"widget_{family}", size, family=family)
    meta = bundle.meta
    assert got == family and meta.proxy and meta.category == "widget"
    if family not in ("cylinder", "sphere"):
        assert meta.size == size
    # colliders inside the visual bounds (assemble checks), a plausible mass
    assert 0.0 < meta.mass <= mass_bounds("floor")[1]
    if family != "frame":  # a frame hangs on a wall
        drift, tilt = _stands_still(bundle)
        assert drift < 0.005 and tilt < np.radians(1.0), (family, drift, tilt)


@pytest.mark.parametrize(
    ("category", "size", "placement", "family"),
    [
        ("treadmill", (1.95, 0.85, 1.4), "floor", "stacked"),
        ("weight_bench", (1.3, 0.6, 0.45), "floor", "slab_on_legs"),
        ("coat_stand", (0.4, 0.4, 1.8), "floor", "tapered_column"),
        ("yoga_mat", (1.8, 0.6, 0.01), "floor", "slab"),
        ("chalkboard", (0.03, 1.5, 1.0), "wall", "frame"),
        ("globe", (0.3, 0.3, 0.3), "object", "sphere"),
        ("barrel", (0.6, 0.6, 0.9), "floor", "cylinder"),
        ("bean_bag", (0.8, 0.8, 0.6), "floor", "rounded_box"),
        ("gadget", (0.3, 0.2, 0.3), "floor", "box"),
    ],
)
def test_family_choice(category, size, placement, family) -> None:
    assert proxy_family(category, size, placement) == family


def test_proxy_takes_the_colour_asked() -> None:
    bundle, _ = build_proxy("treadmill", "t", (1.95, 0.85, 1.4), attributes=Attributes("pink"))
    assert bundle.meta.attributes == {"colour": "pink"}
    assert "pink" in bundle.meta.description
    assert any(v.rgba[:3] == pytest.approx(COLOURS["pink"]) for v in bundle.meta.visual)


def test_proxies_are_deterministic() -> None:
    a, _ = build_proxy("telescope", "t", (0.5, 0.5, 1.4))
    b, _ = build_proxy("telescope", "t", (0.5, 0.5, 1.4))
    assert a.meta == b.meta and a.files == b.files
