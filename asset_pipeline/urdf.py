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

import json
import math
import re
import xml.parsers.expat
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from asset_pipeline.kinematics import (
    JointInfo,
    Kinematics,
    LinkGeometry,
    coloured,
    primitive,
    transformed,
)
from asset_pipeline.load import FORMATS, LoadedFile, load_file
from holomj.errors import FormatError

JOINT_TYPES = ("revolute", "continuous", "prismatic", "fixed")
REFUSED_TYPES = ("floating", "planar")
PACKAGE_LEVELS = 3
MAX_FILE_BYTES = 50_000_000


# --- a small XML tree with line numbers (the stdlib's expat parser) -----------------------------
@dataclass
class Node:
    """An XML element: tag, attributes, children and the line it starts on."""

    tag: str
    attrib: dict[str, str]
    line: int
    children: list[Node] = field(default_factory=list)

    def find(self, tag: str) -> Node | None:
        """The first child with ``tag``."""
        return next((c for c in self.children if c.tag == tag), None)

    def findall(self, tag: str) -> list[Node]:
        """Every child with ``tag``."""
        return [c for c in self.children if c.tag == tag]

    def iter(self):
        """This element and all below it, depth first."""
        yield self
        for child in self.children:
            yield from child.iter()


def parse_xml(data: bytes | str, where: str) -> Node:
    """The root element of ``data``; FormatError for anything that is not plain XML.

    DOCTYPE declarations (and with them entity definitions) are refused.
    """
    parser = xml.parsers.expat.ParserCreate()
    stack: list[Node] = []
    roots: list[Node] = []

    def start(tag: str, attrib: dict[str, str]) -> None:
        node = Node(tag, dict(attrib), parser.CurrentLineNumber)
        if stack:
            stack[-1].children.append(node)
        else:
            roots.append(node)
        stack.append(node)

    def end(tag: str) -> None:
        stack.pop()

    def doctype(*args: object) -> None:
        raise FormatError("a DOCTYPE declaration is not allowed", where=where)

    parser.StartElementHandler = start
    parser.EndElementHandler = end
    parser.StartDoctypeDeclHandler = doctype
    try:
        parser.Parse(data, True)
    except xml.parsers.expat.ExpatError as err:
        reason = xml.parsers.expat.ErrorString(err.code)
        raise FormatError(
            f"not well-formed XML: {reason} at line {err.lineno}", where=where
        ) from None
    if not roots:
        raise FormatError("the file holds no XML element", where=where)
    return roots[0]


def read_text(path: Path) -> bytes:
    """The bytes of a description file; FormatError when missing, empty or huge."""
    where = str(path)
    if not path.is_file():
        raise FormatError("file not found", where=where, fix="check the path")
    size = path.stat().st_size
    if size == 0:
        raise FormatError("the file is empty", where=where)
    if size > MAX_FILE_BYTES:
        raise FormatError(f"the file has {size} bytes, more than {MAX_FILE_BYTES}", where=where)
    return path.read_bytes()


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
        return list(dict.fromkeys(seen))  # type: ignore[arg-type]


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


def _name(node: Node, where: str) -> str:
    name = node.attrib.get("name", "").strip()
    if not name:
        raise FormatError(f"<{node.tag}> (line {node.line}) has no name", where=where)
    return name


def _link(node: Node, name: str, path: Path, materials: dict, warnings: list[str]) -> UrdfLink:
    where = str(path)
    label = f"link {name!r} (line {node.line})"
    elements = node.findall("visual") or node.findall("collision")
    geometry = []
    for k, element in enumerate(elements):
        what = f"{label} {element.tag} {k} (line {element.line})"
        shape = element.find("geometry")
        if shape is None or not shape.children:
            raise FormatError(f"{what} has no <geometry>", where=where)
        origin = _origin(element.find("origin"), what, where)
        rgba = None
        material = element.find("material")
        if material is not None:
            rgba = _colour(material, where)
            if rgba is None:
                rgba = materials.get(material.attrib.get("name", ""))
        geometry.append(_geometry(shape.children[0], origin, rgba, what, path, warnings))
    return UrdfLink(name, geometry, label)


