"""Rugs laid under the main piece, and furniture nudged to open unreachable pockets."""

from __future__ import annotations

from shapely.geometry import Polygon, box

from holomj.layout.open_pockets import reachable_share
from holomj.layout.room_problem import PreparedRoom, problem_from_data
from holomj.layout.rugs import Anchor, RugPose, lay_rug
from holomj.layout.solve import solve_room


def test_a_rug_goes_under_the_coffee_table_along_its_long_side() -> None:
    room = Polygon([(0, 0), (5, 0), (5, 4), (0, 4)])
    table = Anchor(2.0, 2.5, 0.0, width=1.2, depth=0.6, category="coffee_table")
    pose = lay_rug(room, (1.6, 2.3), [table])
    assert isinstance(pose, RugPose)
    assert (pose.x, pose.y, pose.scale) == (2.0, 2.5, 1.0)
    assert pose.yaw_deg == 0.0  # the table's width runs along y, so does the rug's


def test_a_rug_that_does_not_fit_is_moved_then_shrunk_then_refused() -> None:
    room = Polygon([(0, 0), (2.2, 0), (2.2, 1.6), (0, 1.6)])
    pose = lay_rug(room, (1.6, 2.3), [])
    assert isinstance(pose, RugPose) and pose.scale < 1.0
    footprint = box(-0.8 * pose.scale, -1.15 * pose.scale, 0.8 * pose.scale, 1.15 * pose.scale)
    assert footprint.area < room.area
    tiny = Polygon([(0, 0), (1, 0), (1, 1), (0, 1)])
    assert isinstance(lay_rug(tiny, (1.6, 2.3), []), str)


def test_layouts_leave_the_free_floor_reachable() -> None:
    data = {
        "polygon": [[0, 0], [4, 0], [4, 4], [0, 4]],
        "size_unit": "m",
        "doors": [{"id": "d", "position": [2, 0], "width": 0.9}],
        "objects": [
            {"id": f"chair{i}", "width": 0.7, "depth": 0.7, "height": 0.9} for i in range(6)
        ]
        + [{"id": "table", "width": 1.2, "depth": 1.2, "height": 0.75}],
        "constraints_text": "table | middle\n"
        + "".join(f"chair{i} | near, table\n" for i in range(6)),
    }
    problem = problem_from_data(data)
    result = solve_room(problem, solver="cpsat")
    prep = PreparedRoom(problem)
    g = prep.grid
    poses = {
        prep.index[i]: (round(p.x / g), round(p.y / g), round(p.yaw_deg / 90) % 4)
        for i, p in result.placements.items()
    }
    assert reachable_share(prep, poses) >= 0.97
