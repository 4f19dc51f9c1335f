"""Desks in rows: grid groups found from the plan's pairing constraints, laid out as rows that
face one front wall with a seat at each desk's user side, aisles of the stated widths, nothing
cut off from the door; independent placement when the room is too small; end to end, a
classroom whose free floor is all reachable."""

from __future__ import annotations

import importlib.util
import json
import sys
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from shapely.geometry import LineString, Point

from holomj.layout import geometry as geo
from holomj.layout.desk_grid import front_lookers, solve_desk_grid
from holomj.layout.desk_grid_groups import grid_groups
from holomj.layout.desk_grid_shapes import COMPACT, STANDARD
from holomj.layout.open_pockets import reachable_share
from holomj.layout.room_problem import (
    LayoutDoor,
    LayoutObject,
    LayoutSettings,
    LayoutWindow,
    PreparedRoom,
    RoomProblem,
)
from holomj.layout.solve import LayoutResult, Placement, solve_room
from holomj.spec.plan import PlanObject, PlanRelation, PlanRoom

ROOT = Path(__file__).resolve().parents[2]
MARGIN = 0.08
DESK = (1.4, 0.7)  # width, depth: the default library's desk
CHAIR = 0.45
TOL = 0.01
# The benchmark's classroom has sixteen desks; its room (about 48 m²) holds no grid of the
# library's 1.4 m desks with their chairs and aisles a robot passes, so it falls back (see
# test_too_small_a_room_falls_back_to_independent_placement). Eight desks fit a room of the
# same template.
CLASSROOM = "A classroom with eight student desks, each with a chair, and a whiteboard on the wall."


def classroom(
    size: tuple[float, float],
    desks: int = 16,
    *,
    desk: tuple[float, float] = DESK,
    chairs: bool = True,
    windows: Sequence[LayoutWindow] = (),
    extra: Sequence[LayoutObject] = (),
) -> tuple[RoomProblem, dict[str, str]]:
    """A rectangular room with its door in the middle of the wall at y = 0, ``desks`` student
    desks (each with a chair paired to it as the planner writes it) and a teacher desk."""
    w, h = size
    objects = [LayoutObject(id="teacher desk-0", width=1.4, depth=0.7, height=0.75, priority=100)]
    categories = {"teacher desk-0": "desk"}
    lines = ["teacher desk-0 | edge"]
    for k in range(desks):
        objects.append(
            LayoutObject(
                id=f"student desk-{k}", width=desk[0], depth=desk[1], height=0.75, priority=100
            )
        )
        categories[f"student desk-{k}"] = "desk"
        lines.append(f"student desk-{k} | middle")
        if chairs:
            objects.append(
                LayoutObject(
                    id=f"school chair-{k}", width=CHAIR, depth=CHAIR, height=0.9, priority=8
                )
            )
            categories[f"school chair-{k}"] = "dining_chair"
            lines.append(
                f"school chair-{k} | near, student desk-{k} | in front of, student desk-{k} "
                f"| face to, student desk-{k}"
            )
    for obj in extra:
        objects.append(obj)
        categories[obj.id] = obj.id.rsplit("-", 1)[0].replace(" ", "_")
    polygon = [
        (MARGIN, MARGIN),
        (w - MARGIN, MARGIN),
        (w - MARGIN, h - MARGIN),
        (MARGIN, h - MARGIN),
    ]
    problem = RoomProblem(
        room_id="classroom",
        polygon=polygon,
        size_unit="m",
        doors=[LayoutDoor(id="door", position=(w / 2, MARGIN), width=0.9, swing="none")],
        windows=list(windows),
        objects=objects,
        constraints_text="\n".join(lines),
        settings=LayoutSettings(walker_radius_m=0.3, door_clearance_m=1.0),
    )
    return problem, categories


def plain(problem: RoomProblem) -> LayoutResult:
    """The room's solver as furnish_room runs it."""
    return solve_room(problem, solver="cpsat", time_limit_s=1.0, rng=np.random.default_rng(0))


def rect(p: Placement) -> tuple[float, ...]:
    return geo.footprint(p.x, p.y, geo.yaw_index(p.yaw_deg), p.width, p.depth)


def frame(p: Placement) -> tuple[tuple[int, int], tuple[int, int]]:
    """The desk's front (+X, where its user sits) and its left, as unit grid vectors."""
    fx, fy = geo.FRONT[geo.yaw_index(p.yaw_deg)]
    return (fx, fy), (-fy, fx)


