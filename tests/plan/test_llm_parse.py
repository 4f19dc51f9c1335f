"""Strict parsing of LLM answers: extraction, per-step validation, normalisation, fuzzing."""

from __future__ import annotations

import json
from typing import Any

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from holomj.plan.llm_json import LLMResponseError, extract_json_object
from holomj.plan.llm_parse import (
    normalise_object_name,
    normalise_room_id,
    parse_constraints,
    parse_doors,
    parse_floor_plan,
    parse_objects,
    parse_wall_height,
    parse_windows,
)
from holomj.spec.plan import PlanObject

ROOMS = ["living_room", "kitchen"]


def objects_answer(**objects: dict[str, Any]) -> str:
    return json.dumps({"objects": objects})


def item(**fields: Any) -> dict[str, Any]:
    return {"location": "floor", "size_cm": [100, 50, 80], **fields}


# --------------------------------------------------------------------------- extraction


@pytest.mark.parametrize(
    "content",
    [
        '{"a": 1}',
        '  \n{"a": 1}\n',
        '```json\n{"a": 1}\n```',
        '```JSON\n{"a": 1}\n```',
        '```\n{"a": 1}\n```',
        'Here is the plan:\n\n```json\n{"a": 1}\n```\nLet me know if you need more.',
        '<think>The user wants a room... {"a": 2}</think>\n{"a": 1}',
    ],
)
def test_one_json_object_is_extracted(content: str) -> None:
    assert extract_json_object(content) == {"a": 1}


@pytest.mark.parametrize(
    ("content", "message"),
    [
        ("", "the answer is empty"),
        ("   \n", "the answer is empty"),
        ('Sure! {"a": 1}', "not JSON: the answer must be one JSON object"),
        ('```json\n{"a": 1}\n```\n```json\n{"b": 2}\n```', "2 code blocks"),
        ("```python\nimport os\nos.remove('x')\n```", "not JSON: a python code block"),
        ('```json\n{"a": 1}\n', "not closed"),
        ('{"a": 1', "invalid JSON: Expecting ',' delimiter"),
        ('{"a": 1} {"b": 2}', "invalid JSON: Extra data"),
        ('{"a": NaN}', "invalid JSON: NaN is not a JSON number"),
        ('{"a": 1e999}', "invalid JSON: number 1e999 is out of range"),
        ("[1, 2]", "expected one JSON object, got a JSON list"),
        ('```json\n"text"\n```', "not JSON: the code block must hold one JSON object"),
        ("{" * 5000 + "}" * 5000, "invalid JSON"),
        ("x" * 300_000, "longer than"),
    ],
)
def test_anything_else_is_rejected(content: str, message: str) -> None:
    with pytest.raises(LLMResponseError) as info:
        extract_json_object(content)
    assert message in str(info.value)
    assert "\n" not in str(info.value)


# --------------------------------------------------------------------------- names


@pytest.mark.parametrize(
    ("raw", "name"),
    [
        ("Dining Chair", "dining chair"),
        ("dining chair-2", "dining chair"),
        ("dining chair - 3", "dining chair"),
        ("coffee_table", "coffee table"),
        ("  TV   stand ", "tv stand"),
        ("Café Table", "cafe table"),
        ("arm-chair", "arm chair"),
        ("shelf (wall)", "shelf wall"),
        ("'lamp'.", "lamp"),
        ("x" * 80, "x" * 64),
        ("***", None),
        ("-1", None),
    ],
)
def test_object_names_are_normalised(raw: str, name: str | None) -> None:
    assert normalise_object_name(raw) == name


def test_room_ids_are_normalised() -> None:
    assert normalise_room_id("Living Room") == "living_room"
    assert normalise_room_id("bedroom-2") == "bedroom_2"
    assert normalise_room_id("?!") is None


# --------------------------------------------------------------------------- steps


def test_floor_plan_clamps_room_sides_and_rejects_repeated_ids() -> None:
    answer = {
        "scene_type": "Apartment",
        "rooms": [
            {"id": "Living Room", "type": "Living Room", "width_m": 12, "depth_m": 1.5,
             "floor_material": " oak ", "wall_material": "white"},
        ],
    }  # fmt: skip
    draft, notes = parse_floor_plan(json.dumps(answer))
    room = draft.rooms[0]
    assert (room.id, room.type, room.width, room.depth) == ("living_room", "living_room", 8.0, 2.5)
    assert room.floor_material == "oak"
    assert draft.scene_type == "apartment"
    assert len(notes) == 2 and "width 12 m clamped to 8 m" in notes[0]
    answer["rooms"].append({**answer["rooms"][0], "id": "living room"})
    with pytest.raises(LLMResponseError, match="'living_room' is used twice"):
        parse_floor_plan(json.dumps(answer))


