"""Turn a robot's MJCF into a self-contained, fixed-base robot that holds its home pose.

What changes, and why (each change is listed in the robot's notes):

- Files: every mesh, texture, height field and skin is read into memory under
  ``robot/<path>`` (relative to the scene's ``assets/``), so the scene folder carries them.
- Hand: a gripper MJCF is attached at a site of the arm (under ``hand/``), inside a small
  mount body, so the exported XML holds no ``<frame>`` (dm_control cannot parse one).
- Home pose (the registry's, else the MJCF's keyframe ``home``, else the initial pose with
  joints outside their range moved inside): it becomes the initial pose. Each moving body is
  turned (or slid) about its joint by the home value and the joint's ``ref`` set to it: joint
  values keep their meaning and ``qpos0`` is the home pose, for every loader (MuJoCo,
  dm_control, MJX).
- Fixed base: a free joint on a root body is removed; keyframes are dropped (their sizes no
  longer match once the robot is part of a scene).
- Holding still: every body gets gravity compensation and negative joint damping (it feeds
  energy in) is set to 0, so the robot stays in its home pose without a controller.
- Self-contacts: pairs of bodies whose colliders overlap in the home pose (convex hulls of
  non-convex links often do) get a contact exclude, else they would push it out of its pose.
"""

from __future__ import annotations

import hashlib
import math
import re
from dataclasses import dataclass, field
from pathlib import Path

import mujoco
import numpy as np
import shapely

from holomj.errors import InputError
from holomj.mjcf.compiler import compile_spec
from holomj.robots import shapes
from holomj.robots.registry import RobotSource
from holomj.spec.robot import Footprint

FILE_ROOT = "robot"
HAND_PREFIX = "hand/"
HOME_KEY = "home"
HOME_INSET = 0.01  # a joint starting outside its range is moved this fraction inside
SELF_TOLERANCE_M = 0.001
_UNSAFE = re.compile(r"[^A-Za-z0-9_.\-/]")
_SLIDE_OR_HINGE = (int(mujoco.mjtJoint.mjJNT_HINGE), int(mujoco.mjtJoint.mjJNT_SLIDE))


@dataclass
class PreparedRobot:
    """A robot ready to attach: its MjSpec, its files (keys relative to ``assets/``), its
    home pose (joint name -> qpos), footprint, and what was changed."""

    source: RobotSource
    spec: mujoco.MjSpec
    files: dict[str, bytes]
    home: dict[str, float]
    footprint: Footprint
    notes: list[str] = field(default_factory=list)

    def to_xml(self) -> str:
        """The prepared robot as MJCF (file names relative to the scene's ``assets/``)."""
        return self.spec.to_xml()


def load_spec(xml: Path) -> mujoco.MjSpec:
    """Parse an MJCF file, with a one-line InputError naming it."""
    try:
        return mujoco.MjSpec.from_file(str(xml))
    except ValueError as err:
        raise InputError(
            f"MuJoCo cannot load the robot MJCF: {' '.join(str(err).split())}", where=str(xml)
        ) from None


def prepare_robot(source: RobotSource) -> PreparedRobot:
    """Load ``source`` and make it a fixed-base robot standing in its home pose at the origin."""
    notes: list[str] = []
    files: dict[str, bytes] = {}
    spec = load_spec(source.xml)
    _embed_files(spec, source.xml, "", files)
    wanted = {**_keyframe_home(spec, files, source), **source.home}
    if source.hand is not None:
        hand = load_spec(source.hand.xml)
        _embed_files(hand, source.hand.xml, "hand", files)
        _attach_hand(spec, hand, source.hand.site, source.hand.yaw_deg, source.name)
        notes.append(
            f"hand {source.hand.xml.name} attached at site {source.hand.site!r} "
            f"(yaw {source.hand.yaw_deg:g} deg)"
        )
    for key in list(spec.keys):
        notes.append(f"keyframe {key.name or '(unnamed)'!r} dropped")
        spec.delete(key)
    _fix_base(spec, notes)
    _hold_still(spec, notes)
    spec.assets = dict(files)  # kept with the spec: copies and re-parses need them
    model = _compile(spec, files, source)
    home = _home_pose(model, wanted, source)
    _apply_home(spec, model, home)
    model = _compile(spec, files, source)
    _check_home(model, home, source)
    if _exclude_self_contacts(spec, model, source, notes):
        model = _compile(spec, files, source)
    return PreparedRobot(source, spec, files, home, footprint_of(model), notes)


