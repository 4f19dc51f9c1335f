"""The offline planner: sensible plans for example prompts, limits kept, seeds, embeddings."""

from __future__ import annotations

import os
import subprocess
import sys
from collections.abc import Sequence

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from asset_pipeline.procedural.catalog import CATEGORIES
from holomj.errors import InputError
from holomj.layout.constraints import parse_constraint_text
from holomj.plan.fit import MAX_FLOOR_INSTANCES
from holomj.plan.knowledge_schema import KnowledgeBase
from holomj.plan.offline import plan_offline
from holomj.retrieval.text import TextEncoder
from holomj.spec.plan import PlanObject, PlanRoom, ScenePlan

EXAMPLES = [
    "a small kitchen",
    "a two-bedroom apartment with a home office",
    "a cozy reading room with two armchairs and a large bookshelf",
    "an office for a professor who loves plants",
    "a music room with a piano",
    "a daycare classroom",
]
MORE = [
    "a house with 3 bedrooms, 2 bathrooms and lots of plants, without a tv",
    "an 8x5 m industrial living room with oak floor and white walls",
    "a 40 square meters scandinavian studio apartment",
    "a restaurant for 20 guests",
    "a conference room for 12 people with a whiteboard",
    "a classroom with 3 m ceilings",
    "a kids room with a bunk bed and toys",
    "a hotel room with a desk with a laptop",
    "a cafe with 4 small tables and a sofa",
    "a dentist's waiting room with magazines",
    "a bathroom and a laundry room",
    "a kitchen with 100 chairs",
]


class NoEncoder:
    """An encoder that fails the test if the planner uses it."""

    name = "none"
    dim = 384

    def encode(self, texts: Sequence[str]) -> np.ndarray:
        raise AssertionError(f"the encoder was used for {list(texts)}")


def plan(prompt: str, seed: int = 0, encoder: TextEncoder | None = None) -> ScenePlan:
    return plan_offline(prompt, seed, encoder=encoder if encoder is not None else NoEncoder())


def objects(room: PlanRoom) -> dict[str, PlanObject]:
    return {o.name: o for o in room.objects}


def _made_for_the_prompt(plan: ScenePlan, name: str) -> bool:
    """A kind made for a noun the knowledge base does not know (holomj.plan.new_kinds)."""
    return any(f"'{name}'" in n and "planned as itself" in n for n in plan.notes)


def check_plan(plan: ScenePlan, kb: KnowledgeBase) -> None:
    """Every rule a plan must keep, whatever the prompt."""
    limits = kb.limits
    # a library category, or a knowledge base category whose assets come from elsewhere
    categories = set(CATEGORIES) | {kind.category for kind in kb.objects.values()}
    assert ScenePlan.model_validate_json(plan.model_dump_json()) == plan
    assert plan.planner == "offline"
    assert plan.entrance_room in {r.id for r in plan.rooms}
    assert 2.2 <= plan.wall_height <= 6.0
    for room in plan.rooms:
        if room.size is not None:
            assert all(limits.min_side <= s <= limits.max_side for s in room.size)
        else:
            assert room.area_m2 is not None
            assert limits.min_area - 0.05 <= room.area_m2 <= limits.max_grown_area + 0.05
        floor = [o for o in room.objects if o.placement == "floor"]
        wall = [o for o in room.objects if o.placement == "wall"]
        assert sum(o.quantity for o in floor) <= MAX_FLOOR_INSTANCES
        assert sum(o.quantity for o in wall) <= limits.max_wall_instances
        holders = [o for o in room.objects if o.on_top]
        assert sum(o.quantity for o in holders) <= limits.max_receptacles
        footprint = sum(
            o.size[0] * o.size[1] * o.quantity for o in floor if o.size and o.category != "rug"
        )
        area = room.area or 0.0
        if footprint > limits.footprint_fraction * area + 1e-6:
            assert footprint <= limits.single_fraction * area + 1e-6
            assert any(room.id in n and "keeps" in n for n in plan.notes)
        for obj in room.objects:
            assert obj.category in categories or _made_for_the_prompt(plan, obj.name)
            assert obj.size is not None
            if obj.on_top:
                # what the receptacle holds in this room type, or (a small thing asked for
                # that this room type's table does not list) in some room type
                allowed = {c for c, _ in kb.small_choices(room.type, obj.category)}
                allowed |= kb.allowed_small(obj.category)
                assert sum(s.quantity for s in obj.on_top) <= limits.max_small_per_receptacle
                for small in obj.on_top:
                    assert small.category in allowed, (room.id, obj.name, small.name)
                    assert small.category in categories
        ids = [i for o in floor for i in o.instances()]
        parsed = parse_constraint_text("\n".join(room.constraints), ids)
        assert parsed.warnings == [], (room.id, parsed.warnings)
        assert all(c.object in ids for c in parsed.constraints)


