"""The knowledge base: enough scene types, real categories and sizes, constraints that parse."""

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
from holomj.plan.knowledge import KnowledgeBase, load_knowledge

KNOWLEDGE = Path(str(resources.files("holomj.data").joinpath("knowledge")))
MATERIAL_WORDS = ("wood", "tile", "marble", "concrete", "carpet", "paint", "brick", "stone",
                  "wallpaper", "metal")  # fmt: skip


def test_scene_types_residential_and_commercial(kb: KnowledgeBase) -> None:
    kinds = [scene.kind for scene in kb.scene_types.values()]
    assert len(kinds) >= 20
    assert kinds.count("residential") >= 8
    assert kinds.count("commercial") >= 8
    for name in ("kitchen", "apartment", "bedroom", "office", "classroom", "cafe", "restaurant",
                 "waiting_room", "hotel_room", "daycare_classroom", "music_room"):  # fmt: skip
        assert name in kb.scene_types


def test_every_category_is_a_default_library_category(kb: KnowledgeBase) -> None:
    for name, kind in kb.objects.items():
        assert kind.category in CATEGORIES, name
        registry = CATEGORIES[kind.category].placement
        if kind.placement == "floor":
            assert "floor" in registry, name
        elif kind.placement == "object":
            assert "object" in registry, name
        else:  # wall objects: wall assets, or televisions (which stand on objects too)
            assert "wall" in registry or kind.category == "television", name
    assert "rug" not in {kind.category for kind in kb.objects.values()}


def test_sizes_are_close_to_the_assets(kb: KnowledgeBase) -> None:
    """Plan sizes are (width, depth, height); asset sizes (x = depth, y = width, z)."""
    for name, kind in kb.objects.items():
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
    for key in kb.receptacles:
        assert key.split(":")[-1] in CATEGORIES


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
    ],
)
def test_broken_knowledge_names_file_and_entry(
    tmp_path: Path, file: str, edit, message: str
) -> None:
    with pytest.raises(SpecError) as err:
        load_knowledge(broken_copy(tmp_path, file, edit))
    assert message in str(err.value)
    assert "\n" not in str(err.value)


def test_missing_file(tmp_path: Path) -> None:
    folder = broken_copy(tmp_path, "rooms.json", lambda data: None)
    (folder / "styles.json").unlink()
    with pytest.raises(SpecError, match="knowledge file missing"):
        load_knowledge(folder)
