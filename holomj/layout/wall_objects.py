"""Wall objects (paintings, mirrors, shelves, wall cabinets, TVs, clocks) and ceiling lights.

A wall object hangs on the interior face of one of its room's walls: interior walls are centred
on the room edge, so their face is ``wall_thickness / 2`` into the room; exterior walls grow
outwards, so their face is the room edge itself. The object's back touches the face and its
front (+X) points into the room; its position is the centre of its footprint at its bottom, as
for every SceneObject.

Heights (``WALL_HEIGHTS``): the default z of a kind, given as the height of its centre or of its
bottom. ``height_m`` in a request overrides it (always the bottom). An object ``above`` a floor
object is centred over it, on the wall nearest to it, at least ``ABOVE_GAP_M`` above its top (a
TV sits exactly that far above its stand); a TV whose stand's wall is taken (by a window, say)
goes to the widest free stretch of wall instead, and the placement says so.

============  ===================
kind          default height
============  ===================
painting      centre at 1.5 m
mirror        centre at 1.4 m
clock         centre at 1.8 m
wall_cabinet  bottom at 1.45 m
shelf         bottom at 1.3 m
television    centre at 1.2 m
whiteboard    centre at 1.4 m
other         centre at 1.5 m
============  ===================

Nothing may overlap, in the wall plane, a door with its frame (up to the header, and the whole
height for ``open`` doors; an object deeper than ``DEEP_M``, a wall cabinet, also keeps
``DOOR_SIDE_M`` beside the frame, so that the way through the door stays wide), a window with
its frame, another wall object (checked in 3D, so objects on two walls meeting at a corner are
caught), or floor furniture near the wall that rises above the object's bottom.

A deep object hung lower than ``HEAD_BAND_M`` (a wall cabinet) goes over furniture against the
wall (a counter run) when it can; over open floor it wants ``FRONT_CLEAR_M`` free in front of it
and ``SIDE_CLEAR_M`` beside its ends, so that it narrows no way and cuts off no corner, and one
the prompt did not ask for is left out (with the reason) rather than hung where it would.

Curtains and blinds (kinds ``curtains`` and ``blinds``, ``DRESSING_KINDS``) are the exception:
they hang at the room's windows, sized to them, and are placed before everything else (see
:mod:`holomj.layout.window_dressing`). The geometry of wall faces is in
:mod:`holomj.layout.wall_faces`, the search for each object's spot (and the distances named
here) in :mod:`holomj.layout.wall_spots`, the ceiling lights in
:mod:`holomj.layout.ceiling_lights`.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Annotated

import numpy as np
from pydantic import Field
from shapely.geometry import Polygon

from holomj.layout.ceiling_lights import ceiling_lights
from holomj.layout.wall_faces import (
    CEILING_GAP_M,
    END_MARGIN_M,
    OBJECT_GAP_M,
    OPENING_MARGIN_M,
    FloorItem,
    PlacedBox,
    Unplaced,
    WallFace,
    WallPlacement,
    WallSite,
    face_point,
    face_rect,
    room_faces,
)
from holomj.layout.wall_spots import place_above, place_faced, place_free
from holomj.layout.window_dressing import DRESSING_KINDS, DressingRequest, dress_windows
from holomj.spec.base import FrozenModel, Identifier, PositiveFloat
from holomj.spec.categories import normal_type
from holomj.spec.scene import Door, Room, Window
from holomj.spec.walls import Wall

__all__ = [
    "ABOVE_GAP_M",
    "CEILING_GAP_M",
    "DRESSING_KINDS",
    "END_MARGIN_M",
    "OBJECT_GAP_M",
    "OPENING_MARGIN_M",
    "FloorItem",
    "Unplaced",
    "WallObjectRequest",
    "WallPlacement",
    "ceiling_lights",
    "default_bottom",
    "place_wall_objects",
]

# (reference, metres): reference "centre" or "bottom".
WALL_HEIGHTS: dict[str, tuple[str, float]] = {
    "painting": ("centre", 1.5),
    "mirror": ("centre", 1.4),
    "clock": ("centre", 1.8),
    "wall_cabinet": ("bottom", 1.45),
    "shelf": ("bottom", 1.3),
    "television": ("centre", 1.2),
    "whiteboard": ("centre", 1.4),
}
DEFAULT_WALL_HEIGHT = ("centre", 1.5)
ABOVE_GAP_M = 0.1  # between a floor object's top and the wall object above it


class WallObjectRequest(FrozenModel):
    """A wall object to place: size (width along the wall, depth, height), where and how high."""

    id: Identifier
    size: tuple[PositiveFloat, PositiveFloat, PositiveFloat]
    kind: str = Field(default="painting", max_length=64)
    above: Identifier | None = None
    faced_by: Identifier | None = Field(
        default=None, description="Hang where this floor object looks (its front ray)."
    )
    height_m: Annotated[float, Field(ge=0.0, le=20.0)] | None = Field(
        default=None, description="Height of the object's bottom; default by kind."
    )
    optional: bool = Field(
        default=False,
        description="Not asked for: a wall cabinet that would narrow the way is left out.",
    )


def default_bottom(kind: str, height: float) -> float:
    """Default z of the bottom of a wall object of this kind and height."""
    ref, value = WALL_HEIGHTS.get(normal_type(kind), DEFAULT_WALL_HEIGHT)
    return value - height / 2 if ref == "centre" else value


def place_wall_objects(
    room: Room,
    walls: Sequence[Wall],
    doors: Sequence[Door],
    windows: Sequence[Window],
    floor_objects: Sequence[FloorItem | tuple[str, Polygon, float]],
    requests: Sequence[WallObjectRequest],
    rng: np.random.Generator,
    *,
    wall_height: float = 2.7,
    wall_thickness: float = 0.1,
) -> tuple[list[WallPlacement], list[Unplaced]]:
    """Hang the requested objects on the walls of ``room``; report the ones that do not fit.

    ``walls`` are the scene's walls (``derive_walls``); ``floor_objects`` are (id, footprint
    polygon, height) of the floor furniture already placed. Requests are handled in order; a
    free object goes to the middle of the widest free stretch at its height (ties broken by
    ``rng``), an object ``above`` a floor object is centred over it or reported.
    """
    floor = [
        f if isinstance(f, FloorItem) else FloorItem(f[0], Polygon(f[1]), float(f[2]))
        for f in floor_objects
    ]
    by_id = {f.id: f for f in floor}
    faces = room_faces(room, walls, wall_thickness)
    site = WallSite(faces, walls, doors, windows, floor, [], wall_height)
    # Curtains and blinds first: they belong at windows, everything else can go elsewhere.
    dressings = [r for r in requests if normal_type(r.kind) in DRESSING_KINDS]
    result, unplaced = dress_windows(
        room, site, [DressingRequest(r.id, normal_type(r.kind), r.size) for r in dressings]
    )
    for req in requests:
        if normal_type(req.kind) in DRESSING_KINDS:
            continue
        width, depth, height = req.size
        if req.above is not None and req.above not in by_id:
            unplaced.append(Unplaced(req.id, f"unknown floor object {req.above!r} to hang above"))
            continue
        base = _bottom(req, by_id)
        z1 = base + height
        if z1 > wall_height - CEILING_GAP_M + 1e-9:
            unplaced.append(
                Unplaced(
                    req.id, f"top at {z1:.2f} m would reach the wall top ({wall_height:.2f} m)"
                )
            )
            continue
        outcome, base, note = _hang(req, by_id, site, base, rng)
        z1 = base + height
        if isinstance(outcome, str):
            unplaced.append(Unplaced(req.id, outcome))
            continue
        face, t = outcome
        foot = face_rect(face, t, width, depth)
        site.placed.append(PlacedBox(foot, base, z1, face.wall.id, t - width / 2, t + width / 2))
        x, y = face_point(face, t, depth / 2)
        yaw = math.degrees(math.atan2(face.inward[1], face.inward[0]))
        result.append(
            WallPlacement(
                id=req.id,
                x=round(x, 4),
                y=round(y, 4),
                z=round(base, 4),
                yaw_deg=round(yaw, 4) + 0.0,
                wall_id=face.wall.id,
                room=room.id,
                note=note,
            )
        )
    order = {req.id: k for k, req in enumerate(requests)}
    result.sort(key=lambda p: order[p.id])
    unplaced.sort(key=lambda u: order[u.id])
    return result, unplaced


def _bottom(req: WallObjectRequest, by_id: Mapping[str, FloorItem]) -> float:
    """The height of the object's bottom: the asked one or its kind's, and above the floor
    object it hangs over (a TV asked at no height sits just above its stand)."""
    base = req.height_m if req.height_m is not None else default_bottom(req.kind, req.size[2])
    if req.above is not None:
        top = by_id[req.above].height + ABOVE_GAP_M
        if normal_type(req.kind) == "television" and req.height_m is None:
            base = top
        base = max(base, top)
    return max(base, 0.0)


def _hang(
    req: WallObjectRequest,
    by_id: Mapping[str, FloorItem],
    site: WallSite,
    base: float,
    rng: np.random.Generator,
) -> tuple[tuple[WallFace, float] | str, float, str | None]:
    """Where on the walls the object hangs with its bottom at ``base`` (or why nowhere), the
    bottom it hangs at, and a note when it is not where it was meant to be: where its looker
    looks (``faced_by``), over its floor object (``above``: a TV that finds the wall there
    taken goes elsewhere at a TV's height), else on the widest free stretch."""
    note = None
    looker = by_id.get(req.faced_by) if req.faced_by is not None else None
    if looker is not None and looker.front is not None and req.above is None:
        outcome = place_faced(req.size, looker, site, base)
        if isinstance(outcome, str):
            fallback = place_free(req.size, req.optional, site, base, rng)
            if not isinstance(fallback, str):
                note = f"{outcome}: hung on the widest free stretch instead"
                outcome = fallback
        return outcome, base, note
    if req.above is None:
        return place_free(req.size, req.optional, site, base, rng), base, None
    outcome = place_above(req.size, by_id[req.above], site, base)
    if isinstance(outcome, str) and normal_type(req.kind) == "television":
        # A TV is always placed: when the wall over its stand is taken, on the widest free
        # stretch of wall at a TV's height.
        free_base = req.height_m if req.height_m is not None else base
        fallback = place_free(req.size, req.optional, site, free_base, rng)
        if not isinstance(fallback, str):
            return fallback, free_base, f"{outcome}: hung on another wall"
    return outcome, base, note
