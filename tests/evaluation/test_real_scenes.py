"""``holomj eval`` on a real compiled ProcTHOR house and on a generated scene (slow: both are
built first), so systems can be compared on the same houses."""

from __future__ import annotations

import json
import time
from pathlib import Path

import pytest

import holomj
from holomj.jobs.generate import GenerateOptions, generate_scene

HOUSE = Path(__file__).resolve().parents[3] / "shared" / "procthor" / "houses"
MEASURED = ("collisions", "outside", "support", "navigability", "doors_clear", "stability")


@pytest.mark.slow
def test_a_compiled_procthor_house(tmp_path: Path, default_library) -> None:
    source = HOUSE / "procthor_ai2thor_143.json"
    if not source.is_file():
        pytest.skip(f"real ProcTHOR house not found at {source}")
    out = tmp_path / "143"
    holomj.compile(source, out, library=default_library.root, check_seconds=0.0)
    start = time.perf_counter()
    rec = holomj.eval(out).to_json()
    assert time.perf_counter() - start < 10.0
    for key in MEASURED:
        assert rec["scores"][key]["score"] is not None, key
    assert rec["scores"]["collisions"]["ok"] and rec["scores"]["stability"]["ok"]  # it stands
    assert rec["scores"]["outside"]["ok"]
    assert rec["details"]["navigability"]["rooms_unreached"] == []
    assert rec["scores"]["navigability"]["score"] > 0.9
    assert rec["scores"]["front_access"]["total"] >= 3  # toilet, fridge, washbasin, ...
    support = {s["rests_on"] for s in rec["details"]["support"]}
    assert {"floor", "wall"} <= support and len(support) > 3  # and objects on receptacles
    assert {r["as"] for r in rec["rooms"]} >= {"bedroom", "bathroom", "kitchen", "living room"}
    # Against a prompt: the requested objects, found by category in rooms of their type.
    rec = holomj.eval(out, prompt="a house with a bedroom with a bed and a bathroom with a toilet")
    assert rec.against["source"] == "prompt"
    assert rec.scores["counts"]["ok"], rec.details["counts"]


@pytest.mark.slow
def test_a_generated_scene_against_its_plan(tmp_path: Path, default_library) -> None:
    out = tmp_path / "lr"
    prompt = "a living room with a sofa, a tv and an armchair by the window"
    options = GenerateOptions(library=default_library.root, seed=0, render=False)
    generate_scene(prompt, out, options)
    rec = holomj.eval(out).to_json()
    assert rec["against"]["source"] == "plan.json" and rec["against"]["prompt"] == prompt
    assert rec["scores"]["counts"]["score"] >= 0.8, rec["details"]["counts"]
    relation = next(r for r in rec["details"]["relations"] if r["spec"]["subject"] == "armchair")
    assert relation["spec"]["object"] == "window"
    for key in ("collisions", "outside", "support", "stability", "doors_clear"):
        assert rec["scores"][key]["ok"], (key, rec["scores"][key])
    assert rec["scores"]["navigability"]["score"] >= 0.95
    report = json.loads((out / "report.json").read_text())
    assert rec["scores"]["stability"]["total"] == len(report["objects"])


def test_a_frames_open_inside_is_not_cut_off_floor(tmp_path: Path, default_library) -> None:
    """The floor inside a squat rack's frame belongs to the rack; a pen of four crates is a
    pocket the furniture cut off."""
    from tests.evaluation.scenes import box, room_scene

    rack = {"id": "gym.squat_rack_0", "asset": "squat_rack_000", "position": [2.0, 2.2, 0.0]}
    pen = [
        box("crate_0", "gym", (2.0, 1.2), (1.7, 0.1, 0.6)),
        box("crate_1", "gym", (2.0, 2.8), (1.7, 0.1, 0.6)),
        box("crate_2", "gym", (1.2, 2.0), (0.1, 1.5, 0.6)),
        box("crate_3", "gym", (2.8, 2.0), (0.1, 1.5, 0.6)),
    ]
    verdicts = {}
    for name, objects in (("rack", [{**rack, "room": "gym"}]), ("pen", pen)):
        src = tmp_path / f"{name}.json"
        src.write_text(json.dumps(room_scene(objects, room="gym", kind="gym")))
        holomj.compile(src, tmp_path / name, library=default_library.root, check_seconds=0.0)
        verdicts[name] = holomj.eval(tmp_path / name).details["navigability"]
    assert verdicts["rack"]["share"] == 1.0 and verdicts["rack"]["interior_m2"] > 0.05
    assert verdicts["pen"]["share"] < 0.97 and verdicts["pen"]["interior_m2"] == 0.0
