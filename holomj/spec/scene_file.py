"""Reading a holomj ``scene.json``: validation, and texture paths made absolute."""

from __future__ import annotations

from pathlib import Path

from holomj.errors import SpecError
from holomj.spec.base import read_json, validate_model
from holomj.spec.scene import SceneSpec


def read_scene_file(path: Path) -> SceneSpec:
    """The scene in ``path``; relative material textures resolve against the file's folder."""
    path = Path(path)
    source = str(path)
    scene = validate_model(SceneSpec, read_json(path), source)
    return resolve_textures(scene, path.parent, source)


def resolve_textures(scene: SceneSpec, folder: Path, source: str) -> SceneSpec:
    """``scene`` with relative texture paths made absolute against ``folder`` (and checked)."""
    materials = {}
    changed = False
    for name, material in scene.materials.items():
        if material.texture and not Path(material.texture).is_absolute():
            texture = (folder / material.texture).resolve()
            if not texture.is_file():
                raise SpecError(
                    f"texture file {material.texture!r} not found",
                    where=f"{source}: materials.{name}.texture",
                    fix="texture paths are relative to the scene file's folder",
                )
            material = material.model_copy(update={"texture": str(texture)})
            changed = True
        materials[name] = material
    return scene.model_copy(update={"materials": materials}) if changed else scene
