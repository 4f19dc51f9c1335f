"""URDF files of the scene's articulated assets, for simulators that take URDF.

An articulated asset is a top-level body of the model with a hinge or slide joint somewhere in
its subtree: a door (its leaves hang from the world on hinges; the URDF's root link is the door's
frame, at the door's position on the floor) or a piece of furniture with jointed parts (its
root link is the object's body, which floats). Every body becomes a link (bodies welded to it
without a joint are merged into it), every hinge a ``revolute`` joint (``continuous`` when
unlimited), every slide a ``prismatic`` one, with MuJoCo's range (from the pose the links are
written at, whose joint values are URDF's zero), damping and frictionloss (``<dynamics>``; URDF
has no joint springs); a body with several joints gets massless-looking helper links between them.
A link's frame is its joint's anchor (URDF joints turn about their child link's origin), so
its ``<visual>``, ``<collision>`` and ``<inertial>`` origins are shifted accordingly. Inertials
are MuJoCo's (mass, centre of mass, principal inertia with its axes as ``rpy``).

Meshes are Wavefront OBJ files under ``meshes/`` (one per visual or hull shape, shared by
content), referenced relatively; box, sphere and cylinder colliders stay URDF primitives, and
capsules and ellipsoids become meshes. Each file carries a ``<mujoco><compiler .../></mujoco>``
element (ignored by other readers) so that MuJoCo loads it with its visuals and mesh folder.
Colours are the geoms' material colours; textures are not carried.
"""

from __future__ import annotations

import hashlib
import math
import xml.etree.ElementTree as ET
from collections.abc import Sequence
from dataclasses import dataclass, field

import mujoco
import numpy as np

from holomj.formats.model_geometry import ModelGeometry, Triangles
from holomj.formats.welded_bodies import welded, welded_inertia
from holomj.mjcf import names
from holomj.spec.scene import SceneSpec
from holomj.version import __version__

MESHES_DIR = "meshes"
_HELPER_INERTIA = 1e-6


@dataclass
class UrdfFile:
    """One articulated asset: its id, the URDF text and the mesh files it names (relative
    path -> bytes), and its joints as (name, type, lower, upper) for reports and tests."""

    asset_id: str
    urdf: str
    meshes: dict[str, bytes] = field(default_factory=dict)
    joints: list[tuple[str, str, float | None, float | None]] = field(default_factory=list)


def articulated_urdfs(
    model: mujoco.MjModel, scene: SceneSpec, *, qpos: np.ndarray | None = None
) -> list[UrdfFile]:
    """One :class:`UrdfFile` per articulated asset of ``scene`` as compiled into ``model``, in
    the model's body order (doors by door id, objects by object id, other bodies by name)."""
    geo = ModelGeometry(model, qpos)
    objects = {names.object_body(o.id): o.id for o in scene.objects}
    leaves: dict[str, list[int]] = {}
    door_ids = {door.id for door in scene.doors}
    for door in scene.doors:
        for index in range(2):
            body = mujoco.mj_name2id(
                model, mujoco.mjtObj.mjOBJ_BODY, names.door_leaf_body(door.id, index)
            )
            if body >= 0:
                leaves.setdefault(door.id, []).append(body)
    leaf_bodies = {b for bodies in leaves.values() for b in bodies}
    out: list[UrdfFile] = []
    for door in scene.doors:
        bodies = [b for b in leaves.get(door.id, []) if _articulated(geo, b, top=True)]
        if bodies:
            out.append(_door_urdf(geo, door.id, door.position, bodies))
    for body in geo.children[0]:
        if body in leaf_bodies or not _articulated(geo, body, top=False):
            continue
        name = geo.body_name(body)
        ident = objects.get(name, name)
        if ident in door_ids:
            continue
        out.append(_object_urdf(geo, ident, body))
    return out


def _moving_joints(geo: ModelGeometry, body: int) -> list[int]:
    return [
        j
        for j in geo.body_joints(body)
        if int(geo.model.jnt_type[j]) in (mujoco.mjtJoint.mjJNT_HINGE, mujoco.mjtJoint.mjJNT_SLIDE)
    ]


