"""Curtains and blinds: each hangs at one of its room's windows, sized to the window.

The wall-object placer (:func:`holomj.layout.wall_objects.place_wall_objects`) hands every
request of a dressing kind (``DRESSING_KINDS``) to :func:`dress_windows` before it hangs
anything else, so paintings and shelves keep clear of the dressings rather than the reverse.

Windows are dressed largest first (area), then the one most central on its wall, then by id;
each window takes one dressing, and each request takes the first undressed window where it fits.

**Curtains** are centred on the window with their top (the rod) ``ROD_ABOVE_M`` above the
window's top (less when the ceiling is near, down to ``ROD_ABOVE_MIN_M``), ``CURTAIN_OVERHANG_M``
wider than the window on each side (less, down to ``MIN_OVERHANG_M``, when a door, another
window, a wall end, another wall object or furniture is beside it) and hang to
``FLOOR_GAP_M`` above the floor. When furniture stands under the window (a bed, a desk), they
are sill length instead: they end just under the window frame (or at the sill), above the
furniture; the placement's note says so.

**Blinds** hang over the opening: ``BLIND_OVERLAP_M`` wider than the window on each side, from
the sill to ``BLIND_ABOVE_M`` above the window's top. Furniture under the window is fine as long
as it stays below the sill.

The asset is stretched to that size with a per-axis scale (x, its depth, is left alone), the
asset's top being its rod or headrail. Both stand ``STANDOFF_M`` in front of the wall face, so
they clear the window frame (which stands ``FRAME_PROUD_M`` proud of the face) and the wall.

**Colliders.** Dressings stay static objects with ordinary colliders, like every wall object: a
robot meets a curtain as it would a stiff panel, and small objects cannot fall behind it. Static
bodies cannot move, so they cannot make a scene unstable; the penetration audit can only catch
a collider that starts inside something, which this placement rules out: the standoff keeps the
colliders off the wall, its window's glass and frame, the floor gap keeps them off the floor,
and the checks here keep them clear of doors' swing zones, furniture and other wall objects.

Every request ends up placed or in the unplaced list with its reason: a room with no window,
more dressings than windows ("no window left for ..."), or windows where nothing fits.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

from shapely.geometry import Polygon

from holomj.errors import SpecError
from holomj.layout.wall_faces import (
    CEILING_GAP_M,
    OPENING_MARGIN_M,
    PlacedBox,
    Unplaced,
    WallFace,
    WallPlacement,
    WallSite,
    face_rect,
    fits_on,
    hits_placed,
)
from holomj.spec.scene import Room, Window
from holomj.spec.walls import Wall, find_wall_for_opening

DRESSING_KINDS = frozenset({"curtains", "blinds"})

# Window frames stand this far proud of the wall faces (holomj.mjcf.opening_geometry's
# FRAME_DEPTH_EXTRA; a test keeps the two equal).
FRAME_PROUD_M = 0.02
STANDOFF_M = FRAME_PROUD_M + 0.01  # a dressing's back, in front of the wall face
ROD_ABOVE_M = 0.12  # curtain rod (the asset's top) above the window's top
ROD_ABOVE_MIN_M = 0.03
CURTAIN_OVERHANG_M = 0.175  # curtains are wider than the window by this on each side
MIN_OVERHANG_M = OPENING_MARGIN_M  # at least the window frame stays covered
OVERHANG_STEP_M = 0.025
FLOOR_GAP_M = 0.01  # floor-length curtains end this far above the floor
BLIND_OVERLAP_M = 0.03  # blinds are wider than the window by this on each side
BLIND_ABOVE_M = 0.05  # headrail top above the window's top
FURNITURE_GAP_M = 0.01  # between a dressing and the furniture around it


@dataclass(frozen=True)
class DressingRequest:
    """A curtain or blind to hang: its kind and the asset's natural size (width, depth, height)."""

    id: str
    kind: str
    size: tuple[float, float, float]


@dataclass(frozen=True)
class _Opening:
    window: Window
    face: WallFace
    t: float  # the window's centre along its wall


@dataclass(frozen=True)
class _Fit:
    t: float
    width: float
    z0: float
    z1: float
    note: str | None


