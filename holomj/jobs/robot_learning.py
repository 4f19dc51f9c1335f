"""The robot-learning files of a compiled scene, as data: the navigation map and the
``objects.json`` record. The floor grid, reachability, geom outlines and the robot's mount are
the robots package's; the formats package writes them out (it does not import robots)."""

from __future__ import annotations

from typing import Any

from holomj.formats.navmap import NavMap, navmap_of
from holomj.formats.objects_json import objects_record
from holomj.mjcf.compiler import CompiledScene
from holomj.robots import shapes
from holomj.robots.attach import MOUNT_BODY
from holomj.robots.occupancy import DEFAULT_CELL_M, DEFAULT_Z_BAND, build_floor_grid
from holomj.robots.reach import DEFAULT_AGENT_RADIUS_M, compute_reach


def build_navmap(
    compiled: CompiledScene,
    *,
    agent_radius: float = DEFAULT_AGENT_RADIUS_M,
    cell: float = DEFAULT_CELL_M,
    z_band: tuple[float, float] = DEFAULT_Z_BAND,
) -> NavMap:
    """The navigation map of a compiled scene at its initial pose (robot included)."""
    grid = build_floor_grid(compiled.model, compiled.scene, cell=cell, z_band=z_band)
    reach = compute_reach(grid, compiled.scene, agent_radius)
    return navmap_of(grid, reach, z_band, compiled.robot)


def objects_json(compiled: CompiledScene) -> dict[str, Any]:
    """The ``objects.json`` data of a compiled scene."""
    return objects_record(compiled, geom_points=shapes.world_points, robot_base_body=MOUNT_BODY)
