"""Kitchens as counter runs: modules side by side along the walls in one wall, L, U or galley,
the shape honoured when asked for, simpler shapes (and finally independent placement) when it
does not fit, and the same run for the same seed."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from shapely import affinity
from shapely.geometry import LineString, Point, Polygon, box

from holomj.compose.house_shell import build_shell
from holomj.compose.room_assets import retrieve_room
from holomj.compose.room_context import RoomContext
from holomj.compose.room_furnishing import furnish_room
from holomj.layout.counter_run_arrangements import (
    FILLER_MAX_M,
    SHAPES,
    RunModule,
    arrangements,
    leg_ends,
)
from holomj.layout.counter_runs import solve_counter_run
from holomj.layout.furniture_rules import object_id
from holomj.layout.geometry import LAYOUT_MARGIN_M
from holomj.layout.room_problem import LayoutDoor, LayoutObject, RoomProblem
from holomj.layout.solve import solve_room
from holomj.library.store import AssetLibrary
from holomj.spec.decor import DECOR_CATEGORIES
from holomj.spec.plan import ScenePlan
from holomj.spec.scene import Room, SceneObject, SceneSpec
from tests.layout.choosers import CategoryChooser

WALL_THICKNESS = 0.1
GAP_MAX = 0.01  # neighbouring modules of a leg touch (their gap at most 1 cm)
KITCHEN = [
    ("kitchen counter", "kitchen_counter"),
    ("sink counter", "sink_counter"),
    ("stove", "stove"),
    ("dishwasher", "dishwasher"),
    ("fridge", "fridge"),
]
RUN = {"kitchen_counter", "sink_counter", "stove", "base_cabinet", "dishwasher"}


def kitchen_plan(
    size: tuple[float, float],
    objects: list[tuple[str, str]],
    *,
    windows: int = 0,
    seed: int = 1,
    shape: str | None = None,
) -> ScenePlan:
    """A one-room kitchen plan, every object defining and at an edge (as the template has it)."""
    return ScenePlan.model_validate(
        {
            "prompt": "a kitchen",
            "planner": "offline",
            "seed": seed,
            "scene_type": "kitchen",
            "rooms": [
                {
                    "id": "kitchen",
                    "type": "kitchen",
                    "size": list(size),
                    "windows": {"count": windows, "kind": "slider"},
                    "objects": [
                        {
                            "name": name,
                            "category": category,
                            "defining": True,
                        }
                        for name, category in objects
                    ],
                    "constraints": [f"{name}-0 | edge" for name, _ in objects],
                    "counter_run_shape": shape,
                }
            ],
        }
    )


def furnish_kitchen(library, size, objects=KITCHEN, *, windows=0, seed=1, **kw):
    """Plan, shell and furnish one kitchen (``shape``: the counter run the plan asks for); the
    room and its furniture."""
    plan = kitchen_plan(size, objects, windows=windows, seed=seed, **kw)
    shell = build_shell(plan, seed, None)
    context = RoomContext(
        SceneSpec(rooms=shell.rooms).walls, shell.doors, shell.windows, 2.7, WALL_THICKNESS
    )
    plan_room, room = plan.rooms[0], shell.rooms[0]
    assets = retrieve_room(plan_room, library, CategoryChooser(library), seed)
    return room, furnish_room(plan_room, room, context, assets, library, seed)


def footprint(obj: SceneObject, size: tuple[float, float, float]) -> Polygon:
    depth, width, _ = size
    rect = box(-depth / 2, -width / 2, depth / 2, width / 2)
    return affinity.translate(affinity.rotate(rect, obj.yaw_deg), obj.position[0], obj.position[1])


def legs_of(room_id: str, objects: list[SceneObject], record: dict) -> list[list[SceneObject]]:
    by_id = {o.id: o for o in objects}
    return [[by_id[object_id(room_id, m)] for m in leg["modules"]] for leg in record["legs"]]


def inset_of(room: Room) -> Polygon:
    """The outline the layout works in: the room inset by half a wall and the margin."""
    return Polygon(room.polygon).buffer(-(WALL_THICKNESS / 2 + LAYOUT_MARGIN_M), join_style="mitre")


def assert_runs_are_contiguous(
    room: Room, objects: list[SceneObject], record: dict, library
) -> None:
    """Every leg: one yaw, backs on the layout's wall line, neighbours touching in order; no
    two pieces of floor furniture overlap."""
    sizes = sizes_of(library, objects)
    inset = inset_of(room)
    for leg in legs_of(room.id, objects, record):
        assert len({round(o.yaw_deg) % 360 for o in leg}) == 1, [o.id for o in leg]
        yaw = math.radians(leg[0].yaw_deg)
        front, side = (math.cos(yaw), math.sin(yaw)), (-math.sin(yaw), math.cos(yaw))
        spans = []
        for obj in leg:
            depth, width, _ = sizes[obj.asset]
            back = (obj.position[0] - front[0] * depth / 2, obj.position[1] - front[1] * depth / 2)
            assert inset.exterior.distance(Point(back)) < 1e-3, obj.id
            along = obj.position[0] * side[0] + obj.position[1] * side[1]
            spans.append((along - width / 2, along + width / 2, obj.id))
        ordered = sorted(spans)
        for (_, end, a), (start, _, b) in zip(ordered, ordered[1:]):
            assert -1e-6 <= start - end <= GAP_MAX, (a, b, start - end)
        # chain order is order along the wall (one way or the other)
        ids = [s[2] for s in ordered]
        assert ids in ([o.id for o in leg], [o.id for o in leg][::-1])
    floor = [
        o
        for o in objects
        if o.position[2] == 0.0
        and library.get(o.asset).meta.category not in DECOR_CATEGORIES  # rugs lie under
        and "floor" in library.get(o.asset).meta.placement
    ]
    shapes = [footprint(o, sizes[o.asset]) for o in floor]
    for i, a in enumerate(shapes):
        for j in range(i + 1, len(shapes)):
            assert a.intersection(shapes[j]).area < 1e-9, (floor[i].id, floor[j].id)


def sizes_of(library, objects: list[SceneObject]) -> dict[str, tuple]:
    return {o.asset: library.get(o.asset).meta.size for o in objects}


def assert_fronts_are_free(modules: list[SceneObject], sizes: dict[str, tuple]) -> None:
    """No module of the run stands in the 0.3 m in front of another's fronts (the doors of a
    module covering a corner would open into the other leg)."""
    for a in modules:
        depth, width, _ = sizes[a.asset]
        band = box(depth / 2 + 0.005, -width / 2 + 0.005, depth / 2 + 0.3, width / 2 - 0.005)
        band = affinity.translate(affinity.rotate(band, a.yaw_deg, origin=(0, 0)), *a.position[:2])
        for b in modules:
            if b is not a:
                assert footprint(b, sizes[b.asset]).intersection(band).area < 1e-9, (a.id, b.id)


def junction_gap(leg: list[SceneObject], b: SceneObject, sizes: dict[str, tuple]) -> float:
    """How far module ``b`` of one leg is from the nearest module of the other ``leg``."""
    other = footprint(b, sizes[b.asset])
    return min(footprint(a, sizes[a.asset]).distance(other) for a in leg)


@pytest.fixture(scope="module")
def l_kitchen(default_library):
    return furnish_kitchen(default_library, (3.6, 3.2), shape="L", windows=1)


def test_an_l_shaped_kitchen_has_two_legs_meeting_at_a_corner(l_kitchen, default_library):
    room, furniture = l_kitchen
    record = furniture.layout["counter_run"]
    assert record["shape"] == "L" and record["requested"] == "L"
    assert record["chosen_by"] == "request" and record["fallback"] is None
    sizes = sizes_of(default_library, furniture.objects)
    assert_runs_are_contiguous(room, furniture.objects, record, default_library)
    corner_leg, arm = legs_of(room.id, furniture.objects, record)
    assert [leg["role"] for leg in record["legs"]] == ["corner", "arm"]
    # the legs stand on two walls at right angles
    assert (round(corner_leg[0].yaw_deg - arm[0].yaw_deg) // 90) % 2 == 1
    # the corner leg owns the corner square and leaves it empty (a dead corner): its last
    # module stands the depth of the arm's first module off the arm's wall ...
    inset = inset_of(room)
    corner = footprint(corner_leg[-1], sizes[corner_leg[-1].asset])
    arm_back = footprint(arm[0], sizes[arm[0].asset])
    walls = [
        LineString([a, b])
        for a, b in zip(inset.exterior.coords, list(inset.exterior.coords)[1:])
        if LineString([a, b]).distance(arm_back) < 1e-3
    ]
    arm_depth = sizes[arm[0].asset][0]
    assert walls and abs(min(w.distance(corner) for w in walls) - arm_depth) < 0.005
    # ... and the arm starts at its front, touching it without overlapping
    assert junction_gap(corner_leg, arm[0], sizes) <= GAP_MAX
    assert corner.intersection(arm_back).area < 1e-9
    # so no module has the other leg in front of its doors and drawers
    assert_fronts_are_free(corner_leg + arm, sizes)
    # every module is placed, and the run's modules are all the room's run modules
    placed = {o.id for o in furniture.objects}
    assert all(object_id(room.id, m) in placed for m in record["modules"])
    assert not furniture.unplaced


def test_no_module_of_a_run_is_a_cooker_or_dishwasher_in_a_corner(l_kitchen, default_library):
    _, furniture = l_kitchen
    record = furniture.layout["counter_run"]
    corner_module = record["legs"][0]["modules"][-1]
    category = {o.id: default_library.get(o.asset).meta.category for o in furniture.objects}
    assert category[object_id("kitchen", corner_module)] not in ("stove", "dishwasher")


def test_a_galley_kitchen_has_legs_on_opposite_walls_facing_each_other(default_library):
    room, furniture = furnish_kitchen(default_library, (2.6, 4.4), shape="galley", windows=1)
    record = furniture.layout["counter_run"]
    assert record["shape"] == "galley"
    sizes = sizes_of(default_library, furniture.objects)
    assert_runs_are_contiguous(room, furniture.objects, record, default_library)
    a, b = legs_of(room.id, furniture.objects, record)
    assert round(a[0].yaw_deg - b[0].yaw_deg) % 360 == 180
    # they face each other: their stretches along the walls overlap
    yaw = math.radians(a[0].yaw_deg)
    side = (-math.sin(yaw), math.cos(yaw))

    def stretch(leg):
        along = [o.position[0] * side[0] + o.position[1] * side[1] for o in leg]
        half = [sizes[o.asset][1] / 2 for o in leg]
        return min(p - h for p, h in zip(along, half)), max(p + h for p, h in zip(along, half))

    (a0, a1), (b0, b1) = stretch(a), stretch(b)
    assert min(a1, b1) - max(a0, b0) > 0.3
    # and an aisle is left between them
    fronts = [footprint(o, sizes[o.asset]) for o in a], [footprint(o, sizes[o.asset]) for o in b]
    gap = min(p.distance(q) for p in fronts[0] for q in fronts[1])
    assert gap >= 0.9 - 1e-6


def test_a_u_shaped_kitchen_closes_its_legs_at_both_corners(default_library):
    objects = [*KITCHEN[:4], ("base cabinet", "base_cabinet"), KITCHEN[4]]
    # 3.8 m a side: the two dead corners need the room a 3.25 m square lacks
    room, furniture = furnish_kitchen(default_library, (3.8, 3.8), objects, shape="U")
    record = furniture.layout["counter_run"]
    assert record["shape"] == "U", record["tried"]
    sizes = sizes_of(default_library, furniture.objects)
    assert_runs_are_contiguous(room, furniture.objects, record, default_library)
    a, middle, c = legs_of(room.id, furniture.objects, record)
    assert round(a[0].yaw_deg - c[0].yaw_deg) % 360 == 180  # the side legs face each other
    assert (round(a[0].yaw_deg - middle[0].yaw_deg) // 90) % 2 == 1
    gaps = sorted([junction_gap(a, middle[0], sizes), junction_gap(middle, c[0], sizes)])
    assert gaps[0] <= GAP_MAX  # one junction closes exactly
    assert gaps[1] <= FILLER_MAX_M + GAP_MAX  # the other within a filler strip
    assert 0.0 <= record["filler_m"] <= FILLER_MAX_M
    assert_fronts_are_free(a + middle + c, sizes)


def test_a_u_that_does_not_fit_falls_back_to_an_l(default_library):
    room, furniture = furnish_kitchen(default_library, (3.6, 3.2), shape="U")
    record = furniture.layout["counter_run"]
    assert record["requested"] == "U"
    assert record["tried"][0]["shape"] == "U" and record["tried"][0]["outcome"]
    assert record["shape"] == "L"
    assert record["fallback"].startswith("U: ")
    assert_runs_are_contiguous(room, furniture.objects, record, default_library)


def test_a_room_that_holds_no_run_lays_the_modules_out_one_by_one():
    """A narrow room with a door in each long wall: no wall, corner or pair of walls holds
    the run, so the layout is today's independent one, and the record says why."""
    doors = [
        LayoutDoor(id="door_a", position=(0.0, 1.6), width=0.9),
        LayoutDoor(id="door_b", position=(1.8, 1.6), width=0.9),
    ]
    objects = [
        LayoutObject(id="kitchen counter-0", width=1.2, depth=0.62, height=0.9, priority=100),
        LayoutObject(id="sink counter-0", width=1.2, depth=0.62, height=1.1, priority=100),
        LayoutObject(id="stove-0", width=0.6, depth=0.65, height=0.95, priority=100),
    ]
    problem = RoomProblem(
        polygon=[(0.0, 0.0), (1.8, 0.0), (1.8, 3.2), (0.0, 3.2)],
        size_unit="m",
        doors=doors,
        objects=objects,
        constraints_text="kitchen counter-0 | edge\nsink counter-0 | edge\nstove-0 | edge",
    )
    modules = [
        RunModule("kitchen counter-0", "kitchen_counter", 1.2, 0.62, 0.9, 100),
        RunModule("sink counter-0", "sink_counter", 1.2, 0.62, 1.1, 100),
        RunModule("stove-0", "stove", 0.6, 0.65, 0.95, 100),
    ]

    def solve(p: RoomProblem):
        return solve_room(p, rng=np.random.default_rng(5))

    result, record = solve_counter_run(
        problem, modules, solve=solve, rng=np.random.default_rng(0), requested="L"
    )
    assert record is not None and record["shape"] == "independent"
    assert record["fallback"].endswith("the modules are laid out one by one")
    assert {t["shape"] for t in record["tried"]} >= {"L"}
    plain = solve(problem)
    assert result.placements == plain.placements  # exactly today's layout: nothing dropped


