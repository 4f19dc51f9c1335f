"""The knowledge base: enough scene types and kinds, real categories and sane sizes, constraints
that parse, defining kinds, rooms and aliases that agree, and one-line errors for broken data."""

from __future__ import annotations

import json
import shutil
from importlib import resources
from pathlib import Path

import pytest

from asset_pipeline.procedural.catalog import CATEGORIES
from holomj.errors import SpecError
from holomj.layout.constraints import parse_constraint_text
from holomj.layout.proposals import default_catalogue
from holomj.plan.knowledge import load_knowledge
from holomj.plan.knowledge_checks import DEFINING_PRIORITY, SIZE_RANGES
from holomj.plan.knowledge_schema import KnowledgeBase

KNOWLEDGE = Path(str(resources.files("holomj.data").joinpath("knowledge")))
MATERIAL_WORDS = ("wood", "tile", "marble", "concrete", "carpet", "paint", "brick", "stone",
                  "wallpaper", "metal", "vinyl", "rubber")  # fmt: skip


def test_scene_types_residential_and_commercial(kb: KnowledgeBase) -> None:
    kinds = [scene.kind for scene in kb.scene_types.values()]
    assert len(kinds) >= 100
    assert kinds.count("residential") >= 20
    assert kinds.count("commercial") >= 60
    for name in ("kitchen", "apartment", "bedroom", "office", "classroom", "cafe", "restaurant",
                 "waiting_room", "hotel_room", "daycare_classroom", "music_room", "laundry_room",
                 "nursery", "home_theater", "garage", "hair_salon", "observatory", "arcade",
                 "gallery", "gym", "laboratory", "bakery", "bar", "barbershop", "dentist_office",
                 "pharmacy", "florist", "bookshop", "music_studio", "yoga_studio", "dance_studio",
                 "pottery_studio", "workshop", "server_room", "reception", "museum_room",
                 "chapel", "courtroom", "nail_salon", "tailor", "pet_shop", "clinic_room",
                 "hospital_ward", "school_library", "science_lab", "computer_lab",
                 "art_classroom", "kindergarten", "co_working", "boardroom", "break_room",
                 "mailroom", "hotel_lobby", "hostel_dorm", "sauna", "spa"):  # fmt: skip
        assert name in kb.scene_types, name
    for name, scene in kb.scene_types.items():
        assert len(scene.keywords) >= 3, name  # several phrasings


def test_object_kind_counts(kb: KnowledgeBase) -> None:
    placements = [kind.placement for kind in kb.objects.values()]
    assert len(placements) >= 300
    assert placements.count("object") >= 60
    assert placements.count("wall") >= 20
    assert placements.count("ceiling") >= 6
    for name in ("pendant light", "chandelier", "ceiling fan", "ceiling light", "hanging plant",
                 "projector"):  # fmt: skip
        assert kb.objects[name].placement == "ceiling", name
    for name in ("ottoman", "bench", "sideboard", "console table", "bar stool", "kitchen island",
                 "wine rack", "coat rack", "shoe rack", "laundry basket", "washing machine",
                 "dryer", "radiator", "fireplace", "crib", "bunk bed", "toy box", "bean bag",
                 "curtains", "blinds", "monitor", "whiteboard", "chalkboard", "locker",
                 "filing cabinet", "printer", "projector screen", "shop counter", "display case",
                 "shelving gondola", "salon chair", "reception desk", "menu board",
                 "cash register", "arcade cabinet", "pool table", "treadmill", "exercise bike",
                 "piano", "easel", "telescope", "workbench", "tool wall", "lab bench",
                 "fume hood", "mug", "plate", "book", "laptop", "desk lamp", "vase",
                 "small plant", "bottle"):  # fmt: skip
        assert name in kb.objects, name


def test_rugs_are_planned_and_doormats_refused(kb: KnowledgeBase) -> None:
    """Rugs are decor under the furniture (static, no collider); a doormat would lie in a
    door's keep-out zone."""
    assert kb.objects["rug"].category == "rug"
    assert "doormat" in kb.refused


