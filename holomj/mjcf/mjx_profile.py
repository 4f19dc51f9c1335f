"""The ``mjx`` compile profile: an MjSpec that MJX (JAX backend) accepts and runs well.

Limits of MJX-JAX in MuJoCo 3.17 (``doc/mjx.rst``, "Feature Parity" and "Sharp Bits", and
``mujoco.mjx._src.io.put_model``), and what the profile does about each:

- Cylinders and ellipsoids collide only with other primitives (not with boxes, meshes or height
  fields): every colliding cylinder becomes a convex mesh (a circumscribed 16-gon prism, 32
  vertices) and every colliding ellipsoid a 32-vertex hull, with the geom's own pose and mass.
- SAT on convex meshes is slow for big hulls ("fewer than 32 vertices" for mesh-mesh): every
  mesh a collider uses gets ``maxhullvert`` capped at :data:`MAX_HULL_VERT`.
- Margins and gaps are not implemented for meshes: every collider's and pair's margin and gap
  are set to 0 (holomj's scenes use none).
- Integrators: no ``implicit`` (becomes ``implicitfast``), no ``implicitfast`` with fluid drag
  (becomes ``Euler``); solvers: no PGS (becomes Newton); no noslip (set to 0 iterations);
  enable flags other than ``invdiscrete``, ``sleep`` and ``ipc`` are cleared; condim 1 is not
  allowed with the elliptic cone (becomes 3).
- No broad phase: MJX-JAX evaluates every pair of colliders that may touch and reserves
  constraint rows for all their contacts; the custom numerics ``max_geom_pairs`` and
  ``max_contact_points`` (ignored by C MuJoCo) cap them, growing with the moving bodies.
- Articulated objects (doors, drawers, lids on hinge and slide joints, :mod:`.articulation`)
  need nothing MJX lacks: limited hinge and slide joints with damping, friction loss, armature
  and springs, excluded body pairs and handle sites are all MJX features, and their colliders
  get the conversions above (a washing machine's round door is a cylinder). Each moving part is
  a moving body for the broad-phase caps below.
- Not convertible, so rejected with a one-line error naming the element: flex, SDF geoms,
  actuators with other transmissions, dynamics, gains or biases than MJX's, equality constraints
  other than connect/weld/joint/tendon, plugin sensors and contact sensors matching sites,
  bodies or subtrees or reducing to the net force.
"""

from __future__ import annotations

import math

import mujoco
import numpy as np

from holomj.errors import SpecError

MAX_HULL_VERT = 32
PAIRS_PER_MOVING_BODY = 4
MIN_GEOM_PAIRS = 8
CONTACTS_PER_MOVING_BODY = 8
MIN_CONTACT_POINTS = 16
CYLINDER_SIDES = 16
_ELLIPSOID_RINGS = 5  # latitude rings of 6 points, plus the two poles: 32 vertices
_ELLIPSOID_RING_POINTS = 6

_J = mujoco.mjtJoint
_G = mujoco.mjtGeom
_SUPPORTED_TRN = {"mjTRN_JOINT", "mjTRN_JOINTINPARENT", "mjTRN_SITE", "mjTRN_TENDON"}
_SUPPORTED_DYN = {"mjDYN_NONE", "mjDYN_INTEGRATOR", "mjDYN_FILTER", "mjDYN_FILTEREXACT"}
_SUPPORTED_DYN |= {"mjDYN_MUSCLE"}
_SUPPORTED_GAIN = {"mjGAIN_FIXED", "mjGAIN_AFFINE", "mjGAIN_MUSCLE"}
_SUPPORTED_BIAS = {"mjBIAS_NONE", "mjBIAS_AFFINE", "mjBIAS_MUSCLE"}
_SUPPORTED_EQ = {"mjEQ_CONNECT", "mjEQ_WELD", "mjEQ_JOINT", "mjEQ_TENDON"}
_UNSUPPORTED_SENSORS = {"mjSENS_PLUGIN", "mjSENS_USER"}
_SUPPORTED_ENABLE = (
    mujoco.mjtEnableBit.mjENBL_INVDISCRETE
    | mujoco.mjtEnableBit.mjENBL_SLEEP
    | mujoco.mjtEnableBit.mjENBL_IPC
)


def apply_mjx_profile(spec: mujoco.MjSpec) -> list[str]:
    """Change ``spec`` in place so that ``mujoco.mjx.put_model`` accepts its model.

    Returns what was changed, one line per kind of change. Idempotent. Raises
    :class:`~holomj.errors.SpecError` for features MJX lacks that cannot be converted.
    """
    _reject_unconvertible(spec)
    notes = _options(spec)
    notes += _colliders(spec)
    notes += _broadphase(spec)
    return notes


