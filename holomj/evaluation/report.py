"""The evaluation report: every metric of a scene folder, a ``scores`` summary and details.

``scores`` holds one entry per metric, each ``{"score": 0..1 or null, "ok": bool or null,
"summary": text, ...numbers}``; ``score`` is the share that holds (null: not measured, e.g. no
plan or spec to count against), ``ok`` whether the metric passes its threshold:

| metric | score | ok when |
|---|---|---|
| counts | requested rooms, room types and object counts met / asked | all met |
| attributes | colour / material / shape specs met / asked | all met |
| relations | relations met / asked | all met |
| absent | things the annotation excludes that are absent / excluded | all absent |
| defining | typed rooms holding their defining furniture / typed rooms | all |
| collisions | objects in no collider pair deeper than 1 mm / objects | no such pair |
| outside | objects inside their room (5 cm) / objects | none outside |
| support | objects resting on something plausible / objects | all plausible |
| navigability | free floor a 0.2 m robot reaches from the entrance | >= 95 % and every room |
| front_access | front-used furniture whose front the robot reaches / such furniture | all |
| doors_clear | doors with a clear 1 m zone each side (open connections: 0.9 m passage) | all |
| windows_clear | windows with nothing in front / windows | all |
| stability | objects the validation report calls stable / objects | the report is ok |

``overall`` is the mean of the measured scores.
"""

from __future__ import annotations

import time
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

from holomj.evaluation.access import front_access
from holomj.evaluation.collisions import collision_summary
from holomj.evaluation.fidelity import Scorer
from holomj.evaluation.folder import MeasuredFolder
from holomj.evaluation.openings import OPEN_PASSAGE_M, door_clearance, window_clearance
from holomj.evaluation.outside import outside_rooms
from holomj.evaluation.reachability import ReachGrid, reach_summary, robot_reach
from holomj.evaluation.stability import stability_summary
from holomj.evaluation.support import supports
from holomj.evaluation.vocabulary import Vocabulary
from holomj.spec.report import PenetrationPair

EVAL_SCHEMA_VERSION = "1.0"
NAV_OK_SHARE = 0.95
COLLISION_TOLERANCE_M = 0.001
METRICS = (
    "counts",
    "attributes",
    "relations",
    "absent",
    "defining",
    "collisions",
    "outside",
    "support",
    "navigability",
    "front_access",
    "doors_clear",
    "windows_clear",
    "stability",
)


@dataclass
class EvalReport:
    """What ``holomj eval`` measured: ``scores`` (one entry per metric, see the module
    docstring), ``details`` (per item), what it was measured against, notes and timings."""

    folder: str
    against: dict[str, Any]
    scores: dict[str, dict[str, Any]]
    details: dict[str, Any]
    notes: list[str] = field(default_factory=list)
    timings: dict[str, float] = field(default_factory=dict)
    n_objects: int = 0
    rooms: list[dict[str, Any]] = field(default_factory=list)

    @property
    def overall(self) -> float | None:
        """The mean of the measured scores (None when nothing was measured)."""
        values = [s["score"] for s in self.scores.values() if s.get("score") is not None]
        return round(sum(values) / len(values), 4) if values else None

    def problems(self) -> list[tuple[str, str]]:
        """Every failed item as ``(metric, what failed)``, metric by metric."""
        d = self.details
        out: list[tuple[str, str]] = []
        for key in ("counts", "attributes", "relations", "absent", "defining"):
            out += [(key, r["reason"]) for r in d.get(key, []) if not r["held"]]
        pairs = d.get("collisions", {}).get("pairs") or []
        out += [("collisions", f"{p['a']} / {p['b']}: {p['depth_mm']:.1f} mm") for p in pairs]
        out += [("outside", f"{o['id']}: {o['reason']}") for o in d.get("outside", [])]
        out += [
            ("support", f"{s['id']}: {s['reason']}")
            for s in d.get("support", [])
            if not s["plausible"]
        ]
        unreached = d.get("navigability", {}).get("rooms_unreached", [])
        out += [("navigability", f"room {r} not reachable") for r in unreached]
        out += [
            ("front_access", f"{r['id']}: {r['reason']}")
            for r in d.get("front_access", [])
            if not r["held"]
        ]
        for key, name in (("doors", "door"), ("windows", "window")):
            out += [
                (key, f"{r[name]}: {', '.join(r['blocking'])}")
                for r in d.get(key, [])
                if not r["clear"]
            ]
        unstable = d.get("stability", {}).get("unstable") or []
        out += [("stability", f"{u['id']}: {'; '.join(u['reasons'])}") for u in unstable]
        return out

    def to_json(self) -> dict[str, Any]:
        """The report as JSON data (what ``--json`` writes)."""
        return {
            "schema_version": EVAL_SCHEMA_VERSION,
            "folder": self.folder,
            "against": self.against,
            "n_objects": self.n_objects,
            "rooms": self.rooms,
            "overall": self.overall,
            "scores": self.scores,
            "details": self.details,
            "notes": self.notes,
            "timings": self.timings,
        }