def _compile(spec: mujoco.MjSpec, files: dict[str, bytes], source: RobotSource) -> mujoco.MjModel:
    try:
        return compile_spec(spec, files)
    except ValueError as err:
        raise InputError(
            f"MuJoCo rejected the robot: {' '.join(str(err).split())}", where=str(source.xml)
        ) from None


def _embed_files(spec: mujoco.MjSpec, xml: Path, sub: str, files: dict[str, bytes]) -> None:
    """Read every file ``spec`` refers to and rename it to its key under ``robot/``."""
    base = Path(spec.modelfiledir) if spec.modelfiledir else xml.parent
    dirs = {"mesh": spec.meshdir, "texture": spec.texturedir, "other": ""}
    items: list[
        tuple[mujoco.MjsMesh | mujoco.MjsTexture | mujoco.MjsHField | mujoco.MjsSkin, str]
    ] = [(m, "mesh") for m in spec.meshes]
    items += [(t, "texture") for t in spec.textures]
    items += [(h, "other") for h in spec.hfields]
    items += [(s, "other") for s in spec.skins]
    for element, kind in items:
        name = element.file
        if not name:
            continue
        path = Path(name)
        if not path.is_absolute():
            path = base / dirs[kind] / path
        try:
            data = path.read_bytes()
        except OSError as err:
            raise InputError(
                f"cannot read a file the robot needs: {err.strerror or err}", where=str(path)
            ) from None
        element.file = _register(files, sub, name, data)
    if any(t.cubefiles and any(t.cubefiles) for t in spec.textures):
        raise InputError("robot textures made of six cube files are not supported", where=str(xml))
    spec.meshdir = ""
    spec.texturedir = ""


def _register(files: dict[str, bytes], sub: str, name: str, data: bytes) -> str:
    """The key of ``data`` under ``robot/``: identical bytes share one key."""
    for key, existing in files.items():
        if existing == data:
            return key
    clean = _UNSAFE.sub("_", name.replace("\\", "/")).lstrip("/")
    clean = "/".join(p for p in clean.split("/") if p not in ("", ".", ".."))
    key = "/".join(p for p in (FILE_ROOT, sub, clean) if p)
    if key in files:
        stem, dot, ext = key.rpartition(".")
        key = f"{stem}-{hashlib.sha1(data).hexdigest()[:8]}{dot}{ext}"
    files[key] = data
    return key


def _attach_hand(
    spec: mujoco.MjSpec, hand: mujoco.MjSpec, site_name: str, yaw_deg: float, robot: str
) -> None:
    site = spec.site(site_name)
    if site is None:
        raise InputError(f"the arm has no site {site_name!r} to attach its hand", where=robot)
    quat = np.zeros(4)
    mujoco.mju_mulQuat(quat, _unit(site.quat), _axis_quat((0.0, 0.0, 1.0), math.radians(yaw_deg)))
    mount = site.parent.add_body(name="hand_mount", pos=list(site.pos), quat=list(quat))
    spec.attach(hand, prefix=HAND_PREFIX, frame=mount.add_frame())


def _fix_base(spec: mujoco.MjSpec, notes: list[str]) -> None:
    for body in spec.worldbody.bodies:
        for joint in list(body.joints):
            if joint.type == mujoco.mjtJoint.mjJNT_FREE:
                notes.append(f"free joint {joint.name or '(unnamed)'!r} removed: fixed base")
                spec.delete(joint)


