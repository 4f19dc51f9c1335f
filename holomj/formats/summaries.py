"""Summaries of scenes and models: counts, masses and sizes (``holomj info``, compile report)."""

from __future__ import annotations

from typing import Any

import mujoco
from shapely.geometry import Polygon

from holomj.spec.scene import SceneSpec


def model_summary(model: mujoco.MjModel) -> dict[str, Any]:
    """Counts and mass of a compiled model; its lights are the scene's own or, for a scene that
    lists none, the sun and ceiling lights the compiler adds."""
    return {
        "bodies": int(model.nbody),
        "geoms": int(model.ngeom),
        "joints": int(model.njnt),
        "meshes": int(model.nmesh),
        "lights": int(model.nlight),
        "free_joints": int(sum(1 for t in model.jnt_type if t == mujoco.mjtJoint.mjJNT_FREE)),
        "hinges": int(sum(1 for t in model.jnt_type if t == mujoco.mjtJoint.mjJNT_HINGE)),
        "total_mass_kg": round(float(model.body_mass.sum()), 3),
    }


def scene_summary(scene: SceneSpec) -> dict[str, Any]:
    """Rooms, openings and objects of a scene."""
    return {
        "name": scene.name,
        "rooms": [
            {"id": r.id, "type": r.type, "area_m2": round(Polygon(r.polygon).area, 3)}
            for r in scene.rooms
        ],
        "walls": len(scene.walls),
        "doors": len(scene.doors),
        "windows": len(scene.windows),
        "objects": len(scene.objects),
        "static_objects": sum(1 for o in scene.objects if o.static),
        "dynamic_objects": sum(1 for o in scene.objects if not o.static),
        "lights": len(scene.lights),
    }