def _articulated(geo: ModelGeometry, body: int, top: bool) -> bool:
    """Has ``body``'s subtree a hinge or slide (on ``body`` itself only when ``top``)?"""
    if top and _moving_joints(geo, body):
        return True
    return any(_articulated(geo, child, top=True) for child in geo.children[body])


class _Writer:
    """Builds one URDF document."""

    def __init__(self, geo: ModelGeometry, asset_id: str) -> None:
        self.geo = geo
        self.model = geo.model
        self.robot = ET.Element("robot", name=_xml_name(asset_id))
        self.robot.append(ET.Comment(f" holomj {__version__}: {asset_id} "))
        compiler = ET.SubElement(ET.SubElement(self.robot, "mujoco"), "compiler")
        compiler.set("meshdir", ".")
        compiler.set("strippath", "false")
        compiler.set("discardvisual", "false")
        compiler.set("balanceinertia", "true")
        self.file = UrdfFile(asset_id, "")
        self._link_names: set[str] = set()

    def link_name(self, name: str) -> str:
        base = _xml_name(name)
        candidate, index = base, 1
        while candidate in self._link_names:
            candidate = f"{base}_{index}"
            index += 1
        self._link_names.add(candidate)
        return candidate

    def link(
        self,
        name: str,
        geoms: Sequence[tuple[int, np.ndarray, np.ndarray]],
        inertial: tuple[float, np.ndarray, np.ndarray, np.ndarray] | None,
    ) -> ET.Element:
        """A link with ``geoms`` (geom id, position and rotation in the link frame) and
        ``inertial`` (mass, centre, principal inertia, principal axes matrix; None: none)."""
        link = ET.SubElement(self.robot, "link", name=name)
        if inertial is not None:
            mass, centre, principal, axes = inertial
            element = ET.SubElement(link, "inertial")
            _origin(element, centre, axes)
            ET.SubElement(element, "mass", value=_f(mass))
            ET.SubElement(
                element,
                "inertia",
                ixx=_f(principal[0]),
                ixy="0",
                ixz="0",
                iyy=_f(principal[1]),
                iyz="0",
                izz=_f(principal[2]),
            )
        for geom, pos, rot in geoms:
            if self.geo.is_visible(geom):
                self._visual(link, geom, pos, rot)
            if self.geo.is_collider(geom):
                self._collision(link, geom, pos, rot)
        return link

    def _visual(self, link: ET.Element, geom: int, pos: np.ndarray, rot: np.ndarray) -> None:
        tris = self.geo.triangles(geom)
        if tris is None or tris.empty:
            return
        visual = ET.SubElement(link, "visual", name=_xml_name(self.geo.geom_name(geom)))
        _origin(visual, pos, rot)
        ET.SubElement(ET.SubElement(visual, "geometry"), "mesh", filename=self._mesh(tris))
        look = self.geo.look(geom)
        material = ET.SubElement(visual, "material", name=_xml_name(look.name))
        ET.SubElement(material, "color", rgba=" ".join(_f(round(c, 4)) for c in look.rgba))

    def _collision(self, link: ET.Element, geom: int, pos: np.ndarray, rot: np.ndarray) -> None:
        kind = int(self.model.geom_type[geom])
        size = self.model.geom_size[geom]
        name = _xml_name(self.geo.geom_name(geom))
        if self.geo.is_visible(geom):  # its visual has the plain name
            name = f"{name}_collision"
        collision = ET.Element("collision", name=name)
        _origin(collision, pos, rot)
        shape = ET.SubElement(collision, "geometry")
        if kind == mujoco.mjtGeom.mjGEOM_BOX:
            ET.SubElement(shape, "box", size=" ".join(_f(2 * v) for v in size[:3]))
        elif kind == mujoco.mjtGeom.mjGEOM_SPHERE:
            ET.SubElement(shape, "sphere", radius=_f(size[0]))
        elif kind == mujoco.mjtGeom.mjGEOM_CYLINDER:
            ET.SubElement(shape, "cylinder", radius=_f(size[0]), length=_f(2 * size[1]))
        else:
            tris = self.geo.triangles(geom)
            if tris is None or tris.empty:
                return
            ET.SubElement(shape, "mesh", filename=self._mesh(tris))
        link.append(collision)

    def _mesh(self, tris: Triangles) -> str:
        data = _obj_bytes(tris)
        path = f"{MESHES_DIR}/{hashlib.sha1(data).hexdigest()[:16]}.obj"
        self.file.meshes[path] = data
        return path

    def joint(
        self,
        joint: int | None,
        parent: str,
        child: str,
        pos: np.ndarray,
        rot: np.ndarray,
        axis: np.ndarray | None = None,
    ) -> None:
        """A joint from link ``parent`` to ``child`` whose frame is at ``pos``, ``rot`` in the
        parent's frame (``joint`` None: fixed)."""
        model = self.model
        if joint is None:
            element = ET.SubElement(self.robot, "joint", name=f"{child}_fixed", type="fixed")
            kind = "fixed"
            low = high = None
        else:
            hinge = model.jnt_type[joint] == mujoco.mjtJoint.mjJNT_HINGE
            limited = bool(model.jnt_limited[joint])
            kind = ("revolute" if limited else "continuous") if hinge else "prismatic"
            name = model.joint(joint).name or f"joint_{joint}"
            element = ET.SubElement(self.robot, "joint", name=_xml_name(name), type=kind)
            low = high = None
            if limited or not hinge:
                # from the pose the links are written at: the joint's value there is URDF's 0
                q = float(self.geo.data.qpos[model.jnt_qposadr[joint]])
                low, high = (float(v) - q for v in model.jnt_range[joint])
                if not limited:  # an unlimited slide: URDF needs limits; wide ones
                    low, high = -1e3, 1e3
            self.file.joints.append((_xml_name(name), kind, low, high))
        _origin(element, pos, rot)
        ET.SubElement(element, "parent", link=parent)
        ET.SubElement(element, "child", link=child)
        if joint is None:
            return
        ET.SubElement(
            element,
            "axis",
            xyz=" ".join(_f(v) for v in (axis if axis is not None else model.jnt_axis[joint])),
        )
        if low is not None and high is not None:
            ET.SubElement(
                element, "limit", lower=_f(low), upper=_f(high), effort="1000", velocity="10"
            )
        dof = int(model.jnt_dofadr[joint])
        ET.SubElement(
            element,
            "dynamics",
            damping=_f(model.dof_damping[dof]),
            friction=_f(model.dof_frictionloss[dof]),
        )

    def text(self) -> str:
        ET.indent(self.robot, space="  ")
        body = ET.tostring(self.robot, encoding="unicode")
        self.file.urdf = '<?xml version="1.0"?>\n' + body + "\n"
        return self.file.urdf


