"""Doors and windows for a set of rooms.

Doors (:func:`place_doors`): a tree of doors over the rooms' adjacency, grown from the entrance
by cheapest path where passing *through* a room costs its privacy (hallways and living rooms are
cheap, bedrooms dear, bathrooms dearest), so private rooms end up as leaves when the plan allows.
Each door sits on the longest wall the two rooms share, at least ``DOOR_CLEARANCE_M`` from the
segment's ends, plus one exterior door from the entrance room.

Door kinds (``DOOR_KIND_BY_ROOM``; a door takes the most closed kind of its two rooms, in the
order doorway > doorframe > open):

============================================================  ===========
room type                                                     kind
============================================================  ===========
bedroom, master_bedroom, kids_room, bathroom, office, study,  doorway
closet, laundry, garage (and any type not listed)
hallway, corridor, foyer, entrance                            doorframe
kitchen, living_room, dining_room                             open
============================================================  ===========

An ``open`` pair (e.g. living-dining, kitchen-living) gets a double (2 m) opening when the shared
wall holds 2 m plus clearance and both rooms are at least 12 m²; when the wall is too short for
that, it becomes a single ``doorframe``. The exterior door is always a single ``doorway``.

Windows (:func:`place_windows`) use Holodeck's size tables (``WINDOW_SIZES_CM``, width x height)
and go on exterior walls only, centred in the longest free stretch left, 0.3 m from wall ends,
doors and other windows. Default base heights: fixed 0.6 m, hung 0.8 m, slider 0.9 m; a window
is never taller than ``wall_height - 0.15``. Default count per room: ``WINDOW_CAP_BY_ROOM``
(0 for hallways, corridors, closets), one per 3.5 m of exterior wall, at least one.
"""

from __future__ import annotations

import heapq
import math
from collections.abc import Mapping, Sequence
from typing import Annotated, Literal

import numpy as np
from pydantic import Field
from shapely.geometry import Polygon

from holomj.errors import SpecError, closest_names
from holomj.layout.floorplan import ENTRANCE_PREFERENCE
from holomj.spec.base import FrozenModel
from holomj.spec.categories import normal_type
from holomj.spec.scene import Door, Room, Window
from holomj.spec.walls import Wall, derive_walls, find_wall_for_opening

DoorKind = Literal["doorway", "doorframe", "open"]
WindowKind = Literal["fixed", "hung", "slider"]

DOOR_CLEARANCE_M = 0.3  # from the ends of the wall segment a door sits on
SINGLE_WIDTH_M = 1.0
DOUBLE_WIDTH_M = 2.0
MIN_DOOR_WIDTH_M = 0.7  # a door squeezed onto a short shared wall is never narrower
DOUBLE_MIN_ROOM_AREA_M2 = 12.0
DOOR_HEIGHT_M = 2.1
NARROW_DOOR_COST = 10.0  # path cost of a door narrower than 1 m

DOOR_KIND_BY_ROOM: dict[str, DoorKind] = {
    "bedroom": "doorway",
    "master_bedroom": "doorway",
    "kids_room": "doorway",
    "bathroom": "doorway",
    "office": "doorway",
    "study": "doorway",
    "closet": "doorway",
    "laundry": "doorway",
    "garage": "doorway",
    "hallway": "doorframe",
    "corridor": "doorframe",
    "foyer": "doorframe",
    "entrance": "doorframe",
    "kitchen": "open",
    "living_room": "open",
    "dining_room": "open",
}
DEFAULT_DOOR_KIND: DoorKind = "doorway"
_CLOSEDNESS: dict[DoorKind, int] = {"open": 0, "doorframe": 1, "doorway": 2}

