"""Seats that go with their table, areas of a room that are no rooms, things put on the wall or
on a counter (holomj.plan.seating, object_requests, rooms, furnish)."""

from __future__ import annotations

import pytest

from holomj.plan.draft import spread
from holomj.plan.knowledge import knowledge_base
from holomj.plan.offline import plan_offline
from holomj.plan.prompt import parse_prompt
from holomj.plan.seating import seat_for, seat_pairs, seating_table
from holomj.spec.plan import ScenePlan


def _counts(plan: ScenePlan) -> dict[str, int]:
    out: dict[str, int] = {}
    for room in plan.rooms:
        for obj in room.objects:
            out[obj.name] = out.get(obj.name, 0) + obj.quantity
    return out


def _small(plan: ScenePlan) -> dict[str, int]:
    out: dict[str, int] = {}
    for room in plan.rooms:
        for obj in room.objects:
            for item in obj.on_top:
                holders = item.instances or obj.quantity
                out[item.name] = out.get(item.name, 0) + item.quantity * holders
    return out


def test_the_templates_pair_seats_with_their_tables() -> None:
    kb = knowledge_base()
    pairs = seat_pairs(kb)
    assert "dining chair" in pairs["dining table"]
    assert seating_table(kb, "table", ["coffee table", "side table"]) == "dining table"
    assert seating_table(kb, "table", ["cafe table"]) == "cafe table"
    assert seat_for(kb, "chair", "dining table", []) == "dining chair"
    assert seat_for(kb, "chair", "coffee table", []) is None


def test_chairs_around_a_table_are_the_tables_own_seats_not_the_rooms_armchairs() -> None:
    plan = plan_offline(
        "A reading room with four tall bookshelves against the walls, a large table in the "
        "middle and six chairs around it.",
        0,
    )
    counts = _counts(plan)
    assert counts.get("dining chair") == 6
    assert counts.get("dining table") == 1
    assert counts.get("armchair", 0) != 6


def test_a_small_table_with_four_chairs_gets_the_chairs_of_that_table() -> None:
    counts = _counts(plan_offline("A playroom with a small table with four chairs.", 0))
    assert counts.get("cafe table") == 1 and counts.get("cafe chair") == 4


@pytest.mark.parametrize(
    ("text", "chairs"),
    [
        ("A bakery with three small tables with two chairs each.", 6),
        ("A library with four long study tables with four chairs each.", 16),
        ("A cafe with five tables, each with two chairs.", 10),
    ],
)
def test_chairs_each_multiply_by_the_tables(text: str, chairs: int) -> None:
    parsed = parse_prompt(text, knowledge_base())
    assert [o.quantity for o in parsed.objects if o.kind == "chair"] == [chairs]


def test_a_table_for_two_gets_two_seats_and_a_table_for_four_stays_one_table() -> None:
    counts = _counts(plan_offline("A studio apartment with a bed and a dining table for two.", 0))
    assert counts.get("dining table") == 1 and counts.get("dining chair") == 2
    counts = _counts(plan_offline("A kitchen with a table for four.", 0))
    assert counts.get("dining table") == 1 and counts.get("dining chair") == 4


def test_a_corner_or_an_area_of_a_room_is_no_room_of_its_own() -> None:
    plan = plan_offline(
        "A daycare room with six small tables, a reading corner with a rug and beanbags, "
        "and a changing table.",
        0,
    )
    assert len(plan.rooms) == 1
    assert any("as part of" in note for note in plan.notes)
    assert _counts(plan).get("rug") == 1


def test_where_the_scene_is_adds_no_room() -> None:
    plan = plan_offline("A home gym in the garage with a squat rack and a rowing machine.", 0)
    assert len(plan.rooms) == 1
    assert any("says where" in note for note in plan.notes)


def test_a_kitchen_in_a_studio_is_its_kitchen_area_but_a_flats_rooms_stay_rooms() -> None:
    studio = plan_offline("A studio apartment with a bed, a sofa and a small kitchen.", 0)
    assert not any(r.id.startswith("kitchen") for r in studio.rooms)
    assert _counts(studio).get("stove", 0) >= 1
    flat = plan_offline(
        "A two-bedroom flat with a kitchen, the second bedroom is a home office with a desk.", 0
    )
    assert sum(r.id.startswith("kitchen") for r in flat.rooms) == 1
    assert any(r.id == "home_office" for r in flat.rooms)


@pytest.mark.parametrize(
    ("text", "small"),
    [
        ("A kitchen with a fridge, a cooker, a sink and a microwave.", "microwave"),
        ("A cafe with a counter with an espresso machine on it.", "coffee machine"),
    ],
)
def test_a_small_thing_no_receptacle_lists_still_gets_a_place(text: str, small: str) -> None:
    plan = plan_offline(text, 0)
    assert _small(plan).get(small, 0) >= 1, plan.notes
    assert not any("left out" in note for note in plan.notes)


def test_a_flat_thing_on_the_wall_hangs_there() -> None:
    plan = plan_offline("An observatory with a telescope and a star chart on the wall.", 0)
    charts = [o for r in plan.rooms for o in r.objects if o.name == "star chart"]
    assert len(charts) == 1 and charts[0].placement == "wall"
    _width, depth, height = charts[0].size or (0, 0, 0)
    assert depth < 0.05 < height


