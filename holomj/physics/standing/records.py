"""The records making a house stand leaves in ``import_report.json``: separations, the reasons
of every move, reassigned supports and rooms, penetration counts, the validation verdict."""

from __future__ import annotations

from typing import Any

import numpy as np

from holomj.physics.audit import AuditResult
from holomj.physics.standing.drops import Dropped
from holomj.spec.report import StabilityReport
from holomj.spec.scene import SceneSpec

FLOOR = "floor"  # the support of an object that stands on the floor, in the report


def separations(
    first: SceneSpec, second: SceneSpec, why: dict[str, str], walls: dict[str, str]
) -> list[dict[str, Any]]:
    """One record per object ``separate`` moved: from what, and by how much."""
    before = {o.id: np.array(o.position) for o in first.objects}
    records = []
    for obj in second.objects:
        if obj.id not in why:
            continue
        delta = np.array(obj.position) - before[obj.id]
        other = why[obj.id].removeprefix("separated from ")
        if obj.id in walls:
            other = walls[obj.id]
        records.append(
            {
                "object": obj.id,
                "from": other,
                "moved_m": round(float(np.linalg.norm(delta)), 4),
                "translation": [round(float(v), 4) for v in delta],
            }
        )
    return records


def move_reasons(
    prepared: dict[str, list[str]], separated: list[dict[str, Any]], drops: dict[str, Dropped]
) -> dict[str, str]:
    """Per object, why it moved, in order: the first pass, separation, the drop."""
    reasons = {k: [r for r in v if not r.startswith("assigned")] for k, v in prepared.items()}
    for record in separated:
        text = f"moved {record['moved_m'] * 1000:.0f} mm clear of {record['from']}"
        reasons.setdefault(record["object"], []).append(text)
    for object_id, drop in drops.items():
        if drop.accepted:
            reasons.setdefault(object_id, []).append(
                f"dropped onto {drop.onto}"
                + (f" {drop.offset_m * 1000:.0f} mm from its x/y" if drop.offset_m >= 5e-4 else "")
            )
    return {k: "; ".join(v) for k, v in reasons.items() if v}


def reassigned(
    scene: SceneSpec, final: SceneSpec, notes: dict[str, list[str]]
) -> list[dict[str, str]]:
    """Objects whose support or room changed, with the new value and the note saying why."""
    imported = {o.id: o for o in scene.objects}
    records = []
    for obj in final.objects:
        old = imported[obj.id]
        for name, prefixes in (
            ("support", ("rests on", "stands on the floor")),
            ("room", ("assigned", "pulled")),
        ):
            value = getattr(obj, name)
            if value != getattr(old, name):
                why = next((n for n in notes.get(obj.id, []) if n.startswith(prefixes)), "")
                shown = value if value is not None else FLOOR
                records.append({"object": obj.id, "field": name, "value": shown, "why": why})
    return records


def penetrations(pairs: list, found: AuditResult | None = None) -> dict[str, Any]:
    """How many penetrating pairs and the deepest (with ``found``: objects below the floor
    and outside their rooms too)."""
    record: dict[str, Any] = {
        "count": len(pairs),
        "max_m": round(max((p.depth_m for p in pairs), default=0.0), 6),
    }
    if found is not None:
        record["below_floor"] = len(found.below_floor)
        record["outside_rooms"] = len(found.outside_rooms)
    return record


def validation_summary(report: StabilityReport) -> dict[str, Any]:
    """The final verdict in numbers."""
    counts = report.counts
    return {
        "ok": report.ok,
        "objects": counts.get("objects", 0),
        "stable": counts.get("stable", 0),
        "unstable": counts.get("unstable", 0),
        "static": counts.get("static", 0),
        "penetrations": counts.get("penetrations", 0),
        "max_penetration_m": report.max_penetration_m,
        "warnings": dict(report.warnings),
        "furniture": report.furniture,
    }
