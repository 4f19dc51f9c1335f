"""What a refine run measures: the fixed inputs (the instruction read against the scene, the
plan's and the instruction's annotations) and one scene's measure (eval scores, the
instruction's checks, the refine score, findings, validity)."""

from __future__ import annotations

import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from holomj.evaluation.report import EvalReport
from holomj.refinement.finding import Finding


@dataclass
class Measure:
    """One scene measured: the eval report, the instruction's checks, the refine score, the
    findings to fix, whether it validates, and the seconds it took."""

    report: EvalReport
    checks: list[dict[str, Any]]
    score: dict[str, Any]
    findings: list[Finding]
    valid: bool
    seconds: float

    def to_json(self) -> dict[str, Any]:
        """The measure as ``refine.json`` logs it."""
        return {
            **self.score,
            "valid": self.valid,
            "checks": self.checks,
            "findings": [f.to_json() for f in self.findings],
            "seconds": round(self.seconds, 3),
        }


class RefineContext:
    """The fixed inputs of a refine run: the instruction and the two annotations."""

    def __init__(self, folder: Path, text: str) -> None:
        from holomj.evaluation.plan_spec import spec_from_plan
        from holomj.evaluation.vocabulary import Vocabulary
        from holomj.jobs.eval import read_plan
        from holomj.jobs.refine_views import scene_summary
        from holomj.refinement.goals import adjust_plan_spec, instruction_spec
        from holomj.refinement.instruction import read_instruction

        self.summary = scene_summary(folder)
        self.instruction = read_instruction(text, self.summary)
        self.vocab = Vocabulary.load()
        plan = read_plan(folder)
        plan_spec = spec_from_plan(plan, self.vocab, own=True) if plan is not None else None
        self.plan_spec = adjust_plan_spec(plan_spec, self.instruction)
        self.spec = instruction_spec(self.instruction, self.summary)

    def measure(self, folder: Path) -> Measure:
        """Evaluate the scene in ``folder`` against the plan and the instruction."""
        from holomj.evaluation.fidelity import Scorer
        from holomj.file_names import REPORT_JSON
        from holomj.jobs.eval import evaluate
        from holomj.jobs.folder import read_json_report
        from holomj.jobs.refine_findings import findings
        from holomj.refinement.goals import instruction_checks, refine_score

        start = time.perf_counter()
        report = evaluate(folder, spec=self.plan_spec) if self.plan_spec else evaluate(folder)
        scorer = Scorer(folder, self.spec, self.vocab)
        checks = instruction_checks([*scorer.counts(), *scorer.relations()])
        stability = read_json_report(folder, REPORT_JSON)
        valid = bool(stability.get("ok")) if isinstance(stability, dict) else False
        return Measure(
            report=report,
            checks=checks,
            score=refine_score(report.scores, checks),
            findings=findings(report),
            valid=valid,
            seconds=time.perf_counter() - start,
        )
