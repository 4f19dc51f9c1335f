"""The mjx compile profile: what it changes, what it rejects, and MJX accepting the result."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

from holomj.errors import InputError, SpecError
from holomj.library import AssetLibrary
from holomj.mjcf import compile_scene
from holomj.mjcf.mjx_profile import MAX_HULL_VERT, apply_mjx_profile
from holomj.spec.scene import SceneSpec

FEATURES = """
<mujoco>
  <option integrator="implicit" solver="PGS" noslip_iterations="3" cone="elliptic">
    <flag energy="enable"/>
  </option>
  <asset>
    <mesh name="blob" vertex="0 0 0  1 0 0  0 1 0  0 0 1  1 1 1  0.5 0.2 0.9  0.3 0.8 0.1"/>
  </asset>
  <worldbody>
    <geom name="floor" type="plane" size="5 5 0.1"/>
    <geom name="post" type="cylinder" fromto="2 0 0 2 0 1" size="0.1" margin="0.01"/>
    <body name="ball" pos="0 0 1">
      <freejoint/>
      <geom name="egg" type="ellipsoid" size="0.1 0.2 0.3" condim="1" mass="2"/>
      <geom name="can" type="cylinder" size="0.05 0.1" pos="0 0 0.5"/>
      <geom name="look" type="cylinder" size="0.05 0.1" contype="0" conaffinity="0"/>
      <geom name="rock" type="mesh" mesh="blob" gap="0.02"/>
    </body>
  </worldbody>
