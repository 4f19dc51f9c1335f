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
#   the wall above it free of windows) move the living room's furniture;
# - objects at an edge are pushed back onto the wall (Holodeck's snap).
# The jobs-layer move itself left the bytes unchanged.
# - issue 14/15: 223 procedural categories, asset texts with the knowledge base's synonyms,
#   attribute-matched or synthesised assets (white, round, wooden), a 1 m door keep-out and
#   furniture nudged to open unreachable floor (measured as the navigation map sees it).
# - procedural textures with UVs, hull colliders that cover the visuals (collider audit), per-part
#   roles, kitchens as counter runs and the planner's seating/area rules.
# - issue 17: the default library is articulated (counters, cabinets, wardrobes, dressers,
#   nightstands and appliances with doors, drawers and racks on joints: 26 moving parts in this
#   scene), generate puts things inside them, and an L's or U's corner square is left empty
#   (a dead corner); re-pinned once at the end of that work, which also takes in the layout
#   changes of the same day (open pockets), so it was perhaps stale before.
# - issue 14: a room whose furniture fences off floor a robot cannot reach grows (the kitchen,
#   94 % reachable, from 13.6 to 17.0 m²), and the whole house is laid out again; the layout
#   judges passages between footprints grown to the navigation map's 5 cm cells, and a wall
#   cabinet hangs over the counter run, or is left out when not asked for and it would narrow
#   the way.
SCENE_XML_SHA256 = "2abf9431fb564a3e6524685a6e5d851bdd9894720466a4a8af91e826775fde0f"


@pytest.mark.slow
def test_quickstart_scene_bytes_are_pinned(tmp_path: Path, default_library) -> None:
    out = tmp_path / "example"
    options = GenerateOptions(library=default_library.root, seed=QUICKSTART_SEED, render=False)
    generate_scene(QUICKSTART_PROMPT, out, options)
    digest = hashlib.sha256((out / "scene.xml").read_bytes()).hexdigest()
    assert digest == SCENE_XML_SHA256