def _broadphase(spec: mujoco.MjSpec) -> list[str]:
    """Cap the geom pairs and contact points MJX-JAX processes (see MAX_* below).

    MJX-JAX has no real broad phase: every pair of a moving body's collider with any other
    collider is evaluated each step and every possible contact is a row of the constraint
    system. ``max_geom_pairs`` keeps, per kind of pair, the closest pairs (bounding spheres),
    ``max_contact_points`` the deepest contacts. Both grow with the number of moving bodies.
    """
    moving = sum(1 for body in spec.bodies if body.joints)
    values = {
        "max_geom_pairs": PAIRS_PER_MOVING_BODY * moving + MIN_GEOM_PAIRS,
        "max_contact_points": CONTACTS_PER_MOVING_BODY * moving + MIN_CONTACT_POINTS,
    }
    notes = []
    for name, value in values.items():
        existing = spec.numeric(name)
        if existing is not None:
            continue
        spec.add_numeric(name=name, data=[float(value)])
        notes.append(f"{name} = {value} (MJX broad phase)")
    return notes


def _options(spec: mujoco.MjSpec) -> list[str]:
    notes = []
    opt = spec.option
    fluid = opt.density > 0 or opt.viscosity > 0 or any(w != 0 for w in opt.wind)
    if opt.integrator == mujoco.mjtIntegrator.mjINT_IMPLICIT:
        opt.integrator = mujoco.mjtIntegrator.mjINT_IMPLICITFAST
        notes.append("integrator implicit -> implicitfast")
    if opt.integrator == mujoco.mjtIntegrator.mjINT_IMPLICITFAST and fluid:
        opt.integrator = mujoco.mjtIntegrator.mjINT_EULER
        notes.append("integrator implicitfast -> Euler (fluid drag)")
    if opt.solver == mujoco.mjtSolver.mjSOL_PGS:
        opt.solver = mujoco.mjtSolver.mjSOL_NEWTON
        notes.append("solver PGS -> Newton")
    if opt.noslip_iterations:
        opt.noslip_iterations = 0
        notes.append("noslip iterations -> 0")
    if opt.enableflags & ~int(_SUPPORTED_ENABLE):
        opt.enableflags = opt.enableflags & int(_SUPPORTED_ENABLE)
        notes.append("unsupported enable flags cleared")
    return notes


def _colliders(spec: mujoco.MjSpec) -> list[str]:
    counts = {"cylinder": 0, "ellipsoid": 0, "margin": 0, "condim": 0}
    collision_meshes = set()
    elliptic = spec.option.cone == mujoco.mjtCone.mjCONE_ELLIPTIC
    for geom in spec.geoms:
        if not (geom.contype or geom.conaffinity):
            continue
        if geom.type == _G.mjGEOM_SDF:
            raise SpecError("MJX does not support SDF geoms", where=_label(geom, "geom"))
        if geom.type == _G.mjGEOM_CYLINDER:
            _to_mesh(spec, geom, "cylinder")
            counts["cylinder"] += 1
        elif geom.type == _G.mjGEOM_ELLIPSOID:
            _to_mesh(spec, geom, "ellipsoid")
            counts["ellipsoid"] += 1
        if geom.type == _G.mjGEOM_MESH:
            collision_meshes.add(geom.meshname)
        if geom.margin or geom.gap:
            geom.margin, geom.gap = 0.0, 0.0
            counts["margin"] += 1
        if elliptic and geom.condim == 1:
            geom.condim = 3
            counts["condim"] += 1
    for pair in spec.pairs:
        if pair.margin or pair.gap:
            pair.margin, pair.gap = 0.0, 0.0
            counts["margin"] += 1
    capped = 0
    for mesh in spec.meshes:
        if mesh.name in collision_meshes and not 0 < mesh.maxhullvert <= MAX_HULL_VERT:
            mesh.maxhullvert = MAX_HULL_VERT
            capped += 1
    notes = [
        f"{n} colliding {kind}(s) -> convex mesh"
        for kind, n in counts.items()
        if n
        and kind
        in (
            "cylinder",
            "ellipsoid",
        )
    ]
    if counts["margin"]:
        notes.append(f"{counts['margin']} margin/gap(s) -> 0")
    if counts["condim"]:
        notes.append(f"{counts['condim']} condim 1 -> 3 (elliptic cone)")
    if capped:
        notes.append(f"{capped} collision mesh(es) capped at {MAX_HULL_VERT} hull vertices")
    return notes


