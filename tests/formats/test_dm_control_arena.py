"""The composer Arena of a holomj folder: an environment with a Jaco arm resets and steps."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from dm_control import composer
from dm_control.entities.manipulators.kinova import jaco_arm, jaco_hand

from holomj.errors import FormatError
from holomj.jobs.arena import HolomjArena
from holomj.jobs.folder import write_scene_folder
from holomj.library import AssetLibrary
from holomj.mjcf import compile_scene
from holomj.robots.attach import add_robot
from holomj.robots.registry import resolve_robot
from holomj.spec.scene import SceneSpec

JACO_HOME = [resolve_robot("jaco").home[f"joint_{i}"] for i in range(1, 7)]


class _Hold(composer.Task):
    """A trivial task: the arm starts in its home pose; no reward, no observables."""

    def __init__(self, arena: HolomjArena, arm: jaco_arm.JacoArm) -> None:
        self._arena = arena
        self._arm = arm

    @property
    def root_entity(self) -> HolomjArena:
        return self._arena

    def initialize_episode(self, physics, random_state) -> None:
        physics.bind(self._arm.joints).qpos = JACO_HOME

    def get_reward(self, physics) -> float:
        return 0.0


@pytest.fixture
def folder(two_room_scene: SceneSpec, empty_library: AssetLibrary, tmp_path: Path) -> Path:
    compiled = compile_scene(two_room_scene, empty_library)
    return write_scene_folder(compiled, tmp_path / "out")


def test_environment_with_a_jaco_steps(folder: Path) -> None:
    arena = HolomjArena(folder)
    assert arena.find("body", "crate/body") is not None
    spot = arena.robot_spot(radius=0.4, seed=1, front_deg=-134.5)
    assert spot.room in ("kitchen", "living") and spot.clearance_m >= 0.1
    arm = jaco_arm.JacoArm()
    arm.attach(jaco_hand.JacoHand())
    frame = arena.attach_at(arm, spot)
    assert list(frame.pos) == [spot.x, spot.y, 0.0]
    env = composer.Environment(_Hold(arena, arm), random_state=np.random.RandomState(0))
    env.reset()
    physics = env.physics
    np.testing.assert_allclose(physics.bind(arm.joints).qpos, JACO_HOME)
    base = physics.bind(arm.mjcf_model.find("body", "b_base")).xpos
    assert math.hypot(base[0] - spot.x, base[1] - spot.y) < 1e-9
    action = np.zeros(env.action_spec().shape)
    for _ in range(20):
        step = env.step(action)
    assert np.isfinite(physics.data.qpos).all() and step.reward == 0.0
    assert physics.data.time > 0
    assert all(w.number == 0 for w in physics.data.warning)
    crate = physics.bind(arena.find("body", "crate/body")).xpos
    assert crate[0] == pytest.approx(5.5, abs=0.01)


def test_arena_of_a_folder_with_a_robot(
    two_room_scene: SceneSpec, empty_library: AssetLibrary, tmp_path: Path
) -> None:
    compiled = add_robot(
        compile_scene(two_room_scene, empty_library), "jaco", np.random.default_rng(0)
    )
    folder = write_scene_folder(compiled, tmp_path / "robot")
    arena = HolomjArena(folder, name="house")
    assert arena.mjcf_model.model == "house"
    assert arena.robot_record == compiled.robot
    assert arena.find("body", "robot/base_mount") is not None
    env = composer.Environment(composer.NullTask(arena))
    env.reset()
    assert env.physics.model.nbody == compiled.model.nbody
    assert env.physics.model.nq == compiled.model.nq


def test_not_a_folder(tmp_path: Path) -> None:
    with pytest.raises(FormatError, match=r"no scene\.xml"):
        HolomjArena(tmp_path)
