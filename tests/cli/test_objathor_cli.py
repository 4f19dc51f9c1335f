"""``holomj assets import-objathor`` then ``holomj compile`` of a Holodeck house naming the uids.

The house uses the imported assets themselves (no substitution), puts them where Holodeck's
footprints say (the frame conversion is right when the MuJoCo boxes match the footprints) and
loads and steps in MuJoCo without a warning.
"""

from __future__ import annotations

import gzip
import json
from pathlib import Path

import mujoco
import numpy as np
import pytest
from typer.testing import CliRunner

from holomj.cli import app
from holomj.library import AssetLibrary
from tests.asset_pipeline.objathor_data import BOX_UID, CLOCK_UID, DESK_UID, build_objathor_dir

runner = CliRunner()


@pytest.fixture(scope="module")
def library(tmp_path_factory: pytest.TempPathFactory, request: pytest.FixtureRequest) -> Path:
    """The three test assets imported through the command line (shipped colliders)."""
    shared = request.getfixturevalue("shared_assets")
    root = tmp_path_factory.mktemp("objathor_cli")
    build_objathor_dir(root / "dir", shared)
    result = runner.invoke(
        app,
        ["assets", "import-objathor", str(root / "dir"), "--library", str(root / "lib"),
         "--no-thumbnails", "--json"],
    )  # fmt: skip
    assert result.exit_code == 0, result.output
    report = json.loads(result.stdout)
    assert (report["succeeded"], report["failed"]) == (3, 0)
    return root / "lib"


def _footprint(cx: float, cz: float, sx: float, sz: float) -> list[list[float]]:
    """Holodeck ``vertices``: the world footprint in centimetres (Unity x, z)."""
    x0, x1, z0, z1 = (
        (cx - sx / 2) * 100,
        (cx + sx / 2) * 100,
        (cz - sz / 2) * 100,
        (cz + sz / 2) * 100,
    )
    return [[x0, z0], [x0, z1], [x1, z1], [x1, z0]]


def holodeck_house(library: Path) -> dict:
    """One 4 x 4 m room: the desk turned 90° (Unity), a box on it, a clock on the west wall."""
    lib = AssetLibrary.open(library)
    desk, box, clock = (lib.get(u).meta.size for u in (DESK_UID, BOX_UID, CLOCK_UID))
    # Unity rotation y = 90 faces the desk's front (+z) to Unity +x, its width (asset Y, Unity x
    # at rotation 0) runs along Unity z: footprint x extent = desk depth, z extent = its width.
    room = [{"x": 0, "y": 0, "z": 0}, {"x": 0, "y": 0, "z": 4}, {"x": 4, "y": 0, "z": 4},
            {"x": 4, "y": 0, "z": 0}]  # fmt: skip
    return {
        "wall_height": 2.7,
        "rooms": [{"id": "living room", "roomType": "living room", "floorPolygon": room}],
        "objects": [
            {
                "assetId": DESK_UID,
                "id": "desk-0 (living room)",
                "object_name": "desk-0",
                "kinematic": True,
                "position": {"x": 2.0, "y": desk[2] / 2, "z": 2.0},
                "rotation": {"x": 0, "y": 90, "z": 0},
                "roomId": "living room",
                "vertices": _footprint(2.0, 2.0, desk[0], desk[1]),
            },
            {
                "assetId": BOX_UID,
                "id": "box-0|desk-0 (living room)",
                "kinematic": False,
                "position": {"x": 2.0, "y": desk[2] + box[2] / 2, "z": 2.1},
                "rotation": {"x": 0, "y": 30, "z": 0},
                "roomId": "living room",
            },
            {
                "assetId": CLOCK_UID,
                "id": "clock-0 (living room)",
                "object_name": "clock-0",
                "kinematic": True,
                "position": {"x": clock[0] / 2 + 0.01, "y": 1.6, "z": 2.0},
                "rotation": {"x": 0, "y": 90, "z": 0},
                "roomId": "living room",
            },
        ],
        "metadata": {"schema": "1.0.0"},
    }


def _world_box(model: mujoco.MjModel, data: mujoco.MjData, prefix: str) -> np.ndarray:
    """(min, max) over the corners of the collision geoms whose names start with ``prefix``."""
    corners = []
    signs = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)])
    for g in range(model.ngeom):
        if not (model.geom(g).name or "").startswith(prefix) or model.geom_contype[g] == 0:
            continue
        centre, half = model.geom_aabb[g][:3], model.geom_aabb[g][3:]
        local = centre + signs * half
        corners.append(local @ data.geom_xmat[g].reshape(3, 3).T + data.geom_xpos[g])
    points = np.concatenate(corners)
    return np.stack([points.min(axis=0), points.max(axis=0)])


