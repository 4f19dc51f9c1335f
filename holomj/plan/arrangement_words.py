"""What a request's words ask of a room's arrangement, read once by the planner so that the
layout never reads words: the shape of a kitchen's counter run (``a galley kitchen``,
``U-shaped counters``) and work surfaces in rows (``twelve desks in two rows``).

The words are the room's own (its id and type, the descriptions of its counter-run modules and
island, the phrases of its relations) and the request's. A shape word in the request counts
only next to a kitchen word (``a galley kitchen``, ``kitchen in an L shape``), so that an
L-shaped living room asks nothing of the kitchen; rows count in the request's sentences that
name the object. :func:`with_arrangement_words` writes both into the room's plan
(:attr:`~holomj.spec.plan.PlanRoom.counter_run_shape`, :attr:`~holomj.spec.plan.PlanObject.rows`).
"""

from __future__ import annotations

import re
from collections.abc import Iterable

from holomj.layout.counter_run_arrangements import ISLAND_CATEGORY, RUN_CATEGORIES
from holomj.spec.plan import CounterRunShape, PlanRoom, RowsAsked

_SHAPE_WORDS: tuple[tuple[CounterRunShape, re.Pattern[str]], ...] = (
    ("U", re.compile(r"\bu[\s-]*shaped?\b|\bhorseshoe\b")),
    ("L", re.compile(r"\bl[\s-]*shaped?\b")),
    ("galley", re.compile(r"\bgalley\b|\bparallel\b|\bdouble[\s-]*(?:wall|sided)\b")),
    ("one_wall", re.compile(r"\b(?:one|single)[\s-]*wall\b|\bstraight\b|\blinear\b")),
)
_KITCHEN = r"(?:kitchen\w*|counters?|worktops?|countertops?|cabinets?|cabinetry|cupboards?)"
# A shape word asks for a run only right before a kitchen word ("an L-shaped kitchen", "galley
# style kitchen", "U-shaped counters") or after one with nothing but a phrase of shape between
# ("a kitchen laid out in a U shape"): "an L-shaped living room and a kitchen" asks nothing.
_KITCHEN_AFTER = re.compile(rf"^[\s-]*(?:[a-z]+[\s-]+)?{_KITCHEN}\b")
_KITCHEN_BEFORE = re.compile(
    rf"\b{_KITCHEN}\s+(?:(?:laid|set|arranged|built|fitted|out|in|into|as|an?|the|like|"
    r"with|of|shape|shaped|form|style)\s+){0,6}$"
)

_NUMBERS = {
    "a": 1,
    "one": 1,
    "single": 1,
    "two": 2,
    "three": 3,
    "four": 4,
    "five": 5,
    "six": 6,
    "seven": 7,
    "eight": 8,
    "nine": 9,
    "ten": 10,
}
_ROWS = re.compile(
    r"\b(?:in|into)\s+(a|one|single|two|three|four|five|six|seven|eight|nine|ten|\d+)\s+rows?\b"
)
_ANY_ROWS = re.compile(r"\bin\s+(?:neat\s+|straight\s+)?rows\b|\brows\s+of\b")
MAX_ROWS = 20


def counter_run_shape(plan_room: PlanRoom, request: str = "") -> CounterRunShape | None:
    """The counter-run shape the room's words or the request ask for (``"U"``, ``"L"``,
    ``"galley"``, ``"one_wall"``), else None.

    Read from the room's id and type, the descriptions of its run modules and island (an
    ``L-shaped kitchen counter``), the phrases of its relations and ``request``: there a shape
    word counts only next to a kitchen word (``a galley kitchen``, ``U-shaped counters``,
    ``kitchen in an L shape``), so that an L-shaped living room asks nothing."""
    own = [plan_room.id.replace("_", " "), plan_room.type.replace("_", " ")]
    for obj in plan_room.objects:
        if obj.category in RUN_CATEGORIES or obj.category == ISLAND_CATEGORY:
            own.append(obj.description or obj.name)
    own.extend(rel.phrase for rel in plan_room.relations)
    text = " ".join(own).lower()
    for shape, pattern in _SHAPE_WORDS:
        if pattern.search(text):
            return shape
    words = request.lower()
    for shape, pattern in _SHAPE_WORDS:
        for match in pattern.finditer(words):
            before = words[max(0, match.start() - 60) : match.start()]
            if _KITCHEN_AFTER.search(words[match.end() :]) or _KITCHEN_BEFORE.search(before):
                return shape
    return None


def rows_asked(texts: Iterable[str]) -> tuple[bool, int | None]:
    """Whether ``texts`` ask for rows, and how many (``in two rows`` -> 2, ``in rows`` ->
    None)."""
    asked = False
    for text in texts:
        words = text.lower()
        match = _ROWS.search(words)
        if match:
            token = match.group(1)
            value = int(token) if token.isdigit() else _NUMBERS[token]
            return True, max(1, min(value, MAX_ROWS))
        asked = asked or bool(_ANY_ROWS.search(words))
    return asked, None


def object_rows(plan_room: PlanRoom, name: str, request: str = "") -> RowsAsked | None:
    """The rows the words ask for the room's object ``name``: a count, ``"any"`` (rows, how
    many left open) or None (no rows asked). Read from the phrases of the object's relations
    and the request's sentences that name it (or its last word)."""
    texts = [r.phrase for r in plan_room.relations if r.subject == name]
    texts += _sentences_naming(request, name)
    asked, count = rows_asked(texts)
    if count is not None:
        return count
    return "any" if asked else None


def with_arrangement_words(plan_room: PlanRoom, request: str) -> PlanRoom:
    """``plan_room`` with what its words and ``request`` ask of its arrangement written in:
    the counter-run shape and, on each floor object, the rows asked."""
    objects = [
        obj.model_copy(update={"rows": object_rows(plan_room, obj.name, request)})
        if obj.placement == "floor"
        else obj
        for obj in plan_room.objects
    ]
    shape = counter_run_shape(plan_room, request)
    return plan_room.model_copy(update={"counter_run_shape": shape, "objects": objects})


def _sentences_naming(request: str, name: str) -> list[str]:
    """The sentences of the request that name the kind (or its last word)."""
    if not request:
        return []
    head = name.split()[-1].lower()
    stem = head[:-1] if head.endswith("s") else head
    return [s for s in re.split(r"[.;!?]", request) if stem and stem in s.lower()]