def _to_mesh(spec: mujoco.MjSpec, geom: mujoco.MjsGeom, kind: str) -> None:
    """Replace a cylinder or ellipsoid geom by a convex mesh of the same extent."""
    size = np.array(geom.size, dtype=float)
    if not math.isnan(geom.fromto[0]):
        _resolve_fromto(geom, size)
    if kind == "cylinder":
        radius, half = float(size[0]), float(size[1])
        name = f"mjx/cylinder_{radius:.6g}x{half:.6g}"
        points = _prism(radius, half)
    else:
        name = "mjx/ellipsoid_" + "x".join(f"{s:.6g}" for s in size[:3])
        points = _ellipsoid(size[:3])
    if spec.mesh(name) is None:
        spec.add_mesh(name=name, uservert=points.ravel().tolist(), maxhullvert=MAX_HULL_VERT)
    geom.type = _G.mjGEOM_MESH
    geom.meshname = name


def _resolve_fromto(geom: mujoco.MjsGeom, size: np.ndarray) -> None:
    """Turn ``fromto`` into pos, quat and half-length (meshes have no fromto)."""
    start, end = np.array(geom.fromto[:3]), np.array(geom.fromto[3:])
    axis = end - start
    length = float(np.linalg.norm(axis))
    quat = np.array([1.0, 0.0, 0.0, 0.0])
    if length > 0:
        mujoco.mju_quatZ2Vec(quat, axis / length)
    geom.pos = list((start + end) / 2)
    geom.quat = list(quat)
    size[1] = length / 2
    geom.fromto = [math.nan, 0.0, 0.0, 0.0, 0.0, 0.0]


def _prism(radius: float, half: float) -> np.ndarray:
    circumscribed = radius / math.cos(math.pi / CYLINDER_SIDES)
    angles = np.arange(CYLINDER_SIDES) * (2 * math.pi / CYLINDER_SIDES)
    ring = np.column_stack([np.cos(angles), np.sin(angles)]) * circumscribed
    return np.vstack([np.column_stack([ring, np.full(CYLINDER_SIDES, z)]) for z in (-half, half)])


def _ellipsoid(radii: np.ndarray) -> np.ndarray:
    points = [np.array([0.0, 0.0, -1.0]), np.array([0.0, 0.0, 1.0])]
    for i in range(_ELLIPSOID_RINGS):
        polar = math.pi * (i + 1) / (_ELLIPSOID_RINGS + 1)
        offset = math.pi / _ELLIPSOID_RING_POINTS * (i % 2)
        for k in range(_ELLIPSOID_RING_POINTS):
            azimuth = 2 * math.pi * k / _ELLIPSOID_RING_POINTS + offset
            points.append(
                np.array(
                    [
                        math.sin(polar) * math.cos(azimuth),
                        math.sin(polar) * math.sin(azimuth),
                        math.cos(polar),
                    ]
                )
            )
    return np.array(points) * radii


def _reject_unconvertible(spec: mujoco.MjSpec) -> None:
    if spec.flexes:
        raise SpecError("MJX (JAX) does not support flex objects", where="flex")
    for actuator in spec.actuators:
        for value, supported in (
            (actuator.trntype, _SUPPORTED_TRN),
            (actuator.dyntype, _SUPPORTED_DYN),
            (actuator.gaintype, _SUPPORTED_GAIN),
            (actuator.biastype, _SUPPORTED_BIAS),
        ):
            if value.name not in supported:
                raise SpecError(
                    f"MJX does not support actuator {value.name}",
                    where=_label(actuator, "actuator"),
                    fix=f"use one of {', '.join(sorted(supported))}",
                )
    for equality in spec.equalities:
        if equality.type.name not in _SUPPORTED_EQ:
            raise SpecError(
                f"MJX does not support equality {equality.type.name}",
                where=_label(equality, "equality"),
                fix=f"use one of {', '.join(sorted(_SUPPORTED_EQ))}",
            )
    for sensor in spec.sensors:
        if sensor.type.name in _UNSUPPORTED_SENSORS:
            raise SpecError(
                f"MJX does not support sensor {sensor.type.name}", where=_label(sensor, "sensor")
            )
        if sensor.type == mujoco.mjtSensor.mjSENS_CONTACT:
            _check_contact_sensor(sensor)


def _check_contact_sensor(sensor: mujoco.MjsSensor) -> None:
    unsupported = {mujoco.mjtObj.mjOBJ_SITE, mujoco.mjtObj.mjOBJ_BODY, mujoco.mjtObj.mjOBJ_XBODY}
    if sensor.objtype in unsupported or sensor.reftype in unsupported:
        raise SpecError(
            "MJX supports contact sensors matching geoms only", where=_label(sensor, "sensor")
        )
    if len(sensor.intprm) > 1 and sensor.intprm[1] == 3:
        raise SpecError(
            "MJX does not support contact sensors reducing to the net force",
            where=_label(sensor, "sensor"),
        )


def _label(element: object, kind: str) -> str:
    name = getattr(element, "name", "")
    return f"{kind} {name!r}" if name else f"{kind} #{getattr(element, 'id', '?')}"
