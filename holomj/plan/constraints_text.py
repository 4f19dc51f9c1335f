"""Layout constraint lines of an offline plan, written over instance names.

A room template's lines name object kinds (``armchair | near, coffee table``); the floor
planner needs them per instance (``armchair-1 | near, coffee table-0``). Targets are spread over
the target's instances, and parts naming objects the room does not have are left out. An object
the prompt places (``in the corner``) loses the template's place (``edge``, ``middle``).
"""

from __future__ import annotations

from holomj.plan.draft import DraftRoom
from holomj.spec.plan import instance_name

_PLACES = frozenset({"edge", "middle"})


def constraint_lines(room: DraftRoom) -> list[str]:
    """Layout lines per instance: the template's lines for a kind, else the kind's defaults."""
    floor = {o.name: o for o in room.objects if o.floor}
    by_subject: dict[str, list[str]] = {}
    for line in room.lines:
        by_subject.setdefault(line.split("|", 1)[0].strip(), []).append(line)
    placed_by_prompt = {r.subject for r in room.relations if r.target is None}
    out: list[str] = []
    for obj in room.objects:
        if not obj.floor:
            continue
        lines = by_subject.get(obj.name) or obj.kind.constraints
        segments = [seg.strip() for line in lines for seg in line.split("|")[1:]]
        if obj.name in placed_by_prompt:  # the prompt says where: no default place
            segments = [seg for seg in segments if seg.split(",")[0].strip() not in _PLACES]
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