def local(p: Placement, origin: Placement) -> tuple[float, float]:
    """``p``'s centre in ``origin``'s frame: (along its front, to its left)."""
    (fx, fy), (lx, ly) = frame(origin)
    dx, dy = p.x - origin.x, p.y - origin.y
    return dx * fx + dy * fy, dx * lx + dy * ly


def gap(a: tuple[float, ...], b: tuple[float, ...]) -> float:
    gx, gy = geo.rect_gaps(a, b)
    return max(gx, gy)


# --------------------------------------------------------------------------- detection


def test_grid_group_pairs_each_desk_with_its_own_chair() -> None:
    problem, categories = classroom((9.5, 8.5))
    groups = grid_groups(problem, categories)
    assert [g.name for g in groups] == ["student desk"]
    group = groups[0]
    assert len(group.stations) == 16 and not group.two_sided
    for k, station in enumerate(group.stations):
        assert station.desk.id == f"student desk-{k}"
        assert [s.id for s in station.front] == [f"school chair-{k}"]
    assert "teacher desk-0" not in group.members


def test_few_desks_make_a_group_only_when_rows_are_asked() -> None:
    problem, categories = classroom((6.0, 5.0), desks=3)
    assert grid_groups(problem, categories) == []
    desks = PlanObject(name="student desk", category="desk", quantity=3)
    row = PlanRelation(subject="student desk", kind="in_row", phrase="in a row")
    in_row = PlanRoom(id="classroom", type="classroom", objects=[desks], relations=[row])
    groups = grid_groups(problem, categories, in_row)
    assert len(groups) == 1 and groups[0].in_row and groups[0].rows_asked is None
    in_one_row = in_row.model_copy(update={"objects": [desks.model_copy(update={"rows": 1})]})
    assert grid_groups(problem, categories, in_one_row)[0].rows_asked == 1
    for rows, count in ((2, 2), ("any", None)):
        asked = PlanRoom(
            id="classroom", type="classroom", objects=[desks.model_copy(update={"rows": rows})]
        )
        groups = grid_groups(problem, categories, asked)
        assert len(groups) == 1 and not groups[0].in_row and groups[0].rows_asked == count


def test_only_work_surfaces_make_groups() -> None:
    sofa = [LayoutObject(id=f"sofa-{k}", width=2.0, depth=0.9, height=0.8) for k in range(4)]
    dining = [LayoutObject(id=f"dining table-{k}", width=1.6, depth=0.9) for k in range(4)]
    canteen = [LayoutObject(id=f"cafeteria table-{k}", width=2.0, depth=0.8) for k in range(4)]
    problem = RoomProblem(
        polygon=[(0, 0), (12, 0), (12, 12), (0, 12)],
        size_unit="m",
        objects=[*sofa, *dining, *canteen],
    )
    categories = {o.id: "sofa" for o in sofa}
    categories |= {o.id: "dining_table" for o in [*dining, *canteen]}
    groups = grid_groups(problem, categories)
    assert [g.name for g in groups] == ["cafeteria table"]
    assert groups[0].two_sided  # a table is used from both sides


# --------------------------------------------------------------------------- the laid grid


@pytest.fixture(scope="module")
def roomy() -> tuple[RoomProblem, LayoutResult, dict[str, Any]]:
    """Sixteen desks and chairs in a room big enough for standard aisles, a window on the
    wall opposite the door."""
    window = LayoutWindow(id="w", position=(2.0, 8.5 - MARGIN), width=1.2, sill_height=0.9)
    problem, categories = classroom((9.5, 8.5), windows=[window])
    result, record = solve_desk_grid(problem, categories, solve=plain)
    assert record is not None
    return problem, result, record


def test_grid_is_laid_and_recorded(roomy) -> None:
    problem, result, record = roomy
    assert record["fallback"] is None, record["tried"]
    assert record["rows"] * record["columns"] >= 16
    assert record["front_wall"] is not None
    assert record["blocks"][0]["aisles"] == "standard"
    assert not result.unplaced and result.hard_checks.ok
    assert set(result.placements) == {o.id for o in problem.objects}


def rows_of(result: LayoutResult, record: dict[str, Any]) -> list[list[Placement]]:
    return [[result.placements[i] for i in row] for row in record["blocks"][0]["rows_of_desks"]]


