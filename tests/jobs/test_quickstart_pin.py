"""The quick start's scene, byte for byte: a refactor that changes what ``generate`` writes for
the same prompt and seed fails here. Update the pin only for an intended change of output."""

from __future__ import annotations

import hashlib
from pathlib import Path

import pytest

from holomj.jobs.generate import GenerateOptions, generate_scene

QUICKSTART_PROMPT = "a two-bedroom apartment with a home office"
QUICKSTART_SEED = 7
# Update only for an intended change of output, and say which here:
# - in-memory compiles give every asset its own meshes (small objects drop onto the true shapes);
# - layout priorities (defining furniture first) and the TV-above-its-stand rule (the stand keeps
#   the wall above it free of windows) move the living room's furniture.
# The jobs-layer move itself left the bytes unchanged.
SCENE_XML_SHA256 = "302db1d5cf7a0fa7d2776bb8cacd7a808015dcc5840faf9edd5970602fc2153b"


@pytest.mark.slow
def test_quickstart_scene_bytes_are_pinned(tmp_path: Path, default_library) -> None:
    out = tmp_path / "example"
    options = GenerateOptions(library=default_library.root, seed=QUICKSTART_SEED, render=False)
    generate_scene(QUICKSTART_PROMPT, out, options)
    digest = hashlib.sha256((out / "scene.xml").read_bytes()).hexdigest()
    assert digest == SCENE_XML_SHA256
