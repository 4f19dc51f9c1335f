"""The input of the floor-object layout solver for one room, as validated data.

Room geometry is in metres (world x/y, Z up). Object sizes are in ``size_unit`` ("cm" or "m",
required: the file says which), or in an object's own ``unit`` when it gives one. An object's
``width`` runs left-right and its ``depth`` front-back: at yaw 0 its front faces +X, so it spans
``depth`` along X and ``width`` along Y.

Doors and windows sit on a wall of the room polygon: ``position`` is the centre of the opening
on the wall line (within 5 cm of it).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Annotated, Any, Literal

import numpy as np
from pydantic import Field, model_validator
from shapely.geometry import Polygon, box
from shapely.geometry.polygon import orient

from holomj.errors import SpecError, closest_names
from holomj.layout import geometry as geo
from holomj.layout.constraints import (
    PLACE_KINDS,
    Constraint,
    ObjectName,
    ParsedConstraints,
    normalize_name,
    parse_constraint_text,
)
from holomj.layout.place_relations import (
    ADJACENT_GAP_M,
    place_holds,
    place_reason,
    room_anchors,
)
from holomj.spec.base import FrozenModel, PositiveFloat, Vec2, read_json, validate_model

ON_WALL_TOL_M = 0.05
MAX_OBJECT_SIZE_M = 10.0
MIN_OBJECT_SIZE_M = 0.01


class LayoutDoor(FrozenModel):
    """A door in one of the room's walls.

    ``swing``: "in" (the leaf swings into this room: its sweep is kept free), "out" (it swings
    away), "none" (an open doorway). ``hinge`` is the hinge side seen from inside the room,
    looking at the door.
    """

    id: ObjectName
    position: Vec2
    width: Annotated[float, Field(ge=0.4, le=4.0)] = 0.9
    swing: Literal["in", "out", "none"] = "in"
    hinge: Literal["left", "right"] = "left"


class LayoutWindow(FrozenModel):
    """A window in one of the room's walls; objects taller than ``sill_height`` keep clear."""

    id: ObjectName
    position: Vec2
    width: Annotated[float, Field(ge=0.2, le=6.0)] = 1.2
    sill_height: Annotated[float, Field(ge=0.0, le=4.0)] = 0.9
    height: Annotated[float, Field(gt=0.0, le=4.0)] = 1.2


class LayoutObject(FrozenModel):
    """A floor object to place: its footprint (width left-right, depth front-back) and height.

    An object without a height counts as tall (it must keep clear of windows).
    """

    id: ObjectName
    width: PositiveFloat
    depth: PositiveFloat
    height: PositiveFloat | None = None
    unit: Literal["cm", "m"] | None = Field(
        default=None, description="Unit of this object's sizes; default: the problem's size_unit."
    )
    priority: Annotated[int, Field(ge=1, le=1000)] = Field(
        default=1,
        description="How much placing it matters: the solvers place objects of a higher "
        "priority first and drop lower ones before it (a room's defining furniture: 100).",
    )


