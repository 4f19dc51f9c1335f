"""Scene objects: library assets as bodies with visual meshes and convex colliders.

Mass: the object's ``mass_kg``, else the asset's mass (given, or density x collision volume)
scaled by the volume factor ``sx * sy * sz``. It is shared out over the colliders in proportion to
their recorded volumes and given to MuJoCo as each collider's ``mass``, so the body weighs exactly
that while MuJoCo derives the inertia from the collision geometry; visual geoms have none.
Non-uniform scale is exact for meshes and for primitives aligned with the asset axes; rotated
round primitives get the scale their axes see, which is a close approximation.

An articulated asset (one with ``articulation``) is its carcass here, weighing the asset's mass
less its moving parts'; the parts (doors, drawers, lids) become child bodies on hinge and slide
joints (:mod:`holomj.mjcf.articulation`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Literal

import mujoco

from holomj.errors import AssetNotFoundError
from holomj.library.store import AssetLibrary, LibraryAsset
from holomj.mjcf import names
from holomj.mjcf.articulation import add_moving_parts
from holomj.mjcf.colliders import collider_fields
from holomj.mjcf.context import BuildContext
from holomj.mjcf.geometry import clean, yaw_quat
from holomj.spec.assets import ArticulatedPart, AssetMeta
from holomj.spec.decor import DECOR_CATEGORIES, DECOR_GROUP, LIGHT_FIXTURE_CATEGORIES
from holomj.spec.scene import SceneObject


@dataclass(frozen=True)
class _AssetHandles:
    """MJCF names of one asset's meshes and materials at one scale (for an articulated asset,
    those of its carcass, and per moving part its own in ``parts``)."""

    visual_meshes: list[str]
    visual_materials: list[str]
    collision_meshes: dict[int, str]
    parts: dict[str, _AssetHandles] = field(default_factory=dict)


Furniture = Literal["as-is", "static", "free"]


def is_furniture(obj: SceneObject, meta: AssetMeta) -> bool:
    """Objects standing on the floor (no support) that are not small props."""
    return obj.support is None and "floor" in meta.placement and "object" not in meta.placement


def is_static(obj: SceneObject, meta: AssetMeta, furniture: Furniture) -> bool:
    """Whether an object gets no joint: wall- and ceiling-mounted assets always; furniture
    as the ``furniture`` option says (``as-is`` keeps the scene's flag); others by their flag."""
    if set(meta.placement) <= {"wall", "ceiling"} or meta.category in DECOR_CATEGORIES:
        return True
    if furniture != "as-is" and is_furniture(obj, meta):
        return furniture == "static"
    return obj.static


class ObjectBuilder:
    """Adds scene objects to an MjSpec, declaring each asset's meshes once per scale."""

    def __init__(
        self, ctx: BuildContext, library: AssetLibrary, furniture: Furniture = "as-is"
    ) -> None:
        self.ctx = ctx
        self.library = library
        self.furniture = furniture
        self.used: dict[str, LibraryAsset] = {}
        self._handles: dict[tuple[str, tuple[float, float, float]], _AssetHandles] = {}
        self._materials: dict[str, list[str]] = {}
        # (object, asset) of every light fixture added: they carry their room's light
        self.fixtures: list[tuple[SceneObject, AssetMeta]] = []

    def add_all(self) -> None:
        """Add every object of the scene."""
        for index, obj in enumerate(self.ctx.scene.objects):
            try:
                asset = self.library.get(obj.asset)
            except AssetNotFoundError as err:
                raise err.located(f"objects[{index}].asset ({obj.id})") from None
            self.add(obj, asset)

    def add(self, obj: SceneObject, asset: LibraryAsset) -> mujoco.MjsBody:
        """Add one object as a body (with a free joint unless it is static)."""
        meta = asset.meta
        self.used[meta.id] = asset
        if meta.category in LIGHT_FIXTURE_CATEGORIES:
            self.fixtures.append((obj, meta))
        scale = obj.scale3
        handles = self._asset_handles(asset, scale)
        static = is_static(obj, meta, self.furniture)
        quat = obj.quat if obj.quat is not None else yaw_quat(math.radians(obj.yaw_deg))
        body = self.ctx.spec.worldbody.add_body(
            name=names.object_body(obj.id), pos=clean(obj.position), quat=clean(quat)
        )
        body.info = f"object {obj.id} (asset {meta.id})"
        if not static:
            body.add_freejoint(name=names.object_joint(obj.id))
        for k, (mesh, material) in enumerate(zip(handles.visual_meshes, handles.visual_materials)):
            geom = body.add_geom(
                name=names.object_visual(obj.id, k),
                default=self.ctx.default("visual"),
                type=mujoco.mjtGeom.mjGEOM_MESH,
                meshname=mesh,
                material=material,
            )
            geom.info = f"visual {k} of object {obj.id}"
        volume_factor = scale[0] * scale[1] * scale[2]
        mass = obj.mass_kg if obj.mass_kg is not None else meta.mass * volume_factor
        whole = mass
        if meta.articulation is not None:  # the carcass: what the moving parts leave
            mass *= 1.0 - meta.articulation.mass_kg / meta.mass
        total_volume = meta.collision_volume_m3
        default = "collision" if static else "prop"
        torsion, rolling = (0.005, 0.0001) if static else (0.01, 0.001)
        decor = meta.category in DECOR_CATEGORIES  # colliders give mass, never contacts
        for k, part in enumerate(meta.collision):
            geom = body.add_geom(
                name=names.object_collision(obj.id, k),
                default=self.ctx.default(default),
                mass=mass * part.volume_m3 / total_volume,
                friction=[meta.friction, torsion, rolling],
                **collider_fields(part, scale, handles.collision_meshes.get(k)),
            )
            geom.info = f"collider {k} of object {obj.id}"
            if decor:
                geom.contype, geom.conaffinity, geom.group = 0, 0, DECOR_GROUP
        if meta.articulation is not None:
            add_moving_parts(self.ctx, body, obj, meta, handles.parts, scale, whole)
        return body

    def _asset_handles(
        self, asset: LibraryAsset, scale: tuple[float, float, float]
    ) -> _AssetHandles:
        key = (asset.meta.id, scale)
        if key in self._handles:
            return self._handles[key]
        meta = asset.meta
        prefix = names.asset_prefix(meta.id, scale)
        folder = names.asset_folder(meta.id)
        visual_meshes = []
        for k, part in enumerate(meta.visual):
            mesh = self.ctx.spec.add_mesh(
                name=names.asset_visual_mesh(prefix, k),
                file=self._register(asset, folder, part.mesh),
                scale=list(scale),
                inertia=mujoco.mjtMeshInertia.mjMESH_INERTIA_SHELL,
            )
            mesh.info = f"visual mesh {part.mesh} of asset {meta.id}"
            visual_meshes.append(mesh.name)
        collision_meshes = {}
        for k, hull in enumerate(meta.collision):
            if hull.kind != "mesh" or hull.mesh is None:
                continue
            mesh = self.ctx.spec.add_mesh(
                name=names.asset_collision_mesh(prefix, k),
                file=self._register(asset, folder, hull.mesh),
                scale=list(scale),
                inertia=mujoco.mjtMeshInertia.mjMESH_INERTIA_CONVEX,
                maxhullvert=meta.maxhullvert,
            )
            mesh.info = f"collision hull {hull.mesh} of asset {meta.id}"
            collision_meshes[k] = mesh.name
        parts = {}
        for moving in meta.articulation.parts if meta.articulation is not None else ():
            parts[moving.name] = self._part_handles(asset, folder, prefix, moving, scale)
        handles = _AssetHandles(
            visual_meshes, self._asset_materials(asset, folder), collision_meshes, parts
        )
        self._handles[key] = handles
        return handles

    def _part_handles(
        self,
        asset: LibraryAsset,
        folder: str,
        prefix: str,
        part: ArticulatedPart,
        scale: tuple[float, float, float],
    ) -> _AssetHandles:
        """Meshes and materials of one moving part of an articulated asset."""
        meta = asset.meta
        visual_meshes = []
        for k, visual in enumerate(part.visual):
            mesh = self.ctx.spec.add_mesh(
                name=names.asset_part_visual_mesh(prefix, part.name, k),
                file=self._register(asset, folder, visual.mesh),
                scale=list(scale),
                inertia=mujoco.mjtMeshInertia.mjMESH_INERTIA_SHELL,
            )
            mesh.info = f"visual mesh {visual.mesh} of part {part.name} of asset {meta.id}"
            visual_meshes.append(mesh.name)
        collision_meshes = {}
        for k, collider in enumerate(part.collision):
            if collider.kind != "mesh" or collider.mesh is None:
                continue
            mesh = self.ctx.spec.add_mesh(
                name=names.asset_part_collision_mesh(prefix, part.name, k),
                file=self._register(asset, folder, collider.mesh),
                scale=list(scale),
                inertia=mujoco.mjtMeshInertia.mjMESH_INERTIA_CONVEX,
                maxhullvert=meta.maxhullvert,
            )
            mesh.info = f"collision hull {collider.mesh} of part {part.name} of asset {meta.id}"
            collision_meshes[k] = mesh.name
        key = f"{meta.id}\0{part.name}"
        if key not in self._materials:
            materials = []
            for k, visual in enumerate(part.visual):
                name = names.asset_part_material(meta.id, part.name, k)
                material = self.ctx.spec.add_material(
                    name=name,
                    rgba=list(visual.rgba),
                    specular=visual.specular,
                    shininess=visual.shininess,
                )
                if visual.texture is not None:
                    texture = names.asset_part_texture(meta.id, part.name, k)
                    self.ctx.spec.add_texture(
                        name=texture,
                        type=mujoco.mjtTexture.mjTEXTURE_2D,
                        file=self._register(asset, folder, visual.texture),
                    )
                    material.textures[mujoco.mjtTextureRole.mjTEXROLE_RGB] = texture
                materials.append(name)
            self._materials[key] = materials
        return _AssetHandles(visual_meshes, self._materials[key], collision_meshes)

    def _asset_materials(self, asset: LibraryAsset, folder: str) -> list[str]:
        meta = asset.meta
        if meta.id in self._materials:
            return self._materials[meta.id]
        materials = []
        for k, part in enumerate(meta.visual):
            name = names.asset_material(meta.id, k)
            material = self.ctx.spec.add_material(
                name=name,
                rgba=list(part.rgba),
                specular=part.specular,
                shininess=part.shininess,
            )
            if part.texture is not None:
                texture = names.asset_texture(meta.id, k)
                self.ctx.spec.add_texture(
                    name=texture,
                    type=mujoco.mjtTexture.mjTEXTURE_2D,
                    file=self._register(asset, folder, part.texture),
                )
                material.textures[mujoco.mjtTextureRole.mjTEXROLE_RGB] = texture
            materials.append(name)
        self._materials[meta.id] = materials
        return materials

    def _register(self, asset: LibraryAsset, folder: str, relative: str) -> str:
        return self.ctx.add_file(f"{folder}/{relative}", asset.path(relative).read_bytes())
