"""Doors and windows: where they sit on their walls, frames, glass and hinged door leaves."""

from __future__ import annotations

import math
from dataclasses import dataclass

import mujoco
import numpy as np

from holomj.mjcf import names
from holomj.mjcf.context import BuildContext
from holomj.mjcf.geometry import clean, yaw_quat
from holomj.spec.scene import Door, Window
from holomj.spec.walls import Wall, find_wall_for_opening

FRAME_WIDTH = 0.05  # jamb and header width, metres
FRAME_DEPTH_EXTRA = 0.02  # frames stand this much proud of the wall faces
LEAF_THICKNESS = 0.04
LEAF_GAP = 0.008  # clearance between leaf and frame or floor
LEAF_DENSITY = 450.0  # kg/m^3: a solid-core wooden door leaf
HINGE_DAMPING = 2.0
HINGE_FRICTIONLOSS = 0.3  # holds a leaf still against tiny disturbances
GLASS_THICKNESS = 0.01
HANDLE_HEIGHT = 1.0


@dataclass(frozen=True)
class PlacedOpening:
    """A door or window located on its wall: it spans [t0, t1] along the wall, bottom to top."""

    opening: Door | Window
    wall: Wall
    t0: float
    t1: float
    bottom: float
    top: float
    thickness: float  # of the wall it pierces
    wall_offset: float  # signed offset of the wall's centre plane from the wall line (normal)

    @property
    def centre_t(self) -> float:
        """Distance of the centre along the wall."""
        return (self.t0 + self.t1) / 2

    def world(self, t: float, normal_offset: float) -> tuple[float, float]:
        """World x/y of the point ``t`` along the wall, ``normal_offset`` off its centre plane."""
        x, y = self.wall.point_at(t)
        nx, ny = self.wall.normal
        off = self.wall_offset + normal_offset
        return (x + nx * off, y + ny * off)


def place_openings(ctx: BuildContext, walls: list[Wall]) -> dict[str, list[PlacedOpening]]:
    """Every door and window of the scene, grouped by wall id."""
    scene = ctx.scene
    placed: dict[str, list[PlacedOpening]] = {}
    for opening in scene.openings:
        if isinstance(opening, Door):
            width, bottom = opening.effective_width, 0.0
            top = scene.wall_height if opening.kind == "open" else opening.height
        else:
            width, bottom, top = (
                opening.width,
                opening.base_height,
                opening.base_height + opening.height,
            )
        wall, t = find_wall_for_opening(walls, opening.rooms, opening.position, width)
        if wall.exterior:
            thickness = scene.exterior_wall_thickness
            outward_sign = 1.0 if wall.left_room is None else -1.0
            offset = outward_sign * thickness / 2
        else:
            thickness, offset = scene.wall_thickness, 0.0
        placed.setdefault(wall.id, []).append(
            PlacedOpening(
                opening, wall, t - width / 2, t + width / 2, bottom, top, thickness, offset
            )
        )
    return placed


def add_openings(ctx: BuildContext, placed: dict[str, list[PlacedOpening]]) -> None:
    """Frames, glass and door leaves for every placed opening."""
    for wall_id in sorted(placed):
        for item in placed[wall_id]:
            if isinstance(item.opening, Window):
                _add_window(ctx, item)
            elif item.opening.kind != "open":
                _add_door_frame(ctx, item)
                if item.opening.kind == "doorway":
                    _add_door_leaves(ctx, item)


def _box(
    ctx: BuildContext,
    body: mujoco.MjsBody,
    name: str,
    centre: tuple[float, float, float],
    yaw: float,
    half: tuple[float, float, float],
    material: str,
    default: str,
    info: str,
) -> mujoco.MjsGeom:
    geom = body.add_geom(
        name=name,
        default=ctx.default(default),
        type=mujoco.mjtGeom.mjGEOM_BOX,
        pos=clean(centre),
        quat=clean(yaw_quat(yaw)),
        size=clean(half),
        material=material,
    )
    geom.info = info
    return geom


def _frame_pieces(item: PlacedOpening) -> list[tuple[str, float, float, float, float]]:
    """(part, t0, t1, z0, z1) of the jambs, the header and (windows) the sill."""
    fw = FRAME_WIDTH
    pieces = [
        ("frame_left", item.t0, item.t0 + fw, item.bottom, item.top),
        ("frame_right", item.t1 - fw, item.t1, item.bottom, item.top),
        ("frame_top", item.t0 + fw, item.t1 - fw, item.top - fw, item.top),
    ]
    if item.bottom > 0:
        pieces.append(("frame_bottom", item.t0 + fw, item.t1 - fw, item.bottom, item.bottom + fw))
    return pieces


def _add_frame(ctx: BuildContext, item: PlacedOpening, material: str) -> None:
    depth = item.thickness + 2 * FRAME_DEPTH_EXTRA
    for part, t0, t1, z0, z1 in _frame_pieces(item):
        x, y = item.world((t0 + t1) / 2, 0.0)
        _box(
            ctx,
            ctx.spec.worldbody,
            names.opening_part(item.opening.id, part),
            (x, y, (z0 + z1) / 2),
            item.wall.yaw,
            ((t1 - t0) / 2, depth / 2, (z1 - z0) / 2),
            material,
            "visual",
            f"{part} of {item.opening.id}",
        )


def _add_door_frame(ctx: BuildContext, item: PlacedOpening) -> None:
    _add_frame(ctx, item, ctx.scene_material("window_frame"))


