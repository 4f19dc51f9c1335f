"""``generate``: a prompt in, a validated scene folder out.

Every check runs first, once (:func:`check_request`: the prompt, each option, the robot, the
output folder), then the stages run in a straight line, each taking what the ones before
returned (:mod:`holomj.jobs.generate_stages`, each timed in the log): plan (offline knowledge
base, or an LLM with the offline planner as fallback) -> retrieve -> compose (floor plan, doors,
windows, materials, furniture, wall objects: :mod:`holomj.compose`) -> small objects (chosen by
:mod:`holomj.compose.small_objects`, spawn-and-drop on top of receptacles, and inside
articulated storage with ``GenerateOptions.inside``) -> compile -> validate -> export (atomic;
the render, optional, runs on the folder before it is renamed into place: a failed render is
recorded and leaves the scene intact). The scene is compiled once: validation, export and render
use that model in memory.

``OUT`` receives ``scene.xml``, ``assets/``, ``scene.json``, ``plan.json``, ``report.json`` (the
validation report, as ``holomj validate`` writes it), ``generate.json`` (what every stage chose
and why, timings, the render's outcome) and ``generate.log`` (one line per event), all in one
atomic write.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

from holomj.compose.house import scene_name
from holomj.jobs import generate_stages as stages
from holomj.jobs.generate_options import (
    FURNITURE_MODES,
    MAX_PROMPT_CHARS,
    CheckedRequest,
    GenerateOptions,
    check_request,
)
from holomj.jobs.stage_log import Listener, StageLog
from holomj.spec.plan import ScenePlan
from holomj.spec.report import StabilityReport

__all__ = [
    "FURNITURE_MODES",
    "MAX_PROMPT_CHARS",
    "CheckedRequest",
    "GenerateOptions",
    "GenerateResult",
    "check_request",
    "generate_scene",
    "scene_name",
]


@dataclass
class GenerateResult:
    """What ``generate`` made: the folder, the plan, the validation report, the record."""

    out: Path
    plan: ScenePlan
    report: StabilityReport
    record: dict[str, Any]

    @property
    def folder(self) -> Path:
        """The scene folder written."""
        return self.out

    @property
    def ok(self) -> bool:
        """The scene validated ok."""
        return self.report.ok

    @property
    def render_error(self) -> str | None:
        """Why the render stage failed (None when it succeeded or did not run)."""
        outcome = self.record.get("render")
        return None if not outcome or outcome.get("ok") else str(outcome.get("error"))

    @property
    def timings(self) -> dict[str, float]:
        """Wall time per stage in seconds (as in ``generate.json``)."""
        timings: dict[str, float] = self.record["timings_s"]
        return timings

    def summary(self) -> dict[str, Any]:
        """Short JSON-able summary for the CLI."""
        counts = self.record["counts"]
        return {
            "output": str(self.out),
            "ok": self.report.ok,
            "scene_type": self.plan.scene_type,
            "planner": self.plan.planner,
            "rooms": len(self.plan.rooms),
            "objects": counts,
            "unstable": self.report.counts.get("unstable", 0),
            "penetrations": self.report.counts.get("penetrations", 0),
            "notes": self.record["notes"],
            "timings_s": self.timings,
        }


def generate_scene(
    prompt: str,
    out: Path,
    options: GenerateOptions,
    *,
    listener: Listener | None = None,
) -> GenerateResult:
    """Run every stage for ``prompt`` and write ``out`` (see the module docstring)."""
    checked = check_request(prompt, out, options)
    log = StageLog(listener)
    library = stages.open_library(options, log)
    plan = stages.plan_stage(prompt, options, library, log)
    retrieved = stages.retrieve_stage(plan, library, options, log)
    house = stages.compose_stage(prompt, plan, retrieved, library, options, log)
    populated = stages.small_objects_stage(house, retrieved, library, options, log)
    compiled = stages.compile_stage(populated.scene, library, checked, options.seed, log)
    report = stages.validate_stage(compiled, library, checked, options, log)
    record = stages.generate_record(prompt, options.seed, library, retrieved, house, populated)
    record = stages.export_stage(checked.out, compiled, house.plan, report, record, options, log)
    return GenerateResult(checked.out.path, house.plan, report, record)
