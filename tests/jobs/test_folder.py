"""The exported folder: self-contained, loads from anywhere, equals the in-memory model."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import mujoco
import numpy as np
import pytest

from holomj.errors import ExportError, OutputExistsError
from holomj.jobs import folder as writer
from holomj.jobs.folder import write_scene_folder
from holomj.library import AssetLibrary
from holomj.mjcf import compile_scene
from holomj.mjcf.textures import pattern_png
from holomj.spec.base import read_json
from holomj.spec.scene import SceneSpec


@pytest.fixture
def exported(tmp_path: Path, two_room_scene: SceneSpec, empty_library: AssetLibrary):
    compiled = compile_scene(two_room_scene, empty_library)
    out = write_scene_folder(compiled, tmp_path / "out")
    return compiled, out


def _same_model(a: mujoco.MjModel, b: mujoco.MjModel) -> None:
    for field in ("nbody", "ngeom", "njnt", "nmesh", "nmat", "ntex", "ncam", "nlight", "nq", "nv"):
        assert getattr(a, field) == getattr(b, field), field
    for field in (
        "geom_size",
        "geom_pos",
        "geom_quat",
        "geom_group",
        "body_mass",
        "body_inertia",
        "jnt_range",
        "mesh_vert",
    ):
        np.testing.assert_allclose(
            getattr(a, field), getattr(b, field), rtol=1e-5, atol=1e-6, err_msg=field
        )
    assert [a.geom(i).name for i in range(a.ngeom)] == [b.geom(i).name for i in range(b.ngeom)]


def test_reloaded_model_equals_the_compiled_one(exported) -> None:
    compiled, out = exported
    reloaded = mujoco.MjModel.from_xml_path(str(out / "scene.xml"))
    _same_model(compiled.model, reloaded)


def test_only_relative_paths(exported) -> None:
    _, out = exported
    xml = (out / "scene.xml").read_text()
    assert str(out) not in xml and "/tmp" not in xml and 'file="/' not in xml
    for path in out.rglob("*"):
        assert not path.is_symlink()


def test_scene_json_round_trips(exported) -> None:
    compiled, out = exported
    again = SceneSpec.model_validate(read_json(out / "scene.json"))
    assert again == compiled.scene


def test_loads_from_any_working_directory_and_after_copying(exported, tmp_path: Path) -> None:
    _, out = exported
    moved = tmp_path / "elsewhere" / "copy"
    shutil.copytree(out, moved)
    shutil.rmtree(out)
    code = (
        "import mujoco, sys; m = mujoco.MjModel.from_xml_path(sys.argv[1]); d = mujoco.MjData(m); "
        "mujoco.mj_step(m, d); print(m.ngeom)"
    )
    result = subprocess.run(
        [sys.executable, "-c", code, str(moved / "scene.xml")],
        cwd="/",
        capture_output=True,
        text=True,
        check=False,
    )
    assert result.returncode == 0, result.stderr
    assert int(result.stdout.strip()) > 10


def test_dm_control_loads_and_steps(exported) -> None:
    from dm_control import mjcf

    _, out = exported
    root = mjcf.from_path(str(out / "scene.xml"), escape_separators=True)
    physics = mjcf.Physics.from_mjcf_model(root)
    for _ in range(100):
        physics.step()
    assert physics.data.time == pytest.approx(0.2)
    assert int(physics.data.warning.number.sum()) == 0


def test_existing_output_needs_overwrite(
    exported, two_room_scene: SceneSpec, empty_library: AssetLibrary
) -> None:
    compiled, out = exported
    marker = out / "marker.txt"
    marker.write_text("keep")
    with pytest.raises(OutputExistsError, match="--overwrite"):
        write_scene_folder(compiled, out)
    assert marker.read_text() == "keep"
    write_scene_folder(compiled, out, overwrite=True)
    assert not marker.exists()
    assert (out / "scene.xml").is_file()


def test_failed_export_leaves_nothing(
    tmp_path: Path, two_room_scene: SceneSpec, empty_library: AssetLibrary, monkeypatch
) -> None:
    compiled = compile_scene(two_room_scene, empty_library)
    real_write = writer._write_tree

    def half_written(c, root, extra):
        real_write(c, root, extra)
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(writer, "_write_tree", half_written)
    target = tmp_path / "target"
    target.mkdir()
    with pytest.raises(ExportError, match="No space left"):
        write_scene_folder(compiled, target / "out")
    assert list(target.iterdir()) == []
    # A failed overwrite keeps the previous export intact.
    monkeypatch.setattr(writer, "_write_tree", real_write)
    write_scene_folder(compiled, target / "out")
    before = (target / "out" / "scene.xml").read_bytes()
    monkeypatch.setattr(writer, "_write_tree", half_written)
    with pytest.raises(ExportError):
        write_scene_folder(compiled, target / "out", overwrite=True)
    assert (target / "out" / "scene.xml").read_bytes() == before
    assert [p.name for p in target.iterdir()] == ["out"]


def test_extra_reports_are_written(
    tmp_path: Path, two_room_scene: SceneSpec, empty_library: AssetLibrary
) -> None:
    compiled = compile_scene(two_room_scene, empty_library)
    out = write_scene_folder(
        compiled, tmp_path / "out", extra_json={"import_report.json": {"substitutions": []}}
    )
    assert json.loads((out / "import_report.json").read_text()) == {"substitutions": []}


def test_textures_are_copied_and_scene_json_points_at_them(
    tmp_path: Path, shared_assets: Path, empty_library: AssetLibrary
) -> None:
    from tests.conftest import two_room_data

    data = two_room_data()
    texture = shared_assets / "textures" / "libero_marble_floor.png"
    data["materials"] = {"marble_tex": {"texture": str(texture)}}
    data["rooms"][0]["floor_material"] = "marble_tex"
    compiled = compile_scene(SceneSpec.model_validate(data), empty_library)
    out = write_scene_folder(compiled, tmp_path / "out")
    scene = json.loads((out / "scene.json").read_text())
    assert scene["materials"]["marble_tex"]["texture"] == "assets/textures/marble_tex.png"
    assert (out / "assets/textures/marble_tex.png").read_bytes() == texture.read_bytes()
    # The living room's built-in oak floor wears the procedural planks: written beside it, and
    # scene.json keeps naming the built-in material (the compile draws the pattern again).
    assert (out / "assets/textures/oak_floor.png").read_bytes() == pattern_png("planks")
    assert "oak_floor" not in scene.get("materials", {}) or not scene["materials"]["oak_floor"].get(
        "texture"
    )
    os.chdir(tmp_path)
    assert mujoco.MjModel.from_xml_path("out/scene.xml").ntex == 2
