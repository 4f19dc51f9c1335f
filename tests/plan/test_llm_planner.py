"""The LLM planner end to end against a loopback server replaying recorded conversations."""

from __future__ import annotations

import copy
import json
import socket
import time
from pathlib import Path
from typing import Any

import pytest

from holomj.errors import HolomjError
from holomj.layout.constraints import parse_constraint_text
from holomj.plan.llm import LLMPlannerError, plan_llm
from holomj.plan.llm_config import LLMConfig
from holomj.spec.plan import PlanRoom, ScenePlan
from tests.plan.llm_replay import ReplayServer, load_conversation, replay_server

CATEGORIES = (
    "armchair", "bathtub", "bed", "cabinet", "chair", "counter", "desk", "fridge", "lamp",
    "shelf", "sink", "sofa", "table", "toilet",
)  # fmt: skip
API_KEY = "sk-test-123"


def config_for(server: ReplayServer | str, **overrides: Any) -> LLMConfig:
    """A config pointing at ``server`` with fast retries."""
    base_url = server if isinstance(server, str) else server.base_url
    settings: dict[str, Any] = {
        "model": "test-model",
        "api_key": API_KEY,
        "timeout_s": 5.0,
        "max_retries": 2,
        "backoff_s": 0.0,
        **overrides,
    }
    return LLMConfig(base_url=base_url, **settings)


def offline_stub(prompt: str, seed: int) -> ScenePlan:
    """Stands in for the offline planner: a one-room plan."""
    return ScenePlan(
        prompt=prompt,
        planner="offline",
        seed=seed,
        scene_type="room",
        rooms=[PlanRoom(id="room", type="living_room")],
        notes=["offline stub plan"],
    )


def run(name: str, replies: list[dict[str, Any]] | None = None, **kwargs: Any) -> dict[str, Any]:
    """Plan the recorded conversation ``name`` (or its ``replies`` as modified by a test)."""
    conversation = load_conversation(name)
    log: list[str] = []
    config_overrides = kwargs.pop("config", {})
    with replay_server(replies or conversation["replies"]) as server:
        start = time.monotonic()
        try:
            plan = plan_llm(
                conversation["prompt"],
                conversation["seed"],
                config=config_for(server, **config_overrides),
                categories=CATEGORIES,
                log=log.append,
                **kwargs,
            )
        finally:
            elapsed = time.monotonic() - start
        return {
            "plan": plan,
            "requests": server.requests,
            "log": log,
            "remaining": server.remaining,
            "elapsed": elapsed,
        }


def replies_of(name: str) -> list[dict[str, Any]]:
    """A copy of a recorded conversation's replies, for a test to inject faults into."""
    return copy.deepcopy(load_conversation(name)["replies"])


def obj(plan: ScenePlan, room: str, name: str):
    """The plan object ``name`` of ``room``."""
    return next(o for o in plan.room(room).objects if o.name == name)


# --------------------------------------------------------------------------- good conversations


