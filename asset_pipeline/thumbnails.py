"""Thumbnails of an asset rendered headlessly with MuJoCo, from the front and ±45°.

The asset is compiled exactly as scenes use it (holomj's compiler, one room, the asset at the
origin), so a thumbnail shows what MuJoCo will show. Walls (geom group 0) are hidden.
"""

from __future__ import annotations

import io
import math
import tempfile
from pathlib import Path

import mujoco
import numpy as np

from asset_pipeline.library_writer import AssetBundle, write_library
from holomj.library.store import AssetLibrary
from holomj.mjcf import compile_scene
from holomj.spec.scene import SceneSpec

VIEWS = {"front": 0.0, "left45": 45.0, "right45": -45.0}
ELEVATION_DEG = 25.0
FOVY_DEG = 40.0


def thumbnail_cameras(size: tuple[float, float, float]) -> list[dict]:
    """Scene cameras looking at an asset of bounding-box ``size`` from each view angle."""
    target = (0.0, 0.0, size[2] / 2)
    radius = 0.5 * math.sqrt(sum(s * s for s in size))
    distance = radius / math.sin(math.radians(FOVY_DEG / 2)) * 1.05
    cameras = []
    for name, azimuth in VIEWS.items():
        az, el = math.radians(azimuth), math.radians(ELEVATION_DEG)
        position = (
            distance * math.cos(el) * math.cos(az),
            distance * math.cos(el) * math.sin(az),
            target[2] + distance * math.sin(el),
        )
        cameras.append(
            {"id": f"thumb_{name}", "position": position, "target": target, "fovy_deg": FOVY_DEG}
        )
    return cameras


def render_thumbnails(bundle: AssetBundle, pixels: int = 256) -> dict[str, bytes]:
    """PNG images of ``bundle`` keyed by their path inside the asset folder."""
    from PIL import Image

    meta = bundle.meta
    half_room = max(8.0, 10.0 * max(meta.size))
    room = [
        [-half_room, -half_room],
        [half_room, -half_room],
        [half_room, half_room],
        [-half_room, half_room],
    ]
    with tempfile.TemporaryDirectory(prefix="holomj-thumb-") as tmp:
        root = write_library(Path(tmp) / "lib", "thumbnail", [bundle])
        library = AssetLibrary.open(root)
        scene = SceneSpec.model_validate(
            {
                "name": f"thumbnail {meta.id}",
                "wall_height": max(2.7, meta.size[2] + 1.0),
                "rooms": [{"id": "studio", "polygon": room, "floor_material": "white_tile"}],
                "objects": [
                    {"id": "asset", "asset": meta.id, "position": [0, 0, 0], "static": True}
                ],
                "lights": [
                    {
                        "id": "key",
                        "kind": "directional",
                        "position": [3, 2, 6],
                        "direction": [-0.5, -0.3, -1],
                        "energy": 0.7,
                    },
                    {
                        "id": "fill",
                        "kind": "directional",
                        "position": [-3, 2, 4],
                        "direction": [0.5, -0.5, -0.6],
                        "energy": 0.3,
                    },
                ],
                "cameras": thumbnail_cameras(meta.size),
            }
        )
        model = compile_scene(scene, library).model
    model.vis.global_.offwidth = max(model.vis.global_.offwidth, pixels)
    model.vis.global_.offheight = max(model.vis.global_.offheight, pixels)
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    option = mujoco.MjvOption()
    option.geomgroup[:] = np.array([0, 1, 1, 0, 0, 0], dtype=np.uint8)
    images: dict[str, bytes] = {}
    with mujoco.Renderer(model, pixels, pixels) as renderer:
        for name in VIEWS:
            renderer.update_scene(data, camera=f"camera/thumb_{name}", scene_option=option)
            buffer = io.BytesIO()
            Image.fromarray(renderer.render()).save(buffer, format="PNG", optimize=False)
            images[f"thumbnails/{name}.png"] = buffer.getvalue()
    return images


def with_thumbnails(bundle: AssetBundle, pixels: int = 256) -> AssetBundle:
    """``bundle`` plus its thumbnails, listed in the metadata."""
    images = render_thumbnails(bundle, pixels)
    meta = bundle.meta.model_copy(update={"thumbnails": sorted(images)})
    return AssetBundle(meta=meta, files={**bundle.files, **images}, folder=bundle.folder)
