"""The words the LLM planner sends: a system message and one user message per step.

The protocol follows Holodeck's order of questions (floor plan, wall height, doors, windows,
objects per room, layout constraints per room), asked in our own words. Every step asks for one
JSON object in a fixed shape, shows that shape by example, and carries the decisions of earlier
steps (as the corrected data we kept, not the raw answers) so each answer builds on the last.
"""

from __future__ import annotations

import json
from collections.abc import Sequence
from typing import Any

from holomj.layout.constraints import KIND_PHRASE

SYSTEM = (
    "You plan indoor scenes for a physics simulator. Each message asks one question about the "
    "scene. Reply with a single JSON object in exactly the shape the question shows: no prose "
    "before or after it, no comments inside it, no code. Units are metres unless a field's name "
    "says otherwise (size_cm is in centimetres). Keep the scene realistic and modest: furniture "
    "must fit the rooms with space to walk between pieces."
)

MAX_CATEGORIES_SHOWN = 400


def _dump(data: Any) -> str:
    """An example answer: indented, to show the shape."""
    return json.dumps(data, indent=1, ensure_ascii=False)


def _data(data: Any) -> str:
    """Earlier decisions: one line, to save tokens."""
    return json.dumps(data, ensure_ascii=False)


def floor_plan(request: str) -> str:
    """Step 1: scene type, style words and rectangular rooms."""
    example = {
        "scene_type": "apartment",
        "style": ["scandinavian", "bright"],
        "rooms": [
            {
                "id": "living_room",
                "type": "living room",
                "width_m": 5.5,
                "depth_m": 4.2,
                "floor_material": "light oak planks",
                "wall_material": "warm white paint",
            }
        ],
    }
    return (
        f"The request: {request!r}\n\n"
        "Step 1 of the plan: the floor plan. Decide what kind of place this is (scene_type, "
        "one or two words) and which rooms it needs. Every room is a rectangle; give its width "
        "and depth in metres, each between 2.5 and 8. Ids are short snake_case names, unique. "
        "Materials are short descriptions of what the floor and the walls look like. Use as few "
        "rooms as the request allows (a single room when it asks for one room).\n\n"
        f"Answer in this shape:\n{_dump(example)}"
    )


def wall_height(request: str, plan: dict[str, Any]) -> str:
    """Step 2: one wall height for all rooms."""
    return (
        f"The request: {request!r}\n\nThe floor plan so far:\n{_data(plan)}\n\n"
        "Step 2: the wall height. Pick one height in metres for every wall of the scene "
        "(homes are usually 2.5 to 3.0).\n\n"
        'Answer in this shape:\n{"wall_height_m": 2.7}'
    )


def doors(request: str, plan: dict[str, Any]) -> str:
    """Step 3: which rooms share a door, and the entrance."""
    example = {"connections": [["living_room", "kitchen"]], "entrance_room": "living_room"}
    return (
        f"The request: {request!r}\n\nThe floor plan so far:\n{_data(plan)}\n\n"
        "Step 3: doors. List the pairs of rooms that a door should connect, using the room ids "
        "above, so that every room can be reached (bathrooms and bedrooms usually open onto a "
        "hall or the living room, not onto each other). Name the room the front door opens "
        "into as entrance_room. A scene of one room has no connections.\n\n"
        f"Answer in this shape:\n{_dump(example)}"
    )


def windows(request: str, plan: dict[str, Any]) -> str:
    """Step 4: window count and kind per room."""
    example = {
        "rooms": [
            {"room": "living_room", "count": 2, "kind": "hung"},
            {"room": "bathroom", "count": 1, "kind": "fixed"},
        ]
    }
    return (
        f"The request: {request!r}\n\nThe plan so far:\n{_data(plan)}\n\n"
        "Step 4: windows. For each room give how many windows it has (0 to 4) and their kind: "
        "fixed (does not open), hung (slides up) or slider (slides sideways). Use the room ids "
        "above; list every room once.\n\n"
        f"Answer in this shape:\n{_dump(example)}"
    )