# --- input ------------------------------------------------------------------------------------


@pytest.mark.parametrize("prompt", ["", "   \n\t", "x" * 2001])
def test_bad_prompts(prompt: str) -> None:
    with pytest.raises(InputError) as err:
        plan(prompt)
    assert err.value.exit_code == 2
    assert "\n" not in str(err.value)


@pytest.mark.parametrize("seed", [-1, 1.5, "3", True])
def test_bad_seeds(seed: object) -> None:
    with pytest.raises(InputError, match="seed"):
        plan_offline("a kitchen", seed)  # type: ignore[arg-type]


# --- the six examples -------------------------------------------------------------------------


@pytest.mark.parametrize("prompt", EXAMPLES + MORE)
@pytest.mark.parametrize("seed", [0, 1, 2])
def test_plans_keep_the_rules(prompt: str, seed: int, kb: KnowledgeBase) -> None:
    check_plan(plan(prompt, seed), kb)


def test_small_kitchen(kb: KnowledgeBase) -> None:
    for seed in range(4):
        result = plan("a small kitchen", seed)
        assert result.scene_type == "kitchen"
        assert result.scene_type_match == "keyword 'kitchen'"
        (room,) = result.rooms
        assert room.type == "kitchen"
        assert room.area_m2 is not None and room.area_m2 < sum(kb.rooms["kitchen"].area) / 2
        assert {"kitchen counter", "sink counter", "stove", "fridge"} <= set(objects(room))


def test_two_bedroom_apartment_with_home_office() -> None:
    for seed in range(4):
        result = plan("a two-bedroom apartment with a home office", seed)
        assert result.scene_type == "apartment"
        types = [r.type for r in result.rooms]
        assert types.count("bedroom") == 2
        assert types.count("office") == 1
        assert {"living_room", "kitchen", "bathroom"} <= set(types)
        rooms = {r.id: r for r in result.rooms}
        assert result.entrance_room == "living_room"
        assert any(rooms[a].type == "bedroom" for a in rooms["bathroom"].adjacent_to)
        assert "living_room" in rooms["kitchen"].adjacent_to
        assert rooms["home_office"].adjacent_to
        assert "desk" in objects(rooms["home_office"])


def test_cozy_reading_room() -> None:
    result = plan("a cozy reading room with two armchairs and a large bookshelf")
    assert result.scene_type == "reading_room"
    assert result.style == ["cozy"]
    room = objects(result.rooms[0])
    assert room["armchair"].quantity == 2 and room["armchair"].requested
    assert room["bookshelf"].quantity == 1 and room["bookshelf"].requested
    assert room["bookshelf"].size == (1.2, 0.35, 2.0)  # the large bookshelf
    assert not room["floor lamp"].requested
    assert all("cozy" in o.description for o in result.rooms[0].objects)


def test_professor_who_loves_plants() -> None:
    result = plan("an office for a professor who loves plants")
    assert result.scene_type == "professor_office"
    assert "professor" in result.scene_type_match
    room = objects(result.rooms[0])
    assert room["potted plant"].requested and room["potted plant"].quantity >= 3
    assert {"desk", "office chair", "bookshelf"} <= set(room)
    assert any(s.name == "book" for s in room["bookshelf"].on_top)


