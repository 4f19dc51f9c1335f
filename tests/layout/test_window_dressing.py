"""Curtains and blinds hang at windows: centred, above the window's top, wide enough, clear of
the wall, doors, furniture and other wall objects; what finds no window is reported."""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pytest
from shapely.geometry import Polygon, box

from holomj.compose.house_shell import build_shell
from holomj.compose.room_assets import retrieve_room
from holomj.compose.room_context import RoomContext
from holomj.compose.room_furnishing import furnish_room
from holomj.layout.furniture_rules import WALL_KINDS, object_id
from holomj.layout.wall_faces import FloorItem, WallPlacement
from holomj.layout.wall_objects import WallObjectRequest, place_wall_objects
from holomj.layout.window_dressing import (
    CURTAIN_OVERHANG_M,
    DRESSING_KINDS,
    FLOOR_GAP_M,
    FRAME_PROUD_M,
    ROD_ABOVE_M,
    STANDOFF_M,
)
from holomj.spec.scene import Door, Room, SceneSpec, Window
from holomj.spec.walls import Wall, derive_walls, find_wall_for_opening
from tests.layout.choosers import CategoryChooser

THICK = 0.1
CURTAINS = (1.4, 0.1, 2.4)  # the knowledge base's curtains: width, depth, height
BLINDS = (1.2, 0.05, 1.5)


def _rect(rid: str, x0: float, y0: float, x1: float, y1: float) -> Room:
    return Room(id=rid, polygon=[(x0, y0), (x1, y0), (x1, y1), (x0, y1)])


ROOMS = [_rect("living", 0, 0, 5, 4), _rect("bed", 5, 0, 8, 4)]
WALLS = derive_walls(ROOMS)
WEST = Window(id="west", rooms=["living"], position=(0.0, 2.0), width=1.2, height=1.2)


@dataclass(frozen=True)
class Hung:
    """A placed dressing in its wall's terms."""

    wall: Wall
    t: float  # centre along the wall
    width: float
    z0: float
    z1: float
    back: float  # distance of its back in front of the wall face
    foot: Polygon


