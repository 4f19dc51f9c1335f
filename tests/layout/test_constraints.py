"""The constraint language: Holodeck's text form (tolerant, never silent) and the typed form."""

from __future__ import annotations

import json

import pytest

from holomj.errors import SpecError
from holomj.layout.constraints import (
    Constraint,
    constraints_to_text,
    normalize_name,
    parse_constraint_text,
)
from holomj.layout.room_problem import problem_from_data
from tests.conftest import FIXTURES

IDS = ["sofa-0", "coffee_table-0", "tv_stand-0", "armchair-0", "floor lamp-0"]


def kinds(parsed, name):
    return [(c.kind, c.target) for c in parsed.constraints if c.object == name]


def test_holodeck_example_line() -> None:
    text = (
        "sofa-0 | edge\n"
        "coffee table-0 | middle | near, sofa-0 | in front of, sofa-0 | center aligned, sofa-0 "
        "| face to, sofa-0\n"
    )
    parsed = parse_constraint_text(text, IDS)
    assert parsed.warnings == []
    assert kinds(parsed, "sofa-0") == [("edge", None)]
    assert kinds(parsed, "coffee_table-0") == [
        ("middle", None),
        ("near", "sofa-0"),
        ("in_front_of", "sofa-0"),
        ("center_aligned", "sofa-0"),
        ("face_to", "sofa-0"),
    ]


def test_odd_spacing_case_numbering_and_stars() -> None:
    text = (
        "Here is my design: the sofa goes against the wall.\n"
        "  1.  **Sofa-0** |   EDGE  \n"
        "2) Coffee   Table-0|Middle|  Near ,  SOFA-0 | Centre Aligned, sofa-0.\n"
        "- tv_stand-0 | edge | far, coffee table-0 | n/a\n"
    )
    parsed = parse_constraint_text(text, IDS)
    assert kinds(parsed, "sofa-0") == [("edge", None)]
    assert kinds(parsed, "coffee_table-0") == [
        ("middle", None),
        ("near", "sofa-0"),
        ("center_aligned", "sofa-0"),
    ]
    assert kinds(parsed, "tv_stand-0") == [("edge", None), ("far", "coffee_table-0")]
    # The prose line is not silently swallowed either.
    assert any("without '|'" in w for w in parsed.warnings)


def test_unknown_words_warn_and_are_not_remapped() -> None:
    text = "sofa-0 | edge | near wall | hovering, tv stand-0 | face too, tv stand-0\n"
    parsed = parse_constraint_text(text, IDS)
    assert kinds(parsed, "sofa-0") == [("edge", None)]
    joined = "\n".join(parsed.warnings)
    for word in ("near wall", "hovering", "face too"):
        assert f"unknown constraint '{word}'" in joined
    # The warning lists the known words and a close match, but does not apply it.
    assert "face to" in joined and "did you mean" in joined


def test_missing_and_unknown_names_warn() -> None:
    text = (
        " | edge\n"
        "piano-0 | edge\n"
        "armchair-0 | near, | face to, sofa-9 | side of\n"
        "armchair-0 | near, armchair-0\n"
    )
    parsed = parse_constraint_text(text, IDS)
    assert parsed.constraints == []
    joined = "\n".join(parsed.warnings)
    assert "missing object name" in joined
    assert "unknown object 'piano-0'" in joined
    assert "'near' for 'armchair-0' has no target" in joined
    assert "unknown object 'sofa-9'" in joined and "did you mean: sofa-0" in joined
    assert "'side of' for 'armchair-0' has no target" in joined
    assert "cannot be 'near' itself" in joined


def test_global_with_target_and_duplicates_warn() -> None:
    text = "sofa-0 | edge, tv stand-0 | near, tv stand-0 | near, tv_stand-0\n"
    parsed = parse_constraint_text(text, IDS)
    assert kinds(parsed, "sofa-0") == [("edge", None), ("near", "tv_stand-0")]
    joined = "\n".join(parsed.warnings)
    assert "takes no target" in joined
    assert "duplicate constraint" in joined


