"""The fidelity scorer (scripts/eval/score.py, a command line over holomj.evaluation) on small
scenes written by hand.

Scenes are hand-written scene.json files of ``builtin:box`` objects compiled with ``holomj
compile`` (no planner involved); the scorer labels a box by the noun of its id
(``bedroom.bed_0`` -> ``bed``). Every verdict below follows from the geometry written here.
"""

from __future__ import annotations

import ast
import copy
import importlib.util
import json
import shutil
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest

ROOT = Path(__file__).resolve().parents[2]
EVAL = ROOT / "scripts" / "eval"
HOLOMJ = Path(sys.executable).parent / "holomj"


def _load_score() -> Any:
    spec = importlib.util.spec_from_file_location("fidelity_score_under_test", EVAL / "score.py")
    module = importlib.util.module_from_spec(spec)
    assert spec.loader is not None
    sys.modules[spec.name] = module
    spec.loader.exec_module(module)
    return module


score = _load_score()


def box(
    oid: str, room: str, xy: tuple[float, float], size: tuple[float, float, float], **extra: Any
) -> dict[str, Any]:
    """A builtin:box object whose footprint centre is ``xy`` (bottom at z = 0 unless given)."""
    z = extra.pop("z", 0.0)
    return {
        "id": f"{room}.{oid}",
        "asset": "builtin:box",
        "position": [xy[0], xy[1], z],
        "scale": list(size),
        "room": room,
        **extra,
    }


# A 4 x 4 m bedroom beside a 2.5 x 4 m bathroom; entrance on the bedroom's south wall.
BEDROOM_SCENE: dict[str, Any] = {
    "schema_version": "1.0",
    "name": "bedroom_bath",
    "rooms": [
        {"id": "bedroom", "type": "bedroom", "polygon": [[0, 0], [4, 0], [4, 4], [0, 4]]},
        {"id": "bathroom", "type": "bathroom", "polygon": [[4, 0], [6.5, 0], [6.5, 4], [4, 4]]},
    ],
    "doors": [
        {"id": "front", "kind": "doorway", "rooms": ["bedroom"], "position": [2.0, 0.0]},
        {"id": "inner", "kind": "doorway", "rooms": ["bedroom", "bathroom"], "position": [4, 2]},
    ],
    "windows": [
        {
            "id": "win",
            "kind": "fixed",
            "rooms": ["bedroom"],
            "position": [2.0, 4.0],
            "width": 1.2,
            "height": 1.0,
            "base_height": 0.9,
        }
    ],
    "objects": [
        # Headboard (back, -X) against the west wall, foot towards +X.
        box("bed_0", "bedroom", (1.05, 2.0), (2.0, 1.4, 0.5)),
        box("nightstand_0", "bedroom", (0.25, 3.0), (0.4, 0.4, 0.5)),
        # Facing -Y (yaw 270): back against the north wall, in the north-east corner.
        box("wardrobe_0", "bedroom", (3.3, 3.7), (0.6, 1.2, 2.0), yaw_deg=270),
        # Right inside the entrance: covers the front door's zone.
        box("armchair_0", "bedroom", (2.0, 0.5), (0.6, 0.6, 0.8), yaw_deg=90),
        box("toilet_0", "bathroom", (6.1, 3.5), (0.6, 0.4, 0.8), yaw_deg=180),
    ],
}