def test_studio_conversation_makes_the_expected_plan() -> None:
    result = run("studio_reading_nook")
    plan: ScenePlan = result["plan"]
    assert plan.planner == "llm"
    assert (plan.prompt, plan.seed) == ("a small studio apartment with a reading nook", 7)
    assert plan.scene_type == "studio apartment"
    assert plan.style == ["cozy", "warm"]
    assert plan.wall_height == 2.6
    assert plan.entrance_room == "studio"
    assert [r.id for r in plan.rooms] == ["studio", "bathroom"]
    studio, bathroom = plan.rooms
    assert studio.size == (6.2, 4.8)
    assert studio.adjacent_to == ["bathroom"]
    assert studio.floor_material == "honey oak planks"
    assert (studio.windows.count, studio.windows.kind) == (2, "hung")
    assert (bathroom.windows.count, bathroom.windows.kind) == (1, "fixed")
    # The bathroom asked for 2.2 x 2.0 m: clamped to the 2.5 m minimum, with notes.
    assert bathroom.size == (2.5, 2.5)
    assert any("'bathroom': width 2.2 m clamped to 2.5 m" in n for n in plan.notes)
    assert any("'bathroom': depth 2 m clamped to 2.5 m" in n for n in plan.notes)

    names = [o.name for o in studio.objects]
    assert "reading armchair" in names  # "Reading Armchair" normalised
    bed = obj(plan, "studio", "bed")
    assert bed.size == (1.6, 2.05, 0.9)  # centimetres -> metres
    assert bed.category == "bed"
    assert [(s.name, s.quantity) for s in bed.on_top] == [("pillow", 2)]
    chairs = obj(plan, "studio", "dining chair")
    assert (chairs.quantity, chairs.variance, chairs.category) == (2, "same", "chair")
    painting = obj(plan, "studio", "painting")
    assert (painting.placement, painting.above) == ("wall", "bed")
    shelf = obj(plan, "studio", "bookshelf")
    assert [(s.name, s.quantity, s.variance) for s in shelf.on_top] == [
        ("book", 6, "varied"),
        ("potted plant", 1, "same"),
    ]
    rug = obj(plan, "studio", "rug")
    assert rug.category is None  # "carpet" is not an offered category
    assert rug.size == (1.6, 1.6, 0.01)
    assert any("'rug'" in n and "carpet" in n for n in plan.notes)
    # 1600 cm tall (millimetres by mistake): capped at the wall height.
    assert obj(plan, "studio", "floor lamp").size == (0.4, 0.4, 2.6)
    assert "room 'studio': 'floor lamp': size 40 x 40 x 1600 cm clamped to 40 x 40 x 260 cm" in (
        plan.notes
    )

    # Constraints: over floor instances; unknown instances (a third chair, a wall painting)
    # dropped with notes.
    text = "\n".join(studio.constraints)
    assert "dining chair-1 | near, dining table-0 | face to, dining table-0" in studio.constraints
    assert "dining chair-2" not in text
    assert "painting-0" not in text
    assert any("unknown object 'dining chair-2'" in n for n in plan.notes)
    assert any("unknown object 'painting-0'" in n for n in plan.notes)
    floor_instances = [i for o in studio.objects if o.placement == "floor" for i in o.instances()]
    reparsed = parse_constraint_text(text, floor_instances)
    assert reparsed.warnings == []
    assert len(reparsed.constraints) == 20
    assert bathroom.constraints == [
        "shower-0 | edge",
        "toilet-0 | edge | far, shower-0",
        "sink cabinet-0 | edge | side of, toilet-0",
    ]
    assert obj(plan, "bathroom", "mirror").above == "sink cabinet"

    # Round trip through JSON: the plan is plain data.
    assert ScenePlan.model_validate_json(plan.model_dump_json()) == plan


def test_studio_conversation_accounting_and_log() -> None:
    result = run("studio_reading_nook")
    plan: ScenePlan = result["plan"]
    replies = load_conversation("studio_reading_nook")["replies"]
    usage = plan.usage
    assert usage["calls"] == len(replies) == 8
    assert usage["retries"] == 0
    assert usage["prompt_tokens"] == sum(r["prompt_tokens"] for r in replies)
    assert usage["completion_tokens"] == sum(r["completion_tokens"] for r in replies)
    assert usage["model"] == "test-model"
    assert 0.0 <= usage["seconds"] < 30.0
    steps = [(s["step"], s["room"]) for s in usage["steps"]]
    assert steps == [
        ("floor_plan", None),
        ("wall_height", None),
        ("doors", None),
        ("windows", None),
        ("objects", "studio"),
        ("constraints", "studio"),
        ("objects", "bathroom"),
        ("constraints", "bathroom"),
    ]
    assert all(s["ok"] and s["attempts"] == 1 for s in usage["steps"])
    assert usage["steps"][0]["prompt_tokens"] == 412
    call_lines = [line for line in result["log"] if " attempt " in line]
    assert len(call_lines) == 8
    assert call_lines[0].startswith("llm floor_plan attempt 1/3: 412+138 tokens")
    assert "objects[studio]" in call_lines[4]
    assert result["log"][-1].startswith("llm: 8 calls, ")
    assert result["remaining"] == 0