def _hung(p: WallPlacement, size: tuple[float, float, float], room: str = "living") -> Hung:
    wall = next(w for w in WALLS if w.id == p.wall_id)
    t, off = wall.locate((p.x, p.y))
    if wall.exterior:
        inward, face = (-wall.outward[0], -wall.outward[1]), 0.0
    else:
        nx, ny = wall.normal
        inward, face = ((nx, ny) if wall.left_room == room else (-nx, -ny)), THICK / 2
    sign = 1.0 if inward == pytest.approx(wall.normal) else -1.0
    yaw = math.radians(p.yaw_deg)
    assert (math.cos(yaw), math.sin(yaw)) == pytest.approx(inward, abs=1e-6)  # faces the room
    sx, sy, sz = p.scale or (1.0, 1.0, 1.0)
    assert sx == 1.0
    width, depth, height = size[0] * sy, size[1], size[2] * sz
    # The footprint in world x/y: the asset's box rotated by the yaw.
    c, s = math.cos(yaw), math.sin(yaw)
    corners = [(dx, dy) for dx, dy in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
    foot = Polygon(
        [
            (
                p.x + c * dx * depth / 2 - s * dy * width / 2,
                p.y + s * dx * depth / 2 + c * dy * width / 2,
            )
            for dx, dy in corners
        ]
    )
    return Hung(wall, t, width, p.z, p.z + height, sign * off - face - depth / 2, foot)


def _window_t(window: Window) -> tuple[Wall, float]:
    return find_wall_for_opening(WALLS, window.rooms, window.position, window.width)


def _place(requests, windows, floor=(), doors=(), room=ROOMS[0], wall_height=2.7):
    return place_wall_objects(
        room,
        WALLS,
        list(doors),
        list(windows),
        list(floor),
        requests,
        np.random.default_rng(0),
        wall_height=wall_height,
        wall_thickness=THICK,
    )


def _curtains(cid: str = "curtains") -> WallObjectRequest:
    return WallObjectRequest(id=cid, size=CURTAINS, kind="curtains")


def _blinds(bid: str = "blinds") -> WallObjectRequest:
    return WallObjectRequest(id=bid, size=BLINDS, kind="blinds")


def test_curtains_centred_above_the_window_wider_than_it_to_the_floor() -> None:
    placed, unplaced = _place([_curtains()], [WEST])
    assert unplaced == []
    (p,) = placed
    hung = _hung(p, CURTAINS)
    wall, t = _window_t(WEST)
    assert hung.wall.id == wall.id and hung.t == pytest.approx(t, abs=1e-3)
    assert hung.width == pytest.approx(WEST.width + 2 * CURTAIN_OVERHANG_M, abs=1e-3)
    assert hung.z0 == pytest.approx(FLOOR_GAP_M)
    top = WEST.base_height + WEST.height
    assert hung.z1 == pytest.approx(top + ROD_ABOVE_M, abs=1e-3)
    assert 0.1 <= hung.z1 - top <= 0.15
    # In front of the wall face and clear of the window frame, which stands proud of it.
    assert hung.back == pytest.approx(STANDOFF_M, abs=1e-3)
    assert hung.back > FRAME_PROUD_M
    assert Polygon(ROOMS[0].polygon).covers(hung.foot)
    assert p.note is None
    obj = p.scene_object("curtains_asset")
    assert obj.static and obj.scale == p.scale and obj.room == "living"


def test_curtains_on_an_interior_wall_keep_off_its_face() -> None:
    shared = Window(id="inner", rooms=["bed", "living"], position=(5.0, 1.5), width=1.0)
    for room in ROOMS:
        placed, unplaced = _place([_curtains()], [shared], room=room)
        assert unplaced == []
        hung = _hung(placed[0], CURTAINS, room.id)
        assert hung.wall.id == _window_t(shared)[0].id
        assert hung.back == pytest.approx(STANDOFF_M, abs=1e-3)
        # Not in the wall: inside the room shrunk by half the wall's thickness.
        inner = Polygon(room.polygon).buffer(-THICK / 2 - STANDOFF_M + 1e-6, join_style="mitre")
        assert inner.covers(hung.foot)


def test_blinds_cover_the_opening() -> None:
    placed, unplaced = _place([_blinds()], [WEST])
    assert unplaced == []
    hung = _hung(placed[0], BLINDS)
    _, t = _window_t(WEST)
    assert hung.t == pytest.approx(t, abs=1e-3)
    assert WEST.width <= hung.width <= WEST.width + 0.1
    assert hung.z0 == pytest.approx(WEST.base_height)
    top = WEST.base_height + WEST.height
    assert top <= hung.z1 <= top + 0.1
    assert hung.z1 - hung.z0 == pytest.approx(WEST.height, abs=0.1)
    assert hung.back > FRAME_PROUD_M


def test_furniture_under_the_window_makes_curtains_sill_length_and_leaves_blinds() -> None:
    desk = FloorItem("desk", box(0.03, 1.3, 0.63, 2.7), 0.75)
    placed, unplaced = _place([_curtains()], [WEST], floor=[desk])
    assert unplaced == []
    (p,) = placed
    hung = _hung(p, CURTAINS)
    assert desk.height <= hung.z0 <= WEST.base_height
    assert hung.z1 == pytest.approx(WEST.base_height + WEST.height + ROD_ABOVE_M, abs=1e-3)
    assert p.note is not None and "sill length" in p.note and "desk" in p.note
    assert not hung.foot.intersects(desk.footprint) or hung.z0 >= desk.height

    placed, unplaced = _place([_blinds()], [WEST], floor=[desk])
    assert unplaced == [] and placed[0].note is None
    assert _hung(placed[0], BLINDS).z0 == pytest.approx(WEST.base_height)


def test_tall_furniture_at_the_window_is_reported() -> None:
    shelf = FloorItem("bookcase", box(0.03, 1.0, 0.43, 3.0), 1.8)
    placed, unplaced = _place([_curtains(), _blinds()], [WEST], floor=[shelf])
    assert placed == []
    assert [u.id for u in unplaced] == ["curtains", "blinds"]
    assert "bookcase" in unplaced[0].reason and "west" in unplaced[0].reason


def test_a_door_beside_the_window_narrows_the_curtains() -> None:
    door = Door(id="side", rooms=["living"], position=(0.0, 3.2), width=0.8)
    placed, unplaced = _place([_curtains()], [WEST], doors=[door])
    assert unplaced == []
    (p,) = placed
    hung = _hung(p, CURTAINS)
    _, t = _window_t(WEST)
    _, dt = find_wall_for_opening(WALLS, door.rooms, door.position, door.effective_width)
    assert hung.t == pytest.approx(t, abs=1e-3)  # still centred
    assert hung.width >= WEST.width  # still covers the opening
    assert hung.width < WEST.width + 2 * CURTAIN_OVERHANG_M
    # Clear of the door and its frame.
    assert hung.t + hung.width / 2 <= dt - door.effective_width / 2 - 0.05 + 1e-6
    assert p.note is not None and "door side" in p.note


def test_curtains_at_two_windows_by_a_corner_keep_clear_of_each_other() -> None:
    west = Window(id="w", rooms=["living"], position=(0.0, 0.8), width=1.0)
    south = Window(id="s", rooms=["living"], position=(0.8, 0.0), width=1.0)
    placed, unplaced = _place([_curtains("c0"), _curtains("c1")], [west, south])
    assert unplaced == []
    first, second = (_hung(p, CURTAINS) for p in placed)
    assert {first.wall.id, second.wall.id} == {_window_t(west)[0].id, _window_t(south)[0].id}
    assert first.foot.distance(second.foot) >= 0.02 - 1e-3  # scales are rounded
    # The one dressed second gave way at the corner; both still cover their windows.
    assert sorted([first.width, second.width]) == pytest.approx(
        [1.0 + 2 * CURTAIN_OVERHANG_M - 0.05, 1.0 + 2 * CURTAIN_OVERHANG_M], abs=1e-3
    )
    assert any(p.note and "another wall object" in p.note for p in placed)


def test_largest_window_first_one_dressing_each_extra_ones_reported() -> None:
    small = Window(id="south", rooms=["living"], position=(3.5, 0.0), width=1.0, height=1.0)
    big = Window(id="big", rooms=["living"], position=(0.0, 2.0), width=1.6, height=1.4)
    requests = [_curtains("c0"), _blinds("b0"), _curtains("c1")]
    placed, unplaced = _place(requests, [small, big])
    by_id = {p.id: p for p in placed}
    assert set(by_id) == {"c0", "b0"}
    assert by_id["c0"].wall_id == _window_t(big)[0].id
    assert by_id["b0"].wall_id == _window_t(small)[0].id
    (extra,) = unplaced
    assert extra.id == "c1" and "no window left" in extra.reason
    assert "big" in extra.reason and "south" in extra.reason


def test_a_room_with_no_window_reports_its_dressings() -> None:
    other_room = Window(id="elsewhere", rooms=["living"], position=(0.0, 2.0))
    placed, unplaced = _place([_curtains(), _blinds()], [other_room], room=ROOMS[1])
    assert placed == []
    assert [u.id for u in unplaced] == ["curtains", "blinds"]
    assert all("no window" in u.reason and "'bed'" in u.reason for u in unplaced)


def test_other_wall_objects_keep_clear_of_the_curtains() -> None:
    # Only the west wall (with the window) is free: a wide painting asked for before the
    # curtains must still leave the window to them and not overlap them.
    furniture = [
        FloorItem("s", box(0.6, 0.05, 4.9, 0.6), 2.4),
        FloorItem("n", box(0.6, 3.4, 4.9, 3.95), 2.4),
        FloorItem("e", box(4.4, 0.6, 4.9, 3.4), 2.4),
    ]
    painting = WallObjectRequest(id="art", size=(1.1, 0.04, 0.6), kind="painting")
    placed, unplaced = _place([painting, _curtains()], [WEST], floor=furniture)
    assert unplaced == []
    assert [p.id for p in placed] == ["art", "curtains"]  # in request order
    art, curtains = placed
    hung = _hung(curtains, CURTAINS)
    assert hung.t == pytest.approx(_window_t(WEST)[1], abs=1e-3)
    assert art.wall_id == hung.wall.id
    art_t, _ = hung.wall.locate((art.x, art.y))
    assert abs(art_t - hung.t) >= (1.1 + hung.width) / 2 - 1e-6


def test_a_window_at_the_ceiling_leaves_no_room_for_a_curtain_rod() -> None:
    high = Window(id="high", rooms=["living"], position=(0.0, 2.0), base_height=1.3, height=1.33)
    placed, unplaced = _place([_curtains(), _blinds()], [high])
    assert [u.id for u in unplaced] == ["curtains"]
    assert "ceiling" in unplaced[0].reason
    hung = _hung(placed[0], BLINDS)
    assert hung.z1 <= 2.7 - 0.05 + 1e-6 and hung.z1 >= 1.3 + 1.33


def test_frame_depth_and_kinds_agree_with_the_rest_of_holomj() -> None:
    from holomj.mjcf.opening_geometry import FRAME_DEPTH_EXTRA

    assert FRAME_PROUD_M == FRAME_DEPTH_EXTRA
    assert {WALL_KINDS["curtains"], WALL_KINDS["blinds"]} == DRESSING_KINDS


def test_a_bedroom_with_curtains_end_to_end(default_library, tmp_path: Path) -> None:
    """Real planner, shell, layout, MJCF and validation (retrieval by category: quick)."""
    from holomj.mjcf.compiler import compile_scene
    from holomj.physics.scene_io import loaded_from_compiled
    from holomj.physics.settle import validate_loaded
    from holomj.plan.offline import plan_offline

    plan = plan_offline("a bedroom with curtains", 3)
    (plan_room,) = plan.rooms
    (curtains,) = [o for o in plan_room.objects if o.category == "curtains"]
    shell = build_shell(plan, 3, pick_material=None)
    walls = derive_walls(shell.rooms)
    context = RoomContext(walls, shell.doors, shell.windows, plan.wall_height, THICK)
    (room,) = shell.rooms
    assets = retrieve_room(plan_room, default_library, CategoryChooser(default_library), 3)
    done = furnish_room(plan_room, room, context, assets, default_library, 3)
    assert done.windows, "the bedroom has windows to dress"

    ids = {object_id(room.id, i) for i in curtains.instances()}
    hung = [o for o in done.objects if o.id in ids]
    reported = {u["object"]: u["reason"] for u in done.unplaced}
    assert hung, (done.unplaced, done.changes)
    assert len(hung) + sum(i in reported for i in curtains.instances()) == len(ids)
    assert len(hung) == min(len(ids), len(done.windows))
    for reason in reported.values():
        assert "no window left" in reason
    at = set()
    for obj in hung:
        size = default_library.get(obj.asset).meta.size  # depth, width, height
        _, sy, sz = obj.scale3
        window = next(
            w
            for w in done.windows
            for wall, t in [find_wall_for_opening(walls, w.rooms, w.position, w.width)]
            if abs(wall.locate(obj.position[:2])[0] - t) < 1e-3
            and abs(wall.locate(obj.position[:2])[1]) < 0.3
        )
        at.add(window.id)
        assert obj.static
        assert size[1] * sy >= window.width
        top = obj.position[2] + size[2] * sz
        assert window.base_height + window.height < top <= plan.wall_height
    assert len(at) == len(hung)  # one per window

    scene = SceneSpec(
        wall_height=plan.wall_height,
        rooms=shell.rooms,
        doors=shell.doors,
        windows=done.windows,
        objects=done.objects,
    )
    compiled = compile_scene(scene, default_library)
    report = validate_loaded(loaded_from_compiled(compiled, default_library, tmp_path))
    assert report.counts["penetrations"] == 0, report.penetrations
    assert report.ok, [(o.name, o.reasons) for o in report.unstable()]
