"""``objects.json``: what a task designer needs to know about every object, door and the robot.

All poses are world frame at the scene's initial state (metres, quaternions w, x, y, z)::

    schema_version, scene, rooms [{id, type, area_m2, polygon}],
    objects [{id, category, proxy, asset, room, static, position, quat, yaw_deg, scale, mass_kg,
              aabb {min, max}, support, surfaces [{index, height, polygon, area_m2}],
              body, joint}],
    doors [{id, kind, rooms, position, width, leaves [{body, joint, range_rad, hinge, axis}]}],
    robot {name, spec, position, yaw_deg, room, base_body, joints [{name, range}],
           actuators} | null

``support`` is the object a small object was dropped on (``null``: the floor); ``surfaces`` are
an object's receptacle surfaces (tops, shelves) where others may be put; ``aabb`` bounds every
geom of the object, visual ones included. Objects keep the scene's order.
"""

from __future__ import annotations

import math
from typing import Any

import mujoco
import numpy as np

from holomj.mjcf import names
from holomj.mjcf.compiler import CompiledScene
from holomj.physics.surfaces_world import object_yaw, world_surfaces
from holomj.robots import shapes
from holomj.robots.attach import MOUNT_BODY
from holomj.spec.robot import ROBOT_PREFIX
from holomj.spec.walls import room_polygon

OBJECTS_JSON = "objects.json"
OBJECTS_SCHEMA_VERSION = "1.0"
_DIGITS = 6


def objects_record(compiled: CompiledScene) -> dict[str, Any]:
    """The ``objects.json`` data of a compiled scene."""
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
        "objects": [_object(compiled, data, obj) for obj in scene.objects],
        "doors": [_door(model, data, door) for door in scene.doors],
        "robot": _robot(compiled, data),
    }


def _object(compiled: CompiledScene, data: mujoco.MjData, obj: Any) -> dict[str, Any]:
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
    low, high = _aabb(model, data, body)
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
    }


def _aabb(model: mujoco.MjModel, data: mujoco.MjData, body: int) -> tuple[np.ndarray, np.ndarray]:
    geoms = range(model.body_geomadr[body], model.body_geomadr[body] + model.body_geomnum[body])
    points = [shapes.world_points(model, data, g) for g in geoms]
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


def _robot(compiled: CompiledScene, data: mujoco.MjData) -> dict[str, Any] | None:
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
        "base_body": MOUNT_BODY,
        "footprint_radius_m": record.footprint.radius_m,
        "joints": joints,
        "actuators": actuators,
    }


def _vec(values: Any) -> list[float]:
    return [_r(float(v)) for v in values]


def _r(value: float) -> float:
    rounded = round(float(value), _DIGITS)
    return 0.0 if rounded == 0 else rounded
