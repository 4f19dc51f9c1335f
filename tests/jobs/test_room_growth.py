"""A room of open size grows when its defining furniture does not fit, or when its furniture
cuts off free floor a robot cannot reach (holomj.jobs.generate)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

import holomj
from holomj.compose.house import GROWTH, REGROW_SHARE, grow, why_grow
from holomj.compose.room_context import RoomFurniture
from holomj.jobs.generate import GenerateOptions, generate_scene
from holomj.plan.offline import plan_offline

NURSERY = (
    "A nursery with two cribs side by side, a changing table, a white rocking chair next to "
    "the window, a toy chest, a mobile above each crib and a grey rug in the middle."
)


def test_a_room_grows_for_its_defining_furniture_then_for_its_reach() -> None:
    plan = plan_offline("a small bedroom", 0)
    room = plan.rooms[0]
    fine = RoomFurniture(room.id, layout={"reachable_share": REGROW_SHARE + 0.01})
    fenced = RoomFurniture(room.id, layout={"reachable_share": REGROW_SHARE - 0.2})
    no_bed = RoomFurniture(
        room.id,
        layout={"reachable_share": 1.0},
        unplaced=[{"object": "bed-0", "stage": "layout", "reason": "does not fit"}],
    )
    assert why_grow(room, fine) == ""
    assert "reachable (75% was)" in why_grow(room, fenced)
    assert why_grow(room, no_bed) == "its bed fits"
    grown, words = grow(plan, {room.id: why_grow(room, fenced)})
    assert grown.rooms[0].area_m2 == pytest.approx(round(room.area_m2 * GROWTH, 1))
    assert words.startswith(f"grew {room.id} from {room.area_m2:.1f} to")


@pytest.mark.slow
def test_a_crowded_nursery_grows_until_its_floor_is_reachable(
    tmp_path: Path, default_library
) -> None:
    """Two cribs, a changing table, a rocking chair, a toy chest and a dresser fence off floor
    in the nursery's first size; the plan grows it and says so."""
    out = tmp_path / "nursery"
    options = GenerateOptions(library=default_library.root, seed=0, render=False)
    generate_scene(NURSERY, out, options)
    record = json.loads((out / "generate.json").read_text())
    share = record["layout"]["nursery"]["reachable_share"]
    grew = [c for c in record["plan_changes"] if "free floor stays reachable" in c]
    assert share >= REGROW_SHARE or len(grew) == 2, (share, record["plan_changes"])
    navigability = holomj.eval(out).details["navigability"]
    assert navigability["share"] >= 0.97, navigability
