"""Request parsing: scene keywords, room counts, sizes, styles, materials, objects, exclusions."""

from __future__ import annotations

import pytest

from holomj.plan.knowledge_schema import KnowledgeBase
from holomj.plan.prompt import (
    MANY,
    ParsedPrompt,
    normalise_words,
    parse_prompt,
    plural_forms,
    tokenize,
)


def parse(text: str, kb: KnowledgeBase) -> ParsedPrompt:
    return parse_prompt(text, kb)


def objects(parsed: ParsedPrompt) -> dict[str, tuple[int | None, bool]]:
    return {o.kind: (o.quantity, o.many) for o in parsed.objects if not o.excluded}


def test_tokenize_and_numbers() -> None:
    assert tokenize("A Two-Bedroom flat, 8x5m!") == [
        "a", "two", "bedroom", "flat", ",", "8", "x", "5", "m", "!",
    ]  # fmt: skip
    assert tokenize("a professor's café of 40 m²") == ["a", "professor", "cafe", "of", "40", "sqm"]
    assert normalise_words(tokenize("twenty five chairs and a dozen cups")) == [
        "25", "chairs", "and", "12", "cups",
    ]  # fmt: skip
    assert normalise_words(tokenize("lots of plants, a couple of lamps")) == [
        MANY, "plants", ",", "2", "lamps",
    ]  # fmt: skip
    assert normalise_words(tokenize("one hundred chairs")) == ["100", "chairs"]


def test_plural_forms() -> None:
    assert plural_forms("bookshelf") == ["bookshelves", "bookshelfs"]
    assert plural_forms("dining chair") == ["dining chairs"]
    assert plural_forms("bench") == ["benches"]
    assert "pianos" in plural_forms("piano")
    assert plural_forms("nursery") == ["nurseries"]


@pytest.mark.parametrize(
    ("prompt", "scene"),
    [
        ("a small kitchen", "kitchen"),
        ("a two-bedroom apartment with a home office", "apartment"),
        ("a cozy reading room with two armchairs and a large bookshelf", "reading_room"),
        ("an office for a professor who loves plants", "office"),
        ("a music room with a piano", "music_room"),
        ("a daycare classroom", "daycare_classroom"),
        ("A Studio Apartment", "studio_apartment"),
        ("a house with a kitchen", "house"),
        ("a desk in a bedroom", "bedroom"),
    ],
)
def test_scene_keyword_in_head(prompt: str, scene: str, kb: KnowledgeBase) -> None:
    assert parse(prompt, kb).scene == scene


def test_refinement_words_are_found(kb: KnowledgeBase) -> None:
    parsed = parse("an office for a professor who loves plants", kb)
    assert ("professor_office", "professor") in parsed.refinements


def test_unknown_scene_has_no_keyword_but_a_head(kb: KnowledgeBase) -> None:
    parsed = parse("a 2 by 2 meter ballroom with 40 pianos", kb)
    assert parsed.scene is None
    assert parsed.head == "ballroom"
    assert parsed.dims == (2.0, 2.0)
    assert objects(parsed) == {"piano": (40, False)}


@pytest.mark.parametrize(
    ("prompt", "template", "count"),
    [
        ("a two-bedroom apartment", "bedroom", 2),
        ("an apartment with 3 bedrooms", "bedroom", 3),
        ("a 2 bed 1 bath flat", "bedroom", 2),
        ("a house with two bathrooms", "bathroom", 2),
        ("an apartment with a home office", "home_office", None),
        ("a house with a kitchen and a bathroom", "bathroom", None),
        ("an apartment without a dining room", "dining_room", 0),
    ],
)
def test_room_counts(prompt: str, template: str, count: int | None, kb: KnowledgeBase) -> None:
    rooms = {r.template: r for r in parse(prompt, kb).rooms}
    assert template in rooms
    assert rooms[template].count == count


def test_rooms_without_scene(kb: KnowledgeBase) -> None:
    parsed = parse("3 bedrooms and a bathroom", kb)
    assert parsed.scene is None
    assert [(r.template, r.count) for r in parsed.rooms] == [("bedroom", 3), ("bathroom", None)]


@pytest.mark.parametrize(
    ("prompt", "dims", "area"),
    [
        ("a kitchen of 8 by 5 meters", (8.0, 5.0), None),
        ("an 8x5 m kitchen", (8.0, 5.0), None),
        ("a 4 x 3.5 m office", (4.0, 3.5), None),
        ("a 40 square meters living room", None, 40.0),
        ("a living room of 40 m2", None, 40.0),
        ("a 400 square feet bedroom", None, pytest.approx(37.16, abs=0.01)),
        ("a 300 by 400 cm bathroom", (3.0, 4.0), None),
        ("a room of 0.5 m", (0.5, 0.5), None),
    ],
)
def test_sizes(prompt: str, dims: object, area: object, kb: KnowledgeBase) -> None:
    parsed = parse(prompt, kb)
    assert parsed.dims == dims
    assert parsed.area_m2 == area


def test_room_size_attaches_to_its_room(kb: KnowledgeBase) -> None:
    parsed = parse("an apartment with a 4 by 3 m kitchen", kb)
    assert parsed.dims is None
    (kitchen,) = [r for r in parsed.rooms if r.template == "kitchen"]
    assert kitchen.dims == (4.0, 3.0)


def test_object_sizes_and_heights_are_not_room_sizes(kb: KnowledgeBase) -> None:
    parsed = parse("a bedroom with a 2 by 1 m desk and 3 m high ceilings", kb)
    assert parsed.dims is None
    assert parsed.wall_height_m == 3.0
    assert any("object size" in n for n in parsed.notes)


