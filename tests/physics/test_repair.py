"""--repair: separate small penetrations, settle, bake the poses back, re-export atomically."""

from __future__ import annotations

import json
from pathlib import Path

import mujoco
import pytest

from holomj.jobs.folder import load_for_physics
from holomj.jobs.validate import repair_folder, validate
from holomj.library import AssetLibrary
from holomj.physics.audit import audit
from holomj.physics.repair import SETTLED_KEY
from tests.physics.scenes import FAST, box, export, make_scene


def _positions(folder: Path) -> dict[str, list[float]]:
    scene = json.loads((folder / "scene.json").read_text())
    return {o["id"]: o["position"] for o in scene["objects"]}


def test_repair_fixes_five_millimetre_overlaps(empty_library: AssetLibrary, tmp_path: Path) -> None:
    scene = make_scene(
        [
            box("base", (3, 3, -0.005), (0.4, 0.4, 0.2)),  # 5 mm into the floor
            box("top", (3, 3, 0.19), (0.2, 0.2, 0.1), support="base"),  # 5 mm into base
            box("table", (1.5, 1.5, 0), (0.8, 0.8, 0.7), static=True),
            box("cup", (1.5, 1.5, 0.695), (0.1, 0.1, 0.1), support="table"),  # 5 mm into table
        ]
    )
    folder = export(scene, empty_library, tmp_path / "sunk", {"import_report.json": {"kept": True}})
    (folder / "notes.txt").write_text("kept too")
    before = audit(load_for_physics(folder))
    assert len(before.penetrations) == 3 and [d.name for d in before.below_floor] == ["base"]

    outcome = repair_folder(folder, thresholds=FAST)

    after = audit(load_for_physics(folder))
    assert after.ok, after.penetrations
    report = validate(folder, thresholds=FAST)
    assert report.ok, [o.reasons for o in report.objects]
    positions = _positions(folder)
    # base rises 5 mm (minus the contact's rest depth); top rides along and loses its own 5 mm.
    assert positions["base"][2] - (-0.005) == pytest.approx(0.005, abs=0.0015)
    assert positions["top"][2] - 0.19 == pytest.approx(0.010, abs=0.002)
    assert positions["cup"][2] - 0.695 == pytest.approx(0.005, abs=0.0015)
    assert positions["table"] == [1.5, 1.5, 0.0]  # static: never moved by settling
    moved = {a.name: a for a in outcome.repaired}
    assert set(moved) == {"base", "top", "cup"}
    assert moved["cup"].moved_m == pytest.approx(0.005, abs=0.0015)
    assert "separated from table" in moved["cup"].why
    assert outcome.unsaved == []
    # The folder is a complete export again, with the settled keyframe and the other files.
    model = mujoco.MjModel.from_xml_path(str(folder / "scene.xml"))
    key = model.key(SETTLED_KEY)
    assert key.qpos.shape == (model.nq,)
    assert json.loads((folder / "import_report.json").read_text()) == {"kept": True}
    assert (folder / "notes.txt").read_text() == "kept too"
    assert not list(tmp_path.glob(".sunk*"))  # no temporary folders left behind


def test_deep_penetration_is_unsaved_and_nothing_is_deleted(
    empty_library: AssetLibrary, tmp_path: Path
) -> None:
    scene = make_scene(
        [
            box("block", (3, 3, 0), (0.4, 0.4, 0.4), static=True),
            box("buried", (3, 3, 0.32), (0.2, 0.2, 0.2), support="block"),  # 8 cm deep
        ]
    )
    folder = export(scene, empty_library, tmp_path / "deep")
    outcome = repair_folder(folder, thresholds=FAST)
    # Both parties of the pair are in a penetration (rule (c)); only the free one could move.
    assert [u.name for u in outcome.unsaved] == ["block", "buried"]
    assert all("80.0 mm" in u.why for u in outcome.unsaved)
    assert _positions(folder)["buried"] == [3.0, 3.0, 0.32]  # kept where it was
    assert set(_positions(folder)) == {"block", "buried"}


def test_repair_needs_a_holomj_folder(tmp_path: Path) -> None:
    from holomj.errors import InputError

    path = tmp_path / "model.xml"
    path.write_text("<mujoco><worldbody/></mujoco>")
    with pytest.raises(InputError, match="holomj scene folder"):
        repair_folder(path)
