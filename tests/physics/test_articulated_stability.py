"""Validation knows joints: moving parts must stay within 2° / 5 mm of their authored values
through settling, and a door (here a lid) that swings open by itself makes its object unstable."""

from __future__ import annotations

from pathlib import Path

import pytest

from asset_pipeline.library_writer import AssetBundle, write_library
from asset_pipeline.procedural.articulated import generate_articulated
from holomj.jobs.validate import validate
from holomj.library import AssetLibrary
from holomj.mjcf import compile_scene
from holomj.physics.scene_io import loaded_from_compiled
from holomj.physics.settle import run_validation
from holomj.spec.report import STABILITY_RULE, Thresholds
from tests.physics.scenes import FAST, export, make_scene


def _library(root: Path, *, spring_factor: float = 1.0) -> AssetLibrary:
    """A dresser, a fridge and a trunk whose lid spring is ``spring_factor`` times its own."""
    trunk = generate_articulated("trunk", "trunk", None, 0)
    meta = trunk.meta
    assert meta.articulation is not None
    lid = meta.articulation.parts[0]
    joint = lid.joint.model_copy(update={"stiffness": lid.joint.stiffness * spring_factor})
    part = lid.model_copy(update={"joint": joint})
    articulation = meta.articulation.model_copy(update={"parts": [part]})
    trunk = AssetBundle(
        meta=meta.model_copy(update={"articulation": articulation}), files=trunk.files
    )
    bundles = [generate_articulated(c, c, None, 0) for c in ("dresser", "fridge")] + [trunk]
    return AssetLibrary.open(write_library(root, "articulated", bundles))


def _scene():
    return make_scene(
        [
            {"id": "dresser", "asset": "dresser", "position": [1.0, 3.0, 0.0], "room": "room"},
            {"id": "fridge", "asset": "fridge", "position": [3.0, 1.0, 0.0], "room": "room"},
            {"id": "trunk", "asset": "trunk", "position": [4.5, 4.5, 0.0], "room": "room"},
        ]
    )


def test_articulated_furniture_validates_ok(tmp_path: Path) -> None:
    library = _library(tmp_path / "library")
    folder = export(_scene(), library, tmp_path / "scene")
    report = validate(folder, thresholds=FAST)
    assert report.ok, [(o.name, o.reasons) for o in report.unstable()]
    rows = {o.name: o for o in report.objects}
    assert set(rows["dresser"].part_motion) >= {"drawer_0_slide", "drawer_1_slide"}
    assert max(rows["dresser"].part_motion.values()) < FAST.part_travel_m
    assert max(rows["fridge"].part_motion.values()) < FAST.part_rotation_deg
    assert "(d) moving parts" in STABILITY_RULE and report.stability_rule == STABILITY_RULE


def test_a_lid_that_swings_open_by_itself_is_unstable(tmp_path: Path) -> None:
    library = _library(tmp_path / "library", spring_factor=3.0)  # an over-strong lid stay
    compiled = compile_scene(_scene(), library, furniture="free")
    loaded = loaded_from_compiled(compiled, library, tmp_path / "scene.xml")
    report = run_validation(loaded, FAST, "free").report
    rows = {o.name: o for o in report.objects}
    trunk = rows["trunk"]
    assert not trunk.stable and not report.ok
    assert trunk.part_motion["lid_hinge"] > Thresholds().part_rotation_deg
    (reason,) = [r for r in trunk.reasons if "lid_hinge" in r]
    assert "swung" in reason and "by itself" in reason
    # The carcass itself did not move: only the part's rule failed.
    assert trunk.displacement_m < 0.005
    assert rows["dresser"].stable and rows["fridge"].stable


@pytest.mark.parametrize("limit", [0.5, 120.0])
def test_the_part_threshold_is_the_reports(tmp_path: Path, limit: float) -> None:
    library = _library(tmp_path / "library", spring_factor=3.0)
    loaded = loaded_from_compiled(
        compile_scene(_scene(), library, furniture="free"), library, tmp_path / "scene.xml"
    )
    th = FAST.model_copy(update={"part_rotation_deg": limit})
    report = run_validation(loaded, th, "free").report
    trunk = next(o for o in report.objects if o.name == "trunk")
    assert trunk.stable == (limit > 90.0)  # the lid swings fully open, 90°
    assert report.thresholds.part_rotation_deg == limit
