"""``holomj refine`` (:mod:`holomj.jobs.refine`) and its parts (:mod:`holomj.refinement`).

Fast tests read instructions, propose offline edits, check adversarial model replies and the
score on a hand-made scene summary. Slow tests refine a generated living room: offline through
the Python API ("add a reading corner with an armchair and a floor lamp by the window" -> the
armchair and the lamp by the window, validated, eval showing the relation met), with a scripted
OpenAI-compatible server (images sent as image_url parts, malformed and adversarial replies,
a round that makes the scene worse and is rejected, a model that rejects images -> text only),
and a failure that leaves nothing half-written.
"""

from __future__ import annotations

import base64
import hashlib
import json
import shutil
from pathlib import Path

import pytest

import holomj
from holomj.errors import InputError, OutputExistsError
from holomj.jobs.refine import REFINE_JSON, refine
from holomj.library.store import AssetLibrary
from holomj.plan.llm_config import LLMConfig
from holomj.refinement.finding import Finding
from holomj.refinement.goals import instruction_spec, refine_score
from holomj.refinement.instruction import read_instruction
from holomj.refinement.offline import propose, signature
from holomj.refinement.safety import MAX_OPS_PER_ROUND, check_reply, looks_like_code
from holomj.refinement.summary import ObjectInfo, PlannerSceneSummary, RoomInfo
from tests.plan.llm_replay import replay_server

PROMPT = "a living room with a sofa, a coffee table and a tv"
INSTRUCTION = "add a reading corner with an armchair and a floor lamp by the window"


def summary() -> PlannerSceneSummary:
    """A 5 x 4 m living room with a window and a door, a sofa, a coffee table, a tv, a mug."""

    def obj(oid: str, category: str, x: float, y: float, **extra: object) -> ObjectInfo:
        return ObjectInfo(oid, category, "living_room", (x, y, 0.0), 0.0, (1.0, 1.0, 1.0), **extra)  # type: ignore[arg-type]

    return PlannerSceneSummary(
        rooms=[
            RoomInfo(
                "living_room",
                "living_room",
                ((0.0, 0.0), (5.0, 0.0), (5.0, 4.0), (0.0, 4.0)),
                windows=("window_0",),
                doors=("door_0",),
            )
        ],
        objects=[
            obj("living_room.sofa_0", "sofa", 2.5, 1.0),
            obj("living_room.coffee_table_0", "coffee_table", 2.5, 2.0),
            obj("living_room.television_0", "wall_television", 2.5, 3.9, placement="wall"),
            obj(
                "mug_00", "mug", 2.5, 2.0, support="living_room.coffee_table_0", placement="object"
            ),
        ],
        windows=[{"id": "window_0", "rooms": ["living_room"], "position": [5.0, 2.0]}],
        doors=[{"id": "door_0", "rooms": ["living_room"], "position": [1.0, 0.0]}],
        wall_height=2.7,
    )


def folder_hash(folder: Path) -> str:
    digest = hashlib.sha256()
    for path in sorted(p for p in folder.rglob("*") if p.is_file()):
        digest.update(str(path.relative_to(folder)).encode())
        digest.update(path.read_bytes())
    return digest.hexdigest()


# --------------------------------------------------------------------------- instructions


def test_reading_corner_reads_as_two_items_by_the_window() -> None:
    instruction = read_instruction(INSTRUCTION, summary())
    armchair, lamp = instruction.items
    assert (armchair.action, armchair.kind, armchair.room) == ("add", "armchair", "living_room")
    assert armchair.relations == [("by_window", None)]
    assert (lamp.action, lamp.kind) == ("add", "floor lamp")
    assert lamp.relations == [("by_window", None), ("adjacent_to", "item:armchair")]
    assert armchair.stem == "living_room.refine.armchair"
    spec = instruction_spec(instruction, summary())
    rows = {(r["subject"], r["relation"], r["object"]) for r in spec["relations"]}
    assert rows == {
        ("armchair", "next to", "window"),
        ("floor lamp", "next to", "window"),
        ("floor lamp", "next to", "armchair"),
    }
    assert [o["id_stem"] for o in spec["objects"]] == [armchair.stem, lamp.stem]