def test_a_room_without_a_sink_or_cooker_has_no_run():
    problem = RoomProblem(
        polygon=[(0.0, 0.0), (3.0, 0.0), (3.0, 3.0), (0.0, 3.0)],
        size_unit="m",
        objects=[LayoutObject(id="base cabinet-0", width=0.6, depth=0.58, height=0.88)],
    )
    modules = [RunModule("base cabinet-0", "base_cabinet", 0.6, 0.58, 0.88)]
    result, record = solve_counter_run(
        problem, modules, solve=solve_room, rng=np.random.default_rng(0)
    )
    assert record is None and "base cabinet-0" in result.placements


def test_the_same_seed_lays_the_same_run(default_library):
    first = furnish_kitchen(default_library, (3.4, 3.4), windows=1, seed=4)[1]
    again = furnish_kitchen(default_library, (3.4, 3.4), windows=1, seed=4)[1]
    assert first.layout["counter_run"] == again.layout["counter_run"]
    assert [o.model_dump() for o in first.objects] == [o.model_dump() for o in again.objects]
    assert first.layout["counter_run"]["shape"] in SHAPES


def test_kitchens_of_the_offline_planner_get_contiguous_runs(default_library):
    from holomj.plan.offline import plan_offline

    shapes = []
    for seed in (0, 1, 2):
        plan = plan_offline("a kitchen", seed)
        shell = build_shell(plan, seed, None)
        context = RoomContext(
            SceneSpec(rooms=shell.rooms).walls,
            shell.doors,
            shell.windows,
            plan.wall_height,
            WALL_THICKNESS,
        )
        plan_room = plan.rooms[0]
        room = shell.rooms[0]
        assets = retrieve_room(plan_room, default_library, CategoryChooser(default_library), 0)
        furniture = furnish_room(plan_room, room, context, assets, default_library, seed)
        record = furniture.layout["counter_run"]
        shapes.append(record["shape"])
        if record["shape"] != "independent":
            assert_runs_are_contiguous(room, furniture.objects, record, default_library)
        categories = {default_library.get(a).meta.category for a in assets.floor.values()}
        assert sorted(record["modules"]) == sorted(
            i for i, a in assets.floor.items() if default_library.get(a).meta.category in RUN
        )
        assert "sink_counter" in categories
        # all placed, but a wall cabinet the prompt did not ask for that found no counter to
        # hang over and would narrow the way anywhere else
        for item in furniture.unplaced:
            assert item["stage"] == "wall" and "narrow the way" in item["reason"], item
    assert any(s != "independent" for s in shapes), shapes