def test_categories_are_library_ones_or_the_kind_name(kb: KnowledgeBase) -> None:
    """A library category when the default library has one, else the kind's own name."""
    for name, kind in kb.objects.items():
        if kind.category not in CATEGORIES:
            assert kind.category == name.replace(" ", "_"), name
            continue
        registry = CATEGORIES[kind.category].placement
        if kind.placement == "floor":
            assert "floor" in registry, name
        elif kind.placement == "object":
            assert "object" in registry, name
        elif kind.placement == "ceiling":
            assert "ceiling" in registry, name
        else:  # wall objects: wall assets, or televisions (which stand on objects too)
            assert kind.placement == "wall", name
            assert "wall" in registry or kind.category == "television", name


def test_sizes_are_sane(kb: KnowledgeBase) -> None:
    for name, kind in kb.objects.items():
        for size in (kind.size, kind.small, kind.large):
            if size is None:
                continue
            for value, (low, high) in zip(size, SIZE_RANGES[kind.placement], strict=True):
                assert low <= value <= high, (name, size)
    bed = kb.objects["bed"]
    assert bed.size is not None and 1.4 <= bed.size[0] <= 2.0 and 1.9 <= bed.size[1] <= 2.2
    assert kb.objects["telescope"].size == pytest.approx((0.6, 0.6, 1.5))
    assert kb.objects["arcade cabinet"].size == pytest.approx((0.7, 0.8, 1.8))
    for name in ("dining table", "desk", "kitchen counter", "bar counter", "lab bench"):
        size = kb.objects[name].size
        assert size is not None and 0.7 <= size[2] <= 1.15, name  # work-surface heights
    for name, kind in kb.objects.items():
        if kind.placement == "object":
            assert kind.size is None or max(kind.size) <= 1.0, name


def test_sizes_are_close_to_the_assets(kb: KnowledgeBase) -> None:
    """Plan sizes are (width, depth, height); asset sizes (x = depth, y = width, z)."""
    for name, kind in kb.objects.items():
        if kind.category not in CATEGORIES:
            continue  # a new category: its assets come from elsewhere
        info = CATEGORIES[kind.category]
        for size in (kind.size, kind.small, kind.large):
            if size is None:
                continue
            width, depth, height = size
            lo, hi = info.size_min, info.size_max
            assert lo[1] - 0.01 <= width <= hi[1] + 0.01, (name, size)
            assert lo[0] - 0.01 <= depth <= hi[0] + 0.01, (name, size)
            assert lo[2] - 0.01 <= height <= hi[2] + 0.01, (name, size)


def test_sofa_size_matches_the_default_asset(kb: KnowledgeBase) -> None:
    depth, width, height = CATEGORIES["sofa"].default_size
    assert kb.objects["sofa"].size == pytest.approx((width, depth, height))


def test_template_constraints_parse_without_warnings(kb: KnowledgeBase) -> None:
    for name, template in kb.rooms.items():
        for variant, objects, lines in template.object_sets():
            floor = [o.object for o in objects if kb.objects[o.object].placement == "floor"]
            parsed = parse_constraint_text("\n".join(lines), floor)
            assert parsed.warnings == [], (name, variant)
            assert len(parsed.constraints) >= len(lines)
    for name, kind in kb.objects.items():
        for line in kind.constraints:
            floor = [n for n, k in kb.objects.items() if k.placement == "floor"]
            assert parse_constraint_text(line, floor).warnings == [], name


