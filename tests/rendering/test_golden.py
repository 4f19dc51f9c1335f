"""The two-room top view against a golden image, with a tolerance for GL drivers.

Regenerate with ``HOLOMJ_UPDATE_GOLDEN=1 .venv/bin/pytest tests/rendering/test_golden.py``. On a
mismatch, expected/actual/diff PNGs are saved into a temporary folder named in the failure.
"""

from __future__ import annotations

import os
import shutil
import tempfile
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from holomj.jobs.render import render_folder
from tests.conftest import TESTS

GOLDEN = TESTS / "golden" / "render" / "two_room_top_160x120.png"
MEAN_ABS_DIFF_MAX = 3.0  # 0..255, averaged over every pixel and channel
OFF_PIXEL_DIFF = 40  # a pixel is "off" when a channel differs by more than this
OFF_FRACTION_MAX = 0.02


def compare(expected: np.ndarray, actual: np.ndarray) -> tuple[float, float, np.ndarray]:
    """Mean absolute difference, fraction of pixels off, and the per-pixel difference image."""
    diff = np.abs(expected.astype(np.int16) - actual.astype(np.int16)).astype(np.uint8)
    return float(diff.mean()), float((diff.max(axis=2) > OFF_PIXEL_DIFF).mean()), diff


def mismatch(expected: np.ndarray, actual: np.ndarray, name: str) -> str | None:
    """None when ``actual`` matches ``expected`` within the tolerance; otherwise a message
    naming a temporary folder where expected/actual/diff PNGs were saved."""
    if expected.shape != actual.shape:
        return f"{name}: size {actual.shape} differs from the golden {expected.shape}"
    mean_diff, off, diff = compare(expected, actual)
    if mean_diff <= MEAN_ABS_DIFF_MAX and off <= OFF_FRACTION_MAX:
        return None
    folder = Path(tempfile.mkdtemp(prefix="holomj-golden-"))
    Image.fromarray(expected).save(folder / "expected.png")
    Image.fromarray(actual).save(folder / "actual.png")
    amplified = np.clip(diff.astype(np.int16) * 4, 0, 255).astype(np.uint8)
    Image.fromarray(amplified).save(folder / "diff.png")
    return (
        f"{name} differs from its golden image: mean abs diff {mean_diff:.2f} "
        f"(max {MEAN_ABS_DIFF_MAX}), {off:.1%} of pixels off (max {OFF_FRACTION_MAX:.0%}); "
        f"expected/actual/diff saved in {folder}"
    )


def test_two_room_top_view_matches_the_golden_image(two_room_folder: Path) -> None:
    render_folder(two_room_folder, views="top", width=160, height=120, shadows=False)
    actual = np.asarray(Image.open(two_room_folder / "renders" / "top.png").convert("RGB"))
    if os.environ.get("HOLOMJ_UPDATE_GOLDEN") == "1":
        GOLDEN.parent.mkdir(parents=True, exist_ok=True)
        Image.fromarray(actual).save(GOLDEN)
        pytest.skip(f"golden image updated: {GOLDEN}")
    assert GOLDEN.is_file(), f"no golden image at {GOLDEN}; run with HOLOMJ_UPDATE_GOLDEN=1"
    expected = np.asarray(Image.open(GOLDEN).convert("RGB"))
    problem = mismatch(expected, actual, "two-room top view")
    if problem:
        pytest.fail(problem)


def test_a_visible_change_fails_and_saves_the_evidence() -> None:
    """The tolerance is not so loose that a moved or painted object passes."""
    if not GOLDEN.is_file():
        pytest.skip("no golden image yet")
    golden = np.asarray(Image.open(GOLDEN).convert("RGB"))
    assert mismatch(golden, golden.copy(), "same") is None
    problem = mismatch(golden, np.roll(golden, 6, axis=1), "shifted")
    assert problem is not None
    folder = Path(problem.rsplit("saved in ", 1)[1])
    assert sorted(p.name for p in folder.iterdir()) == ["actual.png", "diff.png", "expected.png"]
    shutil.rmtree(folder)
    painted = golden.copy()
    painted[40:60, 60:90] = (255, 0, 0)  # a 20 x 30 px red box (3 % of the image)
    problem = mismatch(golden, painted, "painted")
    assert problem is not None
    shutil.rmtree(problem.rsplit("saved in ", 1)[1])
