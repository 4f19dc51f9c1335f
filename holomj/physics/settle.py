"""Settle a scene, watch it for a while, and judge every object: the stability report.

The simulation starts from the model's initial pose on a fresh ``MjData`` (nothing is shared
with the caller) and steps with the scene's own options. It first *settles*: steps until every
free body has been at rest (linear speed under ``rest_linear_mps`` and angular speed under
``rest_angular_rps``) for ``rest_window_s``, or until ``settle_cap_s``. It then *monitors* a
window of ``monitor_s``, over which each object's drift, rotation, path length (jitter) and
deepest contact are measured; at the end, what it rests on. MuJoCo is deterministic on one
thread, so the same scene always gives the same numbers.

Objects are judged by the one rule of :data:`holomj.spec.report.STABILITY_RULE`: at rest over
the monitor window, close to the pose they were authored at, and without penetration at t = 0.
Positions are those of each object body's centre of mass (``xipos``), so the verdict does not
depend on where the body frame sits (a footed pole that topples ends 90° from its authored pose
with its centre of mass half its height lower, although its frame may not have moved).

Moving parts of articulated objects (the hinge and slide joints of bodies below an object's
body: doors, drawers, lids) count too: settling waits for them to be at rest as well (the same
speed thresholds, per radian or metre), and an object whose part ends more than
``part_rotation_deg`` (hinges) or ``part_travel_m`` (slides) from its authored joint value is
unstable, the reason naming the part ("door_0_hinge swung 35.2° from its authored angle").

MuJoCo 3.17's sleeping islands (``mjENBL_SLEEP``) are off by default: a sleeping body cannot
drift, so creep slower than ``sleep_tolerance`` would go unseen, and the scene's own options
are the ones its users simulate with. ``sleep=True`` turns them on for big scenes: 780 objects
at rest step in 0.7 ms instead of 28 ms.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass

import mujoco
import numpy as np

from holomj.physics.audit import AuditResult, GeomOwners, Rooms, audit, lowest_points
from holomj.physics.scene_io import LoadedScene
from holomj.physics.settling import (
    FIXED,
    FLOOR,
    ObjectTrack,
    PartJoints,
    SettleResult,
    final_supports,
    run_settle,
)
from holomj.spec.report import ObjectReport, StabilityReport, Thresholds
from holomj.spec.scene import SceneObject


def quat_angle_deg(q1: np.ndarray, q2: np.ndarray) -> np.ndarray:
    """Rotation angle between unit quaternions, row by row, in degrees."""
    dot = np.clip(np.abs(np.sum(q1 * q2, axis=1)), 0.0, 1.0)
    return np.degrees(2.0 * np.arccos(dot))


def displacement_from_authored(
    start: np.ndarray, end: np.ndarray, settle_drop: float
) -> np.ndarray:
    """Distance of each final centre of mass from its authored one, after the allowed settle:
    up to ``settle_drop`` of sinking is forgiven (a dropped object falling onto its support)."""
    delta = end - start
    sink = np.minimum(delta[:, 2], 0.0)
    delta[:, 2] = np.where(delta[:, 2] < 0.0, np.minimum(sink + settle_drop, 0.0), delta[:, 2])
    return np.linalg.norm(delta, axis=1)


def object_penetrations(owners: GeomOwners, found: AuditResult) -> np.ndarray:
    """Each object's own deepest interpenetrating pair at t = 0 (0 when it has none)."""
    deepest = np.zeros(len(owners.names))
    for overlap in found.overlaps:
        for geom in (overlap.geom1, overlap.geom2):
            owner = int(owners.geom_owner[geom])
            if owner >= 0:
                deepest[owner] = max(deepest[owner], overlap.depth)
    return deepest


def _penetration_partners(owners: GeomOwners, found: AuditResult) -> dict[str, tuple[str, float]]:
    """Per object name: the other party of its deepest pair at t = 0, and the depth."""
    partners: dict[str, tuple[str, float]] = {}
    for pair in found.penetrations:  # deepest first
        for me, other in ((pair.a, pair.b), (pair.b, pair.a)):
            if me in owners.names and me not in partners:
                partners[me] = (other, pair.depth_m)
    return partners


