"""Compile a SceneSpec and an asset library into an in-memory MuJoCo model (no disk writes)."""

from __future__ import annotations

import hashlib
import re
from dataclasses import dataclass, field
from pathlib import PurePosixPath
from typing import TYPE_CHECKING, Literal

import mujoco

from holomj.errors import CompileError, InputError
from holomj.library.store import AssetLibrary, LibraryAsset
from holomj.mjcf.context import BuildContext
from holomj.mjcf.objects import Furniture, ObjectBuilder
from holomj.mjcf.opening_geometry import add_openings, place_openings
from holomj.mjcf.structure import add_floors_and_ceilings, add_ground, add_walls
from holomj.mjcf.views import add_cameras, add_lights
from holomj.spec.choices import one_of
from holomj.spec.scene import SceneSpec
from mjcf_templates import template_path

if TYPE_CHECKING:
    from holomj.spec.robot import RobotRecord

BASE_TEMPLATE = "base_scene.xml"
Profile = Literal["default", "mjx"]
PROFILES: tuple[Profile, ...] = ("default", "mjx")


@dataclass
class CompiledScene:
    """The result of compiling: the MjSpec, the model, and the files under ``assets/``."""

    scene: SceneSpec
    spec: mujoco.MjSpec
    model: mujoco.MjModel
    files: dict[str, bytes]
    assets: dict[str, LibraryAsset] = field(default_factory=dict)
    furniture: Furniture = "as-is"
    profile: Profile = "default"
    robot: RobotRecord | None = None  # set by holomj.robots.attach

    def to_xml(self) -> str:
        """The scene as MJCF text, with paths relative to the exported folder."""
        return self.spec.to_xml()


def check_profile(profile: str) -> Profile:
    """``profile`` if it is a known compile profile, else an InputError listing them."""
    chosen = one_of(profile, PROFILES)
    if chosen is None:
        raise InputError(
            f"unknown profile {profile!r}", where="--profile", fix=f"use {' or '.join(PROFILES)}"
        )
    return chosen


def compile_scene(
    scene: SceneSpec,
    library: AssetLibrary,
    *,
    furniture: Furniture = "as-is",
    profile: Profile = "default",
) -> CompiledScene:
    """Build the MjSpec for ``scene`` and compile it.

    ``furniture`` overrides the ``static`` flag of floor-standing furniture: ``static`` (no
    joints: cheap, stable), ``free`` (free joints: what validation uses, so a badly placed
    cabinet shows up), or ``as-is``. Wall- and ceiling-mounted assets are always static.
    ``profile`` ``mjx`` makes a model MJX accepts (see :mod:`holomj.mjcf.mjx_profile`).

    Raises :class:`~holomj.errors.AssetNotFoundError` for objects whose asset the library lacks,
    :class:`~holomj.errors.SpecError` for geometry that cannot be built and
    :class:`~holomj.errors.CompileError` when MuJoCo rejects the model.
    """
    check_profile(profile)
    spec = mujoco.MjSpec.from_file(str(template_path(BASE_TEMPLATE)))
    spec.modelname = _model_name(scene.name)
    ctx = BuildContext(spec=spec, scene=scene)
    walls = scene.walls
    openings = place_openings(ctx, walls)
    add_ground(ctx)
    add_floors_and_ceilings(ctx)
    add_walls(ctx, walls, openings)
    add_openings(ctx, openings)
    objects = ObjectBuilder(ctx, library, furniture)
    objects.add_all()
    add_lights(ctx, fixtures=[obj.position for obj, _ in objects.fixtures])
    add_cameras(ctx)
    if profile == "mjx":
        from holomj.mjcf.mjx_profile import apply_mjx_profile

        apply_mjx_profile(spec)
    try:
        spec.assets = dict(ctx.files)  # kept with the spec: its XML export opens them
        model = compile_spec(spec, ctx.files)
    except ValueError as err:
        raise CompileError(f"MuJoCo rejected the model: {' '.join(str(err).split())}") from None
    return CompiledScene(
        scene=scene,
        spec=spec,
        model=model,
        files=dict(sorted(ctx.files.items())),
        assets=dict(sorted(objects.used.items())),
        furniture=furniture,
        profile=profile,
    )


def compile_spec(spec: mujoco.MjSpec, files: dict[str, bytes]) -> mujoco.MjModel:
    """Compile ``spec`` with ``files`` (keyed as its meshes and textures name them, relative to
    its ``meshdir``/``texturedir``) as MuJoCo's in-memory file system; the spec is left as it
    was (its ``assets`` too), so its XML still names the files in their folders.

    MuJoCo 3.17 finds in-memory files loosely (with a ``meshdir``, files of the same name in
    different folders, such as every asset's ``visual_0.obj``, all get the bytes of one of them)
    and caches decoded meshes by file name across compiles (another scene's ``visual_0.obj``
    would be reused). So for the compile every file is renamed to a flat name made from a hash
    of its bytes: exact, and a cache hit is always the same content.
    Raises ``ValueError`` as ``MjSpec.compile`` does.
    """
    flat = {
        name: f"{hashlib.sha256(data).hexdigest()[:24]}{PurePosixPath(name).suffix}"
        for name, data in files.items()
    }
    renamed: list[tuple[mujoco.MjsMesh | mujoco.MjsTexture, str]] = []
    dirs, assets = (spec.meshdir, spec.texturedir), dict(spec.assets)
    try:
        for element in [*spec.meshes, *spec.textures]:
            if element.file and element.file in flat:
                renamed.append((element, element.file))
                element.file = flat[element.file]
        spec.meshdir = spec.texturedir = ""
        spec.assets = {flat[name]: data for name, data in files.items()}
        return spec.compile()
    finally:
        spec.meshdir, spec.texturedir = dirs
        for element, name in renamed:
            element.file = name
        spec.assets = assets


def _model_name(name: str) -> str:
    return re.sub(r"\s+", "_", name.strip()) or "scene"
