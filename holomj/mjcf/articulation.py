"""Moving parts of articulated objects: doors, drawers and lids as bodies on real joints.

An asset with an :class:`~holomj.spec.assets.Articulation` compiles to its carcass body (free or
fixed, as every object) with one child body per moving part, joined by the part's hinge or
slide joint. Every part body sits at the carcass frame (the asset frame), so the part's geoms
keep the coordinates the asset gives them at the closed pose, and the joint's ``ref`` is the
closed value: the model's default pose (``qpos0``, what ``mj_resetData`` gives) is closed.

Names (:mod:`holomj.mjcf.names`): ``<object>/<part>`` bodies, ``<object>/<joint>`` joints
(``cabinet_1/door_0_hinge``), ``<object>/<part>/visual_k`` and ``collision_k`` geoms, and a site
``<object>/<part>/handle`` at the grasp pose (x axis: the pull direction when closed).

Contacts between a part and the body it hangs on are excluded (``<exclude>``), as MuJoCo's
parent filter does for free carcasses anyway: the joint range is what stops a door or a drawer,
and the asset keeps every collider of a closed part clear of its carcass, so whether the
carcass is free or fixed, a part never rubs or jams on it. Parts collide with everything else
(their neighbours, what is put inside, the robot). Part colliders use the ``prop`` class (they
move). Joint limits are stiffer than MuJoCo's default (:data:`LIMIT_SOLREF`), so a door pushed
shut stops within a millimetre of its closed pose.
"""

from __future__ import annotations

import math

import mujoco
import numpy as np

from holomj.mjcf import names
from holomj.mjcf.colliders import collider_fields
from holomj.mjcf.context import BuildContext
from holomj.mjcf.geometry import clean
from holomj.spec.assets import ArticulatedPart, AssetMeta
from holomj.spec.scene import SceneObject

LIMIT_SOLREF = (0.005, 1.0)  # time constant (>= 2 timesteps of 2 ms) and damping ratio
HANDLE_SITE_SIZE = 0.01
HANDLE_SITE_GROUP = 5  # hidden by default in viewers
_JOINT_TYPES = {"hinge": mujoco.mjtJoint.mjJNT_HINGE, "slide": mujoco.mjtJoint.mjJNT_SLIDE}


def add_moving_parts(
    ctx: BuildContext,
    carcass: mujoco.MjsBody,
    obj: SceneObject,
    meta: AssetMeta,
    handles: dict,
    scale: tuple[float, float, float],
    mass: float,
) -> dict[str, mujoco.MjsBody]:
    """Add the moving parts of ``meta`` under ``carcass`` (object ``obj`` at ``scale``, whole
    mass ``mass``); ``handles`` maps part names to their mesh and material names. Returns the
    part bodies by part name."""
    assert meta.articulation is not None
    bodies: dict[str, mujoco.MjsBody] = {}
    s = np.asarray(scale, dtype=float)
    for part in meta.articulation.parts:
        parent = carcass if part.parent is None else bodies[part.parent]
        body = parent.add_body(name=names.object_part_body(obj.id, part.name))
        body.info = f"{part.kind} {part.name} of object {obj.id} (asset {meta.id})"
        part_mass = mass * part.mass_kg / meta.mass
        _add_joint(body, obj, part, s, part_mass / part.mass_kg)
        mine = handles[part.name]
        for k, (mesh, material) in enumerate(zip(mine.visual_meshes, mine.visual_materials)):
            geom = body.add_geom(
                name=names.object_part_visual(obj.id, part.name, k),
                default=ctx.default("visual"),
                type=mujoco.mjtGeom.mjGEOM_MESH,
                meshname=mesh,
                material=material,
            )
            geom.info = f"visual {k} of {part.name} of object {obj.id}"
        volume = part.collision_volume_m3
        for k, collider in enumerate(part.collision):
            geom = body.add_geom(
                name=names.object_part_collision(obj.id, part.name, k),
                default=ctx.default("prop"),
                mass=part_mass * collider.volume_m3 / volume,
                friction=[meta.friction, 0.01, 0.001],
                **collider_fields(collider, scale, mine.collision_meshes.get(k)),
            )
            geom.info = f"collider {k} of {part.name} of object {obj.id}"
        if part.handle is not None:
            site = body.add_site(
                name=names.object_part_handle(obj.id, part.name),
                pos=clean(np.asarray(part.handle.pos) * s),
                quat=clean(part.handle.quat),
                size=[HANDLE_SITE_SIZE, 0.0, 0.0],
                group=HANDLE_SITE_GROUP,
            )
            site.info = f"handle of {part.name} of object {obj.id}"
        exclude = ctx.spec.add_exclude(bodyname1=parent.name, bodyname2=body.name)
        exclude.info = f"{part.name} of object {obj.id} and the body it hangs on"
        bodies[part.name] = body
    return bodies


def _add_joint(
    body: mujoco.MjsBody, obj: SceneObject, part: ArticulatedPart, s: np.ndarray, heavier: float
) -> mujoco.MjsJoint:
    """The part's joint at scale ``s``, its part ``heavier`` times the asset's part mass.

    A slide's travel scales with its axis. What resists motion scales with the part: forces
    (a slide's damping and friction) with its mass, torques (a hinge's damping, friction and
    counterbalance) with its mass times its size, armature with mass times size squared.
    """
    j = part.joint
    axis = np.asarray(j.axis) * s
    stretch = float(np.linalg.norm(axis))
    size = float(np.prod(s)) ** (1.0 / 3.0)
    travel = stretch if j.type == "slide" else 1.0
    force = heavier * (size if j.type == "hinge" else 1.0)
    inertia = force * (size if j.type == "hinge" else 1.0)
    joint = body.add_joint(
        name=names.object_part_joint(obj.id, j.name),
        type=_JOINT_TYPES[j.type],
        axis=clean(axis / stretch),
        pos=clean(np.asarray(j.anchor) * s),
        range=clean([j.range[0] * travel, j.range[1] * travel]),
        limited=mujoco.mjtLimited.mjLIMITED_TRUE,
        ref=_r(j.closed * travel),
        springref=_r(j.springref * travel),
        armature=_r(j.armature * inertia),
        frictionloss=_r(j.frictionloss * force),
    )
    joint.damping = [_r(j.damping * force), 0.0, 0.0]
    joint.stiffness = [_r(j.stiffness * force), 0.0, 0.0]
    joint.solref_limit = list(LIMIT_SOLREF)
    joint.info = f"{j.type} of {part.name} of object {obj.id}"
    return joint


def _r(value: float) -> float:
    return 0.0 if math.isclose(value, 0.0, abs_tol=1e-12) else float(value)
