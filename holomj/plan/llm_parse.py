"""Each step of the LLM planner reads its answer here: a pydantic model of the answer
(:mod:`holomj.plan.llm_answers`, unknown fields rejected) and a ``parse_*`` function that checks
cross references (room ids) and maps the answer into plan data, clamping sizes to sane ranges
and returning a note for every change it made. The JSON itself is extracted by
:mod:`holomj.plan.llm_json`.
"""

from __future__ import annotations

import re
import unicodedata
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

from holomj.layout.constraints import constraints_to_text, parse_constraint_text
from holomj.plan.llm_answers import (
    ConstraintsAnswer,
    DoorsAnswer,
    FloorPlanAnswer,
    ObjectAnswer,
    ObjectsAnswer,
    SmallObjectAnswer,
    WallHeightAnswer,
    WindowsAnswer,
)
from holomj.plan.llm_json import LLMResponseError, parse_answer, plan_errors
from holomj.spec.categories import normal_type
from holomj.spec.plan import PlanObject, PlanSmallObject, PlanWindows

ROOM_SIDE_M = (2.5, 8.0)
WALL_HEIGHT_M = (2.4, 4.5)
MAX_OBJECTS_PER_ROOM = 40
MAX_QUANTITY = 20
MAX_ON_TOP = 10
MAX_ON_TOP_QUANTITY = 10
# Sane (width, depth, height) ranges in centimetres, by placement.
# Heights are also capped at the wall height when the caller knows it.
SIZE_RANGE_CM: dict[str, tuple[tuple[float, float], ...]] = {
    "floor": ((10.0, 500.0), (10.0, 500.0), (1.0, 350.0)),
    "wall": ((5.0, 500.0), (1.0, 100.0), (2.0, 350.0)),
}

_INSTANCE_SUFFIX = re.compile(r"-\s*\d+$")


# --------------------------------------------------------------------------- names


def ascii_words(text: str) -> str:
    """Accents folded to ASCII, lower case."""
    folded = unicodedata.normalize("NFKD", text).encode("ascii", "ignore").decode("ascii")
    return folded.lower()


def normalise_room_id(text: str) -> str | None:
    """``"Living Room 2"`` -> ``"living_room_2"``; None when nothing usable is left."""
    words = re.sub(r"[^a-z0-9]+", " ", ascii_words(text)).split()
    return "_".join(words)[:64].strip("_") or None


def normalise_object_name(text: str) -> str | None:
    """A valid plan object name: ``"Dining Chair-2"`` -> ``"dining chair"``; None if empty.

    Lower case, accents folded, a trailing instance suffix ``-<n>`` dropped, ``_`` and ``-`` as
    spaces, other characters outside ``[a-z0-9 .+]`` removed, at most 64 characters.
    """
    name = _INSTANCE_SUFFIX.sub("", ascii_words(text).strip())
    name = re.sub(r"[_\-/]+", " ", name)
    name = re.sub(r"[^a-z0-9 .+]+", "", name)
    name = " ".join(name.split())[:64]
    name = re.sub(r"^[^a-z0-9]+|[^a-z0-9]+$", "", name)
    return name or None


def _clean_text(text: str, limit: int) -> str:
    return " ".join(text.split())[:limit]


def _room_ref(text: str, room_ids: Sequence[str], what: str) -> str:
    key = normalise_room_id(text)
    if key is not None and key in room_ids:
        return key
    raise LLMResponseError(f"{what}: unknown room {text!r} (rooms: {', '.join(room_ids)})")


# --------------------------------------------------------------------------- steps


@dataclass(frozen=True)
class RoomDraft:
    """A room of the floor-plan step, sizes already clamped."""

    id: str
    type: str
    width: float
    depth: float
    floor_material: str
    wall_material: str


@dataclass(frozen=True)
class FloorPlanDraft:
    """The floor-plan step's result."""

    scene_type: str
    style: tuple[str, ...]
    rooms: tuple[RoomDraft, ...]

    def room_ids(self) -> list[str]:
        """Room ids in answer order."""
        return [room.id for room in self.rooms]


@dataclass(frozen=True)
class DoorsDraft:
    """The doors step's result: room pairs to connect and the entrance room."""

    connections: tuple[tuple[str, str], ...]
    entrance_room: str


