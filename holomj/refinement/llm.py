"""The vision-language refine planner: rendered views and the scene to an OpenAI-compatible chat
endpoint, edit operations back.

Each request is one chat-completions call (:class:`holomj.plan.llm_client.ChatClient`, the
``[llm]`` configuration of ``holomj generate --planner llm``): a system message and one user
message whose content parts are the question (the instruction, the scene summary with ids,
categories, rooms and positions, what the evaluation finds, the feedback on earlier answers and
the operations' JSON Schema) followed by every rendered view as an ``image_url`` part holding a
``data:image/png;base64,...`` URL, each after a text part naming it.

**Text-only fallback.** With ``images=False`` (``--no-images``, or ``HOLOMJ_LLM_IMAGES=0``), or
once the server rejects a request with an error that mentions images (``image``, ``vision``,
``multimodal``, ``image_url``), requests carry the question alone, and the record says so.

**Safety.** Every answer goes through :func:`holomj.refinement.safety.check_reply` (or the
pointing parsers): one JSON object, the schema, known ids, sane sizes and positions, at most
``max_ops`` operations, no code. A refused answer is sent back with the reason and asked again
(``1 + max_retries`` attempts per step); HTTP 429/5xx and timeouts are retried after a pause.
Nothing an answer holds is ever executed.

**Accounting.** Every step returns a record: calls, attempts, prompt and completion tokens,
images sent and their bytes, seconds, whether it went text-only, and each error.
"""

from __future__ import annotations

import base64
import json
import os
import re
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any, TypeVar

from holomj.errors import HolomjError
from holomj.plan.llm_client import ChatClient, LLMTransportError
from holomj.plan.llm_config import LLMConfig
from holomj.plan.llm_json import LLMResponseError
from holomj.refinement.instruction_items import Instruction
from holomj.refinement.safety import (
    MAX_OPS_PER_ROUND,
    Checked,
    check_reply,
    default_add_id,
    next_id,
)
from holomj.refinement.summary import PlannerSceneSummary
from holomj.spec.edit import operations_schema

R = TypeVar("R")
IMAGES_ENV = "HOLOMJ_LLM_IMAGES"
MAX_ECHO_CHARS = 4000
_IMAGE_WORDS = re.compile(r"image|vision|multi-?modal|picture", re.IGNORECASE)

SYSTEM = (
    "You improve a 3D indoor scene for robot simulation by proposing edit operations as JSON "
    "data. You see rendered views of the scene and a summary of it with every object's id. "
    'Answer with one JSON object {"operations": [...]} and nothing else. Never write code: an '
    "answer with code is refused, and nothing in an answer is ever executed."
)


class LLMStepFailed(HolomjError):
    """A step of the conversation could not get a usable answer (or the server failed)."""

    def __init__(self, what: str, record: dict[str, Any], *, where: str | None = None) -> None:
        self.record = record
        super().__init__(
            what, where=where, fix="check the server and the model, or use --planner offline"
        )


def images_enabled(flag: bool | None = None) -> bool:
    """Whether requests carry images: ``flag`` when given, else ``HOLOMJ_LLM_IMAGES`` (0, no,
    false, off: text only), else yes."""
    if flag is not None:
        return flag
    value = os.environ.get(IMAGES_ENV, "").strip().lower()
    return value not in ("0", "no", "false", "off")


def data_url(png: bytes) -> str:
    """A PNG as a ``data:`` URL."""
    return "data:image/png;base64," + base64.b64encode(png).decode("ascii")


def rejects_images(err: LLMTransportError) -> bool:
    """Whether a server error says the model does not take images."""
    return (
        err.status is not None and 400 <= err.status < 500 and bool(_IMAGE_WORDS.search(err.what))
    )


