"""The navigation map of a scene: a free-floor grid, reachability from the entrance, an image.

``navmap.json``::

    schema_version, cell_m, origin [x, y] (world x/y of the grid's lower-left corner),
    shape [rows, cols] (row r covers y in origin_y + [r, r + 1) * cell_m, column c likewise x),
    agent_radius_m, z_band_m (geoms between these heights are obstacles),
    codes {name: value}, cells (run-length: [[value, count], ...] over rows, row 0 first),
    rooms_index (room id by number; -1 = outside), room_cells (run-length of room numbers),
    entrance {room, door, position}, rooms {id: {reachable, reachable_area_m2,
    walkable_area_m2, floor_area_m2}}, robot (position and footprint radius, when present)

Cell codes: 0 outside every room, 1 obstacle (walls, furniture, the robot), 2 closed door leaf
(passable: doors open), 3 free but closer than ``agent_radius_m`` to an obstacle, 4 walkable but
not reachable from the entrance, 5 reachable. ``navmap.png`` shows the same codes, north up.
"""

from __future__ import annotations

import io
from dataclasses import dataclass
from typing import Any, Protocol

import numpy as np
from PIL import Image

from holomj.errors import FormatError
from holomj.spec.robot import RobotRecord

NAVMAP_JSON = "navmap.json"
NAVMAP_PNG = "navmap.png"
NAVMAP_SCHEMA_VERSION = "1.0"
CODES = {
    "outside": 0,
    "obstacle": 1,
    "door": 2,
    "narrow": 3,
    "unreachable": 4,
    "reachable": 5,
}
COLOURS = {
    0: (48, 48, 52),
    1: (110, 110, 116),
    2: (176, 120, 64),
    3: (214, 210, 190),
    4: (232, 128, 120),
    5: (250, 250, 246),
}
ENTRANCE_COLOUR = (40, 170, 80)
ROBOT_COLOUR = (50, 100, 220)
MIN_IMAGE_PX = 480


class FloorGridView(Protocol):
    """The free-floor grid of a scene (what :class:`holomj.robots.occupancy.FloorGrid` holds)."""

    @property
    def origin(self) -> tuple[float, float]: ...
    @property
    def cell(self) -> float: ...
    @property
    def room_ids(self) -> list[str]: ...
    @property
    def room_index(self) -> np.ndarray: ...
    @property
    def blocked(self) -> np.ndarray: ...
    @property
    def leaves(self) -> np.ndarray: ...
    @property
    def shape(self) -> tuple[int, int]: ...
    @property
    def inside(self) -> np.ndarray: ...
    def centres(self) -> tuple[np.ndarray, np.ndarray]: ...


class EntranceView(Protocol):
    """Where the house is entered (what :class:`holomj.robots.reach.Entrance` holds)."""

    @property
    def room(self) -> str | None: ...
    @property
    def door(self) -> str | None: ...
    @property
    def position(self) -> tuple[float, float] | None: ...


class ReachView(Protocol):
    """Reachability on a floor grid (what :class:`holomj.robots.reach.Reach` holds)."""

    @property
    def agent_radius(self) -> float: ...
    @property
    def entrance(self) -> EntranceView: ...
    @property
    def walkable(self) -> np.ndarray: ...
    @property
    def reachable(self) -> np.ndarray: ...
    def room_stats(self) -> dict[str, dict[str, float | bool]]: ...


