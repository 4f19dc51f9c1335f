"""What a room's furnishing reads (the house around it) and what it returns."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

from holomj.spec.plan import PlanObject
from holomj.spec.scene import Door, SceneObject, Window
from holomj.spec.walls import Wall


@dataclass(frozen=True)
class RoomContext:
    """What a room's furnishing needs to know about the house around it."""

    walls: Sequence[Wall]
    doors: Sequence[Door]
    windows: Sequence[Window]
    wall_height: float
    wall_thickness: float


@dataclass
class RoomFurniture:
    """The furnished room: scene objects, receptacles for small objects, and the record."""

    room_id: str
    objects: list[SceneObject] = field(default_factory=list)
    receptacles: list[tuple[str, PlanObject]] = field(default_factory=list)
    picks: list[dict[str, Any]] = field(default_factory=list)
    unplaced: list[dict[str, str]] = field(default_factory=list)
    layout: dict[str, Any] = field(default_factory=dict)
    warnings: list[str] = field(default_factory=list)
    windows: list[Window] = field(default_factory=list)  # the room's windows, after any move
    changes: list[str] = field(default_factory=list)  # what the plan changed to fit, and why
    relations: list[dict[str, Any]] = field(default_factory=list)  # the prompt's, judged
