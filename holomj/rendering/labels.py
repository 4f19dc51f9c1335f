"""Segmentation labels: every geom of the model mapped to the scene thing it belongs to.

Label 0 is the background; then ``floor``, ``wall`` and ``ceiling`` (all rooms' structure), then
the scene's objects, doors and windows in scene order. A segmentation image is a 16-bit PNG of
labels; the legend (:meth:`Labels.to_dict`, saved by the render job beside the images) maps
each label to its name, kind and a display colour.
"""

from __future__ import annotations

import colorsys
from dataclasses import dataclass

import mujoco
import numpy as np

from holomj.spec.scene import SceneSpec

STRUCTURE = ("floor", "wall", "ceiling")
STRUCTURE_KINDS = ("background", "structure")


@dataclass(frozen=True)
class Labels:
    """``geom_label[g]`` is the label of geom ``g``; ``legend[k]`` describes label ``k``."""

    geom_label: np.ndarray
    legend: list[dict[str, object]]

    def image(self, segmentation: np.ndarray) -> np.ndarray:
        """A (H, W) uint16 label image from a renderer's (H, W, 2) object id/type image."""
        objid, objtype = segmentation[..., 0], segmentation[..., 1]
        is_geom = (objtype == int(mujoco.mjtObj.mjOBJ_GEOM)) & (objid >= 0)
        labels = np.zeros(objid.shape, dtype=np.uint16)
        labels[is_geom] = self.geom_label[objid[is_geom]]
        return labels

    def to_dict(self) -> dict[str, object]:
        """The legend as JSON-able data."""
        return {
            "schema_version": "1.0",
            "image": "16-bit PNG, one label per pixel; 0 is the background",
            "labels": self.legend,
        }


def label_color(label: int) -> list[int]:
    """A display colour for a label: spread hues, black for the background."""
    if label == 0:
        return [0, 0, 0]
    hue = (label * 0.618033988749895) % 1.0
    lightness = 0.45 + 0.15 * (label % 3) / 2
    r, g, b = colorsys.hls_to_rgb(hue, lightness, 0.75)
    return [round(r * 255), round(g * 255), round(b * 255)]


def segmentation_labels(model: mujoco.MjModel, scene: SceneSpec) -> Labels:
    """The labels of ``scene`` and the label of every geom of ``model``."""
    entries: list[tuple[str | None, str]] = [(None, "background")]
    entries += [(kind, "structure") for kind in STRUCTURE]
    entries += [(o.id, "object") for o in scene.objects]
    entries += [(d.id, "door") for d in scene.doors]
    entries += [(w.id, "window") for w in scene.windows]
    structure = {name: k for k, (name, kind) in enumerate(entries) if kind == "structure"}
    things = {name: k for k, (name, kind) in enumerate(entries) if kind not in STRUCTURE_KINDS}
    legend: list[dict[str, object]] = [
        {"label": k, "name": name, "kind": kind, "color": label_color(k)}
        for k, (name, kind) in enumerate(entries)
    ]
    geom_label = np.zeros(model.ngeom, dtype=np.uint16)
    for geom in range(model.ngeom):
        name = model.geom(geom).name or model.body(int(model.geom_bodyid[geom])).name
        geom_label[geom] = _label_of(name, structure, things)
    return Labels(geom_label, legend)


def _label_of(name: str, structure: dict[str | None, int], things: dict[str | None, int]) -> int:
    """Names are ``structure/floor/<room>``, ``structure/<wall>/...``, ``<object id>/...``."""
    parts = name.split("/")
    if len(parts) < 2:
        return 0
    if parts[0] in things:
        return things[parts[0]]
    if parts[0] == "structure":
        kind = {"floor": "floor", "ground": "floor", "ceiling": "ceiling"}.get(parts[1], "wall")
        return structure[kind]
    return 0