def test_client_sends_model_seed_auth_and_earlier_answers() -> None:
    result = run("studio_reading_nook")
    requests = result["requests"]
    assert len(requests) == 8
    for request in requests:
        assert request.path == "/v1/chat/completions"
        assert request.headers["Authorization"] == f"Bearer {API_KEY}"
        assert request.headers["Content-Type"] == "application/json"
        assert request.body["model"] == "test-model"
        assert request.body["seed"] == 7
        assert request.body["temperature"] == 0.2
        assert request.body["max_tokens"] == 4096
        assert [m["role"] for m in request.messages] == ["system", "user"]
        assert "a small studio apartment with a reading nook" in request.messages[1]["content"]
        assert "JSON" in request.messages[0]["content"]
    # The doors question carries the floor plan as kept (the bathroom clamped to 2.5 m).
    doors_question = requests[2].messages[1]["content"]
    assert "Step 3: doors" in doors_question
    assert '"id": "bathroom"' in doors_question and '"width_m": 2.5' in doors_question
    # The objects question offers the library's categories and knows doors and windows.
    objects_question = requests[4].messages[1]["content"]
    assert "armchair, bathtub, bed" in objects_question
    assert '"entrance_room": "studio"' in objects_question
    # The constraints question lists the floor instances only.
    constraints_question = requests[5].messages[1]["content"]
    assert "dining chair-0, dining chair-1" in constraints_question
    assert "painting-0" not in constraints_question


def test_two_bedroom_conversation() -> None:
    plan: ScenePlan = run("two_bedroom_office")["plan"]
    assert plan.planner == "llm" and plan.seed == 3
    ids = [r.id for r in plan.rooms]
    assert ids == ["living_room", "bedroom_1", "bedroom_2", "home_office", "bathroom"]
    assert plan.entrance_room == "living_room"  # answered as "Living Room"
    living = plan.room("living_room")
    assert living.type == "living_room"
    assert living.adjacent_to == ["bedroom_1", "bedroom_2", "home_office", "bathroom"]
    assert plan.room("home_office").windows.kind == "hung"  # answered "Hung"
    assert plan.room("bathroom").windows.count == 0
    assert obj(plan, "living_room", "dining chair").quantity == 4
    assert obj(plan, "home_office", "desk").on_top[0].name == "monitor"
    assert obj(plan, "bedroom_1", "painting").above == "double bed"
    assert "nightstand-1 | edge | right of, double bed-0" in plan.room("bedroom_1").constraints
    assert plan.usage["calls"] == 14
    assert not any("unknown object" in n for n in plan.notes)
    for room in plan.rooms:
        instances = [i for o in room.objects if o.placement == "floor" for i in o.instances()]
        assert parse_constraint_text("\n".join(room.constraints), instances).warnings == []


def test_one_room_conversation() -> None:
    plan: ScenePlan = run("rustic_kitchen")["plan"]
    assert [r.id for r in plan.rooms] == ["kitchen"]
    kitchen = plan.rooms[0]
    assert kitchen.adjacent_to == []
    assert plan.entrance_room == "kitchen"
    assert obj(plan, "kitchen", "breakfast bar").requested  # named in the prompt
    assert not obj(plan, "kitchen", "counter").requested
    assert obj(plan, "kitchen", "open shelf").on_top[0].quantity == 4
    assert plan.usage["calls"] == 6
    assert len(kitchen.constraints) == 6


# --------------------------------------------------------------------------- retries


def test_malformed_json_is_fed_back_then_accepted() -> None:
    replies = replies_of("studio_reading_nook")
    bad = {**replies[4], "content": '{"objects": {"bed": {"location": "floor", "size_cm": [16'}
    replies.insert(4, bad)
    result = run("studio_reading_nook", replies)
    plan, requests = result["plan"], result["requests"]
    assert plan.planner == "llm"
    assert plan.usage["calls"] == 9 and plan.usage["retries"] == 1
    objects_step = plan.usage["steps"][4]
    assert objects_step["attempts"] == 2 and objects_step["ok"]
    assert objects_step["errors"][0].startswith("invalid JSON")
    retry = requests[5]
    assert [m["role"] for m in retry.messages] == ["system", "user", "assistant", "user"]
    assert retry.messages[1] == requests[4].messages[1]
    assert retry.messages[2]["content"] == bad["content"]
    assert "invalid JSON" in retry.messages[3]["content"]
    assert any("rejected: invalid JSON" in line for line in result["log"])