# Cost of walking through a room on the way to another one (higher: more private).
PRIVACY: dict[str, float] = {
    "hallway": 0.0,
    "corridor": 0.0,
    "foyer": 0.0,
    "entrance": 0.0,
    "living_room": 0.5,
    "dining_room": 1.0,
    "kitchen": 1.5,
    "office": 3.0,
    "study": 3.0,
    "bedroom": 5.0,
    "master_bedroom": 5.0,
    "kids_room": 5.0,
    "bathroom": 8.0,
    "closet": 8.0,
    "laundry": 6.0,
}
DEFAULT_PRIVACY = 3.0

# Holodeck's window size tables, centimetres, (width, height).
WINDOW_SIZES_CM: dict[str, tuple[tuple[int, int], ...]] = {
    "fixed": ((92, 120), (150, 92), (150, 120), (150, 180), (240, 120), (240, 180)),
    "hung": ((87, 160), (96, 91), (120, 160), (130, 67), (130, 87), (130, 130)),
    "slider": ((91, 92), (120, 61), (120, 91), (120, 120), (150, 92), (150, 120)),
}
WINDOW_BASE_HEIGHT_M: dict[str, float] = {"fixed": 0.6, "hung": 0.8, "slider": 0.9}
WINDOW_TOP_MARGIN_M = 0.15  # a window's top stays this far below the wall top
WINDOW_GAP_M = 0.3  # from wall ends, doors and other windows
WINDOW_SPACING_M = 3.5  # one window per this much exterior wall, by default
WINDOW_CAP_BY_ROOM: dict[str, int] = {
    "living_room": 3,
    "dining_room": 2,
    "kitchen": 2,
    "bedroom": 2,
    "master_bedroom": 3,
    "kids_room": 2,
    "office": 2,
    "study": 2,
    "bathroom": 1,
    "laundry": 1,
    "garage": 1,
    "hallway": 0,
    "corridor": 0,
    "foyer": 0,
    "entrance": 0,
    "closet": 0,
}
DEFAULT_WINDOW_CAP = 2
WINDOW_KIND_BY_ROOM: dict[str, WindowKind] = {
    "living_room": "fixed",
    "dining_room": "fixed",
    "kitchen": "slider",
    "bathroom": "hung",
    "bedroom": "hung",
    "master_bedroom": "hung",
    "kids_room": "hung",
}
DEFAULT_WINDOW_KIND: WindowKind = "slider"
DIRECTIONS: dict[str, tuple[float, float]] = {
    "north": (0.0, 1.0),
    "south": (0.0, -1.0),
    "east": (1.0, 0.0),
    "west": (-1.0, 0.0),
}


class WindowRequest(FrozenModel):
    """Windows wanted in one room: how many, of which kind, facing where, how high."""

    count: Annotated[int, Field(ge=0, le=20)] = 1
    kind: WindowKind | None = None
    direction: Literal["north", "south", "east", "west"] | None = None
    base_height: Annotated[float, Field(ge=0.0, le=4.0)] | None = None


def window_sizes_m(kind: str) -> list[tuple[float, float]]:
    """Holodeck's sizes for a window kind, in metres (width, height)."""
    return [(w / 100, h / 100) for w, h in WINDOW_SIZES_CM[kind]]


# ---------------------------------------------------------------------------------------------
# Doors


def door_kind(type_a: str, type_b: str, kinds: Mapping[str, str] | None = None) -> DoorKind:
    """The kind of a door between rooms of these types: the more closed of their kinds."""
    table: dict[str, str] = {**DOOR_KIND_BY_ROOM, **(dict(kinds) if kinds else {})}
    ka = _known_kind(table.get(normal_type(type_a), DEFAULT_DOOR_KIND))
    kb = _known_kind(table.get(normal_type(type_b), DEFAULT_DOOR_KIND))
    return ka if _CLOSEDNESS[ka] >= _CLOSEDNESS[kb] else kb


def _known_kind(kind: str) -> DoorKind:
    """``kind`` as a door kind, or a :class:`SpecError` naming it."""
    for known in _CLOSEDNESS:
        if known == kind:
            return known
    raise SpecError(
        f"unknown door kind {kind!r}", where="kinds", fix="use doorway, doorframe or open"
    )


