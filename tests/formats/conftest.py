"""Fixtures of the export tests: the two-room scene as a folder, the same scene with articulated
parts added to an object (hinge and slide joints, as articulated furniture has), and the quick
start's apartment (slow tests only)."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import mujoco
import pytest

from holomj.mjcf import names
from holomj.mjcf.compiler import CompiledScene
from holomj.spec.scene import SceneSpec
from tests.rendering.conftest import two_room_compiled_in, two_room_folder_in

QUICKSTART_PROMPT = "a two-bedroom apartment with a home office"
QUICKSTART_SEED = 7


@dataclass(frozen=True)
class Articulated:
    """The two-room model with a lid on a sprung hinge (anchor off the body origin), a drawer
    on a slide (its reference 5 cm out) below the lid, and a welded handle on the drawer, all
    under the crate."""

    model: mujoco.MjModel
    scene: SceneSpec
    crate: str = "crate"
    hinge: str = "crate/lid_hinge"
    slide: str = "crate/drawer_slide"


@pytest.fixture(scope="session")
def two_room_out(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The two-room fixture scene compiled into an output folder (do not modify it)."""
    return two_room_folder_in(tmp_path_factory.mktemp("export"))


def articulated_from(compiled: CompiledScene) -> Articulated:
    spec = compiled.spec  # a fresh compile of our own: free to change
    crate = spec.body(names.object_body("crate"))
    lid = crate.add_body(name="crate/lid", pos=[0.0, 0.0, 0.5], quat=[0.9659258, 0, 0, 0.2588190])
    lid.add_joint(
        name="crate/lid_hinge",
        type=mujoco.mjtJoint.mjJNT_HINGE,
        pos=[-0.3, 0.0, 0.0],
        axis=[0.0, 1.0, 0.0],
        range=[0.0, 1.9],
        limited=mujoco.mjtLimited.mjLIMITED_TRUE,
        damping=0.5,
        stiffness=2.0,  # a lid stay: a spring towards 1.2 rad
        springref=1.2,
    )
    lid.add_geom(
        name="crate/lid_box",
        type=mujoco.mjtGeom.mjGEOM_BOX,
        size=[0.3, 0.2, 0.02],
        pos=[0, 0, 0.02],
        density=500,
    )
    drawer = lid.add_body(name="crate/drawer", pos=[0.1, 0.0, 0.1])
    drawer.add_joint(
        name="crate/drawer_slide",
        type=mujoco.mjtJoint.mjJNT_SLIDE,
        axis=[1.0, 0.0, 0.0],
        range=[0.0, 0.25],
        limited=mujoco.mjtLimited.mjLIMITED_TRUE,
        ref=0.05,  # the model's pose is 5 cm out: the exports' zero
    )
    drawer.add_geom(
        name="crate/drawer_box", type=mujoco.mjtGeom.mjGEOM_BOX, size=[0.1, 0.1, 0.05], density=300
    )
    handle = drawer.add_body(name="crate/handle", pos=[0.12, 0.0, 0.0])
    handle.add_geom(
        name="crate/handle_cyl",
        type=mujoco.mjtGeom.mjGEOM_CYLINDER,
        size=[0.01, 0.05],
        density=2000,
    )
    model = spec.compile()
    return Articulated(model, compiled.scene)


@pytest.fixture(scope="session")
def articulated(two_room_library) -> Articulated:
    """The two-room scene with articulated parts under the crate (a fresh compile)."""
    return articulated_from(two_room_compiled_in(two_room_library))


@pytest.fixture(scope="session")
def two_room_library(tmp_path_factory: pytest.TempPathFactory):
    from holomj.library import AssetLibrary
    from tests.rendering.conftest import empty_library_at

    return AssetLibrary.open(empty_library_at(tmp_path_factory.mktemp("library")))


@pytest.fixture(scope="session")
def apartment(tmp_path_factory: pytest.TempPathFactory, default_library) -> Path:
    """The quick start's apartment, generated without renders (slow: about half a minute)."""
    from holomj.jobs.generate import GenerateOptions, generate_scene

    out = tmp_path_factory.mktemp("quickstart") / "example"
    options = GenerateOptions(library=default_library.root, seed=QUICKSTART_SEED, render=False)
    generate_scene(QUICKSTART_PROMPT, out, options)
    return out
