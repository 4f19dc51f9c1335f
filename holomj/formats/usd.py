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

import math
import re
from dataclasses import dataclass, field
from typing import Any

import mujoco
import numpy as np

from holomj.errors import InputError
from holomj.formats.model_geometry import (
    Look,
    ModelGeometry,
    Triangles,
    matrix_to_quat_wxyz,
    quat_from_to,
)
from holomj.mjcf import names
from holomj.spec.scene import SceneSpec
from holomj.version import __version__

USD_EXTRA_FIX = "pip install 'holomj[export]' (usd-core)"
TEXTURES_DIR = "textures"
_RESERVED = {"PhysicsScene", "Openings", "Lights", "Ground", "Bodies", "Looks", "PhysicsMaterials"}
_UNSAFE = re.compile(r"[^A-Za-z0-9_]")


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


def valid_name(name: str) -> str:
    """``name`` as a USD prim name (letters, digits, underscores; not starting with a digit)."""
    text = _UNSAFE.sub("_", name) or "_"
    return f"_{text}" if text[0].isdigit() else text


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
        self._lights()
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
        _string_attr(prim, "holomj:id", ident)
        _string_attr(prim, "holomj:name", self.geo.body_name(body))
        pos, rot = self.geo.body_pose(body)
        if nested:
            xform.SetResetXformStack(True)  # a rigid body inside another body: world pose
        _set_pose(xform, pos, rot)
        members = self._welded(body)
        dynamic = self._has_joint(body)
        if dynamic:
            UsdPhysics.RigidBodyAPI.Apply(prim)
            self._mass(prim, body, members)
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

    def _welded(self, body: int) -> list[int]:
        """``body`` and the descendants welded to it (no joint in between)."""
        out = [body]
        for child in self.geo.children[body]:
            if not self._has_joint(child):
                out += self._welded(child)
        return out

    def _mass(self, prim: Any, body: int, members: list[int]) -> None:
        from pxr import Gf, UsdPhysics

        model = self.model
        mass_api = UsdPhysics.MassAPI.Apply(prim)
        if len(members) == 1:
            mass = float(model.body_mass[body])
            com = np.asarray(model.body_ipos[body], dtype=float)
            inertia = np.asarray(model.body_inertia[body], dtype=float)
            axes = np.asarray(model.body_iquat[body], dtype=float)
        else:
            mass, com, inertia, axes = self._composite(body, members)
        mass_api.CreateMassAttr(mass)
        mass_api.CreateCenterOfMassAttr(Gf.Vec3f(*com.tolist()))
        mass_api.CreateDiagonalInertiaAttr(Gf.Vec3f(*inertia.tolist()))
        mass_api.CreatePrincipalAxesAttr(Gf.Quatf(float(axes[0]), *axes[1:].tolist()))

    def _composite(
        self, body: int, members: list[int]
    ) -> tuple[float, np.ndarray, np.ndarray, np.ndarray]:
        """Mass, centre of mass, principal inertia and axes of welded bodies, in ``body``'s
        frame."""
        data = self.geo.data
        bpos, brot = self.geo.body_pose(body)
        masses = np.array([float(self.model.body_mass[m]) for m in members])
        total = float(masses.sum())
        if total <= 0:
            return 0.0, np.zeros(3), np.zeros(3), np.array([1.0, 0, 0, 0])
        centres = np.array([brot.T @ (data.xipos[m] - bpos) for m in members])
        com = (masses[:, None] * centres).sum(axis=0) / total
        tensor = np.zeros((3, 3))
        for index, member in enumerate(members):
            irot = brot.T @ data.ximat[member].reshape(3, 3)
            local = irot @ np.diag(self.model.body_inertia[member]) @ irot.T
            offset = centres[index] - com
            tensor += local + masses[index] * (
                np.dot(offset, offset) * np.eye(3) - np.outer(offset, offset)
            )
        values, vectors = np.linalg.eigh(tensor)
        if np.linalg.det(vectors) < 0:
            vectors[:, 2] *= -1
        return total, com, values, matrix_to_quat_wxyz(vectors)

    def _joints(
        self, body: int, path: str, rigid_parent: tuple[str, int] | None, owner: str
    ) -> None:
        """The joints of ``body`` (its prim at ``path``) to ``rigid_parent`` (None: the world),
        as prims under ``owner``/Joints."""
        from pxr import Gf, UsdGeom, UsdPhysics

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
        joint = joints[0]
        kind = int(model.jnt_type[joint])
        name = model.joint(joint).name or f"joint_{joint}"
        joints_path = f"{owner}/Joints"
        if not self.stage.GetPrimAtPath(joints_path):
            UsdGeom.Scope.Define(self.stage, joints_path)
        jpath = self._path(joints_path, name.split("/", 1)[1] if "/" in name else name)
        axis_token = "X"
        if kind == mujoco.mjtJoint.mjJNT_HINGE:
            usd_joint = UsdPhysics.RevoluteJoint.Define(self.stage, jpath)
        elif kind == mujoco.mjtJoint.mjJNT_SLIDE:
            usd_joint = UsdPhysics.PrismaticJoint.Define(self.stage, jpath)
        else:
            usd_joint = UsdPhysics.SphericalJoint.Define(self.stage, jpath)
        prim = usd_joint.GetPrim()
        _string_attr(prim, "holomj:name", name)
        anchor = np.asarray(model.jnt_pos[joint], dtype=float)
        axis = np.asarray(model.jnt_axis[joint], dtype=float)
        frame = _rotation_from_quat(quat_from_to((1.0, 0.0, 0.0), axis))  # joint X = axis
        pos, rot = self.geo.body_pose(body)
        if rigid_parent is None:
            ppos, prot = np.zeros(3), np.eye(3)
        else:
            usd_joint.CreateBody0Rel().SetTargets([rigid_parent[0]])
            ppos, prot = self.geo.body_pose(rigid_parent[1])
        usd_joint.CreateBody1Rel().SetTargets([path])
        world_anchor = pos + rot @ anchor
        usd_joint.CreateLocalPos0Attr(Gf.Vec3f(*(prot.T @ (world_anchor - ppos)).tolist()))
        usd_joint.CreateLocalRot0Attr(_quatf(matrix_to_quat_wxyz(prot.T @ rot @ frame)))
        usd_joint.CreateLocalPos1Attr(Gf.Vec3f(*anchor.tolist()))
        usd_joint.CreateLocalRot1Attr(_quatf(matrix_to_quat_wxyz(frame)))
        if kind in (mujoco.mjtJoint.mjJNT_HINGE, mujoco.mjtJoint.mjJNT_SLIDE):
            usd_joint.CreateAxisAttr(axis_token)
            hinge = kind == mujoco.mjtJoint.mjJNT_HINGE
            unit = math.degrees(1.0) if hinge else 1.0  # USD: degrees; MuJoCo: radians
            # the stage is authored at joint value q, which is USD's zero
            q = float(self.geo.data.qpos[model.jnt_qposadr[joint]])
            if model.jnt_limited[joint]:
                low, high = (float(v) - q for v in model.jnt_range[joint])
                usd_joint.CreateLowerLimitAttr(low * unit)
                usd_joint.CreateUpperLimitAttr(high * unit)
            dof = int(model.jnt_dofadr[joint])
            damping = float(model.dof_damping[dof])
            stiffness = float(model.jnt_stiffness[joint])
            spring_target = float(model.qpos_spring[model.jnt_qposadr[joint]]) - q
            if damping > 0 or stiffness > 0:  # MuJoCo's passive spring-damper as a drive
                drive = UsdPhysics.DriveAPI.Apply(prim, "angular" if hinge else "linear")
                drive.CreateTypeAttr("force")
                drive.CreateStiffnessAttr(stiffness / unit)  # per degree for angular drives
                drive.CreateDampingAttr(damping / unit)
                if stiffness > 0:
                    drive.CreateTargetPositionAttr(spring_target * unit)
            for key, value in (
                ("armature", float(model.dof_armature[dof])),
                ("frictionloss", float(model.dof_frictionloss[dof])),
                ("damping", damping),
                ("stiffness", stiffness),
                ("springref", spring_target),
            ):
                prim.CreateAttribute(f"holomj:{key}", _sdf().ValueTypeNames.Float).Set(value)

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
        from pxr import UsdGeom, UsdShade, Vt

        look = self.geo.look(geom)
        textured = look.texture is not None
        tris = self.geo.triangles(geom, look.repeat if textured else (1.0, 1.0))
        if tris is None or tris.empty:
            return
        mesh = _mesh(self.stage, path, tris)
        _set_pose(mesh, pos, rot)
        if textured and tris.uvs is not None:
            primvar = UsdGeom.PrimvarsAPI(mesh).CreatePrimvar(
                "st", _sdf().ValueTypeNames.TexCoord2fArray, UsdGeom.Tokens.vertex
            )
            uv = tris.uvs.astype(float).copy()
            uv[:, 1] = 1.0 - uv[:, 1]  # USD's st has t = 0 at the image's bottom row
            primvar.Set(Vt.Vec2fArray.FromNumpy(uv.astype(np.float32)))
        mesh.CreateDisplayColorAttr([tuple(float(c) for c in look.linear_rgba[:3])])
        if look.rgba[3] < 1.0:
            mesh.CreateDisplayOpacityAttr([float(look.rgba[3])])
        material = self._look(look, textured and tris.uvs is not None)
        UsdShade.MaterialBindingAPI.Apply(mesh.GetPrim()).Bind(material)
        _string_attr(mesh.GetPrim(), "holomj:name", self.geo.geom_name(geom))

    def _collider(self, geom: int, path: str, pos: np.ndarray, rot: np.ndarray) -> None:
        from pxr import UsdGeom, UsdPhysics, UsdShade

        model = self.model
        kind = int(model.geom_type[geom])
        size = [float(v) for v in model.geom_size[geom]]
        scale = None
        if kind == mujoco.mjtGeom.mjGEOM_BOX:
            shape = UsdGeom.Cube.Define(self.stage, path)
            shape.CreateSizeAttr(2.0)
            scale = size
        elif kind == mujoco.mjtGeom.mjGEOM_SPHERE:
            shape = UsdGeom.Sphere.Define(self.stage, path)
            shape.CreateRadiusAttr(size[0])
        elif kind == mujoco.mjtGeom.mjGEOM_CAPSULE:
            shape = UsdGeom.Capsule.Define(self.stage, path)
            shape.CreateRadiusAttr(size[0])
            shape.CreateHeightAttr(2 * size[1])
            shape.CreateAxisAttr(UsdGeom.Tokens.z)
        elif kind == mujoco.mjtGeom.mjGEOM_CYLINDER:
            shape = UsdGeom.Cylinder.Define(self.stage, path)
            shape.CreateRadiusAttr(size[0])
            shape.CreateHeightAttr(2 * size[1])
            shape.CreateAxisAttr(UsdGeom.Tokens.z)
        elif kind == mujoco.mjtGeom.mjGEOM_PLANE:
            shape = UsdGeom.Plane.Define(self.stage, path)
            shape.CreateAxisAttr(UsdGeom.Tokens.z)
            shape.CreateWidthAttr(2 * size[0] if size[0] > 0 else 1000.0)
            shape.CreateLengthAttr(2 * size[1] if size[1] > 0 else 1000.0)
        else:  # meshes (MuJoCo collides their convex hulls), ellipsoids
            tris = self.geo.triangles(geom)
            if tris is None or tris.empty:
                return
            shape = _mesh(self.stage, path, tris)
            UsdPhysics.MeshCollisionAPI.Apply(shape.GetPrim()).CreateApproximationAttr("convexHull")
        _set_pose(shape, pos, rot, scale)
        prim = shape.GetPrim()
        UsdPhysics.CollisionAPI.Apply(prim)
        shape.CreatePurposeAttr(UsdGeom.Tokens.guide)
        _string_attr(prim, "holomj:name", self.geo.geom_name(geom))
        friction = round(float(model.geom_friction[geom][0]), 4)
        binding = UsdShade.MaterialBindingAPI.Apply(prim)
        binding.Bind(
            self._physics_material(friction), UsdShade.Tokens.weakerThanDescendants, "physics"
        )

    def _physics_material(self, friction: float) -> Any:
        from pxr import UsdPhysics, UsdShade

        if friction not in self._physics_materials:
            path = self._path("/World/PhysicsMaterials", f"friction_{friction:g}")
            if not self.stage.GetPrimAtPath("/World/PhysicsMaterials"):
                from pxr import UsdGeom

                UsdGeom.Scope.Define(self.stage, "/World/PhysicsMaterials")
            material = UsdShade.Material.Define(self.stage, path)
            api = UsdPhysics.MaterialAPI.Apply(material.GetPrim())
            api.CreateStaticFrictionAttr(friction)
            api.CreateDynamicFrictionAttr(friction)
            api.CreateRestitutionAttr(0.0)
            self._physics_materials[friction] = material
        return self._physics_materials[friction]

    def _look(self, look: Look, textured: bool) -> Any:
        from pxr import Gf, UsdGeom, UsdShade

        key = look.name if textured else f"{look.name}/untextured"
        if key in self._looks:
            return self._looks[key]
        if not self.stage.GetPrimAtPath("/World/Looks"):
            UsdGeom.Scope.Define(self.stage, "/World/Looks")
        path = self._path("/World/Looks", key)
        material = UsdShade.Material.Define(self.stage, path)
        shader = UsdShade.Shader.Define(self.stage, f"{path}/PreviewSurface")
        shader.CreateIdAttr("UsdPreviewSurface")
        sdf = _sdf()
        rgba = look.linear_rgba
        shader.CreateInput("roughness", sdf.ValueTypeNames.Float).Set(float(look.roughness))
        shader.CreateInput("metallic", sdf.ValueTypeNames.Float).Set(0.0)
        shader.CreateInput("opacity", sdf.ValueTypeNames.Float).Set(float(rgba[3]))
        if look.emission > 0:
            shader.CreateInput("emissiveColor", sdf.ValueTypeNames.Color3f).Set(
                Gf.Vec3f(*(min(1.0, c * look.emission) for c in rgba[:3]))
            )
        diffuse = shader.CreateInput("diffuseColor", sdf.ValueTypeNames.Color3f)
        if textured and look.texture is not None:
            file = f"{TEXTURES_DIR}/{valid_name(self.geo.texture_name(look.texture))}.png"
            self.out.textures[file] = self.geo.texture_png(look.texture)
            file = f"./{file}"  # anchored to the layer (a bare relative path is a search path)
            reader = UsdShade.Shader.Define(self.stage, f"{path}/TexCoords")
            reader.CreateIdAttr("UsdPrimvarReader_float2")
            reader.CreateInput("varname", sdf.ValueTypeNames.String).Set("st")
            texture = UsdShade.Shader.Define(self.stage, f"{path}/Texture")
            texture.CreateIdAttr("UsdUVTexture")
            texture.CreateInput("file", sdf.ValueTypeNames.Asset).Set(file)
            texture.CreateInput("sourceColorSpace", sdf.ValueTypeNames.Token).Set("sRGB")
            texture.CreateInput("wrapS", sdf.ValueTypeNames.Token).Set("repeat")
            texture.CreateInput("wrapT", sdf.ValueTypeNames.Token).Set("repeat")
            texture.CreateInput("scale", sdf.ValueTypeNames.Float4).Set(
                Gf.Vec4f(float(rgba[0]), float(rgba[1]), float(rgba[2]), 1.0)
            )
            texture.CreateInput("st", sdf.ValueTypeNames.Float2).ConnectToSource(
                reader.ConnectableAPI(), "result"
            )
            diffuse.ConnectToSource(texture.ConnectableAPI(), "rgb")
        else:
            diffuse.Set(Gf.Vec3f(*(float(c) for c in rgba[:3])))
        material.CreateSurfaceOutput().ConnectToSource(shader.ConnectableAPI(), "surface")
        self._looks[key] = material
        return material

    def _lights(self) -> None:
        from pxr import Gf, UsdGeom, UsdLux

        model, data = self.model, self.geo.data
        if model.nlight == 0:
            return
        UsdGeom.Xform.Define(self.stage, "/World/Lights")
        for light in range(model.nlight):
            name = model.light(light).name or f"light_{light}"
            path = self._path("/World/Lights", name)
            diffuse = np.asarray(model.light_diffuse[light], dtype=float)
            strength = float(diffuse.max())
            color = diffuse / strength if strength > 0 else np.ones(3)
            position = data.light_xpos[light]
            rotation = _rotation_from_quat(quat_from_to((0.0, 0.0, -1.0), data.light_xdir[light]))
            if int(model.light_type[light]) == mujoco.mjtLightType.mjLIGHT_DIRECTIONAL:
                lux = UsdLux.DistantLight.Define(self.stage, path)
                lux.CreateIntensityAttr(2000.0 * strength)
            else:
                lux = UsdLux.SphereLight.Define(self.stage, path)
                lux.CreateRadiusAttr(0.05)
                lux.CreateIntensityAttr(30000.0 * strength)
                if int(model.light_type[light]) == mujoco.mjtLightType.mjLIGHT_SPOT:
                    shaping = UsdLux.ShapingAPI.Apply(lux.GetPrim())
                    shaping.CreateShapingConeAngleAttr(float(model.light_cutoff[light]))
            lux.CreateColorAttr(Gf.Vec3f(*color.tolist()))
            _set_pose(UsdGeom.Xformable(lux), position, rotation)
            _string_attr(lux.GetPrim(), "holomj:name", name)