def _geometry(
    node: Node, origin: np.ndarray, rgba, what: str, path: Path, warnings: list[str]
) -> Geometry:
    where = str(path)
    if node.tag == "mesh":
        filename = node.attrib.get("filename", "").strip()
        if not filename:
            raise FormatError(f"{what}: <mesh> (line {node.line}) has no filename", where=where)
        mesh = resolve_mesh(filename, path.parent, f"{what}: mesh {filename!r}", where)
        scale = _floats(node, "scale", 3, what, where, default=(1.0, 1.0, 1.0))
        if any(s == 0 for s in scale):
            raise FormatError(f"{what}: mesh scale {scale} has a zero factor", where=where)
        return Geometry("mesh", origin, mesh=mesh, scale=scale, rgba=rgba, where=what)
    if node.tag == "box":
        size = _floats(node, "size", 3, what, where)
        return Geometry("box", origin, size=_positive(size, what, where), rgba=rgba, where=what)
    if node.tag == "cylinder":
        size = (_float(node, "radius", what, where), _float(node, "length", what, where))
        return Geometry(
            "cylinder", origin, size=_positive(size, what, where), rgba=rgba, where=what
        )
    if node.tag == "sphere":
        size = (_float(node, "radius", what, where),)
        return Geometry("sphere", origin, size=_positive(size, what, where), rgba=rgba, where=what)
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