</mujoco>
"""


def test_profile_changes_what_mjx_lacks() -> None:
    spec = mujoco.MjSpec.from_string(FEATURES)
    before = spec.compile()
    notes = apply_mjx_profile(spec)
    model = spec.compile()
    opt = model.opt
    assert opt.integrator == mujoco.mjtIntegrator.mjINT_IMPLICITFAST
    assert opt.solver == mujoco.mjtSolver.mjSOL_NEWTON and opt.noslip_iterations == 0
    assert opt.enableflags == 0
    assert model.geom("post").type == mujoco.mjtGeom.mjGEOM_MESH
    assert model.geom("can").type == mujoco.mjtGeom.mjGEOM_MESH
    assert model.geom("egg").type == mujoco.mjtGeom.mjGEOM_MESH
    assert model.geom("look").type == mujoco.mjtGeom.mjGEOM_CYLINDER  # visual: left alone
    assert model.geom("egg").condim == 3
    assert np.all(model.geom_margin == 0) and np.all(model.geom_gap == 0)
    assert model.geom("egg").bodyid == model.body("ball").id
    # The converted post stands where the cylinder stood, as tall.
    np.testing.assert_allclose(model.geom("post").pos, before.geom("post").pos, atol=1e-9)
    top = model.geom_aabb[model.geom("post").id]
    assert top[5] == pytest.approx(0.5, abs=1e-6)  # half-height along the post's axis
    assert model.body("ball").mass[0] == pytest.approx(before.body("ball").mass[0], rel=0.05)
    for mesh in range(model.nmesh):
        assert 0 < model.mesh_graph[model.mesh_graphadr[mesh]] <= MAX_HULL_VERT
    assert any("cylinder" in n for n in notes) and any("max_geom_pairs" in n for n in notes)
    assert model.numeric("max_geom_pairs").data[0] > 0
    assert apply_mjx_profile(spec) == []  # idempotent


def test_unconvertible_features_are_rejected() -> None:
    adhesion = mujoco.MjSpec.from_string(
        "<mujoco><worldbody><body name='b'><freejoint/><geom size='0.1'/></body></worldbody>"
        "<actuator><adhesion name='stick' body='b' ctrlrange='0 1'/></actuator></mujoco>"
    )
    with pytest.raises(SpecError, match=r"actuator 'stick'.*mjTRN_BODY"):
        apply_mjx_profile(adhesion)
    sensor = mujoco.MjSpec.from_string(
        "<mujoco><worldbody><body name='b'><freejoint/><geom size='0.1'/>"
        "<site name='s'/></body></worldbody>"
        "<sensor><contact name='touching' site='s'/></sensor></mujoco>"
    )
    with pytest.raises(SpecError, match=r"sensor 'touching'.*geoms only"):
        apply_mjx_profile(sensor)


def test_unknown_profile(two_room_scene: SceneSpec, empty_library: AssetLibrary) -> None:
    with pytest.raises(InputError, match=r"unknown profile 'fast'.*default or mjx"):
        compile_scene(two_room_scene, empty_library, profile="fast")  # type: ignore[arg-type]


def test_default_profile_is_unchanged(
    two_room_scene: SceneSpec, empty_library: AssetLibrary
) -> None:
    default = compile_scene(two_room_scene, empty_library)
    mjx = compile_scene(two_room_scene, empty_library, profile="mjx")
    assert default.profile == "default" and mjx.profile == "mjx"
    assert "max_geom_pairs" not in default.to_xml() and "max_geom_pairs" in mjx.to_xml()
    assert mjx.model.nbody == default.model.nbody


def test_mjx_accepts_the_scene(two_room_scene: SceneSpec, empty_library: AssetLibrary) -> None:
    mjx = pytest.importorskip(
        "mujoco.mjx", reason="needs the mjx extra (pip install 'holomj[mjx]')"
    )
    with pytest.raises(NotImplementedError):  # the default profile's model is not MJX-ready
        mjx.put_model(_with_cylinder(two_room_scene, empty_library, "default"))
    mjx.put_model(_with_cylinder(two_room_scene, empty_library, "mjx"))


def _with_cylinder(scene: SceneSpec, library: AssetLibrary, profile: str) -> mujoco.MjModel:
    """The scene compiled with ``profile`` plus a free cylinder (MJX-JAX cannot collide it with
    boxes): the profile has to convert it."""
    compiled = compile_scene(scene, library, profile=profile)  # type: ignore[arg-type]
    spec = compiled.spec.copy()
    body = spec.worldbody.add_body(name="can", pos=[5.0, 4.0, 0.2])
    body.add_freejoint()
    body.add_geom(type=mujoco.mjtGeom.mjGEOM_CYLINDER, size=[0.05, 0.1, 0], mass=0.3)
    if profile == "mjx":
        apply_mjx_profile(spec)
    spec.assets = dict(compiled.files)
    return spec.compile()


@pytest.mark.slow
def test_mjx_accepts_the_scene_with_a_robot(
    two_room_scene: SceneSpec, empty_library: AssetLibrary
) -> None:
    mjx = pytest.importorskip(
        "mujoco.mjx", reason="needs the mjx extra (pip install 'holomj[mjx]')"
    )
    from holomj.robots.attach import add_robot

    compiled = compile_scene(two_room_scene, empty_library, profile="mjx")
    compiled = add_robot(compiled, "jaco", np.random.default_rng(0))
    mjx.put_model(compiled.model)
    # C MuJoCo still runs the profiled model without a warning.
    data = mujoco.MjData(compiled.model)
    for _ in range(250):
        mujoco.mj_step(compiled.model, data)
    assert all(w.number == 0 for w in data.warning)


@pytest.mark.slow
def test_mjx_steps_the_scene_on_cpu(two_room_scene: SceneSpec, empty_library: AssetLibrary) -> None:
    mjx = pytest.importorskip(
        "mujoco.mjx", reason="needs the mjx extra (pip install 'holomj[mjx]')"
    )
    import jax

    model = compile_scene(two_room_scene, empty_library, profile="mjx").model
    mjx_model = mjx.put_model(model)
    data = mjx.make_data(mjx_model)
    step = jax.jit(mjx.step)
    for _ in range(5):
        data = step(mjx_model, data)
    qpos = np.asarray(data.qpos)
    assert np.all(np.isfinite(qpos)) and float(data.time) == pytest.approx(5 * model.opt.timestep)
    reference = mujoco.MjData(model)
    for _ in range(5):
        mujoco.mj_step(model, reference)
    np.testing.assert_allclose(qpos, reference.qpos, atol=1e-4)