def test_small_objects_agree_with_the_receptacle_table(kb: KnowledgeBase) -> None:
    table = default_catalogue()
    for key, items in table.items():  # the shared table is part of the knowledge, unchanged
        assert kb.receptacles[key] == items
    for name, template in kb.rooms.items():
        for _, objects, _ in template.object_sets():
            for entry in objects:
                if entry.on_top is None or entry.on_top == "auto":
                    continue
                category = kb.objects[entry.object].category
                allowed = {c for c, _ in kb.small_choices(template.type, category)}
                for item in entry.on_top:
                    assert kb.objects[item.object].category in allowed, (name, entry.object)
                assert sum(i.quantity[1] for i in entry.on_top) <= 8, (name, entry.object)
    categories = {kind.category for kind in kb.objects.values()}
    for key, items in kb.receptacles.items():
        receptacle = key.split(":")[-1]
        assert receptacle in CATEGORIES or receptacle in categories, key
        for category, _ in items:
            assert category in categories, (key, category)


def test_receptacle_flags_follow_the_table(kb: KnowledgeBase) -> None:
    holders = {key.split(":")[-1] for key in kb.receptacles}
    for name, kind in kb.objects.items():
        assert kind.receptacle == (kind.placement == "floor" and kind.category in holders), name
    for name in ("desk", "dining table", "kitchen island", "display case", "workbench"):
        assert kb.objects[name].receptacle, name
    for name in ("bed", "chandelier", "mug", "treadmill"):
        assert not kb.objects[name].receptacle, name


def test_every_small_kind_fits_a_receptacle(kb: KnowledgeBase) -> None:
    smalls = [n for n, k in kb.objects.items() if k.placement == "object"]
    for name in smalls:
        category = kb.objects[name].category
        assert any(category in kb.allowed_small(c) for c in kb.receptacles), name


def test_materials_are_described_in_known_words(kb: KnowledgeBase) -> None:
    texts = [t for room in kb.rooms.values() for t in (*room.floor, *room.wall, *room.ceiling)]
    texts += [t for s in kb.styles.values() for t in (*s.floor, *s.wall, *s.ceiling)]
    for text in texts:
        assert any(word in text for word in MATERIAL_WORDS), text


def test_rooms_fit_their_essential_furniture(kb: KnowledgeBase) -> None:
    """Each template's objects of priority 9-10 fit in its smallest area at 35% footprint."""
    for name, template in kb.rooms.items():
        for variant, objects, _ in template.object_sets():
            total = 0.0
            counts: dict[str, int] = {}
            for entry in objects:
                kind = kb.objects[entry.object]
                count = entry.quantity[0] * (counts.get(entry.per, 1) if entry.per else 1)
                counts[entry.object] = count
                if kind.placement == "floor" and entry.priority >= 9 and entry.probability == 1:
                    size = kind.size_for(entry.size)
                    assert size is not None
                    total += size[0] * size[1] * count
            budget = kb.limits.footprint_fraction * template.area[0] * 1.1
            assert total <= budget, (name, variant, total, budget)


def test_scene_rooms_and_keywords(kb: KnowledgeBase) -> None:
    seen: set[str] = set()
    for name, scene in kb.scene_types.items():
        assert scene.entrance in {room.id for room in scene.rooms}
        assert not seen & set(scene.keywords), name
        seen |= set(scene.keywords)
        assert name in scene.embedding_text() or scene.name in scene.embedding_text()


def test_every_room_referenced_exists(kb: KnowledgeBase) -> None:
    for name, scene in kb.scene_types.items():
        for room in scene.rooms:
            assert room.template in kb.rooms, (name, room.template)
    for name, template in kb.rooms.items():
        assert set(template.neighbours) <= set(kb.rooms), name
        assert template.counts_as is None or template.counts_as in kb.rooms, name
    for name, kind in kb.objects.items():
        assert kind.rooms, name
        assert set(kind.rooms) <= set(kb.rooms), name
    used = {room.template for scene in kb.scene_types.values() for room in scene.rooms}
    assert used == set(kb.rooms)  # and every template is used by some scene type