def _door_urdf(
    geo: ModelGeometry, door_id: str, position: Sequence[float], leaves: list[int]
) -> UrdfFile:
    writer = _Writer(geo, door_id)
    base_pos = np.array([float(position[0]), float(position[1]), 0.0])
    frame_geoms = [
        g
        for g in geo.body_geoms(0)
        if geo.geom_name(g).startswith(f"{door_id}/") and (geo.is_visible(g) or geo.is_collider(g))
    ]
    base = writer.link_name(f"{door_id}/frame")
    writer.link(
        base,
        [(g, geo.geom_pose(g)[0] - base_pos, geo.geom_pose(g)[1]) for g in frame_geoms],
        None,
    )
    for leaf in leaves:
        _subtree(writer, leaf, base, base_pos, np.eye(3))
    writer.text()
    return writer.file


def _object_urdf(geo: ModelGeometry, ident: str, body: int) -> UrdfFile:
    writer = _Writer(geo, ident)
    pos, rot = geo.body_pose(body)
    _link_tree(writer, body, writer.link_name(ident), pos, rot)
    writer.text()
    return writer.file


def _subtree(
    writer: _Writer, body: int, parent: str, parent_pos: np.ndarray, parent_rot: np.ndarray
) -> None:
    """``body`` as links below link ``parent`` (whose frame is ``parent_pos``, ``parent_rot``
    in the world), through its joints."""
    geo = writer.geo
    pos, rot = geo.body_pose(body)
    joints = _moving_joints(geo, body)
    name = geo.body_name(body)
    if not joints:  # a free or ball body below a link: fixed here (URDF has neither)
        link = writer.link_name(name)
        writer.joint(None, parent, link, parent_rot.T @ (pos - parent_pos), parent_rot.T @ rot)
        _link_tree(writer, body, link, pos, rot)
        return
    # the link frame is the (last) joint's anchor, axes as the body's
    previous, previous_pos, previous_rot = parent, parent_pos, parent_rot
    for index, joint in enumerate(joints):
        anchor = pos + rot @ geo.model.jnt_pos[joint]
        last = index == len(joints) - 1
        link = writer.link_name(name if last else f"{name}__{index}")
        writer.joint(
            joint,
            previous,
            link,
            previous_rot.T @ (anchor - previous_pos),
            previous_rot.T @ rot,
        )
        if not last:
            writer.link(
                link, [], (_HELPER_INERTIA, np.zeros(3), np.full(3, _HELPER_INERTIA), np.eye(3))
            )
        previous, previous_pos, previous_rot = link, anchor, rot
    _link_tree(writer, body, previous, previous_pos, rot)


