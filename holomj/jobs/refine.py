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
from typing import Any

from holomj.atomic import replace_folder
from holomj.errors import ExportError, InputError
from holomj.jobs.folder import dump_json, prepare_output, require_scene_folder
from holomj.jobs.refine_measure import RefineContext
from holomj.jobs.refine_rounds import REFINE_DIR, Planner, RefineRun
from holomj.seeds import MAX_SEED

REFINE_JSON = "refine.json"
MAX_ROUNDS = 20
MAX_INSTRUCTION_CHARS = 2000


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
    start = time.perf_counter()
    folder = require_scene_folder(Path(folder), "holomj generate' or 'holomj compile")
    text = _instruction_text(instruction)
    max_ops = _checked_numbers(rounds, max_ops, planner, seed)
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

    context = RefineContext(folder, text)
    for note in context.instruction.notes:
        emit(f"instruction: {note}")
    target.absolute().parent.mkdir(parents=True, exist_ok=True)
    work = Path(tempfile.mkdtemp(prefix=f".{target.name}.refine-", dir=target.absolute().parent))
    try:
        run = RefineRun(
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


def _instruction_text(instruction: str) -> str:
    """The instruction on one line; refused when empty or overlong."""
    text = " ".join(str(instruction or "").split())
    if not text:
        raise InputError("empty instruction", where="--instruction", fix="say what to change")
    if len(text) > MAX_INSTRUCTION_CHARS:
        raise InputError(f"longer than {MAX_INSTRUCTION_CHARS} characters", where="--instruction")
    return text


def _checked_numbers(rounds: int, max_ops: int | None, planner: str, seed: int) -> int:
    """Refuse rounds, operations per round, planner or seed out of range; the operations per
    round (default :data:`holomj.refinement.safety.MAX_OPS_PER_ROUND`)."""
    from holomj.refinement.safety import MAX_OPS_PER_ROUND
    from holomj.spec.edit import MAX_OPERATIONS

    if not 1 <= rounds <= MAX_ROUNDS:
        raise InputError(f"must lie in [1, {MAX_ROUNDS}]", where="--rounds")
    max_ops = MAX_OPS_PER_ROUND if max_ops is None else max_ops
    if not 1 <= max_ops <= MAX_OPERATIONS:
        raise InputError(f"must lie in [1, {MAX_OPERATIONS}]", where="--max-ops")
    if planner not in ("offline", "llm"):
        raise InputError(f"unknown planner {planner!r}", where="--planner", fix="offline or llm")
    if not 0 <= seed <= MAX_SEED:
        raise InputError(f"must lie in [0, {MAX_SEED}]", where="--seed")
    return max_ops


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
