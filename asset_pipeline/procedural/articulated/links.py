"""Moving parts of procedural assets: links, their joints and handles, and the part wrapper.

A design of an articulated asset is an ordinary flat tuple of parts (so the attribute
machinery recolours it like any other design) in which the parts of a moving link are wrapped
in :class:`Moving`, carrying their :class:`Link` (name, joint, handle), and the parts whose top
is a surface *inside* the asset (a shelf behind a door, a drawer bottom) are wrapped in
:class:`Inside`. Everything is drawn at the closed pose, in the design's frame; assembly
(:mod:`.assembly`) moves it into the asset frame with the parts.

Frames and signs (front +X, Z up): a positive joint value opens. A door hinged on its -Y edge
turns about -Z, one hinged on its +Y edge about +Z; a drop-down door about +Y; a lid hinged at
its back about -Y; a drawer slides along +X. Pivots sit on the *front* face of a door at its
hinge edge (on the top face of a lid at its back edge), so nothing of the part swings behind
its closed plane into the carcass.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field, replace
from typing import Any, Literal

import numpy as np

from asset_pipeline.procedural.parts import (
    Collider,
    Mesh,
    Part,
    RecipeMaterial,
    RecipeSurface,
    Vec3,
    Vec4,
    add3,
)
from asset_pipeline.procedural.roles import Tagged

JointType = Literal["hinge", "slide"]
GRAVITY = 9.81

# Joint behaviour (SI units; hinge values per radian, slide values per metre).
HINGE_DAMPING_PER_M = 20.0  # N m s / rad per metre from axis to handle: a 30 N pull on the
#                            handle turns any hinged part at about 1.5 rad/s
DOOR_FRICTIONLOSS = 0.6  # N m: a door stays where it is left
DRAWER_DAMPING = 60.0  # N s / m: a 30 N pull draws a drawer out at ~0.5 m/s
DRAWER_FRICTIONLOSS = 3.0  # N
LID_FRICTIONLOSS = 0.5  # N m, on top of what the counterbalance leaves
ARMATURE = 0.01  # kg m^2 (kg for slides): numerical stiffness for light parts
PART_DENSITY = 600.0  # kg / m^3 of collider volume: wood panels, MDF


@dataclass(frozen=True)
class JointDesign:
    """A joint at the closed pose (value 0): type, axis, anchor (a point on a hinge axis, or of
    the sliding part), range and behaviour. See :class:`holomj.spec.assets.ArticulationJoint`."""

    type: JointType
    axis: Vec3
    anchor: Vec3
    range: tuple[float, float]
    damping: float
    frictionloss: float
    armature: float = ARMATURE
    stiffness: float = 0.0
    springref: float = 0.0
    balance: bool = False  # fit a counterbalance spring at assembly (:func:`balanced`)

    def translated(self, offset: Vec3) -> JointDesign:
        """This joint moved by ``offset``."""
        return replace(self, anchor=add3(self.anchor, offset))


@dataclass(frozen=True)
class HandleDesign:
    """Where a hand grasps: the grip's middle, the pull direction and the grip's axis."""

    pos: Vec3
    pull: Vec3
    along: Vec3  # the grip's long axis (the grasp frame's z)
    length: float

    @property
    def quat(self) -> Vec4:
        """The grasp frame: x along ``pull``, z along ``along``."""
        return frame_quat(self.pull, self.along)

    def translated(self, offset: Vec3) -> HandleDesign:
        """This handle moved by ``offset``."""
        return replace(self, pos=add3(self.pos, offset))


@dataclass(frozen=True)
class Link:
    """A moving part: its name (the body), kind, parent link (None: the carcass), joint,
    handle and density (its mass is density times its collider volume)."""

    name: str
    kind: str
    joint: JointDesign
    handle: HandleDesign | None = None
    parent: str | None = None
    density: float = PART_DENSITY

    @property
    def joint_name(self) -> str:
        """The joint's name: ``<link>_hinge`` or ``<link>_slide``."""
        return f"{self.name}_{self.joint.type}"

    def translated(self, offset: Vec3) -> Link:
        """This link (joint anchor and handle) moved by ``offset``."""
        handle = self.handle.translated(offset) if self.handle is not None else None
        return replace(self, joint=self.joint.translated(offset), handle=handle)