def test_music_room_with_piano() -> None:
    result = plan("a music room with a piano")
    assert result.scene_type == "music_room"
    room = objects(result.rooms[0])
    assert room["piano"].quantity == 1 and room["piano"].requested
    assert "stool" in room
    assert any("stool-0 | near, piano-0" in line for line in result.rooms[0].constraints)


def test_daycare_classroom() -> None:
    result = plan("a daycare classroom")
    assert result.scene_type == "daycare_classroom"
    room = objects(result.rooms[0])
    assert {"kids table", "stool", "low shelf"} <= set(room)
    toys = {s.category for s in room["low shelf"].on_top}
    assert toys <= {"toy_block", "toy_ball"} and toys
    assert room["kids table"].size[2] <= 0.7


# --- other requests ---------------------------------------------------------------------------


def test_sizes_styles_and_materials() -> None:
    result = plan("an 8x5 m industrial living room with oak floor and white walls")
    (room,) = result.rooms
    assert room.size == (8.0, 5.0)
    assert "oak" in room.floor_material and "white" in room.wall_material
    assert result.style == ["industrial"]
    assert result.wall_height >= 3.0
    area = plan("a living room of 40 square meters").rooms[0]
    assert area.area_m2 == 40.0 and area.size is None


def test_big_house_with_counts_and_exclusions() -> None:
    result = plan("a house with 3 bedrooms, 2 bathrooms and lots of plants, without a tv")
    types = [r.type for r in result.rooms]
    assert types.count("bedroom") + types.count("master_bedroom") == 3
    assert types.count("bathroom") == 2
    assert not any(o.name == "television" for r in result.rooms for o in r.objects)
    plants = [o for r in result.rooms for o in r.objects if o.name == "potted plant"]
    assert any(p.requested and p.quantity >= 3 for p in plants)
    assert any("left out" in n or "no 'a tv'" in n for n in result.notes)


def test_capacity_sets_the_seats() -> None:
    room = objects(plan("a dining room for 8 people").rooms[0])
    assert room["dining chair"].quantity == 8
    restaurant = plan("a restaurant for 8 guests")
    hall = objects(restaurant.room("dining_hall"))
    assert hall["dining chair"].quantity == 8
    assert hall["dining table"].quantity == 2  # four seats at each small table


def test_small_objects_go_on_receptacles() -> None:
    room = objects(plan("a home office with a desk with a laptop and 3 mugs").rooms[0])
    on_desk = {s.name: s.quantity for s in room["desk"].on_top}
    assert on_desk["laptop"] == 1 and on_desk["mug"] == 3
    living = objects(plan("a living room with 4 candles").rooms[0])
    candles = [s for o in living.values() for s in o.on_top if s.name == "candle"]
    assert sum(c.quantity for c in candles) >= 4


def test_rugs_are_planned_and_doormats_refused() -> None:
    result = plan("a living room with a rug")
    rug = objects(result.rooms[0])["rug"]
    assert rug.requested and rug.quantity == 1
    refused = plan("a hallway with a doormat")
    assert any("doormat" in n and "keep-out" in n for n in refused.notes)


# --- impossible requests ----------------------------------------------------------------------


def test_ballroom_of_2_by_2_with_40_pianos(encoder: TextEncoder, kb: KnowledgeBase) -> None:
    result = plan("a 2 by 2 meter ballroom with 40 pianos", encoder=encoder)
    check_plan(result, kb)
    (room,) = result.rooms
    assert room.size == (2.5, 2.5)
    pianos = objects(room)["piano"]
    assert pianos.requested and 1 <= pianos.quantity < 40
    assert any("2 x 2 m" in n and "2.5" in n for n in result.notes)
    assert any("40 pianos" in n and f"planned {pianos.quantity}" in n for n in result.notes)
    assert result.scene_type_match.startswith("text embedding")


def test_kitchen_with_100_chairs_stays_a_kitchen() -> None:
    result = plan("a kitchen with 100 chairs")
    room = objects(result.rooms[0])
    assert 12 <= room["dining chair"].quantity < MAX_FLOOR_INSTANCES
    assert room["dining chair"].requested
    assert {"kitchen counter", "sink counter", "stove", "fridge"} <= set(room)
    assert any("100 chairs" in n for n in result.notes)


