"""The edit operations format: parsing, refusals of malformed input, its JSON Schema, and a fuzz
of the parser (nothing but a SpecError ever escapes, nothing is ever evaluated)."""

from __future__ import annotations

import json

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from holomj.errors import InputError, SpecError
from holomj.spec.base import parse_json
from holomj.spec.edit import (
    MAX_OPERATIONS,
    OP_NAMES,
    AddOp,
    LightOp,
    MaterialOp,
    MoveOp,
    operations_schema,
    parse_operations,
)

GOOD = [
    {"op": "add", "description": "a green armchair", "relations": [{"kind": "by_window"}]},
    {
        "op": "add",
        "description": "a floor lamp",
        "room": "living_room",
        "size": [0.4, 0.4, 1.6],
        "attributes": ["brass"],
        "relations": [{"kind": "adjacent_to", "target": "living_room.armchair_0"}],
    },
    {"op": "add", "description": "a bookshelf", "position": [1.0, 2.0], "yaw_deg": 90},
    {"op": "add_on", "description": "a red mug", "on": "living_room.coffee_table_0", "count": 2},
    {"op": "remove", "id": "DiningTable|1|0"},
    {"op": "move", "id": "living_room.sofa_0", "position": [1.0, 2.0, 0.0], "yaw_deg": -90},
    {"op": "move", "id": "living_room.sofa_0", "relations": [{"kind": "wall"}]},
    {"op": "move", "id": "mug_00", "on": "living_room.tv_stand_0"},
    {"op": "replace", "id": "living_room.sofa_0", "description": "a red leather sofa"},
    {"op": "material", "room": "living_room", "surface": "floor", "material": "oak parquet"},
    {"op": "material", "surface": "walls", "material": "sage_green_paint"},
    {"op": "light", "room": "living_room", "description": "a pendant light"},
    {"op": "light", "id": "lamp", "energy": 0.5, "color": [1, 0.9, 0.8], "comment": "warmer"},
]


def test_good_operations_parse_into_typed_models():
    ops = parse_operations(GOOD, "ops.json")
    assert [op.op for op in ops] == [g["op"] for g in GOOD]
    assert isinstance(ops[0], AddOp) and ops[0].relations[0].kind == "by_window"
    assert isinstance(ops[5], MoveOp) and ops[5].position == (1.0, 2.0, 0.0)
    assert isinstance(ops[9], MaterialOp) and isinstance(ops[11], LightOp)
    # the wrapped form, as a refine round may write it
    assert parse_operations({"operations": GOOD[:2]}) == ops[:2]
    # a size over 10 m or a position anywhere parses: the scene refuses it, with the reason
    assert parse_operations([{"op": "add", "description": "x", "size": [12, 1, 1]}])


@pytest.mark.parametrize(
    ("data", "where", "words"),
    [
        ({"op": "add"}, "ops.json", "expected a JSON list"),
        ("remove everything", "ops.json", "expected a JSON list"),
        ([{"op": "explode"}], "[0]", "does not match any of the expected tags"),
        ([{"id": "x"}], "[0]", "op"),
        ([{"op": "remove", "id": "x", "code": "import os"}], "[0].remove.code", "unknown field"),
        ([{"op": "remove", "id": "a b"}], "[0].remove.id", "pattern"),
        ([{"op": "remove"}], "[0].remove.id", "required"),
        ([{"op": "add", "description": ""}], "[0].add.description", "at least 1"),
        ([{"op": "add", "description": "x", "size": [1, -1, 1]}], "size[1]", "greater than 0"),
        (
            [{"op": "add", "description": "x", "relations": [{"kind": "near"}]}],
            "relations[0]",
            "target",
        ),
        (
            [{"op": "add", "description": "x", "relations": [{"kind": "corner", "target": "a"}]}],
            "relations[0]",
            "no target",
        ),
        ([{"op": "move", "id": "a"}], "[0].move", "give position"),
        ([{"op": "move", "id": "a", "on": "b", "yaw_deg": 3}], "[0].move", "alone"),
        ([{"op": "material", "surface": "roof", "material": "oak"}], "surface", "floor"),
        ([{"op": "add_on", "description": "mug", "on": "t", "count": 99}], "count", "10"),
        ([{"op": "light", "energy": 1e9}], "energy", "100"),
        ([{"op": "remove", "id": "x"}] * (MAX_OPERATIONS + 1), "ops.json", "at most"),
        ({"schema_version": "9", "operations": []}, "schema_version", "unknown"),
    ],
)
def test_malformed_operations_are_refused_naming_the_field(data, where, words):
    with pytest.raises(SpecError) as err:
        parse_operations(data, "ops.json")
    line = err.value.one_line()
    assert where in line and words in line, line
    assert err.value.exit_code == 2


def test_non_finite_numbers_are_refused():
    with pytest.raises(InputError, match="non-finite"):
        parse_json('[{"op": "add", "description": "x", "size": [NaN, 1, 1]}]', "ops.json")
    with pytest.raises(SpecError, match="finite"):
        parse_operations([{"op": "move", "id": "a", "position": [float("inf"), 0]}], "ops.json")


def test_schema_lists_every_operation():
    schema = operations_schema()
    text = json.dumps(schema)
    assert schema["type"] == "array" and schema["maxItems"] == MAX_OPERATIONS
    for name in OP_NAMES:
        assert f'"const": "{name}"' in text or f'"{name}"' in text
    assert "holomj edit operations" in schema["$comment"]


JSON_SCALARS = st.one_of(
    st.none(),
    st.booleans(),
    st.integers(min_value=-(10**6), max_value=10**6),
    st.floats(allow_nan=True, allow_infinity=True),
    st.text(max_size=12),
    st.sampled_from([*OP_NAMES, "living_room.sofa_0", "by_window", "floor", "walls"]),
)
JSON_VALUES = st.recursive(
    JSON_SCALARS,
    lambda inner: st.one_of(
        st.lists(inner, max_size=4), st.dictionaries(st.text(max_size=8), inner, max_size=4)
    ),
    max_leaves=16,
)
FIELDS = st.sampled_from(
    ["op", "id", "description", "on", "room", "size", "position", "yaw_deg", "relations",
     "surface", "material", "count", "energy", "color", "kind", "target", "above", "comment"]
)  # fmt: skip
OPERATION = st.dictionaries(
    FIELDS,
    st.one_of(JSON_VALUES, st.sampled_from(OP_NAMES)),
    min_size=1,
    max_size=6,
).map(lambda d: {**d, "op": d.get("op", "add")})


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.one_of(JSON_VALUES, st.lists(OPERATION, max_size=4)))
def test_fuzz_parser_raises_only_spec_errors(data):
    try:
        ops = parse_operations(data, "fuzz.json")
    except SpecError as err:
        assert err.one_line().startswith("fuzz.json")
        assert "\n" not in err.one_line()
        return
    assert isinstance(ops, list) and len(ops) <= MAX_OPERATIONS
    assert all(op.op in OP_NAMES for op in ops)
    # what parses round-trips through its JSON form
    assert parse_operations([op.model_dump(mode="json") for op in ops]) == ops
