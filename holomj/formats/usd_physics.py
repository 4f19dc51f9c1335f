"""UsdPhysics authoring for the USD export: a rigid body's mass (bodies welded to it merged in),
a joint with its limits, passive drive and MuJoCo's joint attributes, and friction materials.

Needs ``usd-core`` (the ``export`` extra); callers check with :func:`holomj.formats.usd.load_pxr`.
"""

from __future__ import annotations

import math
from typing import Any

import mujoco
import numpy as np

from holomj.formats.model_geometry import ModelGeometry, matrix_to_quat_wxyz, quat_from_to
from holomj.formats.usd_prims import mesh_prim, quatf, rotation_from_quat, sdf, string_attr
from holomj.formats.welded_bodies import welded_inertia


def apply_mass(prim: Any, geo: ModelGeometry, body: int, members: list[int]) -> None:
    """MassAPI on ``prim``: the mass, centre of mass, principal inertia and axes of ``body`` and
    the bodies welded to it (``members``, ``body`` first)."""
    from pxr import Gf, UsdPhysics

    model = geo.model
    mass_api = UsdPhysics.MassAPI.Apply(prim)
    if len(members) == 1:
        mass = float(model.body_mass[body])
        com = np.asarray(model.body_ipos[body], dtype=float)
        inertia = np.asarray(model.body_inertia[body], dtype=float)
        axes = np.asarray(model.body_iquat[body], dtype=float)
    else:
        mass, com, inertia, axes = _composite(geo, body, members)
    mass_api.CreateMassAttr(mass)
    mass_api.CreateCenterOfMassAttr(Gf.Vec3f(*com.tolist()))
    mass_api.CreateDiagonalInertiaAttr(Gf.Vec3f(*inertia.tolist()))
    mass_api.CreatePrincipalAxesAttr(Gf.Quatf(float(axes[0]), *axes[1:].tolist()))


def _composite(
    geo: ModelGeometry, body: int, members: list[int]
) -> tuple[float, np.ndarray, np.ndarray, np.ndarray]:
    """Mass, centre of mass, principal inertia and axes (a quaternion) of welded bodies, in
    ``body``'s frame."""
    bpos, brot = geo.body_pose(body)
    found = welded_inertia(geo, members, bpos, brot)
    if found is None:
        return 0.0, np.zeros(3), np.zeros(3), np.array([1.0, 0, 0, 0])
    total, centre, values, vectors = found
    return total, centre, values, matrix_to_quat_wxyz(vectors)


def define_joint(
    stage: Any,
    geo: ModelGeometry,
    joint: int,
    joint_path: str,
    body: tuple[str, int],
    rigid_parent: tuple[str, int] | None,
) -> None:
    """MuJoCo joint ``joint`` at ``joint_path``: a revolute, prismatic or spherical joint from
    ``rigid_parent`` (prim path and body id; None: the world) to ``body`` (likewise)."""
    from pxr import Gf, UsdPhysics

    model = geo.model
    kind = int(model.jnt_type[joint])
    if kind == mujoco.mjtJoint.mjJNT_HINGE:
        usd_joint = UsdPhysics.RevoluteJoint.Define(stage, joint_path)
    elif kind == mujoco.mjtJoint.mjJNT_SLIDE:
        usd_joint = UsdPhysics.PrismaticJoint.Define(stage, joint_path)
    else:
        usd_joint = UsdPhysics.SphericalJoint.Define(stage, joint_path)
    prim = usd_joint.GetPrim()
    string_attr(prim, "holomj:name", model.joint(joint).name or f"joint_{joint}")
    anchor = np.asarray(model.jnt_pos[joint], dtype=float)
    axis = np.asarray(model.jnt_axis[joint], dtype=float)
    frame = rotation_from_quat(quat_from_to((1.0, 0.0, 0.0), axis))  # joint X = axis
    pos, rot = geo.body_pose(body[1])
    if rigid_parent is None:
        ppos, prot = np.zeros(3), np.eye(3)
    else:
        usd_joint.CreateBody0Rel().SetTargets([rigid_parent[0]])
        ppos, prot = geo.body_pose(rigid_parent[1])
    usd_joint.CreateBody1Rel().SetTargets([body[0]])
    world_anchor = pos + rot @ anchor
    usd_joint.CreateLocalPos0Attr(Gf.Vec3f(*(prot.T @ (world_anchor - ppos)).tolist()))
    usd_joint.CreateLocalRot0Attr(quatf(matrix_to_quat_wxyz(prot.T @ rot @ frame)))
    usd_joint.CreateLocalPos1Attr(Gf.Vec3f(*anchor.tolist()))
    usd_joint.CreateLocalRot1Attr(quatf(matrix_to_quat_wxyz(frame)))
    if kind in (mujoco.mjtJoint.mjJNT_HINGE, mujoco.mjtJoint.mjJNT_SLIDE):
        usd_joint.CreateAxisAttr("X")
        _limits_and_drive(geo, joint, usd_joint, hinge=kind == mujoco.mjtJoint.mjJNT_HINGE)


