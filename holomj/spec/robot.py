"""Pure data about an attached robot: its footprint and its record (``robot.json`` in a scene
folder)."""

from __future__ import annotations

from typing import Annotated, Final, Literal

from pydantic import Field

from holomj.spec.base import FrozenModel, PositiveFloat, Vec2, Vec3

ROBOT_SCHEMA_VERSION: Final = "1.0"
ROBOT_XML = "robot.xml"  # the prepared robot MJCF: its key among the scene's asset files
ROBOT_PREFIX = "robot/"


class Footprint(FrozenModel):
    """The floor area a robot covers in its home pose, in its base frame (metres).

    ``radius_m`` is the largest distance of its collision geometry from the base origin in x/y:
    a disc of that radius holds the robot at any yaw. ``front_deg`` is the direction it reaches
    towards (the centroid of its outline), 0 = base +X.
    """

    radius_m: PositiveFloat
    height_m: PositiveFloat
    front_deg: float
    polygon: list[Vec2] = Field(min_length=3, description="Convex outline, base frame.")


class RobotRecord(FrozenModel):
    """Which robot stands where, so a scene can be recompiled with it (``robot.json``)."""

    schema_version: Literal["1.0"] = ROBOT_SCHEMA_VERSION
    spec: str = Field(description="The robot as the user named it (registry name or path).")
    name: str
    source: str = Field(description="The MJCF it was read from, at export time.")
    package: str | None = Field(default=None, description="Installed package it came from.")
    xml: str = Field(
        default=f"assets/{ROBOT_XML}",
        description="The prepared robot MJCF inside the scene folder (among its assets).",
    )
    prefix: str = ROBOT_PREFIX
    position: Vec3
    yaw_deg: float
    room: str | None = None
    footprint: Footprint
    clearance_m: Annotated[float, Field(ge=0.0)]
    home: dict[str, float] = Field(description="Initial joint positions (qpos0), by joint.")
    notes: list[str] = Field(default_factory=list)
