"""Read MJCF files (MuJoCo XML) into the kinematics of an articulated asset.

MuJoCo itself loads the file (``MjModel.from_xml_path``: includes, defaults, ``childclass``,
``angle="degree"``, ``meshdir``, mesh ``scale`` and ``euler`` as MuJoCo reads them), so what is
imported is what MuJoCo would simulate. Then, at the model's default pose (``qpos0``):

- every body is a link; the world body too (its geoms are fixed);
- a body without joints is welded to its parent, a body whose one joint is ``free`` and whose
  parent is the world is fixed (the asset is placed by the scene), a body with one ``hinge`` or
  ``slide`` joint moves on it (its range; an unlimited hinge turns freely, an unlimited slide is
  refused); a ``ball`` joint, a ``free`` joint deeper in the tree or two joints on one body are
  refused, naming the body;
- a link's meshes are its visual geoms (``contype = conaffinity = 0``) when the file has any,
  else all its geoms: meshes as MuJoCo compiled them, primitives (box, sphere, capsule,
  cylinder, ellipsoid) triangulated; planes, height fields and SDFs are skipped with a warning;
  colours from the geom's material, else its ``rgba`` (textures are not carried over);
- joint damping, friction loss, armature, stiffness and spring reference come from the file.

The file is Z-up like every MJCF (MuJoCo's frame: metres, Z up).
"""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np

from asset_pipeline.kinematics import JointInfo, Kinematics, LinkGeometry, primitive
from asset_pipeline.load import MeshMaterial, MeshPart
from asset_pipeline.xml_tree import parse_xml, read_text
from holomj.errors import FormatError

MJCF_SUFFIXES = (".xml", ".mjcf")
WORLD = "world"
_PRIMITIVES = {
    mujoco.mjtGeom.mjGEOM_BOX: "box",
    mujoco.mjtGeom.mjGEOM_SPHERE: "sphere",
    mujoco.mjtGeom.mjGEOM_CAPSULE: "capsule",
    mujoco.mjtGeom.mjGEOM_CYLINDER: "cylinder",
    mujoco.mjtGeom.mjGEOM_ELLIPSOID: "ellipsoid",
}


def is_mjcf(path: Path) -> bool:
    """Whether ``path`` is an MJCF file (an ``.xml``/``.mjcf`` whose root is ``<mujoco>``)."""
    path = Path(path)
    if path.suffix.lower() not in MJCF_SUFFIXES or not path.is_file():
        return False
    return root_tag(path) == "mujoco"


def root_tag(path: Path) -> str | None:
    """The root element of an XML file (None when it is not readable XML)."""
    try:
        data = Path(path).read_bytes()
        return parse_xml(data, str(path)).tag
    except (OSError, FormatError):
        return None


def compile_mjcf(path: Path) -> mujoco.MjModel:
    """MuJoCo's model of the file; FormatError with MuJoCo's message (element and line)."""
    read_text(path)
    try:
        return mujoco.MjModel.from_xml_path(str(path))
    except (ValueError, mujoco.FatalError) as err:
        raise FormatError(
            f"MuJoCo cannot load it: {' '.join(str(err).split())}", where=str(path)
        ) from None


def check_mjcf(path: Path) -> None:
    """Load ``path`` and check its tree (see the module docstring) without placing meshes."""
    model = compile_mjcf(path)
    _tree(model, str(path))


