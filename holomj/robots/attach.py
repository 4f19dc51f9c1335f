"""Attach a robot to a compiled scene: choose its spot, put it there, recompile, check it.

The robot goes under the prefix ``robot/``, inside a static mount body ``robot/base_mount`` at
its spot (so the XML holds no ``<frame>``), with its files among the scene's asset files under
``robot/`` and its prepared MJCF as ``robot.xml``; :class:`~holomj.spec.robot.RobotRecord`
says where it stands, so :func:`attach_recorded` can put it back when the scene is recompiled
(the jobs layer reads it from a folder's ``robot.json``) and :func:`reattach_robot` can carry
it over to another compile of the scene in memory.
"""

from __future__ import annotations

import dataclasses
import math

import mujoco
import numpy as np

from holomj.errors import CompileError, FormatError, HolomjError, InputError, SpecError
from holomj.mjcf.compiler import CompiledScene, compile_spec
from holomj.mjcf.geometry import yaw_quat
from holomj.physics.bounds import world_aabbs
from holomj.robots.occupancy import build_floor_grid
from holomj.robots.placement import DEFAULT_CLEARANCE_M, Spot, choose_spot
from holomj.robots.prepare import PreparedRobot, prepare_robot
from holomj.robots.reach import compute_reach
from holomj.robots.registry import RobotSource, resolve_robot
from holomj.spec.robot import ROBOT_PREFIX, ROBOT_XML, RobotRecord

MOUNT_BODY = f"{ROBOT_PREFIX}base_mount"
PENETRATION_TOLERANCE_M = 0.001


def add_robot(
    compiled: CompiledScene,
    spec: str | RobotSource,
    rng: np.random.Generator,
    *,
    clearance: float = DEFAULT_CLEARANCE_M,
    room: str | None = None,
) -> CompiledScene:
    """``compiled`` with the robot ``spec`` (a registry name or an MJCF path, or the robot it
    names, already resolved) on a free spot.

    Raises :class:`~holomj.errors.InputError` for an unknown robot or when no spot is free.
    """
    source = spec if isinstance(spec, RobotSource) else resolve_robot(spec)
    prepared = prepare_robot(source)
    grid = build_floor_grid(compiled.model, compiled.scene)
    reach = compute_reach(grid, compiled.scene)
    spot = choose_spot(
        grid, reach, compiled.scene, prepared.footprint, rng, clearance=clearance, room=room
    )
    record = place_robot(prepared, spot)
    return attach_prepared(compiled, prepared.spec, prepared.files, record, prepared.to_xml())


def place_robot(prepared: PreparedRobot, spot: Spot) -> RobotRecord:
    """The record of ``prepared`` standing at ``spot`` (for callers choosing spots themselves)."""
    return RobotRecord(
        spec=prepared.source.spec,
        name=prepared.source.name,
        source=_source_label(prepared.source),
        package=prepared.source.package,
        position=(spot.x, spot.y, 0.0),
        yaw_deg=spot.yaw_deg,
        room=spot.room,
        footprint=prepared.footprint,
        clearance_m=spot.clearance_m,
        home={f"{ROBOT_PREFIX}{k}": round(float(v), 9) for k, v in prepared.home.items()},
        notes=prepared.notes,
    )


def attach_prepared(
    compiled: CompiledScene,
    robot: mujoco.MjSpec,
    files: dict[str, bytes],
    record: RobotRecord,
    robot_xml: str,
) -> CompiledScene:
    """Attach ``robot`` at ``record``'s pose to (a copy of) ``compiled``'s spec and recompile.

    Raises :class:`~holomj.errors.HolomjError` when the robot interpenetrates the scene at
    t = 0, :class:`~holomj.errors.CompileError` when MuJoCo rejects the result.
    """
    if compiled.robot is not None:
        raise InputError("the scene already has a robot", where=compiled.robot.spec)
    prefix_owner = record.prefix.rstrip("/")
    scene = compiled.scene
    for kind, items in (
        ("objects", scene.objects),
        ("doors", scene.doors),
        ("windows", scene.windows),
    ):
        if any(item.id == prefix_owner for item in items):
            raise InputError(
                f"the id {prefix_owner!r} is the robot's name prefix",
                where=f"{kind}: {prefix_owner}",
                fix="rename that element of the scene",
            )
    spec = compiled.spec.copy()
    merged = dict(compiled.files)
    for key, data in [*files.items(), (ROBOT_XML, robot_xml.encode("utf-8"))]:
        if key in merged and merged[key] != data:
            raise SpecError(f"two different files would be written to assets/{key}")
        merged[key] = data
    if spec.body(MOUNT_BODY) is not None:
        raise InputError("the scene already has a robot mount", where=MOUNT_BODY)
    mount = spec.worldbody.add_body(
        name=MOUNT_BODY,
        pos=list(record.position),
        quat=list(yaw_quat(math.radians(record.yaw_deg))),
    )
    mount.info = f"robot {record.name} ({record.spec})"
    # MuJoCo 3.17 copies the child into the scene, then prefixes the *original* child's file
    # names in place: attach a throwaway copy so that ``robot`` stays usable.
    spec.copy_during_attach = True
    try:
        spec.attach(robot.copy(), prefix=record.prefix, frame=mount.add_frame())
    except ValueError as err:
        raise CompileError(f"cannot attach the robot: {' '.join(str(err).split())}") from None
    if compiled.profile == "mjx":
        from holomj.mjcf.mjx_profile import apply_mjx_profile

        apply_mjx_profile(spec)
    try:
        spec.assets = dict(merged)  # kept with the spec: its XML export opens them
        model = compile_spec(spec, merged)
    except ValueError as err:
        raise CompileError(
            f"MuJoCo rejected the scene with the robot: {' '.join(str(err).split())}"
        ) from None
    _check_no_penetration(model, record)
    return dataclasses.replace(
        compiled, spec=spec, model=model, files=dict(sorted(merged.items())), robot=record
    )


