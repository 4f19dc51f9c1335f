"""Kitchens and bedrooms are generated with articulated furniture by default (issue 17): the
issue's kitchen has at least 6 moving parts and its bedroom at least 3, every one listed in
``objects.json`` passes the open/close checks on the exported ``scene.xml``
(:mod:`tests.jobs.articulated_scene_checks`), things are put inside, and the scenes validate
ok."""

from __future__ import annotations

import json
from pathlib import Path

import mujoco
import pytest

from holomj.jobs.generate import GenerateOptions, generate_scene
from tests.jobs.articulated_scene_checks import check_part, contents, left_alone, listed_joints

PROMPTS = {
    "kitchen": (
        "a kitchen with base cabinets, wall cabinets, a fridge, an oven and a dishwasher",
        6,
    ),
    "bedroom": ("a bedroom with a wardrobe, a dresser and two nightstands", 3),
}


@pytest.fixture(scope="module")
def scenes(tmp_path_factory: pytest.TempPathFactory, default_library) -> dict[str, Path]:
    out = {}
    for name, (prompt, _) in PROMPTS.items():
        folder = tmp_path_factory.mktemp("articulated") / name
        options = GenerateOptions(library=default_library.root, seed=0, render=False)
        result = generate_scene(prompt, folder, options)
        assert result.ok, result.report.counts
        out[name] = folder
    return out


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(PROMPTS))
def test_generated_scene_has_articulated_parts_that_open_and_close(
    scenes: dict[str, Path], name: str
) -> None:
    folder = scenes[name]
    joints = listed_joints(folder)
    assert len(joints) >= PROMPTS[name][1], [j["name"] for j in joints]
    report = json.loads((folder / "report.json").read_text())
    assert report["ok"]
    model = mujoco.MjModel.from_xml_path(str(folder / "scene.xml"))
    moved = left_alone(model, joints)
    assert max(moved.values()) < 1e-3, moved  # nothing opens by itself in 2 s
    rest_in = contents(folder, model)
    failures = {}
    for record in joints:
        owner = record["name"].split("/")[0]
        check = check_part(model, record, joints, rest_in.get(owner, set()))
        if check.problems:
            failures[record["name"]] = check.problems
    assert not failures, failures


@pytest.mark.slow
def test_articulated_storage_gets_things_inside(scenes: dict[str, Path]) -> None:
    record = json.loads((scenes["kitchen"] / "generate.json").read_text())
    inside = {r["receptacle"]: r.get("inside", []) for r in record["small_objects"]}
    fridge = [rid for rid in inside if ".fridge_" in rid]
    assert fridge and all(inside[rid] for rid in fridge), inside  # a fridge always gets food
    scene = json.loads((scenes["kitchen"] / "scene.json").read_text())
    objects = {o["id"]: o for o in scene["objects"]}
    listed = json.loads((scenes["kitchen"] / "objects.json").read_text())["objects"]
    boxes = {o["id"]: o["aabb"] for o in listed}
    for rid, ids in inside.items():
        for oid in ids:  # inside: resting on it, wholly within its box (under its top)
            assert objects[oid]["support"] == rid
            low, high = boxes[rid]["min"], boxes[rid]["max"]
            for k in range(3):
                assert low[k] <= boxes[oid]["min"][k] and boxes[oid]["max"][k] <= high[k], oid
