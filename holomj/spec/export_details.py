"""What an export wrote besides its files, per format: the ``details`` of
:class:`holomj.jobs.export.ExportResult` (see :mod:`holomj.jobs.export`)."""

from __future__ import annotations

from typing import Any

from holomj.spec.base import FrozenModel


class GlbDetails(FrozenModel):
    """glb: whether the collision-only geoms were written too (``<id>/colliders`` nodes)."""

    colliders: bool


class UsdDetails(FrozenModel):
    """usd: what the stage holds, counted, and the notes of what could not be carried over."""

    prims: int
    rigid_bodies: int
    colliders: int
    joints: int
    textures: int
    notes: list[str]


class UrdfDetails(FrozenModel):
    """urdf: one record per articulated asset written (its ``urdf`` file and ``joints``)."""

    assets: list[dict[str, Any]]


ExportDetails = GlbDetails | UsdDetails | UrdfDetails
