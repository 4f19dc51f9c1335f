"""The refine job (``holomj refine OUT --instruction TEXT [--rounds N] [--planner offline|llm]
[-o NEW]``): render, plan edits, apply them to a copy, score, keep what helps.

Before the first round the instruction is read into items (:mod:`holomj.refinement.instruction`)
and measured with the scene's own plan (:mod:`holomj.refinement.goals`: the score is the mean of
the measured ``holomj eval`` scores and of the instruction's checks). Each round:

1. **render** the top view and the rooms the instruction and the problems touch (320 x 240,
   no shadows; in memory, saved under ``refine/round_<n>/``); without OpenGL the round goes on
   without images;
2. **plan**: the offline planner (:mod:`holomj.refinement.offline`) or the vision-language model
   (:mod:`holomj.refinement.llm`: images, summary, checks, problems, feedback and the operations'
   schema; every answer checked by :mod:`holomj.refinement.safety`) proposes edit operations;
3. **apply** them to a copy (:func:`holomj.jobs.edit.apply_edits` into a work folder beside the
   output: only what they touch changes, small objects are dropped, the copy is validated);
4. **score** the copy; **keep** it when at least one operation applied, the copy validates and
   its score is not lower than before; else the round is rejected and the next starts from the
   last kept scene.

Rounds stop early when nothing is left to fix or the planner proposes nothing new. Every round
is logged in ``refine.json`` (operations, their outcomes, scores and checks before and after,
the decision and its reasons, timings, and for the LLM its tokens, images and seconds). The
result (the last kept scene, ``refine.json`` and the round images) is written atomically into
``out`` or back into the folder; a failure leaves nothing half-written and the work folder is
removed.
"""

from __future__ import annotations

import shutil
import tempfile
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Literal

from holomj.atomic import replace_folder
from holomj.errors import ExportError, HolomjError, InputError
from holomj.jobs.folder import dump_json, prepare_output, require_scene_folder
from holomj.seeds import MAX_SEED

REFINE_JSON = "refine.json"
REFINE_DIR = "refine"
MAX_ROUNDS = 20
MAX_INSTRUCTION_CHARS = 2000
REFINE_SCHEMA_VERSION = "1.0"
MAX_PROBLEMS = 20

Planner = Literal["offline", "llm"]


@dataclass
class RefineResult:
    """What :func:`refine` did: the folder written, the scores before and after, the rounds
    (each as logged in ``refine.json``), whether the instruction's checks all hold and the
    scene validates (``ok``), and the whole record."""

    folder: str
    source: str
    instruction: str
    score_before: float
    score_after: float
    kept: int
    rounds: list[dict[str, Any]]
    checks: list[dict[str, Any]]
    valid: bool
    record: dict[str, Any] = field(default_factory=dict)
    seconds: float = 0.0

    @property
    def ok(self) -> bool:
        """Every instruction check holds and the scene validates (and the instruction was
        understood: it had checks, or a round was kept)."""
        done = bool(self.checks) or self.kept > 0
        return done and self.valid and all(c["held"] for c in self.checks)

    @property
    def seconds_per_round(self) -> float:
        """Mean wall time of a round."""
        times = [r["timings"]["total"] for r in self.rounds if "timings" in r]
        return round(sum(times) / len(times), 3) if times else 0.0


@dataclass
class _Measure:
    report: Any
    checks: list[dict[str, Any]]
    score: dict[str, Any]
    findings: list[dict[str, Any]]
    valid: bool
    seconds: float

    def to_json(self) -> dict[str, Any]:
        return {
            **self.score,
            "valid": self.valid,
            "checks": self.checks,
            "findings": self.findings,
            "seconds": round(self.seconds, 3),
        }


class _Context:
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

    def measure(self, folder: Path) -> _Measure:
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
        return _Measure(
            report=report,
            checks=checks,
            score=refine_score(report.scores, checks),
            findings=findings(report),
            valid=valid,
            seconds=time.perf_counter() - start,
        )