@pytest.mark.parametrize(
    ("prompt", "word"),
    [
        ("a small kitchen", "small"),
        ("a large modern apartment", "large"),
        ("a cozy tiny bedroom", "tiny"),
        ("a spacious 2-bedroom flat", "spacious"),
    ],
)
def test_size_words(prompt: str, word: str, kb: KnowledgeBase) -> None:
    assert parse(prompt, kb).size_word == word


def test_size_word_of_an_object_is_not_the_scene_size(kb: KnowledgeBase) -> None:
    parsed = parse("a large bookshelf in a library", kb)
    assert parsed.size_word is None
    assert parsed.objects[0].size == "large"


def test_styles_and_materials(kb: KnowledgeBase) -> None:
    parsed = parse(
        "an industrial, cozy loft with oak floor, white walls and a concrete ceiling", kb
    )
    assert parsed.styles == ["industrial", "cozy"]
    assert parsed.materials == {
        "floor": "oak wood floor",
        "wall": "white painted wall",
        "ceiling": "concrete ceiling",
    }


@pytest.mark.parametrize(
    ("prompt", "surface", "text"),
    [
        ("a kitchen with dark hardwood floors", "floor", "dark wood floor"),
        ("a bedroom with light grey walls", "wall", "light grey painted wall"),
        ("a loft with exposed brick walls", "wall", "red brick wall"),
        ("a carpeted bedroom", "floor", "carpet floor"),
        ("a bathroom with white marble floor", "floor", "white marble floor"),
        ("a scandinavian living room with white oak flooring", "floor", "white oak wood floor"),
    ],
)
def test_material_phrases(prompt: str, surface: str, text: str, kb: KnowledgeBase) -> None:
    assert parse(prompt, kb).materials[surface] == text


def test_material_words_before_objects_describe_the_object(kb: KnowledgeBase) -> None:
    parsed = parse("a bedroom with a wooden desk and a leather sofa", kb)
    assert parsed.materials == {}
    desk = next(o for o in parsed.objects if o.kind == "desk")
    assert desk.adjectives == ["wooden"]


def test_dark_wood_is_a_material_not_a_style(kb: KnowledgeBase) -> None:
    parsed = parse("a dark living room with dark wood floors", kb)
    assert parsed.styles == ["dark"]
    assert parsed.materials["floor"] == "dark wood floor"


@pytest.mark.parametrize(
    ("prompt", "expected"),
    [
        ("a reading room with two armchairs and a large bookshelf", {
            "armchair": (2, False), "bookshelf": (1, False)}),
        ("a living room with 3 plants", {"potted plant": (3, False)}),
        ("a living room with lots of plants", {"potted plant": (None, True)}),
        ("an office for someone who loves plants", {"potted plant": (None, True)}),
        ("a music room with a piano", {"piano": (1, False)}),
        ("a kitchen with 100 chairs", {"chair": (100, False)}),
        ("a dining room with twelve dining chairs", {"dining chair": (12, False)}),
        ("a bedroom with a couple of nightstands", {"nightstand": (2, False)}),
        ("a den with a couch and a tv", {"sofa": (1, False), "television": (1, False)}),
        ("a study with a desk with a laptop and 3 mugs", {
            "desk": (1, False), "laptop": (1, False), "mug": (3, False)}),
        ("a classroom with bookshelves", {"bookshelf": (None, False)}),
    ],
)  # fmt: skip
def test_object_requests(prompt: str, expected: dict, kb: KnowledgeBase) -> None:
    assert objects(parse(prompt, kb)) == expected


def test_plural_without_number_and_generic_words(kb: KnowledgeBase) -> None:
    parsed = parse("a kitchen with chairs", kb)
    (chairs,) = parsed.objects
    assert chairs.generic and chairs.plural and chairs.quantity is None


def test_objects_asked_in_a_room_of_the_scene(kb: KnowledgeBase) -> None:
    parsed = parse("an apartment with a kitchen with a big fridge. Add a piano.", kb)
    rooms = {o.kind: o.room for o in parsed.objects}
    assert rooms == {"fridge": "kitchen", "piano": None}
    fridge = next(o for o in parsed.objects if o.kind == "fridge")
    assert fridge.size == "large"


def test_exclusions(kb: KnowledgeBase) -> None:
    parsed = parse("a living room without a tv or a bookshelf, with a sofa", kb)
    excluded = {o.kind for o in parsed.objects if o.excluded}
    assert excluded == {"television", "bookshelf"}
    assert objects(parsed) == {"sofa": (1, False)}
    assert parse("a bedroom with no windows", kb).windows == 0
    assert parse("a bedroom with 3 windows", kb).windows == 3


def test_refused_and_unknown_things(kb: KnowledgeBase) -> None:
    parsed = parse("a living room with a doormat, a trampoline and a view of the sea", kb)
    assert [r.name for r in parsed.refused] == ["doormat"]
    assert parsed.unknown == ["trampoline", "view of the sea"]


def test_capacity(kb: KnowledgeBase) -> None:
    assert parse("a dining room for 8 people", kb).capacity == 8
    assert parse("a classroom for twenty students", kb).capacity == 20
    assert parse("a conference room with seating for 12", kb).capacity == 12
    assert parse("a kitchen for a family", kb).capacity is None


def test_parsing_is_pure(kb: KnowledgeBase) -> None:
    text = "a cozy reading room with two armchairs and a large bookshelf"
    assert parse(text, kb) == parse(text, kb)
