"""The state shared by the MJCF builders while one scene is compiled."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import mujoco

from holomj.errors import SpecError
from holomj.mjcf import names
from holomj.mjcf.textures import procedural_look
from holomj.spec.materials import BUILTIN_MATERIALS, Material
from holomj.spec.scene import SceneSpec


@dataclass
class BuildContext:
    """An MjSpec under construction plus the files (relative to ``assets/``) it refers to."""

    spec: mujoco.MjSpec
    scene: SceneSpec
    files: dict[str, bytes] = field(default_factory=dict)
    _materials: set[str] = field(default_factory=set)
    _textures: set[str] = field(default_factory=set)

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

    def scene_material(
        self, name: str, *, uv: bool = False, face: tuple[float, float] | None = None
    ) -> str:
        """Name of the MJCF material for a scene material, creating it on first use.

        MuJoCo maps a 2D texture onto a mesh by its texture coordinates times ``texrepeat``,
        and onto each face of a box ``texrepeat`` times whatever the face's size
        (``texuniform`` garbles both). So a textured material comes in variants that share its
        texture: ``uv`` for a mesh whose coordinates already count tiles (a floor or ceiling
        slab), ``face=(width, height)`` for a box whose large faces are that many metres (a
        wall piece: one tile per ``texture_size_m``), and the plain name for anything else
        (one tile per ``texture_size_m`` on a 1 m face). An untextured material has one.
        """
        material = self.scene.materials.get(name) or BUILTIN_MATERIALS.get(name)
        if material is None:
            raise SpecError(f"unknown material {name!r}", where="materials")
        look = procedural_look(name, material)
        if material.texture is None and look is None:
            uv, face = False, None
        tile = look.tile_m if look is not None else material.texture_size_m
        if uv:
            mj_name, repeat = names.scene_uv_material(name), (1.0, 1.0)
        elif face is not None:
            width, height = (round(v, 3) for v in face)
            mj_name = names.scene_face_material(name, width, height)
            repeat = (width / tile, height / tile)
        else:
            mj_name, repeat = names.scene_material(name), (1.0 / tile, 1.0 / tile)
        if mj_name not in self._materials:
            self._materials.add(mj_name)
            self._add_material(mj_name, name, material, repeat)
        return mj_name

    def texture_tile(self, name: str) -> float:
        """World size (metres) of one tile of scene material ``name``'s texture: its own
        ``texture_size_m``, or the tile of the procedural pattern it wears (1 if neither)."""
        material = self.scene.materials.get(name) or BUILTIN_MATERIALS.get(name)
        if material is None:
            return 1.0
        look = procedural_look(name, material)
        return look.tile_m if look is not None else material.texture_size_m

    def _add_material(
        self, mj_name: str, name: str, material: Material, repeat: tuple[float, float]
    ) -> None:
        # A material without a texture of its own may wear a procedural pattern (wood, tile,
        # carpet...) named by its name, tinted so that it keeps its average colour.
        look = procedural_look(name, material)
        mat = self.spec.add_material(
            name=mj_name,
            rgba=list(look.rgba if look is not None else material.rgba),
            specular=material.specular,
            shininess=material.shininess,
            reflectance=material.reflectance,
        )
        if look is not None:
            data = look.png
        elif material.texture is None:
            return
        else:
            path = Path(material.texture)
            try:
                data = path.read_bytes()
            except OSError as err:
                raise SpecError(
                    f"cannot read texture {material.texture!r}: {err.strerror or err}",
                    where=f"materials.{name}.texture",
                ) from None
        texture = names.scene_texture(name)
        if texture not in self._textures:
            self._textures.add(texture)
            relative = self.add_file(names.texture_file(name), data)
            self.spec.add_texture(name=texture, type=mujoco.mjtTexture.mjTEXTURE_2D, file=relative)
        mat.textures[mujoco.mjtTextureRole.mjTEXROLE_RGB] = texture
        mat.texrepeat = list(repeat)
        mat.texuniform = False