def test_holodeck_house_uses_the_imported_assets(library: Path, tmp_path: Path) -> None:
    house = tmp_path / "holodeck_house.json"
    house.write_text(json.dumps(holodeck_house(library)))
    out = tmp_path / "out"
    result = runner.invoke(
        app,
        ["compile", str(house), "-o", str(out), "--library", str(library), "--json",
         "--check-seconds", "1"],
    )  # fmt: skip
    assert result.exit_code == 0, result.output
    report = json.loads((out / "import_report.json").read_text())
    assert report["format"] == "holodeck"
    assert report["substitutions"] == []
    assert report["simulation_warnings"] == {}
    scene = json.loads((out / "scene.json").read_text())
    assets = {o["id"]: o["asset"] for o in scene["objects"]}
    assert assets == {
        "desk-0_living_room": DESK_UID,
        "box-0|desk-0_living_room": BOX_UID,
        "clock-0_living_room": CLOCK_UID,
    }

    model = mujoco.MjModel.from_xml_path(str(out / "scene.xml"))
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    # the desk covers Holodeck's footprint: depth along Unity x, width along Unity z (= holomj Y)
    meta = AssetLibrary.open(library).get(DESK_UID).meta
    (x0, y0, z0), (x1, y1, _) = _world_box(model, data, "desk-0_living_room/")
    assert (x1 - x0, y1 - y0) == pytest.approx((meta.size[0], meta.size[1]), abs=0.01)
    assert ((x0 + x1) / 2, (y0 + y1) / 2) == pytest.approx((2.0, 2.0), abs=0.01)
    assert z0 == pytest.approx(0.0, abs=0.005)
    # the clock hangs flat against the west wall (x = 0), its thin side along holomj X
    (cx0, _, _), (cx1, _, _) = _world_box(model, data, "clock-0_living_room/")
    assert cx1 - cx0 == pytest.approx(
        AssetLibrary.open(library).get(CLOCK_UID).meta.size[0], abs=0.005
    )
    assert cx0 > 0.0
    for _ in range(500):
        mujoco.mj_step(model, data)
    assert not any(data.warning[i].number for i in range(len(data.warning)))
    box_body = model.body("box-0|desk-0_living_room/body").id
    assert data.xpos[box_body][2] == pytest.approx(meta.size[2], abs=0.02)  # resting on the desk


def test_corrupt_pickle_exits_non_zero_naming_the_file(tmp_path: Path, shared_assets: Path) -> None:
    build_objathor_dir(tmp_path / "dir", shared_assets, (BOX_UID,))
    path = tmp_path / "dir" / "assets" / BOX_UID / f"{BOX_UID}.pkl.gz"
    path.write_bytes(gzip.compress(b"not a pickle at all"))
    result = runner.invoke(
        app,
        ["assets", "import-objathor", str(tmp_path / "dir"), "--library", str(tmp_path / "lib"),
         "--no-thumbnails"],
    )  # fmt: skip
    assert result.exit_code == 1
    assert "corrupt pickle" in result.output and f"{BOX_UID}.pkl.gz" in result.output
    assert "0 imported" in result.output and "1 failed" in result.output


def test_bad_input_exits_2(tmp_path: Path, shared_assets: Path) -> None:
    missing = runner.invoke(app, ["assets", "import-objathor", str(tmp_path / "nope")])
    assert missing.exit_code == 2 and "not a folder" in missing.output
    build_objathor_dir(tmp_path / "dir", shared_assets, (BOX_UID,))
    bogus = runner.invoke(
        app, ["assets", "import-objathor", str(tmp_path / "dir"), "--colliders", "bogus"]
    )
    assert bogus.exit_code == 2 and "--colliders" in bogus.output
    unknown = runner.invoke(
        app,
        ["assets", "import-objathor", str(tmp_path / "dir"), "--uids", "deadbeef",
         "--library", str(tmp_path / "lib")],
    )  # fmt: skip
    assert unknown.exit_code == 2 and "deadbeef" in unknown.output
    assert not (tmp_path / "lib").exists()  # nothing written for bad input


def test_uids_limit_the_import(tmp_path: Path, shared_assets: Path) -> None:
    build_objathor_dir(tmp_path / "dir", shared_assets, (BOX_UID, CLOCK_UID))
    result = runner.invoke(
        app,
        ["assets", "import-objathor", str(tmp_path / "dir"), "--uids", CLOCK_UID,
         "--library", str(tmp_path / "lib"), "--no-thumbnails"],
    )  # fmt: skip
    assert result.exit_code == 0, result.output
    assert "1 imported, 0 degraded, 0 failed" in result.output
    ids = AssetLibrary.open(tmp_path / "lib").ids()
    assert CLOCK_UID in ids and BOX_UID not in ids
