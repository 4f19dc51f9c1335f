"""Layout constraint lines of an offline plan, written over instance names.

A room template's lines name object kinds (``armchair | near, coffee table``); the floor
planner needs them per instance (``armchair-1 | near, coffee table-0``). Targets are spread over
the target's instances, and parts naming objects the room does not have are left out.
"""

from __future__ import annotations

from holomj.plan.draft import DraftRoom
from holomj.spec.plan import instance_name


def constraint_lines(room: DraftRoom) -> list[str]:
    """Layout lines per instance: the template's lines for a kind, else the kind's defaults."""
    floor = {o.name: o for o in room.objects if o.floor}
    by_subject: dict[str, list[str]] = {}
    for line in room.lines:
        by_subject.setdefault(line.split("|", 1)[0].strip(), []).append(line)
    out: list[str] = []
    for obj in room.objects:
        if not obj.floor:
            continue
        lines = by_subject.get(obj.name) or obj.kind.constraints
        segments = [seg.strip() for line in lines for seg in line.split("|")[1:]]
        for k in range(obj.quantity):
            parts: list[str] = []
            for segment in segments:
                phrase, _, target = (p.strip() for p in segment.partition(","))
                if target:
                    other = floor.get(target)
                    if other is None or other is obj:
                        continue
                    index = k * other.quantity // obj.quantity
                    part = f"{phrase}, {instance_name(target, index)}"
                else:
                    part = phrase
                if part not in parts:
                    parts.append(part)
            if parts:
                out.append(" | ".join([instance_name(obj.name, k), *parts]))
    return out
