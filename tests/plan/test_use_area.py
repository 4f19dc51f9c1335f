"""Rooms sized by the floor their furniture needs in use (holomj.plan.use_area, plan.fit)."""

from __future__ import annotations

import pytest

from holomj.plan.offline import plan_offline
from holomj.plan.use_area import AISLE_M, RUN_WALL_SHARE, SEAT_ZONE_M, group_area, play_area


def _room(prompt: str):
    plan = plan_offline(prompt, 0)
    assert len(plan.rooms) == 1
    return plan.rooms[0]


def test_a_group_holds_its_seats_and_aisles() -> None:
    assert group_area(1.0, 1.0, 0, False) == pytest.approx(1.0)
    one_sided = group_area(1.2, 0.6, 1, True)
    assert one_sided == pytest.approx((1.2 + AISLE_M) * (0.6 + SEAT_ZONE_M + AISLE_M))
    around = group_area(0.8, 0.8, 4, False)
    assert around == pytest.approx((0.8 + 2 * SEAT_ZONE_M + AISLE_M) ** 2)
    assert group_area(0.8, 0.8, 2, False) < around
    assert play_area(1.4, 2.5, 1.0) == pytest.approx(3.4 * 4.5)


@pytest.mark.parametrize(
    ("prompt", "floor_per_instance", "instances"),
    [
        # sixteen desks, each with its chair in front and an aisle: ~3.4 m² a desk
        ("A classroom with sixteen student desks, each with a chair.", 3.0, 16),
        # eight tables with four chairs around each: ~7.8 m² a table
        ("A restaurant with eight round tables each with four chairs.", 6.0, 8),
    ],
)
def test_a_room_grows_for_the_floor_its_groups_need(
    prompt: str, floor_per_instance: float, instances: int
) -> None:
    room = _room(prompt)
    assert room.area_m2 is not None
    assert room.area_m2 >= floor_per_instance * instances


def test_a_pool_table_gets_room_for_the_cue() -> None:
    room = _room("A game room with a pool table and a dartboard.")
    assert room.area_m2 is not None
    assert room.area_m2 >= play_area(1.4, 2.5, 1.0)


def test_a_restaurant_keeps_every_chair_asked_for() -> None:
    room = _room(
        "An Italian restaurant with eight round tables each with four chairs, a bar counter "
        "with five stools and two potted plants."
    )
    chairs = sum(o.quantity for o in room.objects if "chair" in o.name)
    assert chairs == 32


def test_a_long_counter_run_gets_walls_long_enough() -> None:
    room = _room("A kitchen with three long counters, a sink and a stove.")
    run = sum(
        o.size[0] * o.quantity
        for o in room.objects
        if o.category in {"kitchen_counter", "sink_counter", "stove"} and o.size
    )
    assert run >= 6.0
    assert room.area_m2 is not None and room.area_m2 >= (run / (4 * RUN_WALL_SHARE)) ** 2 - 0.1
