"""Floor plans: packed rooms are rectangles of the asked size that touch and never overlap;
explicit polygons are validated with clear errors."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from shapely.geometry import Polygon

from holomj.errors import SpecError
from holomj.layout.door_window_placement import place_doors, place_windows, reachable
from holomj.layout.floorplan import (
    DOOR_SPAN_M,
    RoomRequest,
    plan_floor,
    room_adjacency,
    shared_edge_length,
    validate_floor,
)
from holomj.spec.scene import Room, SceneSpec
from holomj.spec.walls import derive_walls, find_wall_for_opening

TYPES = ["living_room", "kitchen", "bedroom", "bathroom", "dining_room", "office", "hallway"]


@st.composite
def room_requests(draw: st.DrawFn) -> list[RoomRequest]:
    n = draw(st.integers(1, 8))
    ids = [f"r{i}" for i in range(n)]
    reqs = []
    for rid in ids:
        rtype = draw(st.sampled_from(TYPES))
        mode = draw(st.sampled_from(["area", "area", "size", "default"]))
        lo = draw(st.sampled_from([2.5, 2.5, 2.0, 3.0]))
        hi = draw(st.sampled_from([8.0, 8.0, 6.0, 10.0]))
        others = [o for o in ids if o != rid]
        adjacent = (
            draw(st.lists(st.sampled_from(others), max_size=2, unique=True)) if others else []
        )
        common = {"id": rid, "type": rtype, "adjacent_to": adjacent, "min_side": lo, "max_side": hi}
        if mode == "area":
            reqs.append(RoomRequest(area_m2=draw(st.floats(4.0, 90.0)), **common))
        elif mode == "size":
            size = (draw(st.floats(lo, hi)), draw(st.floats(lo, hi)))
            reqs.append(RoomRequest(size=size, **common))
        else:
            reqs.append(RoomRequest(**common))
    return reqs


def _sides(room: Room) -> tuple[float, float]:
    x0, y0, x1, y1 = Polygon(room.polygon).bounds
    return x1 - x0, y1 - y0


def _spans(scene: SceneSpec) -> dict[str, list[tuple[float, float, str]]]:
    walls = scene.walls
    out: dict[str, list[tuple[float, float, str]]] = {}
    for opening in [*scene.doors, *scene.windows]:
        width = getattr(opening, "effective_width", None) or opening.width
        wall, t = find_wall_for_opening(walls, opening.rooms, opening.position, width)
        out.setdefault(wall.id, []).append((t - width / 2, t + width / 2, opening.id))
    return out


@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(reqs=room_requests(), seed=st.integers(0, 2**32 - 1))
def test_random_requests_give_valid_connected_scenes(reqs: list[RoomRequest], seed: int) -> None:
    rng = np.random.default_rng(seed)
    plan = plan_floor(reqs, rng)
    assert [r.id for r in plan.rooms] == [r.id for r in reqs]
    for req, room in zip(reqs, plan.rooms):
        assert len(room.polygon) == 4  # rectangles
        w, d = _sides(room)
        assert Polygon(room.polygon).area == pytest.approx(w * d)
        for side in (w, d):
            assert req.min_side - 1e-6 <= side <= req.max_side + 1e-6
        if req.size is not None:
            assert sorted((w, d)) == pytest.approx(sorted(req.size), abs=0.006)
        elif req.min_side**2 <= req.target_area <= req.max_side**2:
            assert w * d == pytest.approx(req.target_area, rel=0.02)
    # Connected through edges long enough for a door.
    adjacency = room_adjacency(plan.rooms, DOOR_SPAN_M)
    seen, stack = {plan.entrance}, [plan.entrance]
    while stack:
        for nbr in adjacency[stack.pop()]:
            if nbr not in seen:
                seen.add(nbr)
                stack.append(nbr)
    assert seen == {r.id for r in plan.rooms}
    assert not any(w.startswith("gap") for w in plan.warnings)

    doors = place_doors(plan.rooms, rng, entrance=plan.entrance)
    windows = place_windows(plan.rooms, doors, rng)
    scene = SceneSpec(rooms=plan.rooms, doors=doors, windows=windows)  # validates openings
    assert reachable(plan.rooms, doors, plan.entrance) == {r.id for r in plan.rooms}
    assert any(len(d.rooms) == 1 and d.rooms == [plan.entrance] for d in doors)
    walls = {w.id: w for w in scene.walls}
    for wall_id, spans in _spans(scene).items():
        spans.sort()
        for (_, a1, a), (b0, _, b) in zip(spans, spans[1:]):
            assert b0 >= a1 + 0.3 - 1e-6, (a, b)
        for t0, t1, oid in spans:
            assert t0 >= 0.3 - 1e-6 and t1 <= walls[wall_id].length - 0.3 + 1e-6, oid
            if oid.startswith("window"):
                assert walls[wall_id].exterior
    for window in windows:
        assert window.base_height + window.height <= scene.wall_height - 0.15 + 1e-9


def test_same_seed_same_plan() -> None:
    reqs = [
        RoomRequest(id="living", type="living_room", area_m2=24),
        RoomRequest(id="kitchen", type="kitchen", area_m2=12, adjacent_to=["living"]),
        RoomRequest(id="bed", type="bedroom", area_m2=14),
        RoomRequest(id="bath", type="bathroom", adjacent_to=["bed"]),
    ]
    a = plan_floor(reqs, np.random.default_rng(3))
    b = plan_floor(reqs, np.random.default_rng(3))
    assert a == b
    assert a.entrance == "living"


def test_adjacency_wishes_are_met_when_possible() -> None:
    reqs = [
        RoomRequest(id="living", type="living_room", area_m2=20),
        RoomRequest(id="kitchen", type="kitchen", area_m2=10, adjacent_to=["living"]),
        RoomRequest(id="bed", type="bedroom", area_m2=12, adjacent_to=["bath"]),
        RoomRequest(id="bath", type="bathroom", area_m2=7),
        RoomRequest(id="office", type="office", area_m2=9, adjacent_to=["living"]),
    ]
    plan = plan_floor(reqs, np.random.default_rng(0))
    assert "kitchen" in plan.adjacency["living"]
    assert "bath" in plan.adjacency["bed"]
    assert "office" in plan.adjacency["living"]
    assert plan.warnings == []


def test_impossible_wishes_become_warnings() -> None:
    # Five rooms that all touch each other: not a planar graph, so some wish stays unmet.
    ids = [f"r{i}" for i in range(5)]
    reqs = [RoomRequest(id=rid, area_m2=9, adjacent_to=[o for o in ids if o != rid]) for rid in ids]
    plan = plan_floor(reqs, np.random.default_rng(1))
    assert any("asked to be adjacent" in w for w in plan.warnings)


def test_out_of_range_area_is_clamped_with_a_warning() -> None:
    plan = plan_floor([RoomRequest(id="hall", area_m2=100)], np.random.default_rng(0))
    w, d = _sides(plan.rooms[0])
    assert w <= 8.0 + 1e-9 and d <= 8.0 + 1e-9
    assert any("cannot have sides" in m for m in plan.warnings)


def test_custom_side_bounds_are_honoured() -> None:
    reqs = [
        RoomRequest(id="corridor", type="corridor", area_m2=12, min_side=1.5, max_side=10),
        RoomRequest(id="living", type="living_room", area_m2=30),
    ]
    plan = plan_floor(reqs, np.random.default_rng(2), entrance_room="corridor")
    assert plan.entrance == "corridor"
    for side in _sides(plan.room("corridor")):
        assert 1.5 <= side <= 10


@pytest.mark.parametrize(
    ("requests", "message"),
    [
        ([{"id": "a"}, {"id": "a"}], "duplicate room id"),
        ([{"id": "a", "adjacent_to": ["kitchn"]}, {"id": "kitchen"}], "unknown room 'kitchn'"),
        ([{"id": "a", "area_m2": 10, "size": [3, 3]}], "not both"),
        ([{"id": "a", "size": [1, 3]}], "outside"),
        ([{"id": "a", "min_side": 5, "max_side": 3}], "exceeds max_side"),
        ([], "no rooms"),
    ],
)
def test_bad_requests_raise(requests: list[dict], message: str) -> None:
    with pytest.raises(SpecError, match=message):
        plan_floor(requests, np.random.default_rng(0))


def test_unknown_entrance_names_close_match() -> None:
    with pytest.raises(SpecError, match="did you mean living"):
        plan_floor([{"id": "living"}], np.random.default_rng(0), entrance_room="livng")


# --- explicit polygons ---------------------------------------------------------------------


def _room(rid: str, poly: list[tuple[float, float]]) -> dict:
    return {"id": rid, "polygon": poly}


def test_l_shape_with_its_neighbour_is_valid() -> None:
    kitchen = _room("kitchen", [(0, 0), (4, 0), (4, 3), (0, 3)])
    living = _room("living", [(4, 0), (7, 0), (7, 5), (0, 5), (0, 3), (4, 3)])
    assert validate_floor([kitchen, living]) == []


def test_overlap_is_an_error() -> None:
    a = _room("a", [(0, 0), (4, 0), (4, 4), (0, 4)])
    b = _room("b", [(3, 0), (7, 0), (7, 4), (3, 4)])
    with pytest.raises(SpecError, match=r"'a' overlaps room 'b' by 4\.00 m²"):
        validate_floor([a, b])


def test_containment_is_an_error() -> None:
    outer = _room("outer", [(0, 0), (6, 0), (6, 6), (0, 6)])
    inner = _room("inner", [(1, 1), (3, 1), (3, 3), (1, 3)])
    with pytest.raises(SpecError, match="'outer' contains room 'inner'"):
        validate_floor([outer, inner])


def test_disconnected_rooms_are_an_error() -> None:
    a = _room("a", [(0, 0), (3, 0), (3, 3), (0, 3)])
    b = _room("b", [(5, 0), (8, 0), (8, 3), (5, 3)])
    corner = _room("c", [(3, 3), (6, 3), (6, 6), (3, 6)])  # touches a only at a corner
    with pytest.raises(SpecError, match="not connected: 2 groups"):
        validate_floor([a, b])
    with pytest.raises(SpecError, match="not connected"):
        validate_floor([a, corner])


def test_short_contact_does_not_connect() -> None:
    a = _room("a", [(0, 0), (3, 0), (3, 3), (0, 3)])
    b = _room("b", [(3, 2.5), (6, 2.5), (6, 5.5), (3, 5.5)])  # 0.5 m of shared edge
    assert shared_edge_length(Polygon(a["polygon"]), Polygon(b["polygon"])) == pytest.approx(0.5)
    with pytest.raises(SpecError, match="at least 1 m of wall"):
        validate_floor([a, b])


def test_hole_between_rooms_is_a_warning() -> None:
    # A ring of four rooms around an empty 2 x 2 courtyard.
    rooms = [
        _room("s", [(0, 0), (6, 0), (6, 2), (0, 2)]),
        _room("e", [(4, 2), (6, 2), (6, 4), (4, 4)]),
        _room("n", [(0, 4), (6, 4), (6, 6), (0, 6)]),
        _room("w", [(0, 2), (2, 2), (2, 4), (0, 4)]),
    ]
    warnings = validate_floor(rooms)
    assert len(warnings) == 1
    assert "gap of 4.00 m²" in warnings[0] and "(3.00, 3.00)" in warnings[0]


def test_self_intersection_names_the_room() -> None:
    bowtie = _room("bow", [(0, 0), (3, 3), (3, 0), (0, 3)])
    with pytest.raises(SpecError, match=r"rooms\[0\]\.polygon \(bow\): polygon intersects itself"):
        validate_floor([bowtie])


def test_slanted_walls_warn() -> None:
    a = _room("a", [(0, 0), (4, 0), (5, 3), (0, 3)])
    assert any("not axis-aligned" in w for w in validate_floor([a]))


def test_packed_plans_pass_validation_and_derive_walls() -> None:
    reqs = [RoomRequest(id=f"r{i}", area_m2=8 + 3 * i) for i in range(6)]
    plan = plan_floor(reqs, np.random.default_rng(5))
    assert validate_floor(plan.rooms) == []
    walls = derive_walls(plan.rooms)
    ext = sum(w.length for w in walls if w.exterior)
    assert ext > 0 and math.isfinite(ext)
