"""Relations read from prompts (holomj.plan.prompt_relations) and made plan relations."""

from __future__ import annotations

import pytest

from holomj.plan.knowledge import knowledge_base
from holomj.plan.offline import plan_offline
from holomj.plan.prompt import parse_prompt


def _relations(text: str) -> list[tuple[str, str, str | None]]:
    parsed = parse_prompt(text, knowledge_base())
    objs = parsed.objects
    return [
        (objs[r.subject].kind, r.kind, objs[r.target].kind if r.target is not None else None)
        for r in parsed.relations
    ]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("A study with a desk under the window.", ("desk", "under_window", None)),
        ("A living room with a floor lamp in the corner.", ("floor lamp", "corner", None)),
        ("A bedroom with a bed against the wall.", ("bed", "wall", None)),
        ("A kitchen with a dining table in the middle.", ("dining table", "middle", None)),
        ("A shop with a counter near the entrance.", ("counter", "by_door", None)),
        ("A bedroom with an armchair by the window.", ("armchair", "by_window", None)),
        (
            "A kitchen with a dining table and four chairs around it.",
            ("chair", "around", "dining table"),
        ),
        (
            "A bedroom with a bed and a nightstand on each side of the bed.",
            ("nightstand", "both_sides", "bed"),
        ),
        (
            "A living room with a sofa and a coffee table in front of the sofa.",
            ("coffee table", "in_front_of", "sofa"),
        ),
        ("A bathroom with a washbasin and a mirror above it.", ("mirror", "above", "washbasin")),
        ("An office with a desk with a laptop on it.", ("laptop", "on", "desk")),
        ("A gym with three treadmills in a row.", ("treadmill", "in_row", None)),
    ],
)
def test_relation_phrases_are_read(text: str, expected: tuple[str, str, str | None]) -> None:
    assert expected in _relations(text)


def test_no_relation_without_a_relation_phrase() -> None:
    assert _relations("A bedroom with a bed, a wardrobe and a nightstand.") == []


def test_a_comma_ends_the_reach_of_a_relation() -> None:
    # "in the corner" belongs to the lamp, not to the sofa before the comma
    found = _relations("A living room with a sofa, a floor lamp in the corner.")
    assert found == [("floor lamp", "corner", None)]


def test_the_bed_refers_to_the_bed_already_asked_for() -> None:
    plan = plan_offline("A bedroom with a queen bed and a nightstand on each side of the bed.", 0)
    room = plan.rooms[0]
    counts = {o.name: o.quantity for o in room.objects}
    assert counts["bed"] == 1
    assert counts["nightstand"] == 2  # one on each side
    kinds = {(r.subject, r.kind, r.target) for r in room.relations}
    assert ("nightstand", "both_sides", "bed") in kinds


def test_plan_relations_place_small_objects_and_wall_objects() -> None:
    plan = plan_offline(
        "A bedroom with a bed, a desk with a laptop on it and a dresser with a mirror above it.",
        0,
    )
    room = plan.rooms[0]
    by_name = {o.name: o for o in room.objects}
    assert [s.name for s in by_name["desk"].on_top].count("laptop") == 1
    assert by_name["mirror"].above == "dresser"
    kinds = {(r.subject, r.kind, r.target) for r in room.relations}
    assert {("laptop", "on", "desk"), ("mirror", "above", "dresser")} <= kinds


def test_a_prompt_place_replaces_the_template_default() -> None:
    plan = plan_offline("A living room with a sofa in the middle.", 0)
    room = plan.rooms[0]
    sofa_lines = [c for c in room.constraints if c.startswith("sofa-0")]
    assert all("edge" not in line for line in sofa_lines)
    assert any(r.subject == "sofa" and r.kind == "middle" for r in room.relations)


def _shelves(text: str) -> int:
    plan = plan_offline(text, 0)
    return next(o.quantity for r in plan.rooms for o in r.objects if o.name == "bookshelf")


