"""Shared fixtures: scenes, libraries, and a check that a model raises no MuJoCo warning."""

from __future__ import annotations

import json
import os
import shutil
import tempfile
from pathlib import Path

os.environ.setdefault("MUJOCO_GL", "egl")
# Never touch the user's cache: the default library is built once per test process here.
os.environ["HOLOMJ_HOME"] = tempfile.mkdtemp(prefix="holomj-test-home-")

import pytest

from holomj.library import AssetLibrary
from holomj.spec.scene import SceneSpec

TESTS = Path(__file__).parent
FIXTURES = TESTS / "fixtures"
SHARED_ASSETS = TESTS.parent.parent / "shared" / "assets"


def two_room_data() -> dict:
    """A kitchen and an L-shaped living room: doors (single, double), windows, objects."""
    return json.loads((FIXTURES / "two_room_scene.json").read_text())


@pytest.fixture
def two_room_scene() -> SceneSpec:
    """The two-room scene as a validated SceneSpec."""
    return SceneSpec.model_validate(two_room_data())


@pytest.fixture
def empty_library(tmp_path: Path) -> AssetLibrary:
    """A library with no assets of its own (it still offers builtin:box)."""
    root = tmp_path / "empty_library"
    root.mkdir()
    (root / "library.json").write_text(
        json.dumps({"schema_version": "1.0", "name": "empty", "assets": {}})
    )
    return AssetLibrary.open(root)


@pytest.fixture(scope="session")
def default_library() -> AssetLibrary:
    """The procedural default library, built on first use into this session's HOLOMJ_HOME."""
    from asset_pipeline.default_library import ensure_default_library

    return AssetLibrary.open(ensure_default_library())


@pytest.fixture(scope="session")
def shared_assets() -> Path:
    """../shared/assets (real meshes); tests using it skip visibly when it is absent."""
    if not (SHARED_ASSETS / "MANIFEST.json").is_file():
        pytest.skip(f"shared assets not found at {SHARED_ASSETS}")
    return SHARED_ASSETS


def copy_fixture(name: str, target: Path) -> Path:
    """Copy a fixture file into ``target`` and return the copy's path."""
    target.mkdir(parents=True, exist_ok=True)
    return Path(shutil.copy(FIXTURES / name, target / name))