def dress_windows(
    room: Room, site: WallSite, requests: Sequence[DressingRequest]
) -> tuple[list[WallPlacement], list[Unplaced]]:
    """Hang each curtain or blind at one window of ``room``; report the ones that find none.

    ``site``: the room's wall faces and what stands at them (only this room's windows are
    dressed). What is hung is appended to ``site.placed`` so that later wall objects keep clear
    of it.
    """
    openings = _room_openings(room, site.faces, site.walls, site.windows)
    result: list[WallPlacement] = []
    unplaced: list[Unplaced] = []
    dressed: set[str] = set()
    for req in requests:
        free = [o for o in openings if o.window.id not in dressed]
        if not openings:
            unplaced.append(
                Unplaced(req.id, f"room {room.id!r} has no window to hang {req.kind} at")
            )
            continue
        if not free:
            ids = ", ".join(o.window.id for o in openings)
            unplaced.append(
                Unplaced(
                    req.id,
                    f"no window left for {req.kind} {req.id}: every window of room "
                    f"{room.id!r} ({ids}) is already dressed",
                )
            )
            continue
        reasons = []
        for opening in free:
            fit = _fit(req, opening, room, site)
            if isinstance(fit, str):
                reasons.append(f"{opening.window.id}: {fit}")
                continue
            dressed.add(opening.window.id)
            result.append(_placement(req, opening, fit, room, site.placed))
            break
        else:
            unplaced.append(
                Unplaced(req.id, f"no window of room {room.id!r} takes it ({'; '.join(reasons)})")
            )
    return result, unplaced


def _room_openings(
    room: Room, faces: Sequence[WallFace], walls: Sequence[Wall], windows: Sequence[Window]
) -> list[_Opening]:
    """The room's windows on its wall faces, in the order they are dressed."""
    by_wall = {f.wall.id: f for f in faces}
    out = []
    for window in windows:
        if room.id not in window.rooms:
            continue
        try:
            wall, t = find_wall_for_opening(walls, window.rooms, window.position, window.width)
        except SpecError:  # not on a wall of this scene: the shell reports such windows
            continue
        if wall.id in by_wall:
            out.append(_Opening(window, by_wall[wall.id], t))
    out.sort(
        key=lambda o: (
            -round(o.window.width * o.window.height, 6),
            round(abs(o.t - o.face.wall.length / 2), 6),
            o.window.id,
        )
    )
    return out


def _fit(req: DressingRequest, opening: _Opening, room: Room, site: WallSite) -> _Fit | str:
    """The size and height of ``req`` at ``opening``, or why it does not fit there."""
    window = opening.window
    top_of_window = window.base_height + window.height
    ceiling = site.wall_height - CEILING_GAP_M
    curtains = req.kind == "curtains"
    above, above_min = (ROD_ABOVE_M, ROD_ABOVE_MIN_M) if curtains else (BLIND_ABOVE_M, 0.0)
    top = min(top_of_window + above, ceiling)
    if top < top_of_window + above_min - 1e-9:
        return f"the window's top ({top_of_window:.2f} m) is too near the ceiling for {req.kind}"
    if curtains:
        bottoms: list[tuple[float, str | None]] = [(FLOOR_GAP_M, None)]
        for z, sill in (
            (window.base_height - OPENING_MARGIN_M, "sill length, under the window frame"),
            (window.base_height, "sill length"),
        ):
            if z > bottoms[-1][0] + 1e-9:
                bottoms.append((z, sill))
        overhangs = _steps(CURTAIN_OVERHANG_M, MIN_OVERHANG_M)
    else:
        bottoms = [(max(window.base_height, FLOOR_GAP_M), None)]
        overhangs = [BLIND_OVERLAP_M, 0.0]
    swings = _door_zones(room, site)
    failures: list[str] = []  # what the narrowest dressing meets, at each bottom tried
    for z0, label in bottoms:
        widest: str | None = None  # what the widest one meets at this bottom
        for overhang in overhangs:
            width = window.width + 2 * overhang
            why = _blocked(req, opening, width, z0, top, site, swings)
            if why is None:
                notes = []
                if label is not None:
                    notes.append(f"{label}: floor length would meet {failures[0]}")
                if widest is not None and curtains:
                    notes.append(f"{overhang:.3f} m wider than the window each side: {widest}")
                return _Fit(opening.t, width, z0, top, "; ".join(notes) or None)
            widest = widest or why
        assert why is not None  # every width was tried and failed
        failures.append(why)
    tried = ", then ".join(failures)
    return f"{req.kind} {req.id} would meet {tried}"