def test_kinds_name_the_rooms_that_list_them(kb: KnowledgeBase) -> None:
    for name, template in kb.rooms.items():
        for _, objects, _ in template.object_sets():
            for entry in objects:
                assert name in kb.objects[entry.object].rooms, (name, entry.object)
                if isinstance(entry.on_top, list):
                    for item in entry.on_top:
                        assert name in kb.objects[item.object].rooms, (name, item.object)
    assert "bed" in kb.kinds_in_room("bedroom", "floor")
    assert "chandelier" in kb.kinds_in_room("dining_room", "ceiling")


def test_every_alias_is_unique(kb: KnowledgeBase) -> None:
    owners: dict[str, str] = {}
    groups = [
        *((f"object {n}", [n, *k.aliases]) for n, k in kb.objects.items()),
        *((f"generic {n}", g.aliases) for n, g in kb.generics.items()),
        *((f"refused {n}", r.aliases) for n, r in kb.refused.items()),
        *((f"room {n}", t.aliases) for n, t in kb.rooms.items()),
        *((f"style {n}", s.aliases) for n, s in kb.styles.items()),
    ]
    for owner, phrases in groups:
        for phrase in phrases:
            assert owners.setdefault(phrase, owner) == owner, (phrase, owners[phrase], owner)
    keywords = {k for scene in kb.scene_types.values() for k in scene.keywords}
    objects = {p for n, k in kb.objects.items() for p in (n, *k.aliases)}
    objects |= {p for g in kb.generics.values() for p in g.aliases}
    assert not objects & keywords  # a phrase names a scene type or an object, not both


def test_defining_kinds_are_in_their_templates(kb: KnowledgeBase) -> None:
    for name, template in kb.rooms.items():
        if template.type != "hallway":
            assert template.defining, name  # a hallway is a passage: nothing defines it
        assert set(template.defining) <= set(template.kinds()), name
        for _, objects, _ in template.object_sets():
            by_name = {o.object: o for o in objects}
            present = template.defining_in(by_name)
            assert present or not template.defining, name  # every variant has one
            for kind in present:
                entry = by_name[kind]
                assert entry.priority >= DEFINING_PRIORITY and entry.probability == 1, (name, kind)
    assert kb.rooms["bedroom"].defining == ["bed"]
    assert {"toilet", "washbasin"} <= set(kb.rooms["bathroom"].defining)
    assert {"fridge", "stove", "sink counter"} <= set(kb.rooms["kitchen"].defining)
    assert "sofa" in kb.rooms["living_room"].defining
    assert {"desk", "office chair"} <= set(kb.rooms["home_office"].defining)
    assert {"dining table", "dining chair"} <= set(kb.rooms["dining_room"].defining)
    assert {"salon chair", "mirror"} <= set(kb.rooms["hair_salon"].defining)
    assert "telescope" in kb.rooms["observatory"].defining
    assert "washing machine" in kb.rooms["laundry"].defining


def test_small_rooms_hold_their_defining_kinds(kb: KnowledgeBase) -> None:
    """The smallest room of a template holds its defining floor kinds within the footprint
    limit, and so does a 'tiny' one (the smallest size word) at their smallest sizes within the
    limit the planner keeps essentials under."""
    limits = kb.limits
    smallest_word = min(limits.size_words.values())
    for name, template in kb.rooms.items():
        for variant, objects, _ in template.object_sets():
            usual, tight = _defining_footprints(kb, template, objects, name)
            assert usual <= limits.footprint_fraction * template.area[0] + 1e-6, (name, variant)
            area = max(limits.min_area, template.area[0] * smallest_word)
            assert tight <= limits.single_fraction * area + 1e-6, (name, variant, tight, area)
    bedroom = kb.rooms["bedroom"]  # a small bedroom is about 9 m2, and holds a bed
    assert bedroom.area[0] * limits.size_words["small"] <= 10.0
    assert kb.objects["bed"].small is not None