def test_unknown_object_is_noted_or_matched(encoder: TextEncoder) -> None:
    result = plan("a living room with a trampoline and a grand piano", encoder=encoder)
    trampoline = objects(result.rooms[0])["trampoline"]  # planned as itself, not left out
    assert trampoline.requested and trampoline.category == "trampoline"
    assert any("trampoline" in n and "planned as itself" in n for n in result.notes)
    view = plan("a living room with a view of the sea", encoder=encoder)
    assert any("view of the sea" in n and "left out" in n for n in view.notes)
    assert objects(result.rooms[0])["piano"].requested  # "grand piano" is a piano
    matched = plan("a living room with a grandfather timepiece", encoder=encoder)
    assert objects(matched.rooms[0])["grandfather clock"].requested
    assert any("grandfather timepiece" in n and "closest kind" in n for n in matched.notes)
    assert objects(plan("a bedroom with a beanbag chair").rooms[0])["bean bag"].requested


def test_tiny_room(encoder: TextEncoder, kb: KnowledgeBase) -> None:
    result = plan("a bedroom of 0.5 m", encoder=encoder)
    check_plan(result, kb)
    (room,) = result.rooms
    assert room.size == (2.5, 2.5)
    assert any("0.5" in n for n in result.notes)
    assert objects(room)["bed"].size[0] < 1.6  # a smaller bed, so that it fits


def test_too_many_rooms() -> None:
    result = plan("a house with 30 bedrooms")
    assert len(result.rooms) <= 12
    assert any("30" in n or "rooms per scene" in n for n in result.notes)


# --- seeds ------------------------------------------------------------------------------------


@pytest.mark.parametrize("prompt", EXAMPLES)
def test_same_seed_same_plan(prompt: str) -> None:
    assert plan(prompt, 11).model_dump_json() == plan(prompt, 11).model_dump_json()


@pytest.mark.parametrize("prompt", EXAMPLES)
def test_seeds_give_different_plans(prompt: str) -> None:
    plans = [plan(prompt, seed) for seed in range(6)]
    assert len({p.model_dump_json() for p in plans}) == 6
    furniture = {
        tuple((r.id, o.name, o.quantity) for r in p.rooms for o in r.objects) for p in plans
    }
    materials = {tuple((r.floor_material, r.wall_material) for r in p.rooms) for p in plans}
    assert len(furniture) >= 3
    assert len(materials) >= 2


def test_classroom_variants_across_seeds() -> None:
    kinds = set()
    for seed in range(12):
        kinds |= {o.name for o in plan("a classroom", seed).rooms[0].objects}
    assert {"student desk", "work table"} <= kinds


# --- scene types by embedding -----------------------------------------------------------------


def test_keyword_match_needs_no_model() -> None:
    for prompt in EXAMPLES + MORE:
        plan(prompt)  # NoEncoder fails the test if it is used


@pytest.mark.parametrize(
    ("prompt", "allowed"),
    [
        ("a ballroom", {"nightclub", "dance_studio", "banquet_hall"}),
        ("a research facility", {"laboratory", "science_lab"}),
        ("a recording booth", {"music_studio", "karaoke_room", "music_room"}),
        ("a tv news room", {"tv_studio", "control_room"}),
    ],
)
def test_unknown_scene_types_by_embedding(
    prompt: str, allowed: set[str], encoder: TextEncoder, kb: KnowledgeBase
) -> None:
    result = plan(prompt, encoder=encoder)
    assert result.scene_type in allowed
    assert result.scene_type_match.startswith("text embedding")
    assert "cosine" in result.scene_type_match
    assert any("not a scene type the knowledge base knows" in n for n in result.notes)
    check_plan(result, kb)


def test_dentist_waiting_room(encoder: TextEncoder) -> None:
    result = plan("a dentist's waiting room", encoder=encoder)
    assert result.scene_type == "waiting_room"
    assert "waiting chair" in objects(result.rooms[0])


