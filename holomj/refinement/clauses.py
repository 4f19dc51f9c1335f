"""An instruction cut into clauses, and the verb that says what each clause's objects are for
(see :mod:`holomj.refinement.instruction`)."""

from __future__ import annotations

import re

REMOVE_VERBS = ("remove", "delete", "take away", "take out", "get rid of", "discard", "drop")


MOVE_VERBS = ("move", "shift", "push", "relocate", "rearrange", "slide")


PUT_VERBS = ("put", "place", "set", "position", "stand")


ADD_VERBS = ("add", "include", "insert", "bring", "make", "create", "give", "furnish")


VERBS = REMOVE_VERBS + MOVE_VERBS + PUT_VERBS + ADD_VERBS


TO_PLACE = (
    (r"\b(?:in)?to the (?:middle|center|centre)\b", "in the middle"),
    (r"\b(?:in)?to (?:a|the) corner\b", "in the corner"),
    (r"\bto the window\b", "by the window"),
    (r"\bto the wall\b", "against the wall"),
    (r"\bto the (?:door|entrance)\b", "by the door"),
)


def split_clauses(text: str) -> list[str]:
    """The clauses of an instruction (see the module docstring)."""
    lowered = " ".join(text.lower().split())
    verbs = "|".join(re.escape(v) for v in VERBS)
    parts = re.split(rf"\bthen\b|[;.!?]|(?:,|\band\b)\s*(?=(?:please\s+)?(?:{verbs})\b)", lowered)
    out = []
    for part in parts:
        part = re.sub(r"^\s*(?:and|also|then|please|,)\s+", "", part.strip(" ,")).strip()
        if part:
            out.append(part)
    return out


def clause_verb(clause: str) -> tuple[str, str]:
    """(``add``/``remove``/``move``/``put``, the clause) from the clause's first verb."""
    words = re.sub(r"^(?:please|now|also|and)\s+", "", clause)
    for verbs, action in (
        (REMOVE_VERBS, "remove"),
        (MOVE_VERBS, "move"),
        (PUT_VERBS, "put"),
        (ADD_VERBS, "add"),
    ):
        for verb in verbs:
            if re.match(rf"{re.escape(verb)}\b", words):
                return action, words
    return "add", words