def test_rows_are_aligned_and_evenly_spaced(roomy) -> None:
    _, result, record = roomy
    rows = rows_of(result, record)
    origin = rows[0][0]
    depth = [[local(p, origin)[0] for p in row] for row in rows]
    across = [sorted(local(p, origin)[1] for p in row) for row in rows]
    for values in depth:  # a row's desks share their front-back coordinate
        assert max(values) - min(values) <= TOL
    pitches = [b[0] - a[0] for a, b in zip(depth, depth[1:])]
    assert all(abs(p - pitches[0]) <= TOL for p in pitches)  # equal spacing of the rows
    full = [a for a in across if len(a) == record["columns"]]
    for a in full[1:]:  # full rows have their desks in the same columns
        assert all(abs(u - v) <= TOL for u, v in zip(a, full[0]))
    steps = np.diff(full[0])  # side by side in pairs: two steps only, each repeating evenly
    assert len({round(float(s), 2) for s in steps}) <= 2


def test_all_desks_face_the_front_wall(roomy) -> None:
    problem, result, record = roomy
    desks = [p for row in rows_of(result, record) for p in row]
    assert len({geo.yaw_index(p.yaw_deg) for p in desks}) == 1
    wall = LineString(record["front_wall"])
    look = record["blocks"][0]["facing"]
    for p in desks:
        (fx, fy), _ = frame(p)
        assert (-fx, -fy) == tuple(look)  # users look away from the desk's front...
        ray = LineString([(p.x, p.y), (p.x + 50 * look[0], p.y + 50 * look[1])])
        assert ray.intersects(wall)  # ...at the front wall
    # the front wall is not the door's: the users do not look towards the door
    (cx, cy) = record["blocks"][0]["centre"]
    door = problem.doors[0].position
    assert (door[0] - cx) * look[0] + (door[1] - cy) * look[1] <= 0.5


def test_each_chair_is_at_its_desk_on_the_user_side(roomy) -> None:
    _, result, _ = roomy
    for k in range(16):
        desk = result.placements[f"student desk-{k}"]
        chair = result.placements[f"school chair-{k}"]
        along, side = local(chair, desk)
        assert along > desk.depth / 2  # on the desk's +X side, where its user sits
        assert abs(side) <= desk.width / 2  # across from the desk
        assert gap(rect(chair), rect(desk)) <= 0.1 + 1e-6  # within reach
        assert geo.yaw_index(chair.yaw_deg) == (geo.yaw_index(desk.yaw_deg) + 2) % 4


def test_aisles_are_wide_enough(roomy) -> None:
    _, result, record = roomy
    rows = rows_of(result, record)
    chair_of = {f"student desk-{k}": f"school chair-{k}" for k in range(16)}
    ids = record["blocks"][0]["rows_of_desks"]
    for r in range(len(rows) - 1):
        chairs = [rect(result.placements[chair_of[i]]) for i in ids[r]]
        desks = [rect(result.placements[i]) for i in ids[r + 1]]
        behind = min(gap(c, d) for c in chairs for d in desks)
        assert behind >= STANDARD.row - 1e-6  # behind each chair row
    for row in rows:
        order = sorted(row, key=lambda p: local(p, row[0])[1])
        gaps = [gap(rect(a), rect(b)) for a, b in zip(order, order[1:])]
        wide = [g for g in gaps if g > 0.05]
        assert wide and all(g >= STANDARD.column - 1e-6 for g in wide)  # between pairs
        assert all(g >= -1e-6 for g in gaps)  # desks of a pair touch, never overlap


def test_nothing_overlaps_and_every_free_cell_is_reachable(roomy) -> None:
    problem, result, _ = roomy
    rects = {i: rect(p) for i, p in result.placements.items()}
    ids = sorted(rects)
    for n, a in enumerate(ids):
        for b in ids[n + 1 :]:
            gx, gy = geo.rect_gaps(rects[a], rects[b])
            assert not (gx < -1e-6 and gy < -1e-6), (a, b)
    prep = PreparedRoom(problem)
    poses = {
        prep.index[i]: (p.x / prep.grid, p.y / prep.grid, geo.yaw_index(p.yaw_deg))
        for i, p in result.placements.items()
    }
    assert reachable_share(prep, poses) >= 0.97


