"""What colour a written visual part shows, textured or not (shared by attribute tests)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import pytest


def shows(visual: Any, rgb: Sequence[float], tolerance: float = 2e-4) -> bool:
    """Whether ``visual`` (an asset's visual part) shows colour ``rgb``: its own colour, or for
    a textured material (:mod:`asset_pipeline.procedural.textures`) the tint that averages to
    it."""
    want = tuple(rgb)
    if getattr(visual, "texture", None) is not None:
        from asset_pipeline.procedural.textures import PATTERNS, texture_file, tinted

        pattern = {texture_file(p): p for p in PATTERNS}[visual.texture]
        want = tinted((*want, 1.0), pattern)[:3]
    return visual.rgba[:3] == pytest.approx(want, abs=tolerance)