@dataclass
class VisionChat:
    """Asks one chat model questions with images, step by step, and keeps the accounts."""

    config: LLMConfig
    images: bool = True
    seed: int = 0
    log: Callable[[str], None] | None = None
    text_only_reason: str | None = None
    client: ChatClient = field(init=False)

    def __post_init__(self) -> None:
        self.client = ChatClient(self.config)
        if not self.images and self.text_only_reason is None:
            self.text_only_reason = "images switched off"

    def _emit(self, line: str) -> None:
        if self.log is not None:
            self.log(line)

    def _user(self, text: str, views: Sequence[tuple[str, bytes]]) -> dict[str, Any]:
        if not self.images or not views:
            note = ""
            if views and self.text_only_reason:
                note = f"\n\n(No images: {self.text_only_reason}; work from the summary.)"
            return {"role": "user", "content": text + note}
        parts: list[dict[str, Any]] = [{"type": "text", "text": text}]
        for caption, png in views:
            parts.append({"type": "text", "text": f"Image: {caption}"})
            parts.append({"type": "image_url", "image_url": {"url": data_url(png)}})
        return {"role": "user", "content": parts}

    def _new_record(self, step: str) -> dict[str, Any]:
        """A step's record before its first call (calls, tokens, images, seconds, errors)."""
        return {
            "step": step,
            "model": self.config.model,
            "calls": 0,
            "attempts": 0,
            "prompt_tokens": 0,
            "completion_tokens": 0,
            "images": 0,
            "image_bytes": 0,
            "seconds": 0.0,
            "text_only": not self.images,
            "errors": [],
        }

    def ask(
        self,
        step: str,
        text: str,
        views: Sequence[tuple[str, bytes]],
        parse: Callable[[str], R],
        *,
        system: str = SYSTEM,
    ) -> tuple[R, dict[str, Any]]:
        """Ask ``text`` (with ``views``: (caption, PNG)) until ``parse`` accepts an answer;
        (the parsed answer, the step's record). :class:`LLMStepFailed` when the attempts run
        out or the server cannot be used."""
        record = self._new_record(step)
        history: list[dict[str, Any]] = []
        attempts = 1 + self.config.max_retries
        image_retry = True
        attempt = 0
        while attempt < attempts:
            attempt += 1
            record["attempts"] = attempt
            messages = [{"role": "system", "content": system}, self._user(text, views), *history]
            sent = [v for v in views] if self.images else []
            record["calls"] += 1
            record["images"] += len(sent)
            record["image_bytes"] += sum(len(png) for _, png in sent)
            start = time.monotonic()
            try:
                response = self.client.complete(messages, seed=self.seed)
            except LLMTransportError as err:
                record["seconds"] = round(record["seconds"] + time.monotonic() - start, 3)
                problem = err.one_line()
                record["errors"].append(problem)
                self._emit(f"llm {step} attempt {attempt}: {problem}")
                if self.images and views and image_retry and rejects_images(err):
                    self.images, image_retry = False, False
                    self.text_only_reason = f"the server rejected images ({err.what[:120]})"
                    record["text_only"] = True
                    attempt -= 1  # the same question again, without images
                    continue
                if not err.retryable:
                    raise LLMStepFailed(f"{step}: {problem}", record) from None
                if attempt < attempts:
                    time.sleep(self.config.backoff_s * 2 ** (attempt - 1))
                continue
            record["seconds"] = round(record["seconds"] + response.seconds, 3)
            record["prompt_tokens"] += response.prompt_tokens
            record["completion_tokens"] += response.completion_tokens
            try:
                if response.finish_reason == "length":
                    raise LLMResponseError(
                        f"the answer was cut off at max_tokens={self.config.max_tokens}; "
                        "give a shorter answer"
                    )
                result = parse(response.content)
            except LLMResponseError as err:
                record["errors"].append(err.what)
                self._emit(f"llm {step} attempt {attempt}: refused: {err.what}")
                history = [
                    {"role": "assistant", "content": response.content[:MAX_ECHO_CHARS] or "-"},
                    {
                        "role": "user",
                        "content": f"That answer was refused: {err.what}. Answer again with one "
                        "JSON object in the shape asked for, and nothing else.",
                    },
                ]
                continue
            self._emit(
                f"llm {step} attempt {attempt}: {response.prompt_tokens}+"
                f"{response.completion_tokens} tokens, {response.seconds:.2f} s, ok"
            )
            return result, record
        last = record["errors"][-1] if record["errors"] else "no answer"
        raise LLMStepFailed(
            f"{step}: no usable answer after {attempts} attempt(s) ({last})", record
        )


# --------------------------------------------------------------------------- refine rounds