def test_a_tighter_room_gets_compact_aisles_still_wider_than_a_robot() -> None:
    problem, categories = classroom((7.4, 7.4), desks=12)
    result, record = solve_desk_grid(problem, categories, solve=plain)
    assert record is not None and record["fallback"] is None, record
    block = record["blocks"][0]
    assert block["aisles"] == COMPACT.name  # standard aisles do not fit this room
    ids = block["rows_of_desks"]
    for r in range(len(ids) - 1):
        chairs = [
            rect(result.placements[i.replace("student desk", "school chair")]) for i in ids[r]
        ]
        desks = [rect(result.placements[i]) for i in ids[r + 1]]
        assert min(gap(c, d) for c in chairs for d in desks) >= COMPACT.row - 1e-6
    assert not result.unplaced and result.hard_checks.ok
    prep = PreparedRoom(problem)
    poses = {
        prep.index[i]: (p.x / prep.grid, p.y / prep.grid, geo.yaw_index(p.yaw_deg))
        for i, p in result.placements.items()
    }
    assert reachable_share(prep, poses) >= 0.97


def test_a_room_split_by_its_door_gets_two_blocks_facing_the_same_way() -> None:
    # 12 x 4.5 m, the door in the middle of a long wall: no block of twelve fits beside the
    # door's zone, two blocks of six do, one on either side
    problem, categories = classroom((12.0, 4.5), desks=12)
    result, record = solve_desk_grid(problem, categories, solve=plain)
    assert record is not None and record["fallback"] is None, record["tried"]
    assert record["block_count"] == 2
    assert record["blocks"][0]["facing"] == record["blocks"][1]["facing"]
    assert not result.unplaced and result.hard_checks.ok
    xs = sorted(b["centre"][0] for b in record["blocks"])
    assert xs[0] < problem.doors[0].position[0] < xs[1]
    prep = PreparedRoom(problem)
    poses = {
        prep.index[i]: (p.x / prep.grid, p.y / prep.grid, geo.yaw_index(p.yaw_deg))
        for i, p in result.placements.items()
    }
    assert reachable_share(prep, poses) >= 0.97


def test_tables_used_from_both_sides_get_seats_on_both_sides() -> None:
    tables = [
        LayoutObject(id=f"cafeteria table-{k}", width=2.0, depth=0.8, height=0.75, priority=100)
        for k in range(4)
    ]
    chairs = [LayoutObject(id=f"chair-{k}", width=0.45, depth=0.45, height=0.9) for k in range(16)]
    lines = [
        f"chair-{k} | near, cafeteria table-{k // 4} | face to, cafeteria table-{k // 4}"
        for k in range(16)
    ]
    problem = RoomProblem(
        polygon=[(0, 0), (9, 0), (9, 8), (0, 8)],
        size_unit="m",
        doors=[LayoutDoor(id="door", position=(4.5, 0), width=0.9, swing="none")],
        objects=[*tables, *chairs],
        constraints_text="\n".join(lines),
    )
    categories = {t.id: "dining_table" for t in tables} | {c.id: "dining_chair" for c in chairs}
    result, record = solve_desk_grid(problem, categories, solve=plain)
    assert record is not None and record["fallback"] is None, record["tried"]
    assert not result.unplaced and result.hard_checks.ok
    for k in range(16):
        table = result.placements[f"cafeteria table-{k // 4}"]
        chair = result.placements[f"chair-{k}"]
        along, side = local(chair, table)
        assert abs(along) > table.depth / 2 and abs(side) < table.width / 2
        assert gap(rect(chair), rect(table)) <= 0.1 + 1e-6
        assert (along > 0) == (k % 2 == 0)  # two seats on each long side


def test_a_shape_that_leaves_out_a_requested_object_gives_way() -> None:
    table = LayoutObject(
        id="table tennis table-0", width=1.525, depth=2.74, height=0.76, priority=10
    )
    problem, categories = classroom((8.0, 6.5), desks=8, extra=[table])
    result, record = solve_desk_grid(problem, categories, solve=plain)
    assert record is not None and record["fallback"] is None
    assert any("left out table tennis table-0" in t["outcome"] for t in record["tried"])
    assert "table tennis table-0" in result.placements and not result.unplaced
    assert record["left_out"] == []


