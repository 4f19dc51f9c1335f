"""The rounds of one refine run (see :mod:`holomj.jobs.refine`): each renders, plans, applies
the edits to a copy, scores it and keeps or rejects it; the run's record for ``refine.json``."""

from __future__ import annotations

import time
from collections.abc import Callable
from pathlib import Path
from typing import Any, Literal

from holomj.errors import HolomjError
from holomj.jobs.refine_measure import Measure, RefineContext
from holomj.spec.edit import EditReport

REFINE_DIR = "refine"


REFINE_SCHEMA_VERSION = "1.0"


MAX_PROBLEMS = 20


Planner = Literal["offline", "llm"]


class RefineRun:
    """The rounds of one refine run; :meth:`go` runs them."""

    def __init__(
        self,
        context: RefineContext,
        folder: Path,
        work: Path,
        rounds: int,
        planner: Planner,
        chat: Any,
        seed: int,
        library_path: Path | None,
        max_ops: int,
        render: tuple[bool, int, int],
        log: Callable[[str], None],
    ) -> None:
        self.context, self.source, self.work = context, folder, work
        self.max_rounds, self.planner, self.chat = rounds, planner, chat
        self.seed, self.library_path, self.max_ops = seed, library_path, max_ops
        self.render, self.width, self.height = render
        self.log = log
        self.current = folder
        self.summary = context.summary
        self.measures: list[Measure] = []
        self.rounds: list[dict[str, Any]] = []
        self.images: dict[str, bytes] = {}
        self.tried: set[str] = set()
        self.solo = False  # after a rejected round of several edits: one edit per round
        self.feedback: list[str] = []
        self.stopped = ""

    def go(self) -> None:
        """Measure the scene, then run rounds until the checks hold, nothing new is proposed or
        the rounds are spent."""
        before = self.context.measure(self.current)
        self.measures.append(before)
        self.log(f"before: score {before.score['score']:.4f}, " + _checks_line(before.checks))
        understood = bool(self.context.instruction.items)
        for number in range(1, self.max_rounds + 1):
            done = all(c["held"] for c in before.checks) and not before.findings and before.valid
            ask_anyway = self.chat is not None and not understood and number == 1
            if done and not ask_anyway:
                self.stopped = "the instruction's checks all hold and nothing else to fix"
                if not understood:
                    self.stopped = "the instruction names nothing the offline planner can do"
                break
            row = self.round(number, before)
            self.rounds.append(row)
            if row["decision"] == "kept":
                before = self.measures[-1]
            if row["decision"] in ("no operations", "planner failed"):
                self.stopped = row["reasons"][-1]
                break
        else:
            self.stopped = f"{self.max_rounds} round(s) done"
        if not self.stopped:
            self.stopped = "done"
        self.log(f"stopped: {self.stopped}")

    def round(self, number: int, before: Measure) -> dict[str, Any]:
        """One round (see :mod:`holomj.jobs.refine`): its row for ``refine.json``."""
        from holomj.jobs.edit import apply_edits

        start = time.perf_counter()
        timings: dict[str, float] = {}
        row: dict[str, Any] = {"round": number, "planner": self.planner}
        views = self._views(number, before, row, timings) if self.render else []
        clock = time.perf_counter()
        try:
            operations, refused = self._plan(number, self.summary, before, views, row)
        except HolomjError as err:
            timings["plan"] = round(time.perf_counter() - clock, 3)
            row = _ended(row, timings, start, before, "planner failed", err.one_line(), [])
            record = getattr(err, "record", None)
            if isinstance(record, dict):
                row["llm"] = record
            self.log(f"round {number}: planner failed: {err.one_line()}")
            return row
        timings["plan"] = round(time.perf_counter() - clock, 3)
        row["operations"] = operations
        if refused:
            row["refused_by_checks"] = refused
        if not operations:
            self.log(f"round {number}: nothing (new) to do")
            reason = "the planner proposed nothing (new) to do"
            return _ended(row, timings, start, before, "no operations", reason)
        self.log(f"round {number}: {len(operations)} operation(s)")
        clock = time.perf_counter()
        folder = self.work / f"round_{number}"
        try:
            report = apply_edits(
                self.current,
                operations,
                out=folder,
                seed=self.seed,
                library_path=self.library_path,
                overwrite=True,
                log=lambda line: self.log(f"  {line}"),
            )
        except HolomjError as err:
            timings["edit"] = round(time.perf_counter() - clock, 3)
            self.feedback.append(f"round {number}: the edit failed: {err.one_line()}")
            reason = f"the edit failed: {err.one_line()}"
            return _ended(row, timings, start, before, "rejected", reason)
        timings["edit"] = round(time.perf_counter() - clock, 3)
        self._judge(number, before, folder, operations, report, row, timings)
        timings["total"] = round(time.perf_counter() - start, 3)
        row["timings"] = timings
        self.log(
            f"round {number}: {row['decision']} ({'; '.join(row['reasons'])}) "
            f"in {timings['total']:.1f} s"
        )
        return row

    def _views(
        self, number: int, before: Measure, row: dict[str, Any], timings: dict[str, float]
    ) -> list[tuple[str, bytes]]:
        """The round's views (caption, PNG), kept for ``refine/round_<n>/``; none when
        rendering fails (the round goes on without images)."""
        from holomj.jobs.refine_views import render_views

        shown = render_views(
            self.current, self._rooms(before), width=self.width, height=self.height
        )
        timings["render"] = shown.seconds
        views = []
        for name, png in shown.images.items():
            self.images[f"{REFINE_DIR}/round_{number}/{name}"] = png
            views.append((shown.captions.get(name, name), png))
        row["images"] = [f"{REFINE_DIR}/round_{number}/{n}" for n in shown.images]
        if shown.error:
            row["render_error"] = shown.error
            self.log(f"round {number}: render failed ({shown.error}); going on without images")
        return views

    def _judge(
        self,
        number: int,
        before: Measure,
        folder: Path,
        operations: list[dict[str, Any]],
        report: EditReport,
        row: dict[str, Any],
        timings: dict[str, float],
    ) -> None:
        """Score the edited copy and keep it (it becomes the current scene) or reject it."""
        from holomj.jobs.refine_views import scene_summary
        from holomj.refinement.goals import not_worse

        row["outcomes"] = [
            {"index": o.index, "op": o.op, "status": o.status, "reason": o.reason, "added": o.added}
            for o in report.operations
        ]
        row["validation"] = report.validation
        after = self.context.measure(folder)
        timings["eval"] = round(after.seconds, 3)
        reasons = [f"{report.applied}/{len(report.operations)} operation(s) applied"]
        valid = bool(report.validation and report.validation.get("ok"))
        reasons.append(
            "the edited scene validates" if valid else "the edited scene does NOT validate"
        )
        better = not_worse(after.score["score"], before.score["score"])
        change = _score_change(before.score, after.score)
        reasons.append(
            f"score {before.score['score']:.4f} -> {after.score['score']:.4f}"
            + (" (not worse)" if better else f" (worse: {change})")
        )
        kept = report.applied > 0 and valid and better
        row.update(
            decision="kept" if kept else "rejected",
            reasons=reasons,
            score_before=before.score["score"],
            score_after=after.score["score"],
            before=before.to_json(),
            after=after.to_json(),
        )
        for outcome in report.operations:
            if outcome.status == "refused":
                self.feedback.append(
                    f"round {number}: operation {outcome.index} ({outcome.op}) refused by the "
                    f"edit: {outcome.reason}"
                )
        if kept:
            self.current = folder
            self.measures.append(after)
            self.summary = scene_summary(folder)
            self.solo = False
        else:
            self.feedback.append(f"round {number} was rejected: {'; '.join(reasons)}")
            self._retry_alone(operations, report)

    def _retry_alone(self, operations: list[dict[str, Any]], report: EditReport) -> None:
        """After a rejected round of several applied edits, which of them made it worse is
        not known: they may be proposed again, one per round."""
        from holomj.refinement.offline import signature

        applied = [op for op, o in zip(operations, report.operations) if o.status == "applied"]
        if len(applied) > 1 and not self.solo:
            self.solo = True
            for op in applied:
                self.tried.discard(signature(op))

    def _plan(
        self,
        number: int,
        summary: Any,
        before: Measure,
        views: list[tuple[str, bytes]],
        row: dict[str, Any],
    ) -> tuple[list[dict[str, Any]], list[dict[str, Any]]]:
        if self.chat is None:
            from holomj.refinement.offline import propose

            proposal = propose(
                self.context.instruction,
                summary,
                before.checks,
                before.findings,
                self.tried,
                max_ops=1 if self.solo else self.max_ops,
            )
            row["why"] = proposal.reasons
            return proposal.operations, []
        from holomj.refinement.llm import propose as ask_model

        problems = [f"{metric}: {what}" for metric, what in before.report.problems()]
        problems += [finding.line() for finding in before.findings]
        feedback, self.feedback = self.feedback, []
        answer = ask_model(
            self.chat,
            self.context.instruction,
            summary,
            before.checks,
            problems[:MAX_PROBLEMS],
            feedback,
            views,
            round_number=number,
            rounds=self.max_rounds,
            max_ops=self.max_ops,
        )
        row["llm"] = answer.record
        if answer.renamed:
            row["renamed_ids"] = answer.renamed
        for refused in answer.refused:
            self.feedback.append(
                f"round {number}: operation {refused['index']} ({refused['op']}) refused: "
                f"{refused['reason']}"
            )
        return answer.operations, answer.refused

    def _rooms(self, before: Measure) -> list[str]:
        rooms = list(self.context.instruction.rooms)
        for finding in before.findings:
            obj = self.summary.object(finding.object)
            if obj is not None and obj.room and obj.room not in rooms:
                rooms.append(obj.room)
        return rooms or [r.id for r in self.summary.rooms]

    def record(self, text: str, target: Path, seconds: float) -> dict[str, Any]:
        """The run's record, as ``refine.json`` holds it."""
        first, last = self.measures[0], self.measures[-1]
        times = [r["timings"]["total"] for r in self.rounds if "timings" in r]
        usage = [r["llm"] for r in self.rounds if isinstance(r.get("llm"), dict)]
        record: dict[str, Any] = {
            "schema_version": REFINE_SCHEMA_VERSION,
            "source": str(self.source),
            "output": str(target),
            "instruction": self.context.instruction.to_json(),
            "planner": self.planner,
            "seed": self.seed,
            "score": {
                "definition": "mean of the measured holomj eval scores and of the instruction's "
                "checks (1 met, 0 not); a round is kept when the edited scene validates and "
                "the score does not fall",
                "before": first.score["score"],
                "after": last.score["score"],
            },
            "before": first.to_json(),
            "after": last.to_json(),
            "rounds": self.rounds,
            "kept": sum(1 for r in self.rounds if r["decision"] == "kept"),
            "stopped": self.stopped,
            "ok": last.valid
            and all(c["held"] for c in last.checks)
            and (bool(last.checks) or any(r["decision"] == "kept" for r in self.rounds)),
            "seconds": round(seconds, 3),
            "seconds_per_round": round(sum(times) / len(times), 3) if times else 0.0,
        }
        if self.chat is not None:
            record["llm"] = {
                "model": self.chat.config.model,
                "endpoint": self.chat.config.endpoint,
                "images": self.chat.images,
                "text_only_reason": self.chat.text_only_reason,
                "calls": sum(u.get("calls", 0) for u in usage),
                "prompt_tokens": sum(u.get("prompt_tokens", 0) for u in usage),
                "completion_tokens": sum(u.get("completion_tokens", 0) for u in usage),
                "images_sent": sum(u.get("images", 0) for u in usage),
                "seconds": round(sum(u.get("seconds", 0.0) for u in usage), 3),
            }
        if self.current != self.source:
            record["stale_files"] = [
                n for n in ("renders", "report.html") if (self.current / n).exists()
            ]
        return record


def _ended(
    row: dict[str, Any],
    timings: dict[str, float],
    start: float,
    before: Measure,
    decision: str,
    reason: str,
    operations: list[dict[str, Any]] | None = None,
) -> dict[str, Any]:
    """A round's row when it ends before the edited scene is scored."""
    timings["total"] = round(time.perf_counter() - start, 3)
    row.update(decision=decision, reasons=[reason])
    if operations is not None:
        row["operations"] = operations
    row.update(timings=timings, score_before=before.score["score"])
    return row


def _checks_line(checks: list[dict[str, Any]]) -> str:
    met = sum(1 for c in checks if c["held"])
    return f"instruction {met}/{len(checks)} checks met"


def _score_change(before: dict[str, Any], after: dict[str, Any]) -> str:
    """The metrics that fell, and the instruction's checks."""
    parts = []
    for key, value in before.get("metrics", {}).items():
        new = after.get("metrics", {}).get(key)
        if new is not None and new < value - 1e-9:
            parts.append(f"{key} {value:.3f} -> {new:.3f}")
    met_before, met_after = before["instruction_met"][0], after["instruction_met"][0]
    if met_after < met_before:
        parts.append(f"instruction checks {met_before} -> {met_after}")
    return ", ".join(parts) or "rounding"