def _defining_footprints(kb: KnowledgeBase, template, objects, name: str) -> tuple[float, float]:
    """Floor area of the defining kinds (fewest instances): at default and at smallest sizes."""
    counts: dict[str, int] = {}
    usual = tight = 0.0
    for entry in objects:
        count = entry.quantity[0] * (counts.get(entry.per, 1) if entry.per else 1)
        counts[entry.object] = count
        kind = kb.objects[entry.object]
        if entry.object not in template.defining or kind.placement != "floor":
            continue
        size = kind.size_for(entry.size)
        assert size is not None
        smallest = min((s for s in (size, kind.small) if s is not None), key=lambda s: s[0] * s[1])
        assert max(smallest[:2]) <= kb.limits.max_side, (name, entry.object)
        usual += size[0] * size[1] * count
        tight += smallest[0] * smallest[1] * count
    return usual, tight


def broken_copy(tmp_path: Path, name: str, edit) -> Path:
    folder = tmp_path / "knowledge"
    shutil.copytree(KNOWLEDGE, folder)
    data = json.loads((folder / name).read_text())
    edit(data)
    (folder / name).write_text(json.dumps(data))
    return folder


def test_the_shipped_folder_loads(tmp_path: Path) -> None:
    kb = load_knowledge(broken_copy(tmp_path, "rooms.json", lambda data: None))
    assert "kitchen" in kb.rooms