# A 5 x 4 m living room: sofa and TV face each other across a coffee table.
LIVING_SCENE: dict[str, Any] = {
    "schema_version": "1.0",
    "name": "living",
    "rooms": [
        {"id": "living_room", "type": "living_room", "polygon": [[0, 0], [5, 0], [5, 4], [0, 4]]}
    ],
    "doors": [{"id": "front", "kind": "doorway", "rooms": ["living_room"], "position": [2.5, 0]}],
    "objects": [
        box("sofa_0", "living_room", (0.5, 2.0), (0.9, 2.0, 0.8)),
        box("tv_0", "living_room", (4.8, 2.0), (0.3, 1.2, 0.8), yaw_deg=180),
        box("coffee_table_0", "living_room", (2.0, 2.0), (0.6, 1.0, 0.4)),
        box("floor_lamp_0", "living_room", (0.25, 3.75), (0.4, 0.4, 1.6)),
        box("dining_table_0", "living_room", (3.5, 3.0), (1.2, 0.8, 0.75)),
        box("dining_chair_0", "living_room", (2.6, 3.0), (0.45, 0.45, 0.9)),
        box("dining_chair_1", "living_room", (4.4, 3.0), (0.45, 0.45, 0.9), yaw_deg=180),
        box("painting_0", "living_room", (0.02, 2.0), (0.03, 0.8, 0.6), z=1.2, static=True),
        box(
            "book_0",
            "living_room",
            (2.0, 2.0),
            (0.2, 0.15, 0.03),
            z=0.4,
            support="living_room.coffee_table_0",
        ),
    ],
}

# A 4 x 3 m room cut in two by a row of crates: the far half is out of the robot's reach.
SPLIT_SCENE: dict[str, Any] = {
    "schema_version": "1.0",
    "name": "split",
    "rooms": [{"id": "garage", "type": "garage", "polygon": [[0, 0], [4, 0], [4, 3], [0, 3]]}],
    "doors": [{"id": "front", "kind": "doorway", "rooms": ["garage"], "position": [1.0, 0]}],
    "objects": [box("crate_0", "garage", (2.0, 1.5), (4.0, 0.4, 1.0))],
}


def compile_scene(scene: dict[str, Any], where: Path, library: Path) -> Path:
    """Write ``scene`` as scene.json and compile it with ``holomj compile``; returns the folder."""
    where.mkdir(parents=True, exist_ok=True)
    src = where / "scene.json"
    src.write_text(json.dumps(scene))
    out = where / "out"
    cmd = [str(HOLOMJ), "compile", str(src), "-o", str(out), "--library", str(library)]
    proc = subprocess.run(
        [*cmd, "--check-seconds", "0", "--quiet"], capture_output=True, text=True, check=False
    )
    assert proc.returncode == 0, proc.stdout + proc.stderr
    return out


