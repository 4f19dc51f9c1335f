"""``holomj eval``'s metrics on scenes built to pass them all, and to fail each one.

Every scene is a scene.json written by hand (``tests/evaluation/scenes.py``) and compiled with
``holomj compile``; the expected verdicts follow from the geometry written there.
"""

from __future__ import annotations

import json
import shutil
from pathlib import Path
from typing import Any

import pytest

from holomj.errors import InputError
from holomj.jobs.eval import evaluate
from tests.evaluation.scenes import (
    GOOD,
    GOOD_PLAN,
    box,
    compile_scene,
    room_scene,
    window,
)

SPATIAL = (
    "collisions",
    "outside",
    "support",
    "navigability",
    "front_access",
    "doors_clear",
    "windows_clear",
)

# Two overlapping crates (20 cm deep into each other).
OVERLAP = room_scene(
    [
        box("crate_0", "bedroom", (1.0, 2.0), (0.5, 0.5, 0.5)),
        box("crate_1", "bedroom", (1.3, 2.0), (0.5, 0.5, 0.5)),
    ]
)
# A lamp standing 0.55 m beyond the east wall.
OUTSIDE = room_scene([box("floor_lamp_0", "bedroom", (4.4, 2.0), (0.3, 0.3, 1.5))])
# A chair standing on the bed, a box floating in the air, a mug on the nightstand (fine).
SUPPORT = room_scene(
    [
        box("bed_0", "bedroom", (1.05, 2.0), (2.0, 1.4, 0.5)),
        box("chair_0", "bedroom", (1.0, 2.0), (0.45, 0.45, 0.9), z=0.5),
        box("nightstand_0", "bedroom", (0.25, 3.3), (0.4, 0.4, 0.5)),
        box("mug_0", "bedroom", (0.25, 3.3), (0.1, 0.1, 0.1), z=0.5),
        box("floater_0", "bedroom", (3.0, 2.5), (0.2, 0.2, 0.2), z=1.0),
    ]
)
# A wardrobe whose front faces the north wall 5 cm away, one facing into the room, and a desk
# with its office chair pushed in (the chair is pulled out to use the desk).
FRONTS = room_scene(
    [
        box("wardrobe_0", "bedroom", (2.0, 3.65), (0.6, 1.2, 2.0), yaw_deg=90),
        box("wardrobe_1", "bedroom", (0.35, 1.5), (0.6, 1.2, 2.0)),
        box("desk_0", "bedroom", (3.7, 1.0), (0.6, 0.8, 0.75), yaw_deg=180),
        box("office_chair_0", "bedroom", (3.15, 1.0), (0.5, 0.5, 0.9)),
    ]
)
# A crate right inside the entrance.
DOOR = room_scene([box("crate_0", "bedroom", (2.0, 0.5), (0.8, 0.6, 0.8))])
# A bookshelf in front of the north window, a low sofa under the east one (that is fine).
WINDOWS = room_scene(
    [
        box("bookshelf_0", "bedroom", (2.0, 3.8), (0.35, 1.0, 2.0), yaw_deg=270),
        box("sofa_0", "bedroom", (3.5, 2.0), (0.9, 1.8, 0.8), yaw_deg=180),
    ],
    windows=[window("north", "bedroom", (2.0, 4.0)), window("east", "bedroom", (4.0, 2.0))],
)
# A room cut in two by a row of crates; the second room opens off the cut-off half.
POCKET: dict[str, Any] = {
    "schema_version": "1.0",
    "name": "pocket",
    "rooms": [
        {"id": "garage", "type": "garage", "polygon": [[0, 0], [4, 0], [4, 4], [0, 4]]},
        {"id": "store", "type": "storage", "polygon": [[4, 0], [7, 0], [7, 4], [4, 4]]},
    ],
    "doors": [
        {"id": "front", "kind": "doorway", "rooms": ["garage"], "position": [1.0, 0.0]},
        {"id": "inner", "kind": "doorway", "rooms": ["garage", "store"], "position": [4.0, 3.2]},
    ],
    "objects": [box("crate_0", "garage", (1.95, 2.0), (3.8, 0.4, 1.0))],
}


