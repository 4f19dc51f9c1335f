"""Strict reading of an LLM's answer: one JSON object per answer.

:func:`extract_json_object` accepts exactly one JSON object, either as the whole answer or as the
single fenced code block (```` ```json ````, or untagged) of an answer; anything else (prose
without a block, two blocks, code in another language, NaN, a list) is an
:class:`LLMResponseError` whose message is fed back to the model. Nothing in an answer is ever
executed or evaluated: it is only ever given to :func:`json.loads`.
"""

from __future__ import annotations

import functools
import json
import math
import re
from collections.abc import Callable
from typing import Any, ParamSpec, TypeVar

from pydantic import BaseModel, ValidationError

from holomj.errors import HolomjError
from holomj.spec.base import field_path

MAX_ANSWER_CHARS = 200_000


_THINK = re.compile(r"^\s*<think>.*?</think>", re.S)


_FENCE = re.compile(r"```[ \t]*([A-Za-z0-9_+.-]*)[^\n]*\n(.*?)```", re.S)


T = TypeVar("T", bound=BaseModel)


P = ParamSpec("P")


Q = TypeVar("Q")


class LLMResponseError(HolomjError):
    """An answer of the model was not what the step asked for; the message says why."""


def extract_json_object(content: str) -> dict[str, Any]:
    """The one JSON object of an answer (bare, or in its single fenced block)."""
    if not isinstance(content, str):
        raise LLMResponseError("the answer is not text")
    if len(content) > MAX_ANSWER_CHARS:
        raise LLMResponseError(f"the answer is longer than {MAX_ANSWER_CHARS} characters")
    text = _THINK.sub("", content, count=1).strip()
    if not text:
        raise LLMResponseError("the answer is empty; answer with one JSON object")
    if "```" in text:
        text = _fenced_block(text)
    elif not text.startswith(("{", "[")):
        raise LLMResponseError(
            f"not JSON: the answer must be one JSON object, it starts with {text[:40]!r}"
        )
    data = _loads(text)
    if not isinstance(data, dict):
        raise LLMResponseError(f"expected one JSON object, got a JSON {type(data).__name__}")
    return data


def _fenced_block(text: str) -> str:
    blocks = _FENCE.findall(text)
    if not blocks:
        raise LLMResponseError("a code block is not closed with ```; answer with one JSON object")
    json_blocks = [body for lang, body in blocks if lang.lower() in ("", "json", "jsonc")]
    if not json_blocks:
        lang = blocks[0][0]
        raise LLMResponseError(
            f"not JSON: a {lang} code block is not an answer (code is never run); "
            "answer with one JSON object"
        )
    if len(blocks) > 1:
        raise LLMResponseError(
            f"{len(blocks)} code blocks in the answer; answer with exactly one JSON object"
        )
    body = json_blocks[0].strip()
    if not body.startswith(("{", "[")):
        raise LLMResponseError(
            f"not JSON: the code block must hold one JSON object, it starts with {body[:40]!r}"
        )
    return body


def _loads(text: str) -> Any:
    def reject_constant(name: str) -> Any:
        raise ValueError(f"{name} is not a JSON number")

    def finite_float(token: str) -> float:
        value = float(token)
        if not math.isfinite(value):
            raise ValueError(f"number {token[:20]} is out of range")
        return value

    try:
        return json.loads(text, parse_constant=reject_constant, parse_float=finite_float)
    except json.JSONDecodeError as err:
        raise LLMResponseError(
            f"invalid JSON: {err.msg} at line {err.lineno} column {err.colno}"
        ) from None
    except (ValueError, RecursionError) as err:
        raise LLMResponseError(f"invalid JSON: {err}") from None


def plan_errors(func: Callable[P, Q]) -> Callable[P, Q]:
    """Report plan data that an answer made invalid as an :class:`LLMResponseError`."""

    @functools.wraps(func)
    def wrapper(*args: P.args, **kwargs: P.kwargs) -> Q:
        try:
            return func(*args, **kwargs)
        except ValidationError as err:
            raise LLMResponseError(
                f"the answer makes invalid plan data: {describe_validation(err)}"
            ) from None

    return wrapper


def parse_answer(content: str, model: type[T]) -> T:
    """Extract the answer's JSON object and validate it as ``model``."""
    data = extract_json_object(content)
    try:
        return model.model_validate(data)
    except ValidationError as err:
        raise LLMResponseError(f"wrong schema: {describe_validation(err)}") from None
    except (ValueError, TypeError, RecursionError) as err:
        raise LLMResponseError(f"wrong schema: {err}") from None


def describe_validation(err: ValidationError, limit: int = 3) -> str:
    """The first ``limit`` problems of a validation error, ``field.path: message`` each."""
    problems = []
    for item in err.errors(include_url=False)[:limit]:
        message = "unknown field" if item.get("type") == "extra_forbidden" else item.get("msg")
        problems.append(f"{field_path(tuple(item.get('loc', ())))}: {message}")
    more = err.error_count() - len(problems)
    return "; ".join(problems) + (f" (and {more} more)" if more > 0 else "")