class LayoutSettings(FrozenModel):
    """Thresholds of the constraint semantics and the hard rules (all in metres)."""

    grid_m: Annotated[float, Field(ge=0.01, le=0.5)] = Field(
        default=0.05, description="Position grid of the solvers."
    )
    clearance_m: Annotated[float, Field(ge=0.0, le=1.0)] = Field(
        default=0.05, description="Smallest gap between two objects' footprints."
    )
    edge_tolerance_m: Annotated[float, Field(ge=0.0, le=1.0)] = Field(
        default=0.15, description="'edge': the back face is at most this far from a wall."
    )
    middle_gap_m: Annotated[float, Field(ge=0.0, le=5.0)] = Field(
        default=0.5, description="'middle': the footprint keeps at least this far from all walls."
    )
    near_m: Annotated[float, Field(gt=0.0, le=20.0)] = Field(
        default=1.5,
        description="'near': gap between the buffered footprints at most this (Holodeck's "
        "prompt: 150 cm).",
    )
    far_m: Annotated[float, Field(gt=0.0, le=20.0)] = Field(
        default=1.5,
        description="'far': gap between the buffered footprints at least this (150 cm).",
    )
    footprint_buffer_m: Annotated[float, Field(ge=0.0, le=0.5)] = Field(
        default=0.05,
        description="'near'/'far': footprints are grown by this per side before measuring, as "
        "Holodeck's solver grows them.",
    )
    in_front_max_gap_m: Annotated[float, Field(gt=0.0, le=50.0)] = Field(
        default=5.0, description="'in front of'/'behind': gap along the target's axis at most."
    )
    align_tolerance_m: Annotated[float, Field(ge=0.0, le=1.0)] = Field(
        default=0.05,
        description="'center aligned': centres strictly closer than this on x or on y "
        "(Holodeck's test); on the 5 cm grid that is exact alignment.",
    )
    front_clearance_m: Annotated[float, Field(ge=0.0, le=2.0)] = Field(
        default=0.3, description="Hard: the middle of an object's front face keeps this from walls."
    )
    door_clearance_m: Annotated[float, Field(ge=0.0, le=5.0)] = Field(
        default=0.8, description="Hard: depth kept free inside the room in front of every door."
    )
    window_clearance_m: Annotated[float, Field(ge=0.0, le=5.0)] = Field(
        default=0.3, description="Hard: depth in front of a window kept free of tall objects."
    )
    walker_radius_m: Annotated[float, Field(ge=0.05, le=1.0)] = Field(
        default=0.25, description="Hard: a disc this size must travel between every two doors."
    )
    walk_grid_m: Annotated[float, Field(ge=0.02, le=0.5)] = Field(
        default=0.1, description="Cell size of the walkable-path occupancy grid."
    )


class RoomProblem(FrozenModel):
    """One room to furnish: polygon, openings, objects and their constraints."""

    room_id: ObjectName = "room"
    polygon: list[Vec2] = Field(min_length=3, max_length=256)
    size_unit: Literal["cm", "m"] = Field(description="Unit of object sizes: 'cm' or 'm'.")
    doors: list[LayoutDoor] = Field(default_factory=list, max_length=32)
    windows: list[LayoutWindow] = Field(default_factory=list, max_length=64)
    objects: list[LayoutObject] = Field(default_factory=list, max_length=300)
    constraints_text: str | None = Field(
        default=None, max_length=200_000, description="Holodeck's text form, one line per object."
    )
    constraints: list[Constraint] = Field(default_factory=list, max_length=5000)
    settings: LayoutSettings = Field(default_factory=LayoutSettings)

    @model_validator(mode="after")
    def _check(self) -> RoomProblem:
        poly = self.room_polygon
        if not poly.is_valid or poly.area < 1e-3:
            raise SpecError(
                "room polygon is not a simple polygon with area",
                where="polygon",
                fix="list the corners once, in order, without self-crossing",
            )
        ids: dict[str, str] = {}
        for index, obj in enumerate(self.objects):
            where = f"objects[{index}]"
            key = normalize_name(obj.id)
            if key in ids:
                raise SpecError(
                    f"duplicate object id {obj.id!r} (same name as {ids[key]!r} in the text form)",
                    where=f"{where}.id",
                )
            ids[key] = obj.id
            unit = obj.unit or self.size_unit
            scale = 0.01 if unit == "cm" else 1.0
            for name in ("width", "depth", "height"):
                value = getattr(obj, name)
                if value is None:
                    continue
                metres = value * scale
                if metres > MAX_OBJECT_SIZE_M:
                    raise SpecError(
                        f"{name} {value} {unit} is {metres:g} m, more than {MAX_OBJECT_SIZE_M:g} m",
                        where=f"{where}.{name}",
                        fix="sizes in centimetres need size_unit 'cm'" if unit == "m" else None,
                    )
                if metres < MIN_OBJECT_SIZE_M:
                    raise SpecError(
                        f"{name} {value} {unit} is under 1 cm",
                        where=f"{where}.{name}",
                        fix="sizes in metres need size_unit 'm'" if unit == "cm" else None,
                    )
        opening_ids: set[str] = set()
        openings: tuple[tuple[str, Sequence[LayoutDoor | LayoutWindow]], ...] = (
            ("doors", self.doors),
            ("windows", self.windows),
        )
        for kind, items in openings:
            for index, opening in enumerate(items):
                where = f"{kind}[{index}]"
                if opening.id in opening_ids:
                    raise SpecError(f"duplicate opening id {opening.id!r}", where=f"{where}.id")
                opening_ids.add(opening.id)
                _check_on_wall(self.polygon, opening.position, opening.width, f"{where}.position")
        for index, constraint in enumerate(self.constraints):
            for name in ("object", "target"):
                value = getattr(constraint, name)
                if value is None or normalize_name(value) in ids:
                    continue
                close = closest_names(value, [o.id for o in self.objects])
                raise SpecError(
                    f"unknown object {value!r}",
                    where=f"constraints[{index}].{name}",
                    fix=f"did you mean: {close}" if close else "add it to 'objects'",
                )
        return self

    @property
    def room_polygon(self) -> Polygon:
        """The room as a shapely polygon (metres)."""
        return Polygon(self.polygon)

    def object_size_m(self, obj: LayoutObject) -> tuple[float, float, float | None]:
        """``(width, depth, height)`` of ``obj`` in metres (height None when not given)."""
        scale = 0.01 if (obj.unit or self.size_unit) == "cm" else 1.0
        height = obj.height * scale if obj.height is not None else None
        return obj.width * scale, obj.depth * scale, height

    def all_constraints(self) -> ParsedConstraints:
        """The typed constraints followed by those parsed from ``constraints_text``.

        Names in both resolve to the objects' ids; a typed constraint repeated by the text is
        kept once (with a warning).
        """
        ids = [o.id for o in self.objects]
        canonical = {normalize_name(i): i for i in ids}
        result = ParsedConstraints()
        seen = set()
        for constraint in self.constraints:
            fixed = constraint.model_copy(
                update={
                    "object": canonical[normalize_name(constraint.object)],
                    "target": canonical[normalize_name(constraint.target)]
                    if constraint.target is not None
                    else None,
                }
            )
            if fixed.key in seen:
                result.warnings.append(f"duplicate constraint {fixed.text!r} ignored")
                continue
            seen.add(fixed.key)
            result.constraints.append(fixed)
        if self.constraints_text:
            parsed = parse_constraint_text(self.constraints_text, ids)
            result.warnings.extend(parsed.warnings)
            for constraint in parsed.constraints:
                if constraint.key in seen:
                    result.warnings.append(
                        f"constraint {constraint.text!r} is given twice (typed and text); kept once"
                    )
                    continue
                seen.add(constraint.key)
                result.constraints.append(constraint)
        return result


