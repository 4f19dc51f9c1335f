"""A model's reply checked as data before anything is applied; nothing in it is ever executed.

:func:`check_reply` reads one reply of the refine planner:

1. one JSON object ``{"operations": [...]}`` (:func:`holomj.plan.llm_parse.extract_json_object`:
   bare, or the single fenced JSON block; prose, code blocks in another language, NaN are
   refused), with at most ``max_ops`` operations: a reply that breaks this is refused whole;
2. each operation on its own: no text that looks like code (:func:`looks_like_code`), valid
   against the operations schema (:func:`holomj.spec.edit.parse_operations`), ids that exist in
   the scene (or that an earlier ``add`` of the same reply introduces), known rooms, sizes no
   larger than the room and the wall height allow (and at least 2 cm), positions inside a room
   and under the ceiling. A refused operation is dropped with its reason; the others go on.
3. ``add`` operations get refine's ids (``<room>.refine.<noun>_<n>``), and references to the
   model's ids in later operations follow.

The reasons go back to the model in the next request.
"""

from __future__ import annotations

import json
import re
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from holomj.errors import HolomjError
from holomj.plan.llm_json import LLMResponseError, extract_json_object
from holomj.refinement.summary import PlannerSceneSummary
from holomj.spec.edit import MAX_OPERATIONS, parse_operations

MAX_OPS_PER_ROUND = 8
MIN_SIZE_M = 0.02
MAX_FLOOR_SIZE_M = 6.0
_CODE = re.compile(
    r"(__\w+__|\bimport\s+[a-z_]|\bfrom\s+[a-z_.]+\s+import\b|\beval\s*\(|\bexec\s*\(|"
    r"\bos\.\w+|\bsubprocess\b|\bsys\.\w+|\blambda\b\s*\w*:|\bdef\s+\w+\s*\(|<\s*script|"
    r"\$\(|`|;\s*(?:rm|curl|wget|sh|bash)\b|\brm\s+-rf\b|\bopen\s*\(.*\)|\bprint\s*\()",
    re.IGNORECASE,
)
REFERENCE_FIELDS = ("target", "on", "above")


def looks_like_code(text: str) -> bool:
    """Whether a text reads like a program, a shell command or a template injection."""
    return bool(_CODE.search(text))


@dataclass
class Checked:
    """What survived the checks: operations (as JSON data, ready for ``apply_edits``), the
    refused ones with their reasons, ids renamed, and the reason a whole reply was refused."""

    operations: list[dict[str, Any]] = field(default_factory=list)
    refused: list[dict[str, Any]] = field(default_factory=list)
    renamed: dict[str, str] = field(default_factory=dict)
    fatal: str | None = None

    def feedback(self) -> list[str]:
        """One line per problem, for the model."""
        lines = [self.fatal] if self.fatal else []
        lines += [
            f"operation {r['index']} ({r['op']}) refused: {r['reason']}" for r in self.refused
        ]
        return lines


def check_reply(
    content: str,
    scene: PlannerSceneSummary,
    *,
    max_ops: int = MAX_OPS_PER_ROUND,
    name_add: Callable[[dict[str, Any], set[str]], str] | None = None,
) -> Checked:
    """Check one reply (see the module docstring). ``name_add(op, taken)`` gives an ``add``
    its id (default: ``<room>.refine.<noun>_<n>``)."""
    out = Checked()
    try:
        data = extract_json_object(content)
    except LLMResponseError as err:
        out.fatal = err.what
        return out
    ops = data.get("operations") if isinstance(data, dict) else None
    extra = sorted(set(data) - {"operations", "schema_version", "comment", "notes"})
    if not isinstance(ops, list) or extra:
        out.fatal = 'answer with one JSON object {"operations": [...]} and nothing else'
        return out
    if len(ops) > min(max_ops, MAX_OPERATIONS):
        out.fatal = f"{len(ops)} operations: at most {min(max_ops, MAX_OPERATIONS)} per round"
        return out
    known = set(scene.ids) | set(scene.lights)
    taken = set(scene.ids)
    name_add = name_add or default_add_id(scene)
    for index, raw in enumerate(ops):
        op_name = raw.get("op", "?") if isinstance(raw, dict) else "?"
        try:
            op = _check_one(raw, index, scene, known, out.renamed)
        except _Refuse as err:
            out.refused.append({"index": index, "op": str(op_name)[:20], "reason": err.reason})
            continue
        if op["op"] == "add":
            wanted = op.get("id")
            new = name_add(op, taken)
            taken.add(new)
            known.add(new)
            if wanted:
                out.renamed[wanted] = new
            op["id"] = new
        out.operations.append(op)
    if ops and not out.operations and out.fatal is None:
        out.fatal = "every operation was refused"
    return out


class _Refuse(Exception):
    def __init__(self, reason: str) -> None:
        super().__init__(reason)
        self.reason = reason


def _strings(value: Any) -> list[str]:
    if isinstance(value, str):
        return [value]
    if isinstance(value, dict):
        return [s for k, v in value.items() for s in (*_strings(k), *_strings(v))]
    if isinstance(value, list):
        return [s for v in value for s in _strings(v)]
    return []