def load_mjcf(path: Path | str, max_faces: int = 2_000_000) -> Kinematics:
    """The kinematics of the MJCF file ``path`` at its default pose."""
    path = Path(path)
    where = str(path)
    model = compile_mjcf(path)
    parent_joint, warnings = _tree(model, where)
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    visual_only = (model.geom_contype == 0) & (model.geom_conaffinity == 0)
    names = [_body_name(model, b) for b in range(model.nbody)]
    links: dict[str, LinkGeometry] = {}
    faces = 0
    for body in range(model.nbody):
        geoms = np.flatnonzero(model.geom_bodyid == body)
        shown = geoms[visual_only[geoms]] if visual_only.any() else geoms
        if visual_only.any() and len(shown) == 0:
            shown = geoms
        parts = []
        for geom in shown:
            part = _geom_part(model, data, int(geom), warnings)
            if part is not None:
                parts.append(part)
                faces += len(part.faces)
        if faces > max_faces:
            raise FormatError(f"the meshes have more than {max_faces} faces", where=where)
        links[names[body]] = LinkGeometry(names[body], parts, f"body {names[body]!r}")
    joints = []
    for body in range(1, model.nbody):
        parent = names[int(model.body_parentid[body])]
        joint = parent_joint.get(body)
        if joint is None:
            joints.append(
                JointInfo(
                    name=f"{names[body]}_weld",
                    type="fixed",
                    parent=parent,
                    child=names[body],
                    axis=np.array([1.0, 0.0, 0.0]),
                    anchor=np.zeros(3),
                    range=None,
                    where=f"body {names[body]!r}",
                )
            )
            continue
        joints.append(_joint_info(model, data, joint, parent, names[body]))
    return Kinematics(
        format="mjcf",
        name=path.stem,
        links=links,
        joints=joints,
        up_axis="z",
        warnings=warnings,
    )


def _tree(model: mujoco.MjModel, where: str) -> tuple[dict[int, int], list[str]]:
    """Body -> its moving joint (hinge or slide); refuse what a part cannot be."""
    moving: dict[int, int] = {}
    warnings: list[str] = []
    for body in range(1, model.nbody):
        count = int(model.body_jntnum[body])
        name = _body_name(model, body)
        if count == 0:
            continue
        first = int(model.body_jntadr[body])
        if count > 1:
            kinds = ", ".join(_joint_label(model, first + k) for k in range(count))
            raise FormatError(
                f"body {name!r} has {count} joints ({kinds})",
                where=where,
                fix="a moving part turns on one hinge or slides on one slide joint",
            )
        kind = int(model.jnt_type[first])
        if kind == mujoco.mjtJoint.mjJNT_FREE:
            if int(model.body_parentid[body]) != 0:
                raise FormatError(
                    f"body {name!r}: a free joint inside the tree ({_joint_label(model, first)})",
                    where=where,
                )
            warnings.append(
                f"free joint of body {name!r} dropped: the asset is placed by the scene"
            )
            continue
        if kind == mujoco.mjtJoint.mjJNT_BALL:
            raise FormatError(
                f"body {name!r}: ball joint {_joint_label(model, first)} is not supported",
                where=where,
                fix="use hinge or slide joints",
            )
        if kind == mujoco.mjtJoint.mjJNT_SLIDE and not model.jnt_limited[first]:
            raise FormatError(
                f"body {name!r}: slide joint {_joint_label(model, first)} has no range",
                where=where,
                fix='give it range="low high"',
            )
        moving[body] = first
    return moving, warnings


def _joint_info(
    model: mujoco.MjModel, data: mujoco.MjData, joint: int, parent: str, child: str
) -> JointInfo:
    hinge = int(model.jnt_type[joint]) == mujoco.mjtJoint.mjJNT_HINGE
    qpos = int(model.jnt_qposadr[joint])
    dof = int(model.jnt_dofadr[joint])
    limited = bool(model.jnt_limited[joint])
    low, high = model.jnt_range[joint]
    return JointInfo(
        name=model.joint(joint).name or f"{child}_{'hinge' if hinge else 'slide'}",
        type="hinge" if hinge else "slide",
        parent=parent,
        child=child,
        axis=np.array(data.xaxis[joint], dtype=float),
        anchor=np.array(data.xanchor[joint], dtype=float),
        range=(float(low), float(high)) if limited else None,
        value=float(model.qpos0[qpos]),
        damping=float(model.dof_damping[dof]),
        frictionloss=float(model.dof_frictionloss[dof]),
        armature=float(model.dof_armature[dof]),
        stiffness=float(model.jnt_stiffness[joint]),
        springref=float(model.qpos_spring[qpos]),
        where=f"joint {_joint_label(model, joint)} of body {child!r}",
    )