def _share(held: int, total: int, what: str, **extra: Any) -> dict[str, Any]:
    if total == 0:
        summary = "nothing to measure"
        return {"score": None, "ok": None, "held": 0, "total": 0, "summary": summary, **extra}
    return {
        "score": round(held / total, 4),
        "ok": held == total,
        "held": held,
        "total": total,
        "summary": f"{held}/{total} {what}",
        **extra,
    }


def _rows(rows: list[dict[str, Any]], what: str) -> dict[str, Any]:
    return _share(sum(1 for r in rows if r["held"]), len(rows), what)


def evaluate_scene(
    scene: MeasuredFolder,
    spec: dict[str, Any] | None,
    *,
    vocab: Vocabulary | None = None,
    against: dict[str, Any] | None = None,
    penetrations: Sequence[PenetrationPair] | None = None,
    stability_report: dict[str, Any] | None = None,
    stability_source: str = "report.json",
    notes: Sequence[str] = (),
) -> EvalReport:
    """Measure ``scene`` (see the module docstring). ``spec``: the annotation to count against
    (None: no counts, attributes or relations); ``penetrations``: the audit's pairs at t = 0
    (None: collisions not measured); ``stability_report``: the validation report as JSON data."""
    vocab = vocab or Vocabulary.load()
    notes = list(notes)
    if not scene.objects_json:
        notes.append("no objects.json: no objects measured (recompile the folder)")
    scores: dict[str, dict[str, Any]] = {}
    details: dict[str, Any] = {}
    timings: dict[str, float] = {}
    clock = time.perf_counter()

    def lap(name: str) -> None:
        nonlocal clock
        now = time.perf_counter()
        timings[name] = round(now - clock, 3)
        clock = now

    _fidelity(Scorer(scene.folder, spec or {}, vocab, scene=scene), spec, scores, details, notes)
    lap("fidelity")

    details["collisions"] = collision_summary(
        penetrations, [o.id for o in scene.objects], COLLISION_TOLERANCE_M
    )
    scores["collisions"] = _collision_score(details["collisions"], len(scene.objects))
    outside, checked = outside_rooms(scene)
    details["outside"] = outside
    scores["outside"] = _share(checked - len(outside), checked, "objects inside their room")
    lap("collisions_outside")

    rests = supports(scene, vocab)
    details["support"] = [s.to_json() for s in rests]
    bad = [s for s in rests if not s.plausible]
    scores["support"] = _share(len(rests) - len(bad), len(rests), "objects plausibly supported")
    if bad:
        scores["support"]["implausible"] = [f"{s.id}: {s.reason}" for s in bad[:8]]
    lap("support")

    grid = robot_reach(scene)
    details["navigability"], scores["navigability"] = _navigability(grid)
    lap("navigability")

    _access(scene, vocab, grid, {s.id: s.rests_on for s in rests}, scores, details)
    lap("access_openings")

    details["stability"] = stability_summary(stability_report, stability_source)
    scores["stability"] = _stability_score(details["stability"])
    return EvalReport(
        folder=str(scene.folder),
        against=against or {"source": None},
        scores={k: scores[k] for k in METRICS if k in scores},
        details=details,
        notes=notes,
        timings=timings,
        n_objects=len(scene.objects),
        rooms=[{"id": r.id, "type": r.type, "as": vocab.room_type_of(r)} for r in scene.rooms],
    )


