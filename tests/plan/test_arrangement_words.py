"""The planner reads what a request asks of a room's arrangement (a kitchen's counter-run
shape, desks in rows) into the plan, so that the layout never reads words."""

from __future__ import annotations

import pytest

from holomj.plan.arrangement_words import (
    counter_run_shape,
    object_rows,
    rows_asked,
    with_arrangement_words,
)
from holomj.plan.offline import plan_offline
from holomj.spec.plan import PlanObject, PlanRelation, PlanRoom

KITCHEN = [
    ("kitchen counter", "kitchen_counter"),
    ("sink counter", "sink_counter"),
    ("stove", "stove"),
    ("fridge", "fridge"),
]


def kitchen(descriptions: dict[str, str] | None = None) -> PlanRoom:
    words = descriptions or {}
    objects = [
        PlanObject(name=name, category=category, description=words.get(name, ""))
        for name, category in KITCHEN
    ]
    return PlanRoom(id="kitchen", type="kitchen", size=(3.0, 3.0), objects=objects)


@pytest.mark.parametrize(
    ("request_text", "shape"),
    [
        ("an L-shaped kitchen", "L"),
        ("a kitchen laid out in a U shape", "U"),
        ("a galley kitchen with a window", "galley"),
        ("a one-wall kitchen", "one_wall"),
        ("a flat with U-shaped counters", "U"),
        ("an apartment with an L-shaped living room and a kitchen", None),
        ("a kitchen", None),
    ],
)
def test_the_counter_run_shape_is_read_from_the_request(request_text, shape):
    assert counter_run_shape(kitchen(), request_text) == shape


def test_the_counter_run_shape_is_read_from_the_room_itself():
    room = kitchen({"kitchen counter": "l shaped kitchen counter"})
    assert counter_run_shape(room) == "L"


def test_rows_asked_reads_counts_and_plain_rows() -> None:
    assert rows_asked(["in 2 rows"]) == (True, 2)
    assert rows_asked(["twenty computers on desks in four rows"]) == (True, 4)
    assert rows_asked(["six standing desks in two rows"]) == (True, 2)
    assert rows_asked(["benches in a row"]) == (True, 1)
    assert rows_asked(["study tables in rows"]) == (True, None)
    assert rows_asked(["a rowing machine by the window", "two rows"]) == (False, None)


def test_rows_are_read_from_relations_and_the_sentences_that_name_the_object() -> None:
    desks = PlanObject(name="student desk", category="desk", quantity=3)
    row = PlanRelation(subject="student desk", kind="in_row", phrase="in a row")
    room = PlanRoom(id="classroom", type="classroom", objects=[desks], relations=[row])
    assert object_rows(room, "student desk") == 1
    bare = PlanRoom(id="classroom", type="classroom", objects=[desks])
    assert object_rows(bare, "student desk") is None
    assert object_rows(bare, "student desk", "Three student desks in two rows.") == 2
    assert object_rows(bare, "student desk", "A lamp. Desks in neat rows.") == "any"
    assert object_rows(bare, "student desk", "Chairs in two rows. Three desks.") is None


def test_the_words_are_written_into_the_room_plan() -> None:
    lamp = PlanObject(name="lamp", category="lamp", placement="wall")
    room = kitchen().model_copy(update={"objects": [*kitchen().objects, lamp]})
    written = with_arrangement_words(room, "a galley kitchen; counters in two rows")
    assert written.counter_run_shape == "galley"
    rows = {o.name: o.rows for o in written.objects}
    assert rows["kitchen counter"] == 2 and rows["stove"] is None
    assert rows["lamp"] is None  # wall objects are never in rows


def test_the_offline_planner_writes_the_shape_and_the_rows() -> None:
    plan = plan_offline("a galley kitchen", 1)
    assert plan.room("kitchen").counter_run_shape == "galley"
    classroom = plan_offline("a classroom with twelve student desks in two rows", 1)
    rows = {o.name: o.rows for o in classroom.room("classroom").objects}
    assert rows["student desk"] == 2