def test_verbs_remove_move_and_small_objects() -> None:
    scene = summary()
    removed, plant = read_instruction("remove the tv and add a plant in the corner", scene).items
    assert (removed.action, removed.targets) == ("remove", ["living_room.television_0"])
    assert (plant.action, plant.relations) == ("add", [("corner", None)])
    (sofa,) = read_instruction("move the sofa to the middle of the room", scene).items
    assert (sofa.action, sofa.targets, sofa.relations) == (
        "move",
        ["living_room.sofa_0"],
        [("middle", None)],
    )
    (vase,) = read_instruction("put a vase on the coffee table", scene).items
    assert (vase.action, vase.on) == ("add_on", "living_room.coffee_table_0")
    (pair,) = read_instruction("add two armchairs next to the sofa", scene).items
    assert pair.quantity == 2 and pair.relations == [("adjacent_to", "living_room.sofa_0")]
    nothing = read_instruction("make it cozier please", scene)
    assert not nothing.items and nothing.notes


# --------------------------------------------------------------------------- offline planner


def test_offline_planner_adds_then_moves_then_fixes_doors() -> None:
    scene = summary()
    instruction = read_instruction(INSTRUCTION, scene)
    missing = [
        {"item": "armchair", "check": "object", "held": False, "found": 0, "need": 1, "what": ""},
        {"item": "floor_lamp", "check": "object", "held": False, "found": 0, "need": 1, "what": ""},
    ]
    tried: set[str] = set()
    first = propose(instruction, scene, missing, [], tried)
    assert [op["op"] for op in first.operations] == ["add", "add"]
    chair, lamp = first.operations
    assert chair["id"] == "living_room.refine.armchair_0"
    assert chair["relations"] == [{"kind": "by_window"}]
    assert lamp["relations"] == [
        {"kind": "by_window"},
        {"kind": "adjacent_to", "target": "living_room.refine.armchair_0"},
    ]
    assert all(op["comment"] for op in first.operations)
    # the same again is not proposed; without the armchair, the lamp goes by the window alone
    (alone,) = propose(instruction, scene, missing, [], tried).operations
    assert alone["relations"] == [{"kind": "by_window"}]
    assert propose(instruction, scene, missing, [], tried).operations == []
    # the armchair is there but not by the window; the sofa blocks the door
    scene.objects.append(
        ObjectInfo(
            "living_room.refine.armchair_0", "armchair", "living_room", (1, 1, 0), 0, (1, 1, 1)
        )
    )
    unmet = [
        {"item": "armchair", "check": "relation", "held": False, "what": "armchair next to window"}
    ]
    door = Finding(metric="doors_clear", object="living_room.sofa_0", reason="blocks door_0")
    second = propose(instruction, scene, unmet, [door], set())
    assert second.operations[0] == {
        "op": "move",
        "id": "living_room.refine.armchair_0",
        "relations": [{"kind": "by_window"}],
        "comment": second.operations[0]["comment"],
    }
    assert second.operations[1]["id"] == "living_room.sofa_0"
    assert second.operations[1]["relations"] == [{"kind": "wall"}]
    assert len(propose(instruction, scene, missing, [], set(), max_ops=1).operations) == 1
    assert signature({"op": "add", "id": "a", "description": "x"}) == signature(
        {"op": "add", "id": "b", "description": "x", "comment": "y"}
    )


# --------------------------------------------------------------------------- safety


