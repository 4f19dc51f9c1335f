"""Rules every placer of furniture shares (generate's furnishing and the edit operations): the
walkway and door clearances the layout keeps, the categories that are fixtures, the wall-object
kind of each wall category, and the scene id of a plan instance."""

from __future__ import annotations

import re

# The layout keeps a walkway this wide (radius) between every two doors of a room: 5 cm more than
# the navigation map's agent, so that its finer grid and real collider boxes still find the path.
WALKER_RADIUS_M = 0.3
DOOR_CLEARANCE_M = 1.0  # floor kept free in front of a door, on the room's side
# Floor objects of the categories that are bolted down or plumbed in in real homes are static
# fixtures; all other furniture gets a free joint, so validation puts it to the test.
FIXED_CATEGORIES = frozenset(
    {
        "kitchen_counter",
        "sink_counter",
        "stove",
        "base_cabinet",
        "toilet",
        "bathtub",
        "shower_tray",
        "washbasin",
    }
)
# Library category -> wall-object kind of holomj.layout.wall_objects (default heights).
WALL_KINDS = {
    "painting": "painting",
    "mirror": "mirror",
    "clock": "clock",
    "whiteboard": "whiteboard",
    "kitchen_cabinet": "wall_cabinet",
    "wall_cabinet": "wall_cabinet",
    "shelf": "shelf",
    "television": "television",
    "wall_television": "television",
    # Window dressings hang at the room's windows (holomj.layout.window_dressing).
    "curtains": "curtains",
    "blinds": "blinds",
}


def object_id(room_id: str, instance: str) -> str:
    """Scene id of a plan instance: ``("living_room", "coffee table-0")`` ->
    ``living_room.coffee_table_0``."""
    stem = re.sub(r"[^a-z0-9]+", "_", instance.lower()).strip("_")
    return f"{room_id}.{stem}"
