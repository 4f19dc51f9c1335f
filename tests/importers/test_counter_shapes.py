"""THOR's L- and U-shaped countertops become counter runs, not one solid box."""

from __future__ import annotations

import pytest
from shapely.geometry import box

from holomj.importers.counter_shapes import (
    COUNTER_DEPTH_M,
    counter_shape,
    nearest_run,
    split_counter,
)
from holomj.importers.procthor import import_procthor
from holomj.library.store import AssetLibrary
from holomj.spec.scene import SceneObject

from .conftest import load_real_house


def _choose(run_id: str, size: tuple[float, float, float]) -> tuple[str, tuple]:
    return "counter", size


def test_shapes_are_read_from_the_asset_id() -> None:
    assert counter_shape("Countertop_L_10x4") == "L"
    assert counter_shape("Countertop_C_8x10") == "C"
    assert counter_shape("Countertop_I_4x2") is None
    assert counter_shape("Sofa_1") is None


def test_a_u_shape_is_a_back_run_and_two_side_runs() -> None:
    # facing -Y (yaw -90): its back is at +Y, its sides at -X and +X
    counter = SceneObject(id="c", asset="x", position=(5.0, 5.0, 0.0), yaw_deg=-90.0)
    runs = split_counter(counter, "C", (3.0, 2.4, 0.94), None, _choose)
    d = COUNTER_DEPTH_M
    by_id = {r.id: r for r in runs}
    assert set(by_id) == {"c", "c_side_left", "c_side_right"}
    assert by_id["c"].position[:2] == pytest.approx((5.0, 5.0 + 1.5 - d / 2))
    assert by_id["c"].scale == pytest.approx((d, 2.4, 0.94))
    sides = sorted(r.position[0] for r in runs if r.id != "c")
    assert sides == pytest.approx([5.0 - 1.2 + d / 2, 5.0 + 1.2 - d / 2])
    for run in runs:
        if run.id != "c":  # a side run is as long as the shape is deep, less the back run
            assert run.scale == pytest.approx((d, 3.0 - d, 0.94))
            assert run.position[1] == pytest.approx(5.0 - d / 2)
    assert nearest_run(runs, 4.0, 4.0) == "c_side_right"  # its right is world -X here


def test_an_l_shape_puts_its_side_run_by_the_wall() -> None:
    room = box(0.0, 0.0, 6.0, 6.0)
    # yaw 0 (front +X), back at x = 0.4 - 0.6; left side (+Y) is near the wall y = 6
    counter = SceneObject(id="l", asset="x", position=(1.0, 5.0, 0.0), yaw_deg=0.0)
    runs = split_counter(counter, "L", (1.2, 2.0, 0.9), room, _choose)
    assert [r.id for r in runs] == ["l", "l_side_left"]


def test_a_real_kitchen_u_counter_holds_what_was_on_it(default_library: AssetLibrary) -> None:
    house = load_real_house("procthor_ai2thor_train_4.json")
    scene = import_procthor(house, default_library, "train_4").scene
    runs = [o for o in scene.objects if o.id.startswith("CounterTop|6|0")]
    assert len(runs) == 3
    supports = {o.support for o in scene.objects if (o.support or "").startswith("CounterTop")}
    assert supports == {r.id for r in runs}  # every run holds some of the kitchen's things
