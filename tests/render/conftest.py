"""Fixtures of the render tests: the two-room scene compiled (and rendered) once per session."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from holomj.jobs.compile import compile_file
from holomj.render import RenderSummary, render_folder
from tests.conftest import FIXTURES

SMALL = (160, 120)  # keep renders fast: llvmpipe draws on the CPU


def _empty_library(root: Path) -> Path:
    """The two-room scene uses builtin:box only: an empty library is enough (and fast)."""
    root.mkdir(parents=True, exist_ok=True)
    (root / "library.json").write_text(
        json.dumps({"schema_version": "1.0", "name": "empty", "assets": {}})
    )
    return root


@pytest.fixture(scope="session")
def compiled_two_room(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The two-room fixture scene compiled into an output folder (do not modify it)."""
    root = tmp_path_factory.mktemp("render")
    out = root / "two_room"
    compile_file(
        FIXTURES / "two_room_scene.json",
        out,
        library_path=_empty_library(root / "library"),
        check_seconds=0.0,
    )
    return out


@pytest.fixture
def two_room_folder(compiled_two_room: Path, tmp_path: Path) -> Path:
    """A private copy of the compiled two-room folder, free to modify."""
    return Path(shutil.copytree(compiled_two_room, tmp_path / "two_room"))


@pytest.fixture(scope="session")
def rendered_two_room(
    compiled_two_room: Path, tmp_path_factory: pytest.TempPathFactory
) -> tuple[Path, RenderSummary]:
    """A copy of the two-room folder rendered once with every view, depth and segmentation."""
    out = Path(shutil.copytree(compiled_two_room, tmp_path_factory.mktemp("rendered") / "two"))
    summary = render_folder(
        out,
        views=("top", "rooms", "objects"),
        width=SMALL[0],
        height=SMALL[1],
        depth=True,
        segmentation=True,
    )
    return out, summary
