"""What refine measures: the instruction as an annotation for the evaluator, and the score.

**The instruction's annotation** (:func:`instruction_spec`, the format of
:mod:`holomj.evaluation.specs`), one entry per item of :mod:`holomj.refinement.instruction`:

- *add*: at least the asked number of objects refine added for it (ids ``<room>.refine.<key>_<n>``:
  the entry's ``id_stem``, so objects that were there before do not count), and every relation
  the instruction gives it, for all of them ("by the window" -> next to a window; "next to the
  sofa" -> next to a sofa of the room; "next to the armchair" another item -> next to the
  armchair refine added);
- *add_on*: at least as many objects of the category in the room as before plus the number
  asked, and one of them on the receptacle;
- *remove*: as many objects of the category in the room as before minus the number removed;
- *move*: the moved object's relations (any of the objects moved).

**The plan's annotation** (the folder's ``plan.json``) is measured too, less what the
instruction changes on purpose: a removed kind's counts and relations, a moved kind's
relations (:func:`adjust_plan_spec`).

**The score** (:func:`refine_score`): the mean of every measured score of ``holomj eval``
(counts, attributes, relations, absent, defining, collisions, outside, support, navigability,
front access, doors and windows clear, stability: each in [0, 1]; a metric with nothing to
measure is left out) and of one entry per instruction item check (1 when it holds, 0 when
not)::

    score = (sum of measured eval scores + instruction checks met) / (metrics + checks)

A round is kept when the edited scene validates and its score is not lower than the score
before it.
"""

from __future__ import annotations

import copy
import re
from typing import Any

from holomj.evaluation.plan_spec import RELATION_MAP
from holomj.refinement.instruction_items import Instruction, Item
from holomj.refinement.summary import PlannerSceneSummary

TOLERANCE = 1e-9


def instruction_spec(instruction: Instruction, before: PlannerSceneSummary) -> dict[str, Any]:
    """The annotation of ``instruction`` (see the module docstring), counted against the scene
    ``before`` refine changed it."""
    objects: list[dict[str, Any]] = []
    references: list[dict[str, Any]] = []
    relations: list[dict[str, Any]] = []
    refs: dict[str, str] = {}

    def reference(object_id: str) -> str:
        if object_id in refs:
            return refs[object_id]
        obj = before.object(object_id)
        name = f"target {len(refs) + 1}"
        refs[object_id] = name
        entry: dict[str, Any] = {"name": name, "count": {"ge": 1}}
        if re.search(r"_\d+$", object_id):
            entry["id_stem"] = re.sub(r"_\d+$", "", object_id)
        if obj is not None:
            entry["categories"] = [obj.category]
            if obj.room:
                entry["room_id"] = obj.room
        references.append(entry)
        return name

    for item in instruction.items:
        name = _name(item)
        entry: dict[str, Any] = {"name": name, "item": item.key, "action": item.action}
        if item.room:
            entry["room_id"] = item.room
        if item.action == "add":
            entry.update(id_stem=item.stem, count={"ge": item.quantity})
            entry["categories"] = list(item.categories)
            objects.append(entry)
        elif item.action == "add_on":
            have = len(before.of_category(set(item.categories), item.room))
            entry.update(count={"ge": have + item.quantity}, categories=list(item.categories))
            objects.append(entry)
            if item.on:
                relations.append(_relation(item, name, "on", reference(item.on), "any"))
        elif item.action == "remove":
            have = len(before.of_category(set(item.categories), item.room))
            entry.update(
                count={"eq": max(0, have - item.quantity)}, categories=list(item.categories)
            )
            objects.append(entry)
        else:  # move: its relations, over the objects moved
            stems = {re.sub(r"_\d+$", "", t) for t in item.targets}
            if len(stems) == 1 and all(re.search(r"_\d+$", t) for t in item.targets):
                entry["id_stem"] = stems.pop()
            entry.update(count={"ge": 1}, categories=list(item.categories))
            references.append(entry)
        quantifier = "all" if item.action == "add" else "any"
        for kind, target in item.relations:
            mapped = RELATION_MAP.get(kind)
            if mapped is None:
                continue
            relation, place = mapped
            obj_name: str | None
            if place is None:
                if target is None:
                    continue
                if target.startswith("item:"):
                    other = instruction.item(target[5:])
                    if other is None:
                        continue
                    obj_name = _name(other)
                else:
                    obj_name = reference(target)
            else:
                obj_name = place or None
            if kind == "around":
                relation = "next to"
            relations.append(_relation(item, name, relation, obj_name, quantifier, kind))
    return {
        "id": "instruction",
        "prompt": instruction.text,
        "objects": objects,
        "references": references,
        "relations": relations,
    }