def _check_on_wall(polygon: list[Vec2], position: Vec2, width: float, where: str) -> None:
    best = None
    n = len(polygon)
    for i in range(n):
        (ax, ay), (bx, by) = polygon[i], polygon[(i + 1) % n]
        length = math.hypot(bx - ax, by - ay)
        if length < 1e-9:
            continue
        tx, ty = (bx - ax) / length, (by - ay) / length
        px, py = position[0] - ax, position[1] - ay
        along = px * tx + py * ty
        off = abs(-px * ty + py * tx)
        if -ON_WALL_TOL_M <= along <= length + ON_WALL_TOL_M and off <= ON_WALL_TOL_M:
            if along - width / 2 < -1e-6 or along + width / 2 > length + 1e-6:
                best = best or (
                    f"opening {width:g} m wide does not fit on the wall from {polygon[i]} to "
                    f"{polygon[(i + 1) % n]} ({length:.2f} m) at this position"
                )
                continue
            return
    raise SpecError(
        best or f"{tuple(position)} is not on a wall of the room (within {ON_WALL_TOL_M} m)",
        where=where,
        fix="give the centre of the opening on the wall line",
    )


def load_problem(path: Path) -> RoomProblem:
    """Read and validate a layout problem JSON file (errors name the file and the field)."""
    return problem_from_data(read_json(path), str(path))


def problem_from_data(data: Any, source: str = "<problem>") -> RoomProblem:
    """Validate already-parsed JSON data as a :class:`RoomProblem`."""
    if not isinstance(data, dict):
        raise SpecError("expected a JSON object", where=source)
    return validate_model(RoomProblem, data, source)


# --------------------------------------------------------------------------- prepared form


@dataclass(frozen=True)
class ProblemItem:
    """An object to place, in metres, with its index in the problem."""

    index: int
    id: str
    width: float
    depth: float
    height: float | None
    tall: bool
    priority: int = 1
    windows: tuple[int, ...] = ()  # the windows it must keep clear of (taller than their sill)

    @property
    def size(self) -> tuple[float, float]:
        """``(width, depth)``."""
        return (self.width, self.depth)

    @property
    def area(self) -> float:
        """Footprint area in m²."""
        return self.width * self.depth


