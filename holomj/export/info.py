"""Summaries of scenes: counts, masses and sizes, for ``holomj info`` and the compile report."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import mujoco
from shapely.geometry import Polygon

from holomj.errors import FormatError
from holomj.export.writer import SCENE_JSON, SCENE_XML
from holomj.mjcf.loading import load_model_file
from holomj.spec.base import read_json, validate_model
from holomj.spec.scene import SceneSpec


def model_summary(model: mujoco.MjModel) -> dict[str, Any]:
    """Counts and mass of a compiled model."""
    return {
        "bodies": int(model.nbody),
        "geoms": int(model.ngeom),
        "joints": int(model.njnt),
        "meshes": int(model.nmesh),
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


def folder_summary(out: Path) -> dict[str, Any]:
    """Summary of an exported folder: its scene.json and the model loaded from its scene.xml."""
    out = Path(out)
    if not out.is_dir():
        raise FormatError(
            "not a folder (expected a folder written by 'holomj compile')", where=str(out)
        )
    scene_path = out / SCENE_JSON
    scene = validate_model(SceneSpec, read_json(scene_path), str(scene_path))
    model = load_model_file(out / SCENE_XML)
    return {"folder": str(out), **scene_summary(scene), "model": model_summary(model)}