# --------------------------------------------------------------------------- arrangements


def module(name: str, category: str, width: float) -> RunModule:
    return RunModule(f"{name}-0", category, width, 0.62, 0.9)


MODULES = [
    module("kitchen counter", "kitchen_counter", 1.2),
    module("counter b", "kitchen_counter", 0.6),
    module("sink counter", "sink_counter", 1.2),
    module("stove", "stove", 0.6),
    module("dishwasher", "dishwasher", 0.6),
]


@pytest.mark.parametrize("shape", SHAPES)
def test_no_arrangement_puts_the_cooker_or_dishwasher_in_a_corner(shape):
    found = arrangements(MODULES, shape)
    assert found, shape
    for arr in found:
        for k, leg in enumerate(arr.legs):
            start, end = arr.ends(k)
            for pos, ends in ((0, start), (len(leg) - 1, end)):
                if ends == "corner":
                    assert leg[pos].category not in ("stove", "dishwasher")


def test_the_sink_and_cooker_are_set_into_the_run_when_it_has_modules_to_end_it():
    for shape in ("one_wall", "L"):
        best = arrangements(MODULES, shape)[0]
        chain = [m for leg in best.legs for m in leg]
        assert chain[0].category not in ("sink_counter", "stove"), shape
        assert chain[-1].category not in ("sink_counter", "stove"), shape
    best = arrangements(MODULES, "one_wall")[0]
    order = [m.category for m in best.legs[0]]
    dishwasher = order.index("dishwasher")
    assert "sink_counter" in order[dishwasher - 1 : dishwasher + 2]  # next to the sink