def _limits_and_drive(geo: ModelGeometry, joint: int, usd_joint: Any, *, hinge: bool) -> None:
    """A hinge's or slide's range, its passive spring-damper as a drive, and MuJoCo's joint
    attributes as ``holomj:`` floats."""
    from pxr import UsdPhysics

    model = geo.model
    prim = usd_joint.GetPrim()
    unit = math.degrees(1.0) if hinge else 1.0  # USD: degrees; MuJoCo: radians
    # the stage is authored at joint value q, which is USD's zero
    q = float(geo.data.qpos[model.jnt_qposadr[joint]])
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
        prim.CreateAttribute(f"holomj:{key}", sdf().ValueTypeNames.Float).Set(value)


def physics_material(stage: Any, path: str, friction: float) -> Any:
    """A UsdPhysics material at ``path`` with static and dynamic ``friction``, no restitution."""
    from pxr import UsdPhysics, UsdShade

    material = UsdShade.Material.Define(stage, path)
    api = UsdPhysics.MaterialAPI.Apply(material.GetPrim())
    api.CreateStaticFrictionAttr(friction)
    api.CreateDynamicFrictionAttr(friction)
    api.CreateRestitutionAttr(0.0)
    return material


def collision_shape(
    stage: Any, path: str, geo: ModelGeometry, geom: int
) -> tuple[Any, list[float] | None] | None:
    """The collider prim of ``geom`` at ``path`` and the scale its pose needs: boxes, spheres,
    capsules, cylinders and planes as USD primitives, meshes (MuJoCo collides their convex
    hulls) and ellipsoids as meshes approximated by their convex hull; None for a geom with
    no triangles."""
    from pxr import UsdGeom, UsdPhysics

    kind = int(geo.model.geom_type[geom])
    size = [float(v) for v in geo.model.geom_size[geom]]
    scale = None
    if kind == mujoco.mjtGeom.mjGEOM_BOX:
        shape = UsdGeom.Cube.Define(stage, path)
        shape.CreateSizeAttr(2.0)
        scale = size
    elif kind == mujoco.mjtGeom.mjGEOM_SPHERE:
        shape = UsdGeom.Sphere.Define(stage, path)
        shape.CreateRadiusAttr(size[0])
    elif kind in (mujoco.mjtGeom.mjGEOM_CAPSULE, mujoco.mjtGeom.mjGEOM_CYLINDER):
        kind_class = UsdGeom.Capsule if kind == mujoco.mjtGeom.mjGEOM_CAPSULE else UsdGeom.Cylinder
        shape = kind_class.Define(stage, path)
        shape.CreateRadiusAttr(size[0])
        shape.CreateHeightAttr(2 * size[1])
        shape.CreateAxisAttr(UsdGeom.Tokens.z)
    elif kind == mujoco.mjtGeom.mjGEOM_PLANE:
        shape = UsdGeom.Plane.Define(stage, path)
        shape.CreateAxisAttr(UsdGeom.Tokens.z)
        shape.CreateWidthAttr(2 * size[0] if size[0] > 0 else 1000.0)
        shape.CreateLengthAttr(2 * size[1] if size[1] > 0 else 1000.0)
    else:
        tris = geo.triangles(geom)
        if tris is None or tris.empty:
            return None
        shape = mesh_prim(stage, path, tris)
        UsdPhysics.MeshCollisionAPI.Apply(shape.GetPrim()).CreateApproximationAttr("convexHull")
    return shape, scale
