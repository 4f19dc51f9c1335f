"""Bring parts into the asset frame: Z up, metres, front +X, origin at the footprint's centre.

Order: up-axis conversion (Y-up files: ``(x, y, z) -> (x, -z, y)``), then a turn about Z that
brings the source front (``front``, an axis *after* the up conversion) to +X, then an optional
**uniform** scale, then the translation that puts the bounding box's footprint centre at the
origin and its bottom at z = 0.

Requested sizes: the scale is uniform (shapes are never distorted) and chosen so the object
**fits inside** the requested box: ``s = min(requested_i / extent_i)``. The largest relative
dimension then matches the request exactly and the others are at most as requested.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Literal

import numpy as np

from asset_pipeline.load import MeshPart
from holomj.errors import FormatError, InputError

MIN_SIZE_M = 0.001
MAX_SIZE_M = 50.0

UpAxis = Literal["y", "z"]
Front = Literal["+x", "-x", "+y", "-y"]  # the source axis (after up-conversion) that is the front

_UP = {
    "z": np.eye(3),
    "y": np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]]),
}
# Turn about +Z taking the named axis to +X.
_FRONT = {
    "+x": np.eye(3),
    "-x": np.array([[-1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, 1.0]]),
    "+y": np.array([[0.0, 1.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]),
    "-y": np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]),
}


@dataclass(frozen=True)
class Normalisation:
    """The transform applied: ``x_asset = scale * rotation @ x_file + translation``."""

    up_axis: str
    front: str
    scale: float
    rotation: np.ndarray
    translation: np.ndarray
    size: tuple[float, float, float]
    source_size: tuple[float, float, float]

    def as_report(self) -> dict:
        return {
            "up_axis": self.up_axis,
            "front": self.front,
            "scale": self.scale,
            "source_size_m": list(self.source_size),
            "size_m": list(self.size),
        }


def normalise(
    parts: list[MeshPart],
    where: str,
    up_axis: UpAxis,
    front: Front,
    size: tuple[float, float, float] | None,
) -> tuple[list[MeshPart], Normalisation]:
    """Transform ``parts`` into the asset frame; reject absurd sizes with FormatError."""
    if up_axis not in _UP:
        raise InputError(f"unknown up axis {up_axis!r}", fix="use 'y' or 'z'")
    if front not in _FRONT:
        raise InputError(f"unknown front {front!r}", fix="use '+x', '-x', '+y' or '-y'")
    rotation = _FRONT[front] @ _UP[up_axis]
    turned = [p.vertices @ rotation.T for p in parts]
    lo, hi = _bounds([v[np.unique(p.faces)] for p, v in zip(parts, turned, strict=True)])
    source_size = hi - lo
    scale = 1.0
    if size is not None:
        wanted = np.asarray(size, dtype=np.float64)
        if wanted.shape != (3,) or not np.isfinite(wanted).all() or (wanted <= 0).any():
            raise InputError(f"size must be three positive numbers, got {size!r}")
        usable = source_size > 1e-12
        if not usable.any():
            raise FormatError("the mesh has no extent to scale", where=where)
        scale = float(np.min(wanted[usable] / source_size[usable]))
    extent = source_size * scale
    if extent.max() < MIN_SIZE_M or extent.max() > MAX_SIZE_M:
        raise FormatError(
            f"absurd size {_fmt(extent)} m (allowed: {MIN_SIZE_M} m to {MAX_SIZE_M} m)",
            where=where,
            fix="check the file's units, or pass size=(x, y, z) in metres",
        )
    centre = (lo + hi) / 2 * scale
    translation = np.array([-centre[0], -centre[1], -lo[2] * scale])
    out = [replace(p, vertices=v * scale + translation) for p, v in zip(parts, turned, strict=True)]
    info = Normalisation(
        up_axis=up_axis,
        front=front,
        scale=scale,
        rotation=rotation,
        translation=translation,
        size=_rounded3(extent),
        source_size=_rounded3(source_size),
    )
    return out, info


def _bounds(vertex_sets: list[np.ndarray]) -> tuple[np.ndarray, np.ndarray]:
    lo = np.min([v.min(axis=0) for v in vertex_sets], axis=0)
    hi = np.max([v.max(axis=0) for v in vertex_sets], axis=0)
    return lo, hi


def _fmt(values: np.ndarray) -> str:
    return " x ".join(f"{v:.4g}" for v in values)


def _rounded3(values: np.ndarray) -> tuple[float, float, float]:
    """Three extents rounded to the micrometre."""
    x, y, z = (round(float(e), 6) for e in values)
    return (x, y, z)