@dataclass
class NavMap:
    """A scene's floor grid and its reachability for one agent radius."""

    grid: FloorGridView
    reach: ReachView
    z_band: tuple[float, float]
    robot: dict[str, Any] | None = None

    def codes(self) -> np.ndarray:
        """The cell code raster (see the module docstring), shape ``grid.shape``."""
        grid, reach = self.grid, self.reach
        codes = np.full(grid.shape, CODES["narrow"], dtype=np.uint8)
        codes[reach.walkable] = CODES["unreachable"]
        codes[reach.reachable] = CODES["reachable"]
        codes[~grid.inside] = CODES["outside"]
        codes[grid.leaves] = CODES["door"]
        codes[grid.blocked] = CODES["obstacle"]
        return codes

    def to_json(self) -> dict[str, Any]:
        """The ``navmap.json`` data."""
        grid, reach = self.grid, self.reach
        entrance = reach.entrance
        data: dict[str, Any] = {
            "schema_version": NAVMAP_SCHEMA_VERSION,
            "cell_m": grid.cell,
            "origin": [round(grid.origin[0], 6), round(grid.origin[1], 6)],
            "shape": list(grid.shape),
            "agent_radius_m": reach.agent_radius,
            "z_band_m": list(self.z_band),
            "codes": dict(CODES),
            "cells": rle_encode(self.codes()),
            "rooms_index": list(grid.room_ids),
            "room_cells": rle_encode(grid.room_index),
            "entrance": {
                "room": entrance.room,
                "door": entrance.door,
                "position": list(entrance.position) if entrance.position else None,
            },
            "rooms": reach.room_stats(),
            "image": NAVMAP_PNG,
        }
        if self.robot is not None:
            data["robot"] = self.robot
        return data

    def to_png(self) -> bytes:
        """``navmap.png``: one colour per code, north up, scaled to at least MIN_IMAGE_PX."""
        codes = self.codes()
        palette = np.zeros((256, 3), dtype=np.uint8)
        for code, colour in COLOURS.items():
            palette[code] = colour
        rgb = palette[codes]
        grid = self.grid
        marks = []
        if self.reach.entrance.position is not None:
            marks.append((self.reach.entrance.position, ENTRANCE_COLOUR, 0.25))
        if self.robot is not None:
            marks.append((tuple(self.robot["position"][:2]), ROBOT_COLOUR, 0.12))
        cx, cy = grid.centres()
        for (x, y), colour, radius in marks:
            rgb[np.hypot(cx - x, cy - y) <= radius] = colour
        scale = max(1, -(-MIN_IMAGE_PX // max(grid.shape)))
        image = np.repeat(np.repeat(rgb[::-1], scale, axis=0), scale, axis=1)
        buffer = io.BytesIO()
        Image.fromarray(image, mode="RGB").save(buffer, format="PNG", optimize=False)
        return buffer.getvalue()


def navmap_of(
    grid: FloorGridView, reach: ReachView, z_band: tuple[float, float], robot: RobotRecord | None
) -> NavMap:
    """The navigation map of a scene's floor ``grid`` and ``reach`` (computed for the objects
    between the heights ``z_band``), with the scene's robot marked when it has one."""
    marker = None
    if robot is not None:
        marker = {
            "position": list(robot.position),
            "yaw_deg": robot.yaw_deg,
            "footprint_radius_m": robot.footprint.radius_m,
        }
    return NavMap(grid, reach, z_band, marker)


def rle_encode(values: np.ndarray) -> list[list[int]]:
    """Run-length code of a 2-D integer array, row-major: ``[[value, count], ...]``."""
    flat = np.asarray(values).ravel()
    if flat.size == 0:
        return []
    starts = np.concatenate([[0], np.flatnonzero(flat[1:] != flat[:-1]) + 1])
    counts = np.diff(np.concatenate([starts, [flat.size]]))
    return [[int(flat[s]), int(n)] for s, n in zip(starts, counts)]


def rle_decode(runs: list[list[int]], shape: tuple[int, int]) -> np.ndarray:
    """The array :func:`rle_encode` encoded (int32)."""
    values = np.array([r[0] for r in runs], dtype=np.int32)
    counts = np.array([r[1] for r in runs], dtype=np.int64)
    flat = np.repeat(values, counts)
    if flat.size != shape[0] * shape[1]:
        raise FormatError(
            f"run lengths add up to {flat.size} cells, expected {shape[0] * shape[1]}",
            where=NAVMAP_JSON,
        )
    return flat.reshape(shape)