def test_too_small_a_room_falls_back_to_independent_placement() -> None:
    problem, categories = classroom((3.4, 3.0), desks=4, chairs=False)
    result, record = solve_desk_grid(problem, categories, solve=plain)
    assert record is not None and record["desks"] == 4
    assert record["rows"] is None and record["blocks"] == []
    assert record["fallback"].endswith("the desks are laid out one by one")
    assert record["tried"]  # every shape it tried says why it failed
    alone = plain(problem)  # exactly what the room's solver does without a grid
    assert result.placements == alone.placements


def test_seats_too_many_for_their_desk_are_left_to_the_solver() -> None:
    # three 0.6 m office chairs at a 1.4 m desk (the planner spreads twenty chairs over four
    # desks so) do not fit at its side: nothing is laid out as a grid
    problem, categories = classroom((9.0, 8.0), desks=4, chairs=False)
    desk_of = [0, 0, 0, 1, 2, 3]
    chairs = [
        LayoutObject(id=f"office chair-{k}", width=0.6, depth=0.6, height=1.0)
        for k in range(len(desk_of))
    ]
    lines = [
        f"office chair-{k} | near, student desk-{d} | face to, student desk-{d}"
        for k, d in enumerate(desk_of)
    ]
    problem = problem.model_copy(
        update={
            "objects": [*problem.objects, *chairs],
            "constraints_text": problem.constraints_text + "\n" + "\n".join(lines),
        }
    )
    categories |= {c.id: "office_chair" for c in chairs}
    result, record = solve_desk_grid(problem, categories, solve=plain)
    assert record is not None and record["seats"] == 6
    assert "3 seats (1.90 m) do not fit at student desk-0" in record["fallback"]
    assert result.placements == plain(problem).placements  # laid out one by one


def test_the_board_hangs_where_the_front_row_looks() -> None:
    room = PlanRoom(
        id="classroom",
        type="classroom",
        objects=[
            PlanObject(name="student desk", category="desk", quantity=16),
            PlanObject(name="school chair", category="dining_chair", quantity=16),
            PlanObject(name="whiteboard", category="whiteboard", placement="wall"),
            PlanObject(name="painting", category="painting", placement="wall"),
        ],
    )
    problem, categories = classroom((9.5, 8.5))
    result, record = solve_desk_grid(problem, categories, solve=plain, plan_room=room)
    assert record is not None and record["looker"] == "school chair-0"
    # the first desk (and its seat) stands in the front row's middle
    front = sorted(
        record["blocks"][0]["rows_of_desks"][0],
        key=lambda i: local(result.placements[i], result.placements["student desk-0"])[1],
    )
    middle = {(len(front) - 1) // 2, len(front) // 2}
    assert front.index("student desk-0") in middle
    hung = {o.name: o.faced_by for o in front_lookers(room, record).objects}
    assert hung == {
        "student desk": None,
        "school chair": None,
        "whiteboard": "school chair",
        "painting": None,
    }
    assert front_lookers(room, {"looker": None}) is room


# --------------------------------------------------------------------------- end to end


def _score_module() -> Any:
    spec = importlib.util.spec_from_file_location(
        "fidelity_score_for_desk_grid", ROOT / "scripts" / "eval" / "score.py"
    )
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module
    spec.loader.exec_module(module)
    return module


@pytest.mark.slow
def test_classroom_prompt_gives_rows_reachable_floor_and_the_board_in_front(
    tmp_path: Path, default_library
) -> None:
    from holomj.jobs.generate import GenerateOptions, generate_scene

    out = tmp_path / "scene"
    options = GenerateOptions(library=default_library.root, seed=0, render=False)
    generate_scene(CLASSROOM, out, options)
    record = json.loads((out / "generate.json").read_text())
    grid = record["layout"]["classroom"]["desk_grid"]
    assert grid["fallback"] is None, grid["tried"]
    assert grid["rows"] >= 2 and grid["columns"] >= 2
    report = json.loads((out / "report.json").read_text())
    assert report["ok"], report["counts"]
    score = _score_module()
    reach = score.reachability(score.MeasuredFolder(out))
    assert reach["entrance_found"] and reach["share"] >= 0.97, reach
    objects = json.loads((out / "scene.json").read_text())["objects"]
    assert sum(o["id"].startswith("classroom.student_desk_") for o in objects) == 8
    assert sum(o["id"].startswith("classroom.school_chair_") for o in objects) == 8
    board = next(o for o in objects if o["id"].startswith("classroom.whiteboard_"))
    front = LineString(grid["front_wall"])
    assert front.distance(Point(board["position"][:2])) <= 0.2  # on the wall the desks face
