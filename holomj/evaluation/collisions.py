"""Colliding pairs: the penetration audit of the compiled scene at t = 0
(:mod:`holomj.physics.audit`, run by the job) says which pairs of objects, floor and structure
interpenetrate deeper than its tolerance (1 mm); here they are summarised per object."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from holomj.spec.report import PenetrationPair


def collision_summary(
    pairs: Sequence[PenetrationPair] | None, object_ids: Sequence[str], tolerance_m: float
) -> dict[str, Any]:
    """The pairs deeper than ``tolerance_m`` and the objects in at least one of them."""
    if pairs is None:
        return {"pairs": None, "objects": None, "reason": "no audit"}
    known = set(object_ids)
    deep = [p for p in pairs if p.depth_m > tolerance_m]
    involved = sorted({n for p in deep for n in (p.a, p.b) if n in known})
    return {
        "tolerance_m": tolerance_m,
        "pairs": [
            {
                "a": p.a,
                "b": p.b,
                "depth_mm": round(p.depth_m * 1000, 2),
                "geoms": [p.geom_a, p.geom_b],
            }
            for p in deep
        ],
        "objects": involved,
        "max_depth_mm": round(max((p.depth_m for p in deep), default=0.0) * 1000, 2),
    }
