"""generate checks its request once, before any work: the options (declared once, in
GenerateOptions), the output folder, the planner and the compile profile."""

from __future__ import annotations

from collections import Counter
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

import holomj
from holomj.errors import InputError
from holomj.jobs import folder, generate_options
from holomj.jobs.generate import GenerateOptions, generate_scene


def test_an_unknown_option_is_refused_before_any_work(tmp_path: Path) -> None:
    out = tmp_path / "kitchen"
    with pytest.raises(InputError, match="unknown option 'colour'"):
        holomj.generate("a small kitchen", out, seed=1, colour="red")
    assert not out.exists()


def test_the_plan_stage_reads_generate_options_plan_fields() -> None:
    options = GenerateOptions(seed=4, planner="llm", llm_model="m", width=32)
    plan = options.plan_options()
    assert (plan.seed, plan.planner, plan.llm_model) == (4, "llm", "m")
    assert not hasattr(plan, "width")


@pytest.mark.parametrize(
    ("option", "value", "where"),
    [
        ("planner", "psychic", "--planner"),
        ("furniture", "glued", "--furniture"),
        ("profile", "fast", "--profile"),
        ("robot", "no_such_robot", "--robot"),
    ],
)
def test_a_bad_option_fails_before_the_output_folder_is_made(
    tmp_path: Path, option: str, value: str, where: str
) -> None:
    out = tmp_path / "out"
    with pytest.raises(InputError, match=where):
        generate_scene("a small kitchen", out, GenerateOptions(**{option: value}))
    assert not out.exists() and list(tmp_path.iterdir()) == []


@pytest.mark.slow
def test_every_check_runs_once(
    tmp_path: Path, default_library, monkeypatch: pytest.MonkeyPatch
) -> None:
    calls: Counter[str] = Counter()

    def counted(name: str, function: Callable[..., Any]) -> Callable[..., Any]:
        def wrapper(*args: Any, **kwargs: Any) -> Any:
            calls[name] += 1
            return function(*args, **kwargs)

        return wrapper

    prepare = counted("prepare_output", folder.prepare_output)
    monkeypatch.setattr(folder, "prepare_output", prepare)
    monkeypatch.setattr(generate_options, "prepare_output", prepare)
    planner = counted("check_planner", generate_options.check_planner)
    monkeypatch.setattr(generate_options, "check_planner", planner)
    monkeypatch.setattr("holomj.jobs.plan.check_planner", planner)
    options = GenerateOptions(library=default_library.root, seed=0, render=False)
    generate_scene("a small bathroom", tmp_path / "bath", options)
    assert calls == {"prepare_output": 1, "check_planner": 1}
    assert (tmp_path / "bath" / "generate.json").is_file()