@dataclass(frozen=True)
class Moving:
    """A part of moving link ``link``; behaves as the part it wraps.

    ``material`` mirrors the wrapped part's: ``dataclasses.replace(moving, material=m)`` (what
    the attribute machinery does to recolour a part) gives the wrapped part material ``m``.
    """

    part: Part
    link: Link
    material: RecipeMaterial = field(default=None)  # type: ignore[assignment]  # None: the wrapped part's

    def __post_init__(self) -> None:
        inner = self.part.material
        if self.material is None:
            object.__setattr__(self, "material", inner)
        elif self.material != inner:
            object.__setattr__(self, "part", replace(self.part, material=self.material))

    def mesh(self) -> Mesh | None:
        return self.part.mesh()

    def colliders(self) -> list[Collider]:
        return self.part.colliders()

    def bounds(self) -> tuple[Vec3, Vec3] | None:
        return self.part.bounds()

    def surfaces(self) -> list[RecipeSurface]:
        return self.part.surfaces()

    def translated(self, offset: Vec3) -> Moving:
        return Moving(self.part.translated(offset), self.link.translated(offset))

    def __getattr__(self, name: str) -> Any:
        if name in ("part", "link", "material") or name.startswith("__"):
            raise AttributeError(name)
        return getattr(self.part, name)


@dataclass(frozen=True)
class Inside:
    """A part whose top surface lies inside the asset (reached by opening ``behind``, the
    names of links); behaves as the part it wraps. Same ``material`` mirroring as Moving."""

    part: Part
    behind: tuple[str, ...]
    material: RecipeMaterial = field(default=None)  # type: ignore[assignment]  # None: the wrapped part's

    def __post_init__(self) -> None:
        inner = self.part.material
        if self.material is None:
            object.__setattr__(self, "material", inner)
        elif self.material != inner:
            object.__setattr__(self, "part", replace(self.part, material=self.material))

    def mesh(self) -> Mesh | None:
        return self.part.mesh()

    def colliders(self) -> list[Collider]:
        return self.part.colliders()

    def bounds(self) -> tuple[Vec3, Vec3] | None:
        return self.part.bounds()

    def surfaces(self) -> list[RecipeSurface]:
        return self.part.surfaces()

    def translated(self, offset: Vec3) -> Inside:
        return Inside(self.part.translated(offset), self.behind)

    def __getattr__(self, name: str) -> Any:
        if name in ("part", "behind", "material") or name.startswith("__"):
            raise AttributeError(name)
        return getattr(self.part, name)


def unwrapped(part: Part) -> tuple[Part, Link | None, tuple[str, ...] | None]:
    """The primitive inside role, Moving and Inside wrappers, its link (None: the carcass)
    and, for an Inside part, the links it is behind (None: an outer part)."""
    link: Link | None = None
    behind: tuple[str, ...] | None = None
    while True:
        if isinstance(part, Moving):
            link = part.link
        elif isinstance(part, Inside):
            behind = part.behind
        elif not isinstance(part, Tagged):
            return part, link, behind
        part = part.part


def moving(link: Link, parts: Sequence[Part]) -> list[Part]:
    """``parts`` as parts of ``link``."""
    return [Moving(p, link) for p in parts]


def inside(behind: tuple[str, ...], parts: Sequence[Part]) -> list[Part]:
    """``parts`` whose surfaces are inside, reached through the links ``behind``."""
    return [Inside(p, behind) for p in parts]


# --- joints --------------------------------------------------------------------------------
def side_hinge(
    hinge_y: float, free_y: float, x_front: float, z_mid: float, max_deg: float = 110.0
) -> JointDesign:
    """A door turning about a vertical axis on the front face at its edge ``hinge_y`` (its
    damping follows from its handle: :func:`damped`)."""
    axis = (0.0, 0.0, 1.0 if hinge_y > free_y else -1.0)
    return JointDesign(
        "hinge",
        axis,
        (x_front, hinge_y, z_mid),
        (0.0, math.radians(max_deg)),
        damping=0.0,
        frictionloss=DOOR_FRICTIONLOSS,
    )


def drawer_slide(anchor: Vec3, travel: float) -> JointDesign:
    """A drawer sliding out along +X by up to ``travel``."""
    return JointDesign(
        "slide",
        (1.0, 0.0, 0.0),
        anchor,
        (0.0, travel),
        damping=DRAWER_DAMPING,
        frictionloss=DRAWER_FRICTIONLOSS,
    )


def flap_hinge(
    pivot: Vec3,
    max_deg: float,
    *,
    axis: Vec3,
    damping: float = 0.0,
    frictionloss: float = LID_FRICTIONLOSS,
) -> JointDesign:
    """A horizontal-axis hinge (a drop-down door, a lid, a seat) with a counterbalance spring
    fitted at assembly (:func:`balanced`, once the part's mass and centre are known)."""
    return JointDesign(
        "hinge",
        axis,
        pivot,
        (0.0, math.radians(max_deg)),
        damping=damping,
        frictionloss=frictionloss,
        balance=True,
    )


