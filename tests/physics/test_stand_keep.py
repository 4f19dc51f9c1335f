"""Keeping a house whole: where an object that cannot stand goes next, what follows it, what is
left out with it, and the records (pure bookkeeping; the physics is tested through compile)."""

from __future__ import annotations

import pytest

from holomj.physics.standing.keep import (
    KeptHouse,
    _carried,
    _changes,
    _Facts,
    _next_support,
    _without_orphans,
)
from holomj.spec.scene import SceneObject, SceneSpec


def _obj(oid: str, x: float, y: float, z: float = 0.0, support: str | None = None) -> SceneObject:
    return SceneObject(id=oid, asset="a", position=(x, y, z), support=support, room="r")


TABLE_A = _obj("table_a", 0.0, 0.0)
TABLE_B = _obj("table_b", 3.0, 0.0)
TABLE_C = _obj("table_c", 1.0, 0.0)
SOFA = _obj("sofa", 0.5, 0.0)
BOX = _obj("box", 0.1, 0.0, 0.75, support="table_a")
CUP = _obj("cup", 0.2, 0.1, 0.75, support="table_a")
FACTS = _Facts(
    category={
        "table_a": "side_table",
        "table_b": "side_table",
        "table_c": "side_table",
        "sofa": "sofa",
        "box": "box",
        "cup": "cup",
    },
    area={"table_a": 0.25, "table_b": 0.25, "table_c": 0.25, "sofa": 2, "box": 0.1, "cup": 0.01},
)


def _by_id(*objects: SceneObject) -> dict[str, SceneObject]:
    return {o.id: o for o in objects}


def test_restacked_first_then_the_nearest_receptacle_of_the_same_kind_each_once() -> None:
    objects = _by_id(TABLE_A, TABLE_B, TABLE_C, SOFA, BOX, CUP)
    tried: dict[str, set[str]] = {}
    steps = []
    while (step := _next_support(CUP, objects, FACTS, tried, {})) is not None:
        steps.append((step[0].id, step[1]))
    assert steps == [
        ("box", "restacked on box"),  # larger, beside it on the same table
        ("table_c", "moved to table_c, another side_table"),  # nearer than table_b
        ("table_b", "moved to table_b, another side_table"),
    ]


def test_an_unsaved_object_is_no_new_support_and_a_floor_object_has_none() -> None:
    objects = _by_id(TABLE_A, TABLE_B, BOX, CUP)
    step = _next_support(CUP, objects, FACTS, {}, {"box": "fell off"})
    assert step is not None and step[0].id == "table_b"
    assert _next_support(TABLE_A, objects, FACTS, {}, {}) is None


def test_what_rests_on_a_moved_object_is_carried_and_on_a_left_out_one_left_out() -> None:
    on_box = _obj("note", 0.1, 0.0, 0.9, support="box")
    moved = {"box": BOX.model_copy(update={"support": "table_b", "position": (3.0, 0.0, 0.75)})}
    result = {o.id: o for o in _carried([TABLE_A, TABLE_B, BOX, on_box], moved, {})}
    assert result["box"].support == "table_b"
    assert result["note"].position == pytest.approx((3.0, 0.0, 0.9))  # shifted with the box
    left = {"box": "fell off"}
    kept = _without_orphans([TABLE_A, BOX, on_box, CUP], left)
    assert [o.id for o in kept] == ["table_a", "box", "cup"]  # note dropped, box by the caller
    assert left["note"] == "rests on box, which was left out"


def test_records_say_from_where_to_where_and_why() -> None:
    final = SceneSpec.model_validate(
        {
            "name": "t",
            "rooms": [{"id": "r", "polygon": [(-5, -5), (5, -5), (5, 5), (-5, 5)]}],
            "objects": [TABLE_A, TABLE_B, CUP.model_copy(update={"support": "table_b"})],
        }
    )
    original = _by_id(TABLE_A, TABLE_B, BOX, CUP)
    changes = _changes(original, final, {"cup": "no spot; moved to table_b"}, {"box": "fell"})
    assert changes == [
        {
            "object": "box",
            "change": "left_out",
            "from": {"support": "table_a", "room": "r", "position": [0.1, 0.0, 0.75]},
            "to": None,
            "why": "fell",
        },
        {
            "object": "cup",
            "change": "relocated",
            "from": {"support": "table_a", "room": "r", "position": [0.2, 0.1, 0.75]},
            "to": {"support": "table_b", "room": "r", "position": [0.2, 0.1, 0.75]},
            "why": "no spot; moved to table_b",
        },
    ]
    kept = KeptHouse(outcome=None, imported=4, changes=changes)  # type: ignore[arg-type]  # records only
    assert kept.kept_share == 0.75
    assert [r["object"] for r in kept.left_out] == ["box"]
    assert [r["object"] for r in kept.relocated] == ["cup"]
