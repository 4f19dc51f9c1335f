"""Rugs: laid under the furniture after the layout, never in its way.

A rug is decor that furniture stands on: it takes no part in the floor layout (other objects
may overlap it) and, in the scene, it is static and has no collider (:data:`DECOR_CATEGORIES`;
a real rug is a few millimetres of compressible cloth, so the furniture's feet sink into its
visual by that much and the physics stays that of the floor).

Where it goes (:func:`lay_rug`): centred under the room's main piece, the first present of
:data:`ANCHOR_CATEGORIES` (a coffee table, a dining table, a bed, ...), its long side along the
piece's long side; else in the middle of the room. Several rugs (:func:`lay_rugs`: "rubber mats
on the floor") go one after the other, each clear of those before it: under the main piece,
in the middle, then under the other pieces, biggest first, then anywhere on the floor. A rug
is shifted towards the room's centre, then scaled down (to at most :data:`MIN_SCALE`), until it
lies inside the room with :data:`WALL_MARGIN_M` to spare; otherwise it is not placed, with the
reason.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from shapely import affinity
from shapely.geometry import Point, Polygon, box

ANCHOR_CATEGORIES = ("coffee_table", "dining_table", "bed", "bunk_bed", "sofa", "desk")
WALL_MARGIN_M = 0.1
MIN_SCALE = 0.6
_STEPS = 10


@dataclass(frozen=True)
class Anchor:
    """A placed floor object a rug may go under: centre, yaw, size and category."""

    x: float
    y: float
    yaw_deg: float
    width: float
    depth: float
    category: str


@dataclass(frozen=True)
class RugPose:
    """Where a rug lies: centre, yaw (degrees) and the uniform scale of its footprint."""

    x: float
    y: float
    yaw_deg: float
    scale: float


def lay_rug(
    room: Polygon,
    size: tuple[float, float],
    anchors: Sequence[Anchor],
    avoid: Sequence[Polygon] = (),
    middle: bool = True,
) -> RugPose | str:
    """The pose of a rug of ``size`` (depth along its x, width along its y) in ``room``, or
    why it does not fit.

    Spots are tried in order: under the main piece (the first of :data:`ANCHOR_CATEGORIES`),
    the room's middle (unless not ``middle``), then under every other piece, biggest first; a
    rug must not lie on the rugs of ``avoid`` (those laid before it), and when none of these
    spots is clear of them, any spot of the floor will do."""
    main = [a for c in ANCHOR_CATEGORIES for a in anchors if a.category == c]
    rest = sorted(
        (a for a in anchors if a not in main), key=lambda a: a.width * a.depth, reverse=True
    )
    inner = room.buffer(-WALL_MARGIN_M, join_style="mitre")
    if inner.is_empty:
        return "the room is too small for a rug"
    centre: list[Anchor | None] = [None] if middle else []
    for anchor in [*main[:1], *centre, *main[1:], *rest]:
        pose = _fit(room, inner, size, anchor, avoid)
        if pose is not None:
            return pose
    pose = _anywhere(inner, size, avoid)
    if pose is not None:
        return pose
    if avoid:
        return f"no free floor for another {size[1]:.2f} x {size[0]:.2f} m rug"
    return (
        f"a {size[1]:.2f} x {size[0]:.2f} m rug does not fit in the room even at "
        f"{MIN_SCALE:.0%} of its size"
    )


def lay_rugs(
    room: Polygon, sizes: Sequence[tuple[float, float]], anchors: Sequence[Anchor]
) -> list[RugPose | str]:
    """Poses of several rugs, one after the other (:func:`lay_rug`), none on another; several
    rugs go under the pieces rather than one in the middle taking the floor from the rest."""
    laid: list[Polygon] = []
    out: list[RugPose | str] = []
    for size in sizes:
        pose = lay_rug(room, size, anchors, laid, middle=len(sizes) == 1)
        if isinstance(pose, RugPose):
            laid.append(_footprint(pose.x, pose.y, pose.yaw_deg, size, pose.scale))
        out.append(pose)
    return out


def _fit(
    room: Polygon,
    inner: Polygon,
    size: tuple[float, float],
    anchor: Anchor | None,
    avoid: Sequence[Polygon],
) -> RugPose | None:
    """The rug under ``anchor`` (None: the room's middle), shifted towards the room's centre
    and scaled down until it lies inside and clear of ``avoid``; None when it cannot."""
    centre = room.representative_point() if room.centroid.within(room) else room.centroid
    if anchor is None:
        x, y, yaw = room.centroid.x, room.centroid.y, _yaw_along_room(room)
    else:
        x, y = anchor.x, anchor.y
        # the rug's width (its y) is its long side: along world x at yaw 90
        yaw = 90.0 if _long_axis_is_x(anchor) else 0.0
    scale = 1.0
    while scale >= MIN_SCALE - 1e-9:
        for step in range(_STEPS + 1):
            t = step / _STEPS
            cx, cy = x + (centre.x - x) * t, y + (centre.y - y) * t
            footprint = _footprint(cx, cy, yaw, size, scale)
            if footprint.within(inner) and not any(
                footprint.intersection(other).area > 1e-6 for other in avoid
            ):
                return RugPose(round(cx, 4), round(cy, 4), yaw, round(scale, 3))
        scale -= 0.1
    return None


GRID_STEP_M = 0.25  # spots tried for a rug that fits under no piece clear of the others


def _anywhere(
    inner: Polygon, size: tuple[float, float], avoid: Sequence[Polygon]
) -> RugPose | None:
    """The largest rug (down to :data:`MIN_SCALE`) on any spot of a grid over the room, clear
    of ``avoid``: the first spot found, largest scale first."""
    xmin, ymin, xmax, ymax = inner.bounds
    xs = [xmin + GRID_STEP_M * (i + 0.5) for i in range(int((xmax - xmin) / GRID_STEP_M))]
    ys = [ymin + GRID_STEP_M * (j + 0.5) for j in range(int((ymax - ymin) / GRID_STEP_M))]
    scale = 1.0
    while scale >= MIN_SCALE - 1e-9:
        for yaw in (0.0, 90.0):
            for x in xs:
                for y in ys:
                    footprint = _footprint(x, y, yaw, size, scale)
                    if footprint.within(inner) and not any(
                        footprint.intersection(other).area > 1e-6 for other in avoid
                    ):
                        return RugPose(round(x, 4), round(y, 4), yaw, round(scale, 3))
        scale -= 0.1
    return None


def _long_axis_is_x(anchor: Anchor) -> bool:
    quarter = round(anchor.yaw_deg / 90.0) % 2
    # at yaw 0 an object's width runs along world y and its depth along x
    along_x = anchor.depth if quarter == 0 else anchor.width
    along_y = anchor.width if quarter == 0 else anchor.depth
    return along_x >= along_y


def _yaw_along_room(room: Polygon) -> float:
    xmin, ymin, xmax, ymax = room.bounds
    return 90.0 if xmax - xmin >= ymax - ymin else 0.0


def _footprint(x: float, y: float, yaw: float, size: tuple[float, float], scale: float) -> Polygon:
    depth, width = size[0] * scale, size[1] * scale
    rect = box(-depth / 2, -width / 2, depth / 2, width / 2)
    return affinity.translate(affinity.rotate(rect, yaw, origin=Point(0, 0)), x, y)
