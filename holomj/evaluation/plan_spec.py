"""A plan as an annotation: what a :class:`~holomj.spec.plan.ScenePlan` asks of a scene, in the
annotation format the fidelity scorer reads (:mod:`holomj.evaluation.specs`).

- **Own plan** (``own=True``: the folder's ``plan.json``): everything the plan holds is counted:
  its number of rooms and of rooms per (exact) type, every floor, wall and ceiling object with its
  quantity (``eq``) and each small-object kind per room (``ge 1``: how many land is the drop's);
  instances are found by the ids generation gives them (``living_room.sofa_0``) in that room.
- **Another folder's plan** (a prompt planned for a house that was not generated from it):
  only what the prompt asked for is counted: the requested objects (``requested``) and the small
  objects it puts on something, and one room (``ge 1``) of each type holding them; instances are
  found by category (the plan's hint and the vocabulary's reading of the name) in rooms of the
  plan room's type; a name planned in several rooms of one type is counted once, at least the
  largest quantity one of them asks for. The plan's other objects stay in ``references``,
  where relations look their names up.
- **Attributes**: a colour, material or shape word of a requested object's description that the
  prompt itself puts before the object's name ("a *red* armchair", "two *leather* sofas").
- **Relations**: the plan's relations for all instances of the subject: corner -> in corner,
  wall -> against wall, middle, under_window -> under window, by_window -> next to the window,
  by_door -> near the door, facing_window / facing_door -> facing, adjacent_to and both_sides ->
  next to, near, in_front_of, behind, facing, across_from, on, above; around: around the one
  target for several subjects, next to it for one, next to one of them (75 % of the subjects)
  for several targets. ``in_row`` and
  ``ceiling`` have no geometric test here: they are listed in ``skipped``.
"""

from __future__ import annotations

import re
from collections import defaultdict
from typing import TYPE_CHECKING, Any

from holomj.evaluation.text import find_words, main_phrase, normalise, slug
from holomj.evaluation.vocabulary import Vocabulary
from holomj.spec.relations import RELATION_KINDS

if TYPE_CHECKING:
    from holomj.spec.plan import PlanObject, PlanRelation, PlanRoom, ScenePlan

# plan relation kind -> (annotation relation, target place or None for the plan's target)
RELATION_MAP: dict[str, tuple[str, str | None]] = {
    f.kind: f.judged_as for f in RELATION_KINDS if f.judged_as is not None
}
ATTRIBUTE_GAP_WORDS = 3  # "a red leather armchair": the word at most this many words before


def spec_from_plan(plan: ScenePlan, vocab: Vocabulary, *, own: bool) -> dict[str, Any]:
    """The annotation a plan makes (see the module docstring); ``own``: the folder was
    generated from this plan, so its ids name the plan's instances and everything the plan
    holds is counted; otherwise only what the prompt asked for is."""
    counted: list[dict[str, Any]] = []
    references: list[dict[str, Any]] = []
    merged: dict[tuple[str, str], dict[str, Any]] = {}
    relations: list[dict[str, Any]] = []
    skipped: list[str] = []
    asked_types: set[str] = set()
    for room in plan.rooms:
        on_subjects = {r.subject for r in room.relations if r.kind == "on"}
        entries = [_object_entry(plan, room, obj, vocab, own) for obj in room.objects]
        entries += _small_entries(room, own, on_subjects)
        for entry in entries:
            asked = entry.pop("asked") or own
            if asked:
                asked_types.add(room.type)
            _add(counted if asked else references, merged, entry, own)
        for rel in room.relations:
            judged = _relation_entry(room, rel, own)
            if judged is None:
                skipped.append(f"{room.id}: {rel.subject} {rel.kind} {rel.target or ''}".strip())
            else:
                relations.append(judged)
    spec: dict[str, Any] = {"id": "plan", "prompt": plan.prompt, "scene_type": plan.scene_type}
    if own:
        types: dict[str, int] = defaultdict(int)
        for room in plan.rooms:
            types[room.type] += 1
        spec["rooms"] = {"eq": len(plan.rooms)}
        spec["room_types"] = [
            {"type": t, "count": {"eq": n}, "exact_type": True} for t, n in types.items()
        ]
    else:
        spec["room_types"] = [{"type": t, "count": {"ge": 1}} for t in sorted(asked_types)]
    spec.update(objects=counted, references=references, relations=relations, skipped=skipped)
    return spec