def place_doors(
    rooms: Sequence[Room],
    rng: np.random.Generator,
    *,
    kinds: Mapping[str, str] | None = None,
    entrance: str | None = None,
    extra_doors: int = 0,
    wall_height: float = 2.7,
) -> list[Door]:
    """Doors joining every room to the entrance, plus one exterior door from the entrance room.

    ``kinds`` overrides ``DOOR_KIND_BY_ROOM`` by room type; ``extra_doors`` adds up to that many
    doors between adjacent public rooms beyond the tree. Raises :class:`SpecError` when a room
    cannot be reached (no shared wall long enough for a door) or the entrance has no exterior
    wall that holds a door.
    """
    by_id = {r.id: r for r in rooms}
    walls = derive_walls(rooms)
    areas = {r.id: Polygon(r.polygon).area for r in rooms}
    entrance = _entrance(rooms, walls, entrance)
    links = _links(walls)
    parent = _door_tree(rooms, links, entrance, rng)
    height = min(DOOR_HEIGHT_M, wall_height - 0.3)
    doors: list[Door] = []
    exterior = _exterior_door(by_id[entrance], walls, rng, height)
    doors.append(exterior)
    pairs = [tuple(sorted((child, par))) for child, par in parent.items() if par is not None]
    extra = _extra_pairs(by_id, links, set(pairs), extra_doors)
    for a, b in sorted(pairs) + extra:
        doors.append(_interior_door(by_id[a], by_id[b], links[(a, b)], areas, kinds, rng, height))
    return doors


def _entrance(rooms: Sequence[Room], walls: Sequence[Wall], entrance: str | None) -> str:
    ids = [r.id for r in rooms]
    usable = {w.rooms[0] for w in walls if w.exterior and w.length >= _door_span(SINGLE_WIDTH_M)}
    if entrance is not None:
        if entrance not in ids:
            hint = closest_names(entrance, ids)
            raise SpecError(
                f"unknown entrance room {entrance!r}",
                where="entrance",
                fix=f"did you mean {hint}?" if hint else f"use one of {', '.join(ids)}",
            )
        if entrance not in usable:
            raise SpecError(
                f"room {entrance!r} has no exterior wall long enough for a door "
                f"({_door_span(SINGLE_WIDTH_M):.1f} m)",
                where="entrance",
                fix=f"choose another entrance: {', '.join(sorted(usable)) or 'none qualifies'}",
            )
        return entrance
    candidates = [r for r in rooms if r.id in usable]
    if not candidates:
        raise SpecError(
            "no room has an exterior wall long enough for the front door",
            where="rooms",
            fix=f"give some room an exterior wall of at least {_door_span(SINGLE_WIDTH_M):.1f} m",
        )
    for wanted in ENTRANCE_PREFERENCE:
        for room in candidates:
            if normal_type(room.type) == wanted:
                return room.id
    return max(candidates, key=lambda r: Polygon(r.polygon).area).id


def _door_span(width: float) -> float:
    return width + 2 * DOOR_CLEARANCE_M


def _links(walls: Sequence[Wall]) -> dict[tuple[str, str], Wall]:
    """For each pair of rooms, the longest wall they share that holds a (possibly narrow) door."""
    links: dict[tuple[str, str], Wall] = {}
    for wall in walls:
        if wall.exterior or wall.length < _door_span(MIN_DOOR_WIDTH_M) - 1e-6:
            continue
        pair = (wall.rooms[0], wall.rooms[1])
        if pair not in links or wall.length > links[pair].length + 1e-9:
            links[pair] = wall
    return links