def test_wall_height_is_clamped() -> None:
    assert parse_wall_height('{"wall_height_m": 2.7}') == (2.7, [])
    height, notes = parse_wall_height('{"wall_height_m": 12}')
    assert height == 4.5 and "clamped" in notes[0]
    with pytest.raises(LLMResponseError, match="wall_height_m: Input should be greater than 0"):
        parse_wall_height('{"wall_height_m": -1}')
    with pytest.raises(LLMResponseError, match="wall_height_m: Field required"):
        parse_wall_height('{"height": 2.7}')


def test_doors_resolve_rooms_and_note_unconnected_ones() -> None:
    doors, notes = parse_doors(
        '{"connections": [["Living Room", "kitchen"], ["kitchen", "living_room"]], '
        '"entrance_room": "living room"}',
        [*ROOMS, "bathroom"],
    )
    assert doors.connections == (("living_room", "kitchen"),)
    assert doors.entrance_room == "living_room"
    assert notes == ["room 'bathroom' has no door asked for; the floor planner will connect it"]
    with pytest.raises(LLMResponseError, match="unknown room 'garage'"):
        parse_doors('{"connections": [["garage", "kitchen"]], "entrance_room": "kitchen"}', ROOMS)
    with pytest.raises(LLMResponseError, match="cannot connect to itself"):
        parse_doors('{"connections": [["kitchen", "kitchen"]], "entrance_room": "kitchen"}', ROOMS)
    with pytest.raises(LLMResponseError, match="entrance_room: unknown room"):
        parse_doors('{"connections": [], "entrance_room": "porch"}', ROOMS)


def test_windows_per_room() -> None:
    windows, _ = parse_windows(
        '{"rooms": [{"room": "kitchen", "count": 1, "kind": "Slider"}]}', ROOMS
    )
    assert windows["kitchen"].count == 1 and windows["kitchen"].kind == "slider"
    assert "living_room" not in windows
    with pytest.raises(LLMResponseError, match="listed twice"):
        parse_windows(
            '{"rooms": [{"room": "kitchen", "count": 1, "kind": "hung"},'
            '{"room": "Kitchen", "count": 2, "kind": "hung"}]}',
            ROOMS,
        )
    with pytest.raises(LLMResponseError, match=r"rooms\[0\].kind"):
        parse_windows('{"rooms": [{"room": "kitchen", "count": 1, "kind": "bay"}]}', ROOMS)


def test_objects_are_mapped_with_notes() -> None:
    content = objects_answer(
        **{
            "Sofa": item(size_cm=[220, 95, 85], category="Sofa", quantity=1),
            "sofa-1": item(),
            "rug": item(size_cm=[200, 140, 0.5], category="carpet"),
            "stool": item(quantity=0),
            "chair": item(quantity=50, variance="Varied"),
            "mirror": item(location="wall", size_cm=[60, 3, 80], above="sofa"),
            "clock": item(location="wall", size_cm=None, above="fireplace"),
            "lamp": item(above="sofa"),
            "table": item(
                objects_on_top=[
                    {"name": "Vase", "quantity": 2},
                    {"name": "vase-1"},
                    {"name": "cup", "quantity": 0},
                    {"name": "Book", "quantity": 99, "category": "book"},
                ]
            ),
        }
    )
    objects, notes = parse_objects(
        content, room_id="den", categories=["sofa", "book"], request="a den with a big Sofa"
    )
    by_name = {o.name: o for o in objects}
    assert list(by_name) == ["sofa", "rug", "chair", "mirror", "clock", "lamp", "table"]
    assert by_name["sofa"].category == "sofa" and by_name["sofa"].requested
    assert by_name["sofa"].size == (2.2, 0.95, 0.85)
    assert by_name["rug"].size == (2.0, 1.4, 0.01) and by_name["rug"].category is None
    assert by_name["chair"].quantity == 20 and by_name["chair"].variance == "varied"
    assert by_name["mirror"].above == "sofa" and by_name["mirror"].placement == "wall"
    assert by_name["clock"].above is None and by_name["clock"].size is None
    assert by_name["lamp"].above is None
    on_top = by_name["table"].on_top
    assert [(s.name, s.quantity, s.category) for s in on_top] == [
        ("vase", 2, None),
        ("book", 10, "book"),
    ]
    text = "\n".join(notes)
    for expected in (
        "object 'sofa-1' repeats 'sofa'; dropped",
        "'rug': category 'carpet' is not in the asset library",
        "'rug': size 200 x 140 x 0.5 cm clamped to 200 x 140 x 1 cm",
        "'stool' has quantity 0; dropped",
        "'chair': quantity 50 reduced to 20",
        "'clock': hangs above 'fireplace', not a floor object here",
        "'lamp': 'above' is for wall objects",
        "'cup' on top has quantity 0",
        "'book': quantity 99 reduced to 10",
    ):
        assert expected in text, expected


