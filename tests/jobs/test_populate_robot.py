"""``holomj populate`` on a folder with a robot and the files of a generate run: the robot stays,
renders and logs are kept, the files derived from the scene are rewritten for the new scene."""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path

import mujoco
import numpy as np
import pytest
from typer.testing import CliRunner

from holomj.cli import app
from holomj.library import AssetLibrary
from holomj.mjcf.compiler import CompiledScene
from holomj.physics.spawn import populate
from tests.physics.spawn_helpers import receptacle_scene

runner = CliRunner()


@pytest.fixture
def robot_folder(tmp_path: Path, default_library: AssetLibrary) -> Path:
    """The one-room dining-table scene compiled with the Jaco, validated into ``report.json``,
    with stand-ins for what a generate run leaves besides (renders, report page, log)."""
    scene_json = tmp_path / "scene_in.json"
    scene_json.write_text(receptacle_scene("dining_table_000").model_dump_json(exclude_none=True))
    out = tmp_path / "out"
    library = str(default_library.root)
    compiled = runner.invoke(
        app, ["compile", str(scene_json), "-o", str(out), "-q", "--library", library,
              "--robot", "jaco"],
    )  # fmt: skip
    assert compiled.exit_code == 0, compiled.output
    validated = runner.invoke(app, ["validate", str(out), "-q", "--json", str(out / "report.json")])
    assert validated.exit_code == 0, validated.output
    (out / "renders").mkdir()
    (out / "renders" / "top.png").write_bytes(b"\x89PNG old view")
    (out / "report.html").write_text("<html>old page</html>")
    (out / "generate.log").write_text("[    0.00 s] setup: the history of this folder\n")
    return out


def test_populate_keeps_the_robot_and_rewrites_what_depends_on_the_scene(
    robot_folder: Path, default_library: AssetLibrary
) -> None:
    robot_before = json.loads((robot_folder / "robot.json").read_text())
    report_before = json.loads((robot_folder / "report.json").read_text())
    assert [o["name"] for o in report_before["objects"]] == ["rec"]
    result = runner.invoke(
        app,
        ["populate", str(robot_folder), "--library", str(default_library.root), "--on", "rec",
         "--objects", "mug,book", "--seed", "2"],
    )  # fmt: skip
    assert result.exit_code == 0, result.output
    assert "report.json rewritten" in result.stdout and "holomj render" in result.stdout
    # The robot is still in the scene, where it stood, and the folder validates (not exit 2).
    assert json.loads((robot_folder / "robot.json").read_text()) == robot_before
    model = mujoco.MjModel.from_xml_path(str(robot_folder / "scene.xml"))
    assert model.body("robot/base_mount").pos.tolist() == robot_before["position"]
    validated = runner.invoke(app, ["validate", str(robot_folder), "--json", "-"])
    assert validated.exit_code in (0, 1), validated.output
    # Renders, the page and the log are kept as they were, and listed as predating the run.
    assert (robot_folder / "renders" / "top.png").read_bytes() == b"\x89PNG old view"
    assert (robot_folder / "report.html").read_text() == "<html>old page</html>"
    assert "the history of this folder" in (robot_folder / "generate.log").read_text()
    populate_report = json.loads((robot_folder / "populate_report.json").read_text())
    assert populate_report["stale_files"] == ["renders", "report.html"]
    # report.json, objects.json and the navmap describe the new scene.
    added = {p["object_id"] for p in populate_report["placements"] if p["accepted"]}
    assert len(added) == 2
    report = json.loads((robot_folder / "report.json").read_text())
    assert {o["name"] for o in report["objects"]} == {"rec", *added}
    assert report["furniture"] == "free" and populate_report["validation"]["ok"] == report["ok"]
    objects = json.loads((robot_folder / "objects.json").read_text())
    assert {o["id"] for o in objects["objects"]} == {"rec", *added}
    assert objects["robot"]["name"] == "jaco"
    navmap = json.loads((robot_folder / "navmap.json").read_text())
    assert navmap["robot"]["position"] == robot_before["position"]


def test_populate_without_a_report_writes_none(
    tmp_path: Path, robot_folder: Path, default_library: AssetLibrary
) -> None:
    (robot_folder / "report.json").unlink()
    result = runner.invoke(
        app,
        ["populate", str(robot_folder), "--library", str(default_library.root), "--on", "rec",
         "--objects", "apple", "--json"],
    )  # fmt: skip
    assert result.exit_code == 0, result.output
    assert "validation" not in json.loads(result.stdout)
    assert not (robot_folder / "report.json").exists()


def test_attach_puts_obstacles_into_the_drop_world(default_library: AssetLibrary) -> None:
    """What ``attach`` adds (a folder's robot) is in the world candidates are dropped into: a
    box over the whole table leaves no free space."""

    def cover_the_table(compiled: CompiledScene) -> CompiledScene:
        spec = compiled.spec.copy()
        body = spec.worldbody.add_body(name="cover", pos=[2.0, 2.0, 1.0])
        body.add_geom(type=mujoco.mjtGeom.mjGEOM_BOX, size=[1.5, 1.5, 0.4])
        return dataclasses.replace(compiled, spec=spec, model=spec.compile())

    scene = receptacle_scene("dining_table_000")
    rng = np.random.default_rng(0)
    free = populate(scene, default_library, "rec", [("apple", 1)], rng, max_attempts=3)
    assert free.all_placed
    rng = np.random.default_rng(0)
    covered = populate(
        scene, default_library, "rec", [("apple", 1)], rng, max_attempts=3, attach=cover_the_table
    )
    assert not covered.all_placed
    assert covered.placements[0].rejections == {"collides at spawn": 3}