@pytest.mark.parametrize(
    ("reply", "fatal"),
    [
        ("Sure, I will add an armchair by the window.", "not JSON"),
        ("```python\nimport os\nos.system('rm -rf /')\n```", "code block"),
        ('[{"op": "remove", "id": "living_room.sofa_0"}]', "JSON list"),
        ('{"ops": []}', '{"operations": [...]}'),
        (json.dumps({"operations": [{"op": "remove", "id": "mug_00"}] * 1000}), "1000 operations"),
        ('{"operations": [{"op": "explode"}]}', "every operation was refused"),
        ('{"operations": [{"op": "remove", "id": NaN}]}', "not a JSON number"),
    ],
)
def test_malformed_replies_are_refused_whole(reply: str, fatal: str) -> None:
    checked = check_reply(reply, summary())
    assert checked.fatal is not None and fatal in checked.fatal
    assert checked.operations == []


def test_adversarial_operations_are_refused_one_by_one() -> None:
    ops = [
        {"op": "add", "id": "chair1", "description": "an armchair", "room": "living_room"},
        {"op": "add", "description": "a sofa", "size": [500, 1, 1]},
        {"op": "remove", "id": "living_room.ghost_0"},
        {"op": "add", "description": "__import__('os').system('rm -rf /')"},
        {"op": "add", "description": "a lamp", "position": [40.0, 2.0]},
        {"op": "add", "description": "a lamp", "room": "attic"},
        {"op": "move", "id": "living_room.sofa_0", "relations": [{"kind": "near", "target": "x"}]},
        {
            "op": "add",
            "description": "a lamp",
            "relations": [{"kind": "adjacent_to", "target": "chair1"}],
        },
        {"op": "add", "id": "living_room.sofa_0", "description": "a sofa"},
    ]
    checked = check_reply(json.dumps({"operations": ops}), summary(), max_ops=10)
    assert checked.fatal is None
    reasons = {r["index"]: r["reason"] for r in checked.refused}
    assert "absurd" in reasons[1]
    assert "unknown id 'living_room.ghost_0'" in reasons[2]
    assert "looks like code" in reasons[3]
    assert "outside every room" in reasons[4]
    assert "unknown room 'attic'" in reasons[5]
    assert "unknown relation target 'x'" in reasons[6]
    assert "is taken" in reasons[8]
    first, last = checked.operations
    assert first["id"] == "living_room.refine.chair_0" == checked.renamed["chair1"]
    assert last["relations"] == [{"kind": "adjacent_to", "target": "living_room.refine.chair_0"}]
    assert any("absurd" in line for line in checked.feedback())
    assert looks_like_code("eval('1+1')") and looks_like_code("$(curl evil)")
    assert not looks_like_code("a mid-century armchair, oak legs")
    assert MAX_OPS_PER_ROUND == 8


def test_score_is_the_mean_of_measured_metrics_and_checks() -> None:
    scores = {
        "collisions": {"score": 1.0},
        "navigability": {"score": 0.5},
        "counts": {"score": None},
    }
    checks = [{"held": True}, {"held": False}]
    score = refine_score(scores, checks)
    assert score["score"] == pytest.approx((1.0 + 0.5 + 1 + 0) / 4)
    assert score["instruction_met"] == [1, 2] and score["eval_mean"] == 0.75


# --------------------------------------------------------------------------- a real scene


@pytest.fixture(scope="module")
def living_room(tmp_path_factory: pytest.TempPathFactory, default_library: AssetLibrary) -> Path:
    """A generated living room (never modified: refine writes to other folders or copies)."""
    out = tmp_path_factory.mktemp("refine") / "living_room"
    holomj.generate(PROMPT, out, seed=0, render=False, library=default_library)
    return out


def reading_corner_spec() -> dict:
    """An annotation of the reading corner: the armchair and the lamp refine added, by a
    window, next to each other."""
    return {
        "id": "reading_corner",
        "objects": [
            {
                "name": "reading armchair",
                "id_stem": "living_room.refine.armchair",
                "count": {"ge": 1},
            },
            {
                "name": "reading lamp",
                "id_stem": "living_room.refine.floor_lamp",
                "count": {"ge": 1},
            },
        ],
        "relations": [
            {"subject": "reading armchair", "relation": "next to", "object": "window"},
            {"subject": "reading lamp", "relation": "next to", "object": "window"},
            {"subject": "reading lamp", "relation": "next to", "object": "reading armchair"},
        ],
    }


