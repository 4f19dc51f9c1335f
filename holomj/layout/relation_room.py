"""Room for what the prompt says about where things go, made by leaving optional objects out.

The solver places objects before it satisfies relations (one more object outweighs any number
of constraints), so an optional object of the room's template (a potted plant, a second
armchair) can take the wall that "four bookshelves against the walls" needed. When a prompt
relation does not hold, the room is solved again without some of the optional objects (neither
defining nor asked for), the largest first; the new layout is kept only if it holds more of the
prompt's relations and places every object that is not left out. What was left out, and why,
is returned for the record: nothing is dropped silently.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field

from holomj.layout.relation_constraints import SOURCE_PREFIX
from holomj.layout.solve import LayoutResult

DROP_STEPS = (1, 3)  # the largest optional instances left out at each try, then all of them


@dataclass
class RelationRoom:
    """The layout kept and the optional instances left out for the prompt's relations."""

    result: LayoutResult
    dropped: list[str] = field(default_factory=list)
    reason: str = ""


def prompt_relations_held(result: LayoutResult) -> tuple[int, int]:
    """(held, total) over the layout's constraints that come from the prompt."""
    reports = [r for r in result.constraints if r.source and r.source.startswith(SOURCE_PREFIX)]
    return sum(r.satisfied for r in reports), len(reports)


def make_room_for_relations(
    result: LayoutResult,
    optional: Sequence[str],
    solve_without: Callable[[frozenset[str]], LayoutResult],
) -> RelationRoom:
    """``result``, or a layout without some optional instances that holds more prompt relations.

    ``optional``: the instances that may be left out (neither defining nor asked for), the most
    in the way (the largest) first; ``solve_without(dropped)``: the room solved again without
    those instances. Tries the first :data:`DROP_STEPS` of them, then all, and keeps the first
    layout that holds every prompt relation, else the one that holds the most."""
    held, total = prompt_relations_held(result)
    optional = [i for i in optional if i in result.placements]
    if held == total or not optional:
        return RelationRoom(result)
    best, best_held = RelationRoom(result), held
    counts = sorted({min(n, len(optional)) for n in (*DROP_STEPS, len(optional))})
    for count in counts:
        dropped = set(optional[:count])
        candidate = solve_without(frozenset(dropped))
        candidate_held, _ = prompt_relations_held(candidate)
        if candidate_held <= best_held or not _places_the_rest(candidate, result, dropped):
            continue
        best_held = candidate_held
        best = RelationRoom(
            candidate,
            sorted(dropped),
            f"left out to hold the prompt's relations ({candidate_held} of {total} hold, "
            f"{held} with it)",
        )
        if candidate_held == total:
            break
    return best


def _places_the_rest(candidate: LayoutResult, first: LayoutResult, dropped: set[str]) -> bool:
    """Whether the new layout places everything the first one did, apart from ``dropped``."""
    return set(first.placements) - dropped <= set(candidate.placements)
