"""Colour, material and shape of a scene object, from its asset's description and parts.

``color``: the colour words of the description's main phrase (up to the first
"with"/"on"/"in"/",") and the colour of the visual part with the largest surface area (its rgba
named by hue, saturation and value, and the colour words of its material name). ``material``:
material words (oak -> wood, chrome -> metal, ...) of the main phrase and of the largest visual
part's material name. ``shape``: description words (round, oval, square, rectangular, long,
tall, low) or geometry (footprint aspect, height, a top surface polygon with 8+ vertices for
round). Limits: one colour per part, no texture colours, a description naming only a secondary
part's colour is not seen, ``builtin:box`` proxies have no real colour or material.
"""

from __future__ import annotations

import colorsys
import math
from collections.abc import Iterable
from pathlib import Path
from typing import Any

import numpy as np

from holomj.evaluation.objects import EvaluatedObject
from holomj.evaluation.text import find_words, main_phrase
from holomj.evaluation.vocabulary import Vocabulary

_MESH_AREA: dict[Path, float] = {}


def obj_area(path: Path) -> float:
    """Surface area of an OBJ mesh (0 when it cannot be read)."""
    if path in _MESH_AREA:
        return _MESH_AREA[path]
    verts: list[list[float]] = []
    area = 0.0
    try:
        lines = path.read_text().splitlines()
    except OSError:
        lines = []
    for line in lines:
        if line.startswith("v "):
            verts.append([float(v) for v in line.split()[1:4]])
    arr = np.asarray(verts) if verts else np.zeros((0, 3))
    for line in lines:
        if not line.startswith("f "):
            continue
        idx = [int(tok.split("/")[0]) for tok in line.split()[1:]]
        idx = [i - 1 if i > 0 else len(arr) + i for i in idx]
        for k in range(1, len(idx) - 1):
            a, b, c = arr[idx[0]], arr[idx[k]], arr[idx[k + 1]]
            area += 0.5 * float(np.linalg.norm(np.cross(b - a, c - a)))
    _MESH_AREA[path] = area
    return area


def rgba_colour(rgba: Iterable[float]) -> str:
    """A basic colour name for an rgba (by hue, saturation and value)."""
    r, g, b = list(rgba)[:3]
    h, s, v = colorsys.rgb_to_hsv(r, g, b)
    hue = h * 360.0
    if v < 0.18:
        return "black"
    if s < 0.15:
        return "white" if v > 0.85 else ("black" if v < 0.3 else "grey")
    if s < 0.35 and v > 0.7 and 20.0 <= hue <= 65.0:
        return "beige"
    if hue < 15.0 or hue >= 345.0:
        return "red"
    if hue < 45.0:
        return "orange" if (v > 0.75 and s > 0.6) else "brown"
    if hue < 70.0:
        return "yellow" if v > 0.5 else "brown"
    if hue < 170.0:
        return "green"
    if hue < 260.0:
        return "blue"
    if hue < 300.0:
        return "purple"
    return "pink"


def dominant_part(obj: EvaluatedObject) -> dict[str, Any] | None:
    """The visual part with the largest surface area (the first when it cannot be measured)."""
    parts = (obj.meta or {}).get("visual") or []
    if not parts:
        return None
    if len(parts) == 1 or obj.folder is None:
        return parts[0]
    return max(parts, key=lambda p: obj_area(obj.folder / p.get("mesh", "")))


def object_colours(obj: EvaluatedObject, vocab: Vocabulary) -> set[str]:
    """Colour families of an object: description's main phrase + its largest visual part."""
    main = main_phrase((obj.meta or {}).get("description", ""))
    colours = vocab.colour_words(main)
    part = dominant_part(obj)
    if part is not None:
        if part.get("rgba"):
            colours.add(rgba_colour(part["rgba"]))
        colours |= vocab.colour_words(Path(part.get("mesh", "")).stem)
    return colours


def object_materials(obj: EvaluatedObject, vocab: Vocabulary) -> set[str]:
    """Material families: description's main phrase + the largest visual part's name."""
    main = main_phrase((obj.meta or {}).get("description", ""))
    found = vocab.material_words(main)
    part = dominant_part(obj)
    if part is not None:
        found |= vocab.material_words(Path(part.get("mesh", "")).stem)
    return found


def object_has_shape(obj: EvaluatedObject, shape: str, vocab: Vocabulary) -> bool:
    """Whether the object has ``shape`` by its description words or its geometry."""
    main = main_phrase((obj.meta or {}).get("description", ""))
    words = {vocab.shapes[w] for w in find_words(main, vocab.shapes)}
    lo, hi = obj.extent(obj.front)
    lo2, hi2 = obj.extent((-obj.front[1], obj.front[0]))
    a, b = sorted((hi - lo, hi2 - lo2))
    aspect = b / a if a > 1e-6 else math.inf
    many = max((len(s.get("polygon", [])) for s in obj.surfaces), default=0) >= 8
    roundish = "round" in words or "oval" in words or many
    geometric = {
        "round": roundish and aspect <= 1.25,
        "oval": "oval" in words or (many and aspect > 1.25),
        "square": not roundish and aspect <= 1.15,
        "rectangular": not roundish and aspect > 1.15,
        "long": aspect >= 1.8,
        "tall": obj.height >= 1.5,
        "low": obj.height <= 0.5,
    }
    return shape in words or geometric.get(shape, False)
