"""Stability, from the validation report (``report.json`` of ``holomj validate``/``generate``/
``compile``): the share of objects the report calls stable, and whether it is ``ok``."""

from __future__ import annotations

from typing import Any


def stability_summary(report: dict[str, Any] | None, source: str) -> dict[str, Any]:
    """The report's verdicts, or why there are none."""
    if not isinstance(report, dict) or not isinstance(report.get("objects"), list):
        return {
            "source": None,
            "ok": None,
            "stable": None,
            "objects": None,
            "reason": "no report.json: run 'holomj validate OUT --json OUT/report.json', "
            "or eval with --validate",
        }
    objects = [o for o in report["objects"] if isinstance(o, dict)]
    unstable = [
        {"id": o.get("name") or o.get("id"), "reasons": o.get("reasons", [])}
        for o in objects
        if not o.get("stable", True)
    ]
    return {
        "source": source,
        "ok": bool(report.get("ok")),
        "stable": len(objects) - len(unstable),
        "objects": len(objects),
        "static_objects": len(report.get("static_objects", [])),
        "furniture": report.get("furniture"),
        "unstable": unstable,
        "penetrations": len(report.get("penetrations", [])),
        "warnings": report.get("warnings", {}),
    }
