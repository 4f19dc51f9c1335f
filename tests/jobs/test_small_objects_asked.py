"""Small objects asked for land in the number asked, on receptacles of the kind asked, however
many instances of the receptacle the room has (generate end to end)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from holomj.jobs.generate import GenerateOptions, generate_scene


@pytest.mark.slow
def test_one_printer_for_eight_desks(tmp_path: Path, default_library) -> None:
    out = tmp_path / "office"
    options = GenerateOptions(library=default_library.root, seed=0, render=False)
    generate_scene(
        "An open office with eight desks, eight office chairs and a printer.", out, options
    )
    objects = json.loads((out / "objects.json").read_text())
    objects = objects if isinstance(objects, list) else objects["objects"]
    printers = [o for o in objects if o.get("category") == "printer"]
    assert len(printers) == 1, [o["id"] for o in printers]
    assert ".desk_" in printers[0]["support"]


@pytest.mark.slow
def test_a_tv_with_no_wall_free_stands_on_the_furniture(tmp_path: Path, default_library) -> None:
    """Twelve chairs along three walls and a door and windows on the fourth leave no wall for
    the TV: it stands on the reception desk instead, and the plan says so."""
    out = tmp_path / "waiting"
    options = GenerateOptions(library=default_library.root, seed=0, render=False)
    prompt = (
        "A dentist's waiting room with twelve chairs along three walls, a children's corner "
        "with a small table and a toy box, a reception counter near the door, a fish tank and a "
        "TV mounted on the wall."
    )
    result = generate_scene(prompt, out, options)
    objects = json.loads((out / "objects.json").read_text())
    objects = objects if isinstance(objects, list) else objects["objects"]
    tvs = [o for o in objects if o.get("category") in ("television", "wall_television")]
    assert len(tvs) == 1, [o["id"] for o in objects]
    assert tvs[0].get("support")  # no wall had room: it stands on the reception counter
    assert any("stands on" in c for c in result.record["plan_changes"])