def _door_tree(
    rooms: Sequence[Room],
    links: Mapping[tuple[str, str], Wall],
    entrance: str,
    rng: np.random.Generator,
) -> dict[str, str | None]:
    """Cheapest-path tree from the entrance: passing through a room costs its privacy."""
    types = {r.id: normal_type(r.type) for r in rooms}
    neighbours: dict[str, list[tuple[str, float]]] = {r.id: [] for r in rooms}
    for a, b in sorted(links):
        # A wall too short for a full single door is a last resort.
        cost = float(rng.uniform(0.0, 0.4))
        if links[(a, b)].length < _door_span(SINGLE_WIDTH_M) - 1e-6:
            cost += NARROW_DOOR_COST
        neighbours[a].append((b, cost))
        neighbours[b].append((a, cost))
    dist = {entrance: 0.0}
    parent: dict[str, str | None] = {entrance: None}
    heap: list[tuple[float, str]] = [(0.0, entrance)]
    done: set[str] = set()
    while heap:
        d, room = heapq.heappop(heap)
        if room in done:
            continue
        done.add(room)
        through = 0.0 if room == entrance else PRIVACY.get(types[room], DEFAULT_PRIVACY)
        for nbr, jitter in neighbours[room]:
            cost = d + through + 1.0 + jitter
            if nbr not in dist or cost < dist[nbr] - 1e-12:
                dist[nbr] = cost
                parent[nbr] = room
                heapq.heappush(heap, (cost, nbr))
    missing = sorted(set(types) - done)
    if missing:
        raise SpecError(
            f"rooms {', '.join(repr(m) for m in missing)} cannot be reached from {entrance!r}",
            where="rooms",
            fix=f"make them share at least {_door_span(MIN_DOOR_WIDTH_M):.1f} m of wall "
            "with a reachable room",
        )
    return parent


def _extra_pairs(
    by_id: Mapping[str, Room],
    links: Mapping[tuple[str, str], Wall],
    used: set[tuple[str, ...]],
    count: int,
) -> list[tuple[str, str]]:
    if count <= 0:
        return []
    public = {k for k, v in PRIVACY.items() if v <= 1.5}
    options = [
        pair
        for pair in sorted(links, key=lambda p: (-links[p].length, p))
        if pair not in used
        and normal_type(by_id[pair[0]].type) in public
        and normal_type(by_id[pair[1]].type) in public
    ]
    return options[:count]


def _position(wall: Wall, width: float, rng: np.random.Generator) -> tuple[float, float]:
    slack = max(0.0, (wall.length - width) / 2 - DOOR_CLEARANCE_M)
    t = wall.length / 2 + float(rng.uniform(-1.0, 1.0)) * 0.6 * slack
    lo, hi = DOOR_CLEARANCE_M + width / 2, wall.length - DOOR_CLEARANCE_M - width / 2
    t = min(max(round(t, 2), lo), max(lo, hi))
    x, y = wall.point_at(t)
    return (round(x, 4), round(y, 4))


def _exterior_door(
    room: Room, walls: Sequence[Wall], rng: np.random.Generator, height: float
) -> Door:
    options = [w for w in walls if w.rooms == (room.id,)]
    wall = max(options, key=lambda w: (round(w.length, 6), -walls.index(w)))
    return Door(
        id=f"door_{room.id}_exterior",
        kind="doorway",
        rooms=[room.id],
        position=_position(wall, SINGLE_WIDTH_M, rng),
        leaves="single",
        height=height,
        hinge_side="left" if rng.random() < 0.5 else "right",
        opens_into=room.id,
    )