def test_curtains_dress_each_window_once_and_a_count_brings_its_windows() -> None:
    def dressings(text: str) -> tuple[int, int | None]:
        plan = plan_offline(text, 0)
        room = plan.rooms[0]
        count = sum(o.quantity for o in room.objects if o.category in {"curtains", "blinds"})
        return count, room.windows.count

    assert dressings("A living room with two windows and curtains on every window.") == (2, 2)
    assert dressings("A bedroom with three curtains.") == (3, 3)
    assert dressings("An office with blinds.")[0] == 1
    count, windows = dressings("A bedroom with curtains and no windows.")
    assert (count, windows) == (0, 0)


def test_rooms_each_with_an_object_get_one_each_and_a_bed_asked_for_is_the_rooms_bed() -> None:
    plan = plan_offline(
        "A beach house with a living room, a kitchen, two bedrooms each with a bunk bed, and a "
        "bathroom.",
        0,
    )
    sleeping = [r for r in plan.rooms if r.type in {"bedroom", "master_bedroom"}]
    assert len(sleeping) == 2
    for room in sleeping:
        names = [o.name for o in room.objects]
        assert names.count("bunk bed") == 1 and "bed" not in names, (room.id, names)
    assert not any(o.name == "bunk bed" for r in plan.rooms if r not in sleeping for o in r.objects)


def test_each_refers_to_the_objects_named_before() -> None:
    plan = plan_offline(
        "A nursery with two cribs side by side, a changing table and a mobile above each crib.", 0
    )
    objects = {o.name: o for r in plan.rooms for o in r.objects}
    assert objects["crib"].quantity == 2
    assert (objects["baby mobile"].quantity, objects["baby mobile"].above) == (2, "crib")
    lab = plan_offline("A biology lab with four lab benches and a microscope on each bench.", 0)
    benches = [o for r in lab.rooms for o in r.objects if o.name == "lab bench"]
    assert [b.quantity for b in benches] == [4]
    assert [(s.name, s.quantity) for s in benches[0].on_top if s.name == "microscope"] == [
        ("microscope", 1)
    ]
    assert not any(o.name == "bench" for r in lab.rooms for o in r.objects)


def test_twin_beds_are_a_pair_in_the_one_room_that_has_them() -> None:
    plan = plan_offline("A flat with two bedrooms, one with twin beds.", 0)
    beds = {r.id: [(o.name, o.quantity) for o in r.objects if "bed" in o.name] for r in plan.rooms}
    with_twins = [rid for rid, found in beds.items() if ("single bed", 2) in found]
    assert len(with_twins) == 1 and with_twins[0].startswith("bedroom")
    assert all(not found for rid, found in beds.items() if not rid.startswith("bedroom"))
    matching = _counts(plan_offline("A living room with matching armchairs.", 0))
    assert matching["armchair"] == 2


@pytest.mark.parametrize(
    ("text", "table", "seat", "seats"),
    [
        (
            "A meeting room with a long table in the middle, ten chairs around it and a "
            "whiteboard.",
            "conference table",
            "office chair",
            10,
        ),
        (
            "A boardroom with a long oval table in the middle and twelve black leather chairs "
            "around it.",
            "conference table",
            "executive chair",
            12,
        ),
    ],
)
def test_chairs_asked_around_the_rooms_table_are_all_its_chairs(
    text: str, table: str, seat: str, seats: int
) -> None:
    """The room's own table and seat kinds, and the template's seats do not come on top."""
    plan = plan_offline(text, 0)
    counts = _counts(plan)
    assert counts.get(table) == 1 and counts.get(seat) == seats, counts
    chairs = set(knowledge_base().generics["chair"].kinds) - {"armchair", "stool", "bench"}
    assert sum(n for kind, n in counts.items() if kind in chairs) == seats, counts


@pytest.mark.parametrize(
    ("text", "kept", "total"),
    [
        ("A study with a desk, an office chair and two chairs for visitors.", "office chair", 3),
        ("A living room with a sofa, two armchairs and a chair.", "armchair", 3),
    ],
)
def test_chairs_asked_besides_other_seats_are_more_seats(text: str, kept: str, total: int) -> None:
    """A generic word does not take over the kind another phrase asked for."""
    counts = _counts(plan_offline(text, 0))
    chairs = set(knowledge_base().generics["chair"].kinds)
    asked = {"office chair": 1, "armchair": 2}[kept]
    assert counts[kept] == asked, counts
    assert sum(n for kind, n in counts.items() if kind in chairs) == total, counts


def test_spread_puts_a_few_small_objects_on_some_of_many_receptacles() -> None:
    assert spread(1, 8) == (1, 1)
    assert spread(10, 8) == (2, 5)
    assert spread(8, 8) == (1, None)
    assert spread(3, 1) == (3, None)


@pytest.mark.parametrize(
    ("text", "holder", "small", "total"),
    [
        (
            "An open office with eight desks, eight office chairs and a printer.",
            "desk",
            "printer",
            1,
        ),
        ("A computer lab with twenty desks in rows and a computer on each desk.", "desk", None, 20),
        (
            "A library with ten bookshelves, four study tables and three computers on a desk.",
            "desk",
            None,
            3,
        ),
    ],
)
def test_small_objects_asked_for_come_in_the_number_asked(
    text: str, holder: str, small: str | None, total: int
) -> None:
    """Not one per receptacle instance, and not dropped for a room's receptacle cap; the
    template's own of that kind do not come on top."""
    plan = plan_offline(text, 0)
    counts = _small(plan)
    kinds = {small} if small else {"laptop", "desktop computer", "computer"}
    assert sum(n for name, n in counts.items() if name in kinds) == total, counts
    holders = [o for r in plan.rooms for o in r.objects if any(s.name in kinds for s in o.on_top)]
    assert [o.name for o in holders] == [holder]
