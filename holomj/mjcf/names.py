"""Every MJCF element name holomj generates is made here.

Objects own the prefix ``f"{object_id}/"``; structure lives under ``structure/``, openings under
their id, shared assets (meshes, materials, textures) under ``asset/<asset id>/`` and
``material/<name>``.
"""

from __future__ import annotations

import hashlib
import re

_UNSAFE = re.compile(r"[^A-Za-z0-9_.\-]")


def object_body(object_id: str) -> str:
    """The body of a scene object."""
    return f"{object_id}/body"


def object_joint(object_id: str) -> str:
    """The free joint of a dynamic object."""
    return f"{object_id}/freejoint"


def object_visual(object_id: str, index: int) -> str:
    """The ``index``-th visual geom of an object."""
    return f"{object_id}/visual_{index}"


def object_collision(object_id: str, index: int) -> str:
    """The ``index``-th collision geom of an object."""
    return f"{object_id}/collision_{index}"


def asset_prefix(asset_id: str, scale: tuple[float, float, float]) -> str:
    """Prefix of mesh/material names of one asset at one scale."""
    if all(abs(s - 1.0) < 1e-12 for s in scale):
        return f"asset/{asset_id}"
    return f"asset/{asset_id}@" + "x".join(f"{s:.6g}" for s in scale)


def asset_visual_mesh(prefix: str, index: int) -> str:
    """A visual mesh of an asset at one scale (``prefix`` from :func:`asset_prefix`)."""
    return f"{prefix}/visual_{index}"


def asset_collision_mesh(prefix: str, index: int) -> str:
    """A collision hull mesh of an asset at one scale."""
    return f"{prefix}/collision_{index}"


def asset_material(asset_id: str, index: int) -> str:
    """The material of an asset's ``index``-th visual part (shared by all scales)."""
    return f"asset/{asset_id}/material_{index}"


def asset_texture(asset_id: str, index: int) -> str:
    """The texture of an asset's ``index``-th visual part."""
    return f"asset/{asset_id}/texture_{index}"


def asset_folder(asset_id: str) -> str:
    """A file-system-safe folder name for an asset's files under ``assets/``."""
    safe = _UNSAFE.sub("_", asset_id)
    if safe != asset_id:
        safe = f"{safe}-{hashlib.sha1(asset_id.encode()).hexdigest()[:8]}"
    return safe


def scene_material(name: str) -> str:
    """A scene (room, door, window) material."""
    return f"material/{name}"


def scene_uv_material(name: str) -> str:
    """A textured scene material as worn by meshes with their own texture coordinates (slabs)."""
    return f"material/{name}/uv"


def scene_face_material(name: str, width: float, height: float) -> str:
    """A textured scene material as worn by boxes whose large faces are ``width`` x ``height``
    metres (wall pieces)."""
    return f"material/{name}/{width:g}x{height:g}"


def scene_texture(name: str) -> str:
    """The texture of a scene material."""
    return f"texture/{name}"


def texture_file(name: str) -> str:
    """Where a scene material's texture image goes, relative to ``assets/``."""
    return f"textures/{asset_folder(name)}.png"


def floor_mesh(room_id: str) -> str:
    """The floor slab mesh of a room."""
    return f"structure/floor/{room_id}"


def floor_geom(room_id: str) -> str:
    """The floor slab geom of a room."""
    return f"structure/floor/{room_id}"


def ceiling_geom(room_id: str) -> str:
    """The ceiling slab geom of a room."""
    return f"structure/ceiling/{room_id}"


def ceiling_mesh(room_id: str) -> str:
    """The ceiling slab mesh of a room."""
    return f"structure/ceiling/{room_id}"


def ground() -> str:
    """The collision plane under all floors."""
    return "structure/ground"


def wall_piece(wall_id: str, index: int, side: str) -> str:
    """One box of a wall split around its openings; ``side`` names the room it faces."""
    return f"structure/{wall_id}/{index}/{side}"


def opening_part(opening_id: str, part: str) -> str:
    """A part (frame, glass, leaf, handle) of a door or window."""
    return f"{opening_id}/{part}"


def door_leaf_body(door_id: str, index: int) -> str:
    """The hinged body of a door leaf."""
    return f"{door_id}/leaf_{index}"


def door_hinge(door_id: str, index: int) -> str:
    """The hinge joint of a door leaf."""
    return f"{door_id}/hinge_{index}"


def light(light_id: str) -> str:
    """A light."""
    return f"light/{light_id}"


def camera(camera_id: str) -> str:
    """A user camera."""
    return f"camera/{camera_id}"


def room_camera(room_id: str) -> str:
    """The automatic camera of a room."""
    return f"camera/room/{room_id}"


OVERVIEW_CAMERA = "camera/overview"


# --- articulated objects (doors, drawers, lids of furniture and appliances) ------------------
def object_part_body(object_id: str, part: str) -> str:
    """The body of a moving part (door, drawer, lid) of an articulated object."""
    return f"{object_id}/{part}"


def object_part_joint(object_id: str, joint: str) -> str:
    """The hinge or slide joint of a moving part of an articulated object."""
    return f"{object_id}/{joint}"


def object_part_visual(object_id: str, part: str, index: int) -> str:
    """The ``index``-th visual geom of a moving part."""
    return f"{object_id}/{part}/visual_{index}"


def object_part_collision(object_id: str, part: str, index: int) -> str:
    """The ``index``-th collision geom of a moving part."""
    return f"{object_id}/{part}/collision_{index}"


def object_part_handle(object_id: str, part: str) -> str:
    """The site at the grasp pose of a moving part's handle."""
    return f"{object_id}/{part}/handle"


def asset_part_visual_mesh(prefix: str, part: str, index: int) -> str:
    """A visual mesh of a moving part of an asset at one scale."""
    return f"{prefix}/{part}/visual_{index}"


def asset_part_collision_mesh(prefix: str, part: str, index: int) -> str:
    """A collision hull mesh of a moving part of an asset at one scale."""
    return f"{prefix}/{part}/collision_{index}"


def asset_part_material(asset_id: str, part: str, index: int) -> str:
    """The material of a moving part's ``index``-th visual part."""
    return f"asset/{asset_id}/{part}/material_{index}"


def asset_part_texture(asset_id: str, part: str, index: int) -> str:
    """The texture of a moving part's ``index``-th visual part."""
    return f"asset/{asset_id}/{part}/texture_{index}"
