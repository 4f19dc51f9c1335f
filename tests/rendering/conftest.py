"""Fixtures of the render tests: the two-room scene compiled (and rendered) once per session,
in memory, and written as an output folder (for the golden image and the render job's tests)."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from holomj.jobs.compile import compile_file
from holomj.library import AssetLibrary
from holomj.mjcf.compiler import CompiledScene, compile_scene
from holomj.rendering import Rendering, RenderOptions, render_scene
from holomj.spec.scene_file import read_scene_file
from tests.conftest import FIXTURES

SMALL = (160, 120)  # keep renders fast: llvmpipe draws on the CPU


def empty_library_at(root: Path) -> Path:
    """The two-room scene uses builtin:box only: an empty library is enough (and fast)."""
    root.mkdir(parents=True, exist_ok=True)
    (root / "library.json").write_text(
        json.dumps({"schema_version": "1.0", "name": "empty", "assets": {}})
    )
    return root


def two_room_compiled_in(library: AssetLibrary) -> CompiledScene:
    """The two-room fixture scene compiled in memory with ``library``."""
    return compile_scene(read_scene_file(FIXTURES / "two_room_scene.json"), library)


def two_room_folder_in(root: Path) -> Path:
    """The two-room fixture scene compiled into the output folder ``root/two_room``."""
    out = root / "two_room"
    compile_file(
        FIXTURES / "two_room_scene.json",
        out,
        library_path=empty_library_at(root / "library"),
        check_seconds=0.0,
    )
    return out


@pytest.fixture(scope="session")
def two_room_library(tmp_path_factory: pytest.TempPathFactory) -> AssetLibrary:
    """An empty library (it offers builtin:box, all the two-room scene uses)."""
    return AssetLibrary.open(empty_library_at(tmp_path_factory.mktemp("library")))


@pytest.fixture(scope="session")
def two_room_compiled(two_room_library: AssetLibrary) -> CompiledScene:
    """The two-room fixture scene compiled in memory (do not modify it)."""
    return two_room_compiled_in(two_room_library)


@pytest.fixture(scope="session")
def compiled_two_room(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The two-room fixture scene compiled into an output folder (do not modify it)."""
    return two_room_folder_in(tmp_path_factory.mktemp("render"))


@pytest.fixture
def two_room_folder(compiled_two_room: Path, tmp_path: Path) -> Path:
    """A private copy of the compiled two-room folder, free to modify."""
    return Path(shutil.copytree(compiled_two_room, tmp_path / "two_room"))


@pytest.fixture(scope="session")
def rendered_two_room(two_room_compiled: CompiledScene) -> Rendering:
    """The two-room scene rendered once in memory with every view, depth and segmentation."""
    options = RenderOptions(
        views=("top", "rooms", "objects"),
        width=SMALL[0],
        height=SMALL[1],
        depth=True,
        segmentation=True,
    )
    return render_scene(two_room_compiled.model, two_room_compiled.scene, options)
