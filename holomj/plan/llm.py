"""The LLM planner (``--planner llm``): a scene plan from a conversation with a chat model.

One request per step, in Holodeck's order: floor plan, wall height, doors, windows, then for
each room its objects and the layout constraints of its floor objects. Each step's checked
result goes into the next step's question. An answer that cannot be used (not one JSON object,
wrong shape, unknown room, cut off at ``max_tokens``) is sent back to the model with the reason
and asked again; HTTP 429/5xx answers and timeouts are retried after a short backoff. Each step
gets ``1 + max_retries`` attempts. When a step still fails, the offline planner given as
``fallback`` makes the plan and its notes say why; without a fallback a one-line
:class:`LLMPlannerError` is raised.

Answers are only ever parsed as JSON (:mod:`holomj.plan.llm_parse`); nothing is executed.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any, TypeVar

from pydantic import ValidationError

from holomj.errors import HolomjError, InputError
from holomj.plan import llm_prompts as prompts
from holomj.plan.arrangement_words import with_arrangement_words
from holomj.plan.llm_client import ChatClient, LLMTransportError
from holomj.plan.llm_config import LLMConfig
from holomj.plan.llm_json import LLMResponseError, describe_validation
from holomj.plan.llm_parse import (
    FloorPlanDraft,
    parse_constraints,
    parse_doors,
    parse_floor_plan,
    parse_objects,
    parse_wall_height,
    parse_windows,
)
from holomj.spec.plan import PlanObject, PlanRoom, PlanWindows, ScenePlan

MAX_NOTES = 200
MAX_ECHO_CHARS = 4000  # a failed answer sent back to the model is cut to this length
MAX_REASON_CHARS = 240
MAX_PROMPT_CHARS = 20_000

R = TypeVar("R")


class LLMPlannerError(HolomjError):
    """The LLM planner could not finish a plan and no fallback was given."""


class _StepFailed(Exception):
    """A step used up its attempts (internal: turned into a fallback or LLMPlannerError)."""

    def __init__(self, step: str, room: str | None, attempts: int, reason: str) -> None:
        self.step = step
        self.room = room
        self.attempts = attempts
        self.reason = " ".join(reason.split())[:MAX_REASON_CHARS]
        super().__init__(self.describe())

    def describe(self) -> str:
        """``step 'objects' (room 'studio') after 3 attempts (invalid JSON: ...)``."""
        room = f" (room {self.room!r})" if self.room else ""
        plural = "s" if self.attempts != 1 else ""
        return f"step {self.step!r}{room} after {self.attempts} attempt{plural} ({self.reason})"


@dataclass
class _Usage:
    """Calls, tokens and time, in total and per step."""

    model: str
    calls: int = 0
    retries: int = 0
    prompt_tokens: int = 0
    completion_tokens: int = 0
    started: float = field(default_factory=time.monotonic)
    steps: list[dict[str, Any]] = field(default_factory=list)

    def as_dict(self) -> dict[str, Any]:
        return {
            "model": self.model,
            "calls": self.calls,
            "prompt_tokens": self.prompt_tokens,
            "completion_tokens": self.completion_tokens,
            "seconds": round(time.monotonic() - self.started, 3),
            "retries": self.retries,
            "steps": [dict(step) for step in self.steps],
        }


class _Session:
    """Asks the model one step at a time, with retries, and keeps the accounts."""

    def __init__(self, config: LLMConfig, seed: int, log: Callable[[str], None] | None) -> None:
        self.config = config
        self.seed = seed
        self.client = ChatClient(config)
        self.usage = _Usage(model=config.model)
        self._log = log or (lambda line: None)

    def ask(self, step: str, room: str | None, question: str, parse: Callable[[str], R]) -> R:
        """Ask ``question`` until ``parse`` accepts the answer or the attempts run out."""
        messages = [
            {"role": "system", "content": prompts.SYSTEM},
            {"role": "user", "content": question},
        ]
        record: dict[str, Any] = {
            "step": step,
            "room": room,
            "attempts": 0,
            "prompt_tokens": 0,
            "completion_tokens": 0,
            "seconds": 0.0,
            "ok": False,
            "errors": [],
        }
        self.usage.steps.append(record)
        label = f"{step}[{room}]" if room else step
        attempts = 1 + self.config.max_retries
        problem = ""
        for attempt in range(1, attempts + 1):
            if attempt > 1:
                self.usage.retries += 1
            record["attempts"] = attempt
            self.usage.calls += 1
            start = time.monotonic()
            try:
                response = self.client.complete(messages, seed=self.seed)
            except LLMTransportError as err:
                seconds = time.monotonic() - start
                record["seconds"] = round(record["seconds"] + seconds, 3)
                problem = f"{err.what} at {err.where}" if err.where else err.what
                record["errors"].append(problem)
                self._log(f"llm {label} attempt {attempt}/{attempts}: {seconds:.2f} s, {problem}")
                if not err.retryable:
                    raise _StepFailed(step, room, attempt, problem) from None
                if attempt < attempts:
                    time.sleep(self.config.backoff_s * 2 ** (attempt - 1))
                continue
            self._count(record, response.prompt_tokens, response.completion_tokens)
            record["seconds"] = round(record["seconds"] + response.seconds, 3)
            tokens = f"{response.prompt_tokens}+{response.completion_tokens} tokens"
            try:
                result = self._check(response.finish_reason, response.content, parse)
            except LLMResponseError as err:
                problem = err.what
                record["errors"].append(problem)
                self._log(
                    f"llm {label} attempt {attempt}/{attempts}: {tokens}, "
                    f"{response.seconds:.2f} s, rejected: {problem}"
                )
                messages += [
                    {"role": "assistant", "content": response.content[:MAX_ECHO_CHARS] or "-"},
                    {"role": "user", "content": prompts.feedback(problem)},
                ]
                continue
            record["ok"] = True
            self._log(
                f"llm {label} attempt {attempt}/{attempts}: {tokens}, {response.seconds:.2f} s, ok"
            )
            return result
        raise _StepFailed(step, room, attempts, problem)

    def _check(self, finish_reason: str | None, content: str, parse: Callable[[str], R]) -> R:
        if finish_reason == "length":
            raise LLMResponseError(
                f"the answer was cut off at max_tokens={self.config.max_tokens} "
                "(finish_reason 'length'); give a shorter answer"
            )
        if finish_reason == "content_filter":
            raise LLMResponseError(
                "the server withheld the answer (finish_reason 'content_filter')"
            )
        return parse(content)

    def _count(self, record: dict[str, Any], prompt_tokens: int, completion_tokens: int) -> None:
        record["prompt_tokens"] += prompt_tokens
        record["completion_tokens"] += completion_tokens
        self.usage.prompt_tokens += prompt_tokens
        self.usage.completion_tokens += completion_tokens


def plan_llm(
    prompt: str,
    seed: int,
    *,
    config: LLMConfig,
    fallback: Callable[[str, int], ScenePlan] | None = None,
    categories: Sequence[str] = (),
    log: Callable[[str], None] | None = None,
) -> ScenePlan:
    """Plan a scene for ``prompt`` by asking the configured chat model, step by step.

    ``categories`` (the asset library's) are offered to the model as object category hints.
    ``log`` receives one line per request (tokens, seconds, outcome) and a summary line. When a
    step fails after its retries, ``fallback(prompt, seed)`` makes the plan (its notes say why,
    its usage holds the LLM calls made); with no fallback :class:`LLMPlannerError` is raised.
    """
    if not prompt.strip():
        raise InputError("empty scene prompt", where="prompt", fix="describe the scene to build")
    if len(prompt) > MAX_PROMPT_CHARS:
        raise InputError(f"prompt longer than {MAX_PROMPT_CHARS} characters", where="prompt")
    if seed < 0:
        raise InputError(f"seed {seed} is negative", where="seed", fix="give a seed >= 0")
    session = _Session(config, seed, log)
    emit = log or (lambda line: None)
    try:
        plan = _converse(session, prompt, seed, list(categories))
    except _StepFailed as failure:
        usage = {**session.usage.as_dict(), "failed_step": failure.step}
        what = f"LLM planner failed at {failure.describe()}"
        emit(f"llm: {what}")
        if fallback is None:
            raise LLMPlannerError(
                what,
                where=config.endpoint,
                fix="check the server and the model, or use --planner offline",
            ) from None
        emit("llm: using the offline planner instead")
        return _with_fallback(fallback(prompt, seed), f"{what}; used the offline planner", usage)
    usage = plan.usage
    emit(
        f"llm: {usage['calls']} calls, {usage['prompt_tokens']}+{usage['completion_tokens']} "
        f"tokens, {usage['seconds']:.2f} s, {usage['retries']} retries"
    )
    return plan


def _converse(session: _Session, prompt: str, seed: int, categories: list[str]) -> ScenePlan:
    notes: list[str] = []
    floor, found = session.ask("floor_plan", None, prompts.floor_plan(prompt), parse_floor_plan)
    notes += found
    view = _plan_view(floor)
    height, found = session.ask(
        "wall_height", None, prompts.wall_height(prompt, view), parse_wall_height
    )
    notes += found
    view["wall_height_m"] = height
    ids = floor.room_ids()
    doors, found = session.ask(
        "doors", None, prompts.doors(prompt, view), lambda text: parse_doors(text, ids)
    )
    notes += found
    view["doors"] = [list(pair) for pair in doors.connections]
    view["entrance_room"] = doors.entrance_room
    windows, found = session.ask(
        "windows", None, prompts.windows(prompt, view), lambda text: parse_windows(text, ids)
    )
    notes += found
    view["windows"] = {k: w.model_dump() for k, w in windows.items()}
    furnished = [
        (room_view["id"], *_furnish(session, prompt, view, room_view, categories, notes))
        for room_view in view["rooms"]
    ]
    try:
        rooms = [
            with_arrangement_words(
                _plan_room(floor, room_id, doors.connections, windows, objects, constraints),
                prompt,
            )
            for room_id, objects, constraints in furnished
        ]
        return ScenePlan(
            prompt=prompt,
            planner="llm",
            seed=seed,
            scene_type=floor.scene_type,
            scene_type_match=f"chosen by the LLM ({session.config.model})",
            style=list(floor.style),
            wall_height=height,
            entrance_room=doors.entrance_room,
            rooms=rooms,
            notes=_capped(notes),
            usage=session.usage.as_dict(),
        )
    except ValidationError as err:
        raise _StepFailed("assemble", None, 1, describe_validation(err)) from None


def _furnish(
    session: _Session,
    prompt: str,
    view: dict[str, Any],
    room_view: dict[str, Any],
    categories: list[str],
    notes: list[str],
) -> tuple[list[PlanObject], list[str]]:
    """Steps 5 and 6 for one room: its objects, then its floor objects' constraints."""
    room_id = room_view["id"]
    objects, found = session.ask(
        "objects",
        room_id,
        prompts.objects(prompt, view, room_view, categories),
        lambda text: parse_objects(
            text,
            room_id=room_id,
            categories=categories,
            request=prompt,
            wall_height_m=view["wall_height_m"],
        ),
    )
    notes += found
    floor_objects = [o for o in objects if o.placement == "floor"]
    if not floor_objects:
        return objects, []
    names = [name for o in floor_objects for name in o.instances()]
    shown = [
        {
            "name": o.name,
            "instances": o.instances(),
            "size_cm": [round(v * 100) for v in o.size] if o.size else None,
        }
        for o in floor_objects
    ]
    constraints, found = session.ask(
        "constraints",
        room_id,
        prompts.constraints(prompt, room_view, shown, names),
        lambda text: parse_constraints(text, room_id=room_id, instance_names=names),
    )
    notes += found
    return objects, constraints


def _plan_view(floor: FloorPlanDraft) -> dict[str, Any]:
    """The floor plan as shown to the model in later steps (the values we kept)."""
    return {
        "scene_type": floor.scene_type,
        "style": list(floor.style),
        "rooms": [
            {
                "id": r.id,
                "type": r.type.replace("_", " "),
                "width_m": r.width,
                "depth_m": r.depth,
                "floor_material": r.floor_material,
                "wall_material": r.wall_material,
            }
            for r in floor.rooms
        ],
    }


def _plan_room(
    floor: FloorPlanDraft,
    room_id: str,
    connections: Sequence[tuple[str, str]],
    windows: dict[str, PlanWindows],
    objects: list[PlanObject],
    constraints: list[str],
) -> PlanRoom:
    draft = next(r for r in floor.rooms if r.id == room_id)
    return PlanRoom(
        id=room_id,
        type=draft.type,
        size=(draft.width, draft.depth),
        adjacent_to=[b for a, b in connections if a == room_id],
        floor_material=draft.floor_material,
        wall_material=draft.wall_material,
        windows=windows.get(room_id, PlanWindows()),
        objects=objects,
        constraints=constraints,
    )


def _with_fallback(plan: ScenePlan, note: str, usage: dict[str, Any]) -> ScenePlan:
    data = plan.model_dump()
    data["notes"] = _capped([*plan.notes, note])
    data["usage"] = usage
    return ScenePlan.model_validate(data)


def _capped(notes: list[str]) -> list[str]:
    if len(notes) <= MAX_NOTES:
        return notes
    kept = notes[: MAX_NOTES - 2] + [notes[-1]]  # the last note is the most important one
    return kept[:-1] + [f"... {len(notes) - len(kept)} more notes left out", kept[-1]]
