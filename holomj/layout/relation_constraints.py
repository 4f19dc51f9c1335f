"""A plan's relations (``a desk under the window``) as weighted layout constraints, and their
verdicts after the layout.

Every :class:`~holomj.spec.plan.PlanRelation` of a room expands into constraints over the
instances that are in the layout, weighted :data:`RELATION_WEIGHT` (the templates' defaults
weigh 1), with ``source`` ``prompt: <phrase>`` so that the layout's report can be read back per
relation (:func:`relation_verdicts`). Each kind's constraints and how they are spread over the
instances are the vocabulary's (:data:`holomj.spec.relations.RELATION_KINDS`); per subject
instance ``k`` (targets are spread over the target's instances like the template lines):

=================  =========================================================================
corner, middle,    the place constraint (``wall`` is ``edge``; one object in the middle is
                   also at the room's ``centre``)
under/by window,
by door, wall,
facing window/door
next to            ``adjacent to`` (footprints at most 45 cm apart)
near, in front of, the relation of the same name
behind
facing             ``face to``
across from        ``face to`` both ways (the target's first instance faces the subject's)
around             ``adjacent to`` + ``face to`` (chairs at a table)
on each side of    instance 2j ``left of`` and 2j+1 ``right of`` target j, ``adjacent to``,
                   ``face same as``
in a row           instance k ``adjacent to``, ``face same as`` and ``center aligned`` with k-1
=================  =========================================================================

``on``, ``above`` and ``ceiling`` are kept by the plan's structure (a receptacle's small
objects, a wall object's ``above``), and so is ``facing`` between a floor object and a wall object
(the wall object's ``faced_by``): they have no layout constraint and are judged on the finished
scene.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Sequence
from typing import Any

from holomj.layout.constraints import RELATION_WEIGHT, Constraint
from holomj.layout.solve import ConstraintReport
from holomj.spec.plan import PlanRelation, PlanRoom, instance_name
from holomj.spec.relations import RELATIONS, STRUCTURAL_KINDS, RelationFacts

SOURCE_PREFIX = "prompt: "


def source_of(relation: PlanRelation) -> str:
    """The ``source`` every constraint of ``relation`` carries."""
    return f"{SOURCE_PREFIX}{relation.subject} {relation.kind} {relation.target or ''}".strip()


def relation_constraints(plan_room: PlanRoom, present: Iterable[str]) -> list[Constraint]:
    """The room's relations as constraints over the ``present`` instances (in the layout)."""
    here = set(present)
    counts = {o.name: o.quantity for o in plan_room.objects}
    out: list[Constraint] = []
    seen: set[tuple[str, str, str | None]] = set()

    def add(obj: str, kinds: Iterable[str], target: str | None, source: str) -> None:
        if obj not in here or (target is not None and target not in here) or obj == target:
            return
        for kind in kinds:
            c = Constraint.model_validate(
                {"object": obj, "kind": kind, "target": target, "weight": RELATION_WEIGHT,
                 "source": source}
            )  # fmt: skip
            if c.key not in seen:
                seen.add(c.key)
                out.append(c)

    for rel in plan_room.relations:
        facts = RELATIONS[rel.kind]
        if not facts.constraints or rel.subject not in counts:
            continue
        source = source_of(rel)
        subjects = [instance_name(rel.subject, k) for k in range(counts[rel.subject])]
        if not facts.takes_target:
            _spread_place(facts, subjects, add, source)
        elif rel.target is not None and rel.target in counts:
            targets = [instance_name(rel.target, k) for k in range(counts[rel.target])]
            _spread_pair(facts, subjects, targets, add, source)
    return out


_Add = Callable[[str, Iterable[str], str | None, str], None]


def _spread_place(facts: RelationFacts, subjects: list[str], add: _Add, source: str) -> None:
    """A place (no target): every instance gets the constraints (a lone one also ``alone``),
    or, in a row, each gets them to the instance before it."""
    if facts.expansion == "row":
        for prev, s in zip(subjects, subjects[1:], strict=False):
            add(s, facts.constraints, prev, source)
        return
    for s in subjects:
        add(s, facts.constraints, None, source)
        if len(subjects) == 1:
            add(s, facts.alone, None, source)


def _spread_pair(
    facts: RelationFacts, subjects: list[str], targets: list[str], add: _Add, source: str
) -> None:
    """A relation to another object, spread over both objects' instances (see
    :data:`holomj.spec.relations.Expansion`)."""
    if facts.expansion == "sides":
        for k, s in enumerate(subjects):
            t = targets[min(k // 2, len(targets) - 1)]
            side = "left_of" if k % 2 == 0 else "right_of"
            add(s, (side, *facts.constraints), t, source)
        return
    for k, s in enumerate(subjects):
        add(s, facts.constraints, targets[k * len(targets) // len(subjects)], source)
    if facts.expansion == "mutual":
        add(targets[0], facts.constraints, subjects[0], source)


def _between_floor_objects(rel: PlanRelation, floor: set[str]) -> bool:
    """A layout relation: its subject and its target (if any) stand on the floor."""
    return rel.subject in floor and (rel.target is None or rel.target in floor)


def relation_verdicts(
    plan_room: PlanRoom, reports: Sequence[ConstraintReport]
) -> list[dict[str, Any]]:
    """Per layout relation of the room: its constraints, how many hold, and whether all do."""
    by_source: dict[str, list[ConstraintReport]] = {}
    for report in reports:
        if report.source and report.source.startswith(SOURCE_PREFIX):
            by_source.setdefault(report.source, []).append(report)
    out = []
    floor = {o.name for o in plan_room.objects if o.placement == "floor"}
    for rel in plan_room.relations:
        if rel.kind in STRUCTURAL_KINDS or not _between_floor_objects(rel, floor):
            continue
        found = by_source.get(source_of(rel), [])
        held = sum(r.satisfied for r in found)
        out.append(
            {
                "room": plan_room.id,
                "subject": rel.subject,
                "relation": rel.kind,
                "target": rel.target,
                "phrase": rel.phrase,
                "constraints": len(found),
                "satisfied": held,
                "held": bool(found) and held == len(found),
                "detail": "; ".join(f"{r.text}: {r.detail}" for r in found if not r.satisfied)
                or ("no instance in the layout" if not found else "all hold"),
            }
        )
    return out
