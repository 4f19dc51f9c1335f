"""Whether the plan's structural relations hold in the finished scene: ``on`` (a small object
on the receptacle the request named), ``above`` (a wall object over a floor object) and
``facing`` between a floor object and a wall object (the line of sight meets it).

The layout relations are judged by the layout itself
(:func:`holomj.layout.relation_constraints.relation_verdicts`); these two are kept by the plan's
structure and judged here, on the scene after the small objects are dropped.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from typing import Any

from holomj.layout.furniture_rules import object_id
from holomj.library.store import AssetLibrary
from holomj.spec.plan import PlanRelation, ScenePlan, instance_name
from holomj.spec.scene import SceneObject, SceneSpec

ABOVE_REACH_M = 0.3  # a wall object's centre at most this far beyond the floor object's side
FACING_SLACK_M = 0.05  # a wall object is looked at when the line of sight passes this close


def structural_verdicts(
    plan: ScenePlan,
    scene: SceneSpec,
    small_records: Iterable[dict[str, Any]],
    library: AssetLibrary,
) -> list[dict[str, Any]]:
    """One verdict per ``on`` / ``above`` relation of the plan."""
    objects = {o.id: o for o in scene.objects}
    placed_on: dict[str, list[str]] = {}
    for record in small_records:
        placed_on.setdefault(record["receptacle"], []).extend(record.get("placed", []))
    out = []
    for room in plan.rooms:
        counts = {o.name: o.quantity for o in room.objects}
        small = {s.name: s for o in room.objects for s in o.on_top}
        walls = {o.name for o in room.objects if o.placement == "wall"}
        for rel in room.relations:
            if (
                rel.kind == "facing"
                and rel.target is not None
                and walls & {rel.subject, rel.target}
            ):
                looker, hung = (
                    (rel.target, rel.subject) if rel.subject in walls else (rel.subject, rel.target)
                )
                held, detail = _looks_at(
                    objects.get(object_id(room.id, instance_name(looker, 0))),
                    objects.get(object_id(room.id, instance_name(hung, 0))),
                    library,
                )
                out.append(_verdict(room.id, rel, held, detail))
                continue
            if rel.kind not in ("on", "above") or rel.target is None:
                continue
            targets = [
                object_id(room.id, instance_name(rel.target, k))
                for k in range(counts.get(rel.target, 0))
            ]
            if rel.kind == "on":
                category = small[rel.subject].category if rel.subject in small else None
                held, detail = _on(targets, placed_on, objects, category, library)
            else:
                subject = objects.get(object_id(room.id, instance_name(rel.subject, 0)))
                held, detail = _above(subject, [objects[t] for t in targets if t in objects])
            out.append(_verdict(room.id, rel, held, detail))
    return out


def _verdict(room: str, rel: PlanRelation, held: bool, detail: str) -> dict[str, Any]:
    return {
        "room": room,
        "subject": rel.subject,
        "relation": rel.kind,
        "target": rel.target,
        "phrase": rel.phrase,
        "constraints": 0,
        "satisfied": int(held),
        "held": held,
        "detail": detail,
    }


def _on(
    receptacles: Sequence[str],
    placed_on: dict[str, list[str]],
    objects: dict[str, SceneObject],
    category: str | None,
    library: AssetLibrary,
) -> tuple[bool, str]:
    for rid in receptacles:
        for oid in placed_on.get(rid, []):
            obj = objects.get(oid)
            if obj is None:
                continue
            if category is None or library.get(obj.asset).meta.category == category:
                return True, f"{oid} rests on {rid}"
    return False, "none was placed on " + (", ".join(receptacles) or "it (not in the scene)")


def _looks_at(
    looker: SceneObject | None, hung: SceneObject | None, library: AssetLibrary
) -> tuple[bool, str]:
    """Whether ``looker``'s front ray meets the wall object ``hung`` (within its width)."""
    if looker is None or hung is None:
        return False, "not both in the scene"
    yaw = math.radians(looker.yaw_deg)
    fx, fy = math.cos(yaw), math.sin(yaw)
    dx, dy = hung.position[0] - looker.position[0], hung.position[1] - looker.position[1]
    ahead = dx * fx + dy * fy
    side = abs(-dx * fy + dy * fx)
    half = library.get(hung.asset).meta.size[1] * hung.scale3[1] / 2
    held = ahead > 0 and side <= half + FACING_SLACK_M
    return held, f"{side:.2f} m beside its line of sight, {ahead:.2f} m ahead"


def _above(subject: SceneObject | None, targets: Sequence[SceneObject]) -> tuple[bool, str]:
    if subject is None:
        return False, "the wall object is not in the scene"
    if not targets:
        return False, "the floor object is not in the scene"
    best = min(math.dist(subject.position[:2], t.position[:2]) for t in targets)
    held = best <= ABOVE_REACH_M + 0.5
    return held, f"{best:.2f} m from the nearest one, seen from above"
