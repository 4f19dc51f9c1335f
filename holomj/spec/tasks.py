"""Robot tasks as data (``tasks.json``, ``holomj schema task``).

A task names what should become true in a scene folder, in terms of ``objects.json``: object ids,
joint names, surface indices and room ids. Whether it is true is decided by a predicate on the
MuJoCo state (:mod:`holomj.tasks`), so any policy, in any framework, can be checked.

- ``navigate``: the robot's base within ``radius_m`` of an object (or inside a room), facing it
  within ``facing_deg``;
- ``open`` / ``close``: an articulated part's joint past ``fraction`` of its range from the closed
  value (open), or back below it (close), and staying there for ``hold_s``;
- ``pick_place``: an object resting on a receptacle's surface (touching the receptacle, its
  contacts at the surface's height, its centre inside the surface's footprint), slower than
  ``max_speed_m_s``, for ``hold_s``;
- ``rearrange``: several pick-and-place goals, all holding at once for ``hold_s``.
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field, model_validator

from holomj.spec.base import FrozenModel, Identifier

NonNegative = Annotated[float, Field(ge=0.0)]


class NavigateTask(FrozenModel):
    """The robot's base near an object and facing it, or inside a room."""

    kind: Literal["navigate"] = "navigate"
    id: Identifier
    description: str = ""
    object: str | None = None
    room: str | None = None
    radius_m: Annotated[float, Field(gt=0.0, le=10.0)] = 1.0
    facing_deg: Annotated[float, Field(gt=0.0, le=180.0)] = 45.0
    hold_s: NonNegative = 0.0

    @model_validator(mode="after")
    def _one_target(self) -> NavigateTask:
        if (self.object is None) == (self.room is None):
            raise ValueError("a navigate task names exactly one of 'object' and 'room'")
        return self


class ArticulationTask(FrozenModel):
    """Open or close an articulated part: its joint past ``fraction`` of its range."""

    kind: Literal["open", "close"]
    id: Identifier
    description: str = ""
    object: str
    joint: str
    # open: (value - closed) / (open limit - closed) >= fraction; close: <= fraction
    fraction: Annotated[float, Field(ge=0.0, le=1.0)] = 0.5
    hold_s: NonNegative = 1.0
    # the openness the part is set to when an episode starts (None: as the scene has it)
    start: Annotated[float, Field(ge=0.0, le=1.0)] | None = None


class PlaceGoal(FrozenModel):
    """An object resting on a receptacle's surface (``surface``: an index into its
    ``surfaces`` in ``objects.json``, or into its ``interior_surfaces`` when ``interior``;
    ``None``: any of them)."""

    object: str
    receptacle: str
    surface: Annotated[int, Field(ge=0)] | None = None
    interior: bool = False


class PickPlaceTask(FrozenModel):
    """Pick an object and place it on (or in) a receptacle."""

    kind: Literal["pick_place"] = "pick_place"
    id: Identifier
    description: str = ""
    goal: PlaceGoal
    height_tol_m: Annotated[float, Field(gt=0.0, le=0.2)] = 0.03
    max_speed_m_s: Annotated[float, Field(gt=0.0)] = 0.05
    hold_s: NonNegative = 1.0


class RearrangeTask(FrozenModel):
    """Several objects, each to its goal receptacle, all at once."""

    kind: Literal["rearrange"] = "rearrange"
    id: Identifier
    description: str = ""
    goals: Annotated[list[PlaceGoal], Field(min_length=2)]
    height_tol_m: Annotated[float, Field(gt=0.0, le=0.2)] = 0.03
    max_speed_m_s: Annotated[float, Field(gt=0.0)] = 0.05
    hold_s: NonNegative = 1.0

    @model_validator(mode="after")
    def _distinct_objects(self) -> RearrangeTask:
        objects = [g.object for g in self.goals]
        if len(set(objects)) != len(objects):
            raise ValueError("a rearrange task moves each object once")
        return self


Task = Annotated[
    NavigateTask | ArticulationTask | PickPlaceTask | RearrangeTask, Field(discriminator="kind")
]


class TaskSet(FrozenModel):
    """``tasks.json``: the tasks proposed for (or written for) one scene folder."""

    schema_version: Literal["1.0"] = "1.0"
    scene: str
    tasks: list[Task]

    @model_validator(mode="after")
    def _unique_ids(self) -> TaskSet:
        ids = [t.id for t in self.tasks]
        if len(set(ids)) != len(ids):
            raise ValueError("task ids must be unique")
        return self