def _string_attr(prim: Any, name: str, value: str) -> None:
    prim.CreateAttribute(name, _sdf().ValueTypeNames.String).Set(value)


def _sdf() -> Any:
    from pxr import Sdf

    return Sdf


def _quatf(wxyz: np.ndarray) -> Any:
    from pxr import Gf

    return Gf.Quatf(float(wxyz[0]), float(wxyz[1]), float(wxyz[2]), float(wxyz[3]))


def _rotation_from_quat(wxyz: np.ndarray) -> np.ndarray:
    matrix = np.zeros(9)
    mujoco.mju_quat2Mat(matrix, np.asarray(wxyz, dtype=float))
    return matrix.reshape(3, 3)


def _set_pose(
    xformable: Any, pos: np.ndarray, rot: np.ndarray, scale: list[float] | None = None
) -> None:
    from pxr import Gf, UsdGeom

    xform = UsdGeom.Xformable(xformable)
    xform.AddTranslateOp(UsdGeom.XformOp.PrecisionDouble).Set(Gf.Vec3d(*(float(v) for v in pos)))
    quat = matrix_to_quat_wxyz(rot)
    xform.AddOrientOp(UsdGeom.XformOp.PrecisionDouble).Set(
        Gf.Quatd(float(quat[0]), float(quat[1]), float(quat[2]), float(quat[3]))
    )
    if scale is not None:
        xform.AddScaleOp(UsdGeom.XformOp.PrecisionDouble).Set(Gf.Vec3d(*scale))


def _mesh(stage: Any, path: str, tris: Triangles) -> Any:
    from pxr import UsdGeom, Vt

    mesh = UsdGeom.Mesh.Define(stage, path)
    mesh.CreatePointsAttr(Vt.Vec3fArray.FromNumpy(np.ascontiguousarray(tris.positions)))
    mesh.CreateFaceVertexCountsAttr(Vt.IntArray.FromNumpy(np.full(len(tris.faces), 3, np.int32)))
    mesh.CreateFaceVertexIndicesAttr(
        Vt.IntArray.FromNumpy(np.ascontiguousarray(tris.faces.reshape(-1).astype(np.int32)))
    )
    mesh.CreateNormalsAttr(Vt.Vec3fArray.FromNumpy(np.ascontiguousarray(tris.normals)))
    mesh.SetNormalsInterpolation(UsdGeom.Tokens.vertex)
    mesh.CreateSubdivisionSchemeAttr(UsdGeom.Tokens.none)
    mesh.CreateDoubleSidedAttr(True)
    low, high = tris.positions.min(axis=0), tris.positions.max(axis=0)
    mesh.CreateExtentAttr(Vt.Vec3fArray.FromNumpy(np.vstack([low, high]).astype(np.float32)))
    return mesh