def objects(
    request: str,
    plan: dict[str, Any],
    room: dict[str, Any],
    categories: Sequence[str] = (),
) -> str:
    """Step 5, once per room: the room's furniture and what stands on it."""
    example = {
        "objects": {
            "sofa": {
                "description": "three-seat fabric sofa in dark grey",
                "location": "floor",
                "size_cm": [210, 90, 85],
                "quantity": 1,
                "variance": "same",
                "category": "sofa",
                "objects_on_top": [
                    {
                        "name": "cushion",
                        "description": "square linen cushion",
                        "quantity": 2,
                        "variance": "varied",
                    }
                ],
            },
            "painting": {
                "description": "framed abstract print",
                "location": "wall",
                "size_cm": [90, 4, 60],
                "quantity": 1,
                "variance": "same",
                "above": "sofa",
                "objects_on_top": [],
            },
        }
    }
    shown = sorted({c for c in categories if c.strip()})
    if shown:
        listed = ", ".join(shown[:MAX_CATEGORIES_SHOWN])
        category_text = (
            "category (optional): the closest of these asset categories, written exactly as "
            f"listed, or leave it out: {listed}."
        )
    else:
        category_text = "Leave out category: no asset categories are known."
    return (
        f"The request: {request!r}\n\nThe plan so far:\n{_data(plan)}\n\n"
        f"Step 5: the objects of room {room['id']!r} ({room['type']}, "
        f"{room['width_m']:g} m x {room['depth_m']:g} m). List the furniture and fixtures this "
        "room needs, keyed by a short lower-case name (singular, no numbers). For each object: "
        "description (looks, material, colour); location: floor (stands on the floor) or wall "
        "(hangs on a wall: paintings, mirrors, shelves, wall lamps); size_cm: [width, depth, "
        "height] in centimetres, width left to right and depth front to back as seen from the "
        "object's front; quantity; variance: same (identical copies) or varied; above "
        "(optional, wall objects only): the floor object it hangs over; objects_on_top: small "
        "objects placed on it (name, description, quantity, variance), or []. "
        f"{category_text} Leave doorways and windows free; everything must fit the room with "
        "room to walk.\n\n"
        f"Answer in this shape:\n{_dump(example)}"
    )


def constraints(
    request: str,
    room: dict[str, Any],
    floor_objects: Sequence[dict[str, Any]],
    instance_names: Sequence[str],
) -> str:
    """Step 6, once per room: placement rules for the floor objects."""
    phrases = ", ".join(KIND_PHRASE.values())
    example = {
        "constraints": [
            "sofa-0 | edge",
            "coffee table-0 | middle | in front of, sofa-0 | center aligned, sofa-0",
            "armchair-0 | middle | near, coffee table-0 | face to, coffee table-0",
        ]
    }
    return (
        f"The request: {request!r}\n\n"
        f"Room {room['id']!r} ({room['type']}, {room['width_m']:g} m x {room['depth_m']:g} m) "
        f"holds these floor objects:\n{_data(list(floor_objects))}\n\n"
        "Step 6: where they go. Write one line per object instance, naming instances exactly "
        f"as in this list: {', '.join(instance_names)}. A line is the instance, then "
        "'|'-separated rules. Start with edge (back against a wall) or middle (away from the "
        "walls), then relations to instances placed on earlier lines, written as 'rule, "
        f"instance'. The rules are: {phrases}. near and far are about distance; in front of, "
        "behind, left of, right of and side of are seen from the other object; face to turns "
        "the object towards the other one. Place big pieces first.\n\n"
        f"Answer in this shape:\n{_dump(example)}"
    )


def feedback(error: str) -> str:
    """What the model is told after an answer it has to redo."""
    return (
        f"That answer could not be used: {error}. Answer the same question again with one "
        "JSON object in the shape asked for, and nothing else."
    )