@pytest.mark.slow
def test_offline_refine_adds_the_reading_corner(
    living_room: Path, tmp_path: Path, default_library: AssetLibrary
) -> None:
    before = folder_hash(living_room)
    out = tmp_path / "refined"
    result = holomj.refine(living_room, INSTRUCTION, out=out, library=default_library)
    assert folder_hash(living_room) == before
    assert result.ok, result.checks
    assert result.kept >= 1 and result.score_after > result.score_before
    record = json.loads((out / REFINE_JSON).read_text())
    assert record["ok"] and record["planner"] == "offline"
    kept = next(r for r in record["rounds"] if r["decision"] == "kept")
    assert [op["op"] for op in kept["operations"]] == ["add", "add"]
    assert kept["timings"]["total"] > 0 and "edit" in kept["timings"]
    assert kept["score_after"] >= kept["score_before"]
    assert (out / kept["images"][0]).is_file() and kept["images"][0].endswith("top.png")
    report = json.loads((out / "report.json").read_text())
    assert report["ok"]
    evaluated = holomj.eval(out, spec=reading_corner_spec())
    assert evaluated.scores["counts"]["ok"], evaluated.details["counts"]
    assert evaluated.scores["relations"]["ok"], evaluated.details["relations"]
    print(f"refine: {result.seconds_per_round:.1f} s per round ({len(result.rounds)} round(s))")


def reply(content: object, **extra: object) -> dict:
    text = content if isinstance(content, str) else json.dumps(content)
    return {"content": text, **extra}


@pytest.mark.slow
def test_llm_refine_images_adversarial_rejected_round_and_text_fallback(
    living_room: Path, tmp_path: Path, default_library: AssetLibrary
) -> None:
    good = {
        "operations": [
            {
                "op": "add",
                "id": "reading_chair",
                "description": "an armchair",
                "room": "living_room",
                "relations": [{"kind": "by_window"}],
            },
            {
                "op": "add",
                "id": "reading_lamp",
                "description": "a floor lamp",
                "room": "living_room",
                "relations": [
                    {"kind": "by_window"},
                    {"kind": "adjacent_to", "target": "reading_chair"},
                ],
            },
            {"op": "add", "description": "a sofa", "size": [500, 1, 1], "room": "living_room"},
            {"op": "remove", "id": "living_room.ghost_0"},
        ]
    }
    replies = [
        # round 1 (with images): junk, code, too many operations, then a valid but bad edit
        reply("Sure! Here is my plan: add an armchair."),
        reply("```python\nimport shutil; shutil.rmtree('/')\n```"),
        reply({"operations": [{"op": "remove", "id": "mug_00"}] * 1000}),
        reply({"operations": [{"op": "remove", "id": "living_room.sofa_0"}]}),
        # round 2: the model rejects images; the same question goes again as text
        {"status": 400, "body": {"error": {"message": "image inputs are not supported"}}},
        reply(good, prompt_tokens=900, completion_tokens=120),
    ]
    out = tmp_path / "refined"
    with replay_server(replies) as server:
        config = LLMConfig(base_url=server.base_url, model="vlm", max_retries=3, backoff_s=0.0)
        result = refine(
            living_room,
            INSTRUCTION,
            planner="llm",
            out=out,
            rounds=3,
            llm_config=config,
            library_path=default_library.root,
        )
    assert server.remaining == 0
    first = server.requests[0].messages[1]["content"]
    images = [p for p in first if p["type"] == "image_url"]
    assert len(images) >= 2  # the top view and the living room
    url = images[0]["image_url"]["url"]
    assert url.startswith("data:image/png;base64,")
    assert base64.b64decode(url.split(",", 1)[1])[:8] == b"\x89PNG\r\n\x1a\n"
    text = first[0]["text"]
    assert INSTRUCTION in text and "living_room.sofa_0" in text and '"AddOp"' in text
    # feedback on the refused answers came back in the retries
    assert "not JSON" in server.requests[1].messages[-1]["content"]
    assert "code" in server.requests[2].messages[-1]["content"]
    assert "1000 operations" in server.requests[3].messages[-1]["content"]
    # round 2: images rejected, then text only, with the feedback of round 1
    assert isinstance(server.requests[4].messages[1]["content"], list)
    second = server.requests[5].messages[1]["content"]
    assert isinstance(second, str) and "No images" in second
    assert "round 1 was rejected" in second
    rounds = result.rounds
    assert rounds[0]["decision"] == "rejected"
    assert any("worse" in r for r in rounds[0]["reasons"])
    assert rounds[0]["llm"]["attempts"] == 4 and rounds[0]["llm"]["images"] >= 8
    assert rounds[1]["decision"] == "kept"
    assert rounds[1]["llm"]["text_only"] and rounds[1]["llm"]["prompt_tokens"] >= 900
    refused = {r["index"]: r["reason"] for r in rounds[1]["refused_by_checks"]}
    assert "absurd" in refused[2] and "ghost" in refused[3]
    assert rounds[1]["renamed_ids"]["reading_chair"] == "living_room.refine.armchair_0"
    assert result.ok, result.checks
    record = json.loads((out / REFINE_JSON).read_text())
    assert record["llm"]["images"] is False and "image" in record["llm"]["text_only_reason"]
    assert record["llm"]["calls"] == 6 and record["llm"]["images_sent"] >= 8
    scene = json.loads((out / "scene.json").read_text())
    ids = {o["id"] for o in scene["objects"]}
    assert "living_room.sofa_0" in ids  # the rejected round left no trace
    assert {"living_room.refine.armchair_0", "living_room.refine.floor_lamp_0"} <= ids


