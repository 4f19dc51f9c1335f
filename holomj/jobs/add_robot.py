"""The add-robot job (``holomj add-robot OUT SPEC``): put a robot into a scene folder, atomically.

The folder is recompiled from its ``scene.json`` with its own ``assets/`` library, the robot is
placed and attached, a short simulation checks for MuJoCo warnings, and the folder is rewritten
in one atomic step; its other files (reports, renders) are kept as they were.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import cast

from holomj.errors import InputError
from holomj.jobs.folder import (
    open_library,
    prepare_output,
    read_robot,
    read_scene,
    require_scene_folder,
    write_scene_folder,
)
from holomj.mjcf.compiler import check_profile, compile_scene
from holomj.physics.smoke import simulate
from holomj.robots.attach import add_robot
from holomj.robots.placement import DEFAULT_CLEARANCE_M
from holomj.seeds import stage_rng
from holomj.spec.robot import RobotRecord

SMOKE_SECONDS = 1.0


@dataclass(frozen=True)
class AddRobotResult:
    """The robot that was attached and the MuJoCo warnings of the smoke run."""

    folder: Path
    robot: RobotRecord
    warnings: dict[str, int]


def add_robot_to_folder(
    folder: Path,
    spec: str,
    *,
    seed: int = 0,
    clearance: float | None = None,
    room: str | None = None,
    profile: str = "default",
    replace: bool = False,
) -> AddRobotResult:
    """Attach the robot ``spec`` to the scene folder ``folder`` (see the module docstring).

    Raises :class:`~holomj.errors.InputError` when the folder is not a holomj scene, already
    has a robot (unless ``replace``), the robot is unknown or no spot is free. ``clearance``
    defaults to :data:`~holomj.robots.placement.DEFAULT_CLEARANCE_M`.
    """
    clearance = DEFAULT_CLEARANCE_M if clearance is None else clearance
    folder = require_scene_folder(Path(folder), "holomj compile' or 'holomj generate")
    prepared = prepare_output(folder, overwrite=True)  # rewritable, before any work
    existing = read_robot(folder)
    if existing is not None and not replace:
        raise InputError(
            f"the scene already has a robot ({existing.spec})",
            where=str(folder),
            fix="pass --replace to put the new robot in its place",
        )
    compiled = compile_scene(
        read_scene(folder), open_library(folder), profile=check_profile(profile)
    )
    compiled = add_robot(compiled, spec, stage_rng(seed, "robot"), clearance=clearance, room=room)
    warnings = simulate(compiled.model, SMOKE_SECONDS).warnings
    write_scene_folder(compiled, prepared, keep_from=folder)
    return AddRobotResult(folder, cast(RobotRecord, compiled.robot), warnings)