def _hold_still(spec: mujoco.MjSpec, notes: list[str]) -> None:
    for body in spec.bodies:
        if body.name != "world":
            body.gravcomp = 1.0
    for joint in spec.joints:
        damping = np.array(joint.damping, dtype=float)
        if np.any(damping < 0):
            notes.append(
                f"joint {joint.name!r}: negative damping {float(damping.min()):g} set to 0"
            )
            joint.damping = list(np.maximum(damping, 0.0))
    notes.append("gravity compensation on every body: the robot holds its pose unpowered")


def _keyframe_home(
    spec: mujoco.MjSpec, files: dict[str, bytes], source: RobotSource
) -> dict[str, float]:
    """Hinge and slide values of the MJCF's own keyframe ``home`` (empty when it has none)."""
    if not any(key.name == HOME_KEY for key in spec.keys):
        return {}
    model = _compile(spec.copy(), files, source)
    qpos = model.key(HOME_KEY).qpos
    return {
        model.joint(j).name: float(qpos[model.jnt_qposadr[j]])
        for j in range(model.njnt)
        if int(model.jnt_type[j]) in _SLIDE_OR_HINGE and model.joint(j).name
    }


def _home_pose(
    model: mujoco.MjModel, wanted: dict[str, float], source: RobotSource
) -> dict[str, float]:
    """Joint name -> initial value: ``wanted``'s, else qpos0 (moved into the range if outside)."""
    known = {model.joint(j).name for j in range(model.njnt)}
    unknown = sorted(set(wanted) - known)
    if unknown:
        raise InputError(f"home pose names unknown joints: {', '.join(unknown)}", where=source.name)
    home = {}
    for j in range(model.njnt):
        if int(model.jnt_type[j]) not in _SLIDE_OR_HINGE:
            continue
        name = model.joint(j).name
        value = float(model.qpos0[model.jnt_qposadr[j]])
        if name in wanted:
            value = wanted[name]
        elif model.jnt_limited[j]:
            lo, hi = (float(v) for v in model.jnt_range[j])
            if not lo <= value <= hi:
                inset = HOME_INSET * (hi - lo)
                value = min(max(value, lo + inset), hi - inset)
        home[name] = float(value)
    return home


def _apply_home(spec: mujoco.MjSpec, model: mujoco.MjModel, home: dict[str, float]) -> None:
    """Make ``home`` the initial pose by moving bodies about their joints (see module doc)."""
    moved: set[str] = set()
    for joint in spec.joints:
        if int(joint.type) not in _SLIDE_OR_HINGE or joint.name not in home:
            continue
        j = model.joint(joint.name).id
        current = float(model.qpos0[model.jnt_qposadr[j]])
        delta = home[joint.name] - current
        if abs(delta) < 1e-12:
            continue
        body = joint.parent
        if body.name in moved:
            raise InputError(
                f"body {body.name!r} has several joints away from their home values",
                where=joint.name,
                fix="give a home pose at the initial position of all but one of them",
            )
        moved.add(body.name)
        axis = np.array(joint.axis, dtype=float)
        axis /= np.linalg.norm(axis)
        pos = np.array(joint.pos, dtype=float)
        if joint.type == mujoco.mjtJoint.mjJNT_HINGE:
            turn = _axis_quat(axis, delta)
            rot = np.zeros(9)
            mujoco.mju_quat2Mat(rot, turn)
            shift = pos - rot.reshape(3, 3) @ pos
        else:
            turn = np.array([1.0, 0.0, 0.0, 0.0])
            shift = axis * delta
        body_quat = _body_quat(spec, body)
        body_rot = np.zeros(9)
        mujoco.mju_quat2Mat(body_rot, body_quat)
        body.pos = list(np.array(body.pos) + body_rot.reshape(3, 3) @ shift)
        quat = np.zeros(4)
        mujoco.mju_mulQuat(quat, body_quat, turn)
        body.quat = list(quat)
        scale = 180.0 / math.pi if _degrees(joint) else 1.0
        joint.ref = (current + delta) * scale


def _degrees(joint: mujoco.MjsJoint) -> bool:
    return joint.type == mujoco.mjtJoint.mjJNT_HINGE and bool(joint.compiler.degree)


