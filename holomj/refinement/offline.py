"""The offline refine planner: the edits that fix what the evaluation finds.

Given the instruction's items (:mod:`holomj.refinement.instruction`), the checks of the last
evaluation (:func:`holomj.refinement.goals.instruction_checks`), the scene's other problems that a
move can fix (``findings``, from :mod:`holomj.jobs.refine_findings`) and the operations tried
in earlier rounds, it proposes, in this order:

- a requested object missing -> ``add`` (the item's description, room and relations; ids
  ``<room>.refine.<key>_<n>``; an object to stand next to another item of the instruction
  names that item's new id);
- small objects missing -> ``add_on`` onto the item's receptacle;
- a relation unmet -> ``move`` of the item's objects to where its relations hold;
- an object to remove still there -> ``remove``;
- a blocked door or window -> ``move`` of the blocking object away (against a wall, where
  nothing blocks: the edit lays it out again among the others);
- an unreachable room or pocket of floor -> ``move`` of the object that fences it.

An operation tried before (the same operation, ids of added objects aside: ``tried`` holds
their :func:`signature`) is not proposed again; at most ``max_ops`` operations per round.
"""

from __future__ import annotations

import json
from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import Any

from holomj.refinement.finding import Finding
from holomj.refinement.instruction_items import Instruction, Item
from holomj.refinement.safety import MAX_OPS_PER_ROUND, next_id
from holomj.refinement.summary import PlannerSceneSummary


@dataclass
class Proposal:
    """The operations of one round, and why each was proposed."""

    operations: list[dict[str, Any]] = field(default_factory=list)
    reasons: list[str] = field(default_factory=list)


def signature(op: dict[str, Any]) -> str:
    """What makes two operations the same (an add's id and every comment aside)."""
    data = {
        k: v for k, v in op.items() if k != "comment" and not (k == "id" and op.get("op") == "add")
    }
    return json.dumps(data, sort_keys=True)


def propose(
    instruction: Instruction,
    scene: PlannerSceneSummary,
    checks: list[dict[str, Any]],
    findings: Iterable[Finding] = (),
    tried: set[str] | None = None,
    *,
    max_ops: int = MAX_OPS_PER_ROUND,
) -> Proposal:
    """The next round's operations (see the module docstring)."""
    tried = tried if tried is not None else set()
    return _Planner(instruction, scene, checks, tried, max_ops).run(list(findings))


class _Planner:
    def __init__(
        self,
        instruction: Instruction,
        scene: PlannerSceneSummary,
        checks: list[dict[str, Any]],
        tried: set[str],
        max_ops: int,
    ) -> None:
        self.instruction, self.scene, self.tried, self.max_ops = instruction, scene, tried, max_ops
        self.failing: dict[str, list[dict[str, Any]]] = {}
        for check in checks:
            if not check["held"] and check.get("item"):
                self.failing.setdefault(check["item"], []).append(check)
        self.taken = set(scene.ids)
        self.new_ids: dict[str, str] = {}  # item key -> id added this round (first)
        self.out = Proposal()
        self.moving: set[str] = set()

    def run(self, findings: list[Finding]) -> Proposal:
        for item in self.instruction.items:
            if item.action == "add":
                self._add(item)
        for item in self.instruction.items:
            if item.action == "add_on":
                self._add_on(item)
        for item in self.instruction.items:
            if item.action == "add":
                self._relations(item, self._mine(item))
            elif item.action == "move":
                self._relations(item, [t for t in item.targets if t in self.scene.ids])
            elif item.action == "remove":
                self._remove(item)
        for finding in findings:
            self._fix(finding)
        return self.out

    # -- helpers

    def _emit(self, op: dict[str, Any], why: str) -> bool:
        if len(self.out.operations) >= self.max_ops:
            return False
        key = signature(op)
        if key in self.tried:
            self.out.reasons.append(f"not tried again: {why}")
            return False
        self.tried.add(key)
        self.out.operations.append({**op, "comment": why[:480]})
        self.out.reasons.append(why)
        return True

    def _mine(self, item: Item) -> list[str]:
        """The objects refine added for an item so far."""
        prefix = item.stem + "_"
        return [
            i for i in sorted(self.scene.ids) if i.startswith(prefix) and i[len(prefix) :].isdigit()
        ]

    def _failing(self, item: Item, check: str) -> list[dict[str, Any]]:
        return [c for c in self.failing.get(item.key, []) if c["check"] == check]

    def _relations_of(self, item: Item) -> list[dict[str, Any]]:
        out = []
        for kind, target in item.relations:
            if target is None:
                out.append({"kind": kind})
                continue
            if target.startswith("item:"):
                other = self.instruction.item(target[5:])
                if other is None:
                    continue
                target = self.new_ids.get(other.key) or next(iter(self._mine(other)), None)
                if target is None:
                    continue
            if target in self.taken:
                out.append({"kind": kind, "target": target})
        return out

    # -- the instruction

    def _missing(self, item: Item) -> int:
        """How many objects an item still lacks (0 when its count holds)."""
        for check in self._failing(item, "object"):
            found, need = check.get("found"), check.get("need")
            if isinstance(found, int) and isinstance(need, int):
                return max(0, need - found)
        return 0

    def _add(self, item: Item) -> None:
        missing = self._missing(item)
        if missing <= 0 or item.room is None:
            return
        for _ in range(missing):
            new_id = next_id(item.stem, self.taken)
            op: dict[str, Any] = {
                "op": "add",
                "id": new_id,
                "description": item.description,
                "room": item.room,
                "relations": self._relations_of(item),
            }
            if item.category:
                op["category"] = item.category
            there = item.quantity - missing
            why = f"instruction: {item.phrase or item.kind} ({there} of {item.quantity} there)"
            if self._emit(op, why):
                self.taken.add(new_id)
                self.new_ids.setdefault(item.key, new_id)

    def _add_on(self, item: Item) -> None:
        missing = self._missing(item)
        if missing <= 0 or item.on is None or item.on not in self.scene.ids:
            return
        op: dict[str, Any] = {
            "op": "add_on",
            "description": item.description,
            "on": item.on,
            "count": max(1, min(missing, 10)),
        }
        if item.category:
            op["category"] = item.category
        self._emit(op, f"instruction: {item.phrase or item.kind} on {item.on} ({missing} missing)")

    def _relations(self, item: Item, subjects: list[str]) -> None:
        if not self._failing(item, "relation") or not subjects:
            return
        relations = self._relations_of(item)
        if not relations:
            return
        failed = "; ".join(c["what"] for c in self._failing(item, "relation"))
        for subject in subjects:
            if subject in self.moving:
                continue
            op = {"op": "move", "id": subject, "relations": relations}
            if self._emit(op, f"instruction: {failed} (move {subject})"):
                self.moving.add(subject)

    def _remove(self, item: Item) -> None:
        if not self._failing(item, "object"):
            return
        for target in item.targets:
            if target in self.scene.ids:
                self._emit({"op": "remove", "id": target}, f"instruction: remove {target}")

    # -- what the evaluation finds

    def _fix(self, finding: Finding) -> None:
        obj = self.scene.object(finding.object)
        if obj is None or obj.static or obj.placement != "floor" or obj.id in self.moving:
            return
        relations = [{"kind": "wall"}]
        for item in self.instruction.items:
            if item.action == "add" and obj.id in self._mine(item):
                relations = self._relations_of(item) or relations
        op = {"op": "move", "id": obj.id, "relations": relations}
        if self._emit(op, f"{finding.metric}: {finding.reason} (move {obj.id} away)"):
            self.moving.add(obj.id)
