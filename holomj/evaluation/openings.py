"""Doors and windows kept clear.

A door is clear when no floor-standing object (taller than 5 cm, bottom below 30 cm, not resting
on another) overlaps, by more than 25 cm², the door-wide zone 1 m deep in front of either side.
With ``open_passage_m`` (``holomj eval``: 0.9 m), an open connection between rooms (a wall gap of
kind ``open``, often metres wide) is clear when what stands in its zone leaves a passage at
least that wide along it.
A window is clear when no object (window dressings such as curtains and blinds aside) standing
or hanging in the window-wide zone 0.5 m deep on its room side (overlapping it by more than 25
cm²) hides a quarter or more of the window: the part of the window's width its footprint spans
times the part of the window's height it rises into, over the window's area (a sofa below the
sill or an armchair's back beside it keeps it clear, a wardrobe in front of it does not).
"""

from __future__ import annotations

from typing import Any

import shapely

from holomj.evaluation.folder import MeasuredFolder
from holomj.evaluation.vocabulary import Vocabulary

DOOR_ZONE_DEPTH_M = 1.0
DOOR_OVERLAP_M2 = 0.0025
OPEN_PASSAGE_M = 0.9
WINDOW_ZONE_DEPTH_M = 0.5
WINDOW_OVERLAP_M2 = 0.0025
WINDOW_COVER_SHARE = 0.25


def door_clearance(
    scene: MeasuredFolder, open_passage_m: float | None = None
) -> list[dict[str, Any]]:
    """For each door, the furniture overlapping the 1 m deep zone on either side."""
    out = []
    floor = [o for o in scene.objects if o.is_floor_standing]
    for door in scene.doors:
        blocking = []
        spans = []
        for rid in door.normals:
            zone = door.zone(rid, DOOR_ZONE_DEPTH_M).intersection(scene.room_by_id[rid].poly)
            for o in floor:
                cover = o.fp.intersection(zone)
                if cover.area > DOOR_OVERLAP_M2:
                    blocking.append(f"{o.id} ({rid} side, {cover.area:.2f} m2)")
                    spans.append(_span(cover, door.point, door.along))
        row: dict[str, Any] = {"door": door.id, "clear": not blocking, "blocking": blocking}
        if open_passage_m is not None and door.style == "open":
            passage = _widest_gap(spans, door.width)
            row["passage_m"] = round(passage, 3)
            row["clear"] = passage >= open_passage_m
        out.append(row)
    return out


def _widest_gap(spans: list[tuple[float, float]], width: float) -> float:
    """The widest stretch of ``[-width/2, width/2]`` that none of ``spans`` covers."""
    edge, best = -width / 2, 0.0
    for lo, hi in sorted(spans):
        best = max(best, min(lo, width / 2) - edge)
        edge = max(edge, hi)
    return max(best, width / 2 - edge)


def window_clearance(scene: MeasuredFolder, vocab: Vocabulary) -> list[dict[str, Any]]:
    """For each window, the objects standing or hanging in front of it."""
    out = []
    candidates = [
        o
        for o in scene.objects
        if not (o.labels & vocab.window_dressing) and not (o.labels & vocab.floor_like)
    ]
    for window in scene.windows:
        blocking = []
        top = window.base + window.height
        for rid in window.normals:
            zone = window.zone(rid, WINDOW_ZONE_DEPTH_M).intersection(scene.room_by_id[rid].poly)
            for o in candidates:
                if o.room is not None and o.room != rid:
                    continue
                rise = min(o.zmax, top) - max(o.zmin, window.base)
                if rise <= 0:
                    continue
                cover = o.fp.intersection(zone)
                if cover.area <= WINDOW_OVERLAP_M2:
                    continue
                lo, hi = _span(cover, window.point, window.along)
                span = min(hi, window.width / 2) - max(lo, -window.width / 2)
                hidden = max(span, 0.0) * rise / (window.width * window.height)
                if hidden >= WINDOW_COVER_SHARE:
                    blocking.append(
                        f"{o.id} ({rid} side, hides {hidden * 100:.0f} % of it: "
                        f"{span:.2f} m of its {window.width:.2f} m width, "
                        f"{rise:.2f} m of its {window.height:.2f} m height)"
                    )
        out.append({"window": window.id, "clear": not blocking, "blocking": blocking})
    return out


def _span(geom: Any, point: tuple[float, float], axis: tuple[float, float]) -> tuple[float, float]:
    coords = shapely.get_coordinates(geom)
    values = (coords[:, 0] - point[0]) * axis[0] + (coords[:, 1] - point[1]) * axis[1]
    return float(values.min()), float(values.max())