@pytest.fixture(scope="module")
def folders(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    """Every scene, compiled once for the module."""
    root = tmp_path_factory.mktemp("eval")
    scenes = {
        "good": GOOD,
        "overlap": OVERLAP,
        "outside": OUTSIDE,
        "support": SUPPORT,
        "fronts": FRONTS,
        "door": DOOR,
        "windows": WINDOWS,
        "pocket": POCKET,
    }
    return {name: compile_scene(scene, root / name) for name, scene in scenes.items()}


def scores(folder: Path, **options: Any) -> dict[str, Any]:
    return evaluate(folder, **options).to_json()


def failing(record: dict[str, Any]) -> set[str]:
    """The spatial metrics that do not pass."""
    return {k for k in SPATIAL if record["scores"][k]["ok"] is False}


def test_the_good_scene_passes_every_spatial_metric(folders: dict[str, Path]) -> None:
    rec = scores(folders["good"])
    for key in SPATIAL:
        assert rec["scores"][key]["ok"] is True, (key, rec["scores"][key], rec["details"])
        assert rec["scores"][key]["score"] == 1.0, key
    assert rec["against"] == {"source": None}
    assert rec["scores"]["counts"]["score"] is None  # nothing to count against
    assert "no plan.json" in rec["notes"][0]
    assert rec["scores"]["stability"]["ok"] is None  # compile wrote no report.json
    assert "no report.json" in rec["scores"]["stability"]["summary"]
    support = {s["id"]: s for s in rec["details"]["support"]}
    assert support["living_room.mug_0"]["rests_on"] == "living_room.coffee_table_0"
    assert support["living_room.sofa_0"]["rests_on"] == "floor"
    assert rec["details"]["front_access"][0]["id"] == "living_room.wardrobe_0"
    assert rec["details"]["navigability"]["rooms_unreached"] == []
    assert rec["overall"] == 1.0
    assert set(rec["timings"]) >= {"audit", "support", "navigability", "total"}


def test_validate_option_measures_stability_without_writing(
    folders: dict[str, Path], tmp_path: Path
) -> None:
    folder = tmp_path / "good"
    shutil.copytree(folders["good"], folder)
    before = sorted(p.name for p in folder.iterdir())
    rec = scores(folder, validate=True)
    stability = rec["scores"]["stability"]
    assert stability["ok"] is True and stability["score"] == 1.0, rec["details"]["stability"]
    assert rec["details"]["stability"]["source"].startswith("validated by eval")
    assert sorted(p.name for p in folder.iterdir()) == before  # a measurement writes nothing
    (folder / "report.json").write_text(
        json.dumps(
            {
                "ok": False,
                "objects": [
                    {"name": "living_room.sofa_0", "stable": False, "reasons": ["fell"]},
                    {"name": "x", "stable": True},
                ],
            }
        )
    )
    rec = scores(folder)
    assert rec["scores"]["stability"]["score"] == 0.5 and rec["scores"]["stability"]["ok"] is False
    assert rec["details"]["stability"]["unstable"] == [
        {"id": "living_room.sofa_0", "reasons": ["fell"]}
    ]


def test_overlapping_boxes_are_a_colliding_pair(folders: dict[str, Path]) -> None:
    rec = scores(folders["overlap"])
    assert failing(rec) == {"collisions"}
    pairs = rec["details"]["collisions"]["pairs"]
    assert [(p["a"], p["b"]) for p in pairs] == [("bedroom.crate_0", "bedroom.crate_1")]
    assert pairs[0]["depth_mm"] == pytest.approx(200.0, abs=1.0)
    assert rec["scores"]["collisions"]["score"] == 0.0  # both objects are in it


def test_an_object_beyond_the_wall_is_outside_its_room(folders: dict[str, Path]) -> None:
    rec = scores(folders["outside"])
    assert "outside" in failing(rec)
    (row,) = rec["details"]["outside"]
    assert row["id"] == "bedroom.floor_lamp_0" and row["outside_m"] == pytest.approx(0.55)
    assert row["centre_in"] is None


def test_a_chair_on_a_bed_and_a_floating_box_are_implausible(folders: dict[str, Path]) -> None:
    rec = scores(folders["support"])
    assert failing(rec) == {"support"}
    rows = {s["id"].split(".")[1]: s for s in rec["details"]["support"]}
    assert rows["chair_0"]["rests_on"] == "bedroom.bed_0" and not rows["chair_0"]["plausible"]
    assert "floor furniture" in rows["chair_0"]["reason"]
    assert rows["floater_0"]["rests_on"] is None and not rows["floater_0"]["plausible"]
    assert rows["mug_0"]["rests_on"] == "bedroom.nightstand_0" and rows["mug_0"]["plausible"]
    assert rows["bed_0"]["rests_on"] == "floor" and rows["bed_0"]["plausible"]
    assert rec["scores"]["support"]["score"] == pytest.approx(3 / 5)


def test_a_wardrobe_facing_a_wall_cannot_be_opened(folders: dict[str, Path]) -> None:
    rec = scores(folders["fronts"])
    assert failing(rec) == {"front_access"}
    rows = {r["id"]: r for r in rec["details"]["front_access"]}
    blocked, free = rows["bedroom.wardrobe_0"], rows["bedroom.wardrobe_1"]
    assert not blocked["held"] and "no free floor" in blocked["reason"]
    assert free["held"] and free["gap_m"] < 0.1
    desk = rows["bedroom.desk_0"]
    assert desk["held"] and "seat bedroom.office_chair_0" in desk["reason"]
    assert rec["scores"]["front_access"]["score"] == pytest.approx(2 / 3, abs=1e-3)


def test_a_crate_in_the_doorway_blocks_the_door(folders: dict[str, Path]) -> None:
    rec = scores(folders["door"])
    assert "doors_clear" in failing(rec)
    (door,) = rec["details"]["doors"]
    assert not door["clear"] and door["blocking"][0].startswith("bedroom.crate_0")


def test_a_bookshelf_hides_a_window_a_low_sofa_does_not(folders: dict[str, Path]) -> None:
    rec = scores(folders["windows"])
    assert failing(rec) == {"windows_clear"}
    rows = {r["window"]: r for r in rec["details"]["windows"]}
    assert not rows["north"]["clear"] and rows["north"]["blocking"][0].startswith("bedroom.book")
    assert rows["east"]["clear"]


def test_a_cut_off_pocket_and_an_unreachable_room(folders: dict[str, Path]) -> None:
    rec = scores(folders["pocket"])
    assert failing(rec) == {"navigability"}
    nav = rec["details"]["navigability"]
    assert 0.2 < nav["share"] < 0.6
    assert nav["rooms_unreached"] == ["store"] and nav["per_room"]["garage"] < 0.6
    assert rec["scores"]["navigability"]["rooms_reachable"] == [1, 2]


def test_counts_and_relations_against_the_folders_plan(
    folders: dict[str, Path], tmp_path: Path
) -> None:
    folder = tmp_path / "good"
    shutil.copytree(folders["good"], folder)
    (folder / "plan.json").write_text(json.dumps(GOOD_PLAN))
    rec = scores(folder)
    assert rec["against"]["source"] == "plan.json"
    counts = {r.get("name", r["kind"]): r for r in rec["details"]["counts"]}
    assert counts["sofa"]["held"] and counts["mug"]["held"] and counts["wardrobe"]["held"]
    assert not counts["tv"]["held"]  # planned, not in the scene
    assert rec["scores"]["counts"]["held"] == 6 and rec["scores"]["counts"]["total"] == 7
    relations = [(r["spec"]["plan_kind"], r["held"]) for r in rec["details"]["relations"]]
    assert relations == [("wall", True), ("in_front_of", True), ("facing", False)]
    # A prompt that differs from the plan's is noted; the plan still wins.
    rec = scores(folder, prompt="a kitchen")
    assert rec["against"]["source"] == "plan.json" and "differs" in rec["notes"][0]


def test_counts_against_an_annotation(folders: dict[str, Path]) -> None:
    spec = {
        "id": "t",
        "prompt": "t",
        "rooms": {"eq": 1},
        "objects": [
            {"name": "couch", "count": {"eq": 1}},
            {"name": "wardrobe", "count": {"eq": 2}},
        ],
        "relations": [{"subject": "mug", "relation": "on", "object": "coffee table"}],
        "absent": ["bed"],
    }
    rec = scores(folders["good"], spec=spec)
    assert rec["against"] == {"source": "spec", "id": "t"}
    assert [r["held"] for r in rec["details"]["counts"]] == [True, True, False]
    assert rec["scores"]["relations"]["score"] == 1.0 and rec["scores"]["absent"]["ok"]


def test_bad_input_is_refused(folders: dict[str, Path], tmp_path: Path) -> None:
    with pytest.raises(InputError, match="not a holomj scene folder"):
        evaluate(tmp_path)
    with pytest.raises(InputError, match="not both"):
        evaluate(folders["good"], prompt="a room", spec={"objects": []})
    with pytest.raises(InputError, match=r"objects\[0\].count"):
        evaluate(folders["good"], spec={"objects": [{"name": "sofa", "count": 2}]})
    with pytest.raises(InputError, match="unknown relation"):
        evaluate(folders["good"], spec={"relations": [{"subject": "sofa", "relation": "inside"}]})
