"""The scene as a USD stage with UsdPhysics, for Isaac Sim, Isaac Lab and other USD simulators.

Built from the compiled model (what MuJoCo simulates) and the scene (rooms, objects, openings),
posed at the model's initial state. Metres, kilograms, Z up (MuJoCo's frame). Prims::

    /World                               default prim
      PhysicsScene                       gravity as in the model
      <room>/<object id>                 one Xform per object, at its body's pose
        Visuals/<geom>                   meshes with UsdPreviewSurface materials (textures)
        Collisions/<geom>                the colliders (purpose guide): boxes, spheres, capsules,
                                         cylinders as USD primitives, hulls as meshes with
                                         MeshCollisionAPI convexHull
        <part>                           articulated parts: rigid bodies of their own
                                         (resetXformStack, world pose), joined by
        Joints/<joint>                   revolute / prismatic / spherical joints with limits
      <room>/Structure/<geom>            floors, walls, ceilings (static colliders where they
                                         collide in MuJoCo)
      Openings/<door or window id>       frames and glass; door leaves (leaf_<i>) as rigid
                                         bodies on revolute joints to the world
      Lights/<light>                     UsdLux distant and sphere lights
      Ground                             the ground plane (static collider)
      Bodies/<body>                      bodies of no scene object (a robot), as rigid bodies
      Looks/<material>, PhysicsMaterials/<friction>

A body with a joint (free, hinge, slide, ball) gets ``RigidBodyAPI`` and ``MassAPI`` with the
model's mass, centre of mass, principal inertia and axes (bodies welded to it without a joint
are merged into its mass); a body without one is static: its colliders have no rigid body.
Hinge and slide joints keep their ranges (degrees and metres, from the pose the stage is
authored at: a joint's value there is USD's zero), MuJoCo's passive stiffness and damping as an
angular or linear drive (a spring towards its ``springref``), and armature and frictionloss as
``holomj:`` attributes.
Prim names are MuJoCo names made valid USD identifiers; ``holomj:id`` and ``holomj:name`` keep
the originals. The stage is built in memory; textures referenced as ``./textures/<name>.png`` are
returned beside it for the writer (:mod:`holomj.jobs.export`).

Needs ``usd-core`` (the ``export`` extra).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import mujoco
import numpy as np

from holomj.errors import InputError
from holomj.formats.model_geometry import Look, ModelGeometry
from holomj.formats.usd_physics import (
    apply_mass,
    collision_shape,
    define_joint,
    physics_material,
)
from holomj.formats.usd_prims import (
    define_lights,
    preview_material,
    set_pose,
    string_attr,
    valid_name,
    visual_mesh,
)
from holomj.formats.welded_bodies import welded
from holomj.mjcf import names
from holomj.spec.scene import SceneSpec
from holomj.version import __version__

USD_EXTRA_FIX = "pip install 'holomj[export]' (usd-core)"
TEXTURES_DIR = "textures"
_RESERVED = {"PhysicsScene", "Openings", "Lights", "Ground", "Bodies", "Looks", "PhysicsMaterials"}


def load_pxr() -> Any:
    """The ``pxr`` package (usd-core), or a one-line error naming the extra."""
    try:
        import pxr
        from pxr import Gf, Sdf, Usd, UsdGeom, UsdLux, UsdPhysics, UsdShade  # noqa: F401
    except ImportError as err:
        raise InputError(f"USD export needs usd-core ({err})", fix=USD_EXTRA_FIX) from None
    return pxr


@dataclass
class UsdScene:
    """A stage in memory and the texture files its materials name (path -> PNG bytes)."""

    stage: Any
    textures: dict[str, bytes] = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)


def scene_stage(
    model: mujoco.MjModel, scene: SceneSpec, *, qpos: np.ndarray | None = None
) -> UsdScene:
    """The USD stage of ``scene`` as compiled into ``model`` (see module docstring)."""
    load_pxr()
    return _StageBuilder(ModelGeometry(model, qpos), scene).build()


class _StageBuilder:
    def __init__(self, geometry: ModelGeometry, scene: SceneSpec) -> None:
        from pxr import Usd

        self.geo = geometry
        self.model = geometry.model
        self.scene = scene
        self.stage = Usd.Stage.CreateInMemory()
        self.out = UsdScene(self.stage)
        self._looks: dict[str, Any] = {}
        self._physics_materials: dict[float, Any] = {}
        self._names: dict[str, set[str]] = {}
        self.objects = {names.object_body(o.id): o for o in scene.objects}
        self.openings = {o.id for o in scene.doors} | {o.id for o in scene.windows}
        self.leaves = {
            names.door_leaf_body(door.id, index): door.id
            for door in scene.doors
            for index in range(2)
        }
        self.rooms = {room.id: self._child_name("/World", room.id) for room in scene.rooms}

    # --- paths ------------------------------------------------------------------------------

    def _child_name(self, parent: str, name: str) -> str:
        """A unique valid prim name for ``name`` under ``parent``."""
        base = valid_name(name)
        if parent == "/World" and base in _RESERVED:
            base = f"{base}_"
        taken = self._names.setdefault(parent, set())
        candidate, index = base, 1
        while candidate in taken:
            candidate = f"{base}_{index}"
            index += 1
        taken.add(candidate)
        return candidate

    def _path(self, parent: str, name: str) -> str:
        return f"{parent}/{self._child_name(parent, name)}"

    # --- the stage --------------------------------------------------------------------------

    def build(self) -> UsdScene:
        from pxr import Gf, UsdGeom, UsdPhysics

        stage = self.stage
        UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.z)
        UsdGeom.SetStageMetersPerUnit(stage, 1.0)
        UsdPhysics.SetStageKilogramsPerUnit(stage, 1.0)
        world = UsdGeom.Xform.Define(stage, "/World")
        stage.SetDefaultPrim(world.GetPrim())
        layer = stage.GetRootLayer()
        layer.documentation = f"holomj {__version__}: {self.scene.name}"
        world.GetPrim().SetCustomDataByKey("holomj:scene", self.scene.name)
        physics = UsdPhysics.Scene.Define(stage, "/World/PhysicsScene")
        gravity = np.asarray(self.model.opt.gravity, dtype=float)
        magnitude = float(np.linalg.norm(gravity))
        if magnitude > 0:
            physics.CreateGravityDirectionAttr(Gf.Vec3f(*(gravity / magnitude)))
            physics.CreateGravityMagnitudeAttr(magnitude)
        for room_name in self.rooms.values():
            UsdGeom.Xform.Define(stage, f"/World/{room_name}")
        self._world_geoms()
        for body in self.geo.children[0]:
            self._top_body(body)
        define_lights(
            stage, self.model, self.geo.data, lambda name: self._path("/World/Lights", name)
        )
        return self.out

    def _world_geoms(self) -> None:
        from pxr import UsdGeom

        rooms = {room.id for room in self.scene.rooms}
        for geom in self.geo.body_geoms(0):
            name = self.geo.geom_name(geom) or f"geom_{geom}"
            parent = self._world_parent(name, rooms, geom)
            if not self.stage.GetPrimAtPath(parent):
                UsdGeom.Xform.Define(self.stage, parent)
            self._geom_prims(geom, parent, None)

    def _world_parent(self, name: str, rooms: set[str], geom: int) -> str:
        if self.model.geom_type[geom] == mujoco.mjtGeom.mjGEOM_PLANE:
            return "/World/Ground"
        if name.startswith("structure/"):
            rest = name[len("structure/") :]
            side = rest.rsplit("/", 1)[-1]
            if side in rooms:
                return f"/World/{self.rooms[side]}/Structure"
            return "/World/Structure"
        head = name.split("/", 1)[0]
        if head in self.openings and "/" in name:
            return f"/World/Openings/{valid_name(head)}"
        return "/World/Structure"

    def _top_body(self, body: int) -> None:
        from pxr import UsdGeom

        name = self.geo.body_name(body)
        obj = self.objects.get(name)
        prim_name = None
        if obj is not None:
            room = self.rooms.get(obj.room) if obj.room else None
            parent = f"/World/{room}" if room else "/World/Unassigned"
            ident = obj.id
        elif name in self.leaves:  # a door leaf: <door>/leaf_<i> under its door
            parent = f"/World/Openings/{valid_name(self.leaves[name])}"
            ident = name
            prim_name = name.split("/", 1)[1]
        else:
            parent = "/World/Bodies"
            ident = name
        if not self.stage.GetPrimAtPath(parent):
            UsdGeom.Xform.Define(self.stage, parent)
        articulated = any(self._has_joint(b) for b in self._subtree(body) if b != body)
        self._body(body, parent, ident, None, articulated=articulated, prim_name=prim_name)

    def _subtree(self, body: int) -> list[int]:
        out = [body]
        for child in self.geo.children[body]:
            out += self._subtree(child)
        return out

    def _has_joint(self, body: int) -> bool:
        return int(self.model.body_jntnum[body]) > 0

    def _body(
        self,
        body: int,
        parent_path: str,
        ident: str,
        rigid_parent: tuple[str, int] | None,
        *,
        nested: bool = False,
        articulated: bool = False,
        prim_name: str | None = None,
    ) -> str:
        """``body`` (and the bodies welded to it) as a prim under ``parent_path``, its joints
        and its jointed child bodies; returns its path. ``rigid_parent``: the prim path and body
        id of the rigid body it hangs from (None: the world, or a static body). ``nested``: the
        parent prim is a body (then a jointed body resets the transform stack: world pose)."""
        from pxr import UsdGeom, UsdPhysics

        if prim_name is None:  # a part goes by its name within its object
            prim_name = ident.split("/", 1)[1] if nested and "/" in ident else ident
        path = self._path(parent_path, prim_name)
        xform = UsdGeom.Xform.Define(self.stage, path)
        prim = xform.GetPrim()
        string_attr(prim, "holomj:id", ident)
        string_attr(prim, "holomj:name", self.geo.body_name(body))
        pos, rot = self.geo.body_pose(body)
        if nested:
            xform.SetResetXformStack(True)  # a rigid body inside another body: world pose
        set_pose(xform, pos, rot)
        members = welded(self.geo, body)
        dynamic = self._has_joint(body)
        if dynamic:
            UsdPhysics.RigidBodyAPI.Apply(prim)
            apply_mass(prim, self.geo, body, members)
            if articulated:
                UsdPhysics.ArticulationRootAPI.Apply(prim)
        for member in members:
            for geom in self.geo.body_geoms(member):
                self._geom_prims(geom, path, body)
        self._joints(body, path, rigid_parent, parent_path)
        rigid = (path, body) if dynamic else rigid_parent
        for member in members:
            for child in self.geo.children[member]:
                if self._has_joint(child):
                    self._body(child, path, self.geo.body_name(child), rigid, nested=True)
        return path

    def _joints(
        self, body: int, path: str, rigid_parent: tuple[str, int] | None, owner: str
    ) -> None:
        """The joint of ``body`` (its prim at ``path``) to ``rigid_parent`` (None: the world),
        as a prim under ``owner``/Joints; a body with more joints keeps the first, with a note."""
        from pxr import UsdGeom

        model = self.model
        joints = [
            j for j in self.geo.body_joints(body) if model.jnt_type[j] != mujoco.mjtJoint.mjJNT_FREE
        ]
        if not joints:
            return
        if len(joints) > 1:
            self.out.notes.append(
                f"{self.geo.body_name(body)}: {len(joints)} joints on one body; only "
                f"{model.joint(joints[0]).name} is exported"
            )
        name = model.joint(joints[0]).name or f"joint_{joints[0]}"
        joints_path = f"{owner}/Joints"
        if not self.stage.GetPrimAtPath(joints_path):
            UsdGeom.Scope.Define(self.stage, joints_path)
        joint_path = self._path(joints_path, name.split("/", 1)[1] if "/" in name else name)
        define_joint(self.stage, self.geo, joints[0], joint_path, (path, body), rigid_parent)

    # --- geoms ------------------------------------------------------------------------------

    def _geom_prims(self, geom: int, parent: str, body: int | None) -> None:
        """The visual and collision prims of ``geom``: world geoms (``body`` None) straight
        under ``parent`` at their world poses, a body's under its prim's Visuals/ and
        Collisions/ relative to ``body``."""
        from pxr import UsdGeom

        visible = self.geo.is_visible(geom)
        collides = self.geo.is_collider(geom)
        if not visible and not collides:
            return
        name = self.geo.geom_name(geom) or f"geom_{geom}"
        gpos, grot = self.geo.geom_pose(geom)
        if body is None:
            pos, rot = gpos, grot
            visuals = collisions = parent
            short = name
        else:
            bpos, brot = self.geo.body_pose(body)
            pos, rot = brot.T @ (gpos - bpos), brot.T @ grot
            visuals, collisions = f"{parent}/Visuals", f"{parent}/Collisions"
            short = name.split("/", 1)[1] if "/" in name else name
        plane = self.model.geom_type[geom] == mujoco.mjtGeom.mjGEOM_PLANE
        draw = visible and not plane
        for folder, used in ((visuals, draw), (collisions, collides)):
            if used and not self.stage.GetPrimAtPath(folder):
                UsdGeom.Scope.Define(self.stage, folder)
        if draw:
            self._visual(geom, self._path(visuals, short), pos, rot)
        if collides:
            suffix = "_collision" if draw and visuals == collisions else ""
            self._collider(geom, self._path(collisions, short + suffix), pos, rot)

    def _visual(self, geom: int, path: str, pos: np.ndarray, rot: np.ndarray) -> None:
        from pxr import UsdShade

        look = self.geo.look(geom)
        textured = look.texture is not None
        tris = self.geo.triangles(geom, look.repeat if textured else (1.0, 1.0))
        if tris is None or tris.empty:
            return
        mesh = visual_mesh(self.stage, path, tris, look, pos, rot)
        material = self._look(look, textured and tris.uvs is not None)
        UsdShade.MaterialBindingAPI.Apply(mesh.GetPrim()).Bind(material)
        string_attr(mesh.GetPrim(), "holomj:name", self.geo.geom_name(geom))

    def _collider(self, geom: int, path: str, pos: np.ndarray, rot: np.ndarray) -> None:
        from pxr import UsdGeom, UsdPhysics, UsdShade

        model = self.model
        made = collision_shape(self.stage, path, self.geo, geom)
        if made is None:
            return
        shape, scale = made
        set_pose(shape, pos, rot, scale)
        prim = shape.GetPrim()
        UsdPhysics.CollisionAPI.Apply(prim)
        shape.CreatePurposeAttr(UsdGeom.Tokens.guide)
        string_attr(prim, "holomj:name", self.geo.geom_name(geom))
        friction = round(float(model.geom_friction[geom][0]), 4)
        binding = UsdShade.MaterialBindingAPI.Apply(prim)
        binding.Bind(
            self._physics_material(friction), UsdShade.Tokens.weakerThanDescendants, "physics"
        )

    def _physics_material(self, friction: float) -> Any:
        if friction not in self._physics_materials:
            from pxr import UsdGeom

            path = self._path("/World/PhysicsMaterials", f"friction_{friction:g}")
            if not self.stage.GetPrimAtPath("/World/PhysicsMaterials"):
                UsdGeom.Scope.Define(self.stage, "/World/PhysicsMaterials")
            self._physics_materials[friction] = physics_material(self.stage, path, friction)
        return self._physics_materials[friction]

    def _look(self, look: Look, textured: bool) -> Any:
        from pxr import UsdGeom

        key = look.name if textured else f"{look.name}/untextured"
        if key in self._looks:
            return self._looks[key]
        if not self.stage.GetPrimAtPath("/World/Looks"):
            UsdGeom.Scope.Define(self.stage, "/World/Looks")
        path = self._path("/World/Looks", key)
        texture_file = None
        if textured and look.texture is not None:
            file = f"{TEXTURES_DIR}/{valid_name(self.geo.texture_name(look.texture))}.png"
            self.out.textures[file] = self.geo.texture_png(look.texture)
            texture_file = f"./{file}"  # anchored to the layer (a bare path is a search path)
        self._looks[key] = preview_material(self.stage, path, look, texture_file)
        return self._looks[key]
