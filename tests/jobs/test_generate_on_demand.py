"""End to end: a prompt naming a category the library lacks and a colour gets both, honestly."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from asset_pipeline.procedural.attributes import COLOURS
from holomj.jobs.generate import GenerateOptions, generate_scene
from holomj.library.store import AssetLibrary
from tests.asset_pipeline.look_helpers import shows

PROMPT = "a home gym with a treadmill and a pink sofa"


@pytest.mark.slow
def test_home_gym_with_a_treadmill_and_a_pink_sofa(tmp_path: Path, default_library) -> None:
    library_root = tmp_path / "library"  # a copy: the session's library stays as built
    shutil.copytree(default_library.root, library_root)
    out = tmp_path / "gym"
    result = generate_scene(
        PROMPT, out, GenerateOptions(library=library_root, seed=0, render=False)
    )
    assert result.ok
    record = json.loads((out / "generate.json").read_text())
    rows = {r.get("instance", r.get("name")): r for r in record["retrieval"]}
    treadmill = rows["treadmill-0"]
    # a treadmill, whether the library has one, a generator makes one or it is a proxy
    assert treadmill["category"] == "treadmill"
    assert treadmill["how"] in ("library", "synthesised", "proxy")
    assert treadmill["proxy"] == (treadmill["how"] == "proxy")
    sofa = rows["sofa-0"]
    assert sofa["attributes_asked"]["colour"] == "pink"
    assert sofa["attributes_honoured"]["colour"] == "pink"
    assert not any("every floor asset was scored" in n for n in record["notes"])

    objects = {o["id"]: o for o in json.loads((out / "objects.json").read_text())["objects"]}
    assert objects["home_gym.treadmill_0"]["category"] == "treadmill"
    assert objects["home_gym.treadmill_0"]["proxy"] == treadmill["proxy"]
    library = AssetLibrary.open(library_root)
    sofa_meta = library.get(objects["home_gym.sofa_0"]["asset"]).meta
    assert sofa_meta.category == "sofa" and "pink" in sofa_meta.description
    assert any(shows(v, COLOURS["pink"]) for v in sofa_meta.visual)  # tinted where textured
    # the scene folder is self-contained: its own library holds the synthesised assets
    scene_assets = AssetLibrary.open(out / "assets")
    assert objects["home_gym.sofa_0"]["asset"] in scene_assets

    # the same request again reuses the synthesised assets and writes the same scene
    again = tmp_path / "gym2"
    generate_scene(PROMPT, again, GenerateOptions(library=library_root, seed=0, render=False))
    assert (again / "scene.xml").read_bytes() == (out / "scene.xml").read_bytes()


@pytest.mark.slow
def test_proxy_objects_are_flagged(tmp_path: Path, default_library) -> None:
    from holomj.spec.scene import SceneSpec

    library_root = tmp_path / "library"
    shutil.copytree(default_library.root, library_root)
    library = AssetLibrary.open(library_root)
    from holomj.jobs.synthesis import LibrarySynthesiser

    made = LibrarySynthesiser(library).proxy("moon_rover", (1.0, 1.5, 1.0), "floor", {})
    from holomj.jobs.generate_stages import mark_proxies

    scene = SceneSpec.model_validate(
        {
            "name": "s",
            "rooms": [{"id": "r", "polygon": [[0, 0], [4, 0], [4, 4], [0, 4]]}],
            "objects": [
                {"id": "rover", "asset": made.asset_id, "position": [2, 2, 0], "room": "r"}
            ],
        }
    )
    marked = mark_proxies(scene, library)
    assert marked.objects[0].proxy is True
    dumped = marked.model_dump(mode="json", exclude_none=True)
    assert dumped["objects"][0]["proxy"] is True