@plan_errors
def parse_floor_plan(content: str) -> tuple[FloorPlanDraft, list[str]]:
    """Step 1: scene type, style and rooms (ids normalised, sides clamped to 2.5-8 m)."""
    answer = parse_answer(content, FloorPlanAnswer)
    notes: list[str] = []
    rooms: list[RoomDraft] = []
    for index, room in enumerate(answer.rooms):
        room_id = normalise_room_id(room.id)
        if room_id is None:
            raise LLMResponseError(f"rooms[{index}].id: {room.id!r} has no letters or digits")
        if room_id in [r.id for r in rooms]:
            raise LLMResponseError(f"rooms[{index}].id: room id {room_id!r} is used twice")
        room_type = normal_type(ascii_words(room.type))[:64] or "room"
        sides = []
        for label, value in (("width", room.width_m), ("depth", room.depth_m)):
            clamped = round(min(max(value, ROOM_SIDE_M[0]), ROOM_SIDE_M[1]), 2)
            if abs(clamped - value) > 1e-6:
                notes.append(
                    f"room {room_id!r}: {label} {value:g} m clamped to {clamped:g} m "
                    f"(rooms are {ROOM_SIDE_M[0]:g}-{ROOM_SIDE_M[1]:g} m per side)"
                )
            sides.append(clamped)
        rooms.append(
            RoomDraft(
                id=room_id,
                type=room_type,
                width=sides[0],
                depth=sides[1],
                floor_material=_clean_text(room.floor_material, 200),
                wall_material=_clean_text(room.wall_material, 200),
            )
        )
    scene_type = _clean_text(ascii_words(answer.scene_type), 64) or "room"
    style = tuple(_clean_text(ascii_words(s), 64) for s in answer.style)
    return FloorPlanDraft(scene_type, tuple(s for s in style if s), tuple(rooms)), notes


@plan_errors
def parse_wall_height(content: str) -> tuple[float, list[str]]:
    """Step 2: the wall height in metres, clamped to a sane range."""
    answer = parse_answer(content, WallHeightAnswer)
    value = answer.wall_height_m
    clamped = round(min(max(value, WALL_HEIGHT_M[0]), WALL_HEIGHT_M[1]), 2)
    notes = []
    if abs(clamped - value) > 1e-6:
        notes.append(
            f"wall height {value:g} m clamped to {clamped:g} m "
            f"({WALL_HEIGHT_M[0]:g}-{WALL_HEIGHT_M[1]:g} m)"
        )
    return clamped, notes


@plan_errors
def parse_doors(content: str, room_ids: Sequence[str]) -> tuple[DoorsDraft, list[str]]:
    """Step 3: door connections between known rooms and the entrance room."""
    answer = parse_answer(content, DoorsAnswer)
    pairs: list[tuple[str, str]] = []
    for index, (first, second) in enumerate(answer.connections):
        a = _room_ref(first, room_ids, f"connections[{index}]")
        b = _room_ref(second, room_ids, f"connections[{index}]")
        if a == b:
            raise LLMResponseError(f"connections[{index}]: a room cannot connect to itself ({a})")
        if (a, b) not in pairs and (b, a) not in pairs:
            pairs.append((a, b))
    entrance = _room_ref(answer.entrance_room, room_ids, "entrance_room")
    notes = []
    if len(room_ids) > 1:
        linked = {room for pair in pairs for room in pair}
        for room_id in room_ids:
            if room_id not in linked:
                notes.append(
                    f"room {room_id!r} has no door asked for; the floor planner will connect it"
                )
    return DoorsDraft(tuple(pairs), entrance), notes


@plan_errors
def parse_windows(
    content: str, room_ids: Sequence[str]
) -> tuple[dict[str, PlanWindows], list[str]]:
    """Step 4: window count and kind per room; rooms left out get their type's defaults."""
    answer = parse_answer(content, WindowsAnswer)
    windows: dict[str, PlanWindows] = {}
    for index, item in enumerate(answer.rooms):
        room_id = _room_ref(item.room, room_ids, f"rooms[{index}].room")
        if room_id in windows:
            raise LLMResponseError(f"rooms[{index}].room: room {room_id!r} is listed twice")
        windows[room_id] = PlanWindows(count=item.count, kind=item.kind)
    return windows, []


@plan_errors
def parse_objects(
    content: str,
    *,
    room_id: str,
    categories: Sequence[str] = (),
    request: str = "",
    wall_height_m: float | None = None,
) -> tuple[list[PlanObject], list[str]]:
    """Step 5: a room's objects as plan objects (names normalised, sizes cm -> m, clamped).

    Sizes are clamped to :data:`SIZE_RANGE_CM`, heights also to ``wall_height_m`` when given.
    """
    answer = parse_answer(content, ObjectsAnswer)
    known = {c.strip().lower(): c for c in categories if c.strip()}
    notes: list[str] = []
    where = f"room {room_id!r}"
    items: list[tuple[str, ObjectAnswer]] = []
    for raw_name, item in answer.objects.items():
        name = _object_name(raw_name, [n for n, _ in items], notes, where)
        if name is None:
            continue
        if item.quantity == 0:
            notes.append(f"{where}: {name!r} has quantity 0; dropped")
            continue
        items.append((name, item))
    if len(items) > MAX_OBJECTS_PER_ROOM:
        dropped = ", ".join(n for n, _ in items[MAX_OBJECTS_PER_ROOM:])
        notes.append(f"{where}: more than {MAX_OBJECTS_PER_ROOM} objects; dropped {dropped}")
        items = items[:MAX_OBJECTS_PER_ROOM]
    floor_names = {n for n, item in items if item.location == "floor"}
    objects = []
    for name, item in items:
        label = f"{where}: {name!r}"
        objects.append(
            PlanObject(
                name=name,
                description=_clean_text(item.description, 500),
                category=_category(item.category, known, notes, label),
                size=_size_m(item.size_cm, _size_range(item.location, wall_height_m), notes, label),
                quantity=_quantity(item.quantity, MAX_QUANTITY, notes, label),
                variance=item.variance,
                placement=item.location,
                above=_above(item, floor_names, notes, label),
                on_top=_on_top(item.objects_on_top, known, notes, label),
                requested=_mentioned(name, request),
            )
        )
    return objects, notes


