"""Thumbnails: three real renders of an asset, not blank, different from each other."""

from __future__ import annotations

import io

import numpy as np
from PIL import Image

from asset_pipeline.library_writer import AssetBundle
from asset_pipeline.thumbnails import VIEWS, thumbnail_cameras, with_thumbnails
from holomj.library import AssetLibrary


def _bundle(library: AssetLibrary, asset_id: str) -> AssetBundle:
    asset = library.get(asset_id)
    files = {
        p.relative_to(asset.root).as_posix(): p.read_bytes()
        for p in asset.root.rglob("*")
        if p.is_file() and p.name != "asset.json" and p.parent.name != "thumbnails"
    }
    return AssetBundle(meta=asset.meta.model_copy(update={"thumbnails": []}), files=files)


def test_thumbnails_show_the_asset_from_three_angles(default_library: AssetLibrary) -> None:
    sofa = next(i for i in default_library.ids() if default_library.get(i).meta.category == "sofa")
    bundle = with_thumbnails(_bundle(default_library, sofa), pixels=96)
    assert bundle.meta.thumbnails == sorted(f"thumbnails/{v}.png" for v in VIEWS)
    images = [
        np.asarray(Image.open(io.BytesIO(bundle.files[p])).convert("RGB"))
        for p in bundle.meta.thumbnails
    ]
    for image in images:
        assert image.shape == (96, 96, 3)
        assert image.std() > 10, "thumbnail is blank"
        # The sofa fills a good part of the frame: many pixels differ from the floor colour.
        floor = image[-1, 0].astype(int)
        assert (np.abs(image.astype(int) - floor).sum(axis=2) > 60).mean() > 0.1
    assert not np.array_equal(images[0], images[1])
    assert not np.array_equal(images[1], images[2])


def test_cameras_keep_the_whole_asset_in_view() -> None:
    cams = thumbnail_cameras((2.0, 1.0, 1.0))
    assert [c["id"] for c in cams] == [f"thumb_{v}" for v in VIEWS]
    for cam in cams:
        distance = np.linalg.norm(np.subtract(cam["position"], cam["target"]))
        assert distance > 1.5 * 1.2  # farther than the half-diagonal over sin(fovy / 2)
