"""navmap.json and navmap.png: codes, run-length encoding, reachability, the image."""

from __future__ import annotations

import io
import json
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from holomj.errors import FormatError
from holomj.formats.navmap import CODES, rle_decode, rle_encode
from holomj.jobs.folder import write_scene_folder
from holomj.jobs.robot_learning import build_navmap
from holomj.library import AssetLibrary
from holomj.mjcf import compile_scene
from holomj.spec.scene import SceneSpec
from tests.conftest import two_room_data


@pytest.fixture
def compiled(two_room_scene: SceneSpec, empty_library: AssetLibrary):
    return compile_scene(two_room_scene, empty_library)


def test_rle_round_trip() -> None:
    rng = np.random.default_rng(0)
    values = rng.integers(-1, 3, size=(7, 11))
    values[2:5] = 1
    runs = rle_encode(values)
    assert sum(n for _, n in runs) == values.size
    assert all(a[0] != b[0] for a, b in zip(runs, runs[1:]))
    np.testing.assert_array_equal(rle_decode(runs, values.shape), values)
    with pytest.raises(FormatError, match="run lengths add up to 77 cells, expected 80"):
        rle_decode(runs, (8, 10))


def test_navmap_json_describes_the_grid(compiled) -> None:
    navmap = build_navmap(compiled)
    data = navmap.to_json()
    shape = tuple(data["shape"])
    codes = rle_decode(data["cells"], shape)
    rooms = rle_decode(data["room_cells"], shape)
    assert data["codes"] == CODES and data["rooms_index"] == ["kitchen", "living"]
    assert data["entrance"] == {"room": "living", "door": "front_door", "position": [7.0, 2.0]}
    cell, (x0, y0) = data["cell_m"], data["origin"]

    def at(x: float, y: float) -> tuple[int, int]:
        return int((y - y0) // cell), int((x - x0) // cell)

    assert codes[at(2.0, 1.2)] == CODES["obstacle"]  # the table
    assert codes[at(2.0, 2.97)] == CODES["door"]  # the kitchen door's leaf
    assert codes[at(1.0, 2.2)] == CODES["reachable"]
    assert codes[at(0.1, 0.1)] == CODES["narrow"]  # kitchen corner: too close to the walls
    assert codes[at(-0.5, -0.45)] == CODES["outside"]
    assert rooms[at(1.0, 2.2)] == 0 and rooms[at(6.0, 4.0)] == 1 and rooms[at(-0.4, 2)] == -1
    for room in ("kitchen", "living"):
        stats = data["rooms"][room]
        assert stats["reachable"]
        in_room = rooms == data["rooms_index"].index(room)
        reachable = np.count_nonzero((codes == CODES["reachable"]) & in_room) * cell**2
        doors = np.count_nonzero((codes == CODES["door"]) & in_room) * cell**2
        # Cells under a closed door leaf are reachable too (doors open) but coded "door".
        assert reachable - 1e-9 <= stats["reachable_area_m2"] <= reachable + doors + 1e-9
    assert data["rooms"]["living"]["floor_area_m2"] == pytest.approx(23.0, rel=0.02)


def test_unreachable_room(empty_library: AssetLibrary) -> None:
    data = two_room_data()
    data["doors"] = [d for d in data["doors"] if d["id"] != "kitchen_door"]
    scene = SceneSpec.model_validate(data)
    navmap = build_navmap(compile_scene(scene, empty_library)).to_json()
    assert navmap["rooms"]["kitchen"]["reachable"] is False
    assert navmap["rooms"]["kitchen"]["reachable_area_m2"] == 0
    codes = rle_decode(navmap["cells"], tuple(navmap["shape"]))
    assert np.count_nonzero(codes == CODES["unreachable"]) > 1000


def test_png_matches_the_grid(compiled) -> None:
    navmap = build_navmap(compiled)
    image = Image.open(io.BytesIO(navmap.to_png()))
    rows, cols = navmap.grid.shape
    scale = image.height // rows
    assert image.size == (cols * scale, rows * scale) and max(image.size) >= 480
    assert image.mode == "RGB"
    pixels = np.asarray(image)
    # North up: the first image row is the grid's last row (outside, dark).
    assert tuple(pixels[0, 0]) == (48, 48, 52)
    assert navmap.to_png() == navmap.to_png()


def test_every_export_writes_the_navmap(compiled, tmp_path: Path) -> None:
    out = write_scene_folder(compiled, tmp_path / "out")
    data = json.loads((out / "navmap.json").read_text())
    assert data["image"] == "navmap.png" and (out / "navmap.png").is_file()
    assert "robot" not in data
    assert data == json.loads(json.dumps(build_navmap(compiled).to_json()))
