"""Procedural textures for procedural assets: which pattern a material wears, and its UVs.

A part whose material is wood, fabric, velvet, leather, marble, tile, brick, carpet or concrete
(by its ``pattern``, or else by the words of its label and name) gets the matching seamless
greyscale pattern of :mod:`holomj.mjcf.textures`, tinted by the material's colour (the part's
``rgba`` is :func:`tinted`: the colour over the pattern's mean, so it averages to the colour).
Texture coordinates are a box projection in metres divided by the pattern's tile size, so
grain, threads and tiles keep their physical size whatever the part's size; wood grain runs
along the part's longest side. A material with ``pattern="plain"`` (or a design with
``textured=False``) stays a plain colour.

The patterns are the same bytes in every asset: the library writer stores each once
(content-addressed) and links it into the asset folders that use it.
"""

from __future__ import annotations

import numpy as np

from asset_pipeline.procedural.parts import Mesh, RecipeMaterial
from holomj.mjcf.textures import (
    PATTERNS,
    PLAIN_WORDS,
    pattern_for_words,
    pattern_png,
    tinted,
    words_of,
)

PLAIN = "plain"

__all__ = [
    "PATTERNS",
    "PLAIN",
    "box_uv",
    "pattern_of",
    "pattern_png",
    "texture_file",
    "textured_mesh",
    "tinted",
]


def pattern_of(material: RecipeMaterial) -> str | None:
    """The pattern ``material`` wears, or None for a plain colour.

    An explicit ``material.pattern`` wins (``"plain"``: none). Otherwise the label decides
    (a finish asked for by attribute, ``"red leather"``, names the look), then the name
    (``grey_fabric``, ``oak``); paint, lacquer, glass and metal words keep it plain.
    """
    if material.pattern is not None:
        if material.pattern == PLAIN:
            return None
        if material.pattern not in PATTERNS:
            raise ValueError(
                f"material {material.name!r}: unknown pattern {material.pattern!r} "
                f"(known: {PLAIN}, {', '.join(sorted(PATTERNS))})"
            )
        return material.pattern
    for text in (material.label, material.name):
        words = words_of(text)
        if PLAIN_WORDS & set(words):
            return None
        found = pattern_for_words(words)
        if found is not None:
            return found
    return None


def texture_file(pattern: str) -> str:
    """The file name of pattern ``pattern`` inside an asset folder."""
    return f"texture_{pattern}.png"


def box_uv(mesh: Mesh, tile_m: float, grain_axis: int) -> Mesh:
    """``mesh`` with box-projected texture coordinates: each triangle is projected along the
    axis its normal is closest to, onto the other two axes, in units of ``tile_m`` metres.

    ``u`` follows ``grain_axis`` where the projection allows (not on faces looking along it),
    so stripes of the pattern along ``u`` (wood grain) run along that axis.
    """
    vertices, faces = mesh.vertices, mesh.faces
    corners = vertices[faces]
    normal = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    facing = np.argmax(np.abs(normal), axis=1)  # the axis each triangle is projected along
    # For each facing axis, the (u axis, v axis) pair.
    pairs = np.empty((3, 2), dtype=np.int64)
    for axis in range(3):
        others = [a for a in range(3) if a != axis]
        if grain_axis in others:
            others.remove(grain_axis)
            pairs[axis] = (grain_axis, others[0])
        else:
            pairs[axis] = others
    keys = (faces * 3 + facing[:, None]).reshape(-1)  # (vertex, facing) per corner
    unique, inverse = np.unique(keys, return_inverse=True)
    vertex, facing_axis = unique // 3, unique % 3
    uv = np.stack(
        [
            vertices[vertex, pairs[facing_axis, 0]],
            vertices[vertex, pairs[facing_axis, 1]],
        ],
        axis=1,
    ) / float(tile_m)
    return Mesh(vertices, faces, uv + 0.0, inverse.reshape(faces.shape).astype(np.int64))


def textured_mesh(mesh: Mesh, pattern: str) -> Mesh:
    """``mesh`` with texture coordinates for ``pattern``, the grain along its longest side."""
    extent = mesh.vertices.max(axis=0) - mesh.vertices.min(axis=0)
    return box_uv(mesh, PATTERNS[pattern].tile_m, int(np.argmax(extent)))
