"""Floors, ceilings, the ground plane and walls split around their openings."""

from __future__ import annotations

import math
from dataclasses import dataclass

import mujoco
import numpy as np

from holomj.mjcf import names
from holomj.mjcf.context import BuildContext
from holomj.mjcf.geometry import clean, polygon_slab, yaw_quat
from holomj.mjcf.opening_geometry import PlacedOpening
from holomj.spec.walls import Wall

FLOOR_THICKNESS = 0.02  # visual slab below z = 0
CEILING_THICKNESS = 0.02
_MIN_PIECE = 1e-3  # wall pieces thinner or shorter than this are dropped


def add_ground(ctx: BuildContext) -> None:
    """One collision plane at z = 0 under the whole house (floors are visual slabs)."""
    (x0, x1), (y0, y1) = ctx.extent()
    margin = 5.0
    ctx.spec.worldbody.add_geom(
        name=names.ground(),
        default=ctx.default("ground"),
        type=mujoco.mjtGeom.mjGEOM_PLANE,
        pos=clean([(x0 + x1) / 2, (y0 + y1) / 2, 0.0]),
        size=clean([(x1 - x0) / 2 + margin, (y1 - y0) / 2 + margin, 0.1]),
    )


def add_floors_and_ceilings(ctx: BuildContext) -> None:
    """A textured visual slab per room (any simple polygon), and ceilings if asked for.

    Floor and ceiling slabs carry texture coordinates in units of their material's tile, so a
    texture (the material's own, or the procedural pattern its name calls for: planks for a
    wood floor, tiles, carpet...) keeps its physical size.
    """
    for room in ctx.scene.rooms:
        _add_slab(
            ctx,
            mesh_name=names.floor_mesh(room.id),
            geom_name=names.floor_geom(room.id),
            points=room.polygon,
            bottom=-FLOOR_THICKNESS,
            top=0.0,
            tile=ctx.texture_tile(room.floor_material),
            material=ctx.scene_material(room.floor_material, uv=True),
            default="visual",
            info=f"floor of room {room.id}",
        )
        if ctx.scene.ceilings:
            _add_slab(
                ctx,
                mesh_name=names.ceiling_mesh(room.id),
                geom_name=names.ceiling_geom(room.id),
                points=room.polygon,
                bottom=ctx.scene.wall_height,
                top=ctx.scene.wall_height + CEILING_THICKNESS,
                tile=ctx.texture_tile(room.ceiling_material),
                material=ctx.scene_material(room.ceiling_material, uv=True),
                default="ceiling",
                info=f"ceiling of room {room.id}",
            )


def _add_slab(
    ctx: BuildContext,
    *,
    mesh_name: str,
    geom_name: str,
    points: list[tuple[float, float]],
    bottom: float,
    top: float,
    tile: float,
    material: str,
    default: str,
    info: str,
) -> None:
    slab = polygon_slab(points, bottom, top, tile)
    mesh = ctx.spec.add_mesh(
        name=mesh_name,
        uservert=clean(slab.vertices.reshape(-1)),
        userface=[int(i) for i in slab.faces.reshape(-1)],
        usertexcoord=clean(slab.texcoords.reshape(-1)),
        inertia=mujoco.mjtMeshInertia.mjMESH_INERTIA_SHELL,
    )
    mesh.info = info
    geom = ctx.spec.worldbody.add_geom(
        name=geom_name,
        default=ctx.default(default),
        type=mujoco.mjtGeom.mjGEOM_MESH,
        meshname=mesh_name,
        material=material,
    )
    geom.info = info


@dataclass(frozen=True)
class _Span:
    """A stretch of wall [t0, t1] that is solid between z0 and z1."""

    t0: float
    t1: float
    z0: float
    z1: float


