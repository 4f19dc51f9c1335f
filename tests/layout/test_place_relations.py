"""Place constraints (corner, under / by a window, by a door, adjacent to) in both solvers."""

from __future__ import annotations

import pytest

from holomj.layout.room_problem import problem_from_data
from holomj.layout.solve import solve_room

PROBLEM = {
    "polygon": [[0, 0], [4, 0], [4, 3], [0, 3]],
    "size_unit": "m",
    "doors": [{"id": "d", "position": [2, 0], "width": 0.9}],
    "windows": [{"id": "w", "position": [4, 1.5], "width": 1.2, "sill_height": 0.9}],
    "objects": [
        {"id": "lamp", "width": 0.4, "depth": 0.4, "height": 1.6},
        {"id": "desk", "width": 1.2, "depth": 0.6, "height": 0.75},
        {"id": "rack", "width": 0.5, "depth": 0.4, "height": 1.7},
        {"id": "chair", "width": 0.5, "depth": 0.5, "height": 0.9},
    ],
    "constraints_text": (
        "lamp | corner\ndesk | under window\nrack | by door\nchair | adjacent to, desk\n"
    ),
}


@pytest.mark.parametrize("solver", ["cpsat", "greedy"])
def test_place_constraints_hold_in_an_easy_room(solver: str) -> None:
    result = solve_room(problem_from_data(PROBLEM), solver=solver)
    assert len(result.placements) == 4
    assert all(c.satisfied for c in result.constraints), [
        (c.text, c.detail) for c in result.constraints if not c.satisfied
    ]
    lamp = result.placements["lamp"]
    # both walls of a corner within 8 cm of the footprint
    near_x = min(lamp.x - lamp.depth / 2, 4 - lamp.x - lamp.depth / 2)
    near_y = min(lamp.y - lamp.width / 2, 3 - lamp.y - lamp.width / 2)
    assert near_x <= 0.08 + 1e-6 and near_y <= 0.08 + 1e-6
    desk = result.placements["desk"]
    # back to the window wall, overlapping the 1.2 m window by at least 0.3 m
    assert desk.x > 3.5 and abs(desk.y - 1.5) <= 0.6 + 0.6 - 0.3 + 1e-6


def test_under_window_cannot_hold_for_an_object_taller_than_the_sill() -> None:
    data = {
        **PROBLEM,
        "objects": [{"id": "wardrobe", "width": 1.0, "depth": 0.6, "height": 2.0}],
        "constraints_text": "wardrobe | under window\n",
    }
    result = solve_room(problem_from_data(data), solver="cpsat")
    assert "wardrobe" in result.placements
    assert not result.constraints[0].satisfied


def test_a_room_without_windows_says_so() -> None:
    data = {**PROBLEM, "windows": [], "constraints_text": "desk | by window\n"}
    result = solve_room(problem_from_data(data), solver="greedy")
    report = next(c for c in result.constraints if c.object == "desk")
    assert not report.satisfied and "no windows" in report.detail


@pytest.mark.parametrize("solver", ["cpsat", "greedy"])
def test_facing_the_door_and_the_window(solver: str) -> None:
    data = {
        **PROBLEM,
        "objects": [
            {"id": "desk", "width": 1.2, "depth": 0.6, "height": 0.75},
            {"id": "easel", "width": 0.6, "depth": 0.6, "height": 1.6},
        ],
        "constraints_text": "desk | facing door\neasel | facing window\n",
    }
    result = solve_room(problem_from_data(data), solver=solver)
    assert all(c.satisfied for c in result.constraints)
    desk, easel = result.placements["desk"], result.placements["easel"]
    assert desk.yaw_deg == 270.0 and abs(desk.x - 2.0) <= 0.45  # looks down at the door (y=0)
    assert easel.yaw_deg == 0.0 and abs(easel.y - 1.5) <= 0.6  # looks at the window (x=4)


@pytest.mark.parametrize("solver", ["cpsat", "greedy"])
def test_centre_puts_the_object_at_the_rooms_centre(solver: str) -> None:
    data = {
        **PROBLEM,
        "objects": [{"id": "table", "width": 1.4, "depth": 0.8, "height": 0.75}],
        "constraints_text": "table | middle | centre\n",
    }
    result = solve_room(problem_from_data(data), solver=solver)
    assert all(c.satisfied for c in result.constraints)
    table = result.placements["table"]
    assert abs(table.x - 2.0) <= 0.3 + 1e-6 and abs(table.y - 1.5) <= 0.3 + 1e-6