def test_around_expands_to_near_and_face_to() -> None:
    parsed = parse_constraint_text("armchair-0 | middle | around, coffee table-0", IDS)
    assert kinds(parsed, "armchair-0") == [
        ("middle", None),
        ("near", "coffee_table-0"),
        ("face_to", "coffee_table-0"),
    ]
    assert parsed.warnings == []


def test_without_ids_names_are_normalised() -> None:
    parsed = parse_constraint_text("Coffee_Table-0 | near, SOFA-0")
    assert kinds(parsed, "coffee table-0") == [("near", "sofa-0")]


def test_text_round_trip() -> None:
    text = (
        "sofa-0 | edge\n"
        "coffee_table-0 | middle | near, sofa-0 | face to, sofa-0\n"
        "armchair-0 | side of, coffee_table-0 | left of, sofa-0 | face same as, sofa-0\n"
    )
    parsed = parse_constraint_text(text, IDS)
    assert constraints_to_text(parsed.constraints) == text
    again = parse_constraint_text(constraints_to_text(parsed.constraints), IDS)
    assert [c.key for c in again.constraints] == [c.key for c in parsed.constraints]


def test_typed_json_form() -> None:
    data = [
        {"object": "coffee_table-0", "kind": "in_front_of", "target": "sofa-0", "weight": 2},
        {"object": "sofa-0", "kind": "edge"},
    ]
    constraints = [Constraint.model_validate(d) for d in data]
    assert constraints[0].text == "coffee_table-0 | in front of, sofa-0"
    assert constraints[0].weight == 2.0
    dumped = json.loads(json.dumps([c.model_dump(mode="json") for c in constraints]))
    assert [Constraint.model_validate(d) for d in dumped] == constraints


@pytest.mark.parametrize(
    ("item", "needle"),
    [
        ({"object": "a", "kind": "near"}, "needs a target"),
        ({"object": "a", "kind": "edge", "target": "b"}, "takes no target"),
        ({"object": "a", "kind": "near", "target": "A"}, "itself"),
        ({"object": "a", "kind": "hovering", "target": "b"}, "kind"),
    ],
)
def test_typed_constraint_errors_name_the_field(item: dict, needle: str) -> None:
    data = {
        "polygon": [[0, 0], [4, 0], [4, 4], [0, 4]],
        "size_unit": "m",
        "objects": [{"id": "a", "width": 1, "depth": 1}, {"id": "b", "width": 1, "depth": 1}],
        "constraints": [{"object": "b", "kind": "edge"}, item],
    }
    with pytest.raises(SpecError) as info:
        problem_from_data(data, "in.json")
    message = str(info.value)
    assert message.startswith("in.json: constraints[1]")
    assert needle in message


def test_typed_constraint_unknown_object() -> None:
    data = {
        "polygon": [[0, 0], [4, 0], [4, 4], [0, 4]],
        "size_unit": "m",
        "objects": [{"id": "sofa-0", "width": 2, "depth": 1}],
        "constraints": [{"object": "sofa-0", "kind": "near", "target": "sofa-1"}],
    }
    with pytest.raises(SpecError, match=r"constraints\[0\]\.target: unknown object 'sofa-1'"):
        problem_from_data(data, "in.json")


def test_typed_and_text_merge_once() -> None:
    data = json.loads((FIXTURES / "layout_living_room.json").read_text())
    data["constraints"] = [{"object": "sofa-0", "kind": "edge"}]
    problem = problem_from_data(data)
    merged = problem.all_constraints()
    assert len(merged.constraints) == 36
    assert any("given twice" in w for w in merged.warnings)


def test_fixture_has_36_constraints_without_warnings() -> None:
    problem = problem_from_data(json.loads((FIXTURES / "layout_living_room.json").read_text()))
    merged = problem.all_constraints()
    assert len(merged.constraints) == 36
    assert merged.warnings == []


def test_normalize_name() -> None:
    assert normalize_name("  **Coffee_Table-0** ") == "coffee table-0"