def test_plurals_without_a_number_get_a_range_by_room_size() -> None:
    small = _shelves("A small study with bookshelves.")
    large = _shelves("A large library with bookshelves.")
    assert 2 <= small <= large <= 4
    assert small < large


def test_counts_asked_for_pass_the_default_floor_cap() -> None:
    plan = plan_offline("A classroom with a whiteboard, ten desks and ten chairs.", 0)
    counts = {o.name: o.quantity for r in plan.rooms for o in r.objects}
    assert counts.get("desk") == 10
    assert sum(q for n, q in counts.items() if "chair" in n) == 10


def test_a_tv_on_the_stand_stands_on_it() -> None:
    plan = plan_offline("A living room with a sofa and a TV on a TV stand.", 0)
    room = plan.rooms[0]
    names = {o.name: o for o in room.objects}
    assert "television" not in names  # not hung on the wall
    assert "television" in [s.name for s in names["tv stand"].on_top]


def test_facing_a_wall_tv_means_facing_its_stand() -> None:
    plan = plan_offline("A living room with a sofa facing a TV and a TV stand.", 0)
    kinds = {(r.subject, r.kind, r.target) for r in plan.rooms[0].relations}
    assert ("sofa", "facing", "tv stand") in kinds


def test_each_with_multiplies_the_count() -> None:
    plan = plan_offline("A restaurant with eight round tables, each with four chairs.", 0)
    counts = {o.name: o.quantity for r in plan.rooms for o in r.objects}
    assert sum(q for n, q in counts.items() if "chair" in n) == 32


def test_a_small_object_asked_for_replaces_the_templates_own() -> None:
    plan = plan_offline("A garage with a workbench with a toolbox on it.", 0)
    toolboxes = sum(
        s.quantity * o.quantity
        for r in plan.rooms
        for o in r.objects
        for s in o.on_top
        if s.name == "toolbox"
    )
    assert toolboxes == 1


def test_two_things_side_by_side_are_next_to_each_other() -> None:
    plan = plan_offline("A garage with a car and a motorcycle side by side.", 0)
    kinds = {(r.subject, r.kind, r.target) for r in plan.rooms[0].relations}
    assert ("motorcycle", "adjacent_to", "car") in kinds


def test_a_lamp_put_on_something_is_a_small_lamp_one_on_each() -> None:
    plan = plan_offline("A hotel room with a bed and two nightstands with lamps.", 0)
    room = plan.rooms[0]
    stands = next(o for o in room.objects if o.name == "nightstand")
    lamps = [s for s in stands.on_top if s.name == "desk lamp"]
    assert stands.quantity == 2 and [s.quantity for s in lamps] == [1]
    assert all(o.name != "floor lamp" or not o.requested for o in room.objects)


def test_a_wall_object_faced_by_a_floor_object_hangs_where_it_looks() -> None:
    plan = plan_offline("A hair salon with a salon chair facing a mirror.", 0)
    room = plan.rooms[0]
    mirror = next(o for o in room.objects if o.name == "mirror")
    assert mirror.faced_by == "salon chair"
    assert ("salon chair", "facing", "mirror") in {
        (r.subject, r.kind, r.target) for r in room.relations
    }


def test_relations_naming_places_chain_and_one_naming_an_object_ends_the_chain() -> None:
    assert _relations("A barbershop with three barber chairs in a row facing a long mirror.") == [
        ("barber chair", "in_row", None),
        ("barber chair", "facing", "mirror"),
    ]
    assert _relations("A bedroom with a bed in the corner by the window.") == [
        ("bed", "corner", None),
        ("bed", "by_window", None),
    ]
    # "on the wall" is the TV's, not the sofa's
    assert ("sofa", "wall", None) not in _relations(
        "A living room with a sofa facing a TV on the wall."
    )


def test_each_facing_a_wall_object_gives_each_its_own() -> None:
    plan = plan_offline("A hair salon with three salon chairs, each facing a mirror.", 0)
    mirrors = [o for r in plan.rooms for o in r.objects if o.name == "mirror"]
    assert [(m.quantity, m.faced_by) for m in mirrors] == [(3, "salon chair")]