def test_wrong_schema_is_fed_back() -> None:
    replies = replies_of("studio_reading_nook")
    replies.insert(0, {**replies[0], "content": '{"scene_type": "studio", "room": []}'})
    result = run("studio_reading_nook", replies)
    feedback = result["requests"][1].messages[3]["content"]
    assert "wrong schema" in feedback
    assert "rooms: Field required" in feedback and "room: unknown field" in feedback
    assert result["plan"].planner == "llm"


def test_unknown_room_in_doors_is_fed_back() -> None:
    replies = replies_of("studio_reading_nook")
    wrong = '{"connections": [["studio", "kitchen"]], "entrance_room": "studio"}'
    replies.insert(2, {**replies[2], "content": wrong})
    result = run("studio_reading_nook", replies)
    feedback = result["requests"][3].messages[3]["content"]
    assert "unknown room 'kitchen' (rooms: studio, bathroom)" in feedback
    assert result["plan"].room("studio").adjacent_to == ["bathroom"]


def test_truncated_answer_is_retried() -> None:
    replies = replies_of("studio_reading_nook")
    cut = {**replies[4], "content": replies[4]["content"][:300], "finish_reason": "length"}
    replies.insert(4, cut)
    result = run("studio_reading_nook", replies)
    assert result["plan"].planner == "llm"
    feedback = result["requests"][5].messages[3]["content"]
    assert "cut off at max_tokens=4096" in feedback and "'length'" in feedback
    assert result["plan"].usage["retries"] == 1


def test_slow_answer_times_out_and_is_retried() -> None:
    replies = replies_of("studio_reading_nook")
    replies.insert(1, {**replies[1], "delay_s": 1.0})
    result = run("studio_reading_nook", replies, config={"timeout_s": 0.3})
    plan = result["plan"]
    assert plan.planner == "llm" and plan.wall_height == 2.6
    step = plan.usage["steps"][1]
    assert step["step"] == "wall_height" and step["attempts"] == 2
    assert "timeout" in step["errors"][0] and "0.3 s" in step["errors"][0]
    # A transport error is retried with the same question (nothing to feed back).
    assert result["requests"][2].messages == result["requests"][1].messages
    assert any("wall_height attempt 1/3" in line and "timeout" in line for line in result["log"])
    assert result["elapsed"] < 5.0


def test_http_500_then_success_after_backoff() -> None:
    replies = replies_of("studio_reading_nook")
    replies.insert(3, {"expect": "Step 4: windows", "status": 500})
    replies.insert(4, {"expect": "Step 4: windows", "status": 429})
    result = run("studio_reading_nook", replies, config={"backoff_s": 0.05})
    plan = result["plan"]
    assert plan.planner == "llm"
    windows = plan.usage["steps"][3]
    assert windows["attempts"] == 3 and windows["ok"]
    assert windows["errors"][0].startswith("HTTP 500")
    assert windows["errors"][1].startswith("HTTP 429")
    assert plan.usage["retries"] == 2
    assert result["elapsed"] >= 0.05 + 0.1  # backoff 0.05 s, then 0.1 s


def test_python_code_is_rejected_and_never_run(tmp_path: Path) -> None:
    marker = tmp_path / "executed"
    code = f"import pathlib\npathlib.Path({str(marker)!r}).write_text('ran')\n"
    replies = replies_of("studio_reading_nook")
    step = replies[1]
    replies[1:1] = [
        {**step, "content": f"```python\n{code}```"},
        {**step, "content": code},
    ]
    result = run("studio_reading_nook", replies)
    assert not marker.exists()
    errors = result["plan"].usage["steps"][1]["errors"]
    assert errors[0].startswith("not JSON: a python code block")
    assert errors[1].startswith("not JSON:")
    assert result["plan"].planner == "llm"


