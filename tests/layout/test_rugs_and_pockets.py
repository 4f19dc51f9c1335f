"""Rugs laid under the main piece, and furniture nudged to open unreachable pockets."""

from __future__ import annotations

from shapely.geometry import Polygon, box

from holomj.layout.hard_rules import hard_checks
from holomj.layout.open_pockets import ReachMeter, open_pockets, reachable_share
from holomj.layout.room_problem import PreparedRoom, problem_from_data
from holomj.layout.rugs import Anchor, RugPose, _footprint, lay_rug, lay_rugs
from holomj.layout.solve import solve_room
from holomj.layout.solver_greedy import satisfied_weight


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


def test_several_rugs_lie_side_by_side_never_on_each_other() -> None:
    room = Polygon([(0, 0), (6, 0), (6, 4), (0, 4)])
    pieces = [
        Anchor(1.5, 2.0, 0.0, width=0.8, depth=1.8, category="treadmill"),
        Anchor(4.5, 2.0, 0.0, width=1.2, depth=1.2, category="squat_rack"),
    ]
    size = (1.2, 1.8)
    poses = lay_rugs(room, [size] * 3, pieces)
    assert all(isinstance(p, RugPose) for p in poses)
    shapes = [_footprint(p.x, p.y, p.yaw_deg, size, p.scale) for p in poses]
    for a in range(3):
        assert shapes[a].within(room)
        for b in range(a):
            assert shapes[a].intersection(shapes[b]).area < 1e-6
    # one rug alone lies where it always did: in the middle when no main piece is present
    single = lay_rug(room, size, pieces)
    assert isinstance(single, RugPose) and (single.x, single.y) == (3.0, 2.0)
    crowded = lay_rugs(Polygon([(0, 0), (2, 0), (2, 2), (0, 2)]), [size] * 2, [])
    assert isinstance(crowded[0], RugPose) and isinstance(crowded[1], str)


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