def _check_no_penetration(model: mujoco.MjModel, record: RobotRecord) -> None:
    """No robot collider may interpenetrate anything at t = 0 (static pairs included)."""
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    mount = model.body(MOUNT_BODY).id
    robot_body = np.zeros(model.nbody, dtype=bool)
    robot_body[mount] = True
    for body in range(mount + 1, model.nbody):  # parents come before children
        robot_body[body] = robot_body[model.body_parentid[body]]
    colliding = (model.geom_contype != 0) | (model.geom_conaffinity != 0)
    on_robot = robot_body[model.geom_bodyid]
    not_plane = model.geom_type != mujoco.mjtGeom.mjGEOM_PLANE
    others = np.flatnonzero(colliding & ~on_robot & not_plane)
    low, high = world_aabbs(model, data)
    fromto = np.zeros(6)
    for g1 in np.flatnonzero(colliding & on_robot):
        near = others[
            np.all(low[others] <= high[g1] + 0.01, axis=1)
            & np.all(low[g1] <= high[others] + 0.01, axis=1)
        ]
        for g2 in near:
            dist = mujoco.mj_geomDistance(model, data, int(g1), int(g2), 0.01, fromto)
            if dist < -PENETRATION_TOLERANCE_M:
                raise HolomjError(
                    f"robot geom {model.geom(g1).name or g1} interpenetrates "
                    f"{model.geom(int(g2)).name or g2} by {-dist * 1000:.1f} mm at t = 0",
                    where=f"robot {record.name} at ({record.position[0]:.2f}, "
                    f"{record.position[1]:.2f})",
                    fix="report this: the spot was chosen clear of every collider",
                )


def _source_label(source: RobotSource) -> str:
    """The source MJCF, relative to its package when it came from one (portable)."""
    if source.package is None:
        return str(source.xml)
    parts = source.xml.parts
    for index in range(len(parts) - 1, -1, -1):
        if parts[index] in ("dm_robotics", "dm_control"):
            return f"{source.package}:{'/'.join(parts[index:])}"
    return str(source.xml)


def reattach_robot(target: CompiledScene, source: CompiledScene) -> CompiledScene:
    """``target`` (the same scene compiled otherwise, e.g. with static furniture) with the robot
    that ``source`` carries, at the same spot, from ``source``'s files in memory; ``target``
    unchanged when ``source`` has no robot."""
    if source.robot is None:
        return target
    xml = source.files[ROBOT_XML].decode("utf-8")
    files = {k: v for k, v in source.files.items() if k.startswith("robot/")}
    return attach_recorded(target, source.robot, xml, files, where=ROBOT_XML)


def attach_recorded(
    compiled: CompiledScene,
    record: RobotRecord,
    xml: str,
    files: dict[str, bytes],
    *,
    where: str = ROBOT_XML,
) -> CompiledScene:
    """``compiled`` with the robot of ``record`` (its prepared MJCF ``xml`` and ``files``, keyed
    as among the scene's assets) attached where the record says."""
    try:
        robot = mujoco.MjSpec.from_string(xml, assets=files)
    except ValueError as err:
        raise FormatError(
            f"MuJoCo cannot load the robot: {' '.join(str(err).split())}", where=where
        ) from None
    return attach_prepared(compiled, robot, files, record, xml)