def _check_one(
    raw: Any, index: int, scene: PlannerSceneSummary, known: set[str], renamed: dict[str, str]
) -> dict[str, Any]:
    if not isinstance(raw, dict):
        raise _Refuse("an operation must be a JSON object")
    for text in _strings(raw):
        if looks_like_code(text):
            raise _Refuse(f"text that looks like code is never run: {text[:60]!r}")
    data = _renamed(raw, renamed)
    try:
        (op,) = parse_operations([data], f"operations[{index}]")
    except HolomjError as err:
        raise _Refuse(" ".join(err.one_line().split())[:300]) from None
    record = op.model_dump(mode="json", exclude_none=True)
    kind = record["op"]
    if kind == "add":
        if record.get("id") in scene.ids:
            raise _Refuse(f"id {record['id']!r} is taken: give a new id")
        _room(record.get("room"), scene)
        _size(record.get("size"), scene)
        _position(record.get("position"), scene)
    elif kind in ("remove", "move", "replace"):
        _known(record["id"], known, "id")
        if kind == "move":
            _position(record.get("position"), scene)
        if kind == "replace":
            _size(record.get("size"), scene)
    elif kind == "material":
        _room(record.get("room"), scene)
    elif kind == "light":
        if record.get("id") is not None:
            _known(record["id"], known, "id")
        _room(record.get("room"), scene)
        _position(record.get("position"), scene)
    for rel in record.get("relations", []):
        if rel.get("target") is not None:
            _known(rel["target"], known, "relation target")
    for key in ("on", "above"):
        if record.get(key) is not None:
            _known(record[key], known, key)
    return record


def _renamed(raw: dict[str, Any], renamed: dict[str, str]) -> dict[str, Any]:
    """``raw`` with the model's ids of earlier adds replaced by the ids they were given."""
    if not renamed:
        return raw
    data = json.loads(json.dumps(raw))
    if data.get("op") != "add" and data.get("id") in renamed:
        data["id"] = renamed[data["id"]]
    for key in ("on", "above"):
        if data.get(key) in renamed:
            data[key] = renamed[data[key]]
    for rel in data.get("relations") or []:
        if isinstance(rel, dict) and rel.get("target") in renamed:
            rel["target"] = renamed[rel["target"]]
    return data


def _known(object_id: str, known: set[str], what: str) -> None:
    if object_id not in known:
        from holomj.errors import closest_names

        near = closest_names(object_id, sorted(known))
        hint = f"; did you mean {near}?" if near else "; use the ids of the scene summary"
        raise _Refuse(f"unknown {what} {object_id!r}{hint}")


def _room(room: str | None, scene: PlannerSceneSummary) -> None:
    if room is not None and scene.room(room) is None:
        rooms = ", ".join(r.id for r in scene.rooms)
        raise _Refuse(f"unknown room {room!r} (rooms: {rooms})")


def _size(size: list[float] | None, scene: PlannerSceneSummary) -> None:
    if size is None:
        return
    xmin, ymin, xmax, ymax = scene.bounds
    largest = min(MAX_FLOOR_SIZE_M, max(xmax - xmin, ymax - ymin))
    width, depth, height = size
    if max(width, depth) > largest or height > scene.wall_height:
        raise _Refuse(
            f"size ({width:g}, {depth:g}, {height:g}) m is absurd: at most {largest:.1f} m "
            f"wide or deep and {scene.wall_height:.1f} m high"
        )
    if min(size) < MIN_SIZE_M:
        raise _Refuse(f"size ({width:g}, {depth:g}, {height:g}) m: every side at least 2 cm")


def _position(position: list[float] | None, scene: PlannerSceneSummary) -> None:
    if position is None:
        return
    x, y = position[0], position[1]
    if scene.room_at(x, y) is None:
        raise _Refuse(f"position ({x:g}, {y:g}) is outside every room")
    if len(position) > 2 and not 0.0 <= position[2] <= scene.wall_height:
        raise _Refuse(f"height {position[2]:g} m is below the floor or above the ceiling")


def default_add_id(scene: PlannerSceneSummary) -> Callable[[dict[str, Any], set[str]], str]:
    """The default namer of added objects: ``<room>.refine.<noun>_<n>``."""

    def name(op: dict[str, Any], taken: set[str]) -> str:
        noun = _noun(str(op.get("id") or op.get("description") or "object"))
        return next_id(f"{add_room(op, scene) or 'scene'}.refine.{noun}", taken)

    return name


def add_room(op: dict[str, Any], scene: PlannerSceneSummary) -> str | None:
    """The room an add goes to: its ``room``, its first relation target's, its position's, the
    only room."""
    if op.get("room"):
        return str(op["room"])
    for rel in op.get("relations", []):
        target = scene.object(rel.get("target") or "")
        if target is not None and target.room:
            return target.room
    if op.get("position"):
        return scene.room_at(op["position"][0], op["position"][1])
    return scene.rooms[0].id if len(scene.rooms) == 1 else None


def next_id(stem: str, taken: set[str]) -> str:
    """``<stem>_<n>`` with the first ``n`` not taken."""
    n = 0
    while f"{stem}_{n}" in taken:
        n += 1
    return f"{stem}_{n}"


def _noun(text: str) -> str:
    last = text.split(".")[-1]
    words = re.findall(r"[a-z]+", re.sub(r"_?\d+$", "", last.lower()))
    words = [w for w in words if w not in ("a", "an", "the", "some", "refine")]
    return "_".join(words[-2:]) or "object"