@plan_errors
def parse_constraints(
    content: str, *, room_id: str, instance_names: Sequence[str]
) -> tuple[list[str], list[str]]:
    """Step 6: constraint lines; those naming unknown instances are dropped with a note."""
    answer = parse_answer(content, ConstraintsAnswer)
    parsed = parse_constraint_text("\n".join(answer.constraints), list(instance_names))
    notes = [f"room {room_id!r} constraints: {warning}" for warning in parsed.warnings]
    return constraints_to_text(parsed.constraints).splitlines(), notes


# --------------------------------------------------------------------------- helpers


def _object_name(raw: str, taken: Sequence[str], notes: list[str], where: str) -> str | None:
    name = normalise_object_name(raw)
    if name is None:
        notes.append(f"{where}: object name {raw!r} has no letters or digits; dropped")
        return None
    if name in taken:
        notes.append(f"{where}: object {raw!r} repeats {name!r}; dropped")
        return None
    if name != " ".join(raw.lower().split()):
        notes.append(f"{where}: object name {raw!r} written as {name!r}")
    return name


def _category(
    hint: str | None, known: Mapping[str, str], notes: list[str], label: str
) -> str | None:
    if hint is None:
        return None
    match = known.get(hint.strip().lower())
    if match is None:
        notes.append(f"{label}: category {hint!r} is not in the asset library; ignored")
        return None
    return match[:64]


def _size_range(placement: str, wall_height_m: float | None) -> tuple[tuple[float, float], ...]:
    width, depth, (low, high) = SIZE_RANGE_CM[placement]
    if wall_height_m is not None:
        high = max(low, min(high, wall_height_m * 100.0))
    return width, depth, (low, high)


def _size_m(
    size_cm: tuple[float, float, float] | None,
    ranges: tuple[tuple[float, float], ...],
    notes: list[str],
    label: str,
) -> tuple[float, float, float] | None:
    if size_cm is None:
        return None
    clamped = tuple(round(min(max(v, low), high), 1) for v, (low, high) in zip(size_cm, ranges))
    if any(abs(a - b) > 0.05 for a, b in zip(clamped, size_cm)):
        shown = " x ".join(f"{v:g}" for v in size_cm)
        notes.append(
            f"{label}: size {shown} cm clamped to {' x '.join(f'{v:g}' for v in clamped)} cm"
        )
    width, depth, height = (round(v / 100.0, 3) for v in clamped)
    return (width, depth, height)


def _quantity(value: int, limit: int, notes: list[str], label: str) -> int:
    if value > limit:
        notes.append(f"{label}: quantity {value} reduced to {limit}")
        return limit
    return value


def _above(item: ObjectAnswer, floor_names: set[str], notes: list[str], label: str) -> str | None:
    if item.above is None:
        return None
    if item.location != "wall":
        notes.append(f"{label}: 'above' is for wall objects; ignored")
        return None
    target = normalise_object_name(item.above)
    if target not in floor_names:
        notes.append(f"{label}: hangs above {item.above!r}, not a floor object here; ignored")
        return None
    return target


def _on_top(
    answers: Sequence[SmallObjectAnswer], known: Mapping[str, str], notes: list[str], label: str
) -> list[PlanSmallObject]:
    result: list[PlanSmallObject] = []
    for answer in answers:
        name = _object_name(answer.name, [s.name for s in result], notes, f"{label} on top")
        if name is None:
            continue
        if answer.quantity == 0:
            notes.append(f"{label}: {name!r} on top has quantity 0; dropped")
            continue
        if len(result) == MAX_ON_TOP:
            notes.append(
                f"{label}: more than {MAX_ON_TOP} kinds of objects on top; {name!r} dropped"
            )
            continue
        result.append(
            PlanSmallObject(
                name=name,
                description=_clean_text(answer.description, 500),
                category=_category(answer.category, known, notes, f"{label} on top: {name!r}"),
                quantity=_quantity(
                    answer.quantity, MAX_ON_TOP_QUANTITY, notes, f"{label}: {name!r}"
                ),
                variance=answer.variance,
            )
        )
    return result


def _mentioned(name: str, request: str) -> bool:
    """Whether the request names the object (singular or plural)."""
    return re.search(rf"\b{re.escape(name)}(?:e?s)?\b", ascii_words(request)) is not None