@dataclass
class LLMProposal:
    """What the model proposed for one round: the operations that passed the checks, the ones
    refused (with reasons), ids renamed, and the accounting record."""

    operations: list[dict[str, Any]]
    refused: list[dict[str, Any]]
    renamed: dict[str, str]
    record: dict[str, Any]


def refine_question(
    instruction: Instruction,
    scene: PlannerSceneSummary,
    checks: list[dict[str, Any]],
    problems: list[str],
    feedback: list[str],
    *,
    round_number: int,
    rounds: int,
    max_ops: int,
) -> str:
    """The text of one round's request."""
    schema = json.dumps(operations_schema(), separators=(",", ":"))
    todo = [
        f"- {c['what']}: {'met' if c['held'] else 'NOT met'} ({c['reason'][:160]})" for c in checks
    ]
    lines = [
        f"Instruction: {instruction.text}",
        "",
        f"Round {round_number} of {rounds}. Propose at most {max_ops} edit operations that carry "
        "out the instruction and fix the problems below without making anything else worse. "
        "The operations are applied in order to a copy of the scene; only what they touch "
        "changes; the copy is validated (physics) and scored, and kept only when it is not "
        "worse. Answer with an empty list when nothing should change.",
        "",
        "Scene summary (metres; x, y on the floor, z up; size_m is the bounding box):",
        json.dumps(scene.to_json(), separators=(",", ":")),
        "",
        "Instruction checks (the evaluation of the scene now):",
        *(todo or ["- (none could be measured)"]),
        "",
        "Other problems the evaluation finds:",
        *([f"- {p}" for p in problems] or ["- none"]),
    ]
    if feedback:
        lines += ["", "Feedback on earlier answers:", *[f"- {f}" for f in feedback]]
    lines += [
        "",
        "Rules: use only the object, room and light ids of the summary, or the id you give an "
        'object you "add" in the same answer; sizes are (width, depth, height) in metres; '
        "positions must lie inside a room; no code anywhere.",
        'Answer format: {"operations": [ ... ]}, each operation valid against this JSON Schema:',
        schema,
    ]
    return "\n".join(lines)


def propose(
    chat: VisionChat,
    instruction: Instruction,
    scene: PlannerSceneSummary,
    checks: list[dict[str, Any]],
    problems: list[str],
    feedback: list[str],
    views: Sequence[tuple[str, bytes]],
    *,
    round_number: int,
    rounds: int,
    max_ops: int = MAX_OPS_PER_ROUND,
) -> LLMProposal:
    """Ask the model for one round's operations (checked; see the module docstring)."""
    question = refine_question(
        instruction,
        scene,
        checks,
        problems,
        feedback,
        round_number=round_number,
        rounds=rounds,
        max_ops=max_ops,
    )
    namer = add_namer(instruction, scene)

    def parse(content: str) -> Checked:
        checked = check_reply(content, scene, max_ops=max_ops, name_add=namer)
        if checked.fatal:
            raise LLMResponseError("; ".join(checked.feedback())[:1500])
        return checked

    checked, record = chat.ask(f"refine round {round_number}", question, views, parse)
    record["refused"] = checked.refused
    return LLMProposal(checked.operations, checked.refused, checked.renamed, record)


def add_namer(
    instruction: Instruction, scene: PlannerSceneSummary
) -> Callable[[dict[str, Any], set[str]], str]:
    """Ids for the model's adds: an add of an instruction item's kind in its room gets the
    item's id stem (so the instruction's checks count it), any other ``<room>.refine.<noun>``."""
    fallback = default_add_id(scene)
    from holomj.plan.knowledge import knowledge_base
    from holomj.plan.prompt import parse_prompt
    from holomj.refinement.safety import add_room

    kb = knowledge_base()

    def name(op: dict[str, Any], taken: set[str]) -> str:
        room = add_room(op, scene)
        try:
            parsed = parse_prompt(f"a room with {op.get('description', '')}", kb)
            kinds = {o.kind for o in parsed.objects}
        except HolomjError:
            kinds = set()
        for item in instruction.items:
            if item.action == "add" and item.kind in kinds and item.room in (room, None):
                return next_id(item.stem, taken)
        return fallback(op, taken)

    return name
