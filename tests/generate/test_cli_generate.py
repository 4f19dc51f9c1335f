"""``holomj generate`` and ``holomj plan`` through the command line (typer runner)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from holomj.cli import app
from tests.plan.llm_replay import load_conversation, replay_server

runner = CliRunner()
PROMPT = "a music room with a piano"


def generate(out: Path, library: Path, *extra: str):
    return runner.invoke(
        app,
        ["generate", PROMPT, "-o", str(out), "--library", str(library), "--no-render", *extra],
    )


def test_bad_input_exits_2_and_writes_nothing(tmp_path: Path, default_library) -> None:
    out = tmp_path / "out"
    result = runner.invoke(app, ["generate", "   ", "-o", str(out)])
    assert result.exit_code == 2 and "prompt is empty" in result.output
    assert not out.exists()
    result = runner.invoke(app, ["generate", PROMPT, "-o", str(out), "--planner", "psychic"])
    assert result.exit_code == 2 and "--planner" in result.output
    out.mkdir()
    (out / "keep.txt").write_text("mine")
    result = generate(out, default_library.root)
    assert result.exit_code == 2 and "exists" in result.output
    assert [p.name for p in out.iterdir()] == ["keep.txt"]


@pytest.mark.slow
def test_same_seed_same_bytes_other_seed_other_scene(tmp_path: Path, default_library) -> None:
    outs = {}
    for name, seed in (("a", "5"), ("b", "5"), ("c", "6")):
        result = generate(tmp_path / name, default_library.root, "--seed", seed, "--json")
        assert result.exit_code == 0, result.output
        summary = json.loads(result.output)
        assert summary["ok"] and summary["planner"] == "offline"
        outs[name] = (tmp_path / name / "scene.xml").read_bytes()
    assert outs["a"] == outs["b"]
    assert outs["a"] != outs["c"]
    log = (tmp_path / "a" / "generate.log").read_text()
    for stage in ("plan", "retrieve", "layout", "small_objects", "validate", "export"):
        assert f"] {stage}: done" in log


@pytest.mark.slow
def test_llm_planner_through_a_loopback_server(tmp_path: Path, default_library) -> None:
    conversation = load_conversation("studio_reading_nook")
    with replay_server(conversation["replies"]) as server:
        result = runner.invoke(
            app,
            [
                "generate",
                conversation["prompt"],
                "-o",
                str(tmp_path / "llm"),
                "--library",
                str(default_library.root),
                "--no-render",
                "--planner",
                "llm",
                "--llm-base-url",
                server.base_url,
                "--llm-model",
                conversation.get("model", "test-model"),
                "--seed",
                str(conversation["seed"]),
                "--json",
            ],
        )
    assert result.exit_code == 0, result.output
    summary = json.loads(result.output)
    assert summary["planner"] == "llm"
    plan = json.loads((tmp_path / "llm" / "plan.json").read_text())
    assert plan["usage"]["calls"] == len(server.requests) >= 5
    assert summary["objects"]["furniture"] >= 3


def test_llm_planner_falls_back_when_the_server_is_down(tmp_path: Path) -> None:
    import socket

    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        port = sock.getsockname()[1]
    out = tmp_path / "plan.json"
    result = runner.invoke(
        app,
        [
            "plan",
            "a small kitchen",
            "--planner",
            "llm",
            "--llm-base-url",
            f"http://127.0.0.1:{port}/v1",
            "--llm-model",
            "m",
            "-o",
            str(out),
        ],
    )
    assert result.exit_code == 0, result.output
    plan = json.loads(out.read_text())
    assert plan["planner"] == "offline"
    assert any("offline planner" in note for note in plan["notes"])


def test_plan_prints_a_valid_plan() -> None:
    from holomj.spec.plan import ScenePlan

    result = runner.invoke(app, ["plan", "a small kitchen", "--seed", "2"])
    assert result.exit_code == 0, result.output
    plan = ScenePlan.model_validate_json(result.stdout)
    assert plan.rooms and plan.seed == 2
