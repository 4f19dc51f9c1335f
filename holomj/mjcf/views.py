"""Lights and cameras: the scene's own, plus defaults so every scene can be seen."""

from __future__ import annotations

import math
from collections.abc import Sequence

import mujoco
import numpy as np
from shapely.geometry import Point, Polygon

from holomj.mjcf import names
from holomj.mjcf.context import BuildContext
from holomj.mjcf.geometry import clean, look_at_quat
from holomj.spec.decor import LIGHT_BELOW_FIXTURE_M

_LIGHT_TYPES = {
    "point": mujoco.mjtLightType.mjLIGHT_POINT,
    "spot": mujoco.mjtLightType.mjLIGHT_SPOT,
    "directional": mujoco.mjtLightType.mjLIGHT_DIRECTIONAL,
}
EYE_HEIGHT = 1.6
ROOM_CAMERA_FOVY = 75.0


def add_lights(ctx: BuildContext, fixtures: Sequence[Sequence[float]] = ()) -> None:
    """The scene's lights, or a sun plus the rooms' ceiling lights when it has none: a point
    light under every light fixture of a room (``fixtures``: their base positions; a fixture's
    base is its lowest point), else one at the room's centre under the ceiling."""
    scene = ctx.scene
    if scene.lights:
        for light in scene.lights:
            diffuse = np.clip(np.array(light.color) * min(light.energy, 1.0), 0.0, 1.0)
            direction = np.array(light.direction) / np.linalg.norm(light.direction)
            added = ctx.spec.worldbody.add_light(
                name=names.light(light.id),
                type=_LIGHT_TYPES[light.kind],
                pos=clean(light.position),
                dir=clean(direction),
                diffuse=clean(diffuse),
                specular=clean(diffuse * 0.3),
                castshadow=light.cast_shadow,
                cutoff=light.cutoff_deg,
                intensity=light.energy,
            )
            added.info = f"light {light.id}"
        return
    xs, ys = ctx.extent()
    centre = ((xs[0] + xs[1]) / 2, (ys[0] + ys[1]) / 2)
    ctx.spec.worldbody.add_light(
        name=names.light("sun"),
        type=mujoco.mjtLightType.mjLIGHT_DIRECTIONAL,
        pos=clean([centre[0], centre[1], scene.wall_height + 10.0]),
        dir=clean(np.array([0.3, 0.2, -1.0]) / np.linalg.norm([0.3, 0.2, -1.0])),
        diffuse=[0.5, 0.5, 0.5],
        specular=[0.1, 0.1, 0.1],
        castshadow=True,
    )
    for room in scene.rooms:
        polygon = Polygon(room.polygon)
        c = polygon.centroid
        inside = [f for f in fixtures if polygon.contains(Point(f[0], f[1]))]
        if not inside:
            ctx.spec.worldbody.add_light(
                name=names.light(f"room/{room.id}"),
                type=mujoco.mjtLightType.mjLIGHT_POINT,
                pos=clean([c.x, c.y, scene.wall_height - 0.3]),
                diffuse=[0.25, 0.25, 0.25],
                specular=[0.05, 0.05, 0.05],
                castshadow=False,
            )
            continue
        share = 0.25 / len(inside) ** 0.5  # more fixtures, each a little dimmer
        for k, (x, y, z) in enumerate(inside):
            added = ctx.spec.worldbody.add_light(
                name=names.light(f"room/{room.id}/fixture{k}"),
                type=mujoco.mjtLightType.mjLIGHT_POINT,
                pos=clean([x, y, max(z - LIGHT_BELOW_FIXTURE_M, 0.5)]),
                diffuse=[share, share, share],
                specular=[0.05, 0.05, 0.05],
                castshadow=False,
            )
            added.info = f"light of the fixture at ({x:.2f}, {y:.2f}) in {room.id}"


def add_cameras(ctx: BuildContext) -> None:
    """User cameras, a top-down orthographic overview and one eye-height camera per room."""
    scene = ctx.scene
    for camera in scene.cameras:
        ctx.spec.worldbody.add_camera(
            name=names.camera(camera.id),
            pos=clean(camera.position),
            quat=list(look_at_quat(camera.position, camera.target)),
            fovy=camera.fovy_deg,
            proj=_projection(camera.orthographic),
        )
    xs, ys = ctx.extent()
    span = max(xs[1] - xs[0], ys[1] - ys[0]) * 1.1 + 0.5
    ctx.spec.worldbody.add_camera(
        name=names.OVERVIEW_CAMERA,
        pos=clean([(xs[0] + xs[1]) / 2, (ys[0] + ys[1]) / 2, scene.wall_height + 20.0]),
        quat=[1.0, 0.0, 0.0, 0.0],
        fovy=span,
        proj=mujoco.mjtProjection.mjPROJ_ORTHOGRAPHIC,
    )
    for room in scene.rooms:
        position, target = room_camera_pose(room.polygon, min(EYE_HEIGHT, scene.wall_height - 0.2))
        ctx.spec.worldbody.add_camera(
            name=names.room_camera(room.id),
            pos=clean(position),
            quat=list(look_at_quat(position, target)),
            fovy=ROOM_CAMERA_FOVY,
        )


def room_camera_pose(
    polygon: list[tuple[float, float]], eye_height: float
) -> tuple[tuple[float, float, float], tuple[float, float, float]]:
    """A camera in the room corner farthest from the centroid, looking at the centroid."""
    shape = Polygon(polygon)
    c = shape.centroid
    corner = max(polygon, key=lambda p: (math.dist(p, (c.x, c.y)), p))
    dx, dy = c.x - corner[0], c.y - corner[1]
    dist = math.hypot(dx, dy)
    inset = min(0.3, dist / 2)
    position = (corner[0] + dx / dist * inset, corner[1] + dy / dist * inset, eye_height)
    if not shape.contains(Point(position[0], position[1])):
        rep = shape.representative_point()
        position = (rep.x, rep.y, eye_height)
    target = (c.x, c.y, 0.6)
    if math.dist(position[:2], target[:2]) < 0.2:
        target = (c.x + 1.0, c.y, 0.6)
    return position, target


def _projection(orthographic: bool) -> mujoco.mjtProjection:
    return (
        mujoco.mjtProjection.mjPROJ_ORTHOGRAPHIC
        if orthographic
        else mujoco.mjtProjection.mjPROJ_PERSPECTIVE
    )