# --------------------------------------------------------------------------- fallback


def test_persistent_garbage_falls_back_to_the_offline_planner() -> None:
    replies = replies_of("studio_reading_nook")[:4]
    prose = "Sure! For a cozy studio I would suggest a bed, an armchair and a lamp."
    replies += [{"expect": "objects of room 'studio'", "content": prose}] * 3
    result = run("studio_reading_nook", replies, fallback=offline_stub)
    plan: ScenePlan = result["plan"]
    assert plan.planner == "offline"
    assert [r.id for r in plan.rooms] == ["room"]
    assert plan.notes[0] == "offline stub plan"
    note = plan.notes[-1]
    assert note.startswith(
        "LLM planner failed at step 'objects' (room 'studio') after 3 attempts (not JSON:"
    )
    assert note.endswith("; used the offline planner")
    assert plan.usage["calls"] == 7 and plan.usage["failed_step"] == "objects"
    assert plan.usage["retries"] == 2
    assert any("using the offline planner" in line for line in result["log"])
    assert result["remaining"] == 0


def test_client_error_is_not_retried_and_falls_back() -> None:
    replies = [{"status": 401, "body": {"error": {"message": "Invalid API key provided"}}}]
    result = run("studio_reading_nook", replies, fallback=offline_stub)
    plan: ScenePlan = result["plan"]
    assert plan.planner == "offline"
    assert len(result["requests"]) == 1
    assert "after 1 attempt (HTTP 401" in plan.notes[-1]
    assert "Invalid API key provided" in plan.notes[-1]


def _closed_port() -> int:
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        return sock.getsockname()[1]


def test_connection_refused_falls_back() -> None:
    log: list[str] = []
    start = time.monotonic()
    plan = plan_llm(
        "a small studio apartment with a reading nook",
        5,
        config=config_for(f"http://127.0.0.1:{_closed_port()}/v1"),
        fallback=offline_stub,
        log=log.append,
    )
    assert time.monotonic() - start < 5.0
    assert plan.planner == "offline" and plan.seed == 5
    assert "connection refused" in plan.notes[-1]
    assert "after 1 attempt" in plan.notes[-1]
    assert plan.usage["calls"] == 1
    assert len([line for line in log if "connection refused" in line]) == 2  # call + failure


def test_connection_refused_without_fallback_is_one_line() -> None:
    url = f"http://127.0.0.1:{_closed_port()}/v1"
    with pytest.raises(HolomjError) as info:
        plan_llm("a kitchen", 0, config=config_for(url))
    message = str(info.value)
    assert isinstance(info.value, LLMPlannerError)
    assert "\n" not in message
    assert "failed at step 'floor_plan'" in message and "connection refused" in message
    assert "--planner offline" in message
    assert info.value.exit_code == 1


def test_garbage_without_fallback_raises_one_line() -> None:
    replies = [{"content": "[1, 2, 3]"}] * 2
    with pytest.raises(LLMPlannerError) as info:
        run("studio_reading_nook", replies, config={"max_retries": 1})
    message = str(info.value)
    assert "\n" not in message
    assert "step 'floor_plan' after 2 attempts" in message
    assert "expected one JSON object, got a JSON list" in message


def test_broken_envelope_is_retried_then_falls_back() -> None:
    replies = [{"raw": "<html>Bad gateway</html>"}] * 3
    result = run("studio_reading_nook", replies, fallback=offline_stub)
    plan: ScenePlan = result["plan"]
    assert plan.planner == "offline"
    assert "not a JSON chat completion" in plan.notes[-1]
    assert plan.usage["calls"] == 3


def test_prompt_is_checked_before_any_request() -> None:
    with pytest.raises(HolomjError) as info:
        plan_llm("   ", 0, config=config_for("http://127.0.0.1:9/v1"))
    assert info.value.exit_code == 2


def test_usage_is_json_serialisable() -> None:
    plan = run("rustic_kitchen")["plan"]
    data = json.loads(plan.model_dump_json())
    assert data["usage"]["steps"][0]["step"] == "floor_plan"
    assert data["planner"] == "llm"
