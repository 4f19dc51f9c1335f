"""Nouns the knowledge base does not know stay themselves (holomj.plan.new_kinds)."""

from __future__ import annotations

from holomj.plan.knowledge import knowledge_base
from holomj.plan.new_kinds import SIZE_BOUNDS, kind_name
from holomj.plan.offline import plan_offline


def _requested(text: str) -> dict[str, object]:
    plan = plan_offline(text, 0)
    return {o.name: o for r in plan.rooms for o in r.objects if o.requested}


def test_an_unknown_thing_is_planned_as_itself_with_a_sane_size() -> None:
    plan = plan_offline("A living room with a sofa and a hamster cage.", 0)
    cage = next(o for r in plan.rooms for o in r.objects if o.name == "hamster cage")
    assert cage.category == "hamster_cage" and cage.requested and cage.placement == "floor"
    low, high = SIZE_BOUNDS["floor"]
    assert cage.size is not None
    assert all(lo <= v <= hi for v, lo, hi in zip(cage.size, low, high, strict=True))
    assert any("hamster cage" in n and "planned as itself" in n for n in plan.notes)
    assert "hamster cage" not in knowledge_base().objects  # the knowledge base is unchanged


def test_a_near_synonym_is_the_known_kind_and_scene_words_are_not_things() -> None:
    assert "grandfather clock" in _requested("A hallway with a grandfather timepiece.")
    plan = plan_offline("A living room with a view of the sea.", 0)
    assert any("view of the sea" in n and "left out" in n for n in plan.notes)
    assert all(o.name != "view of the sea" for r in plan.rooms for o in r.objects)


def test_kind_names_are_plan_object_names() -> None:
    assert kind_name("a Hamster-Cage!") == "hamster cage"
    assert kind_name("the ") is None


def test_an_unknown_things_relation_words_are_not_its_name() -> None:
    assert kind_name("a laser cutter against the wall") == "laser cutter"
    assert kind_name("a scale near the door") == "scale"


def test_a_thing_no_room_type_has_goes_to_the_main_room() -> None:
    plan = plan_offline("A studio apartment with a telescope by the window.", 0)
    home = next(r.id for r in plan.rooms for o in r.objects if o.name == "telescope")
    assert home == max(plan.rooms, key=lambda r: r.area_m2 or 0).id  # not the bathroom