def _interior_door(
    a: Room,
    b: Room,
    wall: Wall,
    areas: Mapping[str, float],
    kinds: Mapping[str, str] | None,
    rng: np.random.Generator,
    height: float,
) -> Door:
    kind = door_kind(a.type, b.type, kinds)
    leaves: Literal["single", "double"] = "single"
    width = SINGLE_WIDTH_M
    if kind == "open":
        big = min(areas[a.id], areas[b.id]) >= DOUBLE_MIN_ROOM_AREA_M2
        if big and wall.length >= _door_span(DOUBLE_WIDTH_M):
            leaves, width = "double", DOUBLE_WIDTH_M
        else:
            kind = "doorframe"
    if wall.length < _door_span(width):
        width = round(math.floor((wall.length - 2 * DOOR_CLEARANCE_M) * 100) / 100, 2)
    # The leaf swings into the more private room.
    pa = PRIVACY.get(normal_type(a.type), DEFAULT_PRIVACY)
    pb = PRIVACY.get(normal_type(b.type), DEFAULT_PRIVACY)
    into = a.id if pa >= pb else b.id
    return Door(
        id=f"door_{a.id}_{b.id}",
        kind=kind,
        rooms=[a.id, b.id],
        position=_position(wall, width, rng),
        leaves=leaves,
        width=None
        if width == (DOUBLE_WIDTH_M if leaves == "double" else SINGLE_WIDTH_M)
        else width,
        height=height,
        hinge_side="left" if rng.random() < 0.5 else "right",
        opens_into=into,
    )


def reachable(rooms: Sequence[Room | str], doors: Sequence[Door], entrance: str) -> set[str]:
    """Rooms reachable from ``entrance`` through the doors (breadth-first)."""
    ids = {r if isinstance(r, str) else r.id for r in rooms}
    graph: dict[str, set[str]] = {rid: set() for rid in ids}
    for door in doors:
        if len(door.rooms) == 2 and all(r in graph for r in door.rooms):
            a, b = door.rooms
            graph[a].add(b)
            graph[b].add(a)
    if entrance not in graph:
        return set()
    seen = {entrance}
    queue = [entrance]
    while queue:
        room = queue.pop(0)
        for nbr in sorted(graph[room] - seen):
            seen.add(nbr)
            queue.append(nbr)
    return seen


# ---------------------------------------------------------------------------------------------
# Windows


def place_windows(
    rooms: Sequence[Room],
    doors: Sequence[Door],
    rng: np.random.Generator,
    *,
    per_room: Mapping[str, int | WindowRequest | Mapping[str, object]] | None = None,
    kind: WindowKind | None = None,
    base_height: float | None = None,
    wall_height: float = 2.7,
    report: list[str] | None = None,
) -> list[Window]:
    """Windows on the rooms' exterior walls, clear of doors and of each other.

    ``per_room`` maps room ids to a count or a :class:`WindowRequest` (or its fields as a dict);
    when given, rooms it leaves out get no windows. Without it every room gets the default count
    for its type and exterior wall length.
    ``kind`` and ``base_height`` apply to every window not given its own. Windows that do not
    fit are reported in ``report`` (when given), never placed half-way.
    """
    walls = derive_walls(rooms)
    requests = _window_requests(rooms, walls, per_room, kind, base_height)
    taken: dict[str, list[tuple[float, float]]] = {}
    for door in doors:
        wall, t = find_wall_for_opening(walls, door.rooms, door.position, door.effective_width)
        half = door.effective_width / 2
        taken.setdefault(wall.id, []).append((t - half, t + half))
    windows: list[Window] = []
    limit = wall_height - WINDOW_TOP_MARGIN_M
    for room in rooms:
        req = requests.get(room.id)
        if req is None or req.count == 0:
            continue
        wkind = req.kind or WINDOW_KIND_BY_ROOM.get(normal_type(room.type), DEFAULT_WINDOW_KIND)
        base = req.base_height if req.base_height is not None else WINDOW_BASE_HEIGHT_M[wkind]
        sizes = [(w, h) for w, h in window_sizes_m(wkind) if base + h <= limit + 1e-9]
        if not sizes:
            raise SpecError(
                f"no {wkind} window fits below {limit:.2f} m with its base at {base:.2f} m",
                where=f"windows of room {room.id!r}",
                fix="lower base_height, pick another kind or raise wall_height",
            )
        own = [w for w in walls if w.rooms == (room.id,)]
        if req.direction is not None:
            want = DIRECTIONS[req.direction]
            own = [w for w in own if w.outward[0] * want[0] + w.outward[1] * want[1] > 0.99]
        for k in range(req.count):
            placed = _place_one(own, taken, sizes, rng)
            if placed is None:
                if report is not None:
                    report.append(
                        f"room {room.id!r}: window {k + 1} of {req.count} does not fit on its "
                        "exterior walls"
                    )
                break
            wall, t, (w, h) = placed
            taken.setdefault(wall.id, []).append((t - w / 2, t + w / 2))
            x, y = wall.point_at(t)
            windows.append(
                Window(
                    id=f"window_{room.id}_{k}",
                    kind=wkind,
                    rooms=[room.id],
                    position=(round(x, 4), round(y, 4)),
                    width=w,
                    height=h,
                    base_height=base,
                )
            )
    return windows


