"""Audit, settle and the stability report on small scenes built for each failure."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from holomj.jobs.folder import load_for_physics
from holomj.jobs.validate import validate
from holomj.library import AssetLibrary
from holomj.mjcf import compile_scene
from holomj.physics.audit import audit
from holomj.spec.report import StabilityReport
from holomj.spec.scene import SceneSpec
from tests.physics.scenes import FAST, box, export, make_scene, sphere_library


def _object(report: StabilityReport, name: str):
    return next(o for o in report.objects if o.name == name)


def test_two_room_scene_is_stable(
    two_room_scene: SceneSpec, empty_library: AssetLibrary, tmp_path: Path
) -> None:
    folder = export(two_room_scene, empty_library, tmp_path / "two_rooms")
    report = validate(folder, furniture="free")
    assert report.ok, [o.reasons for o in report.objects]
    assert {o.name for o in report.objects} == {o.id for o in two_room_scene.objects}
    assert report.penetrations == [] and report.below_floor == [] and report.outside_rooms == []
    assert report.settled and report.warnings == {}
    cube = _object(report, "cube")
    assert cube.support == "table" and cube.expected_support == "table"
    assert _object(report, "crate").support == "floor"
    assert _object(report, "table").support == "fixed"  # static in the scene
    assert all(o.drift_m < 0.001 and o.at_rest for o in report.objects)
    assert report.max_penetration_m == 0.0  # nothing interpenetrates at t = 0
    assert 0 < report.max_contact_depth_m < 0.001  # contacts are soft while resting
    assert report.sim_time_s == pytest.approx(report.settle_time_s + 3.0)


def test_leaning_tower_falls(empty_library: AssetLibrary, tmp_path: Path) -> None:
    objects = []
    for level in range(4):  # each box 8 cm further out: the top three overhang the base
        support = {"support": f"b{level - 1}"} if level else {}
        objects.append(
            box(f"b{level}", (3 + 0.08 * level, 3, 0.2 * level), (0.2, 0.2, 0.2), **support)
        )
    report = validate(
        export(make_scene(objects), empty_library, tmp_path / "tower"), thresholds=FAST
    )
    assert not report.ok
    top = _object(report, "b3")
    assert not top.stable and top.fell
    assert any("fell" in r for r in top.reasons)
    assert _object(report, "b0").expected_support == "floor"


def test_floating_box_falls(empty_library: AssetLibrary, tmp_path: Path) -> None:
    scene = make_scene([box("floater", (3, 3, 0.3), (0.2, 0.2, 0.2))])
    report = validate(export(scene, empty_library, tmp_path / "float"), thresholds=FAST)
    floater = _object(report, "floater")
    assert not report.ok and not floater.stable and floater.fell
    assert floater.drop_m == pytest.approx(0.3, abs=0.01)
    assert floater.support == "floor"  # it lands, but it fell to get there


def test_interpenetrating_boxes_are_reported(empty_library: AssetLibrary, tmp_path: Path) -> None:
    scene = make_scene(
        [box("left", (2.0, 3, 0), (0.4, 0.4, 0.4)), box("right", (2.37, 3, 0), (0.4, 0.4, 0.4))]
    )
    report = validate(export(scene, empty_library, tmp_path / "overlap"), thresholds=FAST)
    assert not report.ok
    assert len(report.penetrations) == 1
    pair = report.penetrations[0]
    assert {pair.a, pair.b} == {"left", "right"}
    assert pair.depth_m == pytest.approx(0.03, abs=1e-6)
    assert pair.geom_a.endswith("/collision_0") and pair.geom_b.endswith("/collision_0")
    assert report.counts["penetrations"] == 1


def test_static_pairs_and_floor_are_audited(empty_library: AssetLibrary, tmp_path: Path) -> None:
    scene = make_scene(
        [
            box("shelf_a", (2.0, 3, 0), (0.4, 0.4, 0.4), static=True),
            box("shelf_b", (2.38, 3, 0), (0.4, 0.4, 0.4), static=True),  # 2 cm into shelf_a
            box("sunk", (4.0, 3, -0.004), (0.2, 0.2, 0.2)),  # 4 mm into the floor
            box("outside", (7.0, 3, 0), (0.2, 0.2, 0.2)),
        ]
    )
    found = audit(load_for_physics(export(scene, empty_library, tmp_path / "statics")))
    pairs = {(p.a, p.b): p.depth_m for p in found.penetrations}
    assert pairs[("shelf_a", "shelf_b")] == pytest.approx(0.02, abs=1e-6)
    assert pairs[("sunk", "floor")] == pytest.approx(0.004, abs=1e-6)
    assert [d.name for d in found.below_floor] == ["sunk"]
    assert found.below_floor[0].value_m == pytest.approx(-0.004)
    assert [d.name for d in found.outside_rooms] == ["outside"]
    assert found.outside_rooms[0].value_m == pytest.approx(1.0)
    # Walls touch each other and the ground: structure against structure is never reported.
    assert all("structure" not in (p.a, p.b) or "outside" in (p.a, p.b) for p in found.penetrations)


def test_box_hanging_off_a_table_edge_falls(empty_library: AssetLibrary, tmp_path: Path) -> None:
    scene = make_scene(
        [
            box("table", (3, 3, 0), (1.0, 1.0, 0.75), static=True),
            # 30 cm long, only 7 cm of it on the table: the centre of mass is 8 cm past the edge.
            box("plank", (3.58, 3, 0.75), (0.3, 0.1, 0.05), support="table"),
        ]
    )
    report = validate(export(scene, empty_library, tmp_path / "edge"), thresholds=FAST)
    plank = _object(report, "plank")
    assert not report.ok and not plank.stable
    assert plank.fell and plank.support != "table"


def test_sphere_on_a_slope_rolls_away(tmp_path: Path) -> None:
    library = sphere_library(tmp_path / "lib")
    angle = math.radians(20)
    quat = (math.cos(angle / 2), 0.0, math.sin(angle / 2), 0.0)  # 20° about +y
    normal = (math.sin(angle), 0.0, math.cos(angle))
    origin = (3.0, 3.0, 0.45)
    top = [origin[i] + 0.1 * normal[i] for i in range(3)]  # centre of the top face
    centre = [top[i] + 0.05 * normal[i] for i in range(3)]
    scene = make_scene(
        [
            box("slope", origin, (2.0, 1.0, 0.1), quat=quat, static=True),
            {
                "id": "ball",
                "asset": "ball",
                "position": [centre[0], centre[1], centre[2] - 0.05],
                "support": "slope",
                "room": "room",
            },
        ]
    )
    folder = export(scene, library, tmp_path / "slope")
    found = audit(load_for_physics(folder))
    assert found.penetrations == []  # it starts just touching
    report = validate(folder, thresholds=FAST)
    ball = _object(report, "ball")
    assert not report.ok and not ball.stable
    assert ball.fell and ball.support != "slope"
    assert any("expected slope" in r for r in ball.reasons)


def test_validation_is_deterministic(
    two_room_scene: SceneSpec, empty_library: AssetLibrary, tmp_path: Path
) -> None:
    objects = [o.model_dump() for o in two_room_scene.objects]
    objects.append(
        {
            "id": "faller",
            "asset": "builtin:box",
            "position": [5.0, 4.0, 0.4],
            "scale": 0.2,
            "yaw_deg": 17,
            "room": "living",
        }
    )
    scene = SceneSpec.model_validate({**two_room_scene.model_dump(), "objects": objects})
    folder = export(scene, empty_library, tmp_path / "det")
    timing = {"wall_time_s", "realtime_factor"}
    first = validate(folder, thresholds=FAST).model_dump(exclude=timing)
    again = validate(folder, thresholds=FAST).model_dump(exclude=timing)
    assert first == again
    assert next(o for o in first["objects"] if o["name"] == "faller")["fell"]


def test_foreign_mjcf(tmp_path: Path) -> None:
    path = tmp_path / "foreign.xml"
    path.write_text(
        """<mujoco><worldbody><geom name="ground" type="plane" size="5 5 .1"/>
        <body name="resting" pos="0 0 0.1"><freejoint/><geom type="box" size=".1 .1 .1"/></body>
        <body name="dropped" pos="1 0 0.5"><freejoint/><geom type="sphere" size=".1"/></body>
        <geom name="look" type="box" size=".5 .5 .5" pos="0 0 0" contype="0" conaffinity="0"
              group="2"/>
        </worldbody></mujoco>"""
    )
    report = validate(path, thresholds=FAST)
    assert {o.name for o in report.objects} == {"resting", "dropped"}
    resting = next(o for o in report.objects if o.name == "resting")
    assert resting.stable and resting.expected_support is None and resting.support == "floor"
    assert not next(o for o in report.objects if o.name == "dropped").stable
    assert report.penetrations == [] and report.outside_rooms == []


def test_static_furniture_option(default_library: AssetLibrary, tmp_path: Path) -> None:
    scene = make_scene(
        [
            {"id": "table", "asset": "dining_table_000", "position": [3, 3, 0], "room": "room"},
            {
                "id": "mug",
                "asset": "mug_000",
                "position": [3, 3, 0.75],
                "support": "table",
                "room": "room",
            },
        ]
    )
    folder = export(scene, default_library, tmp_path / "furniture")
    static = validate(folder, thresholds=FAST, furniture="static")
    free = validate(folder, thresholds=FAST, furniture="free")
    assert static.ok and free.ok, (static.objects, free.objects)
    assert not _object(static, "table").dynamic and _object(free, "table").dynamic
    assert _object(free, "mug").support == "table"
    # compile_scene honours the option itself; the report says which mode ran.
    assert static.furniture == "static"
    assert compile_scene(scene, default_library, furniture="static").model.njnt == 1


def test_sleeping_gives_the_same_verdicts(empty_library: AssetLibrary, tmp_path: Path) -> None:
    scene = make_scene(
        [
            box("crate", (2, 2, 0), (0.5, 0.4, 0.3)),
            box("cube", (2, 2, 0.3), (0.1, 0.1, 0.1), support="crate"),
            box("floater", (4, 4, 0.3), (0.2, 0.2, 0.2)),
        ]
    )
    folder = export(scene, empty_library, tmp_path / "sleep")
    awake = validate(folder, thresholds=FAST)
    asleep = validate(folder, thresholds=FAST, sleep=True)
    for a, b in zip(awake.objects, asleep.objects):
        assert (a.name, a.stable, a.fell, a.support) == (b.name, b.stable, b.fell, b.support)
    assert [o.stable for o in asleep.objects] == [True, True, False]