def damped(link: Link) -> Link:
    """``link`` with its hinge damped in proportion to the lever of its handle
    (:data:`HINGE_DAMPING_PER_M`), at least as much as it asks: the same pull moves a small and
    a large door alike, and a door let go with a push comes to rest instead of slamming."""
    joint = link.joint
    if joint.type != "hinge" or link.handle is None:
        return link
    arm = np.subtract(link.handle.pos, joint.anchor)
    axis = np.asarray(joint.axis, dtype=float)
    lever = float(np.linalg.norm(arm - axis * np.dot(arm, axis)))
    damping = max(joint.damping, HINGE_DAMPING_PER_M * lever)
    return replace(link, joint=replace(joint, damping=damping))


def balanced(joint: JointDesign, mass: float, com: Vec3) -> JointDesign:
    """``joint`` with the counterbalance of a part of ``mass`` centred at ``com``.

    Gravity turns a part on a horizontal hinge by a torque that changes with the angle; the
    spring (stiffness and reference fitted by least squares over the range) cancels most of it,
    and the friction loss holds what is left with a margin, so the part stays at any angle it
    is left at, as an oven door on its springs or a chest lid on its stays does. The spring
    never pushes a closed part open: at the closed end the net torque points closed or is zero.
    """
    angles = np.linspace(joint.range[0], joint.range[1], 64)
    gravity = np.array([_gravity_torque(joint.anchor, com, joint.axis, mass, a) for a in angles])
    # Spring torque k * (ref - q); fit -gravity ~ k * ref - k * q: a line in q, whose value at
    # q = 0 may not exceed -gravity(0) (the spring must not push a closed part open).
    slope, intercept = np.polyfit(angles, -gravity, 1)
    if intercept > -gravity[0]:
        intercept = -gravity[0]
        slope = float(np.dot(angles, -gravity - intercept) / np.dot(angles, angles))
    stiffness = max(0.0, -float(slope))
    springref = float(intercept / stiffness) if stiffness > 1e-9 else 0.0
    spring = stiffness * (springref - angles) if stiffness > 1e-9 else np.zeros_like(angles)
    left = float(np.max(np.abs(gravity + spring)))
    return replace(
        joint,
        frictionloss=joint.frictionloss + 1.3 * left,
        stiffness=stiffness,
        springref=springref,
        balance=False,
    )


def _gravity_torque(pivot: Vec3, com: Vec3, axis: Vec3, mass: float, angle: float) -> float:
    """Gravity's torque about ``axis`` (through ``pivot``) on a part turned by ``angle``."""
    r = rotate(np.subtract(com, pivot), axis, angle)
    torque = np.cross(r, np.array([0.0, 0.0, -GRAVITY * mass]))
    return float(np.dot(torque, axis))


def rotate(vector: Any, axis: Vec3, angle: float) -> np.ndarray:
    """``vector`` turned by ``angle`` about unit ``axis`` (Rodrigues)."""
    v, k = np.asarray(vector, dtype=float), np.asarray(axis, dtype=float)
    c, s = math.cos(angle), math.sin(angle)
    return v * c + np.cross(k, v) * s + k * np.dot(k, v) * (1.0 - c)


def frame_quat(x_axis: Vec3, z_axis: Vec3) -> Vec4:
    """The unit quaternion (w, x, y, z) of the frame with these x and z axes (orthonormal)."""
    x = np.asarray(x_axis, dtype=float)
    z = np.asarray(z_axis, dtype=float)
    x, z = x / np.linalg.norm(x), z / np.linalg.norm(z)
    y = np.cross(z, x)
    m = np.column_stack([x, y, z])
    trace = m[0, 0] + m[1, 1] + m[2, 2]
    if trace > 0:
        s = 2.0 * math.sqrt(trace + 1.0)
        q = (0.25 * s, (m[2, 1] - m[1, 2]) / s, (m[0, 2] - m[2, 0]) / s, (m[1, 0] - m[0, 1]) / s)
    elif m[0, 0] > m[1, 1] and m[0, 0] > m[2, 2]:
        s = 2.0 * math.sqrt(1.0 + m[0, 0] - m[1, 1] - m[2, 2])
        q = ((m[2, 1] - m[1, 2]) / s, 0.25 * s, (m[0, 1] + m[1, 0]) / s, (m[0, 2] + m[2, 0]) / s)
    elif m[1, 1] > m[2, 2]:
        s = 2.0 * math.sqrt(1.0 + m[1, 1] - m[0, 0] - m[2, 2])
        q = ((m[0, 2] - m[2, 0]) / s, (m[0, 1] + m[1, 0]) / s, 0.25 * s, (m[1, 2] + m[2, 1]) / s)
    else:
        s = 2.0 * math.sqrt(1.0 + m[2, 2] - m[0, 0] - m[1, 1])
        q = ((m[1, 0] - m[0, 1]) / s, (m[0, 2] + m[2, 0]) / s, (m[1, 2] + m[2, 1]) / s, 0.25 * s)
    sign = -1.0 if q[0] < 0 else 1.0
    qw, qx, qy, qz = (round(float(sign * v), 9) + 0.0 for v in q)
    return (qw, qx, qy, qz)
