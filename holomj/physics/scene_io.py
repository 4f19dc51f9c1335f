"""A model ready for physics checks, and what is known about its objects.

A holomj scene comes compiled in memory (:func:`loaded_from_compiled`: its objects are the
scene's objects, so validation can free the furniture and results can be baked back into the
scene); any other MJCF file is loaded as it is (:func:`load_mjcf`: its "objects" are the bodies
with a free joint). Reading an output folder is the jobs layer's (``holomj.jobs.folder``).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import mujoco

from holomj.library.store import AssetLibrary
from holomj.mjcf import names
from holomj.mjcf.compiler import CompiledScene
from holomj.mjcf.loading import load_model_file
from holomj.spec.scene import SceneSpec


@dataclass
class LoadedScene:
    """A model ready to simulate, and what we know about its objects."""

    source: Path
    model: mujoco.MjModel
    objects: dict[str, int]  # object id (or body name for foreign MJCF) -> body id
    scene: SceneSpec | None = None
    library: AssetLibrary | None = None
    compiled: CompiledScene | None = None
    folder: Path | None = None  # the holomj folder it came from, when it did


def loaded_from_compiled(
    compiled: CompiledScene, library: AssetLibrary, source: Path, folder: Path | None = None
) -> LoadedScene:
    """A compiled scene, in memory, ready to validate (its objects are the scene's objects)."""
    model = compiled.model
    objects = {o.id: model.body(names.object_body(o.id)).id for o in compiled.scene.objects}
    return LoadedScene(Path(source), model, objects, compiled.scene, library, compiled, folder)


def load_mjcf(path: Path) -> LoadedScene:
    """Any MJCF file, as it is: its objects are the bodies with a free joint."""
    model = load_model_file(Path(path))
    objects = {}
    for joint in range(model.njnt):
        if model.jnt_type[joint] == mujoco.mjtJoint.mjJNT_FREE:
            body = int(model.jnt_bodyid[joint])
            objects[model.body(body).name or f"body_{body}"] = body
    return LoadedScene(Path(path), model, objects)