def _steps(high: float, low: float) -> list[float]:
    count = max(0, round((high - low) / OVERHANG_STEP_M))
    return [round(high - k * OVERHANG_STEP_M, 4) for k in range(count)] + [low]


def _blocked(
    req: DressingRequest,
    opening: _Opening,
    width: float,
    z0: float,
    z1: float,
    site: WallSite,
    swings: Sequence[tuple[Polygon, float, str]],
) -> str | None:
    """What a dressing ``width`` wide from ``z0`` to ``z1`` at ``opening`` would meet, if
    anything."""
    face, t = opening.face, opening.t
    if not fits_on(face, t, width):
        return f"the end of wall {face.wall.id}"
    depth = req.size[1]
    foot = face_rect(face, t, width, depth, STANDOFF_M)
    for other in site.windows:
        if other.id == opening.window.id:
            continue
        try:
            wall, ot = find_wall_for_opening(site.walls, other.rooms, other.position, other.width)
        except SpecError:
            continue
        if wall.id != face.wall.id:
            continue
        half = other.width / 2 + OPENING_MARGIN_M
        oz0 = other.base_height - OPENING_MARGIN_M
        oz1 = other.base_height + other.height + OPENING_MARGIN_M
        if _overlap(t - width / 2, t + width / 2, ot - half, ot + half) and _overlap(
            z0, z1, oz0, oz1
        ):
            return f"window {other.id}"
    for zone, height, what in swings:
        if z0 < height and foot.intersects(zone) and foot.intersection(zone).area > 1e-9:
            return what
    for item in site.floor:
        if item.height > z0 + 1e-9 and item.footprint.distance(foot) < FURNITURE_GAP_M:
            return f"floor object {item.id}"
    if hits_placed(foot, z0, z1, site.placed):
        return "another wall object"
    return None


def _overlap(a0: float, a1: float, b0: float, b1: float) -> bool:
    return a0 < b1 - 1e-9 and b0 < a1 - 1e-9


def _door_zones(room: Room, site: WallSite) -> list[tuple[Polygon, float, str]]:
    """For each door of the room: the floor in front of it on the room's side, as deep as the
    door is wide (where its leaves swing and people pass), with its height (none for an open
    doorway, which is as high as the wall)."""
    by_wall = {f.wall.id: f for f in site.faces}
    zones = []
    for door in site.doors:
        if room.id not in door.rooms:
            continue
        width = door.effective_width
        try:
            wall, t = find_wall_for_opening(site.walls, door.rooms, door.position, width)
        except SpecError:
            continue
        face = by_wall.get(wall.id)
        if face is None:
            continue
        zone = face_rect(face, t, width + 2 * OPENING_MARGIN_M, width + face.offset, -face.offset)
        height = math.inf if door.kind == "open" else door.height + OPENING_MARGIN_M
        zones.append((zone, height, f"door {door.id}"))
    return zones


def _placement(
    req: DressingRequest, opening: _Opening, fit: _Fit, room: Room, placed: list[PlacedBox]
) -> WallPlacement:
    width0, depth, height0 = req.size
    face = opening.face
    foot = face_rect(face, fit.t, fit.width, depth, STANDOFF_M)
    placed.append(
        PlacedBox(foot, fit.z0, fit.z1, face.wall.id, fit.t - fit.width / 2, fit.t + fit.width / 2)
    )
    centre = foot.centroid
    yaw = math.degrees(math.atan2(face.inward[1], face.inward[0]))
    scale = (1.0, round(fit.width / width0, 4), round((fit.z1 - fit.z0) / height0, 4))
    return WallPlacement(
        id=req.id,
        x=round(centre.x, 4),
        y=round(centre.y, 4),
        z=round(fit.z0, 4),
        yaw_deg=round(yaw, 4) + 0.0,
        wall_id=face.wall.id,
        room=room.id,
        note=fit.note,
        scale=None if scale == (1.0, 1.0, 1.0) else scale,
    )
