"""Summaries of scenes and models: counts, masses and sizes (``holomj info``, compile report).

Typed results; ``to_dict()`` gives the JSON form the reports and ``--json`` print (key order as
the fields)."""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from typing import Any

import mujoco
from shapely.geometry import Polygon

from holomj.spec.scene import SceneSpec


@dataclass(frozen=True)
class ModelSummary:
    """Counts and mass of a compiled model; its lights are the scene's own or, for a scene that
    lists none, the sun and ceiling lights the compiler adds."""

    bodies: int
    geoms: int
    joints: int
    meshes: int
    lights: int
    free_joints: int
    hinges: int
    total_mass_kg: float

    def to_dict(self) -> dict[str, Any]:
        """JSON-able form."""
        return dataclasses.asdict(self)


@dataclass(frozen=True)
class RoomSummary:
    """A room's id, type and floor area (m², 3 decimals)."""

    id: str
    type: str
    area_m2: float


@dataclass(frozen=True)
class SceneSummary:
    """Rooms, openings and objects of a scene; ``lights``: the lights it lists."""

    name: str
    rooms: list[RoomSummary]
    walls: int
    doors: int
    windows: int
    objects: int
    static_objects: int
    dynamic_objects: int
    lights: int

    def to_dict(self) -> dict[str, Any]:
        """JSON-able form."""
        return dataclasses.asdict(self)


def model_summary(model: mujoco.MjModel) -> ModelSummary:
    """Counts and mass of a compiled model."""
    return ModelSummary(
        bodies=int(model.nbody),
        geoms=int(model.ngeom),
        joints=int(model.njnt),
        meshes=int(model.nmesh),
        lights=int(model.nlight),
        free_joints=int(sum(1 for t in model.jnt_type if t == mujoco.mjtJoint.mjJNT_FREE)),
        hinges=int(sum(1 for t in model.jnt_type if t == mujoco.mjtJoint.mjJNT_HINGE)),
        total_mass_kg=round(float(model.body_mass.sum()), 3),
    )


def scene_summary(scene: SceneSpec) -> SceneSummary:
    """Rooms, openings and objects of a scene."""
    return SceneSummary(
        name=scene.name,
        rooms=[
            RoomSummary(id=r.id, type=r.type, area_m2=round(Polygon(r.polygon).area, 3))
            for r in scene.rooms
        ],
        walls=len(scene.walls),
        doors=len(scene.doors),
        windows=len(scene.windows),
        objects=len(scene.objects),
        static_objects=sum(1 for o in scene.objects if o.static),
        dynamic_objects=sum(1 for o in scene.objects if not o.static),
        lights=len(scene.lights),
    )
