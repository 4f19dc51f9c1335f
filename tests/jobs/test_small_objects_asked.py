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