@pytest.fixture(scope="module")
def folders(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    """The three scenes, compiled once for the module."""
    if not HOLOMJ.exists():
        pytest.skip(f"no holomj console script at {HOLOMJ}")
    root = tmp_path_factory.mktemp("fidelity")
    library = root / "library"
    library.mkdir()
    (library / "library.json").write_text(
        json.dumps({"schema_version": "1.0", "name": "empty", "assets": {}})
    )
    return {
        name: compile_scene(scene, root / name, library)
        for name, scene in (
            ("bedroom", BEDROOM_SCENE),
            ("living", LIVING_SCENE),
            ("split", SPLIT_SCENE),
        )
    }


def run(folder: Path, **spec: Any) -> dict[str, Any]:
    """Score ``folder`` against an annotation made of ``spec``."""
    return score.score_folder(folder, {"id": "t", "prompt": "t", **spec})


def verdicts(record: dict[str, Any], key: str) -> list[bool]:
    """The held flags of one list of a record."""
    return [row["held"] for row in record[key]]


# ----------------------------------------------------------------------------- counts


def test_counts_eq_ge_rooms_and_room_types(folders: dict[str, Path]) -> None:
    rec = run(
        folders["bedroom"],
        rooms={"eq": 2},
        room_types=[
            {"type": "bedroom", "count": {"eq": 1}},
            {"type": "kitchen", "count": {"ge": 1}},
        ],
        objects=[
            {"name": "bed", "count": {"eq": 1}},
            {"name": "bedside tables", "count": {"eq": 1}},  # synonym + plural of nightstand
            {"name": "nightstand", "count": {"eq": 2}},
            {"name": "chair", "count": {"ge": 1}},  # an armchair is not a chair
            {"name": "toilet", "count": {"eq": 1}, "room": "bathroom"},
            {"name": "toilet", "count": {"eq": 0}, "room": "bedroom"},
        ],
    )
    assert verdicts(rec, "counts") == [True, True, False, True, True, False, False, True, True]
    assert rec["counts"][5]["found"] == 1
    assert rec["summary"]["count"] == [6, 9]
    assert rec["summary"]["room_count"] == [2, 3]


def test_unknown_names_match_proxies_by_their_id(folders: dict[str, Path], tmp_path: Path) -> None:
    folder = tmp_path / "scene"
    shutil.copytree(folders["split"], folder)
    objects = json.loads((folder / "objects.json").read_text())
    objects["objects"][0]["id"] = "garage.arcade_cabinet_0"
    objects["objects"][0]["category"] = None
    (folder / "objects.json").write_text(json.dumps(objects))
    rec = run(folder, objects=[{"name": "arcade cabinets", "count": {"eq": 1}}])
    assert verdicts(rec, "counts") == [True]
    # A proxy labelled with its category later counts the same way.
    objects["objects"][0]["category"] = "arcade_cabinet"
    objects["objects"][0]["id"] = "garage.thing_0"
    (folder / "objects.json").write_text(json.dumps(objects))
    rec = run(folder, objects=[{"name": "arcade cabinet", "count": {"eq": 1}}])
    assert verdicts(rec, "counts") == [True]


# ----------------------------------------------------------------------------- relations


def test_relations_that_hold_and_fail_in_the_bedroom(folders: dict[str, Path]) -> None:
    rels = [
        {"subject": "nightstand", "relation": "next to", "object": "bed"},  # 10 cm apart
        {"subject": "bed", "relation": "against wall", "object": "wall"},
        {"subject": "wardrobe", "relation": "in corner", "object": None},
        {"subject": "wardrobe", "relation": "against wall", "object": "wall"},
        {"subject": "armchair", "relation": "next to", "object": "door"},  # 20 cm from 'front'
        {"subject": "bed", "relation": "under window", "object": "window"},  # west wall
        {"subject": "nightstand", "relation": "in corner", "object": None},  # 80 cm from north
        {"subject": "bed", "relation": "middle", "object": None},
        {"subject": "toilet", "relation": "next to", "object": "bed"},  # other room
        {"subject": "sofa", "relation": "near", "object": "bed"},  # no sofa
    ]
    rec = run(folders["bedroom"], relations=rels)
    assert verdicts(rec, "relations") == [True] * 5 + [False] * 5
    assert "no sofa" in rec["relations"][-1]["reason"]


def test_relations_in_the_living_room(folders: dict[str, Path]) -> None:
    rels = [
        {"subject": "coffee table", "relation": "in front of", "object": "sofa"},
        {"subject": "sofa", "relation": "facing", "object": "tv"},
        {"subject": "tv", "relation": "facing", "object": "couch"},
        {"subject": "sofa", "relation": "across from", "object": "tv"},
        {"subject": "coffee table", "relation": "middle", "object": None},
        {"subject": "floor lamp", "relation": "in corner", "object": None},
        {"subject": "painting", "relation": "above", "object": "sofa"},
        {"subject": "book", "relation": "on", "object": "coffee table"},
        {"subject": "chair", "relation": "around", "object": "dining table"},
        {
            "subject": "dining chair",
            "relation": "facing",
            "object": "dining table",
            "quantifier": "all",
        },
        {"subject": "sofa", "relation": "near", "object": "coffee table"},
        # fail:
        {"subject": "tv", "relation": "in front of", "object": "sofa"},  # 3.5 m away
        {"subject": "coffee table", "relation": "behind", "object": "sofa"},
        {"subject": "sofa", "relation": "facing", "object": "floor lamp"},
        {"subject": "book", "relation": "on", "object": "dining table"},
        {"subject": "painting", "relation": "above", "object": "tv"},
        {"subject": "coffee table", "relation": "against wall", "object": "wall"},
        {"subject": "chair", "relation": "around", "object": "coffee table"},
    ]
    rec = run(folders["living"], relations=rels)
    assert verdicts(rec, "relations") == [True] * 11 + [False] * 7
    assert rec["summary"]["relation"] == [11, 18]


def test_quantifiers(folders: dict[str, Path]) -> None:
    near_wall = {"subject": "dining chair", "relation": "next to", "object": "dining table"}
    lamp = {"subject": "dining chair", "relation": "near", "object": "floor lamp"}
    rec = run(
        folders["living"],
        relations=[
            {**near_wall, "quantifier": "all"},
            {**lamp, "quantifier": "any"},  # chair_0 is 1.95 m from the lamp's footprint
            {**lamp, "quantifier": "all"},
        ],
    )
    assert verdicts(rec, "relations") == [True, False, False]


# ----------------------------------------------------------------------------- absent, defining


def test_absent_objects_rooms_and_openings(folders: dict[str, Path]) -> None:
    rec = run(folders["bedroom"], absent=["tv", "wardrobe", "kitchen", "bathroom", "windows"])
    assert verdicts(rec, "absent") == [True, False, True, False, False]
    rec = run(folders["living"], absent=["window"])
    assert verdicts(rec, "absent") == [True]


def test_defining_furniture_per_room_and_annotated_types(folders: dict[str, Path]) -> None:
    rec = run(folders["bedroom"], defining=["bedroom", "bathroom", "kitchen"])
    rows = {(r["room"], r["room_type"]): r for r in rec["defining"]}
    assert rows[("bedroom", "bedroom")]["held"]
    bath = rows[("bathroom", "bathroom")]
    assert not bath["held"] and "washbasin" in bath["reason"] and "toilet" not in bath["reason"]
    assert not rows[(None, "kitchen")]["held"]
    assert rec["summary"]["defining"] == [1, 3]
    living = run(folders["living"], defining=["living room"])
    assert verdicts(living, "defining") == [True]


# ----------------------------------------------------------------------------- doors, reach


def test_door_covered_by_furniture(folders: dict[str, Path]) -> None:
    rec = run(folders["bedroom"])
    doors = {d["door"]: d for d in rec["doors"]}
    assert not doors["front"]["clear"]
    assert doors["front"]["blocking"][0].startswith("bedroom.armchair_0")
    assert doors["inner"]["clear"]
    assert rec["doors_clear"] is False
    assert run(folders["living"])["doors_clear"] is True


def test_reachability_navmap_and_raster(folders: dict[str, Path], tmp_path: Path) -> None:
    living = run(folders["living"])["reachability"]
    assert living["method"] == "navmap" and living["share"] >= 0.97
    split = run(folders["split"])["reachability"]
    assert split["method"] == "navmap" and 0.3 < split["share"] < 0.6
    folder = tmp_path / "split"
    shutil.copytree(folders["split"], folder)
    (folder / "navmap.json").unlink()
    raster = run(folder)["reachability"]
    assert raster["method"] == "raster"
    assert abs(raster["share"] - split["share"]) < 0.05


def test_validation_from_report(folders: dict[str, Path], tmp_path: Path) -> None:
    assert run(folders["living"])["validation"] == {"ok": False, "reason": "no report.json"}
    folder = tmp_path / "living"
    shutil.copytree(folders["living"], folder)
    (folder / "report.json").write_text(json.dumps({"ok": True, "objects": []}))
    assert run(folder)["validation"]["ok"] is True
    (folder / "report.json").write_text(
        json.dumps({"ok": False, "objects": [{"id": "living_room.sofa_0", "stable": False}]})
    )
    validation = run(folder)["validation"]
    assert validation["ok"] is False and "living_room.sofa_0" in validation["reason"]


# ----------------------------------------------------------------------------- attributes


def test_attributes_of_plain_boxes(folders: dict[str, Path]) -> None:
    rec = run(
        folders["bedroom"],
        objects=[
            {"name": "wardrobe", "count": {"eq": 1}, "attributes": {"shape": "tall"}},
            {"name": "bed", "count": {"eq": 1}, "attributes": {"shape": "rectangular"}},
            {"name": "nightstand", "count": {"eq": 1}, "attributes": {"shape": "square"}},
            {"name": "bed", "count": {"eq": 1}, "attributes": {"shape": "round"}},
            {"name": "bed", "count": {"eq": 1}, "attributes": {"color": "red"}},
            {"name": "bed", "count": {"eq": 1}, "attributes": {"material": "oak"}},
        ],
    )
    assert verdicts(rec, "attributes") == [True, True, True, False, False, False]


def test_colour_and_material_from_asset_metadata(tmp_path: Path) -> None:
    vocab = score.Vocabulary.load()
    meta = {
        "description": "a navy blue desk with black metal legs",
        "visual": [{"mesh": "navy_lacquer.obj", "rgba": [0.16, 0.21, 0.32, 1.0]}],
    }
    obj = score.EvaluatedObject(
        id="d",
        labels={"desk"},
        room=None,
        fp=score.box(0, 0, 1, 1),
        center=(0.5, 0.5),
        yaw=0.0,
        zmin=0.0,
        zmax=0.75,
        support=None,
        meta=meta,
    )
    assert score.object_colours(obj, vocab) == {"blue"}  # not black: the legs are a side note
    assert "painted" in score.object_materials(obj, vocab)
    meta["description"] = "a oak bookshelf with six open shelves"
    meta["visual"] = [{"mesh": "oak.obj", "rgba": [0.66, 0.49, 0.31, 1.0]}]
    assert score.object_colours(obj, vocab) == {"brown"}
    assert score.object_materials(obj, vocab) == {"wood"}
    assert score.rgba_colour([0.95, 0.95, 0.95]) == "white"
    assert score.rgba_colour([0.05, 0.05, 0.05]) == "black"
    assert score.rgba_colour([0.8, 0.1, 0.1]) == "red"


# ----------------------------------------------------------------------------- vocabulary, CLI


def test_vocabulary_names_synonyms_and_plurals() -> None:
    vocab = score.Vocabulary.load()
    assert vocab.resolve("bookcases") == {"bookshelf"}
    assert vocab.resolve("couch") == {"sofa"}
    assert vocab.resolve("TV") == {"television", "wall_television"}
    assert vocab.resolve("shelves") >= {"shelving_unit", "bookshelf"}
    assert "telescope" in vocab.resolve("telescopes")
    assert vocab.resolve("grand piano") == {"piano"}
    assert vocab.room_canonical("ensuite") == "bathroom"


# The scorer may use holomj's evaluation package (and what that may import), never the planner.
ALLOWED_HOLOMJ = (
    "holomj.evaluation",
    "holomj.spec",
    "holomj.errors",
    "holomj.version",
    "holomj.file_names",
    "holomj.data",
)


def test_cli_prints_a_record_and_imports_no_planner(folders: dict[str, Path]) -> None:
    spec = {"id": "x", "prompt": "p", "objects": [{"name": "sofa", "count": {"eq": 1}}]}
    code = (
        "import runpy, sys, json\n"
        f"sys.argv = ['score.py', {str(folders['living'])!r}, '--spec', {json.dumps(spec)!r}]\n"
        "try:\n"
        f"    runpy.run_path({str(EVAL / 'score.py')!r}, run_name='__main__')\n"
        "except SystemExit as e:\n"
        "    assert not e.code, e.code\n"
        f"allowed = {ALLOWED_HOLOMJ!r}\n"
        "bad = sorted(m for m in sys.modules if m.split('.')[0] == 'holomj' and m != 'holomj'\n"
        "             and not any(m == a or m.startswith(a + '.') for a in allowed))\n"
        "assert not bad, bad\n"
    )
    proc = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=False, cwd=ROOT
    )
    assert proc.returncode == 0, proc.stderr
    record = json.loads(proc.stdout)
    assert record["id"] == "x" and record["summary"]["count"] == [1, 1]


