"""What every edit operation shares: the context (libraries, retrieval, seed) and the outcome.

An operation function takes the current :class:`~holomj.spec.scene.SceneSpec`, the operation
and the :class:`EditContext`, and returns a :class:`Change` (the new scene and what it did) or
raises :class:`Refused` with the reason; a refused operation leaves the scene as it was.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from holomj.library.store import AssetLibrary
from holomj.mjcf.compiler import CompiledScene
from holomj.physics.spawn_requests import merge_libraries
from holomj.seeds import stage_rng
from holomj.spec.scene import SceneObject, SceneSpec

MAX_SIZE_M = 10.0  # an object (or an asked size) larger than this is absurd
MIN_SIZE_M = 0.01


class Refused(Exception):
    """An operation the scene cannot take, and why (one line, with a hint when there is one)."""

    def __init__(self, reason: str) -> None:
        super().__init__(reason)
        self.reason = reason


@dataclass
class Change:
    """What an applied operation did: the new scene and the ids it touched."""

    scene: SceneSpec
    added: list[str] = field(default_factory=list)
    removed: list[str] = field(default_factory=list)
    moved: list[str] = field(default_factory=list)
    changed: list[str] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    details: dict[str, Any] = field(default_factory=dict)
    why: dict[str, str] = field(default_factory=dict)  # object id -> why it moved


@dataclass
class EditContext:
    """What operations need besides the scene.

    ``own``: the scene's own assets (a folder's ``assets/``); ``source``: the library new assets
    come from (None: operations that need a new asset are refused); ``synthesiser``: makes
    assets on demand into ``source`` (:class:`holomj.jobs.synthesis.LibrarySynthesiser`, passed
    in by the jobs layer); ``attach``: adds what the scene carries besides its objects (a
    robot) to a compiled world, for drops.
    """

    own: AssetLibrary
    source: AssetLibrary | None = None
    synthesiser: Any = None
    seed: int = 0
    attach: Callable[[CompiledScene], CompiledScene] | None = None
    text_model: Path | None = None
    materials: Path | None = None
    blockers: tuple[Any, ...] = ()  # holomj.edit.floor.Blocker: what else stands on the floor
    _retriever: Any = field(default=None, repr=False)
    _encoder: Any = field(default=None, repr=False)
    _materials: Any = field(default=None, repr=False)
    _merged: AssetLibrary | None = field(default=None, repr=False)
    _merged_size: int = field(default=-1, repr=False)

    @property
    def library(self) -> AssetLibrary:
        """One view of the scene's own assets and the source library (own first); it learns
        the assets made on demand since."""
        if self.source is None:
            return self.own
        size = len(self.source)
        if self._merged is None or size != self._merged_size:
            self._merged = merge_libraries(self.own, self.source)
            self._merged_size = size
        return self._merged

    def rng(self, *parts: object) -> np.random.Generator:
        """A generator for one operation (``("add", 3)``): the same seed gives the same edit."""
        return stage_rng(self.seed, "edit", *(str(p) for p in parts))

    @property
    def encoder(self) -> Any:
        """The sentence encoder (loaded on first use)."""
        if self._encoder is None:
            from holomj.retrieval.text import text_encoder

            self._encoder = text_encoder(self.text_model)
        return self._encoder

    @property
    def retriever(self) -> Any:
        """Asset retrieval over ``source`` (with assets on demand when a synthesiser is given);
        refuses when there is no source library."""
        if self.source is None:
            raise Refused("no asset library to retrieve new assets from")
        if self._retriever is None:
            from holomj.retrieval.assets import retriever_for

            self._retriever = retriever_for(
                self.source, encoder=self.encoder, synthesiser=self.synthesiser
            )
        return self._retriever

    @property
    def material_library(self) -> Any:
        """The material library: built-ins and the user folder ``materials``."""
        if self._materials is None:
            from holomj.retrieval.materials import MaterialLibrary

            self._materials = MaterialLibrary.load(self.materials)
        return self._materials


def find(scene: SceneSpec, object_id: str) -> SceneObject:
    """The object ``object_id``; refused (naming close ids) when the scene has none."""
    for obj in scene.objects:
        if obj.id == object_id:
            return obj
    from holomj.errors import closest_names

    near = closest_names(object_id, [o.id for o in scene.objects])
    hint = f"; did you mean {near}?" if near else ""
    raise Refused(f"unknown object id {object_id!r}{hint}")


def resting_on(scene: SceneSpec, object_id: str) -> list[SceneObject]:
    """Every object resting on ``object_id``, directly or on something that does (in scene
    order)."""
    below = {object_id}
    out: list[SceneObject] = []
    grew = True
    while grew:
        grew = False
        for obj in scene.objects:
            if obj.support in below and obj.id not in below:
                below.add(obj.id)
                out.append(obj)
                grew = True
    order = {o.id: k for k, o in enumerate(scene.objects)}
    return sorted(out, key=lambda o: order[o.id])


def rebuilt(scene: SceneSpec, **fields: Any) -> SceneSpec:
    """``scene`` with some fields replaced, checked again as a whole (ids unique, supports
    and materials known...). Objects are passed on as they are, never re-validated one by
    one, so an untouched object keeps its pose to the last bit."""
    data = scene.model_dump(exclude={"objects", *fields})
    return SceneSpec.model_validate({**data, "objects": list(scene.objects), **fields})


def with_objects(scene: SceneSpec, objects: list[SceneObject]) -> SceneSpec:
    """``scene`` with ``objects`` (see :func:`rebuilt`)."""
    return rebuilt(scene, objects=list(objects))


def check_size(size: tuple[float, float, float], what: str) -> None:
    """Refuse an absurd size (over :data:`MAX_SIZE_M` or under 1 cm)."""
    for name, value in zip(("width", "depth", "height"), size):
        if value > MAX_SIZE_M:
            raise Refused(f"{what}: {name} {value:g} m is absurd (more than {MAX_SIZE_M:g} m)")
        if value < MIN_SIZE_M:
            raise Refused(f"{what}: {name} {value:g} m is under 1 cm")
