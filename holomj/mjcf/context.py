"""The state shared by the MJCF builders while one scene is compiled."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import mujoco

from holomj.errors import SpecError
from holomj.mjcf import names
from holomj.spec.materials import BUILTIN_MATERIALS, Material
from holomj.spec.scene import SceneSpec


@dataclass
class BuildContext:
    """An MjSpec under construction plus the files (relative to ``assets/``) it refers to."""

    spec: mujoco.MjSpec
    scene: SceneSpec
    files: dict[str, bytes] = field(default_factory=dict)
    _materials: set[str] = field(default_factory=set)

    def default(self, name: str) -> mujoco.MjsDefault:
        """A default class from the base template."""
        found = self.spec.find_default(name)
        if found is None:
            raise KeyError(f"default class {name!r} missing from the base template")
        return found

    def extent(self) -> tuple[tuple[float, float], tuple[float, float]]:
        """(min x, max x), (min y, max y) over all room polygons."""
        xs = [p[0] for room in self.scene.rooms for p in room.polygon]
        ys = [p[1] for room in self.scene.rooms for p in room.polygon]
        return (min(xs), max(xs)), (min(ys), max(ys))

    def add_file(self, relative: str, data: bytes) -> str:
        """Register a file for ``assets/``; the same path must always carry the same bytes."""
        previous = self.files.get(relative)
        if previous is not None and previous != data:
            raise SpecError(f"two different files would be written to assets/{relative}")
        self.files[relative] = data
        return relative

    def scene_material(self, name: str) -> str:
        """Name of the MJCF material for a scene material, creating it on first use."""
        mj_name = names.scene_material(name)
        if name in self._materials:
            return mj_name
        material = self.scene.materials.get(name) or BUILTIN_MATERIALS.get(name)
        if material is None:
            raise SpecError(f"unknown material {name!r}", where="materials")
        self._materials.add(name)
        self._add_material(mj_name, name, material)
        return mj_name

    def _add_material(self, mj_name: str, name: str, material: Material) -> None:
        mat = self.spec.add_material(
            name=mj_name,
            rgba=list(material.rgba),
            specular=material.specular,
            shininess=material.shininess,
            reflectance=material.reflectance,
        )
        if material.texture is None:
            return
        path = Path(material.texture)
        try:
            data = path.read_bytes()
        except OSError as err:
            raise SpecError(
                f"cannot read texture {material.texture!r}: {err.strerror or err}",
                where=f"materials.{name}.texture",
            ) from None
        relative = self.add_file(names.texture_file(name), data)
        self.spec.add_texture(
            name=names.scene_texture(name), type=mujoco.mjtTexture.mjTEXTURE_2D, file=relative
        )
        mat.textures[mujoco.mjtTextureRole.mjTEXROLE_RGB] = names.scene_texture(name)
        # texuniform: one tile per texrepeat metres on boxes; slabs carry their own UVs.
        mat.texrepeat = [1.0 / material.texture_size_m, 1.0 / material.texture_size_m]
        mat.texuniform = True
