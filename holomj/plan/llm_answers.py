"""The pydantic models of the LLM planner's answers, one per step (unknown fields rejected,
words lower-cased, counts bounded)."""

from __future__ import annotations

from typing import Annotated, Any, Literal

from pydantic import BaseModel, ConfigDict, Field, field_validator

MAX_ROOMS = 12

Text = Annotated[str, Field(max_length=2000)]
Short = Annotated[str, Field(min_length=1, max_length=200)]


class _Answer(BaseModel):
    model_config = ConfigDict(extra="forbid", allow_inf_nan=False, str_strip_whitespace=True)


def _lower(value: Any) -> Any:
    return value.strip().lower() if isinstance(value, str) else value


class RoomAnswer(_Answer):
    """One room of the floor-plan answer."""

    id: Short
    type: Short
    width_m: Annotated[float, Field(gt=0.0, le=100.0)]
    depth_m: Annotated[float, Field(gt=0.0, le=100.0)]
    floor_material: Short
    wall_material: Short


class FloorPlanAnswer(_Answer):
    """Step 1: what kind of scene, and its rooms."""

    scene_type: Short
    style: list[Short] = Field(default_factory=list, max_length=10)
    rooms: list[RoomAnswer] = Field(min_length=1, max_length=MAX_ROOMS)


class WallHeightAnswer(_Answer):
    """Step 2: one wall height for the whole scene."""

    wall_height_m: Annotated[float, Field(gt=0.0, le=50.0)]


class DoorsAnswer(_Answer):
    """Step 3: which rooms are connected by a door, and where one enters."""

    connections: list[tuple[Short, Short]] = Field(default_factory=list, max_length=60)
    entrance_room: Short


class WindowAnswer(_Answer):
    """The windows of one room."""

    room: Short
    count: Annotated[int, Field(ge=0, le=12)]
    kind: Literal["fixed", "hung", "slider"]

    _kind_lower = field_validator("kind", mode="before")(_lower)


class WindowsAnswer(_Answer):
    """Step 4: windows per room (rooms left out get their type's defaults)."""

    rooms: list[WindowAnswer] = Field(max_length=MAX_ROOMS)


class SmallObjectAnswer(_Answer):
    """An object standing on top of a receptacle."""

    name: Short
    description: Text = ""
    quantity: Annotated[int, Field(ge=0, le=100)] = 1
    variance: Literal["same", "varied"] = "varied"
    category: Short | None = None

    _variance_lower = field_validator("variance", mode="before")(_lower)


class ObjectAnswer(_Answer):
    """One floor or wall object of a room (the key of the answer's map is its name)."""

    description: Text = ""
    location: Literal["floor", "wall"]
    size_cm: (
        tuple[
            Annotated[float, Field(gt=0.0, le=10_000.0)],
            Annotated[float, Field(gt=0.0, le=10_000.0)],
            Annotated[float, Field(gt=0.0, le=10_000.0)],
        ]
        | None
    )
    quantity: Annotated[int, Field(ge=0, le=100)] = 1
    variance: Literal["same", "varied"] = "same"
    category: Short | None = None
    above: Short | None = None
    objects_on_top: list[SmallObjectAnswer] = Field(default_factory=list, max_length=30)

    _lower_words = field_validator("location", "variance", mode="before")(_lower)


class ObjectsAnswer(_Answer):
    """Step 5 (per room): the room's objects, keyed by name."""

    objects: dict[Short, ObjectAnswer] = Field(max_length=80)


class ConstraintsAnswer(_Answer):
    """Step 6 (per room): layout constraint lines over instance names."""

    constraints: list[Annotated[str, Field(max_length=1000)]] = Field(max_length=200)
