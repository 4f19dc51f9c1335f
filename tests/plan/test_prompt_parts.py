"""Parts asked of an object ("cabinets with brass handles") stay with it (plan.prompt_parts)."""

from __future__ import annotations

import pytest

from holomj.plan.knowledge import knowledge_base
from holomj.plan.offline import plan_offline
from holomj.plan.prompt import parse_prompt
from holomj.plan.prompt_parts import part_after


def test_a_part_phrase_is_the_item_after_with_that_ends_in_a_part_noun() -> None:
    words = ["a", "desk", "with", "black", "drawers", ",", "a", "chair"]
    assert part_after(words, 2) == (3, 5)
    assert part_after(["a", "table", "with", "four", "chairs"], 2) is None
    assert part_after(["a", "bed"], 2) is None


@pytest.mark.parametrize(
    ("text", "kind", "part", "description"),
    [
        (
            "A kitchen with white kitchen cabinets with brass handles.",
            "kitchen cabinet",
            "brass handles",
            "white kitchen cabinet with brass handles",
        ),
        ("A dining room with a wooden table with metal legs.", "table", "metal legs", None),
        ("An office with a desk with black drawers.", "desk", "black drawers", None),
        ("A dining room with a chair with a red seat.", "chair", "red seat", None),
        ("A living room with a lamp with a white shade.", "lamp", "white shade", None),
    ],
)
def test_parts_stay_with_their_object_and_are_no_object_or_unknown_noun(
    text: str, kind: str, part: str, description: str | None
) -> None:
    parsed = parse_prompt(text, knowledge_base())
    assert [o.kind for o in parsed.objects] == [kind]
    assert parsed.objects[0].parts == [part]
    assert parsed.unknown == []
    if description is not None:
        plan = plan_offline(text, 0)
        assert description in [o.description for r in plan.rooms for o in r.objects]


def test_with_and_another_object_is_still_another_object() -> None:
    parsed = parse_prompt("A kitchen with a table with four chairs.", knowledge_base())
    assert [o.kind for o in parsed.objects] == ["table", "chair"]
    assert all(not o.parts for o in parsed.objects)


def test_a_noun_right_before_an_objects_noun_describes_it() -> None:
    parsed = parse_prompt("A living room with an orange sofa.", knowledge_base())
    assert [(o.kind, o.adjectives) for o in parsed.objects] == [("sofa", ["orange"])]
    parsed = parse_prompt("A kitchen with an orange and a bowl.", knowledge_base())
    assert [o.kind for o in parsed.objects] == ["orange", "bowl"]