def _window_requests(
    rooms: Sequence[Room],
    walls: Sequence[Wall],
    per_room: Mapping[str, int | WindowRequest | Mapping[str, object]] | None,
    kind: WindowKind | None,
    base_height: float | None,
) -> dict[str, WindowRequest]:
    ids = [r.id for r in rooms]
    out: dict[str, WindowRequest] = {}
    given = dict(per_room or {})
    for name in given:
        if name not in ids:
            hint = closest_names(name, ids)
            raise SpecError(
                f"unknown room {name!r}",
                where="per_room",
                fix=f"did you mean {hint}?" if hint else f"use one of {', '.join(ids)}",
            )
    for room in rooms:
        value = given.get(room.id)
        if value is None and per_room is not None:
            continue
        if value is None:
            ext = sum(w.length for w in walls if w.rooms == (room.id,))
            cap = WINDOW_CAP_BY_ROOM.get(normal_type(room.type), DEFAULT_WINDOW_CAP)
            count = min(cap, max(1, int(ext // WINDOW_SPACING_M))) if ext > 0 else 0
            req = WindowRequest(count=count)
        elif isinstance(value, int):
            req = WindowRequest(count=value)
        elif isinstance(value, WindowRequest):
            req = value
        else:
            req = WindowRequest.model_validate(value)
        updates: dict[str, object] = {}
        if req.kind is None and kind is not None:
            updates["kind"] = kind
        if req.base_height is None and base_height is not None:
            updates["base_height"] = base_height
        out[room.id] = req.model_copy(update=updates) if updates else req
    return out


def _free_intervals(
    length: float, taken: Sequence[tuple[float, float]]
) -> list[tuple[float, float]]:
    blocked = sorted(
        [(-1.0, WINDOW_GAP_M), (length - WINDOW_GAP_M, length + 1.0)]
        + [(a - WINDOW_GAP_M, b + WINDOW_GAP_M) for a, b in taken]
    )
    free = []
    cursor = -1.0
    for a, b in blocked:
        if a > cursor:
            free.append((cursor, a))
        cursor = max(cursor, b)
    return [(max(a, 0.0), min(b, length)) for a, b in free if min(b, length) - max(a, 0.0) > 0]


def _place_one(
    walls: Sequence[Wall],
    taken: Mapping[str, list[tuple[float, float]]],
    sizes: Sequence[tuple[float, float]],
    rng: np.random.Generator,
) -> tuple[Wall, float, tuple[float, float]] | None:
    stretches = [
        (b - a, wall, a, b)
        for wall in walls
        for a, b in _free_intervals(wall.length, taken.get(wall.id, []))
    ]
    if not stretches:
        return None
    longest = max(s[0] for s in stretches)
    fitting = [s for s in sizes if s[0] <= longest + 1e-9]
    if not fitting:
        return None
    size = fitting[int(rng.integers(len(fitting)))]
    options = [s for s in stretches if s[0] >= size[0] - 1e-9]
    jitter = rng.uniform(0.0, 0.05, size=len(options))
    best = max(range(len(options)), key=lambda i: options[i][0] + float(jitter[i]))
    _, wall, a, b = options[best]
    t = round((a + b) / 2, 2)
    if t - size[0] / 2 < a - 1e-9 or t + size[0] / 2 > b + 1e-9:
        t = (a + b) / 2
    return wall, t, size
