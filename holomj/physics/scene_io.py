"""Load a scene for physics checks: a holomj folder (recompiled from scene.json) or any MJCF.

A holomj folder is recompiled from its ``scene.json`` with its own ``assets/`` library, so
validation can free the furniture (``furniture="free"``) and results can be baked back into
the scene. Any other MJCF file is loaded as it is; its "objects" are the bodies with a free
joint.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import mujoco

from holomj.errors import FormatError
from holomj.export.writer import ASSETS_DIR, SCENE_JSON, SCENE_XML
from holomj.library.store import AssetLibrary
from holomj.mjcf import names
from holomj.mjcf.compiler import CompiledScene, compile_scene
from holomj.mjcf.loading import load_model_file
from holomj.mjcf.objects import Furniture
from holomj.robots.attach import attach_saved_robot
from holomj.spec.scene import SceneSpec
from holomj.spec.scene_file import read_scene_file


@dataclass
class LoadedScene:
    """A model ready to simulate, and what we know about its objects."""

    source: Path
    model: mujoco.MjModel
    objects: dict[str, int]  # object id (or body name for foreign MJCF) -> body id
    scene: SceneSpec | None = None
    library: AssetLibrary | None = None
    compiled: CompiledScene | None = None
    folder: Path | None = None  # the holomj folder, when it is one


def holomj_folder(path: Path) -> Path | None:
    """The holomj output folder ``path`` names (the folder or its scene.xml), else None."""
    path = Path(path)
    folder = path if path.is_dir() else path.parent
    is_scene = (folder / SCENE_JSON).is_file() and (folder / ASSETS_DIR / "library.json").is_file()
    return folder if is_scene and (path.is_dir() or path.name == SCENE_XML) else None


def loaded_from_compiled(
    compiled: CompiledScene, library: AssetLibrary, source: Path, folder: Path | None = None
) -> LoadedScene:
    """A compiled scene, in memory, ready to validate (its objects are the scene's objects)."""
    model = compiled.model
    objects = {o.id: model.body(names.object_body(o.id)).id for o in compiled.scene.objects}
    return LoadedScene(Path(source), model, objects, compiled.scene, library, compiled, folder)


def load_scene(
    path: Path, *, furniture: Furniture = "free", library: AssetLibrary | None = None
) -> LoadedScene:
    """Load ``path`` (a holomj folder, its scene.xml, or any MJCF file) for simulation."""
    path = Path(path)
    if not path.exists():
        raise FormatError("not found", where=str(path))
    folder = holomj_folder(path)
    if folder is not None:
        scene = read_scene_file(folder / SCENE_JSON)
        library = library or AssetLibrary.open(folder / ASSETS_DIR)
        compiled = compile_scene(scene, library, furniture=furniture)
        compiled = attach_saved_robot(compiled, folder)
        return loaded_from_compiled(compiled, library, path, folder)
    if path.is_dir():
        raise FormatError(
            "not a holomj scene folder (no scene.json and assets/library.json)",
            where=str(path),
            fix="pass a folder written by 'holomj compile' or an MJCF file",
        )
    model = load_model_file(path)
    objects = {}
    for joint in range(model.njnt):
        if model.jnt_type[joint] == mujoco.mjtJoint.mjJNT_FREE:
            body = int(model.jnt_bodyid[joint])
            objects[model.body(body).name or f"body_{body}"] = body
    return LoadedScene(path, model, objects)
