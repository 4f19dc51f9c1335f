"""Keep a house whole: objects that cannot stand where they were authored move, or are left out.

:func:`make_stand` refuses nothing: an object it cannot save is listed ``unsaved``. This stage
runs it again (at most :data:`MAX_ROUNDS` times) after dealing with each unsaved object:

1. **Restacked.** A small object whose receptacle holds it nowhere (turned and shifted on
   it, as the drops already try) is stacked on the nearest object beside it on that
   receptacle with a footprint at least as large (a newspaper on a box).
2. **Another receptacle of the same kind.** Else it goes to the nearest other receptacle of
   the same category in the house (the other side table, the next shelf), at the same height
   above it. Each new support is tried once.
3. **Left out.** When no receptacle is left to try (or the object is not a small object on a
   receptacle: a piece of furniture wedged in too deep to separate, an object that does not
   settle), it is left out of the house, with what rests on it, and recorded with where it
   was and why.

The outcome is the last :class:`~holomj.physics.standing.stage.StandOutcome`, its ``changes``
one record per object that moved to another receptacle or was left out (``object``,
``change``: ``relocated`` | ``left_out``, ``from``: support and position as imported, ``to``:
support and position as written (None when left out), ``why``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from holomj.library.store import AssetLibrary
from holomj.physics.standing.records import FLOOR
from holomj.physics.standing.stage import (
    Recompile,
    StandOptions,
    StandOutcome,
    make_stand,
)
from holomj.spec.scene import SceneObject, SceneSpec

MAX_ROUNDS = 3


@dataclass
class KeptHouse:
    """The house made to stand, with every object moved elsewhere or left out."""

    outcome: StandOutcome
    imported: int  # objects in the house as imported
    changes: list[dict[str, Any]] = field(default_factory=list)
    rounds: int = 1
    imported_positions: dict[str, tuple[float, float, float]] = field(default_factory=dict)

    @property
    def left_out(self) -> list[dict[str, Any]]:
        """The records of the objects left out."""
        return [c for c in self.changes if c["change"] == "left_out"]

    @property
    def relocated(self) -> list[dict[str, Any]]:
        """The records of the objects moved to another receptacle."""
        return [c for c in self.changes if c["change"] == "relocated"]

    @property
    def kept_share(self) -> float:
        """The share of the imported objects the written house keeps."""
        if not self.imported:
            return 1.0
        return (self.imported - len(self.left_out)) / self.imported

    def to_report(self) -> dict[str, Any]:
        """The fields this stage adds to ``import_report.json`` (besides the stand's own):
        every ``moved`` record with its ``from`` and ``to`` position (as imported, as
        written), the counts, ``relocated`` and ``left_out`` (see the module docstring)."""
        written = {o.id: o.position for o in self.outcome.scene.objects}
        moved = [
            {
                **record,
                "from": _rounded(self.imported_positions.get(record["object"])),
                "to": _rounded(written.get(record["object"])),
            }
            for record in self.outcome.to_report()["moved"]
        ]
        return {
            "moved": moved,
            "objects_imported": self.imported,
            "objects_kept": self.imported - len(self.left_out),
            "kept_share": round(self.kept_share, 4),
            "relocated": self.relocated,
            "left_out": self.left_out,
            "stand_rounds": self.rounds,
        }


def make_stand_keeping(
    scene: SceneSpec,
    library: AssetLibrary,
    recompile: Recompile,
    options: StandOptions | None = None,
    *,
    source: Path | str = "scene",
) -> KeptHouse:
    """Make ``scene`` stand, moving or leaving out what cannot (see the module docstring)."""
    facts = _Facts.of(scene, library)
    original = {o.id: o for o in scene.objects}
    tried: dict[str, set[str]] = {}
    why_moved: dict[str, str] = {}
    left: dict[str, str] = {}
    work = scene
    rounds = 0
    while True:
        rounds += 1
        last = rounds >= MAX_ROUNDS
        outcome = make_stand(
            work, library, recompile, options, validate_unsaved=False, source=source
        )
        if not outcome.unsaved:
            break
        unsaved = {u.name: u.why for u in outcome.unsaved}
        by_id = {o.id: o for o in work.objects}
        moved: dict[str, SceneObject] = {}
        for obj in work.objects:
            why = unsaved.get(obj.id)
            if why is None or _follows_parent(obj, why, unsaved):
                continue
            step = None if last else _next_support(obj, by_id, facts, tried, unsaved)
            if step is None:
                left[obj.id] = why
                continue
            target, how = step
            why_moved[obj.id] = f"{why}; {how}"
            moved[obj.id] = _onto(obj, by_id[str(obj.support)], target)
        objects = _carried(work.objects, moved, left)
        objects = _without_orphans(objects, left)
        work = SceneSpec.model_validate({**work.model_dump(), "objects": objects})
        if last or not objects:
            outcome = make_stand(
                work, library, recompile, options, validate_unsaved=False, source=source
            )
            break
    changes = _changes(original, outcome.scene, why_moved, left)
    positions = {k: o.position for k, o in original.items()}
    return KeptHouse(outcome, len(scene.objects), changes, rounds, positions)


def _rounded(position: tuple[float, float, float] | None) -> list[float] | None:
    return None if position is None else [round(v, 4) for v in position]


def _next_support(
    obj: SceneObject,
    objects: dict[str, SceneObject],
    facts: _Facts,
    tried: dict[str, set[str]],
    unsaved: dict[str, str],
) -> tuple[SceneObject, str] | None:
    """Where ``obj`` goes next, and how to say it: restacked on a larger object beside it on
    the same receptacle, else the nearest other receptacle of the same category; each tried
    once, none that is itself unsaved."""
    if obj.support is None or obj.support not in objects:
        return None
    current = objects[obj.support]
    done = tried.setdefault(obj.id, {current.id})
    free = [o for o in objects.values() if o.id not in done and o.id != obj.id]
    free = [o for o in free if o.id not in unsaved]
    stacks = [
        o
        for o in free
        if o.support == current.id and facts.area[o.id] >= facts.area[obj.id] and o.quat is None
    ]
    kind = facts.category[current.id]
    others = [o for o in free if facts.category.get(o.id) == kind]
    for group, how in ((stacks, "restacked on {}"), (others, "moved to {}, another " + kind)):
        if group:
            best = min(group, key=lambda o: (math.dist(o.position[:2], obj.position[:2]), o.id))
            done.add(best.id)
            return best, how.format(best.id)
    return None


@dataclass(frozen=True)
class _Facts:
    """Per object: its asset's category and its footprint area (scaled)."""

    category: dict[str, str]
    area: dict[str, float]

    @classmethod
    def of(cls, scene: SceneSpec, library: AssetLibrary) -> _Facts:
        metas = {o.id: library.get(o.asset).meta for o in scene.objects}
        return cls(
            {k: m.category for k, m in metas.items()},
            {
                o.id: metas[o.id].size[0] * o.scale3[0] * metas[o.id].size[1] * o.scale3[1]
                for o in scene.objects
            },
        )


def _follows_parent(obj: SceneObject, why: str, unsaved: dict[str, str]) -> bool:
    """An object unsaved only because its receptacle was: it goes where that one goes."""
    return why.startswith("rests on ") and obj.support in unsaved


def _onto(obj: SceneObject, parent: SceneObject, target: SceneObject) -> SceneObject:
    """``obj`` over the centre of ``target`` (the drops look for the free spot nearest to it),
    as high above it as it was above ``parent``."""
    above = obj.position[2] - parent.position[2]
    tx, ty, tz = target.position
    return obj.model_copy(
        update={"support": target.id, "position": (tx, ty, tz + above), "room": target.room}
    )


def _carried(
    objects: list[SceneObject], moved: dict[str, SceneObject], left: dict[str, str]
) -> list[SceneObject]:
    """``objects`` with the moved ones in their new place, what rests on them carried along
    (by the same shift), and without what was left out or rests on it."""
    before = {o.id: o.position for o in objects}
    shift = {k: _minus(v.position, before[k]) for k, v in moved.items()}
    result = []
    for obj in objects:
        if obj.id in moved:
            result.append(moved[obj.id])
            continue
        delta = _inherited(obj, objects, shift)
        if delta is not None:
            x, y, z = obj.position
            obj = obj.model_copy(update={"position": (x + delta[0], y + delta[1], z + delta[2])})
        result.append(obj)
    return _without_orphans([o for o in result if o.id not in left], left)


def _minus(
    a: tuple[float, float, float], b: tuple[float, float, float]
) -> tuple[float, float, float]:
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def _inherited(
    obj: SceneObject, objects: list[SceneObject], shift: dict[str, tuple[float, float, float]]
) -> tuple[float, float, float] | None:
    """The shift of the nearest moved ancestor of ``obj`` (None when none moved)."""
    parents = {o.id: o.support for o in objects}
    seen = {obj.id}
    support = obj.support
    while support is not None and support not in seen:
        if support in shift:
            return shift[support]
        seen.add(support)
        support = parents.get(support)
    return None


def _without_orphans(objects: list[SceneObject], left: dict[str, str]) -> list[SceneObject]:
    """``objects`` less those resting (directly or not) on one left out, each recorded."""
    changed = True
    while changed:
        changed = False
        kept = []
        for obj in objects:
            if obj.support is not None and obj.support in left:
                left[obj.id] = f"rests on {obj.support}, which was left out"
                changed = True
            else:
                kept.append(obj)
        objects = kept
    return objects


def _changes(
    original: dict[str, SceneObject],
    final: SceneSpec,
    why_moved: dict[str, str],
    left: dict[str, str],
) -> list[dict[str, Any]]:
    written = {o.id: o for o in final.objects}
    records = []
    for object_id, obj in original.items():
        if object_id in left:
            records.append(_record(obj, None, "left_out", left[object_id]))
        elif object_id in why_moved and object_id in written:
            records.append(_record(obj, written[object_id], "relocated", why_moved[object_id]))
    return records


def _record(
    before: SceneObject, after: SceneObject | None, change: str, why: str
) -> dict[str, Any]:
    def place(obj: SceneObject) -> dict[str, Any]:
        return {
            "support": obj.support if obj.support is not None else FLOOR,
            "room": obj.room,
            "position": [round(v, 4) for v in obj.position],
        }

    return {
        "object": before.id,
        "change": change,
        "from": place(before),
        "to": None if after is None else place(after),
        "why": why,
    }
