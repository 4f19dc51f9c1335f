"""Leaving optional objects out so that the prompt's relations hold (layout.relation_room)."""

from __future__ import annotations

from holomj.layout.layout_result import ConstraintReport, HardChecks, LayoutResult, Placement
from holomj.layout.relation_room import make_room_for_relations, prompt_relations_held


def _layout(placed: list[str], held: dict[str, bool]) -> LayoutResult:
    reports = [
        ConstraintReport(
            text=f"{name} | edge",
            object=name,
            kind="edge",
            target=None,
            weight=10.0,
            satisfied=ok,
            detail="",
            source="prompt: bookshelf wall",
        )
        for name, ok in held.items()
    ]
    return LayoutResult(
        room_id="room",
        placements={p: Placement(x=0, y=0, yaw_deg=0, width=1, depth=1) for p in placed},
        constraints=reports,
        satisfied=sum(held.values()),
        total=len(held),
        unplaced=[],
        solve_time_s=0.0,
        solver_used="cpsat",
        solver_status="OPTIMAL",
        hard_checks=HardChecks(),
        warnings=[],
    )


def test_a_layout_that_holds_every_prompt_relation_is_kept_as_it_is() -> None:
    first = _layout(["bookshelf-0", "plant-0"], {"bookshelf-0": True})
    calls: list[frozenset[str]] = []
    made = make_room_for_relations(first, ["plant-0"], lambda d: calls.append(d) or first)
    assert made.result is first and not made.dropped and not calls


def test_the_largest_optional_objects_go_first_and_only_as_many_as_needed() -> None:
    first = _layout(["bookshelf-0", "armchair-0", "plant-0"], {"bookshelf-0": False})
    tried: list[frozenset[str]] = []

    def solve_without(dropped: frozenset[str]) -> LayoutResult:
        tried.append(dropped)
        placed = [p for p in ("bookshelf-0", "armchair-0", "plant-0") if p not in dropped]
        return _layout(placed, {"bookshelf-0": "armchair-0" in dropped})

    made = make_room_for_relations(first, ["armchair-0", "plant-0"], solve_without)
    assert tried == [frozenset({"armchair-0"})]
    assert made.dropped == ["armchair-0"] and "1 of 1 hold" in made.reason
    assert prompt_relations_held(made.result) == (1, 1)


def test_a_layout_that_loses_other_objects_or_holds_no_more_is_not_taken() -> None:
    first = _layout(["bookshelf-0", "desk-0", "plant-0"], {"bookshelf-0": False})

    def loses_the_desk(dropped: frozenset[str]) -> LayoutResult:
        return _layout(["bookshelf-0"], {"bookshelf-0": True})

    made = make_room_for_relations(first, ["plant-0"], loses_the_desk)
    assert made.result is first and made.dropped == []

    def no_better(dropped: frozenset[str]) -> LayoutResult:
        kept = [p for p in ("bookshelf-0", "desk-0", "plant-0") if p not in dropped]
        return _layout(kept, {"bookshelf-0": False})

    made = make_room_for_relations(first, ["plant-0"], no_better)
    assert made.result is first and made.dropped == []
