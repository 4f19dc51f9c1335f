"""Read URDF files (PartNet-Mobility style) into the kinematics of an articulated asset.

What is read (everything else is ignored, with a warning where it matters):

- ``<robot>`` holding ``<link name>`` and ``<joint name type>`` elements and top-level
  ``<material name><color rgba/></material>`` definitions;
- per link, its ``<visual>`` elements (its ``<collision>`` ones when it has no visual): an
  ``<origin xyz rpy>``, one ``<geometry>`` (``<mesh filename scale>`` of a format the asset
  pipeline loads, ``<box size>``, ``<cylinder radius length>``, ``<sphere radius>``) and an
  optional ``<material>`` colour, used for meshes that carry no material of their own;
- per joint: ``<parent link>``, ``<child link>``, ``<origin xyz rpy>`` (the child's frame in the
  parent's at value 0), ``<axis xyz>`` (in the joint frame, default ``1 0 0``), ``<limit lower
  upper>`` (required for ``revolute`` and ``prismatic``; radians / metres) and ``<dynamics
  damping friction>``. Types: ``revolute`` (a hinge), ``continuous`` (an unlimited hinge),
  ``prismatic`` (a slide), ``fixed``. ``floating`` and ``planar`` are refused. ``rpy`` is roll,
  pitch, yaw about the fixed x, y, z axes: ``R = Rz(yaw) Ry(pitch) Rx(roll)`` (URDF's rule).

Mesh paths are relative to the URDF's folder; ``package://NAME/REST`` is looked up as ``REST``
and ``NAME/REST`` in the URDF's folder and the folders above it (three levels), ``file://`` as
an absolute path. Inertials are ignored: the asset pipeline derives the mass.

Checks, each a one-line :class:`~holomj.errors.FormatError` naming the file and the element
(with its line): not XML or not a ``<robot>``, a xacro macro left unexpanded, a DOCTYPE, a
missing or duplicate name, an unknown link, a joint type other than the four above, a link with
two parent joints, joints forming a cycle, a missing or unreadable number, a zero axis, an
empty or more-than-a-turn range, a missing mesh file or an unsupported mesh format.

**PartNet-Mobility** (SAPIEN's dataset, https://sapien.ucsd.edu) stores one object per folder:
``mobility.urdf``, ``meta.json`` (``model_cat``: the category, e.g. ``StorageFurniture``,
``anno_id``), ``semantics.txt`` (one ``<link> <joint kind> <label>`` line per link, e.g.
``link_0 hinge door``), ``textured_objs/*.obj`` (+ ``.mtl``), ``bounding_box.json`` and
``mobility_v2.json``. Its URDF has an empty root link ``base``, a ``fixed`` joint from it to
the object's body with ``rpy="1.5708 0 -1.5708"`` (the OBJ files are Y-up with the object's
front towards +Z; that turn makes the URDF frame Z-up with the front towards -X), moving links
``link_N`` whose visual origin is minus their joint's origin (so every mesh stays in the shared
frame), and screw joints as a prismatic joint to an empty ``link_N_helper`` plus a continuous
one. The meshes are *not in metres*: each object is normalised to about unit size, so give a
``--size`` (or a sidecar ``size``) to get real dimensions. Joint values 0 are the pose the
meshes are in, which is usually, but not always, inside the limits.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from asset_pipeline.load import FORMATS
from asset_pipeline.xml_tree import (
    XmlNode,
    attr_float,
    attr_floats,
    attr_vec3,
    origin_transform,
    parse_xml,
    positive_sizes,
    read_text,
)
from holomj.errors import FormatError

JOINT_TYPES = ("revolute", "continuous", "prismatic", "fixed")
REFUSED_TYPES = ("floating", "planar")
PACKAGE_LEVELS = 3


# --- the URDF model ---------------------------------------------------------------------------
@dataclass(frozen=True)
class Geometry:
    """One visual (or collision) geometry of a link.

    ``kind``: mesh, box, cylinder or sphere; ``mesh`` the resolved file; ``size``: the box's
    full extents, (radius, length) of a cylinder, (radius,) of a sphere; ``origin`` a 4x4
    transform in the link frame; ``rgba`` the URDF material's colour, if any.
    """

    kind: str
    origin: np.ndarray
    mesh: Path | None = None
    scale: tuple[float, float, float] = (1.0, 1.0, 1.0)
    size: tuple[float, ...] = ()
    rgba: tuple[float, float, float, float] | None = None
    where: str = ""


@dataclass(frozen=True)
class UrdfLink:
    name: str
    geometry: list[Geometry]
    where: str


@dataclass(frozen=True)
class UrdfJoint:
    """A joint as written: type, links, origin (4x4), unit axis (joint frame), limits."""

    name: str
    type: str
    parent: str
    child: str
    origin: np.ndarray
    axis: np.ndarray
    limit: tuple[float, float] | None
    damping: float | None
    friction: float | None
    where: str


@dataclass(frozen=True)
class UrdfModel:
    """A checked URDF: links and joints in file order, the roots, and what was ignored."""

    path: Path
    name: str
    links: dict[str, UrdfLink]
    joints: list[UrdfJoint]
    roots: list[str]
    warnings: list[str]

    def files(self) -> list[Path]:
        """Every mesh file it names, once, in order."""
        seen = [g.mesh for link in self.links.values() for g in link.geometry if g.mesh]
        return list(dict.fromkeys(seen))


def read_urdf(path: Path | str) -> UrdfModel:
    """Read and check the URDF at ``path`` (see the module docstring); no mesh is loaded."""
    path = Path(path)
    return parse_urdf(read_text(path), path)


def parse_urdf(data: bytes | str, path: Path) -> UrdfModel:
    """Check the URDF text ``data`` of the file ``path`` (mesh paths resolve from its folder)."""
    where = str(path)
    root = parse_xml(data, where)
    for node in root.iter():
        if node.tag.startswith("xacro:"):
            raise FormatError(
                f"<{node.tag}> (line {node.line}) is a xacro macro",
                where=where,
                fix="expand it first: xacro model.urdf.xacro > model.urdf",
            )
    if root.tag != "robot":
        raise FormatError(f"the root element is <{root.tag}>, not <robot>", where=where)
    warnings: list[str] = []
    materials = {}
    for node in root.findall("material"):
        name = node.attrib.get("name")
        colour = _colour(node, where)
        if name and colour is not None:
            materials[name] = colour
    links: dict[str, UrdfLink] = {}
    for node in root.findall("link"):
        name = _name(node, where)
        if name in links:
            raise FormatError(f"two links are named {name!r} (line {node.line})", where=where)
        links[name] = _link(node, name, path, materials, warnings)
    if not links:
        raise FormatError("the robot has no <link>", where=where)
    joints: list[UrdfJoint] = []
    seen: set[str] = set()
    parent_of: dict[str, UrdfJoint] = {}
    for node in root.findall("joint"):
        joint = _joint(node, links, where, warnings)
        if joint.name in seen:
            raise FormatError(
                f"two joints are named {joint.name!r} (line {node.line})", where=where
            )
        seen.add(joint.name)
        if joint.child in parent_of:
            other = parent_of[joint.child]
            raise FormatError(
                f"link {joint.child!r} has two parent joints, {other.name!r} and "
                f"{joint.name!r} (line {node.line}): a URDF is a tree",
                where=where,
            )
        parent_of[joint.child] = joint
        joints.append(joint)
    _check_acyclic(links, parent_of, where)
    roots = [name for name in links if name not in parent_of]
    if len(roots) > 1:
        warnings.append(f"{len(roots)} root links ({', '.join(roots)}): all are the fixed part")
    name = root.attrib.get("name", path.stem)
    return UrdfModel(path, name, links, _tree_order(joints, roots), roots, warnings)


def _check_acyclic(links: dict, parent_of: dict[str, UrdfJoint], where: str) -> None:
    for start in links:
        chain = [start]
        link = start
        while link in parent_of:
            link = parent_of[link].parent
            if link in chain:
                loop = chain[chain.index(link) :] + [link]
                joint = parent_of[chain[-1]]
                raise FormatError(
                    f"joints form a cycle through links {' -> '.join(reversed(loop))} "
                    f"(joint {joint.name!r}, {joint.where})",
                    where=where,
                    fix="a URDF must be a tree: remove one joint of the cycle",
                )
            chain.append(link)


def _tree_order(joints: list[UrdfJoint], roots: list[str]) -> list[UrdfJoint]:
    """Joints ordered parents first (breadth first from the roots, file order among siblings)."""
    by_parent: dict[str, list[UrdfJoint]] = {}
    for joint in joints:
        by_parent.setdefault(joint.parent, []).append(joint)
    ordered, queue = [], list(roots)
    while queue:
        link = queue.pop(0)
        for joint in by_parent.get(link, []):
            ordered.append(joint)
            queue.append(joint.child)
    return ordered


def _name(node: XmlNode, where: str) -> str:
    name = node.attrib.get("name", "").strip()
    if not name:
        raise FormatError(f"<{node.tag}> (line {node.line}) has no name", where=where)
    return name


def _link(node: XmlNode, name: str, path: Path, materials: dict, warnings: list[str]) -> UrdfLink:
    where = str(path)
    label = f"link {name!r} (line {node.line})"
    elements = node.findall("visual") or node.findall("collision")
    geometry = []
    for k, element in enumerate(elements):
        what = f"{label} {element.tag} {k} (line {element.line})"
        shape = element.find("geometry")
        if shape is None or not shape.children:
            raise FormatError(f"{what} has no <geometry>", where=where)
        origin = origin_transform(element.find("origin"), what, where)
        rgba = None
        material = element.find("material")
        if material is not None:
            rgba = _colour(material, where)
            if rgba is None:
                rgba = materials.get(material.attrib.get("name", ""))
        geometry.append(_geometry(shape.children[0], origin, rgba, what, path, warnings))
    return UrdfLink(name, geometry, label)


def _geometry(
    node: XmlNode, origin: np.ndarray, rgba, what: str, path: Path, warnings: list[str]
) -> Geometry:
    where = str(path)
    if node.tag == "mesh":
        filename = node.attrib.get("filename", "").strip()
        if not filename:
            raise FormatError(f"{what}: <mesh> (line {node.line}) has no filename", where=where)
        mesh = resolve_mesh(filename, path.parent, f"{what}: mesh {filename!r}", where)
        scale = attr_vec3(node, "scale", what, where, default=(1.0, 1.0, 1.0))
        if any(s == 0 for s in scale):
            raise FormatError(f"{what}: mesh scale {scale} has a zero factor", where=where)
        return Geometry("mesh", origin, mesh=mesh, scale=scale, rgba=rgba, where=what)
    if node.tag == "box":
        size = attr_floats(node, "size", 3, what, where)
        return Geometry(
            "box", origin, size=positive_sizes(size, what, where), rgba=rgba, where=what
        )
    if node.tag == "cylinder":
        size = (attr_float(node, "radius", what, where), attr_float(node, "length", what, where))
        return Geometry(
            "cylinder", origin, size=positive_sizes(size, what, where), rgba=rgba, where=what
        )
    if node.tag == "sphere":
        size = (attr_float(node, "radius", what, where),)
        return Geometry(
            "sphere", origin, size=positive_sizes(size, what, where), rgba=rgba, where=what
        )
    raise FormatError(
        f"{what}: unknown geometry <{node.tag}> (line {node.line})",
        where=where,
        fix="use mesh, box, cylinder or sphere",
    )


def resolve_mesh(filename: str, base: Path, what: str, where: str) -> Path:
    """The mesh file ``filename`` names (see the module docstring); FormatError if absent."""
    suffix = Path(filename).suffix.lower()
    if suffix not in FORMATS:
        raise FormatError(
            f"{what}: mesh format {suffix or '(none)'!r} is not supported",
            where=where,
            fix=f"convert it to one of {', '.join(sorted(FORMATS))}",
        )
    candidates: list[Path] = []
    if filename.startswith("package://"):
        package, _, rest = filename[len("package://") :].partition("/")
        folder = base
        for _ in range(PACKAGE_LEVELS + 1):
            candidates += [folder / rest, folder / package / rest]
            folder = folder.parent
    elif filename.startswith("file://"):
        candidates.append(Path(filename[len("file://") :]))
    else:
        candidates.append(base / filename)
    for candidate in candidates:
        if candidate.is_file():
            return candidate
    raise FormatError(f"{what}: mesh file not found", where=where, fix="check the filename")


def _joint(node: XmlNode, links: dict, where: str, warnings: list[str]) -> UrdfJoint:
    name = _name(node, where)
    label = f"joint {name!r} (line {node.line})"
    kind = node.attrib.get("type", "").strip()
    if kind not in JOINT_TYPES:
        refused = " is not supported" if kind in REFUSED_TYPES else " is unknown"
        raise FormatError(
            f"{label}: joint type {kind!r}{refused}",
            where=where,
            fix=f"use one of {', '.join(JOINT_TYPES)}",
        )
    ends = {}
    for end in ("parent", "child"):
        element = node.find(end)
        link = element.attrib.get("link", "").strip() if element is not None else ""
        if not link:
            raise FormatError(f"{label}: no <{end} link=...>", where=where)
        if link not in links:
            raise FormatError(f"{label}: {end} link {link!r} is not defined", where=where)
        ends[end] = link
    if ends["parent"] == ends["child"]:
        raise FormatError(
            f"{label}: joints form a cycle ({ends['parent']!r} is its own parent)", where=where
        )
    origin = origin_transform(node.find("origin"), label, where)
    axis_node = node.find("axis")
    axis = np.array(
        attr_floats(axis_node, "xyz", 3, label, where, default=(1.0, 0.0, 0.0))
        if axis_node is not None
        else (1.0, 0.0, 0.0)
    )
    if kind != "fixed" and np.linalg.norm(axis) < 1e-9:
        raise FormatError(f"{label}: the axis is zero", where=where)
    axis = axis / max(float(np.linalg.norm(axis)), 1e-12)
    limit = None
    if kind in ("revolute", "prismatic"):
        element = node.find("limit")
        if element is None:
            raise FormatError(f"{label}: a {kind} joint needs <limit lower upper>", where=where)
        what = f"{label} <limit> (line {element.line})"
        lower = attr_float(element, "lower", what, where, default=0.0)
        upper = attr_float(element, "upper", what, where, default=0.0)
        if not lower < upper:
            raise FormatError(f"{what}: empty range [{lower:g}, {upper:g}]", where=where)
        if kind == "revolute" and upper - lower > 2 * math.pi + 1e-9:
            raise FormatError(
                f"{what}: range [{lower:g}, {upper:g}] rad is more than a turn",
                where=where,
                fix="use type continuous for an unlimited hinge",
            )
        limit = (lower, upper)
    damping = friction = None
    dynamics = node.find("dynamics")
    if dynamics is not None:
        what = f"{label} <dynamics> (line {dynamics.line})"
        damping = attr_float(dynamics, "damping", what, where, default=0.0)
        friction = attr_float(dynamics, "friction", what, where, default=0.0)
        if damping < 0 or friction < 0:
            raise FormatError(f"{what}: damping and friction must not be negative", where=where)
    if node.find("mimic") is not None:
        warnings.append(f"{label}: <mimic> ignored (the joint moves on its own)")
    return UrdfJoint(
        name, kind, ends["parent"], ends["child"], origin, axis, limit, damping, friction, label
    )


def _colour(node: XmlNode, where: str) -> tuple[float, float, float, float] | None:
    colour = node.find("color")
    if colour is None:
        return None
    values = attr_floats(colour, "rgba", 4, f"material (line {node.line})", where)
    r, g, b, a = (min(max(v, 0.0), 1.0) for v in values)
    return (r, g, b, a)
