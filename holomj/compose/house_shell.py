"""The shell of a planned house: rooms packed into a floor plan, doors, windows, materials.

Rooms come from :func:`holomj.layout.floorplan.plan_floor` (rectangles in rows), doors from
:func:`holomj.layout.door_window_placement.place_doors` (a tree grown from the entrance),
windows from :func:`holomj.layout.door_window_placement.place_windows`: rooms whose plan leaves
the window count open get their type's default, the others exactly what the plan says. Each
draws from its own stage generator.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

from holomj.layout.door_window_placement import (
    WindowKind,
    WindowRequest,
    place_doors,
    place_windows,
)
from holomj.layout.floorplan import RoomRequest, plan_floor
from holomj.seeds import stage_rng
from holomj.spec.materials import Material
from holomj.spec.plan import PlanRoom, ScenePlan
from holomj.spec.scene import Door, Room, Window

DEFAULT_MIN_SIDE_M = 2.5
DEFAULT_MAX_SIDE_M = 8.0
MAX_SIDE_M = 40.0

# Picks a material for a description on a surface ("floor", "wall", "ceiling").
MaterialPicker = Callable[[str, str], tuple[str, Material]]


@dataclass
class HouseShell:
    """Rooms (with materials), doors and windows of a house, before any furniture."""

    rooms: list[Room]
    doors: list[Door]
    windows: list[Window]
    entrance: str
    materials: dict[str, Material] = field(default_factory=dict)
    material_choices: dict[str, dict[str, str]] = field(default_factory=dict)
    warnings: list[str] = field(default_factory=list)


def room_request(room: PlanRoom) -> RoomRequest:
    """The floor planner's request for a plan room; side limits widen to admit its size."""
    lo, hi = DEFAULT_MIN_SIDE_M, DEFAULT_MAX_SIDE_M
    if room.size is not None:
        lo = max(1.0, min(lo, *room.size))
        hi = min(MAX_SIDE_M, max(hi, *room.size))
    elif room.area_m2 is not None:
        lo = max(1.0, min(lo, math.sqrt(room.area_m2) * 0.75))
        hi = min(MAX_SIDE_M, max(hi, math.sqrt(room.area_m2) * 1.3))
    return RoomRequest(
        id=room.id,
        type=room.type,
        size=room.size,
        area_m2=room.area_m2,
        adjacent_to=room.adjacent_to,
        min_side=lo,
        max_side=hi,
    )


def build_shell(plan: ScenePlan, seed: int, pick_material: MaterialPicker | None) -> HouseShell:
    """Floor plan, doors, windows and (when ``pick_material`` is given) materials of ``plan``."""
    floor = plan_floor(
        [room_request(r) for r in plan.rooms],
        stage_rng(seed, "floor"),
        entrance_room=plan.entrance_room,
    )
    warnings = list(floor.warnings)
    rooms = floor.rooms
    doors = place_doors(
        rooms, stage_rng(seed, "doors"), entrance=floor.entrance, wall_height=plan.wall_height
    )
    windows = _windows(plan, rooms, doors, seed, warnings)
    shell = HouseShell(rooms, doors, windows, floor.entrance, warnings=warnings)
    if pick_material is not None:
        _assign_materials(plan, shell, pick_material)
    return shell


def _windows(
    plan: ScenePlan, rooms: list[Room], doors: list[Door], seed: int, warnings: list[str]
) -> list[Window]:
    """Rooms with a planned count get exactly that; the others their type's default count, in
    the planned kind when the plan names one (one placement call per kind)."""
    explicit = {
        r.id: WindowRequest(count=r.windows.count, kind=r.windows.kind)
        for r in plan.rooms
        if r.windows.count is not None
    }
    by_kind: dict[WindowKind | None, set[str]] = {}
    for r in plan.rooms:
        if r.windows.count is None:
            by_kind.setdefault(r.windows.kind, set()).add(r.id)
    windows: list[Window] = []
    for kind in sorted(by_kind, key=lambda k: k or ""):
        group = by_kind[kind]
        missed: list[str] = []
        found = place_windows(
            rooms,
            doors,
            stage_rng(seed, "windows", kind or "default"),
            kind=kind,
            wall_height=plan.wall_height,
            report=missed,
        )
        windows.extend(w for w in found if w.rooms[0] in group)
        warnings.extend(m for m in missed if any(m.startswith(f"room {r!r}:") for r in group))
    if explicit:
        windows.extend(
            place_windows(
                rooms,
                doors,
                stage_rng(seed, "windows", "explicit"),
                per_room=explicit,
                wall_height=plan.wall_height,
                report=warnings,
            )
        )
    order = {r.id: i for i, r in enumerate(rooms)}
    return sorted(windows, key=lambda w: (order[w.rooms[0]], w.id))


def _assign_materials(plan: ScenePlan, shell: HouseShell, pick: MaterialPicker) -> None:
    rooms = []
    for room in shell.rooms:
        wanted = plan.room(room.id)
        chosen: dict[str, str] = {}
        for surface, description in (
            ("floor", wanted.floor_material),
            ("wall", wanted.wall_material),
            ("ceiling", wanted.ceiling_material),
        ):
            name, material = pick(description, surface)
            shell.materials[name] = material
            chosen[surface] = name
        shell.material_choices[room.id] = chosen
        rooms.append(
            room.model_copy(
                update={
                    "floor_material": chosen["floor"],
                    "wall_material": chosen["wall"],
                    "ceiling_material": chosen["ceiling"],
                }
            )
        )
    shell.rooms = rooms
