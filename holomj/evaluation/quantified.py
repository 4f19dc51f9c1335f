"""A relation judged per subject instance, then quantified: the verdicts of one annotation
relation over the subject's instances (against the room's walls, corners and middle, against its
windows or doors, or against the target's instances), and ``around`` (seats around a table).

The geometric tests are :mod:`holomj.evaluation.relations`'; :class:`~holomj.evaluation.
fidelity.Scorer` finds the instances and calls these.
"""

from __future__ import annotations

import math

from holomj.evaluation import relations as rel_
from holomj.evaluation.folder import MeasuredFolder
from holomj.evaluation.objects import EvaluatedObject
from holomj.evaluation.relations import Verdict

PLACE_RELATIONS = ("against wall", "in corner", "middle")
WALL_WORDS = ("wall", "walls")
OPENING_WORDS = ("window", "windows", "door", "doors", "entrance", "door entrance")
# One instance's verdict: the instance, whether it holds, and why.
PerInstance = tuple[EvaluatedObject, bool, str]


def by_place(
    scene: MeasuredFolder, kind: str, subjects: list[EvaluatedObject]
) -> list[PerInstance]:
    """``kind`` of each subject to the room's walls (a corner, the middle, against, near or next
    to a wall)."""
    per: list[PerInstance] = []
    for s in subjects:
        if kind == "in corner":
            ok, why = rel_.in_corner(scene, s)
        elif kind == "middle":
            ok, why = rel_.middle(scene, s)
        elif kind in ("near", "next to"):
            wall = rel_.wall_side(scene, s)
            dist = wall[0] if wall else math.inf
            limit = rel_.NEAR_M if kind == "near" else rel_.NEXT_TO_M
            ok, why = dist < limit, f"{dist:.2f} m from the nearest wall"
        else:
            ok, why = rel_.against_wall(scene, s)
        per.append((s, ok, why))
    return per


def by_opening(
    scene: MeasuredFolder, kind: str, subjects: list[EvaluatedObject], opening: str
) -> list[PerInstance]:
    """``kind`` of each subject to one of its room's windows (``opening`` a window word) or
    doors."""
    ops = scene.windows if opening.startswith("window") else scene.doors
    per: list[PerInstance] = []
    for s in subjects:
        mine = [op for op in ops if not op.rooms or s.room in op.rooms]
        hit = [op.id for op in mine if rel_.opening_relation(kind, s, op)]
        why = f"{kind} {hit[0]}" if hit else f"{kind} none of {len(mine)} {opening}(s)"
        per.append((s, bool(hit), why))
    return per


def by_object(
    scene: MeasuredFolder,
    kind: str,
    subjects: list[EvaluatedObject],
    objects: list[EvaluatedObject],
    target: str,
) -> list[PerInstance]:
    """``kind`` of each subject to any instance of the target in its room."""
    per: list[PerInstance] = []
    for s in subjects:
        hit = [
            o.id
            for o in objects
            if o.id != s.id and rel_.same_room(s, o) and rel_.pair_relation(scene, kind, s, o)
        ]
        per.append((s, bool(hit), f"with {hit[0]}" if hit else f"with none of {target}"))
    return per


def quantified(per: list[PerInstance], quantifier: str, subject: str) -> Verdict:
    """Whether ``any`` (default), ``all`` or ``most`` of the instances hold, with the first
    reasons."""
    n_ok = sum(1 for _, ok, _ in per if ok)
    need = {"all": len(per), "most": math.ceil(rel_.MOST * len(per))}.get(quantifier, 1)
    detail = "; ".join(f"{s.id}: {why}" for s, _, why in per[:6])
    return Verdict(n_ok >= need, f"{n_ok}/{len(per)} {subject} ({quantifier}): {detail}")


def around(subjects: list[EvaluatedObject], objects: list[EvaluatedObject]) -> Verdict:
    """Seats around a table: most of a table's seats (at least two) within
    :data:`~holomj.evaluation.relations.AROUND_M` of it, on at least two of its sides."""
    best = (0, 0, "")
    for o in objects:
        close = [
            s for s in subjects if rel_.same_room(s, o) and s.fp.distance(o.fp) <= rel_.AROUND_M
        ]
        peers = [s for s in subjects if rel_.same_room(s, o)]
        sides = len(rel_.sides_of(o, close))
        ok = len(close) >= max(2, math.ceil(rel_.MOST * len(peers))) and sides >= 2
        if ok:
            return Verdict(True, f"{len(close)}/{len(peers)} around {o.id} on {sides} sides")
        if len(close) > best[0]:
            best = (len(close), sides, o.id)
    return Verdict(
        False,
        f"at most {best[0]}/{len(subjects)} within {rel_.AROUND_M} m of {best[2] or '-'}",
    )