def refine(
    folder: Path | str,
    instruction: str,
    *,
    rounds: int = 3,
    planner: Planner = "offline",
    out: Path | str | None = None,
    overwrite: bool = False,
    seed: int = 0,
    library_path: Path | None = None,
    llm_config: Any = None,
    images: bool | None = None,
    max_ops: int | None = None,
    render: bool = True,
    width: int = 320,
    height: int = 240,
    log: Callable[[str], None] | None = None,
) -> RefineResult:
    """Refine the scene in ``folder`` by ``instruction`` (see the module docstring) and write the
    result into ``out`` (default: back into ``folder``).

    ``llm_config``: a :class:`holomj.plan.llm_config.LLMConfig` (default: the environment and
    ``$HOLOMJ_HOME/config.toml``); ``images``: send the views to the model (default: yes unless
    ``HOLOMJ_LLM_IMAGES=0``); ``max_ops``: operations per round (default 8, at most 50).

    Raises :class:`~holomj.errors.InputError` for a folder that is not a holomj scene, an empty
    or overlong instruction, bad numbers, an unknown planner or no LLM configured, and
    :class:`~holomj.errors.OutputExistsError` when ``out`` exists (without ``overwrite``).
    """
    from holomj.refinement.safety import MAX_OPS_PER_ROUND
    from holomj.spec.edit import MAX_OPERATIONS

    start = time.perf_counter()
    folder = require_scene_folder(Path(folder), "holomj generate' or 'holomj compile")
    text = " ".join(str(instruction or "").split())
    if not text:
        raise InputError("empty instruction", where="--instruction", fix="say what to change")
    if len(text) > MAX_INSTRUCTION_CHARS:
        raise InputError(f"longer than {MAX_INSTRUCTION_CHARS} characters", where="--instruction")
    if not 1 <= rounds <= MAX_ROUNDS:
        raise InputError(f"must lie in [1, {MAX_ROUNDS}]", where="--rounds")
    max_ops = MAX_OPS_PER_ROUND if max_ops is None else max_ops
    if not 1 <= max_ops <= MAX_OPERATIONS:
        raise InputError(f"must lie in [1, {MAX_OPERATIONS}]", where="--max-ops")
    if planner not in ("offline", "llm"):
        raise InputError(f"unknown planner {planner!r}", where="--planner", fix="offline or llm")
    if not 0 <= seed <= MAX_SEED:
        raise InputError(f"must lie in [0, {MAX_SEED}]", where="--seed")
    target = Path(out) if out is not None else folder
    in_place = target.resolve() == folder.resolve()
    if not in_place:
        prepare_output(target, overwrite)
    chat = None
    if planner == "llm":
        from holomj.refinement.llm import VisionChat, images_enabled

        config = resolve_llm_config(llm_config)
        chat = VisionChat(config, images=images_enabled(images), seed=seed, log=log)
    emit = log or (lambda line: None)

    context = _Context(folder, text)
    for note in context.instruction.notes:
        emit(f"instruction: {note}")
    target.absolute().parent.mkdir(parents=True, exist_ok=True)
    work = Path(tempfile.mkdtemp(prefix=f".{target.name}.refine-", dir=target.absolute().parent))
    try:
        run = _Run(
            context, folder, work, rounds, planner, chat, seed, library_path, max_ops,
            (render, width, height), emit,
        )  # fmt: skip
        run.go()
        record = run.record(text, target, time.perf_counter() - start)
        _write(run.current, target, record, run.images)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    final = run.measures[-1]
    return RefineResult(
        folder=str(target),
        source=str(folder),
        instruction=text,
        score_before=run.measures[0].score["score"],
        score_after=final.score["score"],
        kept=sum(1 for r in run.rounds if r["decision"] == "kept"),
        rounds=run.rounds,
        checks=final.checks,
        valid=final.valid,
        record=record,
        seconds=round(time.perf_counter() - start, 3),
    )


def resolve_llm_config(value: Any = None) -> Any:
    """An :class:`~holomj.plan.llm_config.LLMConfig`: ``value`` itself, or made from a dict of
    ``base_url``, ``model``, ``api_key``, ``config_file`` (None values left to the environment
    and ``$HOLOMJ_HOME/config.toml``), or from those alone when ``value`` is None.
    :class:`~holomj.errors.InputError` when no server or model is configured."""
    from holomj.plan.llm_config import LLMConfig, load_llm_config

    if isinstance(value, LLMConfig):
        return value
    settings = dict(value or {})
    unknown = sorted(set(settings) - {"base_url", "model", "api_key", "config_file"})
    if unknown:
        raise InputError(f"unknown LLM setting {unknown[0]!r}", where="llm_config")
    return load_llm_config(**settings)


