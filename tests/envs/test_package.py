"""Single-file packages of the generated kitchen (``holomj pack``): the .mjb and the .zip load as
the model scene.xml compiles to, and an environment runs on a package."""

from __future__ import annotations

import json
import shutil
import zipfile
from pathlib import Path

import mujoco
import numpy as np
import pytest

from holomj import envs
from holomj.errors import InputError
from holomj.formats.package import load_package
from holomj.jobs.pack import model_differences, pack_folder
from holomj.jobs.tasks import propose_folder_tasks


@pytest.fixture(scope="module")
def packed(kitchen: Path, tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    target = tmp_path_factory.mktemp("packed")
    result = pack_folder(kitchen, "all", target)
    return {name: Path(path) for name, path in result.files.items()}


def test_mjb_and_zip_load_as_the_scene_xml_model(kitchen: Path, packed: dict[str, Path]) -> None:
    expected = mujoco.MjModel.from_xml_path(str(kitchen / "scene.xml"))
    assert set(packed) == {"mjb", "zip"}
    for path in (packed["mjb"], packed["zip"], kitchen):
        model = load_package(path)
        assert (model.nbody, model.ngeom, model.njnt) == (
            expected.nbody,
            expected.ngeom,
            expected.njnt,
        )
        np.testing.assert_allclose(model.qpos0, expected.qpos0)
        np.testing.assert_allclose(model.geom_size, expected.geom_size)
        np.testing.assert_allclose(model.mesh_vert, expected.mesh_vert)
        assert model_differences(expected, model) == []
    assert mujoco.MjModel.from_binary_path(str(packed["mjb"])).ngeom == expected.ngeom


def test_the_zip_extracts_to_a_loadable_folder(packed: dict[str, Path], tmp_path: Path) -> None:
    with zipfile.ZipFile(packed["zip"]) as archive:
        names = archive.namelist()
        archive.extractall(tmp_path)
    assert "scene.xml" in names and "objects.json" in names
    assert not any(name.startswith("export/") for name in names)
    model = mujoco.MjModel.from_xml_path(str(tmp_path / "scene.xml"))
    assert model.ngeom == load_package(packed["zip"]).ngeom


def test_bad_packages_are_refused(tmp_path: Path, kitchen: Path) -> None:
    with pytest.raises(InputError):
        load_package(tmp_path / "missing.mjb")
    other = tmp_path / "scene.txt"
    other.write_text("x")
    with pytest.raises(InputError):
        load_package(other)
    with pytest.raises(InputError):
        pack_folder(kitchen, "obj", tmp_path)
    copy = tmp_path / "copy"
    shutil.copytree(kitchen, copy, ignore=shutil.ignore_patterns("export"))
    (copy / "scene.xml").unlink()
    with pytest.raises(InputError):
        pack_folder(copy)


def test_an_environment_runs_on_the_mjb_package(kitchen: Path, packed: dict[str, Path]) -> None:
    task = propose_folder_tasks(kitchen, limit=40, write=False).tasks[0]
    env = envs.make(kitchen, task, robot="jaco", package=packed["mjb"])
    try:
        observation, _ = env.reset(seed=0)
        assert env.observation_space.contains(observation)
        env.step(env.action_space.sample())
    finally:
        env.close()


def test_holomj_pack_writes_both_files(kitchen: Path, tmp_path: Path) -> None:
    from typer.testing import CliRunner

    from holomj.cli.app import app

    runner = CliRunner()
    result = runner.invoke(app, ["pack", str(kitchen), "-o", str(tmp_path), "--json"])
    assert result.exit_code == 0, result.output
    record = json.loads(result.output)
    assert sorted(record["files"]) == ["mjb", "zip"]
    assert (tmp_path / "scene.mjb").is_file() and (tmp_path / "scene.zip").is_file()
    bad = runner.invoke(app, ["pack", str(kitchen), "-o", str(tmp_path), "-f", "obj"])
    assert bad.exit_code == 2
