"""Narrowing a user's string to one of a fixed set of names, typed as the set is.

``one_of("llm", PLANNERS)`` returns ``"llm"`` typed as the planners' ``Literal``, so a checked
option needs no cast; the caller raises its own one-line error (naming the option) on None.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TypeVar

Choice = TypeVar("Choice", bound=str)


def one_of(value: str, choices: Sequence[Choice]) -> Choice | None:
    """The entry of ``choices`` equal to ``value``, else None."""
    for choice in choices:
        if choice == value:
            return choice
    return None