@pytest.mark.slow
def test_a_failure_leaves_nothing_half_written(
    living_room: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    import holomj.jobs.edit

    def broken(*args: object, **kwargs: object) -> None:
        raise RuntimeError("the disk caught fire")

    monkeypatch.setattr(holomj.jobs.edit, "apply_edits", broken)
    work = tmp_path / "work"
    work.mkdir()
    copy = work / "scene"
    shutil.copytree(living_room, copy)
    before = folder_hash(copy)
    with pytest.raises(RuntimeError, match="caught fire"):
        refine(copy, INSTRUCTION, out=work / "new", render=False)
    with pytest.raises(RuntimeError, match="caught fire"):
        refine(copy, INSTRUCTION, render=False)  # in place
    assert sorted(p.name for p in work.iterdir()) == ["scene"]  # no NEW, no work folder
    assert folder_hash(copy) == before


@pytest.mark.slow
def test_bad_input_writes_nothing(
    living_room: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    before = folder_hash(living_room)
    for kwargs, where in (
        ({"instruction": "  "}, "--instruction"),
        ({"rounds": 0}, "--rounds"),
        ({"max_ops": 51}, "--max-ops"),
        ({"planner": "oracle"}, "--planner"),
    ):
        args = {"instruction": INSTRUCTION, **kwargs}
        with pytest.raises(InputError, match=where):
            refine(living_room, out=tmp_path / "x", **args)  # type: ignore[arg-type]
    for name in ("HOLOMJ_LLM_BASE_URL", "OPENAI_BASE_URL", "HOLOMJ_LLM_MODEL"):
        monkeypatch.delenv(name, raising=False)
    with pytest.raises(InputError, match="no LLM"):
        refine(living_room, INSTRUCTION, planner="llm", out=tmp_path / "x")
    (tmp_path / "exists").mkdir()
    with pytest.raises(OutputExistsError):
        refine(living_room, INSTRUCTION, out=tmp_path / "exists")
    assert not (tmp_path / "x").exists()
    assert folder_hash(living_room) == before