@pytest.mark.parametrize(
    ("file", "edit", "message"),
    [
        (
            "rooms.json",
            lambda d: d["rooms"]["living_room"]["constraints"].append("sofa | near, unicorn"),
            "rooms.json: rooms.living_room.constraints",
        ),
        (
            "rooms.json",
            lambda d: d["rooms"]["kitchen"]["objects"].append({"object": "hoverboard"}),
            "unknown object kind 'hoverboard'",
        ),
        (
            "rooms.json",
            lambda d: d["rooms"]["bedroom"]["objects"][1].update(on_top=[{"object": "pan"}]),
            "'pan' does not go on 'nightstand'",
        ),
        (
            "objects.json",
            lambda d: d["objects"]["armchair"]["aliases"].append("couch"),
            "the phrase 'couch' names both",
        ),
        (
            "scene_types.json",
            lambda d: d["scene_types"]["kitchen"]["rooms"][0].update(template="galley"),
            "unknown room template 'galley'",
        ),
        (
            "scene_types.json",
            lambda d: d["scene_types"]["cafe"]["keywords"].append("restaurant"),
            "keyword 'restaurant' names scene types",
        ),
        (
            "objects.json",
            lambda d: d["objects"]["sofa"].update(size=[2.0, -1.0, 0.8]),
            "objects.json: objects.sofa.size",
        ),
        (
            "objects.json",
            lambda d: d["objects"]["sofa"].update(size=[2.0, 0.0, 0.8]),
            "objects.json: objects.sofa.size",
        ),
        (
            "objects.json",
            lambda d: d["objects"]["sofa"].update(size=[12.0, 0.9, 0.85]),
            "objects.json: objects.sofa.size: width 12 m is outside the sane range",
        ),
        (
            "objects.json",
            lambda d: d["objects"]["mug"].update(size=[0.1, 0.1, 1.5]),
            "objects.json: objects.mug.size: height 1.5 m is outside the sane range",
        ),
        (
            "objects.json",
            lambda d: d["objects"]["chandelier"].update(large=[0.3, 0.3, 0.2]),
            "objects.json: objects.chandelier.large: the large size",
        ),
        (
            "objects.json",
            lambda d: d["objects"]["sofa"].update(placement="roof"),
            "objects.json: objects.sofa.placement: Input should be",
        ),
        (
            "objects.json",
            lambda d: d["objects"]["sofa"].update(category="Big Sofa"),
            "objects.json: objects.sofa.category",
        ),
        (
            "objects.json",
            lambda d: d["objects"]["telescope"]["aliases"].append("pool table"),
            "objects.json: objects.telescope.aliases: the phrase 'pool table' names both",
        ),
        (
            "objects.json",
            lambda d: d["objects"]["sofa"]["rooms"].append("ballroom"),
            "objects.json: objects.sofa.rooms: unknown room template 'ballroom'",
        ),
        (
            "objects.json",
            lambda d: d["objects"]["sofa"].update(rooms=[]),
            "objects.json: objects.sofa.rooms",
        ),
        (
            "objects.json",
            lambda d: d["objects"]["sofa"].pop("receptacle"),
            "objects.json: objects.sofa.receptacle: Field required",
        ),
        (
            "objects.json",
            lambda d: d["objects"]["sofa"].update(receptacle=True),
            "objects.json: objects.sofa.receptacle: marked receptacle",
        ),
        (
            "objects.json",
            lambda d: d["objects"]["desk"].update(receptacle=False),
            "objects.json: objects.desk.receptacle: the receptacle table lists",
        ),
        (
            "objects.json",
            lambda d: d["objects"]["chandelier"].update(receptacle=True),
            "objects.json: objects.chandelier: Value error, only floor objects are receptacles",
        ),
        (
            "objects.json",
            lambda d: d["objects"]["telescope"].update(rooms=["living_room"]),
            "objects.json: objects.telescope.rooms: rooms.json: rooms.observatory lists "
            "'telescope'",
        ),
        (
            "rooms.json",
            lambda d: d["rooms"]["bedroom"].pop("defining"),
            "rooms.json: rooms.bedroom.defining: Field required",
        ),
        (
            "rooms.json",
            lambda d: d["rooms"]["bedroom"]["defining"].append("unicorn"),
            "rooms.json: rooms.bedroom.defining: unknown object kind 'unicorn'",
        ),
        (
            "rooms.json",
            lambda d: d["rooms"]["bedroom"]["defining"].append("telescope"),
            "rooms.json: rooms.bedroom.defining: unknown object of this template 'telescope'",
        ),
        (
            "rooms.json",
            lambda d: d["rooms"]["bedroom"]["defining"].append("nightstand"),
            "rooms.json: rooms.bedroom.defining: defining kind 'nightstand' has priority 7",
        ),
        (
            "rooms.json",
            lambda d: d["rooms"]["bedroom"]["defining"].append("bed"),
            "rooms.json: rooms.bedroom.defining: defining kind 'bed' listed twice",
        ),
        (
            "rooms.json",
            lambda d: d["rooms"]["dining_room"].update(defining=["dining chair"]),
            "defining kind 'dining chair' counts per 'dining table', which is not defining",
        ),
        (
            "rooms.json",
            lambda d: d["rooms"]["bedroom"]["objects"][0].update(on_top="auto"),
            "rooms.json: rooms.bedroom.objects[0].on_top: 'bed' is not a receptacle",
        ),
        (
            "rooms.json",
            lambda d: d["rooms"]["observatory"]["aliases"].append("telescope"),
            "rooms.json: rooms.observatory.aliases: the phrase 'telescope' names both",
        ),
    ],
)
def test_broken_knowledge_names_file_and_entry(
    tmp_path: Path, file: str, edit, message: str
) -> None:
    with pytest.raises(SpecError) as err:
        load_knowledge(broken_copy(tmp_path, file, edit))
    assert message in str(err.value)
    assert "\n" not in str(err.value)


def test_a_receptacles_file_adds_new_keys_only(tmp_path: Path) -> None:
    folder = broken_copy(tmp_path, "receptacles.json", lambda d: d.update(desk=[["pan", 1]]))
    kb = load_knowledge(folder)
    assert kb.receptacles["desk"] == default_catalogue()["desk"]  # the shared table wins
    assert kb.receptacles["workbench"]  # a new receptacle category from the knowledge base


def test_missing_file(tmp_path: Path) -> None:
    folder = broken_copy(tmp_path, "rooms.json", lambda data: None)
    (folder / "styles.json").unlink()
    with pytest.raises(SpecError, match="knowledge file missing"):
        load_knowledge(folder)