# --- fuzz -------------------------------------------------------------------------------------

WORDS = [
    "a", "two", "3", "lots", "of", "with", "without", "and", "for", "small", "large", "by", "x",
    "m", "square", "meters", "kitchen", "bedroom", "bedrooms", "apartment", "office", "cafe",
    "chairs", "tables", "piano", "plants", "oak", "floor", "white", "walls", "cozy", "modern",
    "rug", "trampoline", "0.5", "100", "40", "people", "no", "tv", "books", "desk", ",", ".",
    "professor", "kids", "ceiling", "high", "seating", "bathroom", "house", "studio", "-",
]  # fmt: skip


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(text=st.text(max_size=200), seed=st.integers(0, 2**32 - 1))
def test_fuzz_any_text(text: str, seed: int, encoder: TextEncoder, kb: KnowledgeBase) -> None:
    try:
        result = plan_offline(text, seed, encoder=encoder)
    except InputError:
        assert not text.strip() or len(text) > 2000
        return
    check_plan(result, kb)


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(words=st.lists(st.sampled_from(WORDS), max_size=30), seed=st.integers(0, 1000))
def test_fuzz_prompt_words(
    words: list[str], seed: int, encoder: TextEncoder, kb: KnowledgeBase
) -> None:
    text = " ".join(words)
    try:
        result = plan_offline(text, seed, encoder=encoder)
    except InputError:
        assert not text.strip()
        return
    check_plan(result, kb)


def test_same_plan_in_another_process() -> None:
    """Plans do not depend on Python's hash seed (set order) or process state."""
    code = (
        "import hashlib; from holomj.plan.offline import plan_offline; "
        f"print(hashlib.sha256(''.join(plan_offline(p, 5).model_dump_json() for p in {EXAMPLES!r})"
        ".encode()).hexdigest())"
    )
    digests = {
        subprocess.run(
            [sys.executable, "-c", code],
            env={**os.environ, "PYTHONHASHSEED": str(hash_seed)},
            capture_output=True,
            text=True,
            check=True,
        ).stdout.strip()
        for hash_seed in (1, 2)
    }
    assert len(digests) == 1


def test_a_requested_kind_takes_the_template_objects_place(kb: KnowledgeBase) -> None:
    """'a twin bed' is the bedroom's bed, not a second one, and it stays defining."""
    room = plan("a bedroom with a twin bed").rooms[0]
    beds = [o for o in room.objects if o.category == "bed"]
    assert [(o.name, o.quantity, o.requested, o.defining) for o in beds] == [
        ("single bed", 1, True, True)
    ]
    plain = plan("a bedroom").rooms[0]
    assert [o.defining for o in plain.objects if o.category == "bed"] == [True]
    defining = kb.rooms["bedroom"].defining
    assert all(not o.defining for o in plain.objects if o.name not in defining)


def test_a_prompt_that_lists_its_rooms_gets_those_rooms() -> None:
    """Three or more kinds of room named: each once unless counted, the scene type's other
    rooms only at their minimum (no second bathroom or third bedroom nobody asked for)."""
    result = plan("a house with a kitchen, a living room, a bedroom and a bathroom")
    types = [r.type for r in result.rooms]
    assert types.count("bathroom") == 1
    assert sum(t in ("bedroom", "master_bedroom") for t in types) == 1
    assert {"kitchen", "living_room"} <= set(types)
    counted = plan("a house with a kitchen, a living room, three bedrooms and two bathrooms")
    ctypes = [r.type for r in counted.rooms]
    assert sum(t in ("bedroom", "master_bedroom") for t in ctypes) == 3
    assert ctypes.count("bathroom") == 2


def test_one_room_named_without_a_scene_is_that_room_alone() -> None:
    """'a veterinary exam room with ...' is one exam room, not a home around it."""
    result = plan("a veterinary exam room with an exam table in the middle")
    assert [r.type for r in result.rooms] == ["vet_exam_room"]
    assert "alone" in result.scene_type_match
