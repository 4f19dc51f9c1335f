"""Apply a list of edit operations to a scene, in memory, one after another.

Each operation sees the scene the ones before it left; one that is refused (an unknown id, an
absurd size, a position outside the room, a material nothing matches, no free place...) changes
nothing and is reported with the reason. What moved is found by comparing every object's pose
before and after, so the report can never miss one: an object not touched by an operation keeps
its pose exactly.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any

from holomj.edit.footprints import object_yaw
from holomj.edit.lights import light
from holomj.edit.objects import add, move, remove, replace
from holomj.edit.small import add_on
from holomj.edit.state import Change, EditContext, Refused
from holomj.edit.surfaces import material
from holomj.errors import HolomjError
from holomj.spec.edit import MovedObject, OperationResult
from holomj.spec.scene import SceneSpec

OPERATIONS: dict[str, Callable[[SceneSpec, Any, EditContext, int], Change]] = {
    "add": add,
    "add_on": add_on,
    "remove": remove,
    "move": move,
    "replace": replace,
    "material": material,
    "light": light,
}


@dataclass
class Applied:
    """The edited scene, every operation's outcome, and what was added, removed and moved."""

    scene: SceneSpec
    results: list[OperationResult] = field(default_factory=list)
    added: list[str] = field(default_factory=list)
    removed: list[str] = field(default_factory=list)
    moved: list[MovedObject] = field(default_factory=list)

    @property
    def applied(self) -> int:
        """How many operations were applied."""
        return sum(r.status == "applied" for r in self.results)

    @property
    def refused(self) -> int:
        """How many operations were refused."""
        return sum(r.status == "refused" for r in self.results)


def apply_operations(
    scene: SceneSpec,
    operations: Sequence[Any],
    ctx: EditContext,
    *,
    log: Callable[[str], None] | None = None,
) -> Applied:
    """Apply ``operations`` (:mod:`holomj.spec.edit` models) to ``scene`` in order."""
    current = scene
    results: list[OperationResult] = []
    why: dict[str, str] = {}
    for index, op in enumerate(operations):
        start = time.perf_counter()
        try:
            change = OPERATIONS[op.op](current, op, ctx, index)
        except Refused as err:
            change, reason = None, err.reason
        except HolomjError as err:  # a stage's own check said no (an input it refuses)
            change, reason = None, err.one_line()
        seconds = round(time.perf_counter() - start, 3)
        if change is None:
            results.append(
                OperationResult(
                    index=index, op=op.op, status="refused", reason=reason, seconds=seconds
                )
            )
            if log is not None:
                log(f"operation {index} ({op.op}) refused: {reason}")
            continue
        current = change.scene
        for oid in change.moved:
            why[oid] = change.why.get(oid, f"operation {index}: {op.op}")
        results.append(
            OperationResult(
                index=index,
                op=op.op,
                status="applied",
                added=change.added,
                removed=change.removed,
                moved=change.moved,
                changed=change.changed,
                notes=change.notes,
                details=change.details,
                seconds=seconds,
            )
        )
        if log is not None:
            what = ", ".join(
                f"{name} {', '.join(ids)}"
                for name, ids in (
                    ("added", change.added), ("removed", change.removed),
                    ("moved", change.moved), ("changed", change.changed),
                )
                if ids
            )  # fmt: skip
            log(f"operation {index} ({op.op}) applied: {what or 'no change'}")
    return _outcome(scene, current, results, why)


def _outcome(
    before: SceneSpec, after: SceneSpec, results: list[OperationResult], why: dict[str, str]
) -> Applied:
    old = {o.id: o for o in before.objects}
    new = {o.id: o for o in after.objects}
    moved = []
    for oid, o in old.items():
        n = new.get(oid)
        if n is None or (n.position == o.position and n.yaw_deg == o.yaw_deg and n.quat == o.quat):
            continue
        moved.append(
            MovedObject(
                id=oid,
                from_position=o.position,
                to_position=n.position,
                from_yaw_deg=round(object_yaw(o), 4),
                to_yaw_deg=round(object_yaw(n), 4),
                why=why.get(oid, "changed"),
            )
        )
    return Applied(
        scene=after,
        results=results,
        added=[i for i in new if i not in old],
        removed=[i for i in old if i not in new],
        moved=moved,
    )
