"""Small scenes written by hand for the evaluation tests, compiled with ``holomj compile``.

Objects are ``builtin:box`` stand-ins; the evaluator labels a box by the noun of its id
(``bedroom.wardrobe_0`` -> ``wardrobe``). Every verdict the tests expect follows from the
geometry written here (metres; a box's position is the centre of its bottom; yaw 0 = front +X).
"""

from __future__ import annotations

import copy
import json
from pathlib import Path
from typing import Any

import holomj

EMPTY_LIBRARY = {"schema_version": "1.0", "name": "empty", "assets": {}}


def box(
    oid: str, room: str, xy: tuple[float, float], size: tuple[float, float, float], **extra: Any
) -> dict[str, Any]:
    """A builtin:box object whose footprint centre is ``xy`` (bottom at z = 0 unless given)."""
    z = extra.pop("z", 0.0)
    return {
        "id": f"{room}.{oid}",
        "asset": "builtin:box",
        "position": [xy[0], xy[1], z],
        "scale": list(size),
        "room": room,
        **extra,
    }


def room_scene(
    objects: list[dict[str, Any]],
    *,
    room: str = "bedroom",
    kind: str = "bedroom",
    size: tuple[float, float] = (4.0, 4.0),
    windows: list[dict[str, Any]] | None = None,
) -> dict[str, Any]:
    """One room (``size``, lower-left corner at the origin) with its entrance on the south
    wall at x = 2 and the given objects and windows."""
    w, d = size
    return {
        "schema_version": "1.0",
        "name": "eval_test",
        "rooms": [{"id": room, "type": kind, "polygon": [[0, 0], [w, 0], [w, d], [0, d]]}],
        "doors": [{"id": "front", "kind": "doorway", "rooms": [room], "position": [2.0, 0.0]}],
        "windows": windows or [],
        "objects": objects,
    }


def window(
    oid: str, room: str, xy: tuple[float, float], width: float = 1.2, **extra: Any
) -> dict[str, Any]:
    """A fixed window 1 m tall with its sill at 0.9 m (unless given)."""
    return {
        "id": oid,
        "kind": "fixed",
        "rooms": [room],
        "position": list(xy),
        "width": width,
        "height": extra.pop("height", 1.0),
        "base_height": extra.pop("base_height", 0.9),
        **extra,
    }


# A 6 x 5 m living room that passes every metric: sofa against the west wall, a mug on the
# coffee table, a wardrobe with free floor in front, the door and the window clear.
GOOD = room_scene(
    [
        box("sofa_0", "living_room", (0.5, 2.5), (0.9, 2.0, 0.8)),
        box("coffee_table_0", "living_room", (2.0, 2.5), (0.6, 1.0, 0.4)),
        box(
            "mug_0",
            "living_room",
            (2.0, 2.5),
            (0.1, 0.1, 0.1),
            z=0.4,
            support="living_room.coffee_table_0",
        ),
        box("wardrobe_0", "living_room", (5.65, 2.5), (0.6, 1.2, 2.0), yaw_deg=180),
    ],
    room="living_room",
    kind="living_room",
    size=(6.0, 5.0),
    windows=[window("win", "living_room", (3.0, 5.0))],
)

# The plan the GOOD scene was "generated" from (plan.json): a living room with a sofa, a coffee
# table with a mug on it, a wardrobe, and a TV the scene lacks; the sofa is against the wall.
GOOD_PLAN = {
    "schema_version": "1.0",
    "prompt": "a living room with a sofa against the wall, a coffee table and a tv",
    "planner": "offline",
    "seed": 0,
    "scene_type": "living_room",
    "rooms": [
        {
            "id": "living_room",
            "type": "living_room",
            "objects": [
                {"name": "sofa", "category": "sofa", "requested": True},
                {
                    "name": "coffee table",
                    "category": "coffee_table",
                    "requested": True,
                    "on_top": [{"name": "mug", "category": "mug"}],
                },
                {"name": "wardrobe", "category": "wardrobe"},
                {"name": "tv", "category": "television", "requested": True},
            ],
            "relations": [
                {"subject": "sofa", "kind": "wall", "phrase": "against the wall"},
                {"subject": "coffee table", "kind": "in_front_of", "target": "sofa"},
                {"subject": "sofa", "kind": "facing", "target": "tv"},
            ],
        }
    ],
}


def variant(base: dict[str, Any], *objects: dict[str, Any], **fields: Any) -> dict[str, Any]:
    """``base`` with more objects (and other fields replaced)."""
    scene = copy.deepcopy(base)
    scene["objects"] += list(objects)
    scene.update(fields)
    return scene


def compile_scene(scene: dict[str, Any], where: Path) -> Path:
    """Write ``scene`` as scene.json and compile it (empty library, no smoke run); the folder."""
    where.mkdir(parents=True, exist_ok=True)
    library = where / "library"
    library.mkdir(exist_ok=True)
    (library / "library.json").write_text(json.dumps(EMPTY_LIBRARY))
    src = where / "scene.json"
    src.write_text(json.dumps(scene))
    out = where / "out"
    holomj.compile(src, out, library=library, check_seconds=0.0)
    return out