def test_a_door_fenced_in_by_furniture_is_reopened_by_what_fences_it() -> None:
    # a row of cabinets just inside the door cuts off the room, where many stools stand: the
    # stools border the pocket too, but only moving a cabinet reopens the door
    crates = [
        {"id": f"crate{i}", "width": 0.9, "depth": 0.6, "height": 0.9, "priority": 10}
        for i in range(6)
    ]
    stools = [
        {"id": f"stool{i}", "width": 0.3, "depth": 0.3, "height": 0.5, "priority": 1}
        for i in range(20)
    ]
    data = {
        "polygon": [[0, 0], [6, 0], [6, 5], [0, 5]],
        "size_unit": "m",
        "doors": [{"id": "d", "position": [3, 0], "width": 0.9}],
        "objects": crates + stools,
    }
    problem = problem_from_data(data)
    prep = PreparedRoom(problem)
    g = prep.grid
    poses = {k: (round((0.5 + k) / g), round(1.8 / g), 3) for k in range(6)}  # facing the door
    for k in range(20):
        poses[6 + k] = (round((1.0 + k % 5) / g), round((3.0 + 0.5 * (k // 5)) / g), 3)
    checks, _ = hard_checks(prep, poses)
    assert checks.ok
    assert reachable_share(prep, poses) < 0.5
    opened = open_pockets(prep, poses)
    assert reachable_share(prep, opened) >= 0.9
    assert any(opened[k] != poses[k] for k in range(6))


def test_what_gives_way_to_open_a_pocket() -> None:
    from holomj.layout.open_pockets import CUT_OFF_SHARE, TEMPLATE_SHARE, _may_give_way

    kept, lost = (lambda: 10.0), (lambda: 0.0)
    # a door cut off: any soft constraint gives way
    assert _may_give_way(CUT_OFF_SHARE - 0.01, 10.0, lost)
    # a pocket short of the template share: the templates' constraints only
    share = (CUT_OFF_SHARE + TEMPLATE_SHARE) / 2
    assert _may_give_way(share, 10.0, kept) and not _may_give_way(share, 10.0, lost)
    # above it: nothing gives way
    assert not _may_give_way(TEMPLATE_SHARE + 0.001, 10.0, kept)


def test_a_pocket_fenced_by_a_bed_and_a_wardrobe_opens_with_the_nightstand_pushed_along() -> None:
    # a bed against the bottom wall between two nightstands and a wardrobe on the top wall over
    # its foot, 0.4 m off the right wall: the floor right of the bed is cut off (the aisle over
    # the bed is 0.45 m). It opens only when the bed clears the wardrobe, pushing its nightstand
    # along; the wardrobe cannot slide left (a window) and moving it alone does not open it.
    data = {
        "polygon": [[0, 0], [5.25, 0], [5.25, 3.15], [0, 3.15]],
        "size_unit": "m",
        "doors": [{"id": "d", "position": [0, 1.3], "width": 1.0}],
        "windows": [
            {"id": "w0", "position": [2.65, 3.15], "width": 1.2, "sill_height": 0.8},
            {"id": "w1", "position": [5.25, 1.6], "width": 1.3, "sill_height": 0.8},
        ],
        "objects": [
            {"id": "bed", "width": 1.6, "depth": 2.1, "height": 1.0, "priority": 100},
            {"id": "nightstand", "width": 0.45, "depth": 0.4, "height": 0.55},
            {"id": "wardrobe", "width": 1.2, "depth": 0.6, "height": 2.0},
            {"id": "nightstand2", "width": 0.45, "depth": 0.4, "height": 0.55},
        ],
        "constraints_text": "bed | edge\n"
        "nightstand | edge | near, bed | side of, bed\n"
        "nightstand2 | edge | near, bed | side of, bed\n"
        "wardrobe | edge",
    }
    prep = PreparedRoom(problem_from_data(data))
    g = prep.grid
    poses = {
        0: (round(3.2 / g), round(1.05 / g), 1),
        1: (round(2.1 / g), round(0.2 / g), 1),
        2: (round(4.25 / g), round(2.85 / g), 3),
        3: (round(4.3 / g), round(0.2 / g), 1),
    }
    checks, _ = hard_checks(prep, poses)
    assert checks.ok
    assert reachable_share(prep, poses) < 0.8
    opened = open_pockets(prep, poses)
    assert hard_checks(prep, opened)[0].ok
    assert reachable_share(prep, opened) >= 0.97
    kept = satisfied_weight(prep, prep.metres(poses))
    assert satisfied_weight(prep, prep.metres(opened)) >= kept - 1e-9


def test_a_half_metre_gap_is_no_way_through_on_a_navigation_maps_cells() -> None:
    """Two desks 0.5 m apart fence a pocket: bare footprints leave a 0.2 m robot room to pass,
    but a navigation map, which blocks every 5 cm cell a desk touches, closes the gap; the
    layout's measure judges passages as the map sees them (and 0.6 m is open either way)."""
    desk = {"width": 1.4, "depth": 0.7, "height": 0.75}
    data = {
        "polygon": [[0, 0], [4.2, 0], [4.2, 2.85], [0, 2.85]],
        "size_unit": "m",
        "doors": [{"id": "d", "position": [2.5, 0], "width": 0.9}],
        "objects": [{"id": "desk0", **desk}, {"id": "desk1", **desk}],
    }
    prep = PreparedRoom(problem_from_data(data))
    # desk0 against the north wall, desk1 below and to its right: the floor north of desk1 is
    # reached only through the gap between the desks' ends
    for gap, closed in ((0.5, True), (0.6, False)):
        rects = [(0.65, 2.05, 2.05, 2.75), (2.05 + gap, 1.1, 3.45 + gap, 1.8)]
        nav = ReachMeter(prep).pockets(rects)[0]
        bare = ReachMeter(prep, nav_cells=False).pockets(rects)[0]
        assert bare >= 0.97
        assert (nav < 0.9) is closed, (gap, nav)
