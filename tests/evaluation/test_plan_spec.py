"""A plan as an annotation (``holomj.evaluation.plan_spec``), and checking annotations."""

from __future__ import annotations

import copy
from typing import Any

import pytest

from holomj.errors import InputError
from holomj.evaluation.plan_spec import prompt_attributes, spec_from_plan
from holomj.evaluation.specs import check_spec
from holomj.evaluation.vocabulary import Vocabulary
from holomj.spec.plan import ScenePlan

PLAN: dict[str, Any] = {
    "prompt": "a bedroom with a red armchair by the window, two nightstands and a lamp on one",
    "planner": "offline",
    "seed": 0,
    "scene_type": "bedroom",
    "rooms": [
        {
            "id": "bedroom",
            "type": "bedroom",
            "objects": [
                {"name": "bed", "category": "bed", "description": "a white bed", "defining": True},
                {
                    "name": "armchair",
                    "category": "armchair",
                    "description": "red armchair",
                    "requested": True,
                },
                {
                    "name": "nightstand",
                    "category": "nightstand",
                    "quantity": 2,
                    "requested": True,
                    "on_top": [{"name": "lamp", "category": "desk_lamp"}],
                },
                {"name": "rug", "category": "rug"},
            ],
            "relations": [
                {"subject": "armchair", "kind": "by_window", "phrase": "by the window"},
                {"subject": "lamp", "kind": "on", "target": "nightstand"},
                {"subject": "nightstand", "kind": "both_sides", "target": "bed"},
                {"subject": "nightstand", "kind": "in_row"},
                {"subject": "nightstand", "kind": "around", "target": "bed"},
                {"subject": "armchair", "kind": "around", "target": "nightstand"},
            ],
        },
        {"id": "bedroom_1", "type": "bedroom", "objects": [{"name": "bed", "category": "bed"}]},
    ],
}


@pytest.fixture(scope="module")
def vocab() -> Vocabulary:
    return Vocabulary.load()


def test_own_plan_counts_everything_by_id(vocab: Vocabulary) -> None:
    spec = spec_from_plan(ScenePlan.model_validate(PLAN), vocab, own=True)
    assert spec["rooms"] == {"eq": 2}
    assert spec["room_types"] == [{"type": "bedroom", "count": {"eq": 2}, "exact_type": True}]
    rows = {(o["room_id"], o["name"]): o for o in spec["objects"]}
    assert set(rows) == {
        ("bedroom", "bed"),
        ("bedroom", "armchair"),
        ("bedroom", "nightstand"),
        ("bedroom", "rug"),
        ("bedroom", "lamp"),
        ("bedroom_1", "bed"),
    }
    assert rows[("bedroom", "nightstand")]["count"] == {"eq": 2}
    assert rows[("bedroom", "nightstand")]["id_stem"] == "bedroom.nightstand"
    assert rows[("bedroom", "lamp")]["count"] == {"ge": 1}
    assert rows[("bedroom", "lamp")]["categories"] == ["desk_lamp"]
    assert rows[("bedroom", "armchair")]["attributes"] == {"color": "red"}
    assert "attributes" not in rows[("bedroom", "bed")]  # "white" is the planner's, not asked
    kinds = [
        (r["plan_kind"], r["relation"], r["object"], r["quantifier"]) for r in spec["relations"]
    ]
    assert kinds == [
        ("by_window", "next to", "window", "all"),
        ("on", "on", "nightstand", "all"),
        ("both_sides", "next to", "bed", "all"),
        ("around", "around", "bed", "any"),  # two seats around one
        ("around", "next to", "nightstand", "most"),  # around one of several
    ]
    assert spec["skipped"] == ["bedroom: nightstand in_row"]
    assert all(r["room_id"] == "bedroom" for r in spec["relations"])
    assert check_spec(copy.deepcopy(spec)) == spec  # a plan's annotation is a valid annotation


def test_a_plan_for_another_folder_counts_what_was_asked(vocab: Vocabulary) -> None:
    spec = spec_from_plan(ScenePlan.model_validate(PLAN), vocab, own=False)
    assert "rooms" not in spec
    assert spec["room_types"] == [{"type": "bedroom", "count": {"ge": 1}}]
    assert [(o["name"], o["count"]) for o in spec["objects"]] == [
        ("armchair", {"eq": 1}),
        ("nightstand", {"eq": 2}),
        ("lamp", {"ge": 1}),  # the subject of an 'on'
    ]
    assert not any("id_stem" in o or "room_id" in o for o in spec["objects"])
    # The two plan rooms' beds are one reference: at least the most one room asks for.
    refs = {o["name"]: o for o in spec["references"]}
    assert set(refs) == {"bed", "rug"} and refs["bed"]["count"] == {"ge": 1}


def test_attribute_words_must_come_from_the_prompt(vocab: Vocabulary) -> None:
    prompt = "a room with two leather sofas, a round glass table and a green lamp"
    assert prompt_attributes(prompt, "sofa", "brown leather sofa", vocab) == {"material": "leather"}
    assert prompt_attributes(prompt, "coffee table", "a round glass coffee table", vocab) == {
        "material": "glass",
        "shape": "round",
    }
    assert prompt_attributes(prompt, "chair", "a green chair", vocab) == {}


@pytest.mark.parametrize(
    ("spec", "where"),
    [
        ([], "an annotation must be a JSON object"),
        ({"rooms": {"eq": "2"}}, "rooms"),
        ({"objects": [{"count": {"eq": 1}}]}, r"objects\[0\]\.name"),
        ({"objects": [{"name": "bed", "count": {"lt": 1}}]}, r"objects\[0\]\.count"),
        ({"objects": [{"name": "bed", "count": {"eq": 1}, "attributes": {"smell": "x"}}]}, "attr"),
        ({"relations": [{"subject": "bed", "relation": "on top of"}]}, "unknown relation"),
        ({"relations": [{"subject": "bed", "relation": "near", "quantifier": "few"}]}, "quant"),
        ({"absent": [3]}, r"absent\[0\]"),
        ({"objects": {"name": "bed"}}, "must be a list"),
    ],
)
def test_bad_annotations_name_the_field(spec: Any, where: str) -> None:
    with pytest.raises(InputError, match=where):
        check_spec(spec, "spec.json")
