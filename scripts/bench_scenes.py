"""Scenes for the benchmarks: N library objects on a non-overlapping grid in a grid of rooms."""

from __future__ import annotations

import math

from holomj.library import AssetLibrary
from holomj.spec.scene import SceneSpec

ROOM_M = 6.0
CELL_M = 0.9  # grid pitch; objects have footprints of at most MAX_FOOTPRINT_M
MAX_FOOTPRINT_M = 0.7
MARGIN_M = 0.6


def grid_house(library: AssetLibrary, n_objects: int) -> SceneSpec:
    """Square 6 m rooms in a grid with doors between neighbours, objects on a 0.9 m grid."""
    per_side = int((ROOM_M - 2 * MARGIN_M) // CELL_M) + 1
    per_room = per_side * per_side
    n_rooms = max(1, math.ceil(n_objects / per_room))
    cols = math.ceil(math.sqrt(n_rooms))
    rooms, doors = [], []
    for r in range(n_rooms):
        cx, cy = r % cols, r // cols
        x0, y0 = cx * ROOM_M, cy * ROOM_M
        rooms.append(
            {
                "id": f"room_{r}",
                "polygon": [
                    [x0, y0],
                    [x0 + ROOM_M, y0],
                    [x0 + ROOM_M, y0 + ROOM_M],
                    [x0, y0 + ROOM_M],
                ],
            }
        )
        if cx > 0:
            doors.append(
                {
                    "id": f"door_{r}_w",
                    "rooms": [f"room_{r - 1}", f"room_{r}"],
                    "position": [x0, y0 + ROOM_M / 2],
                }
            )
        if cy > 0:
            doors.append(
                {
                    "id": f"door_{r}_s",
                    "rooms": [f"room_{r - cols}", f"room_{r}"],
                    "position": [x0 + ROOM_M / 2, y0],
                }
            )
    doors.append({"id": "front", "rooms": ["room_0"], "position": [0.0, ROOM_M / 2]})
    assets = [
        library.get(i)
        for i in library.ids()
        if i != "builtin:box"
        and max(library.get(i).meta.size[:2]) <= MAX_FOOTPRINT_M
        and set(library.get(i).meta.placement) & {"floor", "object"}
    ]
    objects = []
    for k in range(n_objects):
        room, cell = divmod(k, per_room)
        row, col = divmod(cell, per_side)
        x0, y0 = rooms[room]["polygon"][0]
        asset = assets[k % len(assets)]
        objects.append(
            {
                "id": f"obj_{k:04d}",
                "asset": asset.meta.id,
                "position": [x0 + MARGIN_M + col * CELL_M, y0 + MARGIN_M + row * CELL_M, 0.0],
                "room": f"room_{room}",
            }
        )
    return SceneSpec.model_validate(
        {"name": f"bench {n_objects} objects", "rooms": rooms, "doors": doors, "objects": objects}
    )