def test_leg_ends_name_corners_and_junctions():
    assert leg_ends("L", (0,)) == (("open", "corner"), ("junction", "open"))
    assert leg_ends("U", (1, 1)) == (
        ("open", "junction"),
        ("corner", "corner"),
        ("junction", "open"),
    )
    assert leg_ends("galley", ()) == (("open", "open"), ("open", "open"))


# --------------------------------------------------------------------------- end to end


@pytest.mark.slow
def test_a_generated_kitchen_has_its_counters_in_a_run_and_stands_still(
    tmp_path: Path, default_library
) -> None:
    from holomj.jobs.generate import GenerateOptions, generate_scene

    out = tmp_path / "kitchen"
    generate_scene(
        "a kitchen", out, GenerateOptions(library=default_library.root, seed=0, render=False)
    )
    record = json.loads((out / "generate.json").read_text())["layout"]["kitchen"]
    run = record["counter_run"]
    assert run["shape"] in SHAPES, run
    scene = SceneSpec.model_validate_json((out / "scene.json").read_text())
    room = next(r for r in scene.rooms if r.id == "kitchen")
    objects = [o for o in scene.objects if o.room == "kitchen"]
    library = AssetLibrary.open(default_library.root)  # with the assets made on demand
    assert_runs_are_contiguous(room, objects, run, library)
    report = json.loads((out / "report.json").read_text())
    assert report["ok"], report["counts"]
    assert report["counts"]["unstable"] == 0 and report["counts"]["penetrations"] == 0
    # a window the run stands in front of was raised above the worktop, and the scene says so
    raised = {w["id"]: w["base_height"] for w in run.get("raised_windows", [])}
    for window in scene.windows:
        if window.id in raised:
            assert window.base_height == pytest.approx(raised[window.id])