def test_scorer_source_imports_only_holomj_evaluation() -> None:
    for path in (EVAL / "score.py", ROOT / "scripts" / "bench_fidelity.py"):
        tree = ast.parse(path.read_text())
        for node in ast.walk(tree):
            names = []
            if isinstance(node, ast.Import):
                names = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom):
                names = [node.module or ""]
            ours = [n for n in names if n.split(".")[0] == "holomj"]
            assert all(n.startswith("holomj.evaluation") for n in ours), (path, names)


# ----------------------------------------------------------------------------- the dev set


def test_dev_set_is_well_formed() -> None:
    prompts = score.load_specs(str(EVAL / "prompts_dev.jsonl"))
    vocab = score.Vocabulary.load()
    assert len(prompts) >= 120
    assert len({p["id"] for p in prompts}) == len(prompts)
    assert len({p["prompt"] for p in prompts}) == len(prompts)
    assert {p["difficulty"] for p in prompts} == {"easy", "medium", "hard"}
    assert len({p["scene_type"] for p in prompts}) >= 12
    for p in prompts:
        assert set(p) >= {"id", "prompt", "difficulty", "scene_type", "rooms", "objects"}, p["id"]
        assert not p["prompt"].startswith("#") and "\n" not in p["prompt"]
        counts = [p["rooms"]] + [o["count"] for o in p["objects"]]
        counts += [t["count"] for t in p.get("room_types", [])]
        for count in counts:
            assert len(count) == 1 and next(iter(count)) in ("eq", "ge"), p["id"]
            assert isinstance(next(iter(count.values())), int), p["id"]
        for o in p["objects"]:
            assert set(o.get("attributes") or {}) <= {"color", "material", "shape"}, p["id"]
            attrs = o.get("attributes") or {}
            if "color" in attrs:
                assert vocab.colour_words(attrs["color"]), (p["id"], attrs)
            if "material" in attrs:
                assert vocab.material_words(attrs["material"]), (p["id"], attrs)
            if "shape" in attrs:
                assert attrs["shape"] in vocab.shapes, (p["id"], attrs)
            if o.get("room"):
                assert vocab.room_canonical(o["room"]), (p["id"], o)
        names = {score.normalise(o["name"]) for o in p["objects"]}
        for rel in p.get("relations", []):
            assert rel["relation"] in score.RELATIONS, (p["id"], rel)
            assert score.normalise(rel["subject"]) in names, (p["id"], rel)
            target = rel.get("object")
            if target and target not in ("wall", "window", "door"):
                assert score.normalise(target) in names, (p["id"], rel)
        for name in p.get("defining", []):
            assert score.normalise(name) in vocab.defining, (p["id"], name)


def test_dev_set_names_are_all_in_the_vocabulary() -> None:
    """Every annotated name is an entry (or synonym) of the vocabulary, not a guess."""
    prompts = score.load_specs(str(EVAL / "prompts_dev.jsonl"))
    vocab = score.Vocabulary.load()
    missing = set()
    for p in prompts:
        for name in [o["name"] for o in p["objects"]] + p.get("absent", []):
            if name in ("window", "door") or vocab.room_canonical(name):
                continue
            if vocab.canonical(name) is None:
                missing.add(name)
    assert not missing, sorted(missing)


def test_spec_copy_is_not_mutated(folders: dict[str, Path]) -> None:
    spec = {"id": "t", "prompt": "t", "objects": [{"name": "bed", "count": {"eq": 1}}]}
    before = copy.deepcopy(spec)
    score.score_folder(folders["bedroom"], spec)
    assert spec == before
