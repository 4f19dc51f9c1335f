"""THOR's L- and U-shaped countertops in their real shape: counter runs, not one solid box.

AI2-THOR's ``Countertop_L_WxD`` and ``Countertop_C_WxD`` (``C``: a U seen from above) are one
asset each, whose bounding box covers the whole corner of the kitchen: standing in for them
with one counter scaled to that box would fill the corner with a solid block. They are built
instead as counter runs of THOR's counter depth (:data:`COUNTER_DEPTH_M`, its 2 ft):

* the **back** run along the back of the bounding box (holomj's object frame: the front faces
  +X, so the back is at -X), across its whole width;
* **side** runs from the back run to the front, along the box's sides: both for a ``C``; for
  an ``L`` the side nearer to a wall of its room (the open side of an L faces the room).

The first run keeps the object's id (what rests on the counter keeps its support); the others
are ``<id>_side_left`` / ``<id>_side_right``. A side run is turned to face into the shape. Each
run gets its own stand-in at its size; what rested on the countertop rests on the run under
it (the nearest).
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from dataclasses import dataclass

from shapely.geometry import Point, Polygon

from holomj.importers.frames import normalise_deg
from holomj.spec.scene import SceneObject

COUNTER_DEPTH_M = 0.6106  # THOR's straight counter depth (Countertop_I_4x2)
SHAPED = re.compile(r"^countertop_([lc])_", re.IGNORECASE)

Size = tuple[float, float, float]
# (object id, size (depth, width, height)) -> (asset, scale) of a stand-in for one run
ChooseRun = Callable[[str, Size], tuple[str, float | Size]]


def counter_shape(asset_id: str) -> str | None:
    """``"L"`` or ``"C"`` for THOR's shaped countertops, else None."""
    found = SHAPED.match(asset_id)
    return found.group(1).upper() if found else None


@dataclass(frozen=True)
class _CounterRun:
    suffix: str
    centre: tuple[float, float]  # in the object's frame
    size: Size  # in the run's own frame (depth, width, height)
    turn_deg: float


def split_counter(
    obj: SceneObject,
    shape: str,
    size: Size,
    room: Polygon | None,
    choose: ChooseRun,
) -> list[SceneObject]:
    """``obj`` (an ``L`` or ``C`` countertop of true ``size``) as its counter runs."""
    depth, width, height = size
    d = min(COUNTER_DEPTH_M, depth / 2, width / 2)
    side_length = depth - d
    runs = [_CounterRun("", (-depth / 2 + d / 2, 0.0), (d, width, height), 0.0)]
    sides = [
        _CounterRun("_side_left", (d / 2, width / 2 - d / 2), (d, side_length, height), -90.0),
        _CounterRun("_side_right", (d / 2, -width / 2 + d / 2), (d, side_length, height), 90.0),
    ]
    if shape == "C":
        runs += sides
    else:
        runs.append(min(sides, key=lambda r: _wall_distance(obj, r, room)))
    result = []
    for run in runs:
        x, y = _world(obj, run.centre)
        run_id = f"{obj.id}{run.suffix}"[:128]
        asset, scale = choose(run_id, run.size)
        result.append(
            obj.model_copy(
                update={
                    "id": run_id,
                    "asset": asset,
                    "scale": scale,
                    "position": (x, y, obj.position[2]),
                    "yaw_deg": normalise_deg(obj.yaw_deg + run.turn_deg),
                    "quat": None,
                }
            )
        )
    return result


def nearest_run(runs: list[SceneObject], x: float, y: float) -> str:
    """The id of the run whose centre is nearest to ``(x, y)``."""
    return min(runs, key=lambda r: math.hypot(r.position[0] - x, r.position[1] - y)).id


def _world(obj: SceneObject, local: tuple[float, float]) -> tuple[float, float]:
    yaw = math.radians(obj.yaw_deg)
    c, s = math.cos(yaw), math.sin(yaw)
    lx, ly = local
    return (obj.position[0] + c * lx - s * ly, obj.position[1] + s * lx + c * ly)


def _wall_distance(obj: SceneObject, run: _CounterRun, room: Polygon | None) -> float:
    """How far the run's centre is from its room's walls (0 without a room)."""
    if room is None:
        return 0.0
    return room.exterior.distance(Point(*_world(obj, run.centre)))