def _joint(node: Node, links: dict, where: str, warnings: list[str]) -> UrdfJoint:
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
    origin = _origin(node.find("origin"), label, where)
    axis_node = node.find("axis")
    axis = np.array(
        _floats(axis_node, "xyz", 3, label, where, default=(1.0, 0.0, 0.0))
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
        lower = _float(element, "lower", what, where, default=0.0)
        upper = _float(element, "upper", what, where, default=0.0)
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
        damping = _float(dynamics, "damping", what, where, default=0.0)
        friction = _float(dynamics, "friction", what, where, default=0.0)
        if damping < 0 or friction < 0:
            raise FormatError(f"{what}: damping and friction must not be negative", where=where)
    if node.find("mimic") is not None:
        warnings.append(f"{label}: <mimic> ignored (the joint moves on its own)")
    return UrdfJoint(
        name, kind, ends["parent"], ends["child"], origin, axis, limit, damping, friction, label
    )


def _origin(node: Node | None, what: str, where: str) -> np.ndarray:
    """The 4x4 transform of an ``<origin xyz rpy>`` (identity when absent)."""
    transform = np.eye(4)
    if node is None:
        return transform
    what = f"{what} <origin> (line {node.line})"
    xyz = _floats(node, "xyz", 3, what, where, default=(0.0, 0.0, 0.0))
    rpy = _floats(node, "rpy", 3, what, where, default=(0.0, 0.0, 0.0))
    transform[:3, :3] = rpy_matrix(rpy)
    transform[:3, 3] = xyz
    return transform


def rpy_matrix(rpy: tuple[float, float, float]) -> np.ndarray:
    """URDF's roll-pitch-yaw: ``Rz(yaw) @ Ry(pitch) @ Rx(roll)``."""
    r, p, y = rpy
    cr, sr, cp, sp, cy, sy = (
        math.cos(r),
        math.sin(r),
        math.cos(p),
        math.sin(p),
        math.cos(y),
        math.sin(y),
    )
    rx = np.array([[1, 0, 0], [0, cr, -sr], [0, sr, cr]])
    ry = np.array([[cp, 0, sp], [0, 1, 0], [-sp, 0, cp]])
    rz = np.array([[cy, -sy, 0], [sy, cy, 0], [0, 0, 1]])
    return rz @ ry @ rx


_NUMBER = re.compile(r"^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$")


def _floats(
    node: Node,
    key: str,
    count: int,
    what: str,
    where: str,
    default: tuple[float, ...] | None = None,
) -> tuple[float, ...]:
    text = node.attrib.get(key)
    if text is None:
        if default is None:
            raise FormatError(f"{what}: <{node.tag}> (line {node.line}) has no {key}", where=where)
        return default
    items = text.split()
    if len(items) != count or not all(_NUMBER.match(item) for item in items):
        raise FormatError(
            f"{what}: {key}={text[:40]!r} of <{node.tag}> (line {node.line}) is not "
            f"{count} number{'s' if count > 1 else ''}",
            where=where,
        )
    values = tuple(float(item) for item in items)
    if not all(math.isfinite(v) for v in values):
        raise FormatError(f"{what}: {key} of <{node.tag}> is not finite", where=where)
    return values


def _float(node: Node, key: str, what: str, where: str, default: float | None = None) -> float:
    return _floats(node, key, 1, what, where, None if default is None else (default,))[0]


def _positive(values: tuple[float, ...], what: str, where: str) -> tuple[float, ...]:
    if any(v <= 0 for v in values):
        raise FormatError(f"{what}: sizes must be positive, got {values}", where=where)
    return values


def _colour(node: Node, where: str) -> tuple[float, float, float, float] | None:
    colour = node.find("color")
    if colour is None:
        return None
    values = _floats(colour, "rgba", 4, f"material (line {node.line})", where)
    return tuple(min(max(v, 0.0), 1.0) for v in values)  # type: ignore[return-value]


# --- PartNet-Mobility extras --------------------------------------------------------------------
def partnet_meta(path: Path) -> dict:
    """``meta.json`` beside a PartNet-Mobility URDF (empty when absent or unreadable)."""
    meta = Path(path).parent / "meta.json"
    try:
        data = json.loads(meta.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return {}
    return data if isinstance(data, dict) else {}


def partnet_labels(path: Path) -> dict[str, str]:
    """Link -> semantic label from ``semantics.txt`` (``link_0 hinge door``), if present."""
    labels = {}
    try:
        text = (Path(path).parent / "semantics.txt").read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError):
        return {}
    for line in text.splitlines():
        words = line.split()
        if len(words) >= 2:
            labels[words[0]] = words[-1].lower()
    return labels


def is_partnet(model: UrdfModel) -> bool:
    """Whether the URDF looks like PartNet-Mobility's (its meta.json or its robot name)."""
    return bool(partnet_meta(model.path).get("model_cat")) or model.name.startswith("partnet_")


def asset_id_hint(path: Path) -> str | None:
    """An id for a PartNet-Mobility ``mobility.urdf``: ``<model_cat>_<folder>`` (e.g.
    ``storagefurniture_45612``); None for other files."""
    path = Path(path)
    if path.suffix.lower() != ".urdf" or not path.stem.lower().startswith("mobility"):
        return None
    category = str(partnet_meta(path).get("model_cat") or "partnet")
    folder = re.sub(r"[^A-Za-z0-9_.\-]+", "_", path.parent.name).strip("_.-")
    text = re.sub(r"[^a-z0-9_]+", "_", category.lower()).strip("_") or "partnet"
    return f"{text}_{folder}" if folder else text


# --- to kinematics ------------------------------------------------------------------------------
_JOINT_KINDS = {"revolute": "hinge", "continuous": "hinge", "prismatic": "slide", "fixed": "fixed"}


def load_urdf(path: Path | str, max_faces: int = 2_000_000) -> Kinematics:
    """The kinematics of the URDF at ``path``: its meshes loaded and placed at joint values 0."""
    model = read_urdf(path)
    frames = {root: np.eye(4) for root in model.roots}
    joints = []
    for joint in model.joints:
        at = frames[joint.parent] @ joint.origin
        frames[joint.child] = at
        joints.append(
            JointInfo(
                name=joint.name,
                type=_JOINT_KINDS[joint.type],  # type: ignore[arg-type]
                parent=joint.parent,
                child=joint.child,
                axis=at[:3, :3] @ joint.axis,
                anchor=at[:3, 3].copy(),
                range=joint.limit,
                damping=joint.damping,
                frictionloss=joint.friction,
                where=joint.where,
            )
        )
    warnings = list(model.warnings)
    loaded: dict[Path, LoadedFile] = {}
    links: dict[str, LinkGeometry] = {}
    faces = 0
    for name in [*model.roots, *(j.child for j in model.joints)]:
        link = model.links[name]
        parts = []
        for geometry in link.geometry:
            placed = frames[name] @ geometry.origin
            if geometry.mesh is None:
                parts.append(
                    coloured(
                        transformed(primitive(geometry.kind, geometry.size), placed), geometry.rgba
                    )
                )
                continue
            mesh = loaded.get(geometry.mesh)
            if mesh is None:
                mesh = _load_mesh(geometry, model.path, max_faces - faces)
                loaded[geometry.mesh] = mesh
                warnings += [f"{geometry.mesh.name}: {w}" for w in mesh.warnings]
            scale = np.diag([*geometry.scale, 1.0])
            for part in mesh.parts:
                parts.append(coloured(transformed(part, placed @ scale), geometry.rgba))
                faces += len(part.faces)
        if faces > max_faces:
            raise FormatError(
                f"the meshes have more than {max_faces} faces",
                where=str(model.path),
                fix="decimate them first or raise max_faces",
            )
        links[name] = LinkGeometry(name, parts, link.where)
    meta = partnet_meta(model.path)
    return Kinematics(
        format="urdf",
        name=model.name,
        links=links,
        joints=joints,
        up_axis="z",
        labels=partnet_labels(model.path),
        category=str(meta["model_cat"]) if meta.get("model_cat") else None,
        partnet=is_partnet(model),
        warnings=warnings,
    )


def _load_mesh(geometry: Geometry, urdf: Path, max_faces: int) -> LoadedFile:
    assert geometry.mesh is not None
    try:
        return load_file(geometry.mesh, max(1, max_faces))
    except FormatError as err:
        raise FormatError(
            f"{geometry.where}: mesh {geometry.mesh.name}: {err.what}", where=str(urdf), fix=err.fix
        ) from None
