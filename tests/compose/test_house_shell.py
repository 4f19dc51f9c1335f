"""The house shell of a plan: floor plan, doors, windows, materials."""

from __future__ import annotations

from shapely.geometry import Polygon

from holomj.compose.house_shell import build_shell, room_request
from holomj.layout.door_window_placement import reachable
from holomj.spec.materials import Material
from holomj.spec.plan import PlanRoom
from holomj.spec.scene import SceneSpec
from tests.layout.plans import two_room_plan


def test_shell_has_every_room_connected_with_the_planned_windows() -> None:
    plan = two_room_plan()
    shell = build_shell(plan, seed=4, pick_material=None)
    assert [r.id for r in shell.rooms] == ["living_room", "kitchen"]
    areas = {r.id: Polygon(r.polygon).area for r in shell.rooms}
    assert abs(areas["living_room"] - 20) < 0.1 and abs(areas["kitchen"] - 11) < 0.1
    assert reachable(shell.rooms, shell.doors, shell.entrance) == {"living_room", "kitchen"}
    living = [w for w in shell.windows if w.rooms == ["living_room"]]
    assert len(living) == 2 and all(w.kind == "fixed" for w in living)
    # The kitchen leaves the count open: it gets its type's default (at least one).
    assert [w for w in shell.windows if w.rooms == ["kitchen"]]
    SceneSpec(rooms=shell.rooms, doors=shell.doors, windows=shell.windows)  # consistent


def test_shell_is_deterministic_for_a_seed_and_varies_across_seeds() -> None:
    plan = two_room_plan()
    a = build_shell(plan, seed=1, pick_material=None)
    b = build_shell(plan, seed=1, pick_material=None)
    assert (a.rooms, a.doors, a.windows) == (b.rooms, b.doors, b.windows)
    shells = [build_shell(plan, seed=s, pick_material=None) for s in range(6)]
    assert len({(tuple(map(tuple, s.rooms[0].polygon)), s.doors[0].position) for s in shells}) > 1


def test_materials_are_picked_per_surface_and_used_by_the_rooms() -> None:
    asked = []

    def pick(description: str, surface: str) -> tuple[str, Material]:
        asked.append((description, surface))
        return f"{surface}_pick", Material(rgba=(0.1, 0.2, 0.3, 1.0))

    plan = two_room_plan()
    shell = build_shell(plan, seed=0, pick_material=pick)
    assert all(r.floor_material == "floor_pick" for r in shell.rooms)
    assert all(r.wall_material == "wall_pick" for r in shell.rooms)
    assert set(shell.materials) == {"floor_pick", "wall_pick", "ceiling_pick"}
    assert ("wood floor", "floor") in asked
    assert shell.material_choices["kitchen"]["ceiling"] == "ceiling_pick"


def test_room_requests_widen_side_limits_for_large_or_small_rooms() -> None:
    big = room_request(PlanRoom(id="hall", type="classroom", size=(12.0, 9.0)))
    assert big.size == (12.0, 9.0) and big.max_side >= 12.0
    tiny = room_request(PlanRoom(id="wc", type="bathroom", size=(1.5, 2.0)))
    assert tiny.min_side <= 1.5
    large_area = room_request(PlanRoom(id="gym", type="gym", area_m2=120.0))
    assert large_area.max_side**2 >= 120.0