def _link_tree(
    writer: _Writer, body: int, link: str, link_pos: np.ndarray, link_rot: np.ndarray
) -> None:
    """The contents of link ``link`` (frame ``link_pos``, ``link_rot`` in the world): ``body``
    and the bodies welded to it; then the jointed children below it."""
    geo = writer.geo
    members = welded(geo, body)
    geoms = []
    for member in members:
        for geom in geo.body_geoms(member):
            gpos, grot = geo.geom_pose(geom)
            geoms.append((geom, link_rot.T @ (gpos - link_pos), link_rot.T @ grot))
    writer.link(link, geoms, welded_inertia(geo, members, link_pos, link_rot))
    for member in members:
        for child in geo.children[member]:
            if geo.model.body_jntnum[child]:
                _subtree(writer, child, link, link_pos, link_rot)


def _origin(parent: ET.Element, pos: np.ndarray, rot: np.ndarray) -> None:
    rpy = _rpy(rot)
    attrs = {}
    if np.abs(pos).max() > 1e-12:
        attrs["xyz"] = " ".join(_f(v) for v in pos)
    if np.abs(rpy).max() > 1e-12:
        attrs["rpy"] = " ".join(_f(v) for v in rpy)
    ET.SubElement(parent, "origin", attrs)


def _rpy(rot: np.ndarray) -> np.ndarray:
    """URDF's fixed-axis roll, pitch, yaw (R = Rz(yaw) Ry(pitch) Rx(roll))."""
    r = np.asarray(rot, dtype=float)
    pitch = math.asin(max(-1.0, min(1.0, -r[2, 0])))
    if abs(r[2, 0]) < 1 - 1e-9:
        roll = math.atan2(r[2, 1], r[2, 2])
        yaw = math.atan2(r[1, 0], r[0, 0])
    else:  # gimbal lock: put it all in yaw
        roll = 0.0
        yaw = math.atan2(-r[0, 1], r[1, 1])
    return np.array([roll, pitch, yaw])


def _obj_bytes(tris: Triangles) -> bytes:
    lines = [f"v {x:.7g} {y:.7g} {z:.7g}" for x, y, z in tris.positions.astype(float)]
    lines += [f"vn {x:.5g} {y:.5g} {z:.5g}" for x, y, z in tris.normals.astype(float)]
    lines += [f"f {a}//{a} {b}//{b} {c}//{c}" for a, b, c in (tris.faces.astype(int) + 1)]
    return ("\n".join(lines) + "\n").encode("ascii")


def _xml_name(name: str) -> str:
    return "".join(c if c.isalnum() or c in "_-." else "_" for c in name) or "_"


def _f(value: float) -> str:
    text = f"{float(value):.9g}"
    return "0" if text in ("-0", "0") else text