def _name(item: Item) -> str:
    return item.key.replace("_", " ")


def _relation(
    item: Item,
    subject: str,
    relation: str,
    obj: str | None,
    quantifier: str,
    kind: str | None = None,
) -> dict[str, Any]:
    row: dict[str, Any] = {
        "subject": subject,
        "relation": relation,
        "object": obj,
        "quantifier": quantifier,
        "item": item.key,
        "edit_kind": kind or relation,
    }
    if item.room:
        row["room_id"] = item.room
    return row


def adjust_plan_spec(
    spec: dict[str, Any] | None, instruction: Instruction
) -> dict[str, Any] | None:
    """The plan's annotation less what the instruction changes on purpose: the counts and
    relations of a removed kind in its room, the relations of a moved kind."""
    if spec is None:
        return None
    spec = copy.deepcopy(spec)
    for item in instruction.items:
        if item.action not in ("remove", "move"):
            continue
        cats = set(item.categories)
        names = {
            o["name"]
            for o in spec.get("objects", []) + spec.get("references", [])
            if (set(o.get("categories") or []) & cats and o.get("room_id") in (None, item.room))
            or _stem_names(o, item)
        }
        if item.action == "remove":
            spec["objects"] = [o for o in spec.get("objects", []) if o["name"] not in names]
            spec["relations"] = [
                r
                for r in spec.get("relations", [])
                if r.get("subject") not in names and r.get("object") not in names
            ]
        else:
            spec["relations"] = [
                r for r in spec.get("relations", []) if r.get("subject") not in names
            ]
    return spec


def _stem_names(entry: dict[str, Any], item: Item) -> bool:
    stem = entry.get("id_stem")
    if not stem:
        return False
    return any(re.fullmatch(re.escape(stem) + r"_\d+", t) for t in item.targets)


def instruction_checks(rows: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """The evaluator's rows of the instruction's annotation as checks: what, held, why."""
    out = []
    for row in rows:
        spec = row.get("spec") or {}
        if row.get("kind") == "relation":
            what = f"{spec.get('subject')} {spec.get('relation')} {spec.get('object') or ''}"
        else:
            what = f"{spec.get('name', row.get('name'))} count {spec.get('count')}"
        out.append(
            {
                "item": spec.get("item"),
                "check": row.get("kind"),
                "what": " ".join(what.split()),
                "held": bool(row.get("held")),
                "reason": row.get("reason", ""),
                "found": row.get("found"),
                "need": next(iter((spec.get("count") or {}).values()), None),
            }
        )
    return out


def refine_score(scores: dict[str, dict[str, Any]], checks: list[dict[str, Any]]) -> dict[str, Any]:
    """The refine score of one scene (see the module docstring), with its parts."""
    measured = {k: float(v["score"]) for k, v in scores.items() if v.get("score") is not None}
    met = sum(1 for c in checks if c["held"])
    parts = len(measured) + len(checks)
    total = (sum(measured.values()) + met) / parts if parts else 0.0
    return {
        "score": round(total, 6),
        "eval_mean": round(sum(measured.values()) / len(measured), 6) if measured else None,
        "instruction_met": [met, len(checks)],
        "metrics": {k: round(v, 4) for k, v in measured.items()},
    }


def not_worse(after: float, before: float) -> bool:
    """Whether a score is not lower than another (within rounding)."""
    return after >= before - TOLERANCE