def _add_window(ctx: BuildContext, item: PlacedOpening) -> None:
    window = item.opening
    assert isinstance(window, Window)
    _add_frame(ctx, item, ctx.scene_material("window_frame"))
    inner = (
        item.t0 + FRAME_WIDTH,
        item.t1 - FRAME_WIDTH,
        item.bottom + FRAME_WIDTH,
        item.top - FRAME_WIDTH,
    )
    x, y = item.world(item.centre_t, 0.0)
    centre = (x, y, (inner[2] + inner[3]) / 2)
    half = ((inner[1] - inner[0]) / 2, GLASS_THICKNESS / 2, (inner[3] - inner[2]) / 2)
    glass = _box(
        ctx,
        ctx.spec.worldbody,
        names.opening_part(window.id, "glass"),
        centre,
        item.wall.yaw,
        half,
        ctx.scene_material("glass"),
        "structure",
        f"glass of {window.kind} window {window.id}",
    )
    glass.group = 2
    # Sliders get a vertical mullion, hung windows a horizontal meeting rail.
    if window.kind in ("slider", "hung"):
        depth = item.thickness / 2 + FRAME_DEPTH_EXTRA
        if window.kind == "slider":
            bar = (FRAME_WIDTH / 2, depth / 2, half[2])
        else:
            bar = (half[0], depth / 2, FRAME_WIDTH / 2)
        _box(
            ctx,
            ctx.spec.worldbody,
            names.opening_part(window.id, "mullion"),
            centre,
            item.wall.yaw,
            bar,
            ctx.scene_material("window_frame"),
            "visual",
            f"mullion of {window.kind} window {window.id}",
        )


def _add_door_leaves(ctx: BuildContext, item: PlacedOpening) -> None:
    """One hinged leaf (single) or two (double), swinging into ``opens_into`` up to 90°."""
    door = item.opening
    assert isinstance(door, Door)
    into = door.opens_into or door.rooms[0]
    normal = np.array(item.wall.normal)
    # Unit vector from the wall into the room the door opens into.
    into_dir = normal if item.wall.left_room == into else -normal
    direction = np.array(item.wall.direction)
    inner_t0, inner_t1 = item.t0 + FRAME_WIDTH + LEAF_GAP, item.t1 - FRAME_WIDTH - LEAF_GAP
    # Seen from the room it opens into, "left" is to the viewer's left facing the door.
    facing = -into_dir
    viewer_left = np.array([-facing[1], facing[0]])
    left_is_start = float(np.dot(viewer_left, -direction)) > 0
    hinge_at_start = left_is_start == (door.hinge_side == "left")
    if door.leaves == "double":
        mid = (inner_t0 + inner_t1) / 2
        leaves = [(inner_t0, mid - LEAF_GAP / 2, True), (mid + LEAF_GAP / 2, inner_t1, False)]
    else:
        leaves = [(inner_t0, inner_t1, hinge_at_start)]
    height = item.top - FRAME_WIDTH - 2 * LEAF_GAP
    # The leaf sits flush with the wall face on the opening side.
    face_offset = float(np.dot(into_dir, normal)) * (item.thickness / 2)
    material = ctx.scene_material(door.material)
    handle_material = ctx.scene_material("door_handle")
    for index, (t0, t1, at_start) in enumerate(leaves):
        width = t1 - t0
        hinge_t = t0 if at_start else t1
        leaf_dir = direction if at_start else -direction
        hinge_xy = item.world(hinge_t, face_offset)
        yaw = math.atan2(leaf_dir[1], leaf_dir[0])
        # Body frame: x along the closed leaf, y = x rotated +90°.
        body_y = np.array([-leaf_dir[1], leaf_dir[0]])
        into_local_y = float(np.dot(into_dir, body_y))
        body = ctx.spec.worldbody.add_body(
            name=names.door_leaf_body(door.id, index),
            pos=clean([hinge_xy[0], hinge_xy[1], LEAF_GAP]),
            quat=clean(yaw_quat(yaw)),
        )
        body.info = f"leaf {index} of door {door.id}"
        swing = math.pi / 2
        joint = body.add_joint(
            name=names.door_hinge(door.id, index),
            type=mujoco.mjtJoint.mjJNT_HINGE,
            axis=[0.0, 0.0, 1.0],
            limited=mujoco.mjtLimited.mjLIMITED_TRUE,
            range=[0.0, swing] if into_local_y > 0 else [-swing, 0.0],
            damping=HINGE_DAMPING,
            frictionloss=HINGE_FRICTIONLOSS,
            armature=0.01,
        )
        joint.info = f"hinge of door {door.id}"
        # Closed leaf: from the hinge along +x, its thickness on the wall side of the face.
        leaf = body.add_geom(
            name=names.opening_part(door.id, f"panel_{index}"),
            default=ctx.default("structure"),
            type=mujoco.mjtGeom.mjGEOM_BOX,
            pos=clean([width / 2, -into_local_y * LEAF_THICKNESS / 2, height / 2]),
            size=clean([width / 2, LEAF_THICKNESS / 2, height / 2]),
            material=material,
            density=LEAF_DENSITY,
        )
        leaf.info = f"leaf {index} of door {door.id}"
        for side, sign in (("in", 1.0), ("out", -1.0)):
            y = -into_local_y * LEAF_THICKNESS / 2 + sign * (LEAF_THICKNESS / 2 + 0.03)
            handle = body.add_geom(
                name=names.opening_part(door.id, f"handle_{index}_{side}"),
                default=ctx.default("visual"),
                type=mujoco.mjtGeom.mjGEOM_BOX,
                pos=clean([width - 0.08, y, HANDLE_HEIGHT - LEAF_GAP]),
                size=[0.06, 0.01, 0.012],
                material=handle_material,
            )
            handle.info = f"handle of door {door.id}"