def test_object_heights_are_capped_at_the_wall_height() -> None:
    content = objects_answer(
        wardrobe=item(size_cm=[100, 60, 320]), poster=item(location="wall", size_cm=[60, 1, 300])
    )
    objects, notes = parse_objects(content, room_id="r", wall_height_m=2.5)
    assert [o.size for o in objects] == [(1.0, 0.6, 2.5), (0.6, 0.01, 2.5)]
    assert len(notes) == 2
    objects, notes = parse_objects(content, room_id="r")
    assert [o.size[2] for o in objects] == [3.2, 3.0] and notes == []


def test_objects_schema_errors() -> None:
    with pytest.raises(LLMResponseError, match="location: Field required"):
        parse_objects(objects_answer(sofa={"size_cm": [1, 2, 3]}), room_id="r")
    with pytest.raises(LLMResponseError, match="size_cm: Tuple should have at most 3 items"):
        parse_objects(objects_answer(sofa=item(size_cm=[1, 2, 3, 4])), room_id="r")
    with pytest.raises(LLMResponseError, match="colour: unknown field"):
        parse_objects(objects_answer(sofa=item(colour="red")), room_id="r")


def test_constraints_drop_unknown_instances() -> None:
    lines, notes = parse_constraints(
        json.dumps(
            {
                "constraints": [
                    "Sofa-0 | edge",
                    "coffee_table-0 | middle | in front of, sofa-0 | around, sofa-0",
                    "lamp-0 | near, sofa-3",
                    "painting-0 | edge",
                ]
            }
        ),
        room_id="den",
        instance_names=["sofa-0", "coffee table-0", "lamp-0"],
    )
    assert lines == [
        "sofa-0 | edge",
        "coffee table-0 | middle | in front of, sofa-0 | near, sofa-0 | face to, sofa-0",
    ]
    assert any("unknown object 'sofa-3'" in n for n in notes)
    assert any("unknown object 'painting-0'" in n for n in notes)
    assert all(n.startswith("room 'den' constraints: ") for n in notes)


# --------------------------------------------------------------------------- fuzz

_json = st.recursive(
    st.none() | st.booleans() | st.integers() | st.floats(allow_nan=False) | st.text(max_size=20),
    lambda children: (
        st.lists(children, max_size=4) | st.dictionaries(st.text(max_size=10), children, max_size=4)
    ),
    max_leaves=20,
)
_keys = st.sampled_from(
    ["objects", "rooms", "constraints", "connections", "entrance_room", "wall_height_m",
     "scene_type", "location", "size_cm", "quantity", "room", "count", "kind", "id"]
)  # fmt: skip
_answer = st.dictionaries(_keys | st.text(max_size=8), _json, max_size=5)
_name = st.text(min_size=1, max_size=30)
_object = st.fixed_dictionaries(
    {
        "location": st.sampled_from(["floor", "wall", "Wall"]),
        "size_cm": st.none()
        | st.lists(st.floats(min_value=0.001, max_value=10_000), min_size=3, max_size=3),
    },
    optional={
        "quantity": st.integers(0, 100),
        "variance": st.sampled_from(["same", "varied", "Varied"]),
        "category": _name,
        "above": _name,
        "description": st.text(max_size=600),
        "objects_on_top": st.lists(
            st.fixed_dictionaries(
                {"name": _name}, optional={"quantity": st.integers(0, 100), "category": _name}
            ),
            max_size=12,
        ),
    },
)
PARSERS = [
    parse_floor_plan,
    parse_wall_height,
    lambda text: parse_doors(text, ROOMS),
    lambda text: parse_windows(text, ROOMS),
    lambda text: parse_objects(text, room_id="r", categories=["sofa"], request="a sofa"),
    lambda text: parse_constraints(text, room_id="r", instance_names=["sofa-0", "lamp-0"]),
]
FUZZ = settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def _only_our_errors(content: str) -> None:
    for parse in PARSERS:
        try:
            parse(content)
        except LLMResponseError as err:
            assert "\n" not in str(err)


@FUZZ
@given(st.text(max_size=300))
def test_fuzz_arbitrary_text(content: str) -> None:
    _only_our_errors(content)


@FUZZ
@given(_answer, st.booleans())
def test_fuzz_arbitrary_json(answer: dict[str, Any], fence: bool) -> None:
    text = json.dumps(answer)
    _only_our_errors(f"```json\n{text}\n```" if fence else text)


@FUZZ
@given(st.dictionaries(_name, _object, max_size=8))
def test_fuzz_objects_give_valid_plan_objects(objects: dict[str, Any]) -> None:
    try:
        result, notes = parse_objects(
            json.dumps({"objects": objects}), room_id="r", categories=["sofa", "Lamp"]
        )
    except LLMResponseError:
        return
    names = [o.name for o in result]
    assert len(names) == len(set(names))
    for plan_object in result:
        assert PlanObject.model_validate(plan_object.model_dump()) == plan_object
        assert plan_object.category in (None, "sofa", "Lamp")
    assert all(isinstance(n, str) and "\n" not in n for n in notes)
