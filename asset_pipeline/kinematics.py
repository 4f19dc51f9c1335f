"""The kinematic tree of an articulated file (URDF or MJCF) as the asset importer needs it.

Readers (:mod:`asset_pipeline.urdf`, :mod:`asset_pipeline.mjcf_import`) produce a
:class:`Kinematics`: every link with its meshes already placed in the model's root frame at the
pose the file gives (joint values :attr:`JointInfo.value`), and every joint with its axis and
anchor in that same frame. :mod:`asset_pipeline.articulated_import` turns it into an asset.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import Literal

import numpy as np

from asset_pipeline.load import MeshMaterial, MeshPart

DEFAULT_RGBA = (0.7, 0.7, 0.7, 1.0)  # what load.py gives a mesh without a material

JointKind = Literal["hinge", "slide", "fixed"]


@dataclass
class LinkGeometry:
    """A link (a body of the file) and its meshes in the model frame; ``where`` names it."""

    name: str
    parts: list[MeshPart]
    where: str


@dataclass
class JointInfo:
    """A joint of the file in the model frame at the file's pose.

    ``type``: hinge (radians), slide (file units) or fixed; ``range`` None for an unlimited
    hinge; ``value`` the joint value the link meshes are given at (URDF: 0; MJCF: ``qpos0``).
    Dynamics are None when the file does not give them.
    """

    name: str
    type: JointKind
    parent: str
    child: str
    axis: np.ndarray
    anchor: np.ndarray
    range: tuple[float, float] | None
    value: float = 0.0
    damping: float | None = None
    frictionloss: float | None = None
    armature: float | None = None
    stiffness: float | None = None
    springref: float | None = None
    where: str = ""

    def limits(self) -> tuple[float, float]:
        """The joint's range; a ValueError for an unlimited one (an articulated import closes
        every part first, giving an unlimited hinge the range (-pi, pi))."""
        if self.range is None:
            raise ValueError(f"joint {self.name!r} has no range")
        return self.range


@dataclass
class Kinematics:
    """A whole file: links (parents before children), joints (parents first), its format,
    its up axis, semantic labels of links, a category it names, and reading warnings."""

    format: str
    name: str
    links: dict[str, LinkGeometry]
    joints: list[JointInfo]
    up_axis: Literal["y", "z"] = "z"
    labels: dict[str, str] = field(default_factory=dict)
    category: str | None = None
    partnet: bool = False
    warnings: list[str] = field(default_factory=list)

    @property
    def faces(self) -> int:
        """Triangles over all links."""
        return sum(len(p.faces) for link in self.links.values() for p in link.parts)

    @property
    def vertices(self) -> int:
        """Vertices over all links."""
        return sum(len(p.vertices) for link in self.links.values() for p in link.parts)


def transformed(part: MeshPart, matrix: np.ndarray) -> MeshPart:
    """``part`` with its vertices mapped by the 4x4 affine ``matrix`` (faces flipped when the
    map mirrors, so they stay outward)."""
    vertices = part.vertices @ matrix[:3, :3].T + matrix[:3, 3]
    faces = part.faces
    if np.linalg.det(matrix[:3, :3]) < 0:
        faces = faces[:, ::-1]
    return replace(part, vertices=vertices, faces=faces)


def coloured(part: MeshPart, rgba: tuple[float, float, float, float] | None) -> MeshPart:
    """``part`` painted ``rgba`` when it has no material of its own (plain grey, no texture)."""
    if rgba is None or part.material.texture_png is not None:
        return part
    if part.material.rgba != DEFAULT_RGBA:
        return part
    r, g, b, a = rgba
    return replace(part, material=MeshMaterial(rgba=(r, g, b, a), name=part.material.name))


def primitive(kind: str, size: tuple[float, ...]) -> MeshPart:
    """A triangle mesh of a box (full extents), cylinder (radius, length, along z), sphere
    (radius) or capsule (radius, length), centred at the origin."""
    import trimesh

    if kind == "box":
        mesh = trimesh.creation.box(extents=size[:3])
    elif kind == "cylinder":
        mesh = trimesh.creation.cylinder(radius=size[0], height=size[1], sections=32)
    elif kind == "capsule":
        mesh = trimesh.creation.capsule(radius=size[0], height=size[1], count=[16, 16])
    elif kind == "sphere":
        mesh = trimesh.creation.icosphere(subdivisions=2, radius=size[0])
    elif kind == "ellipsoid":
        mesh = trimesh.creation.icosphere(subdivisions=2, radius=1.0)
        mesh.vertices = mesh.vertices * np.asarray(size[:3])
    else:
        raise ValueError(kind)
    return MeshPart(
        vertices=np.asarray(mesh.vertices, dtype=np.float64),
        faces=np.asarray(mesh.faces, dtype=np.int64),
        uv=None,
        material=MeshMaterial(rgba=DEFAULT_RGBA),
    )


def rotation_about(axis: np.ndarray, angle: float) -> np.ndarray:
    """The 3x3 rotation by ``angle`` about the unit ``axis`` (Rodrigues)."""
    k = np.asarray(axis, dtype=float)
    cross = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + np.sin(angle) * cross + (1 - np.cos(angle)) * cross @ cross


def joint_motion(joint: JointInfo, amount: float) -> np.ndarray:
    """The 4x4 map of the child's geometry when ``joint`` moves by ``amount``."""
    motion = np.eye(4)
    if joint.type == "hinge":
        rot = rotation_about(joint.axis, amount)
        motion[:3, :3] = rot
        motion[:3, 3] = joint.anchor - rot @ joint.anchor
    elif joint.type == "slide":
        motion[:3, 3] = joint.axis * amount
    return motion