def wall_spans(length: float, height: float, openings: list[PlacedOpening]) -> list[_Span]:
    """Solid boxes of a wall once its openings are cut out (sorted, non-overlapping)."""
    spans: list[_Span] = []
    cursor = 0.0
    for opening in sorted(openings, key=lambda o: o.t0):
        if opening.t0 - cursor > _MIN_PIECE:
            spans.append(_Span(cursor, opening.t0, 0.0, height))
        if opening.bottom > _MIN_PIECE:
            spans.append(_Span(opening.t0, opening.t1, 0.0, opening.bottom))
        if height - opening.top > _MIN_PIECE:
            spans.append(_Span(opening.t0, opening.t1, opening.top, height))
        cursor = max(cursor, opening.t1)
    if length - cursor > _MIN_PIECE:
        spans.append(_Span(cursor, length, 0.0, height))
    return spans


def add_walls(
    ctx: BuildContext, walls: list[Wall], openings: dict[str, list[PlacedOpening]]
) -> None:
    """Boxes for every wall, split around doors and windows.

    An interior wall is two slabs of half the thickness, one per room, so each side wears its
    own room's wall material. An exterior wall is one slab grown outwards from the room edge and
    lengthened at convex corners so the house is closed.
    """
    scene = ctx.scene
    for wall in walls:
        spans = wall_spans(wall.length, scene.wall_height, openings.get(wall.id, []))
        ext0, ext1 = _end_extensions(
            wall, walls, scene.wall_thickness, scene.exterior_wall_thickness
        )
        if wall.exterior:
            thick = scene.exterior_wall_thickness
            sides: list[tuple[str | None, tuple[float, float], float]] = [
                (wall.rooms[0], _scale(wall.outward, thick / 2), thick)
            ]
        else:
            half = scene.wall_thickness / 2
            right_room = next(r for r in wall.rooms if r != wall.left_room)
            sides = [
                (wall.left_room, _scale(wall.normal, half / 2), half),
                (right_room, _scale(wall.normal, -half / 2), half),
            ]
        for index, span in enumerate(spans):
            t0 = span.t0 - (ext0 if span.t0 <= _MIN_PIECE else 0.0)
            t1 = span.t1 + (ext1 if span.t1 >= wall.length - _MIN_PIECE else 0.0)
            mid = wall.point_at((t0 + t1) / 2)
            for room_id, offset, thickness in sides:
                geom = ctx.spec.worldbody.add_geom(
                    name=names.wall_piece(wall.id, index, str(room_id)),
                    default=ctx.default("structure"),
                    type=mujoco.mjtGeom.mjGEOM_BOX,
                    pos=clean([mid[0] + offset[0], mid[1] + offset[1], (span.z0 + span.z1) / 2]),
                    quat=clean(yaw_quat(wall.yaw)),
                    size=clean([(t1 - t0) / 2, thickness / 2, (span.z1 - span.z0) / 2]),
                    material=ctx.scene_material(
                        ctx.scene.room(str(room_id)).wall_material,
                        face=(t1 - t0, span.z1 - span.z0),
                    ),
                )
                geom.info = f"{wall.id} between {' and '.join(wall.rooms)}"


def _scale(v: tuple[float, float], k: float) -> tuple[float, float]:
    return (v[0] * k, v[1] * k)


def _end_extensions(
    wall: Wall, walls: list[Wall], interior: float, exterior: float
) -> tuple[float, float]:
    """How far to lengthen a wall at its start and end so corners close."""
    if not wall.exterior:
        return interior / 2, interior / 2
    result = []
    for point, along in ((wall.start, -1.0), (wall.end, 1.0)):
        extend = 0.0
        direction = np.array(wall.direction) * along
        for other in walls:
            if other is wall or not other.exterior:
                continue
            if min(math.dist(point, other.start), math.dist(point, other.end)) > 1e-6:
                continue
            # Convex corner: the neighbour's outside lies ahead of this wall's end.
            if float(np.dot(direction, other.outward)) > 1e-6:
                extend = exterior
        result.append(extend)
    return result[0], result[1]