def judge(
    loaded: LoadedScene,
    track: ObjectTrack,
    result: SettleResult,
    th: Thresholds,
    found: AuditResult,
) -> list[ObjectReport]:
    """Turn the raw numbers into one :class:`ObjectReport` per object (``STABILITY_RULE``)."""
    model, data = loaded.model, result.data
    owners = track.owners
    bodies = owners.object_bodies
    end_pos = data.xipos[bodies]
    end_quat = data.xquat[bodies]
    drift = np.linalg.norm(end_pos - result.monitor_pos, axis=1)
    rotation = quat_angle_deg(end_quat, result.monitor_quat)
    displacement = displacement_from_authored(result.start_pos, end_pos, th.settle_drop_m)
    turned = quat_angle_deg(end_quat, result.start_quat)
    drop = result.start_pos[:, 2] - end_pos[:, 2]
    penetration = object_penetrations(owners, found)
    partners = _penetration_partners(owners, found)
    below_floor_at_start = {d.name for d in found.below_floor}
    outside_at_start = {d.name for d in found.outside_rooms}
    lowest = lowest_points(model, data, owners)
    supports = final_supports(model, data, owners)
    at_rest = np.ones(len(bodies), dtype=bool)
    at_rest[track.dynamic] = track.at_rest(data, th)
    scene_objects = {o.id: o for o in loaded.scene.objects} if loaded.scene else {}
    inside = _inside_rooms(loaded, owners, scene_objects, end_pos, th)
    motion = _part_motion(model, track.parts, result.start_qpos, data.qpos, len(bodies))
    reports = []
    for i, name in enumerate(owners.names):
        dynamic = bool(track.dynamic[i])
        spec = scene_objects.get(name)
        numbers = _ObjectNumbers(
            drift=float(drift[i]),
            rotation=float(rotation[i]),
            displacement=float(displacement[i]),
            turned=float(turned[i]),
            drop=float(drop[i]),
            fell=bool(drop[i] > th.fall_m or lowest[i] < -th.below_floor_m),
            penetration=float(penetration[i]),
            partner=partners.get(name, ("something", float(penetration[i]))),
            below_floor=name in below_floor_at_start,
            outside=name in outside_at_start,
            left_room=inside is not None and not inside[name],
            room=spec.room if spec is not None and spec.room else None,
            dynamic=dynamic,
            support=(supports[i] or None) if dynamic else FIXED,
            expected=(spec.support or FLOOR) if spec is not None else None,
            motion=motion[i],
        )
        reasons = numbers.reasons(th, result.warnings)
        reports.append(
            ObjectReport(
                name=name,
                stable=not reasons,
                dynamic=dynamic,
                displacement_m=_r(displacement[i]),
                rotation_from_authored_deg=_r(turned[i], 4),
                drift_m=_r(drift[i]),
                rotation_deg=_r(rotation[i], 4),
                path_m=_r(result.path[i]),
                drop_m=_r(drop[i]),
                fell=numbers.fell,
                left_room=numbers.left_room,
                support=numbers.support,
                expected_support=numbers.expected,
                penetration_m=_r(penetration[i]),
                contact_depth_m=_r(result.penetration[i]),
                at_rest=bool(at_rest[i]),
                part_motion={j: _r(v, 4 if h else 6) for j, (v, h) in motion[i].items()},
                reasons=reasons,
            )
        )
    return reports


def _inside_rooms(
    loaded: LoadedScene,
    owners: GeomOwners,
    scene_objects: dict[str, SceneObject],
    end_pos: np.ndarray,
    th: Thresholds,
) -> dict[str, bool] | None:
    """Per object name: whether it ended inside its room (any room when it names none); None
    for a model without a holomj scene."""
    if not loaded.scene:
        return None
    rooms = Rooms(loaded.scene, th.room_margin_m)
    inside = {}
    for i, name in enumerate(owners.names):
        room = scene_objects[name].room if name in scene_objects else None
        inside[name] = bool(rooms.inside(end_pos[i : i + 1, :2], room)[0])
    return inside


@dataclass(frozen=True)
class _ObjectNumbers:
    """One object's measured numbers and facts, which :meth:`reasons` judges."""

    drift: float
    rotation: float
    displacement: float
    turned: float
    drop: float
    fell: bool
    penetration: float
    partner: tuple[str, float]  # the other party of its deepest pair at t = 0, and the depth
    below_floor: bool
    outside: bool
    left_room: bool
    room: str | None
    dynamic: bool
    support: str | None
    expected: str | None
    motion: dict[str, tuple[float, bool]]

    def reasons(self, th: Thresholds, warnings: dict[str, int]) -> list[str]:
        """Why the object is not stable (empty: it is), in the order of ``STABILITY_RULE``."""
        reasons = []
        # (a) at rest over the monitor window
        if self.drift >= th.drift_m:
            reasons.append(f"drifted {self.drift * 1000:.1f} mm during the monitor window")
        if self.rotation >= th.rotation_deg:
            reasons.append(f"turned {self.rotation:.1f}° during the monitor window")
        # (b) close to the authored pose
        if self.displacement >= th.displacement_m:
            reasons.append(f"ended {self.displacement * 1000:.1f} mm from its authored position")
        if self.turned >= th.rotation_from_authored_deg:
            reasons.append(f"ended {self.turned:.1f}° from its authored orientation")
        if self.fell:
            reasons.append(
                f"fell {self.drop:.3f} m" if self.drop > th.fall_m else "fell through the floor"
            )
        # (c) no penetration at t = 0, in its place, on its support
        if self.penetration > th.tolerance_m:
            other, depth = self.partner
            reasons.append(f"penetrates {other} by {depth * 1000:.1f} mm at t = 0")
        if self.below_floor:
            reasons.append("below the floor at t = 0")
        if self.outside:
            reasons.append("outside every room at t = 0")
        if self.left_room:
            reasons.append(f"left room {self.room}" if self.room else "ended outside every room")
        if self.dynamic and self.expected is not None and self.support != self.expected:
            reasons.append(f"rests on {self.support or 'nothing'}, expected {self.expected}")
        if self.dynamic and warnings:
            reasons.append("MuJoCo warnings: " + ", ".join(sorted(warnings)))
        # (d) moving parts where they were authored
        for joint, (value, hinge) in self.motion.items():
            if hinge and value >= th.part_rotation_deg:
                reasons.append(f"{joint} swung {value:.1f}° from its authored angle by itself")
            elif not hinge and value >= th.part_travel_m:
                reasons.append(
                    f"{joint} slid {value * 1000:.1f} mm from its authored position by itself"
                )
        return reasons