class _Run:
    """The rounds of one refine run."""

    def __init__(
        self,
        context: _Context,
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
        self.measures: list[_Measure] = []
        self.rounds: list[dict[str, Any]] = []
        self.images: dict[str, bytes] = {}
        self.tried: set[str] = set()
        self.solo = False  # after a rejected round of several edits: one edit per round
        self.feedback: list[str] = []
        self.stopped = ""

    def go(self) -> None:
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

    def round(self, number: int, before: _Measure) -> dict[str, Any]:
        from holomj.jobs.edit import apply_edits
        from holomj.jobs.refine_views import render_views, scene_summary
        from holomj.refinement.goals import not_worse

        start = time.perf_counter()
        timings: dict[str, float] = {}
        row: dict[str, Any] = {"round": number, "planner": self.planner}
        summary = self.summary
        views: list[tuple[str, bytes]] = []
        if self.render:
            rooms = self._rooms(before)
            shown = render_views(self.current, rooms, width=self.width, height=self.height)
            timings["render"] = shown.seconds
            for name, png in shown.images.items():
                path = f"{REFINE_DIR}/round_{number}/{name}"
                self.images[path] = png
                views.append((shown.captions.get(name, name), png))
            row["images"] = [f"{REFINE_DIR}/round_{number}/{n}" for n in shown.images]
            if shown.error:
                row["render_error"] = shown.error
                self.log(f"round {number}: render failed ({shown.error}); going on without images")
        clock = time.perf_counter()
        try:
            operations, refused = self._plan(number, summary, before, views, row)
        except HolomjError as err:
            timings["plan"] = round(time.perf_counter() - clock, 3)
            timings["total"] = round(time.perf_counter() - start, 3)
            row.update(
                decision="planner failed",
                reasons=[err.one_line()],
                operations=[],
                timings=timings,
                score_before=before.score["score"],
            )
            if isinstance(getattr(err, "record", None), dict):
                row["llm"] = err.record
            self.log(f"round {number}: planner failed: {err.one_line()}")
            return row
        timings["plan"] = round(time.perf_counter() - clock, 3)
        row["operations"] = operations
        if refused:
            row["refused_by_checks"] = refused
        if not operations:
            timings["total"] = round(time.perf_counter() - start, 3)
            row.update(
                decision="no operations",
                reasons=["the planner proposed nothing (new) to do"],
                timings=timings,
                score_before=before.score["score"],
            )
            self.log(f"round {number}: nothing (new) to do")
            return row
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
            timings["total"] = round(time.perf_counter() - start, 3)
            row.update(
                decision="rejected",
                reasons=[f"the edit failed: {err.one_line()}"],
                timings=timings,
                score_before=before.score["score"],
            )
            self.feedback.append(f"round {number}: the edit failed: {err.one_line()}")
            return row
        timings["edit"] = round(time.perf_counter() - clock, 3)
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
        timings["total"] = round(time.perf_counter() - start, 3)
        row["timings"] = timings
        self.log(
            f"round {number}: {row['decision']} ({'; '.join(reasons)}) in {timings['total']:.1f} s"
        )
        return row

    def _retry_alone(self, operations: list[dict[str, Any]], report: Any) -> None:
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
        before: _Measure,
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
        problems += [f"{f['metric']}: {f['object']} {f['reason']}" for f in before.findings]
        feedback, self.feedback = self.feedback, []
        proposal = ask_model(
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
        row["llm"] = proposal.record
        if proposal.renamed:
            row["renamed_ids"] = proposal.renamed
        for refused in proposal.refused:
            self.feedback.append(
                f"round {number}: operation {refused['index']} ({refused['op']}) refused: "
                f"{refused['reason']}"
            )
        return proposal.operations, proposal.refused

    def _rooms(self, before: _Measure) -> list[str]:
        rooms = list(self.context.instruction.rooms)
        for finding in before.findings:
            obj = self.summary.object(finding["object"])
            if obj is not None and obj.room and obj.room not in rooms:
                rooms.append(obj.room)
        return rooms or [r.id for r in self.summary.rooms]

    def record(self, text: str, target: Path, seconds: float) -> dict[str, Any]:
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


def _write(current: Path, target: Path, record: dict[str, Any], images: dict[str, bytes]) -> None:
    """The folder ``current`` with ``refine.json`` and the round images, written atomically as
    ``target`` (an earlier ``refine/`` of it is replaced)."""

    def fill(tmp: Path) -> None:
        for entry in sorted(current.iterdir()):
            if entry.name.startswith(".") or entry.name in (REFINE_DIR, REFINE_JSON):
                continue
            if entry.is_dir():
                shutil.copytree(entry, tmp / entry.name)
            else:
                shutil.copy2(entry, tmp / entry.name)
        for name, data in images.items():
            path = tmp / name
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_bytes(data)
        (tmp / REFINE_JSON).write_text(dump_json(record), encoding="utf-8")

    try:
        replace_folder(target, fill)
    except OSError as err:
        raise ExportError(f"writing failed: {err}", where=str(target)) from None


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
