"""End to end: ``generate`` on a dozen varied prompts gives valid, stable scenes that hold the
objects the prompt asked for (real planner, real text retrieval, real physics)."""

from __future__ import annotations

import json
from pathlib import Path

import mujoco
import pytest

from holomj.jobs.generate import GenerateOptions, generate_scene
from holomj.jobs.validate import validate
from holomj.layout.furniture_rules import FIXED_CATEGORIES, object_id
from holomj.library.store import AssetLibrary

PROMPTS = [
    "a small kitchen",
    "a two-bedroom apartment with a home office",
    "a cozy reading room with two armchairs and a large bookshelf",
    "an office for a professor who loves plants",
    "a music room with a piano",
    "a daycare classroom",
    "a studio apartment with a reading nook",
    "a bathroom with white tiles",
    "a conference room with a whiteboard",
    "a small cafe",
    "a hotel room with a desk",
    "a yoga studio",
    "a small bedroom",
    "a living room with a sofa, a coffee table, a TV stand and two armchairs",
]


@pytest.mark.slow
@pytest.mark.parametrize("prompt", PROMPTS)
def test_generate_gives_a_valid_stable_scene_with_the_requested_objects(
    prompt: str, tmp_path: Path, default_library
) -> None:
    out = tmp_path / "scene"
    options = GenerateOptions(library=default_library.root, seed=3, render=False)
    result = generate_scene(prompt, out, options)

    for name in ("scene.xml", "scene.json", "plan.json", "report.json", "generate.json"):
        assert (out / name).is_file(), name
    assert (out / "assets" / "library.json").is_file()
    assert "plan" in (out / "generate.log").read_text()

    report = json.loads((out / "report.json").read_text())
    assert report["ok"], (prompt, report["counts"], result.record["unplaced"])
    assert report["counts"]["unstable"] == 0 and report["counts"]["penetrations"] == 0
    # Only bolted-down fixtures (and wall objects) were held still; all else was put to the test.
    scene = {o["id"]: o for o in json.loads((out / "scene.json").read_text())["objects"]}
    assert set(report["static_objects"]) == {k for k, o in scene.items() if o["static"]} | {
        o["name"] for o in report["objects"] if not o["dynamic"]
    }
    library = AssetLibrary.open(default_library.root)  # with the assets made on demand
    for name in report["static_objects"]:
        asset = library.get(scene[name]["asset"]).meta
        assert asset.category in FIXED_CATEGORIES or set(asset.placement) <= {"wall", "ceiling"}
    # And 'holomj validate' with every piece of furniture free agrees.
    free = validate(out, furniture="free", sleep=True)
    assert free.ok, (prompt, [(o.name, o.reasons) for o in free.unstable()])

    scene_ids = {o["id"] for o in json.loads((out / "scene.json").read_text())["objects"]}
    plan = result.plan
    for room in plan.rooms:
        for obj in room.objects:
            if obj.requested or obj.defining:  # asked for, or what makes the room what it is
                for instance in obj.instances():
                    assert object_id(room.id, instance) in scene_ids, (prompt, instance)
    assert result.record["counts"]["furniture"] >= 2

    # Every room can be walked into from the entrance, furniture and all.
    navmap = json.loads((out / "navmap.json").read_text())
    assert all(room["reachable"] for room in navmap["rooms"].values()), (prompt, navmap["rooms"])

    model = mujoco.MjModel.from_xml_path(str(out / "scene.xml"))
    assert model.nbody > len(scene_ids)
