"""``objects.json``: what a task designer needs to know about every object, door and the robot.

All poses are world frame at the scene's initial state (metres, quaternions w, x, y, z)::

    schema_version, scene, rooms [{id, type, area_m2, polygon}],
    objects [{id, category, proxy, asset, room, static, position, quat, yaw_deg, scale, mass_kg,
              aabb {min, max}, support, surfaces [{index, height, polygon, area_m2}],
              body, joint,
              joints [{name, part, kind, type, axis, anchor, range, value, closed, body,
                       handle {site, position, quat, pull} | null}],
              interior_surfaces [{index, part, body, behind, height, polygon, area_m2,
                                  clearance_m}]}],
    doors [{id, kind, rooms, position, width, leaves [{body, joint, range_rad, hinge, axis}]}],
    robot {name, spec, position, yaw_deg, room, base_body, joints [{name, range}],
           actuators} | null

``support`` is the object a small object was dropped on (``null``: the floor); ``surfaces`` are
an object's receptacle surfaces (tops, shelves) where others may be put; ``aabb`` bounds every
geom of the object (its moving parts too), visual ones included. Objects keep the scene's order.

Articulated objects (doors, drawers, lids: :mod:`holomj.mjcf.articulation`) list their
``joints``: the joint's name, the moving part and its kind, ``hinge`` (values in radians) or
``slide`` (metres), the world axis and anchor, the range, the current ``value`` and the
``closed`` one (positive values open), the ``body`` to grasp and the ``handle``: the site at the
grasp point, its world position and orientation (x axis: the direction to pull to open, z axis:
along the grip) and that pull direction. ``interior_surfaces`` are the surfaces inside (a shelf
behind a door, a drawer bottom) at the current pose, with the part they move with (null: the
carcass), its body and the joints to open to reach them. Both lists are empty for rigid objects.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import mujoco
import numpy as np

from holomj.mjcf import names
from holomj.mjcf.compiler import CompiledScene
from holomj.physics.surfaces_world import object_yaw, world_surfaces
from holomj.spec.robot import ROBOT_PREFIX
from holomj.spec.walls import room_polygon

OBJECTS_JSON = "objects.json"
OBJECTS_SCHEMA_VERSION = "1.0"
_DIGITS = 6
# (model, data, geom) -> world points whose convex hull holds the geom (holomj.robots.shapes)
GeomPoints = Callable[[mujoco.MjModel, mujoco.MjData, int], np.ndarray]


def objects_record(
    compiled: CompiledScene, *, geom_points: GeomPoints, robot_base_body: str
) -> dict[str, Any]:
    """The ``objects.json`` data of a compiled scene; ``geom_points`` outlines a geom (for the
    bounding boxes), ``robot_base_body`` names the body a robot is mounted on."""
    model = compiled.model
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    scene = compiled.scene
    return {
        "schema_version": OBJECTS_SCHEMA_VERSION,
        "scene": scene.name,
        "rooms": [
            {
                "id": room.id,
                "type": room.type,
                "area_m2": _r(room_polygon(room.polygon).area),
                "polygon": [[_r(x), _r(y)] for x, y in room.polygon],
            }
            for room in scene.rooms
        ],
        "objects": [_object(compiled, data, obj, geom_points) for obj in scene.objects],
        "doors": [_door(model, data, door) for door in scene.doors],
        "robot": _robot(compiled, data, robot_base_body),
    }


def _object(
    compiled: CompiledScene, data: mujoco.MjData, obj: Any, geom_points: GeomPoints
) -> dict[str, Any]:
    model = compiled.model
    body = model.body(names.object_body(obj.id)).id
    asset = compiled.assets.get(obj.asset)
    meta = asset.meta if asset is not None else None
    joint = int(model.body_jntadr[body]) if model.body_jntnum[body] else -1
    surfaces = []
    if meta is not None:
        surfaces = [
            {
                "index": s.index,
                "height": _r(s.height),
                "polygon": [[_r(x), _r(y)] for x, y in s.polygon.exterior.coords[:-1]],
                "area_m2": _r(s.area),
            }
            for s in world_surfaces(obj, meta)
        ]
    parts = ()
    if meta is not None and meta.articulation is not None:
        parts = tuple(
            model.body(names.object_part_body(obj.id, p.name)).id for p in meta.articulation.parts
        )
    low, high = _aabb(model, data, geom_points, body, parts)
    joints, interior = _articulation(compiled, data, obj, meta)
    return {
        "id": obj.id,
        "category": meta.category if meta is not None else None,
        "proxy": bool(meta is not None and meta.proxy) or bool(getattr(obj, "proxy", None)),
        "asset": obj.asset,
        "room": obj.room,
        "static": joint < 0,
        "position": _vec(data.xpos[body]),
        "quat": _vec(data.xquat[body]),
        "yaw_deg": _r(math.degrees(object_yaw(obj))),
        "scale": list(obj.scale3),
        "mass_kg": _r(float(model.body_subtreemass[body])),
        "aabb": {"min": _vec(low), "max": _vec(high)},
        "support": obj.support,
        "surfaces": surfaces,
        "body": model.body(body).name,
        "joint": model.joint(joint).name if joint >= 0 else None,
        "joints": joints,
        "interior_surfaces": interior,
    }


def _articulation(
    compiled: CompiledScene, data: mujoco.MjData, obj: Any, meta: Any
) -> tuple[list[dict[str, Any]], list[dict[str, Any]]]:
    """The joints and interior surfaces of an articulated object (empty lists otherwise)."""
    if meta is None or meta.articulation is None:
        return [], []
    model = compiled.model
    joints = []
    for part in meta.articulation.parts:
        body = model.body(names.object_part_body(obj.id, part.name)).id
        joint = model.joint(names.object_part_joint(obj.id, part.joint.name)).id
        handle = None
        if part.handle is not None:
            site = model.site(names.object_part_handle(obj.id, part.name)).id
            quat = np.zeros(4)
            mujoco.mju_mat2Quat(quat, data.site_xmat[site])
            handle = {
                "site": model.site(site).name,
                "position": _vec(data.site_xpos[site]),
                "quat": _vec(quat),
                "pull": _vec(data.site_xmat[site].reshape(3, 3)[:, 0]),
            }
        adr = model.jnt_qposadr[joint]
        joints.append(
            {
                "name": model.joint(joint).name,
                "part": part.name,
                "kind": part.kind,
                "type": part.joint.type,
                "axis": _vec(data.xaxis[joint]),
                "anchor": _vec(data.xanchor[joint]),
                "range": _vec(model.jnt_range[joint]),
                "value": _r(float(data.qpos[adr])),
                "closed": _r(float(model.qpos0[adr])),
                "body": model.body(body).name,
                "handle": handle,
            }
        )
    interior = []
    scale = np.asarray(obj.scale3, dtype=float)
    carcass = model.body(names.object_body(obj.id)).id
    for index, surface in enumerate(meta.articulation.interior):
        on = carcass
        if surface.part is not None:
            on = model.body(names.object_part_body(obj.id, surface.part)).id
        rot = data.xmat[on].reshape(3, 3)
        local = [
            (x * scale[0], y * scale[1], surface.height * scale[2]) for x, y in surface.polygon
        ]
        world = [data.xpos[on] + rot @ np.asarray(p) for p in local]
        interior.append(
            {
                "index": index,
                "part": surface.part,
                "body": model.body(on).name,
                "behind": [names.object_part_joint(obj.id, j) for j in surface.behind],
                "height": _r(float(np.mean([p[2] for p in world]))),
                "polygon": [[_r(p[0]), _r(p[1])] for p in world],
                "area_m2": _r(surface.area_m2 * scale[0] * scale[1]),
                "clearance_m": (
                    _r(surface.clearance_m * scale[2]) if surface.clearance_m is not None else None
                ),
            }
        )
    return joints, interior


def _aabb(
    model: mujoco.MjModel,
    data: mujoco.MjData,
    geom_points: GeomPoints,
    body: int,
    parts: tuple[int, ...] = (),
) -> tuple[np.ndarray, np.ndarray]:
    geoms = [
        g
        for b in (body, *parts)
        for g in range(model.body_geomadr[b], model.body_geomadr[b] + model.body_geomnum[b])
    ]
    points = [geom_points(model, data, g) for g in geoms]
    if not points:
        return data.xpos[body].copy(), data.xpos[body].copy()
    cloud = np.vstack(points)
    return cloud.min(axis=0), cloud.max(axis=0)


def _door(model: mujoco.MjModel, data: mujoco.MjData, door: Any) -> dict[str, Any]:
    leaves = []
    for index in range(2):
        try:
            body = model.body(names.door_leaf_body(door.id, index)).id
            joint = model.joint(names.door_hinge(door.id, index)).id
        except KeyError:
            break
        leaves.append(
            {
                "body": model.body(body).name,
                "joint": model.joint(joint).name,
                "range_rad": _vec(model.jnt_range[joint]),
                "hinge": _vec(data.xanchor[joint]),
                "axis": _vec(data.xaxis[joint]),
            }
        )
    return {
        "id": door.id,
        "kind": door.kind,
        "rooms": list(door.rooms),
        "position": [_r(door.position[0]), _r(door.position[1])],
        "width": _r(door.effective_width),
        "leaves": leaves,
    }


def _robot(compiled: CompiledScene, data: mujoco.MjData, base_body: str) -> dict[str, Any] | None:
    record = compiled.robot
    if record is None:
        return None
    model = compiled.model
    joints = [
        {
            "name": model.joint(j).name,
            "range": _vec(model.jnt_range[j]) if model.jnt_limited[j] else None,
            "home": _r(float(model.qpos0[model.jnt_qposadr[j]])),
        }
        for j in range(model.njnt)
        if model.joint(j).name.startswith(ROBOT_PREFIX)
    ]
    actuators = [
        model.actuator(a).name
        for a in range(model.nu)
        if model.actuator(a).name.startswith(ROBOT_PREFIX)
    ]
    return {
        "name": record.name,
        "spec": record.spec,
        "position": list(record.position),
        "yaw_deg": record.yaw_deg,
        "room": record.room,
        "base_body": base_body,
        "footprint_radius_m": record.footprint.radius_m,
        "joints": joints,
        "actuators": actuators,
    }


def _vec(values: Any) -> list[float]:
    return [_r(float(v)) for v in values]


def _r(value: float) -> float:
    rounded = round(float(value), _DIGITS)
    return 0.0 if rounded == 0 else rounded