class PreparedRoom:
    """Everything both solvers and the post-check share, computed once from a problem.

    Integer grid: a position ``X`` (in grid units) is ``X * grid_m`` metres. An object's
    collision box is its footprint grown by half the clearance on every side and rounded up to
    whole grid units: ``coll_half(i, k)`` gives its half sizes in units.
    """

    def __init__(self, problem: RoomProblem) -> None:
        s = problem.settings
        self.problem = problem
        self.settings = s
        self.room = orient(problem.room_polygon, sign=1.0)
        self.walls = geo.room_walls(problem.polygon)
        parsed = problem.all_constraints()
        self.constraints = parsed.constraints
        self.warnings = list(parsed.warnings)
        self.items: list[ProblemItem] = []
        for index, obj in enumerate(problem.objects):
            width, depth, height = problem.object_size_m(obj)
            blocked = tuple(
                k for k, w in enumerate(problem.windows) if height is None or height > w.sill_height
            )
            self.items.append(
                ProblemItem(
                    index, obj.id, width, depth, height, bool(blocked), obj.priority, blocked
                )
            )
        self.index = {item.id: item.index for item in self.items}
        self.thresholds = geo.LayoutThresholds(
            near=s.near_m,
            far=s.far_m,
            in_front_max_gap=s.in_front_max_gap_m,
            align_tolerance=s.align_tolerance_m,
            edge_tolerance=s.edge_tolerance_m,
            middle_gap=s.middle_gap_m,
            footprint_buffer=s.footprint_buffer_m,
        )
        self.door_zones = []
        for door in problem.doors:
            zone = geo.door_keepout(
                door.position, door.width, door.swing, self.walls, s.door_clearance_m
            )
            swing = geo.door_swing(door.position, door.width, door.swing, door.hinge, self.walls)
            if swing is not None:
                zone = zone.union(swing)
            self.door_zones.append(zone)
        centroid = self.room.centroid
        self.anchors = room_anchors(
            self.walls,
            (float(centroid.x), float(centroid.y)),
            [(w.position, w.width) for w in problem.windows],
            [(d.position, d.width) for d in problem.doors],
        )
        self.window_zones = [
            geo.window_zone(w.position, w.width, self.walls, s.window_clearance_m)
            for w in problem.windows
        ]
        self.grid = s.grid_m
        self.raster = geo.Raster.around(self.room, self.grid)
        self.i0 = round(self.raster.x0 / self.grid)
        self.j0 = round(self.raster.y0 / self.grid)
        self.wall_block = ~self.raster.covered(self.room)
        self.door_block = np.zeros_like(self.wall_block)
        for zone in self.door_zones:
            self.door_block |= self.raster.touched(zone)
        self.window_blocks = [self.raster.touched(zone) for zone in self.window_zones]
        self.window_block = np.zeros_like(self.wall_block)
        for block in self.window_blocks:
            self.window_block |= block
        self.walk = geo.WalkChecker(self.room, self.door_zones, s.walk_grid_m, s.walker_radius_m)
        if self.walk.reason == "doors are not connected even in the empty room":
            self.warnings.append(
                "the doors are not connected even in the empty room: the walkable-path rule "
                "is not applied"
            )

    def windows_block(self, i: int) -> np.ndarray:
        """The cells object ``i`` may not cover because of windows whose sill it is taller
        than."""
        block = np.zeros_like(self.wall_block)
        for k in self.items[i].windows:
            block |= self.window_blocks[k]
        return block

    def units_up(self, metres: float) -> int:
        """``metres`` in whole grid units, rounded up."""
        return math.ceil(metres / self.grid - 1e-9)

    def units_down(self, metres: float) -> int:
        """``metres`` in whole grid units, rounded down."""
        return math.floor(metres / self.grid + 1e-9)

    def coll_half(self, i: int, k: int) -> tuple[int, int]:
        """Half sizes (grid units) of object ``i``'s collision box at yaw index ``k``."""
        item = self.items[i]
        hx, hy = geo.half_extents(item.width, item.depth, k)
        c = self.settings.clearance_m / 2
        return self.units_up(hx + c), self.units_up(hy + c)

    def true_half_down(self, i: int, k: int) -> tuple[int, int]:
        """Half sizes (grid units) of the footprint at yaw index ``k``, rounded down."""
        item = self.items[i]
        hx, hy = geo.half_extents(item.width, item.depth, k)
        return self.units_down(hx), self.units_down(hy)

    def true_half_up(self, i: int, k: int) -> tuple[int, int]:
        """Half sizes (grid units) of the footprint at yaw index ``k``, rounded up."""
        item = self.items[i]
        hx, hy = geo.half_extents(item.width, item.depth, k)
        return self.units_up(hx), self.units_up(hy)

    def footprint(self, i: int, x: float, y: float, k: int) -> tuple[float, ...]:
        """Object ``i``'s footprint rectangle (metres) at centre ``(x, y)`` and yaw index k."""
        item = self.items[i]
        return geo.footprint(x, y, k, item.width, item.depth)

    def metres(self, poses: dict[int, tuple[int, int, int]]) -> dict[int, tuple[float, float, int]]:
        """Grid poses ``{index: (X, Y, k)}`` in metres ``{index: (x, y, k)}``."""
        g = self.grid
        return {i: (x * g, y * g, k) for i, (x, y, k) in poses.items()}

    def footprints(self, poses: dict[int, tuple[int, int, int]]) -> list[tuple[float, ...]]:
        """The footprint rectangles (metres) of the objects at grid ``poses``."""
        return self.footprints_m(self.metres(poses))

    def footprints_m(self, metres: dict[int, tuple[float, float, int]]) -> list[tuple[float, ...]]:
        """The footprint rectangles of the objects at poses in metres ``{index: (x, y, k)}``."""
        return [self.footprint(i, x, y, k) for i, (x, y, k) in metres.items()]

    # ------------------------------------------------------------------ evaluation

    def evaluate(
        self, constraint: Constraint, poses: dict[int, tuple[float, float, int]]
    ) -> tuple[bool, str]:
        """Whether ``constraint`` holds for poses ``{index: (x_m, y_m, yaw_index)}``, and why."""
        i = self.index[constraint.object]
        if i not in poses:
            return False, f"{constraint.object} is not placed"
        x, y, k = poses[i]
        item = self.items[i]
        th = self.thresholds
        if constraint.kind == "edge":
            ok = bool(geo.edge_holds(x, y, k, item.size, self.walls, th.edge_tolerance))
            return ok, (
                f"back within {th.edge_tolerance:g} m of a wall behind it"
                if ok
                else f"back not within {th.edge_tolerance:g} m of a wall behind it"
            )
        if constraint.kind in PLACE_KINDS:
            ok = bool(
                place_holds(constraint.kind, x, y, k, item.size, self.anchors, th.edge_tolerance)
            )
            return ok, place_reason(constraint.kind, ok, self.anchors)
        if constraint.kind == "middle":
            rect = self.footprint(i, x, y, k)
            dist = float(self.room.exterior.distance(box(*rect)))
            ok = geo.middle_holds(rect, self.room, th.middle_gap)
            return ok, f"{dist:.2f} m from the nearest wall (middle needs {th.middle_gap:g} m)"
        assert constraint.target is not None
        j = self.index[constraint.target]
        if j not in poses:
            return False, f"target {constraint.target} is not placed"
        xt, yt, kt = poses[j]
        target = self.items[j]
        ok = bool(
            geo.relation_holds(constraint.kind, x, y, k, item.size, xt, yt, kt, target.size, th)
        )
        if constraint.kind == "adjacent_to":
            gx, gy = geo.rect_gaps(self.footprint(i, x, y, k), self.footprint(j, xt, yt, kt))
            gap = math.hypot(max(gx, 0.0), max(gy, 0.0))
            return ok, f"gap {gap:.2f} m between footprints (needs <= {ADJACENT_GAP_M:g} m)"
        if constraint.kind in ("near", "far"):
            gx, gy = geo.rect_gaps(self.footprint(i, x, y, k), self.footprint(j, xt, yt, kt))
            gap = math.hypot(max(gx, 0.0), max(gy, 0.0))
            buffered = max(gap - 2 * th.footprint_buffer, 0.0)
            limit = th.near if constraint.kind == "near" else th.far
            sign = "<=" if constraint.kind == "near" else ">="
            why = f"gap {buffered:.2f} m between buffered footprints (needs {sign} {limit:g} m)"
            return ok, why
        return ok, "holds" if ok else "does not hold"
