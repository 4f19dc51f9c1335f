"""A tiny asset library for importer tests (built under tmp_path, box meshes only)."""

from __future__ import annotations

import json
import shutil
from importlib import resources
from pathlib import Path

import pytest

from holomj.library import AssetLibrary

FIXTURES = Path(__file__).parent.parent / "fixtures"

# id: (category, size x (depth), size y (width), size z (height))
TEST_ASSETS = {
    "sofa_modern": ("sofa", 0.9, 2.0, 0.85),
    "sofa_small": ("sofa", 0.85, 1.5, 0.8),
    "bed_double": ("bed", 2.1, 1.6, 0.6),
    "dining_table_oak": ("dining_table", 0.9, 1.6, 0.75),
    "chair_wood": ("chair", 0.55, 0.5, 0.9),
    "Mug_1": ("mug", 0.09, 0.12, 0.1),
}


def write_library(root: Path, assets: dict[str, tuple]) -> Path:
    """Write ``library.json`` and one ``assets/<id>/asset.json`` per asset (a box mesh each).

    Each asset is ``(category, size x, size y, size z)``, optionally followed by its placement
    list (default ``["floor"]``)."""
    box_obj = Path(str(resources.files("holomj.data").joinpath("builtin", "box", "box.obj")))
    index = {}
    for asset_id, (category, sx, sy, sz, *rest) in assets.items():
        folder = root / "assets" / asset_id
        folder.mkdir(parents=True)
        shutil.copy(box_obj, folder / "box.obj")
        meta = {
            "schema_version": "1.0",
            "id": asset_id,
            "category": category,
            "size": [sx, sy, sz],
            "placement": rest[0] if rest else ["floor"],
            "visual": [{"mesh": "box.obj"}],
            "collision": [
                {
                    "kind": "box",
                    "size": [sx / 2, sy / 2, sz / 2],
                    "pos": [0.0, 0.0, sz / 2],
                    "volume_m3": sx * sy * sz,
                }
            ],
        }
        (folder / "asset.json").write_text(json.dumps(meta))
        index[asset_id] = f"assets/{asset_id}"
    library = {"schema_version": "1.0", "name": "importer-tests", "assets": index}
    (root / "library.json").write_text(json.dumps(library))
    return root


@pytest.fixture(scope="session")
def library(tmp_path_factory: pytest.TempPathFactory) -> AssetLibrary:
    """The test library: two sofas, a bed, a dining table, a chair and ``Mug_1``."""
    root = write_library(tmp_path_factory.mktemp("library"), TEST_ASSETS)
    return AssetLibrary.open(root)


def load_fixture(name: str) -> dict:
    """A fixture file parsed as JSON."""
    return json.loads((FIXTURES / name).read_text())


# Real ProcTHOR houses (copies of allenai/ai2thor files, see their README.md) beside the repo.
PROCTHOR_HOUSES = Path(__file__).resolve().parents[3] / "shared" / "procthor" / "houses"
REAL_HOUSES = (
    "procthor_ai2thor_143.json",  # schema 0.0.1
    "procthor_ai2thor_1310.json",  # schema 0.0.1
    "procthor_ai2thor_train_4.json",  # schema 1.0.0
)


def load_real_house(name: str) -> dict:
    """A real house from ``../shared/procthor/houses``; skips visibly when it is absent."""
    path = PROCTHOR_HOUSES / name
    if not path.is_file():
        pytest.skip(f"real ProcTHOR house not found at {path}")
    return json.loads(path.read_text())