def _relation_entry(room: PlanRoom, rel: PlanRelation, own: bool) -> dict[str, Any] | None:
    """The annotation relation a plan relation is judged as (None: no geometric test)."""
    mapped = RELATION_MAP.get(rel.kind)
    if mapped is None:
        return None
    kind, place = mapped
    quantifier = "all"
    if rel.kind == "around":
        kind, quantifier = _around(room, rel.subject, rel.target)
    entry: dict[str, Any] = {
        "subject": rel.subject,
        "relation": kind,
        "object": rel.target if place is None else (place or None),
        "quantifier": quantifier,
        "room": room.type,
        "plan_kind": rel.kind,
    }
    if rel.phrase:
        entry["phrase"] = rel.phrase
    if own:
        entry["room_id"] = room.id
    return entry


def _around(room: PlanRoom, subject: str, target: str | None) -> tuple[str, str]:
    """How an ``around`` is judged: around one table when there are several seats and one
    table; next to it for a lone seat; next to one of them for seats shared by many tables."""
    counts = {o.name: o.quantity for o in room.objects}
    if counts.get(target or "", 1) > 1:
        return "next to", "most"
    if counts.get(subject, 1) < 2:
        return "next to", "all"
    return "around", "any"


def _small_entries(room: PlanRoom, own: bool, on_subjects: set[str]) -> list[dict[str, Any]]:
    """One entry per small-object kind of a room (``ge 1``)."""
    small: dict[str, dict[str, Any]] = {}
    for obj in room.objects:
        for item in obj.on_top:
            entry = small.setdefault(
                item.name,
                {
                    "name": item.name,
                    "count": {"ge": 1},
                    "room": room.type,
                    "categories": [],
                    "small": True,
                    "asked": item.name in on_subjects,
                },
            )
            if item.category and item.category not in entry["categories"]:
                entry["categories"].append(item.category)
            if own:
                entry["room_id"] = room.id
    return list(small.values())


def _object_entry(
    plan: ScenePlan, room: PlanRoom, obj: PlanObject, vocab: Vocabulary, own: bool
) -> dict[str, Any]:
    entry: dict[str, Any] = {
        "name": obj.name,
        "count": {"eq": obj.quantity},
        "room": room.type,
        "categories": [obj.category] if obj.category else [],
        "requested": obj.requested,
        "asked": obj.requested,
    }
    if own:
        entry["room_id"] = room.id
        entry["id_stem"] = f"{room.id}.{slug(obj.name)}"
    if obj.requested:
        attributes = prompt_attributes(plan.prompt, obj.name, obj.description, vocab)
        if attributes:
            entry["attributes"] = attributes
    return entry


def _add(
    objects: list[dict[str, Any]],
    merged: dict[tuple[str, str], dict[str, Any]],
    entry: dict[str, Any],
    own: bool,
) -> None:
    """Append ``entry``; without ids, one name in one room type is counted once: at least
    the most any one plan room of that type asks for (the planner may add rooms the prompt
    did not ask for, and copy a request into them)."""
    if own:
        objects.append(entry)
        return
    key = (entry["room"], normalise(entry["name"]))
    if key not in merged:
        merged[key] = entry
        objects.append(entry)
        return
    have = merged[key]
    most = max(next(iter(have["count"].values())), next(iter(entry["count"].values())))
    have["count"] = {"ge": most}
    have["categories"] = sorted(set(have.get("categories", [])) | set(entry["categories"]))


def prompt_attributes(
    prompt: str, name: str, description: str, vocab: Vocabulary
) -> dict[str, str]:
    """The colour, material and shape words of ``description`` the prompt puts right before the
    object's name (its last word, or a plural of it)."""
    main = main_phrase(description)
    text = normalise(prompt)
    noun = normalise(name).split()[-1] if normalise(name) else ""
    found: dict[str, str] = {}
    for key, table in (
        ("color", vocab.colors),
        ("material", vocab.materials),
        ("shape", vocab.shapes),
    ):
        for word in find_words(main, table):
            gap = rf"(?:\w+\s+){{0,{ATTRIBUTE_GAP_WORDS}}}"
            pattern = rf"\b{re.escape(word)}\s+{gap}{re.escape(noun)}\w*"
            if noun and re.search(pattern, text):
                found[key] = word
                break
    return found
