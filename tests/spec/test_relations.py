"""The relation vocabulary is one table: everything that names relation kinds agrees with it."""

from __future__ import annotations

from typing import get_args

from holomj.evaluation.relations import RELATIONS as ANNOTATION_RELATIONS
from holomj.layout.constraints import ALL_KINDS
from holomj.plan.prompt_relations import read_relations
from holomj.spec.edit import EditRelation
from holomj.spec.plan import PlanRelation
from holomj.spec.relations import (
    EDIT_KIND_OF,
    KIND_OF_WORDS,
    PHRASE_FAMILIES,
    PLACE_WORDS,
    PLANNED_KINDS,
    RELATION_KINDS,
    RELATIONS,
)


def test_schemas_take_the_kinds_of_the_table() -> None:
    plan_kinds = get_args(PlanRelation.model_fields["kind"].annotation)
    assert plan_kinds == PLANNED_KINDS
    edit_kinds = get_args(EditRelation.model_fields["kind"].annotation)
    assert edit_kinds == tuple(k for k, v in EDIT_KIND_OF.items() if k == v)
    assert "in_row" not in edit_kinds and "both_sides" not in edit_kinds


def test_every_name_in_the_table_is_known_where_it_is_used() -> None:
    families = set(PHRASE_FAMILIES.values())
    targets = set(PLACE_WORDS.values()) | {"object", "row"}
    for facts in RELATION_KINDS:
        assert set(facts.constraints) | set(facts.alone) <= set(ALL_KINDS), facts.kind
        if facts.judged_as is not None:
            assert facts.judged_as[0] in ANNOTATION_RELATIONS, facts.kind
        if facts.edit_as is not None:
            assert RELATIONS[facts.edit_as].edit_as == facts.edit_as, facts.kind
        assert facts.read_from, f"{facts.kind}: no words read as it"
        for family, target in facts.read_from:
            assert family in families and target in targets, (facts.kind, family, target)
    assert len(KIND_OF_WORDS) == sum(len(f.read_from) for f in RELATION_KINDS)  # no word twice


def test_a_phrase_is_read_as_the_kind_the_table_gives() -> None:
    words = ["a", "desk", "under", "the", "window", "and", "a", "lamp", "next", "to", "a", "sofa"]
    found = read_relations(words, [(0, 2), (6, 8), (10, 12)])
    assert [(r.subject, r.kind, r.target) for r in found] == [
        (0, "under_window", None),
        (1, "adjacent_to", 2),
    ]
