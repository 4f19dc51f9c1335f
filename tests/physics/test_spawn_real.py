"""Spawn-and-drop of real meshes from ../shared/assets (CoACD 'fast' preset) onto a table."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from holomj.library import AssetLibrary
from holomj.physics.spawn import populate
from holomj.physics.spawn_requests import merge_libraries
from tests.physics.spawn_helpers import receptacle_scene, settle_check

REAL = {
    "real_cup": ("objects/bm_coffee_cup/coffee_cup.glb", "mug"),
    "real_apple": ("objects/bm_apple/apple.glb", "apple"),
    "real_dice": ("objects/bm_d6_dice/d6_dice.glb", "toy_block"),
    "real_book": ("objects/bm_book_01/book_01.glb", "book"),
}


@pytest.fixture(scope="module")
def real_library(shared_assets: Path, tmp_path_factory: pytest.TempPathFactory) -> AssetLibrary:
    from asset_pipeline.importer import ImportOptions, import_asset
    from asset_pipeline.library_writer import write_library
    from asset_pipeline.manage import coacd_params

    bundles = []
    for asset_id, (relative, category) in REAL.items():
        options = ImportOptions(category=category, coacd=coacd_params("fast"))
        bundles.append(import_asset(shared_assets / relative, asset_id, options).bundle)
    root = write_library(tmp_path_factory.mktemp("real") / "lib", "real", bundles)
    return AssetLibrary.open(root)


def test_real_meshes_land_on_a_table(
    default_library: AssetLibrary, real_library: AssetLibrary
) -> None:
    library = merge_libraries(default_library, real_library)
    scene = receptacle_scene("dining_table_001")
    requests = [(asset_id, 1) for asset_id in REAL] + [("real_apple", 1), ("real_dice", 1)]
    result = populate(scene, library, "rec", requests, np.random.default_rng(2))
    assert result.all_placed, result.to_dict()
    added = [o.id for o in result.scene.objects[1:]]
    assert len(added) == 6
    checks, warnings = settle_check(result.scene, library, added)
    assert warnings == {}
    for object_id, check in checks.items():
        assert check["moved"] < 0.01, (object_id, check)
        assert check["on_rec"], (object_id, check)
