"""Segmentation labels: every geom maps to the scene thing it belongs to."""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np

from holomj.rendering.labels import label_color, segmentation_labels
from holomj.spec.scene_file import read_scene_file


def _labels(folder: Path):
    model = mujoco.MjModel.from_xml_path(str(folder / "scene.xml"))
    scene = read_scene_file(folder / "scene.json")
    return model, segmentation_labels(model, scene)


def test_every_geom_has_the_label_of_its_owner(compiled_two_room: Path) -> None:
    model, labels = _labels(compiled_two_room)
    by_name = {e["name"]: e["label"] for e in labels.legend}
    kinds = {e["name"]: e["kind"] for e in labels.legend}
    assert labels.legend[0]["kind"] == "background"
    assert kinds["kitchen_door"] == "door" and kinds["kitchen_window"] == "window"
    seen = set()
    for geom in range(model.ngeom):
        name = model.geom(geom).name
        label = int(labels.geom_label[geom])
        if name.startswith("structure/floor/"):
            assert label == by_name["floor"], name
        elif name.startswith("structure/") and name != "structure/ground":
            assert label == by_name["wall"], name
        elif name.split("/")[0] in by_name:
            assert label == by_name[name.split("/")[0]], name
        seen.add(label)
    for thing in ("table", "crate", "cube", "kitchen_door", "front_door", "living_window"):
        assert by_name[thing] in seen, thing


def test_label_image_maps_geoms_and_leaves_the_rest_background(compiled_two_room: Path) -> None:
    model, labels = _labels(compiled_two_room)
    table = model.geom("table/visual_0").id
    geom, body = int(mujoco.mjtObj.mjOBJ_GEOM), int(mujoco.mjtObj.mjOBJ_BODY)
    seg = np.array([[[table, geom], [-1, -1]], [[table, body], [0, geom]]], dtype=np.int32)
    image = labels.image(seg)
    assert image.dtype == np.uint16
    assert image[0, 0] == labels.geom_label[table] and image[0, 1] == 0
    assert image[1, 0] == 0  # not a geom
    assert image[1, 1] == labels.geom_label[0]


def test_label_colours_differ() -> None:
    colours = {tuple(label_color(k)) for k in range(1, 200)}
    assert len(colours) > 190 and label_color(0) == [0, 0, 0]