def _body_quat(spec: mujoco.MjSpec, body: mujoco.MjsBody) -> np.ndarray:
    """The body's orientation as a unit quaternion, resolving euler/axisangle/... forms."""
    if body.alt.type != mujoco.mjtOrientation.mjORIENTATION_QUAT:
        quat = np.array(
            spec.resolve_orientation(bool(body.compiler.degree), body.compiler.eulerseq, body.alt)
        )
        body.alt.type = mujoco.mjtOrientation.mjORIENTATION_QUAT
        return _unit(quat)
    return _unit(body.quat)


def _unit(quat: object) -> np.ndarray:
    q = np.array(quat, dtype=float)
    return q / np.linalg.norm(q)


def _axis_quat(axis: object, angle: float) -> np.ndarray:
    quat = np.zeros(4)
    mujoco.mju_axisAngle2Quat(quat, np.array(axis, dtype=float), angle)
    return quat


def _check_home(model: mujoco.MjModel, home: dict[str, float], source: RobotSource) -> None:
    for name, value in home.items():
        j = model.joint(name).id
        if abs(model.qpos0[model.jnt_qposadr[j]] - value) > 1e-6:
            raise InputError(f"could not set joint {name!r} to its home value", where=source.name)
        if model.jnt_limited[j]:
            lo, hi = model.jnt_range[j]
            if not lo <= value <= hi:
                raise InputError(
                    f"home value {value:.4g} of joint {name!r} is outside its range "
                    f"[{lo:.4g}, {hi:.4g}]",
                    where=source.name,
                )


def _exclude_self_contacts(
    spec: mujoco.MjSpec, model: mujoco.MjModel, source: RobotSource, notes: list[str]
) -> bool:
    """Exclude contacts between pairs of bodies that interpenetrate in the home pose.

    Links modelled by the convex hulls of non-convex meshes often overlap their neighbours'
    hulls; left alone, those contacts would push the robot out of its pose at t = 0.
    Returns whether anything was excluded.
    """
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    pairs = set()
    for contact in data.contact[: data.ncon]:
        if contact.dist < -SELF_TOLERANCE_M:
            b1 = int(model.geom_bodyid[contact.geom1])
            b2 = int(model.geom_bodyid[contact.geom2])
            pairs.add((min(b1, b2), max(b1, b2), -float(contact.dist)))
    done = set()
    for b1, b2, depth in sorted(pairs):
        n1, n2 = model.body(b1).name, model.body(b2).name
        if not n1 or not n2:
            raise InputError(
                "the robot's home pose interpenetrates itself between unnamed bodies",
                where=source.name,
                fix="name its bodies or give a collision-free home pose",
            )
        if (n1, n2) in done:
            continue
        done.add((n1, n2))
        spec.add_exclude(bodyname1=n1, bodyname2=n2)
        notes.append(
            f"contacts between {n1!r} and {n2!r} excluded: they overlap by {depth * 1000:.1f} mm "
            "in the home pose"
        )
    return bool(done)


def footprint_of(model: mujoco.MjModel) -> Footprint:
    """The floor outline, reach direction and height of a robot compiled on its own."""
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    geoms = shapes.collider_ids(model)
    if geoms.size == 0:
        raise InputError("the robot has no collision geometry", fix="give it colliders")
    points = np.vstack([shapes.world_points(model, data, g) for g in geoms])
    hull = shapely.MultiPoint([tuple(p) for p in points[:, :2]]).convex_hull
    if hull.geom_type != "Polygon":
        hull = hull.buffer(0.01)
    outline = [(round(float(x), 4), round(float(y), 4)) for x, y in hull.exterior.coords[:-1]]
    radius = float(np.max(np.linalg.norm(points[:, :2], axis=1)))
    centroid = hull.centroid
    front = 0.0
    if math.hypot(centroid.x, centroid.y) > 0.02:
        front = math.degrees(math.atan2(centroid.y, centroid.x))
    return Footprint(
        radius_m=round(radius, 4),
        height_m=round(float(points[:, 2].max()), 4),
        front_deg=round(front, 3),
        polygon=outline,
    )