def _part_motion(
    model: mujoco.MjModel,
    parts: PartJoints | None,
    start: np.ndarray,
    end: np.ndarray,
    count: int,
) -> list[dict[str, tuple[float, bool]]]:
    """Per object: joint name (without the object's prefix) -> (departure from the authored
    value in degrees or metres, hinge?)."""
    motion: list[dict[str, tuple[float, bool]]] = [{} for _ in range(count)]
    if parts is None or not len(parts):
        return motion
    for owner, joint, value, hinge in zip(
        parts.owner, parts.joint, parts.departures(start, end), parts.hinge, strict=True
    ):
        name = model.joint(int(joint)).name
        name = name.split("/", 1)[1] if "/" in name else name
        motion[int(owner)][name] = (float(value), bool(hinge))
    return motion


def _r(value: float, digits: int = 6) -> float:
    """Rounded for the report (micrometres): stable JSON, no float noise."""
    value = float(value)
    return 0.0 if math.isclose(value, 0.0, abs_tol=10 ** -(digits + 1)) else round(value, digits)


@dataclass
class Validation:
    """A report and the simulation behind it (for baking settled poses back)."""

    report: StabilityReport
    track: ObjectTrack
    result: SettleResult


def validate_loaded(
    loaded: LoadedScene,
    thresholds: Thresholds | None = None,
    furniture: str = "free",
    sleep: bool = False,
) -> StabilityReport:
    """Audit at t = 0, settle, monitor and judge ``loaded``."""
    return run_validation(loaded, thresholds, furniture, sleep).report


def run_validation(
    loaded: LoadedScene,
    thresholds: Thresholds | None = None,
    furniture: str = "free",
    sleep: bool = False,
) -> Validation:
    """:func:`validate_loaded`, keeping the settled simulation state."""
    th = thresholds or Thresholds()
    started = time.perf_counter()
    found = audit(loaded, tolerance=th.tolerance_m, room_margin=th.room_margin_m)
    track = ObjectTrack.of(loaded.model, loaded.objects)
    result = run_settle(loaded.model, track, th, sleep)
    objects = judge(loaded, track, result, th, found)
    wall = time.perf_counter() - started
    return Validation(assemble(loaded, found, result, objects, th, furniture, wall), track, result)


def assemble(
    loaded: LoadedScene,
    found: AuditResult,
    result: SettleResult,
    objects: list[ObjectReport],
    th: Thresholds,
    furniture: str,
    wall: float,
) -> StabilityReport:
    """The scene-level report around the per-object ones."""
    unstable = [o for o in objects if not o.stable]
    counts = {
        "objects": len(objects),
        "dynamic": sum(o.dynamic for o in objects),
        "stable": len(objects) - len(unstable),
        "unstable": len(unstable),
        "static": sum(not o.dynamic for o in objects),
        "moved_from_authored": sum(
            o.displacement_m >= th.displacement_m
            or o.rotation_from_authored_deg >= th.rotation_from_authored_deg
            for o in objects
        ),
        "fell": sum(o.fell for o in objects),
        "left_room": sum(o.left_room for o in objects),
        "wrong_support": sum(
            o.dynamic and o.expected_support is not None and o.support != o.expected_support
            for o in objects
        ),
        "penetrations": len(found.penetrations),
        "below_floor": len(found.below_floor),
        "outside_rooms": len(found.outside_rooms),
    }
    ok = not unstable and found.ok and not result.warnings
    return StabilityReport(
        ok=ok,
        source=str(loaded.source),
        furniture=furniture,
        objects=objects,
        static_objects=[o.name for o in objects if not o.dynamic],
        penetrations=found.penetrations,
        below_floor=found.below_floor,
        outside_rooms=found.outside_rooms,
        max_penetration_m=_r(
            max([o.penetration_m for o in objects] + [p.depth_m for p in found.penetrations])
            if objects or found.penetrations
            else 0.0
        ),
        max_contact_depth_m=_r(max((o.contact_depth_m for o in objects), default=0.0)),
        warnings=result.warnings,
        counts=counts,
        sim_time_s=_r(result.sim_time, 4),
        wall_time_s=round(wall, 3),
        realtime_factor=round(result.sim_time / wall, 2) if wall > 0 else 0.0,
        settle_time_s=_r(result.settle_time, 4),
        settled=result.settled,
        monitor_s=th.monitor_s,
        thresholds=th,
    )
