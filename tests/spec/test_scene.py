"""SceneSpec validation: every rule gives a one-line SpecError naming the field."""

from __future__ import annotations

import copy
import json
import math

import pytest

from holomj.errors import SpecError
from holomj.spec.base import parse_json, validate_model
from holomj.spec.scene import SceneSpec
from tests.conftest import two_room_data


def _invalid(mutate, match: str) -> None:
    data = two_room_data()
    mutate(data)
    with pytest.raises(SpecError, match=match) as info:
        validate_model(SceneSpec, data, "scene.json")
    message = str(info.value)
    assert message.startswith("scene.json"), message
    assert "\n" not in message


def test_two_room_scene_is_valid(two_room_scene: SceneSpec) -> None:
    assert two_room_scene.schema_version == "1.0"
    assert [r.id for r in two_room_scene.rooms] == ["kitchen", "living"]
    assert two_room_scene.doors[1].effective_width == pytest.approx(1.8)
    assert two_room_scene.doors[0].effective_width == pytest.approx(1.0)


def test_round_trip_through_json_is_identity(two_room_scene: SceneSpec) -> None:
    text = two_room_scene.model_dump_json()
    again = SceneSpec.model_validate_json(text)
    assert again == two_room_scene


def test_scene_is_frozen(two_room_scene: SceneSpec) -> None:
    with pytest.raises(Exception, match="frozen"):
        two_room_scene.name = "other"  # type: ignore[misc]


def test_unknown_field_is_named() -> None:
    _invalid(lambda d: d["rooms"][1].update(colour="red"), r"rooms\[1\]\.colour: unknown field")


def test_non_finite_number_is_rejected() -> None:
    _invalid(lambda d: d["objects"][0].update(position=[math.nan, 0, 0]), r"objects\[0\]\.position")
    _invalid(lambda d: d.update(wall_height=math.inf), r"wall_height")


def test_json_nan_literal_is_rejected() -> None:
    with pytest.raises(Exception, match="non-finite"):
        parse_json('{"wall_height": NaN}', "scene.json")


def test_self_intersecting_room() -> None:
    bow_tie = [[0, 0], [4, 4], [4, 0], [0, 4]]
    _invalid(
        lambda d: d["rooms"][0].update(polygon=bow_tie),
        r"rooms\[0\]\.polygon \(kitchen\): polygon intersects itself",
    )


def test_overlapping_rooms() -> None:
    _invalid(
        lambda d: d["rooms"][0].update(polygon=[[0, 0], [5, 0], [5, 3], [0, 3]]),
        r"room 'kitchen' overlaps room 'living'",
    )


def test_duplicate_ids() -> None:
    _invalid(
        lambda d: d["objects"][1].update(id="crate"),
        r"^scene\.json: objects\[1\]\.id: duplicate id 'crate' \(also objects\[0\]\.id\)$",
    )
    # doors and windows share one namespace; the message names the real fields of both
    _invalid(
        lambda d: d["windows"][0].update(id="front_door"),
        r"^scene\.json: windows\[0\]\.id: duplicate id 'front_door' \(also doors\[1\]\.id\)$",
    )


def test_door_off_its_wall() -> None:
    _invalid(
        lambda d: d["doors"][0].update(position=[2, 2]),
        r"doors\[0\]: centre \(2.00, 2.00\) is not on the wall between rooms "
        r"'kitchen' and 'living'",
    )


def test_window_too_wide_for_its_wall() -> None:
    _invalid(lambda d: d["windows"][0].update(width=3.5), r"windows\[0\]: an opening 3.50 m wide")


def test_window_on_missing_exterior_wall() -> None:
    _invalid(
        lambda d: d["windows"][0].update(rooms=["kitchen", "nowhere"]), r"unknown room 'nowhere'"
    )


def test_overlapping_openings() -> None:
    _invalid(
        lambda d: d["windows"].append(
            {"id": "w3", "rooms": ["living"], "position": [3.5, 5], "width": 1.0}
        ),
        r"windows\[2\]: overlaps windows\[1\]",
    )


def test_opening_higher_than_wall() -> None:
    _invalid(lambda d: d["windows"][0].update(base_height=1.6), r"reaches the wall top")


def test_support_must_exist() -> None:
    _invalid(
        lambda d: d["objects"][2].update(support="ghost"),
        r"objects\[2\]\.support: unknown support object",
    )


def test_unknown_material() -> None:
    _invalid(
        lambda d: d["rooms"][0].update(floor_material="lava"),
        r"rooms\[0\]\.floor_material: unknown material 'lava'",
    )


def test_scene_material_can_be_defined() -> None:
    data = two_room_data()
    data["materials"] = {"lava": {"rgba": [1, 0.2, 0, 1]}}
    data["rooms"][0]["floor_material"] = "lava"
    assert SceneSpec.model_validate(data).materials["lava"].rgba[0] == 1


def test_bad_identifier() -> None:
    _invalid(lambda d: d["objects"][0].update(id="has space"), r"objects\[0\]\.id")


def test_zero_quaternion() -> None:
    _invalid(lambda d: d["objects"][0].update(quat=[0, 0, 0, 0]), r"quaternion has zero length")


def test_quaternion_is_normalised() -> None:
    data = two_room_data()
    data["objects"][0]["quat"] = [2, 0, 0, 0]
    assert SceneSpec.model_validate(data).objects[0].quat == (1.0, 0.0, 0.0, 0.0)


def test_wrong_schema_version() -> None:
    _invalid(lambda d: d.update(schema_version="9.9"), r"schema_version")


def test_json_schema_export_lists_all_top_level_fields() -> None:
    from holomj.spec.schema import json_schema

    schema = json_schema("scene")
    assert {"rooms", "doors", "windows", "objects", "lights", "cameras", "materials"} <= set(
        schema["properties"]
    )
    assert schema["additionalProperties"] is False
    json.dumps(schema)


def test_mutating_a_copy_does_not_touch_the_original() -> None:
    data = two_room_data()
    saved = copy.deepcopy(data)
    SceneSpec.model_validate(data)
    assert data == saved