def _fidelity(
    scorer: Scorer,
    spec: dict[str, Any] | None,
    scores: dict[str, dict[str, Any]],
    details: dict[str, Any],
    notes: list[str],
) -> None:
    """Counts, attributes, relations and absent things against ``spec`` (none without one),
    and the typed rooms' defining furniture, into ``scores`` and ``details``."""
    if spec is not None:
        for key, rows, what in (
            ("counts", scorer.counts(), "counts met"),
            ("attributes", scorer.attributes(), "attributes met"),
            ("relations", scorer.relations(), "relations met"),
            ("absent", scorer.absent(), "excluded things absent"),
        ):
            details[key], scores[key] = rows, _rows(rows, what)
        notes += [f"relation not measured: {skipped}" for skipped in spec.get("skipped", [])]
    else:
        for key in ("counts", "attributes", "relations", "absent"):
            scores[key] = {
                "score": None,
                "ok": None,
                "summary": "no plan or spec to measure against",
            }
    details["defining"] = scorer.defining()
    scores["defining"] = _rows(details["defining"], "typed rooms with their defining furniture")


def _access(
    scene: MeasuredFolder,
    vocab: Vocabulary,
    grid: ReachGrid | None,
    resting: dict[str, str | None],
    scores: dict[str, dict[str, Any]],
    details: dict[str, Any],
) -> None:
    """Reachable fronts and clear doors and windows, into ``scores`` and ``details``."""
    details["front_access"] = front_access(scene, vocab, grid, resting)
    scores["front_access"] = _rows(details["front_access"], "fronts reachable")
    details["doors"] = door_clearance(scene, OPEN_PASSAGE_M)
    details["windows"] = window_clearance(scene, vocab)
    doors_clear = sum(1 for d in details["doors"] if d["clear"])
    windows_clear = sum(1 for w in details["windows"] if w["clear"])
    scores["doors_clear"] = _share(doors_clear, len(details["doors"]), "doors clear")
    scores["windows_clear"] = _share(windows_clear, len(details["windows"]), "windows clear")


def _collision_score(collisions: dict[str, Any], n_objects: int) -> dict[str, Any]:
    if collisions["pairs"] is None:
        return {"score": None, "ok": None, "summary": "not audited"}
    hit = len(collisions["objects"])
    pairs = len(collisions["pairs"])
    return {
        "score": round(1 - hit / n_objects, 4) if n_objects else None,
        "ok": not pairs,
        "pairs": pairs,
        "objects": hit,
        "max_depth_mm": collisions["max_depth_mm"],
        "summary": f"{pairs} pair(s) deeper than 1 mm "
        f"({hit} objects, deepest {collisions['max_depth_mm']:.1f} mm)",
    }


def _navigability(grid: ReachGrid | None) -> tuple[dict[str, Any], dict[str, Any]]:
    """(details, score) of the reach from the entrance."""
    if grid is None:
        return {"share": None, "reason": "no rooms"}, {
            "score": None,
            "ok": None,
            "summary": "no rooms",
        }
    nav = reach_summary(grid)
    unreached = [r for r, v in nav["per_room"].items() if not v]
    rooms = len(nav["per_room"])
    nav["rooms_reachable"] = rooms - len(unreached)
    nav["rooms_unreached"] = unreached
    summary = (
        f"{nav['share'] * 100:.1f} % of the free floor reachable, "
        f"{nav['rooms_reachable']}/{rooms} rooms"
    )
    score = {
        "score": nav["share"],
        "ok": nav["share"] >= NAV_OK_SHARE and not unreached and nav["entrance_found"],
        "rooms_reachable": [nav["rooms_reachable"], rooms],
        "summary": summary + ("" if nav["entrance_found"] else " (no entrance found)"),
    }
    return nav, score


def _stability_score(stab: dict[str, Any]) -> dict[str, Any]:
    if stab["ok"] is None:
        return {"score": None, "ok": None, "summary": stab["reason"]}
    total = stab["objects"]
    return {
        "score": round(stab["stable"] / total, 4) if total else None,
        "ok": stab["ok"],
        "stable": stab["stable"],
        "total": total,
        "summary": f"{stab['stable']}/{total} objects stable "
        f"({'ok' if stab['ok'] else 'not ok'}, {stab['source']})",
    }
