"""Shared fixtures of the robot tests: prepared robots (once per session) and a compiled scene."""

from __future__ import annotations

import pytest

from holomj.library import AssetLibrary
from holomj.mjcf import compile_scene
from holomj.mjcf.compiler import CompiledScene
from holomj.robots.prepare import PreparedRobot, prepare_robot
from holomj.robots.registry import installed_robots, resolve_robot
from holomj.spec.scene import SceneSpec


@pytest.fixture(scope="session")
def jaco() -> PreparedRobot:
    """dm_control's Kinova Jaco with its hand (dm_control is a core dependency)."""
    return prepare_robot(resolve_robot("jaco"))


@pytest.fixture(scope="session")
def panda() -> PreparedRobot:
    """The Panda of dm-robotics-panda; skipped visibly when that package is not installed."""
    if "panda" not in installed_robots():
        pytest.skip("dm-robotics-panda is not installed (pip install dm-robotics-panda --no-deps)")
    return prepare_robot(resolve_robot("panda"))


@pytest.fixture
def two_room_compiled(two_room_scene: SceneSpec, empty_library: AssetLibrary) -> CompiledScene:
    """The two-room fixture scene, compiled with the default profile."""
    return compile_scene(two_room_scene, empty_library)
