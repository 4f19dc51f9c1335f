"""The stability rule on hand-made scenes, through the CLI: every check the validator makes has a
scene that it (and the checks listed with it) catches, and controls that must pass.

The scenes are plain MJCF (``tests/data/physics/*.xml``, validated as they are) and holomj
scenes (``tests/data/physics/scenes/*.json``, compiled with ``holomj compile`` against a small
library of primitive assets, then validated as folders); ``cases.json`` lists, per object, the
checks that must fail. A check that is removed, or one that fires where it should not, fails
here.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from holomj.cli import app
from holomj.spec.report import ObjectReport, StabilityReport
from tests.physics.scenes import primitive_library

DATA = Path(__file__).parents[1] / "data" / "physics"
CASES = {k: v for k, v in json.loads((DATA / "cases.json").read_text()).items() if k[0] != "_"}
SCENES = DATA / "scenes"


def failed_checks(obj: ObjectReport, report: StabilityReport) -> set[str]:
    """The checks of the stability rule that ``obj`` fails, from its numbers."""
    th = report.thresholds
    checks = {
        "drift": obj.drift_m >= th.drift_m,
        "turn": obj.rotation_deg >= th.rotation_deg,
        "displacement": obj.displacement_m >= th.displacement_m,
        "rotation_from_authored": obj.rotation_from_authored_deg >= th.rotation_from_authored_deg,
        "penetration": obj.penetration_m > th.tolerance_m,
        "fell": obj.fell,
        "support": obj.dynamic
        and obj.expected_support is not None
        and obj.support != obj.expected_support,
        "left_room": obj.left_room,
    }
    return {name for name, failed in checks.items() if failed}


def check_report(report: StabilityReport, expected: dict[str, list[str]]) -> None:
    """Every object judged as ``expected``; report-level fields agree with the rows."""
    rows = {o.name: o for o in report.objects}
    assert set(rows) == set(expected)
    for name, checks in expected.items():
        obj = rows[name]
        assert failed_checks(obj, report) == set(checks), (name, obj)
        assert obj.stable == (not checks), (name, obj.reasons)
        assert bool(obj.reasons) == bool(checks), (name, obj.reasons)
    assert report.ok == all(not checks for checks in expected.values())
    assert report.counts["unstable"] == sum(bool(c) for c in expected.values())
    deepest = max((p.depth_m for p in report.penetrations), default=0.0)
    assert report.max_penetration_m == pytest.approx(deepest, abs=1e-6)
    assert report.max_penetration_m == pytest.approx(
        max(o.penetration_m for o in report.objects), abs=1e-6
    )
    for pair in report.penetrations:
        for name in (pair.a, pair.b):
            if name in rows:
                assert rows[name].penetration_m >= pair.depth_m - 1e-6
                assert any("at t = 0" in r for r in rows[name].reasons)
    assert report.static_objects == [o.name for o in report.objects if not o.dynamic]


def run_validate(target: Path, out: Path, *options: str) -> tuple[int, StabilityReport, str]:
    """``holomj validate TARGET --json OUT --strict``: exit code, report and console text."""
    result = CliRunner().invoke(
        app, ["validate", str(target), "--json", str(out), "--strict", *options]
    )
    report = StabilityReport.model_validate_json(out.read_text())
    return result.exit_code, report, result.output


@pytest.mark.parametrize("case", sorted(CASES))
def test_plain_mjcf_scene(case: str, tmp_path: Path) -> None:
    expected = CASES[case]["mjcf"]
    code, report, output = run_validate(DATA / f"{case}.xml", tmp_path / "report.json")
    check_report(report, expected)
    assert code == (0 if report.ok else 1), output


@pytest.fixture(scope="module")
def primitives(tmp_path_factory: pytest.TempPathFactory) -> Path:
    root = tmp_path_factory.mktemp("primitives") / "library"
    primitive_library(root, json.loads((SCENES / "primitive_assets.json").read_text()))
    return root


@pytest.mark.parametrize("case", sorted(c for c in CASES if "holomj" in CASES[c]))
def test_holomj_scene(case: str, primitives: Path, tmp_path: Path) -> None:
    folder = tmp_path / case
    compiled = CliRunner().invoke(
        app,
        ["compile", str(SCENES / f"{case}.json"), "-o", str(folder), "--library", str(primitives)],
    )
    assert compiled.exit_code == 0, compiled.output
    furniture = CASES[case].get("holomj_furniture", "free")
    code, report, output = run_validate(folder, tmp_path / "report.json", "--furniture", furniture)
    check_report(report, CASES[case]["holomj"])
    assert code == (0 if report.ok else 1), output
    assert report.furniture == furniture


def test_every_scene_file_has_a_case() -> None:
    xml = {p.stem for p in DATA.glob("*.xml")}
    scenes = {p.stem for p in SCENES.glob("*.json")} - {"primitive_assets"}
    assert xml == set(CASES)
    assert scenes == {c for c in CASES if "holomj" in CASES[c]}
