"""Hand-written plans for the generate tests (what a planner could produce)."""

from __future__ import annotations

from holomj.spec.plan import ScenePlan


def chairs(n: int) -> list[str]:
    return [f"dining chair-{k} | near, dining table-0 | face to, dining table-0" for k in range(n)]


def two_room_plan(**updates) -> ScenePlan:
    """A living room and a kitchen with floor, wall and small objects."""
    data = {
        "prompt": "a living room and a kitchen",
        "planner": "offline",
        "seed": 0,
        "scene_type": "apartment",
        "rooms": [
            {
                "id": "living_room",
                "type": "living_room",
                "area_m2": 20,
                "adjacent_to": ["kitchen"],
                "windows": {"count": 2, "kind": "fixed"},
                "objects": [
                    {"name": "sofa", "category": "sofa", "size": [2.0, 0.9, 0.85]},
                    {
                        "name": "coffee table",
                        "category": "coffee_table",
                        "on_top": [
                            {"name": "book", "category": "book", "quantity": 2},
                            {"name": "mug", "category": "mug"},
                        ],
                    },
                    {"name": "armchair", "category": "armchair", "quantity": 2},
                    {"name": "tv stand", "category": "tv_stand"},
                    {
                        "name": "painting",
                        "category": "painting",
                        "placement": "wall",
                        "quantity": 2,
                    },
                    {"name": "spaceship", "category": "spaceship"},
                ],
                "constraints": [
                    "sofa-0 | edge",
                    "coffee table-0 | middle | in front of, sofa-0",
                    "armchair-0 | near, coffee table-0 | face to, coffee table-0",
                    "armchair-1 | near, coffee table-0",
                    "tv stand-0 | edge | face to, sofa-0",
                ],
            },
            {
                "id": "kitchen",
                "type": "kitchen",
                "area_m2": 11,
                "objects": [
                    {"name": "kitchen counter", "category": "kitchen_counter"},
                    {"name": "fridge", "category": "fridge"},
                    {
                        "name": "dining table",
                        "category": "dining_table",
                        "on_top": [{"name": "plate", "category": "plate", "quantity": 3}],
                    },
                    {"name": "dining chair", "category": "dining_chair", "quantity": 4},
                ],
                "constraints": [
                    "kitchen counter-0 | edge",
                    "fridge-0 | edge",
                    "dining table-0 | middle",
                    *chairs(4),
                ],
            },
        ],
    }
    data.update(updates)
    return ScenePlan.model_validate(data)
