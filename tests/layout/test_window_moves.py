"""Moving or raising a window to make room for a room's defining furniture."""

from __future__ import annotations

from shapely.geometry import Polygon, box

from holomj.layout.window_moves import (
    FRONT_CLEAR_M,
    MIN_WINDOW_HEIGHT_M,
    raise_sill,
    relocate_window,
)
from holomj.spec.scene import Door, Room, Window
from holomj.spec.walls import derive_walls

ROOM = Room(id="bedroom", polygon=[(0, 0), (4, 0), (4, 3), (0, 3)])
WALLS = derive_walls([ROOM])
POLY = Polygon(ROOM.polygon)


def window(x: float, y: float, width: float = 1.2) -> Window:
    return Window(id="w", rooms=["bedroom"], position=(x, y), width=width)


def test_a_window_moves_to_the_nearest_free_stretch() -> None:
    bed = box(0.0, 2.0, 2.1, 3.0)  # along the top wall, under the window's old spot
    old = window(1.0, 3.0)
    moved = relocate_window(old, "bedroom", POLY, WALLS, [], [], [bed])
    assert moved is not None and moved.id == "w" and moved.width == old.width
    x, y = moved.position
    # still on the top wall, past the bed's end plus the front strip, or on another wall
    front = box(x - 0.6, y - FRONT_CLEAR_M, x + 0.6, y) if abs(y - 3.0) < 1e-6 else None
    assert front is None or not front.intersects(bed)
    assert moved.position != old.position


def test_doors_and_other_windows_keep_their_stretch() -> None:
    door = Door(id="d", rooms=["bedroom"], position=(2.0, 0.0))
    other = window(4.0, 1.5).model_copy(update={"id": "w2"})
    everything = [box(0, 0, 4, 3).difference(box(0.5, 0.5, 3.5, 2.5))]  # a ring of furniture
    assert (
        relocate_window(window(1.0, 3.0), "bedroom", POLY, WALLS, [door], [other], everything)
        is None
    )
    moved = relocate_window(window(1.0, 3.0), "bedroom", POLY, WALLS, [door], [other], [])
    assert moved is not None
    mx, my = moved.position
    assert not (abs(my) < 1e-6 and abs(mx - 2.0) < 0.5 + 0.6 + 0.3)  # clear of the door
    assert not (abs(mx - 4.0) < 1e-6 and abs(my - 1.5) < 1.2 + 0.3)  # clear of the window


def test_raised_sill_clears_the_headboard_or_gives_up() -> None:
    old = window(1.0, 3.0).model_copy(update={"base_height": 0.8, "height": 1.3})
    raised = raise_sill(old, above=1.0, wall_height=2.7)
    assert raised is not None and raised.base_height == 1.05
    assert raised.base_height + raised.height <= 2.7 - 0.2 + 1e-9
    assert raise_sill(old, above=2.0, wall_height=2.7) is None  # under MIN_WINDOW_HEIGHT_M left
    assert MIN_WINDOW_HEIGHT_M > 0