def _geom_part(
    model: mujoco.MjModel, data: mujoco.MjData, geom: int, warnings: list[str]
) -> MeshPart | None:
    kind = int(model.geom_type[geom])
    if kind == mujoco.mjtGeom.mjGEOM_MESH:
        mesh = int(model.geom_dataid[geom])
        first, count = int(model.mesh_vertadr[mesh]), int(model.mesh_vertnum[mesh])
        face, nface = int(model.mesh_faceadr[mesh]), int(model.mesh_facenum[mesh])
        part = MeshPart(
            vertices=np.array(model.mesh_vert[first : first + count], dtype=np.float64),
            faces=np.array(model.mesh_face[face : face + nface], dtype=np.int64),
            uv=None,
            material=MeshMaterial(rgba=(0.7, 0.7, 0.7, 1.0)),
        )
    elif kind in _PRIMITIVES:
        size = model.geom_size[geom]
        name = _PRIMITIVES[kind]
        dims = {
            "box": tuple(2 * size),
            "sphere": (size[0],),
            "capsule": (size[0], 2 * size[1]),
            "cylinder": (size[0], 2 * size[1]),
            "ellipsoid": tuple(size),
        }[name]
        part = primitive(name, dims)
    else:
        label = model.geom(geom).name or f"geom {geom}"
        shape = mujoco.mjtGeom(kind).name.removeprefix("mjGEOM_").lower()
        warnings.append(f"{label}: a {shape} geom is skipped")
        return None
    rot = np.asarray(data.geom_xmat[geom]).reshape(3, 3)
    vertices = part.vertices @ rot.T + data.geom_xpos[geom]
    material = int(model.geom_matid[geom])
    rgba = model.mat_rgba[material] if material >= 0 else model.geom_rgba[geom]
    r, g, b, a = (round(float(v), 4) for v in np.clip(rgba, 0.0, 1.0))
    return MeshPart(
        vertices=vertices, faces=part.faces, uv=None, material=MeshMaterial(rgba=(r, g, b, a))
    )


def _body_name(model: mujoco.MjModel, body: int) -> str:
    if body == 0:
        return WORLD
    return model.body(body).name or f"body_{body}"


def _joint_label(model: mujoco.MjModel, joint: int) -> str:
    kind = mujoco.mjtJoint(int(model.jnt_type[joint])).name.removeprefix("mjJNT_").lower()
    name = model.joint(joint).name
    return f"{name!r} ({kind})" if name else f"#{joint} ({kind})"


def mjcf_files(path: Path) -> list[Path]:
    """The files an MJCF names (meshes, textures, includes, recursively), for cache keys."""
    found: list[Path] = []
    _collect(Path(path), found, set())
    return found


def _collect(path: Path, found: list[Path], seen: set[Path]) -> None:
    if path in seen or not path.is_file():
        return
    seen.add(path)
    try:
        root = parse_xml(path.read_bytes(), str(path))
    except (FormatError, OSError):
        return
    base = path.parent
    dirs = {"mesh": base, "texture": base, "hfield": base, "skin": base}
    for compiler in (n for n in root.iter() if n.tag == "compiler"):
        asset = compiler.attrib.get("assetdir")
        for key in dirs:
            folder = compiler.attrib.get(f"{key}dir") or (
                compiler.attrib.get("meshdir") if key in ("hfield", "skin") else None
            )
            folder = folder or asset
            if folder:
                dirs[key] = base / folder
    for node in root.iter():
        name = node.attrib.get("file")
        if not name:
            continue
        if node.tag == "include":
            _collect(base / name, found, seen)
        elif node.tag in dirs:
            target = dirs[node.tag] / name
            if target.is_file() and target not in found:
                found.append(target)
