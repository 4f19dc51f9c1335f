"""Which views a render makes and where their cameras go, for a scene ready to render.

The top view needs nothing but the house's bounds; a room view looks at the mass-weighted centre
of the furniture in the room; a close-up frames a receptacle (an object the scene names as some
other object's ``support``) together with everything resting on it. Poses come from the model
in its resting state (see :mod:`holomj.rendering.source`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from shapely.geometry import Point, Polygon

from holomj.mjcf import names
from holomj.rendering.cameras import CameraPose, Mass, TopCamera, closeup_camera, room_camera
from holomj.rendering.plan_view import PlanViewObject
from holomj.rendering.source import RenderScene
from holomj.rendering.views import ViewJob
from holomj.spec.scene import SceneSpec

TOP_CAMERA = "render/top"


@dataclass(frozen=True)
class Subject:
    """A view to make: its kind, the room or object it shows, and its camera's name."""

    kind: str  # "top", "room" or "object"
    id: str | None
    camera: str


def view_subjects(scene: SceneSpec, views: tuple[str, ...]) -> list[Subject]:
    """Every view the chosen ``views`` make for ``scene``, in a stable order."""
    subjects: list[Subject] = []
    if "top" in views:
        subjects.append(Subject("top", None, TOP_CAMERA))
    if "rooms" in views:
        subjects += [Subject("room", r.id, f"render/room/{r.id}") for r in scene.rooms]
    if "objects" in views:
        supports = {o.support for o in scene.objects if o.support is not None}
        subjects += [
            Subject("object", o.id, f"render/object/{o.id}")
            for o in scene.objects
            if o.id in supports
        ]
    return subjects


def house_bounds(scene: SceneSpec) -> tuple[float, float, float, float]:
    """(xmin, ymin, xmax, ymax) of the rooms, grown by the exterior wall thickness."""
    xs = [x for room in scene.rooms for x, _ in room.polygon]
    ys = [y for room in scene.rooms for _, y in room.polygon]
    grow = scene.exterior_wall_thickness
    return min(xs) - grow, min(ys) - grow, max(xs) + grow, max(ys) + grow


def view_jobs(rs: RenderScene, subjects: list[Subject], top: TopCamera) -> list[ViewJob]:
    """A posed camera and an image name stem for every subject."""
    masses: list[Mass] | None = None
    jobs = []
    for subject in subjects:
        if subject.kind == "top" or subject.id is None:
            jobs.append(ViewJob("top", None, "top", top.pose(subject.camera)))
            continue
        stem = names.asset_folder(subject.id)
        if subject.kind == "room":
            if masses is None:
                masses = [m for m in (rs.mass(o.id) for o in rs.scene.objects) if m is not None]
            pose = room_camera(
                subject.camera,
                rs.scene.room(subject.id).polygon,
                masses,
                rs.scene.wall_height,
                top.width_px / top.height_px,
            )
            jobs.append(ViewJob("room", subject.id, f"rooms/{stem}", pose))
        else:
            pose = _closeup(rs, subject.id, subject.camera)
            jobs.append(ViewJob("object", subject.id, f"objects/{stem}", pose))
    return jobs


def _closeup(rs: RenderScene, receptacle: str, camera: str) -> CameraPose:
    ids = [receptacle] + [o.id for o in rs.scene.objects if o.support == receptacle]
    parts = [rs.object_points(i) for i in ids]
    points = np.concatenate(parts) if parts else np.zeros((0, 3))
    if len(points) == 0:
        points = np.zeros((1, 3))
    lo, hi = points.min(axis=0), points.max(axis=0)
    centre = (float(lo[0] + hi[0]) / 2, float(lo[1] + hi[1]) / 2, float(lo[2] + hi[2]) / 2)
    radius = max(0.5 * math.dist(lo, hi), 0.15)
    room = _room_of(rs.scene, receptacle, centre)
    return closeup_camera(camera, centre, radius, rs.yaw_deg(receptacle), room)


def _room_of(
    scene: SceneSpec, object_id: str, centre: tuple[float, float, float]
) -> Polygon | None:
    """The room an object belongs to (its ``room``, else the one holding ``centre``)."""
    obj = next(o for o in scene.objects if o.id == object_id)
    if obj.room is not None:
        return Polygon(scene.room(obj.room).polygon)
    for room in scene.rooms:
        shape = Polygon(room.polygon)
        if shape.contains(Point(centre[0], centre[1])):
            return shape
    return None


def plan_objects(rs: RenderScene) -> list[PlanViewObject]:
    """Every object's footprint on the plan, small ones (resting on another) marked."""
    result = []
    for obj in rs.scene.objects:
        footprint = rs.footprint(obj.id)
        if footprint is not None:
            result.append(PlanViewObject(obj.id, footprint, obj.support is not None))
    return result
