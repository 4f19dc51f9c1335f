"""The geometric first pass of making a house stand: what rests on what, the floor, the rooms.

Read from the scene compiled at its imported poses (every object that is to be dropped with a
free joint):

0. **Children on the floor.** A child (``support`` set) authored at floor level, well under
   every surface of its parent (ProcTHOR puts a baseball bat under a table as the table's
   child), stands on the floor instead.
1. **Supports.** An object without a ``support`` whose asset may stand on objects, whose
   lowest collider point is more than :data:`FLOOR_TOLERANCE_M` above the floor, whose centre
   lies on a receptacle's support surface and whose bottom is no lower than
   :data:`ON_SURFACE_TOLERANCE_M` under that surface now rests on that receptacle (the
   highest such surface): it is dropped there with the receptacle's ``children``.
2. **Floor.** Every other free object without a support is moved up or down so that its lowest
   collider point is at z = 0.
3. **Rooms.** An object whose centre lies outside its room (or outside every room, when it has
   none) is pulled into it: to the nearest point of the room inset by half its footprint (a
   wall object: by 1 cm), and an object without a room gets the room it is in.

Wall- and ceiling-mounted objects keep their height. Objects resting on others are placed by
the drops (:mod:`holomj.physics.standing.drops`), not here.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import mujoco
import numpy as np
from shapely.geometry import Point, Polygon
from shapely.geometry.polygon import orient
from shapely.ops import nearest_points

from holomj.physics.audit import GeomOwners, lowest_points
from holomj.physics.bounds import world_aabbs
from holomj.physics.surfaces_world import (
    WorldSurface,
    footprint_polygon,
    object_yaw,
    world_surfaces,
)
from holomj.spec.assets import AssetMeta
from holomj.spec.scene import SceneObject

FLOOR_TOLERANCE_M = 0.02  # lower than this above the floor: standing on the floor
ON_SURFACE_TOLERANCE_M = 0.05  # a bottom this far under a surface still rests on it
MIN_SURFACE_HEIGHT_M = 0.05  # surfaces lower than this are the floor's business
ROOM_TOLERANCE_M = 0.01  # a centre this far outside its room is pulled in
WALL_INSET_M = 0.01  # a wall object pulled into its room ends this far inside
BOX_TOP_INSET_M = 0.02  # the top of a receptacle without surfaces, inset from its edges
CHILD_ON_FLOOR_M = 0.05  # a child authored this low ...
UNDER_M = 0.15  # ... and this far under every surface of its parent stands on the floor


@dataclass(frozen=True)
class DropSurface:
    """A support surface in the world; ``box_top`` when the asset has no surfaces and the top
    of its bounding box stands in (a drop may then land lower, e.g. on a sofa's seat)."""

    world: WorldSurface
    box_top: bool = False


def receptacle_surfaces(obj: SceneObject, meta: AssetMeta) -> list[DropSurface]:
    """The support surfaces of ``obj`` at its pose; the top of its bounding box when its asset
    has none."""
    surfaces = [DropSurface(s) for s in world_surfaces(obj, meta)]
    if surfaces:
        return surfaces
    sx, sy, sz = obj.scale3
    half = (
        max(meta.size[0] * sx / 2 - BOX_TOP_INSET_M, 0.01),
        max(meta.size[1] * sy / 2 - BOX_TOP_INSET_M, 0.01),
    )
    x, y, z = obj.position
    polygon = orient(footprint_polygon(half, x, y, object_yaw(obj)), 1.0)
    return [DropSurface(WorldSurface(-1, z + meta.size[2] * sz, polygon, math.inf), box_top=True)]


@dataclass
class Prepared:
    """The scene's objects after the first pass, and why each one changed."""

    objects: list[SceneObject]
    reasons: dict[str, list[str]] = field(default_factory=dict)
    rests_on: dict[str, str] = field(default_factory=dict)  # new supports found in step 1

    def note(self, object_id: str, reason: str) -> None:
        """Record a change of ``object_id``."""
        self.reasons.setdefault(object_id, []).append(reason)


def prepare(
    objects: list[SceneObject],
    model: mujoco.MjModel,
    body_of: dict[str, int],
    metas: dict[str, AssetMeta],
    rooms: dict[str, Polygon],
) -> Prepared:
    """Steps 1-3 of the module docstring. ``model`` holds the objects at their poses in
    ``objects`` (``body_of``: object id -> body id); ``metas`` maps object ids to assets."""
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    owners = GeomOwners(model, body_of)
    lowest = dict(zip(owners.names, lowest_points(model, data, owners)))
    free = _free_bodies(model)
    half = _footprint_halves(model, data, owners)
    out = Prepared(list(objects))
    surfaces = {
        o.id: receptacle_surfaces(o, metas[o.id])
        for o in objects
        if metas[o.id].surfaces or "floor" in metas[o.id].placement
    }
    by_id = {o.id: o for o in objects}
    result = []
    for obj in objects:
        is_free = body_of[obj.id] in free
        if is_free and obj.support is not None and math.isfinite(lowest[obj.id]):
            parent = by_id[obj.support]
            heights = [s.world.height for s in receptacle_surfaces(parent, metas[parent.id])]
            low = lowest[obj.id]
            if low <= CHILD_ON_FLOOR_M and min(heights, default=math.inf) >= low + UNDER_M:
                out.note(obj.id, f"stands on the floor, not on {obj.support} (authored there)")
                obj = obj.model_copy(update={"support": None})
        if is_free and obj.support is None and math.isfinite(lowest[obj.id]):
            small = "object" in metas[obj.id].placement
            obj = _rest(obj, lowest[obj.id], surfaces if small else {}, out)
        if obj.support is None:
            obj = _into_room(obj, rooms, half.get(obj.id, 0.0) if is_free else None, out)
        result.append(obj)
    out.objects = result
    return out


def _rest(
    obj: SceneObject, lowest: float, surfaces: dict[str, list[DropSurface]], out: Prepared
) -> SceneObject:
    """Step 1 (on a receptacle) or step 2 (on the floor) for one free object."""
    if lowest > FLOOR_TOLERANCE_M:
        below = _surface_below(obj, lowest, surfaces)
        if below is not None:
            out.rests_on[obj.id] = below
            out.note(obj.id, f"rests on {below} (its footprint lies on it)")
            return obj.model_copy(update={"support": below})
    if abs(lowest) <= 1e-4:
        return obj
    x, y, z = obj.position
    verb = "lowered" if lowest > 0 else "raised"
    out.note(obj.id, f"{verb} {abs(lowest) * 1000:.0f} mm to stand on the floor")
    return obj.model_copy(update={"position": (x, y, round(z - lowest, 6))})


def _surface_below(
    obj: SceneObject, lowest: float, surfaces: dict[str, list[DropSurface]]
) -> str | None:
    point = Point(obj.position[0], obj.position[1])
    best: tuple[float, str] | None = None
    for owner, owned in surfaces.items():
        if owner == obj.id:
            continue
        for surface in owned:
            height = surface.world.height
            if height < MIN_SURFACE_HEIGHT_M or lowest < height - ON_SURFACE_TOLERANCE_M:
                continue
            if not surface.world.polygon.contains(point):
                continue
            if best is None or height > best[0]:
                best = (height, owner)
    return best[1] if best is not None else None


def _into_room(
    obj: SceneObject, rooms: dict[str, Polygon], half: float | None, out: Prepared
) -> SceneObject:
    """Step 3 for one object (``half``: its footprint's smaller half extent, None for an
    object held still)."""
    x, y, z = obj.position
    point = Point(x, y)
    room_id = obj.room
    if room_id is None or room_id not in rooms:
        inside = [rid for rid, poly in rooms.items() if poly.distance(point) <= ROOM_TOLERANCE_M]
        if inside:
            if room_id is None:
                out.note(obj.id, f"assigned to room {inside[0]}")
                return obj.model_copy(update={"room": inside[0]})
            return obj
        room_id = min(rooms, key=lambda rid: rooms[rid].distance(point))
    polygon = rooms[room_id]
    outside = polygon.distance(point)
    if outside <= ROOM_TOLERANCE_M:
        return obj
    inset = WALL_INSET_M if half is None else min(max(half, WALL_INSET_M), 0.5)
    target = _nearest_inside(polygon, point, inset)
    moved = math.hypot(target[0] - x, target[1] - y)
    out.note(obj.id, f"pulled {moved * 1000:.0f} mm into room {room_id} (its centre lay outside)")
    return obj.model_copy(
        update={"position": (round(target[0], 6), round(target[1], 6), z), "room": room_id}
    )


def _nearest_inside(polygon: Polygon, point: Point, inset: float) -> tuple[float, float]:
    for amount in (inset, inset / 2, WALL_INSET_M):
        region = polygon.buffer(-amount, join_style="mitre")
        if not region.is_empty:
            near = nearest_points(region, point)[0]
            return float(near.x), float(near.y)
    rep = polygon.representative_point()
    return float(rep.x), float(rep.y)


def _free_bodies(model: mujoco.MjModel) -> set[int]:
    return {
        int(model.jnt_bodyid[j])
        for j in range(model.njnt)
        if model.jnt_type[j] == mujoco.mjtJoint.mjJNT_FREE
    }


def _footprint_halves(
    model: mujoco.MjModel, data: mujoco.MjData, owners: GeomOwners
) -> dict[str, float]:
    """Per object: half the smaller side of its colliders' world-aligned footprint box."""
    low, high = world_aabbs(model, data)
    halves: dict[str, float] = {}
    for index, name in enumerate(owners.names):
        geoms = np.flatnonzero(owners.collider & (owners.geom_owner == index))
        if geoms.size:
            extent = high[geoms, :2].max(axis=0) - low[geoms, :2].min(axis=0)
            halves[name] = float(extent.min()) / 2.0
    return halves
